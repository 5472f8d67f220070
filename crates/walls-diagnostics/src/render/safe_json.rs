//! JSON that holds no hazard ([`crate::terminal`]) as it is, for the machine formats
//! (`json`, `sarif`, `gitlab`): serde_json escapes the C0 controls (ESC as `\u001b`);
//! this formatter writes DEL, the C1 controls, the line separators and the bidirectional
//! controls as `\uXXXX` escapes too. Any JSON reader reads the same strings back, and a
//! report shown in a terminal (`cat report.json`, a CI log) acts on nothing.

use crate::terminal;
use serde::Serialize;
use serde_json::ser::{Formatter, PrettyFormatter};
use std::io::{self, Write};

/// Writes `value` as pretty-printed JSON (as `serde_json::to_writer_pretty` does), with
/// every hazard escaped.
pub(crate) fn write(out: &mut dyn Write, value: &impl Serialize) -> io::Result<()> {
    let mut serializer = serde_json::Serializer::with_formatter(out, Safe(PrettyFormatter::new()));
    value.serialize(&mut serializer).map_err(io::Error::from)
}

/// serde_json's pretty formatter, but for the text of strings.
struct Safe<'a>(PrettyFormatter<'a>);

impl Formatter for Safe<'_> {
    fn write_string_fragment<W: ?Sized + Write>(
        &mut self,
        writer: &mut W,
        fragment: &str,
    ) -> io::Result<()> {
        let mut at = 0;
        for (i, c) in fragment
            .char_indices()
            .filter(|&(_, c)| terminal::is_hazard(c))
        {
            writer.write_all(&fragment.as_bytes()[at..i])?;
            // Every hazard is in the Basic Multilingual Plane: one `\u` escape.
            write!(writer, "\\u{:04x}", u32::from(c))?;
            at = i + c.len_utf8();
        }
        writer.write_all(&fragment.as_bytes()[at..])
    }

    fn begin_array<W: ?Sized + Write>(&mut self, writer: &mut W) -> io::Result<()> {
        self.0.begin_array(writer)
    }

    fn end_array<W: ?Sized + Write>(&mut self, writer: &mut W) -> io::Result<()> {
        self.0.end_array(writer)
    }

    fn begin_array_value<W: ?Sized + Write>(
        &mut self,
        writer: &mut W,
        first: bool,
    ) -> io::Result<()> {
        self.0.begin_array_value(writer, first)
    }

    fn end_array_value<W: ?Sized + Write>(&mut self, writer: &mut W) -> io::Result<()> {
        self.0.end_array_value(writer)
    }

    fn begin_object<W: ?Sized + Write>(&mut self, writer: &mut W) -> io::Result<()> {
        self.0.begin_object(writer)
    }

    fn end_object<W: ?Sized + Write>(&mut self, writer: &mut W) -> io::Result<()> {
        self.0.end_object(writer)
    }

    fn begin_object_key<W: ?Sized + Write>(
        &mut self,
        writer: &mut W,
        first: bool,
    ) -> io::Result<()> {
        self.0.begin_object_key(writer, first)
    }

    fn end_object_key<W: ?Sized + Write>(&mut self, writer: &mut W) -> io::Result<()> {
        self.0.end_object_key(writer)
    }

    fn begin_object_value<W: ?Sized + Write>(&mut self, writer: &mut W) -> io::Result<()> {
        self.0.begin_object_value(writer)
    }

    fn end_object_value<W: ?Sized + Write>(&mut self, writer: &mut W) -> io::Result<()> {
        self.0.end_object_value(writer)
    }
}

#[cfg(test)]
mod tests {
    use super::write;

    #[test]
    fn no_hazard_stands_as_it_is_and_the_strings_read_back() {
        let value = serde_json::json!({
            "message": "# \u{1b}]52;c;aGk=\u{7} \u{7f}\u{9b}2J \u{202e}x\u{2069} \u{2028} μ\r\n",
            "a\u{85}": [1, "\u{1b}"],
        });
        let mut out = Vec::new();
        write(&mut out, &value).unwrap();
        let text = String::from_utf8(out).unwrap();
        assert_eq!(
            text,
            "{\n  \"a\\u0085\": [\n    1,\n    \"\\u001b\"\n  ],\n  \"message\": \
             \"# \\u001b]52;c;aGk=\\u0007 \\u007f\\u009b2J \\u202ex\\u2069 \\u2028 μ\\r\\n\"\n}"
        );
        let read: serde_json::Value = serde_json::from_str(&text).unwrap();
        assert_eq!(read, value);
    }
}
