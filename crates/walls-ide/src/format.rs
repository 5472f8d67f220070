//! Formatting a checked file, whole or a range of it, as edits.

use crate::Analysis;
use std::ops::Range;
use walls_diagnostics::Edit;
use walls_format::FormatOptions;

/// The whole text formatted, if formatting changes it (and the file can be formatted:
/// whether it can is asked first, so that a file with a million syntax errors does not
/// copy them to say no).
pub fn format(analysis: &Analysis, options: &FormatOptions) -> Option<String> {
    if !walls_format::can_format(&analysis.checked.parse) {
        return None;
    }
    let formatted = walls_format::format(&analysis.checked.parse, options).ok()?;
    (formatted.text != analysis.text()).then_some(formatted.text)
}

/// The edit that formats the items `range` touches, if there is one.
pub fn format_range(
    analysis: &Analysis,
    range: Range<usize>,
    options: &FormatOptions,
) -> Option<Edit> {
    if !walls_format::can_format(&analysis.checked.parse) {
        return None;
    }
    walls_format::format_range(&analysis.checked.parse, range, options).ok()?
}
