//! ssdraw's view, read from an `ssdraw.par`, so that a pkdgrav user's existing camera
//! carries over to `walls-sim preview --ssdraw ssdraw.par` (docs/preview.md, "ssdraw's
//! view").
//!
//! ssdraw's parameter file is a list of labelled values, one a line: the label in
//! words (`Camera position`, `Wall time offset`), then its values, with an optional `=`
//! or `:` between them and `#` starting a comment. The labels read are:
//!
//! | label | values | what the preview does |
//! |---|---|---|
//! | `Camera position` | x y z | the camera is there |
//! | `Camera look-at` (or `Look-at point`) | x y z | and looks at this point |
//! | `Camera up` | x y z | the picture's up, unless `Camera sky` is given |
//! | `Camera sky` | x y z | the picture's up (POV-Ray's `sky`) |
//! | `Wall time offset` | t | walls are drawn at the frame's time + t |
//! | `Wall data file` | name | the walls file, when the command line names none |
//! | `Aspect ratio` | w/h | the picture's width over its height |
//! | `Background colour` | r g b (0–1) | the background |
//! | `Colour N` | r g b (0–1) | colour index N (0–255) is drawn in r g b |
//!
//! `colour` may be spelt `color`; labels are matched without regard to case or
//! spacing. Every other line is reported back with its number as not used: the preview
//! draws what it can and says what it left out, never silently.

use nalgebra::Vector3;
use std::collections::BTreeMap;

type Vec3 = Vector3<f64>;

/// What an `ssdraw.par` sets for the picture; `None` where it is silent.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct SsdrawView {
    /// Where the camera is.
    pub camera: Option<Vec3>,
    /// The point it looks at.
    pub look_at: Option<Vec3>,
    /// The picture's up (`Camera sky`, else `Camera up`).
    pub up: Option<Vec3>,
    /// Added to each frame's time where the walls are drawn.
    pub wall_time_offset: Option<f64>,
    /// The walls file it names.
    pub walls_file: Option<String>,
    /// The picture's width over its height.
    pub aspect: Option<f64>,
    /// The background's red, green and blue.
    pub background: Option<[f64; 3]>,
    /// Colour indices redefined, with their red, green and blue.
    pub colours: BTreeMap<u8, [f64; 3]>,
    /// The lines not used, with their numbers (from 1) and labels.
    pub unused: Vec<(usize, String)>,
}

/// An `ssdraw.par` line that names a label the preview reads with values it cannot.
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

/// The label's canonical form: lower case, words separated by one space, `colour`
/// spelt `color`.
fn canonical(label: &str) -> String {
    label
        .split_whitespace()
        .collect::<Vec<_>>()
        .join(" ")
        .to_ascii_lowercase()
        .replace("colour", "color")
}

/// Reads an `ssdraw.par` (see the module documentation).
pub fn read(text: &str) -> Result<SsdrawView, SsdrawError> {
    let mut view = SsdrawView::default();
    let mut sky = None;
    for (k, raw) in text.lines().enumerate() {
        let line = k + 1;
        let content = raw.split('#').next().unwrap_or("").trim();
        if content.is_empty() {
            continue;
        }
        let (label, values) = split(content);
        let name = canonical(label);
        let err = |message: String| SsdrawError { line, message };
        let numbers = |n: usize| -> Result<Vec<f64>, SsdrawError> {
            let words: Vec<&str> = values.split_whitespace().collect();
            // The tools' one rule for numbers: not finite, overflow, underflow refused.
            let parsed: Option<Vec<f64>> = (words.iter())
                .map(|w| walls_keywords::number::read(w).ok())
                .collect();
            match parsed {
                Some(v) if v.len() == n => Ok(v),
                _ => Err(err(format!(
                    "`{label}` takes {n} number{}, not `{values}`",
                    if n == 1 { "" } else { "s" }
                ))),
            }
        };
        let vector = || numbers(3).map(|v| Vec3::new(v[0], v[1], v[2]));
        match name.as_str() {
            "camera position" => view.camera = Some(vector()?),
            "camera look-at" | "look-at point" => view.look_at = Some(vector()?),
            "camera up" => view.up = Some(vector()?),
            "camera sky" => sky = Some(vector()?),
            "background color" => view.background = Some(rgb(&numbers(3)?).map_err(err)?),
            "wall time offset" => view.wall_time_offset = Some(numbers(1)?[0]),
            "aspect ratio" => {
                let a = numbers(1)?[0];
                if a <= 0.0 {
                    return Err(err(format!("`{label}` must be above 0, not {a}")));
                }
                view.aspect = Some(a);
            }
            "wall data file" => {
                if values.is_empty() {
                    return Err(err(format!("`{label}` names no file")));
                }
                view.walls_file = Some(values.to_string());
            }
            _ => match colour_index(&name) {
                Some(index) => {
                    let index = index.map_err(err)?;
                    let rgb = rgb(&numbers(3)?).map_err(err)?;
                    view.colours.insert(index, rgb);
                }
                None => view.unused.push((line, label.to_string())),
            },
        }
    }
    if sky.is_some() {
        view.up = sky;
    }
    Ok(view)
}

