//! ssdraw's parameter file, `ssdraw.par`, read as ssdraw reads it
//! (docs/pkdgrav-physics.md §16), so that a pkdgrav user's camera carries over to
//! `walls-sim preview --ssdraw ssdraw.par` (docs/preview.md, "ssdraw's view").
//!
//! A line is a label at its start, then the value: `Camera position        0 0 10`, no
//! `=` or `:`. `!` or `#` cuts the rest of a line. Labels are exact, case-sensitive
//! prefixes of the line ([`LABELS`]), and the first line a label starts is the one read;
//! lines that start with no label, or with a label an earlier line started, are not read
//! by ssdraw. The preview uses `Camera position`, `Look at/view direction`, `Sky vector`,
//! `Wall data file`, `Wall time offset` and `Aspect ratio` ([`SsdrawView`]), and reads
//! `Particle shape` (whether ssdraw writes POV-Ray, and so which labels it needs),
//! `Camera option` and `View option` (told back as not followed: §16 gives them no
//! meaning). Everything else is told back as data ([`SsdrawView::notes`], `unused`,
//! `missing`), never dropped silently.
//!
//! Where ssdraw would go on regardless, the preview refuses with the line's number
//! ([`SsdrawError`]): a line over [`MAX_LINE`] bytes or a file over [`MAX_LINES`] lines
//! (ssdraw reads no more), and a value of a label the preview reads that does not read
//! whole (ssdraw reads numbers without checks: `1e400` as infinity, `1e-400` as 0,
//! `abc` as 0; the tools' one rule for numbers, [`walls_keywords::number::read`],
//! refuses them). A label ssdraw needs and the file lacks is fatal to ssdraw; the
//! preview lists it in [`SsdrawView::missing`] and draws all the same.

use nalgebra::Vector3;

type Vec3 = Vector3<f64>;

/// The most bytes (C's characters) a line may have, its line ending left out.
pub const MAX_LINE: usize = 256;

/// The most lines a file may have.
pub const MAX_LINES: usize = 1000;

/// When ssdraw reads a label: always, only when it writes POV-Ray (`Particle shape` 2),
/// or only when a walls file is named.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Needed {
    /// Every run.
    Always,
    /// With POV-Ray output.
    PovRay,
    /// When `Wall data file` names a file.
    WithWalls,
}

/// Every label ssdraw reads, in the order §16 lists them, with when it needs it.
pub const LABELS: [(&str, Needed); 31] = [
    ("Length unit", Needed::Always),
    ("Time unit", Needed::Always),
    ("Frame size", Needed::Always),
    ("Light source option", Needed::Always),
    ("Light source position", Needed::Always),
    ("Light source intensity", Needed::Always),
    ("Camera option", Needed::Always),
    ("Camera position", Needed::Always),
    ("View option", Needed::Always),
    ("Look at/view direction", Needed::Always),
    ("Focus distance", Needed::Always),
    ("Sky vector", Needed::Always),
    ("Starting view size", Needed::Always),
    ("View scaling criterion", Needed::Always),
    ("Scale length by radius?", Needed::Always),
    ("View target zoom factor", Needed::Always),
    ("Particle shape", Needed::Always),
    ("Particle radius scaling", Needed::Always),
    ("Color override", Needed::Always),
    ("Draw color first", Needed::Always),
    ("Start at COM?", Needed::Always),
    ("Inertia control", Needed::Always),
    ("Use sliding patches?", Needed::Always),
    ("Wall data file", Needed::Always),
    ("Shape file", Needed::PovRay),
    ("Renormalize?", Needed::PovRay),
    ("Aspect ratio", Needed::PovRay),
    ("Camera light intensity", Needed::PovRay),
    ("Blob threshold", Needed::PovRay),
    ("Highlight index", Needed::PovRay),
    ("Wall time offset", Needed::WithWalls),
];

/// `Particle shape`'s value for POV-Ray output.
const POV_RAY_SHAPE: i64 = 2;

