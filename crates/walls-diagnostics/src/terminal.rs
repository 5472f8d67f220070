//! Text from input, made safe to show: the one definition of the characters a terminal or
//! an editor acts on, or draws elsewhere, instead of showing them, and their escapes.
//!
//! A walls file, a `.par` file, a mesh or a file name can hold bytes that a terminal
//! obeys: `ESC ] 52 ; c ; … BEL` (OSC 52) sets the clipboard, `ESC [ 2 J` clears the
//! screen, a carriage return writes over what came before, and the bidirectional overrides
//! reorder what a reviewer sees (the "Trojan Source" attack). Such a character is a
//! *hazard*:
//!
//! * the C0 controls U+0000–U+001F except tab and line feed, and a carriage return unless
//!   it ends a line (`\r\n`, which terminals and editors show as a line end);
//! * DEL, U+007F, and the C1 controls U+0080–U+009F (U+0085 is a line end to some
//!   editors);
//! * the line and paragraph separators U+2028 and U+2029, which editors show as line
//!   breaks where pkdgrav sees none;
//! * the bidirectional embeddings and overrides U+202A–U+202E and the isolates
//!   U+2066–U+2069.
//!
//! [`escape`] shows each hazard as the escape a Rust string literal would use: `\xHH`
//! (two lower-case hexadecimal digits) for U+0000–U+007F (`\x1b` for ESC, `\x07` for BEL,
//! `\r` as `\x0d`), `\u{H…}` (lower-case, no leading zeros) for the others (`\u{85}`,
//! `\u{202e}`). The escaped text holds no hazard, so escaping twice changes nothing. A
//! backslash is not escaped: the escapes are for reading, not for reading back.
//!
//! Every human output of the tools shows input through [`escape`] (or [`Escaped`]):
//! the human renderer of diagnostics, the command line's messages, diffs. The machine
//! formats keep the text and are safe in their own way (JSON escapes these characters as
//! `\u001b`; GitHub's workflow commands take the escaped text, as they are shown in a log).
//! `walls-syntax` reports hazards in walls files with [`find`] (S006).

use std::borrow::Cow;
use std::fmt;

/// Whether `c` is a hazard (the module documentation lists them), wherever it stands;
/// a carriage return before a line feed is not one, which only [`find`] and [`escape`],
/// seeing what follows, can tell.
pub const fn is_hazard(c: char) -> bool {
    matches!(
        c,
        '\0'..='\x08'
            | '\x0b'..='\x1f'
            | '\x7f'..='\u{9f}'
            | '\u{2028}'..='\u{202e}'
            | '\u{2066}'..='\u{2069}'
    )
}

/// Whether byte `b` may start a hazard: a control byte other than tab and line feed,
/// DEL, or the first byte of a C1 control (0xC2) or of U+2028–U+2069 (0xE2).
const fn may_start_hazard(b: u8) -> bool {
    (b < 0x20 && b != b'\t' && b != b'\n') | (b == 0x7f) | (b == 0xc2) | (b == 0xe2)
}

/// Bytes looked at together when searching: a block without a byte that may start a
/// hazard (nearly every block of a walls file) is passed over in a few instructions.
const BLOCK: usize = 32;

/// The first hazard of `text` at or after byte `from` (a character boundary): its
/// offset and the character.
pub fn find(text: &str, from: usize) -> Option<(usize, char)> {
    let bytes = text.as_bytes();
    let mut at = from;
    while at < bytes.len() {
        let end = (at + BLOCK).min(bytes.len());
        let block = &bytes[at..end];
        // No early exit: the compiler turns this into a few vector instructions.
        if !block
            .iter()
            .fold(false, |any, &b| any | may_start_hazard(b))
        {
            at = end;
            continue;
        }
        for (i, &b) in block.iter().enumerate() {
            let i = at + i;
            if may_start_hazard(b)
                && let Some(c) = at_offset(text, i)
            {
                return Some((i, c));
            }
        }
        at = end;
    }
    None
}

/// The hazard at byte `i` of `text`, if one starts there.
pub fn at_offset(text: &str, i: usize) -> Option<char> {
    let c = text.get(i..)?.chars().next()?;
    let line_end = c == '\r' && text.as_bytes().get(i + 1) == Some(&b'\n');
    (is_hazard(c) && !line_end).then_some(c)
}

