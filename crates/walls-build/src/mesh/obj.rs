//! Wavefront OBJ files: `v x y z` points and `f` faces (`v`, `v/vt`, `v//vn` and
//! `v/vt/vn` forms, negative indices counting back from the last point read, polygons as
//! fans of triangles from their first point). Texture coordinates, normals, groups,
//! objects, smoothing and materials (`vt`, `vn`, `g`, `o`, `s`, `usemtl`, `mtllib`) mean
//! nothing to a wall and are skipped; any other statement is skipped with a warning.

use super::{Face, Mesh, Origin, Problem, ReadMesh};

/// The statements skipped without a word.
const IGNORED: &[&str] = &["vt", "vn", "g", "o", "s", "usemtl", "mtllib"];

/// Reads the `v` and `f` statements of an OBJ file.
pub(super) fn parse(bytes: &[u8]) -> Result<ReadMesh, Problem> {
    let text = text(bytes)?;
    let mut vertices = Vec::new();
    let mut faces = Vec::new();
    let mut warnings = Vec::new();
    for (n, line) in text.lines().enumerate() {
        let n = n + 1;
        let line = line.split('#').next().unwrap_or_default();
        let mut words = line.split_whitespace();
        let Some(statement) = words.next() else {
            continue;
        };
        let rest: Vec<&str> = words.collect();
        match statement {
            "v" => {
                // x y z, and an optional w or colour (r g b) after them.
                if !matches!(rest.len(), 3 | 4 | 6 | 7) {
                    return Err(Problem::at(
                        Origin::Line(n),
                        format!(
                            "a point `v` takes 3 coordinates (x y z), found {}",
                            rest.len()
                        ),
                    ));
                }
                vertices.push(point(&rest[..3], n, &mut warnings)?);
            }
            "f" => {
                if rest.len() < 3 {
                    return Err(Problem::at(
                        Origin::Line(n),
                        format!("a face `f` takes at least 3 points, found {}", rest.len()),
                    ));
                }
                let corners = rest
                    .iter()
                    .map(|r| index(r, vertices.len(), n))
                    .collect::<Result<Vec<usize>, Problem>>()?;
                for k in 1..corners.len() - 1 {
                    faces.push(Face {
                        vertices: [corners[0], corners[k], corners[k + 1]],
                        origin: Origin::Line(n),
                    });
                }
            }
            s if IGNORED.contains(&s) => {}
            other => warnings.push(Problem::at(
                Origin::Line(n),
                format!(
                    "`{other}` statements are skipped: only points (`v`) and faces (`f`) make walls"
                ),
            )),
        }
    }
    Ok(ReadMesh {
        mesh: Mesh {
            vertices,
            faces,
            first_index: 1,
        },
        warnings,
    })
}

/// A face's reference to a point (`7`, `7/2`, `7//3`, `-1/2/3`), as an index from 0.
fn index(reference: &str, count: usize, line: usize) -> Result<usize, Problem> {
    let first = reference.split('/').next().unwrap_or_default();
    let Ok(i) = first.parse::<i64>() else {
        return Err(Problem::at(
            Origin::Line(line),
            format!("`{reference}` is not a point's number"),
        ));
    };
    let resolved = if i < 0 { count as i64 + i } else { i - 1 };
    if i == 0 || resolved < 0 || resolved >= count as i64 {
        return Err(Problem::at(
            Origin::Line(line),
            format!(
                "point {i} does not exist: {count} point{} read so far",
                if count == 1 { "" } else { "s" }
            ),
        ));
    }
    Ok(resolved as usize)
}

/// Three numbers: a point of a text mesh, read by the tools' one rule for numbers
/// ([`walls_keywords::number`]): one that is not finite, overflows or underflows is an
/// error, a subnormal a warning in `warnings`, each with its line.
pub(super) fn point(
    words: &[&str],
    line: usize,
    warnings: &mut Vec<Problem>,
) -> Result<[f64; 3], Problem> {
    use walls_keywords::number;
    if words.len() != 3 {
        return Err(Problem::at(
            Origin::Line(line),
            format!("a point takes 3 coordinates, found {}", words.len()),
        ));
    }
    let mut p = [0.0; 3];
    for (x, word) in p.iter_mut().zip(words) {
        *x = number::read(word)
            .map_err(|why| Problem::at(Origin::Line(line), format!("`{word}` is {why}")))?;
        if let Some(tiny) = number::subnormal(*x) {
            warnings.push(Problem::at(
                Origin::Line(line),
                format!("`{word}` is {tiny}"),
            ));
        }
    }
    Ok(p)
}