/// What an `ssdraw.par` sets for the picture (`None` where it has no line), and what of
/// it the preview does not use.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct SsdrawView {
    /// `Camera position`: where the camera is, in the walls' coordinates.
    pub camera: Option<Vec3>,
    /// `Look at/view direction`, taken as the point the camera looks at.
    pub look_at: Option<Vec3>,
    /// `Sky vector`: the picture's up.
    pub up: Option<Vec3>,
    /// `Wall data file`: the walls file it names (`None` for an empty value).
    pub walls_file: Option<String>,
    /// `Wall time offset` as written; 0 means the walls file's own `time` (§16).
    pub wall_time_offset: Option<f64>,
    /// `Aspect ratio`: the picture's width over its height.
    pub aspect: Option<f64>,
    /// Lines read that the preview does not follow, or that ssdraw does not read, with
    /// why ([`Note`]), in line order.
    pub notes: Vec<Note>,
    /// The lines of labels ssdraw reads and the preview does not use, with the label.
    pub unused: Vec<(usize, &'static str)>,
    /// The labels ssdraw needs for this file and it lacks (ssdraw aborts at the first),
    /// in [`LABELS`]' order.
    pub missing: Vec<&'static str>,
}

/// A line the preview tells back: its number (from 1) and what about it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Note {
    /// The line's number, from 1.
    pub line: usize,
    /// What the preview (or ssdraw) does with it.
    pub message: String,
}

/// A line whose value the preview cannot read, or a file ssdraw cannot read whole.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SsdrawError {
    /// The line's number, from 1.
    pub line: usize,
    /// What is wrong.
    pub message: String,
}

impl std::fmt::Display for SsdrawError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "line {}: {}", self.line, self.message)
    }
}

impl std::error::Error for SsdrawError {}

/// Reads an `ssdraw.par`'s bytes (see the module documentation).
pub fn read(bytes: impl AsRef<[u8]>) -> Result<SsdrawView, SsdrawError> {
    let bytes = bytes.as_ref();
    let mut view = SsdrawView::default();
    // Where each label was found first, by its place in LABELS.
    let mut found: [Option<usize>; LABELS.len()] = [None; LABELS.len()];
    let mut shape = None;
    let body = bytes.strip_suffix(b"\n").unwrap_or(bytes);
    let lines = (!bytes.is_empty()).then(|| body.split(|&b| b == b'\n'));
    for (k, raw) in lines.into_iter().flatten().enumerate() {
        let line = k + 1;
        let err = |message: String| SsdrawError { line, message };
        if line > MAX_LINES {
            return Err(err(format!(
                "ssdraw reads at most {MAX_LINES} lines; this file has more"
            )));
        }
        let raw = raw.strip_suffix(b"\r").unwrap_or(raw);
        if raw.len() > MAX_LINE {
            return Err(err(format!(
                "longer than the {MAX_LINE} characters a line ssdraw reads (it would split the line)"
            )));
        }
        let content = match raw.iter().position(|&b| b == b'!' || b == b'#') {
            Some(cut) => &raw[..cut],
            None => raw,
        };
        if content.iter().all(u8::is_ascii_whitespace) {
            continue;
        }
        let Some(i) = LABELS
            .iter()
            .position(|(label, _)| content.starts_with(label.as_bytes()))
        else {
            view.notes.push(Note {
                line,
                message: not_a_label(content),
            });
            continue;
        };
        let label = LABELS[i].0;
        if let Some(first) = found[i] {
            view.notes.push(Note {
                line,
                message: format!(
                    "`{label}` again: ssdraw reads line {first}'s (the first), and so does the preview; this line is not read"
                ),
            });
            continue;
        }
        found[i] = Some(line);
        let value = std::str::from_utf8(&content[label.len()..])
            .map_err(|_| err(format!("`{label}`'s value is not UTF-8 text")))?
            .trim();
        let vector = || numbers::<3>(label, value).map(Vec3::from).map_err(err);
        match label {
            "Camera position" => view.camera = Some(vector()?),
            "Look at/view direction" => view.look_at = Some(vector()?),
            "Sky vector" => view.up = Some(vector()?),
            "Wall time offset" => view.wall_time_offset = Some(numbers::<1>(label, value).map_err(err)?[0]),
            "Aspect ratio" => {
                let [a] = numbers::<1>(label, value).map_err(err)?;
                if a <= 0.0 {
                    return Err(err(format!("`{label}` must be above 0, not {a}")));
                }
                view.aspect = Some(a);
            }
            "Wall data file" => {
                if let Some(c) = value.chars().find(|c| c.is_control()) {
                    return Err(err(format!(
                        "`{label}` names a file with the control character {}: `{}`",
                        c.escape_default(),
                        shown(value)
                    )));
                }
                view.walls_file = (!value.is_empty()).then(|| value.to_string());
            }
            "Particle shape" => {
                let whole = value.parse::<i64>().map_err(|_| {
                    err(format!(
                        "`{label}` takes a whole number (0 point, 1 solid sphere, 2 POV-Ray), not `{}`",
                        shown(value)
                    ))
                })?;
                shape = Some(whole);
                view.unused.push((line, label));
            }
            "Camera option" => view.notes.push(Note {
                line,
                message: format!(
                    "`{label}` `{}` is read but not followed: the preview takes `Camera position` in the walls' own coordinates",
                    shown(value)
                ),
            }),
            "View option" => view.notes.push(Note {
                line,
                message: format!(
                    "`{label}` `{}` is read but not followed: the preview takes `Look at/view direction` as the point looked at",
                    shown(value)
                ),
            }),
            _ => view.unused.push((line, label)),
        }
    }
    // A camera at the point it looks at looks nowhere (POV-Ray refuses such a scene).
    if let (Some(camera), Some(look_at)) = (view.camera, view.look_at)
        && camera == look_at
    {
        let at = |label: &str| LABELS.iter().position(|(l, _)| *l == label);
        let line = at("Look at/view direction")
            .and_then(|i| found[i])
            .unwrap_or(0);
        let camera_line = at("Camera position").and_then(|i| found[i]).unwrap_or(0);
        return Err(SsdrawError {
            line,
            message: format!(
                "`Look at/view direction` is `Camera position` (line {camera_line}): a camera at the point it looks at looks nowhere"
            ),
        });
    }
    let needed = |need: Needed| match need {
        Needed::Always => true,
        Needed::PovRay => shape == Some(POV_RAY_SHAPE),
        Needed::WithWalls => view.walls_file.is_some(),
    };
    view.missing = (LABELS.iter().zip(&found))
        .filter(|((_, need), at)| at.is_none() && needed(*need))
        .map(|((label, _), _)| *label)
        .collect();
    Ok(view)
}

