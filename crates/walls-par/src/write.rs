//! Writing a `.par` file that pkdgrav's reader takes as meant (docs/pkdgrav-physics.md
//! §14): one `key = value` line per setting, each value written for its key's type so
//! that it reads back exactly, comment lines (a `#` in the first column) above it, and no
//! line of 127 bytes or more, which pkdgrav would split.
//!
//! [`Setting`]s are rendered by [`render`], which refuses a key the build does not
//! register and a value no line can hold; comments are folded to fit and cleaned of what
//! pkdgrav refuses anywhere (`!`) and of control characters.

use crate::keys::{self, Kind};
use crate::options::Build;

/// The longest line pkdgrav reads whole: 127 bytes, less the newline it counts.
pub const MAX_LINE: usize = 126;

/// Where comments are folded: short enough to read beside the keys.
const FOLD: usize = 96;

/// A value as a `.par` line writes it.
#[derive(Debug, Clone, PartialEq)]
pub enum Value {
    /// A double: written in the shortest form that reads back as the same double.
    Real(f64),
    /// A whole number (an `int` key); wide enough for any count the tools hold, so that a
    /// value beyond pkdgrav's int is refused as itself.
    Int(i128),
    /// A switch (a `bool` key): 1 or 0.
    Bool(bool),
    /// A string, written as is.
    Text(String),
}

/// One `key = value` line of the file and the comment lines above it.
#[derive(Debug, Clone, PartialEq)]
pub struct Setting {
    /// The key, as pkdgrav registers it.
    pub key: &'static str,
    /// Its value.
    pub value: Value,
    /// What the comment above it says (folded to fit, see [`render`]); empty for none.
    pub comment: String,
}

/// A part of the file: a comment heading it (perhaps empty) and its settings.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Section {
    /// The comment above the section.
    pub heading: String,
    /// Its settings, in the order written.
    pub settings: Vec<Setting>,
    /// Lines copied as they are (from another `.par` file, checked already), after the
    /// settings, each with its comment.
    pub copied: Vec<(String, String)>,
}

/// `x` as a `.par` file writes a double: the shortest digits that read back as `x`, plain
/// from 10⁻⁴ to 10¹⁵ unless the exponent form is more than three characters shorter,
/// else with an exponent (C's `strtod`, and so pkdgrav's `%lf`, read either exactly).
pub fn real(x: f64) -> String {
    let plain = format!("{x}");
    let exponent = format!("{x:e}");
    let ordinary = x == 0.0 || (1e-4..1e15).contains(&x.abs());
    if ordinary && plain.len() <= exponent.len() + 3 {
        plain
    } else {
        exponent
    }
}

impl Value {
    /// The text of the value for a key of type `kind`, or why it cannot be written so.
    fn text(&self, kind: Kind) -> Result<String, String> {
        let mismatch = || format!("a {} key cannot take {self:?}", kind.as_str());
        match (self, kind) {
            (Value::Real(x), Kind::Double) if x.is_finite() => Ok(real(*x)),
            (Value::Real(x), Kind::Double) => Err(format!("{x} is not a number pkdgrav reads")),
            (Value::Int(n), Kind::Int) => i32::try_from(*n)
                .map(|n| n.to_string())
                .map_err(|_| format!("{n} is beyond pkdgrav's int (at most {})", i32::MAX)),
            (Value::Bool(b), Kind::Bool | Kind::Int) => Ok(u8::from(*b).to_string()),
            (Value::Text(s), Kind::Str) => {
                let bad = s
                    .chars()
                    .any(|c| c.is_control() || c == '#' || c == '!' || c == '"');
                if s.trim().is_empty() || s.trim() != s || bad {
                    Err(format!(
                        "{s:?} cannot be written as a .par string (blank, or with a #, !, quote or control character)"
                    ))
                } else {
                    Ok(s.clone())
                }
            }
            _ => Err(mismatch()),
        }
    }
}

