//! STL files, binary and ASCII. Every facet is three points of its own, so identical
//! points are welded into one vertex (numbered from 1 in the order they first appear),
//! which is what lets a mesh be oriented across its shared edges. The facets' normals
//! are not read: the winding says which way a facet faces, as the format requires them
//! to agree.

use super::{Face, Mesh, Origin, Problem, ReadMesh};
use std::collections::HashMap;

/// Reads a binary STL (when the file's size is the one its header announces) or an
/// ASCII one (whose subnormal numbers are warned about).
pub(super) fn parse(bytes: &[u8]) -> Result<ReadMesh, Problem> {
    if let Some(count) = binary_count(bytes) {
        return binary(bytes, count).map(|mesh| ReadMesh {
            mesh,
            warnings: Vec::new(),
        });
    }
    let text_start = bytes.iter().position(|b| !b.is_ascii_whitespace());
    if text_start.is_some_and(|i| bytes[i..].starts_with(b"solid")) {
        return ascii(bytes);
    }
    let why = if bytes.len() < 84 {
        format!(
            "{} bytes is too short for a binary STL (at least 84)",
            bytes.len()
        )
    } else {
        let announced = u32::from_le_bytes([bytes[80], bytes[81], bytes[82], bytes[83]]);
        format!(
            "as a binary STL, its header announces {announced} facets, which take 84 + 50 × {announced} = {} bytes, but the file has {}",
            84 + 50 * u64::from(announced),
            bytes.len()
        )
    };
    Err(Problem::whole(format!(
        "not an STL file: {why}, and it does not start with `solid` as an ASCII STL does"
    )))
}

/// The number of facets of a binary STL, if the file's size is the one its header
/// announces.
fn binary_count(bytes: &[u8]) -> Option<usize> {
    let count = u32::from_le_bytes(bytes.get(80..84)?.try_into().ok()?);
    (84 + 50 * u64::from(count) == bytes.len() as u64).then_some(count as usize)
}

/// Points welded into vertices: one vertex per distinct position (`-0` is `0`).
#[derive(Default)]
struct Welder {
    vertices: Vec<[f64; 3]>,
    index: HashMap<[u64; 3], usize>,
    faces: Vec<Face>,
}

impl Welder {
    fn vertex(&mut self, p: [f64; 3]) -> usize {
        let bits = p.map(|x| (x + 0.0).to_bits());
        *self.index.entry(bits).or_insert_with(|| {
            self.vertices.push(p);
            self.vertices.len() - 1
        })
    }

    fn face(&mut self, points: [[f64; 3]; 3], origin: Origin) {
        let vertices = points.map(|p| self.vertex(p));
        self.faces.push(Face { vertices, origin });
    }

    fn mesh(self) -> Mesh {
        Mesh {
            vertices: self.vertices,
            faces: self.faces,
            first_index: 1,
        }
    }
}

/// 80 bytes of header, the number of facets, then 50 bytes a facet: a normal and three
/// points as little-endian 32-bit floats, and two bytes of attributes.
fn binary(bytes: &[u8], count: usize) -> Result<Mesh, Problem> {
    let mut welder = Welder::default();
    for (i, facet) in bytes[84..].chunks_exact(50).take(count).enumerate() {
        let origin = Origin::Facet(i + 1);
        let mut points = [[0.0; 3]; 3];
        for (p, point) in points.iter_mut().enumerate() {
            for (c, x) in point.iter_mut().enumerate() {
                let at = 12 + 12 * p + 4 * c;
                let single =
                    f32::from_le_bytes([facet[at], facet[at + 1], facet[at + 2], facet[at + 3]]);
                if !single.is_finite() {
                    return Err(Problem::at(
                        origin,
                        format!("point {} has a coordinate that is {single}", p + 1),
                    ));
                }
                // The shortest decimal that is this single-precision number: 0.1, not
                // 0.100000001490116.
                *x = single.to_string().parse().unwrap_or(f64::from(single));
            }
        }
        welder.face(points, origin);
    }
    Ok(welder.mesh())
}

/// Where the reader is in an ASCII STL.
#[derive(Clone, Copy, PartialEq, Eq)]
enum State {
    /// Between solids.
    Outside,
    /// In a solid, between facets.
    Solid,
    /// After `facet normal …`.
    Facet,
    /// After `outer loop`, with this many points read.
    Loop(usize),
    /// After `endloop`.
    Looped,
}

/// `solid NAME`, then facets (`facet normal x y z`, `outer loop`, three `vertex x y z`,
/// `endloop`, `endfacet`), then `endsolid NAME`; more than one solid may follow.
fn ascii(bytes: &[u8]) -> Result<ReadMesh, Problem> {
    let text = super::obj::text(bytes)?;
    let mut welder = Welder::default();
    let mut warnings = Vec::new();
    let mut state = State::Outside;
    let mut points = [[0.0; 3]; 3];
    let mut facet_line = 0;
    let mut last = 0;
    for (n, line) in text.lines().enumerate() {
        let n = n + 1;
        last = n;
        let words: Vec<&str> = line.split_whitespace().collect();
        let Some(&first) = words.first() else {
            continue;
        };
        let word = first.to_ascii_lowercase();
        let second = words.get(1).map(|w| w.to_ascii_lowercase());
        state = match (state, word.as_str()) {
            (State::Outside, "solid") => State::Solid,
            (State::Solid, "facet") => {
                facet_line = n;
                State::Facet
            }
            (State::Solid, "endsolid") => State::Outside,
            (State::Facet, "outer") if second.as_deref() == Some("loop") => State::Loop(0),
            (State::Loop(k), "vertex") if k < 3 => {
                points[k] = super::obj::point(&words[1..], n, &mut warnings)?;
                State::Loop(k + 1)
            }
            (State::Loop(3), "endloop") => State::Looped,
            (State::Looped, "endfacet") => {
                welder.face(points, Origin::Line(facet_line));
                State::Solid
            }
            (State::Loop(k), "vertex" | "endloop") => {
                return Err(Problem::at(
                    Origin::Line(n),
                    format!(
                        "a facet has 3 points, this one {}",
                        if k < 3 { "fewer" } else { "more" }
                    ),
                ));
            }
            (state, _) => {
                return Err(Problem::at(
                    Origin::Line(n),
                    format!("expected {}, found `{}`", expected(state), line.trim()),
                ));
            }
        };
    }
    if state != State::Outside {
        return Err(Problem::at(
            Origin::Line(last),
            format!("the file ends where {} should follow", expected(state)),
        ));
    }
    Ok(ReadMesh {
        mesh: welder.mesh(),
        warnings,
    })
}