/// Every run of hazards of `text` (consecutive hazards make one run), as byte ranges.
pub fn runs(text: &str) -> impl Iterator<Item = std::ops::Range<usize>> + '_ {
    let mut from = 0;
    std::iter::from_fn(move || {
        let (start, c) = find(text, from)?;
        let mut end = start + c.len_utf8();
        while let Some(c) = at_offset(text, end) {
            end += c.len_utf8();
        }
        from = end;
        Some(start..end)
    })
}

/// `text` with every hazard shown as its escape (see the module documentation); borrowed
/// when it has none.
pub fn escape(text: &str) -> Cow<'_, str> {
    let Some((first, _)) = find(text, 0) else {
        return Cow::Borrowed(text);
    };
    let mut out = String::with_capacity(text.len() + 8);
    out.push_str(&text[..first]);
    let mut at = first;
    while let Some((i, c)) = find(text, at) {
        out.push_str(&text[at..i]);
        push_escape(&mut out, c);
        at = i + c.len_utf8();
    }
    out.push_str(&text[at..]);
    Cow::Owned(out)
}

/// Appends the escape of `c`: `\xHH` up to U+007F, `\u{H…}` above.
fn push_escape(out: &mut String, c: char) {
    use fmt::Write;
    let code = u32::from(c);
    // Writing to a String cannot fail.
    let _ = if code < 0x80 {
        write!(out, "\\x{code:02x}")
    } else {
        write!(out, "\\u{{{code:x}}}")
    };
}

/// A value whose text is shown with its hazards escaped: `format!("{}", Escaped(&name))`.
#[derive(Debug, Clone, Copy)]
pub struct Escaped<'a>(pub &'a str);

impl fmt::Display for Escaped<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&escape(self.0))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn osc_52_and_the_other_hazards_are_escaped() {
        assert_eq!(
            escape("# \x1b]52;c;aGk=\x07 done"),
            "# \\x1b]52;c;aGk=\\x07 done"
        );
        assert_eq!(
            escape("a\u{202e}b\u{2066}c\u{85}d\x7f"),
            "a\\u{202e}b\\u{2066}c\\u{85}d\\x7f"
        );
        assert_eq!(
            escape("\0\x0b\x0c\u{2028}\u{9f}"),
            "\\x00\\x0b\\x0c\\u{2028}\\u{9f}"
        );
    }

    #[test]
    fn tabs_line_ends_and_other_text_are_kept() {
        for kept in [
            "",
            "plain",
            "a\tb\nc",
            "a\r\nb\r\n",
            "μ … ─ é 中 \u{feff} \u{200f}",
        ] {
            assert!(matches!(escape(kept), Cow::Borrowed(_)), "{kept:?}");
        }
        // A carriage return that does not end a line writes over it.
        assert_eq!(escape("safe\rEVIL\r\n"), "safe\\x0dEVIL\r\n");
        assert_eq!(escape("ends with\r"), "ends with\\x0d");
        assert_eq!(escape("\r\r\n"), "\\x0d\r\n");
    }

    #[test]
    fn escaping_twice_changes_nothing() {
        let once = escape("\x1b[2J\u{202e}\r!").into_owned();
        assert_eq!(escape(&once), once);
    }

    #[test]
    fn every_hazard_and_only_hazards_are_found() {
        let text: String = (0..0x2100u32).filter_map(char::from_u32).collect();
        let found: Vec<char> = runs(&text)
            .flat_map(|r| text[r].chars().collect::<Vec<_>>())
            .collect();
        let expected: Vec<char> = text.chars().filter(|&c| is_hazard(c)).collect();
        assert_eq!(found, expected);
        assert!(expected.contains(&'\r') && !expected.contains(&'\t') && !expected.contains(&'\n'));
        assert_eq!(expected.len(), 30 + 1 + 32 + 7 + 4);
    }

    #[test]
    fn runs_are_consecutive_hazards_in_blocks_and_across_them() {
        let text = format!(
            "{}\x1b]52;c;x\x07\x07 \u{202e}\x1b|{}\r",
            "a".repeat(30),
            "b".repeat(40)
        );
        let found: Vec<_> = runs(&text).collect();
        assert_eq!(found, [30..31, 38..40, 41..45, 86..87]);
        assert_eq!(runs(&"a\r\n".repeat(100)).count(), 0);
    }

    #[test]
    fn escaped_displays_the_escape() {
        assert_eq!(format!("[{}]", Escaped("a\x1bb")), "[a\\x1bb]");
    }
}