/// `text` as comment lines: `# ` and at most [`FOLD`] bytes of words each (a longer word
/// is cut at [`MAX_LINE`]), with `!` and control characters replaced by `?` (pkdgrav
/// refuses a `!` in any line).
pub fn comment(text: &str) -> String {
    let clean: String = text
        .chars()
        .map(|c| if c == '!' || c.is_control() { '?' } else { c })
        .collect();
    let mut out = String::new();
    let mut line = String::from("#");
    for word in clean.split(' ').filter(|w| !w.is_empty()) {
        if line.len() > 1 && line.len() + 1 + word.len() > FOLD {
            out.push_str(&line);
            out.push('\n');
            line = String::from("#");
        }
        line.push(' ');
        line.push_str(word);
        if line.len() > MAX_LINE {
            let mut cut = MAX_LINE;
            while !line.is_char_boundary(cut) {
                cut -= 1;
            }
            line.truncate(cut);
        }
    }
    if line.len() > 1 {
        out.push_str(&line);
        out.push('\n');
    }
    out
}

/// The `.par` file of `header` (a comment) and `sections` for `build`: an error naming
/// the key when the build does not register one, or a value cannot be written for its
/// type or on one line.
pub fn render(header: &str, sections: &[Section], build: &Build) -> Result<String, String> {
    let mut out = comment(header);
    for section in sections {
        out.push('\n');
        out.push_str(&comment(&section.heading));
        for s in &section.settings {
            let Some(key) = keys::registered(s.key, build) else {
                return Err(format!(
                    "`{}` is not a key the build ({}) registers",
                    s.key,
                    build.names()
                ));
            };
            let value = s
                .value
                .text(key.kind)
                .map_err(|e| format!("`{}`: {e}", s.key))?;
            let line = format!("{:<24} = {value}", s.key);
            if line.len() > MAX_LINE {
                return Err(format!(
                    "`{}`: its line would be {} bytes, more than the {MAX_LINE} pkdgrav reads whole",
                    s.key,
                    line.len()
                ));
            }
            out.push_str(&comment(&s.comment));
            out.push_str(&line);
            out.push('\n');
        }
        for (line, why) in &section.copied {
            out.push_str(&comment(why));
            out.push_str(line);
            out.push('\n');
        }
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reals_read_back_exactly_in_their_shorter_form() {
        for x in [
            0.0,
            -1.0,
            0.8,
            1.474327e-11,
            1e308,
            5e-324,
            2.0 / 7.0,
            -123456.789,
        ] {
            let text = real(x);
            assert_eq!(
                text.parse::<f64>().unwrap().to_bits(),
                x.to_bits(),
                "{text}"
            );
            assert!(text.len() <= 24, "{text}");
        }
        assert_eq!(real(1.474327e-11), "1.474327e-11");
        assert_eq!(real(0.5), "0.5");
        assert_eq!(real(0.001), "0.001");
        assert_eq!(real(4.055619930475087e-5), "4.055619930475087e-5");
        assert_eq!(real(1e20), "1e20");
        assert_eq!(real(-1.0), "-1");
    }

    #[test]
    fn comments_fold_and_lose_what_pkdgrav_refuses() {
        let long = "word ".repeat(60);
        let c = comment(&format!("{long} a ! b \u{1b}[31m"));
        assert!(c.lines().all(|l| l.starts_with("# ") && l.len() <= FOLD));
        assert!(!c.contains('!') && !c.contains('\u{1b}'));
        let one = comment(&"x".repeat(300));
        assert_eq!(one.lines().count(), 1);
        assert_eq!(one.trim_end().len(), MAX_LINE);
        assert_eq!(comment(""), "");
    }

    #[test]
    fn render_refuses_what_pkdgrav_would_not_read() {
        let build = Build::default();
        let section = |key, value| Section {
            heading: String::new(),
            settings: vec![Setting {
                key,
                value,
                comment: String::new(),
            }],
            copied: Vec::new(),
        };
        let ok = render("h", &[section("dDelta", Value::Real(1e-3))], &build).unwrap();
        assert_eq!(ok, "# h\n\ndDelta                   = 0.001\n");
        for (key, value) in [
            ("dFooBar", Value::Real(1.0)),
            ("nSteps", Value::Int(1 << 40)),
            ("dDelta", Value::Real(f64::NAN)),
            ("achOutName", Value::Text("a # b".into())),
            ("achOutName", Value::Text("x".repeat(120))),
            ("dDelta", Value::Int(1)),
        ] {
            assert!(render("", &[section(key, value)], &build).is_err(), "{key}");
        }
        let text = render("", &[section("bDoGravity", Value::Bool(false))], &build).unwrap();
        assert!(text.ends_with("bDoGravity               = 0\n"));
    }
}