/// The labels read without a colour index, in canonical form (lower case, single
/// spaces, `color`); `read` matches these.
const LABELS: [&str; 9] = [
    "camera position",
    "camera look-at",
    "look-at point",
    "camera up",
    "camera sky",
    "background color",
    "wall time offset",
    "wall data file",
    "aspect ratio",
];

/// The label and the values of a line: split at the first `=` or `:` if it has one,
/// else after the longest run of leading words that is a label read (`Colour N`
/// included), else before the first word that starts like a number.
fn split(content: &str) -> (&str, &str) {
    if let Some(i) = content.find(['=', ':']) {
        return (content[..i].trim(), content[i + 1..].trim());
    }
    let ends: Vec<usize> = content
        .split_whitespace()
        .map(|w| w.as_ptr() as usize - content.as_ptr() as usize + w.len())
        .collect();
    for &end in ends.iter().rev() {
        if LABELS.contains(&canonical(&content[..end]).as_str()) {
            return (content[..end].trim(), content[end..].trim());
        }
    }
    if ends.len() >= 2 && canonical(&content[..ends[0]]) == "color" {
        return (content[..ends[1]].trim(), content[ends[1]..].trim());
    }
    let first_number = content
        .split_whitespace()
        .find(|w| w.starts_with(|c: char| c.is_ascii_digit() || matches!(c, '-' | '+' | '.')));
    match first_number {
        Some(w) => {
            let i = w.as_ptr() as usize - content.as_ptr() as usize;
            (content[..i].trim(), content[i..].trim())
        }
        None => (content, ""),
    }
}

/// `Some` for a `color N` label: N as a colour index, or why it is not one.
fn colour_index(name: &str) -> Option<Result<u8, String>> {
    let rest = name.strip_prefix("color ")?;
    Some(
        rest.parse::<u8>()
            .map_err(|_| format!("`{rest}` is not a colour index (0 to 255)")),
    )
}

/// Red, green and blue from 0 to 1.
fn rgb(v: &[f64]) -> Result<[f64; 3], String> {
    if v.iter().all(|x| (0.0..=1.0).contains(x)) {
        Ok([v[0], v[1], v[2]])
    } else {
        Err(format!(
            "colours are red, green and blue from 0 to 1, not {} {} {}",
            v[0], v[1], v[2]
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_view_carries_over() {
        let text = "\
# my view
Camera position = 0 -10 5
Camera look-at: 0 0 1
Camera up 0 0 1
Camera sky 0 1 0
Wall time offset = 0.25
Wall data file walls.dat
Aspect ratio = 1.5
Background colour = 0 0 0.2
Colour 16 = 1 0.5 0
color 3 0 1 0
Particle shape = 2
";
        let view = read(text).unwrap();
        assert_eq!(view.camera, Some(Vec3::new(0.0, -10.0, 5.0)));
        assert_eq!(view.look_at, Some(Vec3::new(0.0, 0.0, 1.0)));
        assert_eq!(view.up, Some(Vec3::y()), "the sky wins over up");
        assert_eq!(view.wall_time_offset, Some(0.25));
        assert_eq!(view.walls_file.as_deref(), Some("walls.dat"));
        assert_eq!(view.aspect, Some(1.5));
        assert_eq!(view.background, Some([0.0, 0.0, 0.2]));
        assert_eq!(view.colours[&16], [1.0, 0.5, 0.0]);
        assert_eq!(view.colours[&3], [0.0, 1.0, 0.0]);
        assert_eq!(view.unused, [(12, "Particle shape".to_string())]);
    }

    #[test]
    fn bad_values_name_their_line() {
        for (text, message) in [
            (
                "\nCamera position = 1 2\n",
                "line 2: `Camera position` takes 3 numbers, not `1 2`",
            ),
            (
                "Colour 300 = 1 1 1",
                "line 1: `300` is not a colour index (0 to 255)",
            ),
            (
                "Background color = 2 0 0",
                "line 1: colours are red, green and blue from 0 to 1, not 2 0 0",
            ),
            (
                "Aspect ratio = -1",
                "line 1: `Aspect ratio` must be above 0, not -1",
            ),
            ("Wall data file =", "line 1: `Wall data file` names no file"),
            // A number the tools' rule refuses (1e-400 was read as 0).
            (
                "Camera up = 0 0 1e-400",
                "line 1: `Camera up` takes 3 numbers, not `0 0 1e-400`",
            ),
        ] {
            assert_eq!(read(text).unwrap_err().to_string(), message, "{text:?}");
        }
    }
}