/// What may come in `state`, for messages.
fn expected(state: State) -> &'static str {
    match state {
        State::Outside => "`solid`",
        State::Solid => "`facet normal X Y Z` or `endsolid`",
        State::Facet => "`outer loop`",
        State::Loop(k) if k < 3 => "`vertex X Y Z`",
        State::Loop(_) => "`endloop`",
        State::Looped => "`endfacet`",
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A binary STL of the given triangles.
    fn binary_stl(triangles: &[[[f32; 3]; 3]]) -> Vec<u8> {
        let mut bytes = vec![b' '; 80];
        bytes.extend((triangles.len() as u32).to_le_bytes());
        for t in triangles {
            bytes.extend([0u8; 12]);
            for x in t.iter().flatten() {
                bytes.extend(x.to_le_bytes());
            }
            bytes.extend([0u8; 2]);
        }
        bytes
    }

    #[test]
    fn binary_points_are_welded_and_read_as_their_shortest_decimal() {
        let a = [0.1, 0.0, 0.0];
        let bytes = binary_stl(&[
            [a, [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]],
            [[1.0, 0.0, 0.0], a, [0.0, -0.0, 1.0]],
        ]);
        let mesh = parse(&bytes).unwrap().mesh;
        assert_eq!(mesh.vertices.len(), 4);
        assert_eq!(mesh.vertices[0], [0.1, 0.0, 0.0]);
        assert_eq!(mesh.faces[1].vertices, [1, 0, 3]);
        assert_eq!(mesh.faces[1].origin, Origin::Facet(2));
    }

    #[test]
    fn a_binary_point_that_is_not_finite_names_its_facet() {
        let bytes = binary_stl(&[[[0.0; 3], [1.0, f32::NAN, 0.0], [0.0, 1.0, 0.0]]]);
        assert_eq!(
            parse(&bytes).unwrap_err().to_string(),
            "facet 1: point 2 has a coordinate that is NaN"
        );
    }

    #[test]
    fn ascii_facets_are_read_and_mistakes_named_by_line() {
        let good = "solid s\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertex 1 0 0\n   vertex 0 1 0\n  endloop\n endfacet\nendsolid s\n";
        let mesh = parse(good.as_bytes()).unwrap().mesh;
        assert_eq!(mesh.faces[0].origin, Origin::Line(2));
        assert_eq!(mesh.vertices[2], [0.0, 1.0, 0.0]);
        let short = good.replace("   vertex 0 1 0\n", "");
        assert_eq!(
            parse(short.as_bytes()).unwrap_err().to_string(),
            "line 6: a facet has 3 points, this one fewer"
        );
        let cut = &good[..good.find(" endfacet").unwrap()];
        assert_eq!(
            parse(cut.as_bytes()).unwrap_err().to_string(),
            "line 7: the file ends where `endfacet` should follow"
        );
        let bad = good.replace("vertex 1 0 0", "vertex 1 O 0");
        assert_eq!(
            parse(bad.as_bytes()).unwrap_err().to_string(),
            "line 5: `O` is not a number"
        );
        // Numbers as every tool reads them: underflow is refused like overflow, with the
        // line (1e-400 was read as 0 before); a subnormal is read, with a warning.
        for (number, message) in [
            (
                "1e-400",
                "line 5: `1e-400` is too small for a double: pkdgrav reads it as 0",
            ),
            (
                "1e999",
                "line 5: `1e999` is too large for a double: pkdgrav reads it as infinity",
            ),
            ("nan", "line 5: `nan` is not a finite number"),
        ] {
            let bad = good.replace("vertex 1 0 0", &format!("vertex 1 0 {number}"));
            assert_eq!(parse(bad.as_bytes()).unwrap_err().to_string(), message);
        }
        let tiny = parse(good.replace("vertex 1 0 0", "vertex 1 0 1e-320").as_bytes()).unwrap();
        assert_eq!(tiny.mesh.vertices[1], [1.0, 0.0, 1e-320]);
        assert_eq!(
            tiny.warnings
                .iter()
                .map(ToString::to_string)
                .collect::<Vec<_>>(),
            [
                "line 5: `1e-320` is below the smallest normal double: pkdgrav reads it as 1e-320, with fewer significant digits"
            ]
        );
    }

    #[test]
    fn a_file_that_is_neither_says_why() {
        let mut bytes = binary_stl(&[[[0.0; 3]; 3]]);
        bytes.pop();
        assert_eq!(
            parse(&bytes).unwrap_err().to_string(),
            "not an STL file: as a binary STL, its header announces 1 facets, which take 84 + 50 × 1 = 134 bytes, but the file has 133, and it does not start with `solid` as an ASCII STL does"
        );
    }
}