/// A text mesh as UTF-8, or the line where it stops being text.
pub(super) fn text(bytes: &[u8]) -> Result<&str, Problem> {
    std::str::from_utf8(bytes).map_err(|e| {
        let at = e.valid_up_to();
        let line = bytes[..at].iter().filter(|&&b| b == b'\n').count() + 1;
        Problem::at(
            Origin::Line(line),
            format!("byte {at} is not text (UTF-8): a binary file?"),
        )
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn faces_take_every_reference_form_and_polygons_become_fans() {
        let obj = "# a square and a triangle\no square\nv 0 0 0\nv 1 0 0\nv 1 1 0 1.0\nv 0 1 0\nvt 0 0\nvn 0 0 1\ns off\nf 1/1/1 2//1 3/1 4\nf -4 -3 -1\nl 1 2\n";
        let read = parse(obj.as_bytes()).unwrap();
        let faces: Vec<_> = read.mesh.faces.iter().map(|f| f.vertices).collect();
        assert_eq!(faces, [[0, 1, 2], [0, 2, 3], [0, 1, 3]]);
        assert_eq!(read.mesh.faces[2].origin, Origin::Line(11));
        assert_eq!(
            read.warnings
                .iter()
                .map(ToString::to_string)
                .collect::<Vec<_>>(),
            ["line 12: `l` statements are skipped: only points (`v`) and faces (`f`) make walls"]
        );
    }

    #[test]
    fn mistakes_are_named_by_line() {
        let cases: [(&[u8], &str); 10] = [
            (
                b"v 0 0\n",
                "line 1: a point `v` takes 3 coordinates (x y z), found 2",
            ),
            (b"v 0 0 x\n", "line 1: `x` is not a number"),
            // Underflow is refused like overflow (1e-400 was read as 0 before).
            (
                b"v 0 0 1e-400\n",
                "line 1: `1e-400` is too small for a double: pkdgrav reads it as 0",
            ),
            (
                b"v 0 0 -1e999\n",
                "line 1: `-1e999` is too large for a double: pkdgrav reads it as infinity",
            ),
            (b"v 0 inf 0\n", "line 1: `inf` is not a finite number"),
            (
                b"v 0 0 0\nf 1 1\n",
                "line 2: a face `f` takes at least 3 points, found 2",
            ),
            (
                b"v 0 0 0\nf 1 a/1 1\n",
                "line 2: `a/1` is not a point's number",
            ),
            (
                b"v 0 0 0\nf 1 0 1\n",
                "line 2: point 0 does not exist: 1 point read so far",
            ),
            (
                b"v 0 0 0\nf 1 -2 1\n",
                "line 2: point -2 does not exist: 1 point read so far",
            ),
            (
                b"v 0 0 0\n\xff\n",
                "line 2: byte 8 is not text (UTF-8): a binary file?",
            ),
        ];
        for (obj, message) in cases {
            let got = parse(obj).map(|_| ()).unwrap_err().to_string();
            assert_eq!(got, message);
        }
    }

    #[test]
    fn a_subnormal_point_is_read_with_a_warning() {
        let read = parse(b"v 0 0 0\nv 1 0 0\nv 0 1 -2e-310\nf 1 2 3\n").unwrap();
        assert_eq!(read.mesh.vertices[2], [0.0, 1.0, -2e-310]);
        assert_eq!(
            read.warnings
                .iter()
                .map(ToString::to_string)
                .collect::<Vec<_>>(),
            [
                "line 3: `-2e-310` is below the smallest normal double: pkdgrav reads it as -2e-310, with fewer significant digits"
            ]
        );
    }
}
