//! pkdgrav's per-colour cohesion file (`achCohesionFile`, docs/pkdgrav-physics.md §7):
//! the number of colours N, the rule that combines two colours' coefficients (0 none, 1
//! mean, 2 max, 3 min), then N lines of `color coefficient`. Numbers are separated by
//! white space (N and the rule may share a line). Every error names the file and the
//! line.

use super::{FileError, InputError, error};
use crate::contact::cohesion::{Colours, Rule};
use crate::warning::Warning;

/// The whitespace-separated words of `text`, each with its line (1-based).
fn words(text: &str) -> Vec<(usize, &str)> {
    text.lines()
        .enumerate()
        .flat_map(|(i, l)| l.split_whitespace().map(move |w| (i + 1, w)))
        .collect()
}

/// Reads a cohesion file's text: the colours, and the warnings about its subnormal
/// coefficients (W701, located in the file: `line 3: …`).
pub fn read_cohesion(text: &str) -> Result<(Colours, Vec<Warning>), InputError> {
    let words = words(text);
    let last_line = text.lines().count().max(1);
    let mut next = words.iter().copied();
    let mut take = |what: &str| {
        next.next().ok_or_else(|| {
            error(
                format!("line {last_line}"),
                format!("the file ends where {what} should be"),
            )
        })
    };
    let (n_line, n_word) = take("the number of colours")?;
    let count: usize = n_word.parse().map_err(|_| {
        error(
            format!("line {n_line}"),
            format!("the number of colours is `{n_word}`, not a whole number of 0 or more"),
        )
    })?;
    // pkdgrav reads the count into a C int, which would hold another number.
    if count > i32::MAX as usize {
        return Err(error(
            format!("line {n_line}"),
            format!(
                "the number of colours is `{n_word}`, beyond a C int, which pkdgrav reads it into (it would read another number): give at most {}",
                i32::MAX
            ),
        ));
    }
    let (r_line, r_word) = take("the rule (0 none, 1 mean, 2 max, 3 min)")?;
    let rule = r_word
        .parse::<i64>()
        .ok()
        .and_then(Rule::from_number)
        .ok_or_else(|| {
            error(
                format!("line {r_line}"),
                format!(
                    "the rule is `{r_word}`; it must be 0 (none), 1 (mean), 2 (max) or 3 (min)"
                ),
            )
        })?;
    // The count is the file's word, not memory to reserve: a file of a few bytes may
    // announce 10¹⁰ colours, and is then short of them.
    let mut coefficients: Vec<(i32, f64)> = Vec::with_capacity(count.min(words.len() / 2));
    let mut listed = std::collections::HashSet::new();
    let mut warnings = Vec::new();
    for k in 1..=count {
        let (c_line, c_word) = take(&format!("colour {k} of {count}"))?;
        let colour: i32 = c_word.parse().map_err(|_| {
            error(
                format!("line {c_line}"),
                format!("the colour is `{c_word}`, not a whole number"),
            )
        })?;
        let (x_line, x_word) = take(&format!("the coefficient of colour {colour}"))?;
        let at = || format!("line {x_line}: the coefficient of colour {colour}");
        let x = super::number(x_word, at, &mut warnings).map_err(|why| {
            error(
                format!("line {x_line}"),
                format!("the coefficient of colour {colour} is `{x_word}`, {why}"),
            )
        })?;
        if !listed.insert(colour) {
            return Err(error(
                format!("line {c_line}"),
                format!("colour {colour} is listed twice"),
            ));
        }
        coefficients.push((colour, x));
    }
    if let Some((line, word)) = next.next() {
        return Err(error(
            format!("line {line}"),
            format!("`{word}` follows the {count} colours the file's first number announces"),
        ));
    }
    Ok((Colours { rule, coefficients }, warnings))
}

/// Reads the cohesion file at `path`, the warnings located in it.
pub fn read_file(path: &str) -> Result<(Colours, Vec<Warning>), FileError> {
    let text = std::fs::read_to_string(path).map_err(|e| FileError::read(path, e))?;
    let (colours, warnings) = read_cohesion(&text).map_err(|e| FileError::input(path, e))?;
    Ok((colours, super::in_file(path, warnings)))
}