/// `N` numbers: the whitespace-separated words of `value`, each read by the tools' rule
/// (finite, neither overflowing nor underflowing), or why not.
fn numbers<const N: usize>(label: &str, value: &str) -> Result<[f64; N], String> {
    let takes = || {
        format!(
            "`{label}` takes {N} number{}, not `{}`",
            if N == 1 { "" } else { "s" },
            shown(value)
        )
    };
    let read: Vec<f64> = (value.split_ascii_whitespace())
        .map(|word| {
            walls_keywords::number::read(word)
                .map_err(|problem| format!("{}: `{}` is {problem}", takes(), shown(word)))
        })
        .collect::<Result<_, _>>()?;
    read.try_into().map_err(|_| takes())
}

/// What is said of a line that starts with no label: ssdraw does not read it; with the
/// label it may have meant, when it starts with one but for case or leading blanks.
fn not_a_label(content: &[u8]) -> String {
    let text = String::from_utf8_lossy(content);
    let text = text.trim();
    let lower = text.to_lowercase();
    let meant = LABELS
        .iter()
        .find(|(label, _)| lower.starts_with(&label.to_lowercase()));
    let hint = match meant {
        Some((label, _)) => {
            format!(" (ssdraw's labels are exact, case-sensitive and start the line: `{label}`?)")
        }
        None => String::new(),
    };
    format!(
        "`{}` starts with no label ssdraw reads: ssdraw ignores the line, and so does the preview{hint}",
        shown(text)
    )
}

/// `text` to quote in a message: control characters escaped, at most 60 characters.
fn shown(text: &str) -> String {
    let mut out: String = text
        .chars()
        .take(60)
        .flat_map(|c| {
            let escaped: Vec<char> = if c.is_control() {
                c.escape_default().collect()
            } else {
                vec![c]
            };
            escaped
        })
        .collect();
    if text.chars().nth(60).is_some() {
        out.push('…');
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shown_escapes_and_shortens() {
        assert_eq!(shown("a\u{0}b\u{1b}"), "a\\u{0}b\\u{1b}");
        assert_eq!(shown(&"x".repeat(61)), format!("{}…", "x".repeat(60)));
        assert_eq!(shown(&"x".repeat(60)), "x".repeat(60));
    }

    #[test]
    fn no_label_is_a_prefix_of_another() {
        // So a line starts with one label at most, and "the first match" is the first
        // line a label starts.
        for (a, _) in LABELS {
            for (b, _) in LABELS {
                assert!(a == b || !b.starts_with(a), "{a} / {b}");
            }
        }
    }
}
