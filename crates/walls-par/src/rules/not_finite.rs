//! P005 `par-not-finite`: a number pkdgrav reads as infinity, NaN or 0 where digits say
//! otherwise (`1e400`, `inf`, `1e-400`), or an integer beyond a C `int`, which `%d` reads
//! as some other number.
//!
//! Reported as the values are read.

use crate::keys::Key;
use crate::value::Value;
use std::ops::Range;
use walls_diagnostics::{Code, Diagnostic};

/// A number no run can use as written.
pub static NOT_FINITE: Code = Code {
    id: "P005",
    name: "par-not-finite",
    summary: "a `.par` number pkdgrav reads as infinity, NaN or 0, or an integer beyond a C int",
    explanation: concat!(
        "pkdgrav reads doubles with C's `%lf`, which takes `inf`, `nan` and `1e400` (infinity)
without a word and reads `1e-400` as 0; it reads integers with `%d`, which gives some
other number for one beyond a C `int` (2147483647). The run then goes on with a value
nobody wrote.

Bad:
```par\n",
        settled!(),
        "dDelta               = 1e-400
nSteps               = 1000
dKn                  = 1e5
iCheckInterval       = 0
```

Good:
```par\n",
        clean!(),
        "```
"
    ),
};

/// Reports a double pkdgrav reads as infinity, NaN, or 0 from digits that are not all
/// zeros (`written`, at `span`).
pub(crate) fn check_value(
    key: &Key,
    value: &Value,
    written: &str,
    span: Range<usize>,
    out: &mut Vec<Diagnostic>,
) {
    let Value::Double(x) = *value else {
        return;
    };
    let reads = if x.is_nan() {
        "NaN"
    } else if x.is_infinite() {
        "infinity"
    } else if x == 0.0 && zero_digits_differ(written) {
        "0"
    } else {
        return;
    };
    out.push(
        Diagnostic::error(
            &NOT_FINITE,
            span,
            format!("pkdgrav reads `{}` = `{written}` as {reads}", key.name),
        )
        .with_help("write a finite number a double holds (from about 2.2e-308 to 1.8e308 in size)"),
    );
}

/// Whether the mantissa of `written` (before its exponent) has a digit other than 0.
fn zero_digits_differ(written: &str) -> bool {
    let body = written.trim_start_matches(['-', '+']);
    if let Some(hex) = body.strip_prefix("0x").or_else(|| body.strip_prefix("0X")) {
        let mantissa = hex.split(['p', 'P']).next().unwrap_or("");
        return mantissa.bytes().any(|b| b.is_ascii_hexdigit() && b != b'0');
    }
    let mantissa = body.split(['e', 'E']).next().unwrap_or("");
    mantissa.bytes().any(|b| matches!(b, b'1'..=b'9'))
}

/// Reports an integer value beyond a C `int` (at `span` of `text`).
pub(crate) fn beyond_int(key: &Key, span: Range<usize>, text: &str, out: &mut Vec<Diagnostic>) {
    let written = text[span.clone()]
        .split('#')
        .next()
        .unwrap_or("")
        .trim_end();
    out.push(
        Diagnostic::error(
            &NOT_FINITE,
            span,
            format!(
                "`{}` = `{written}` is beyond a C int: pkdgrav's %d reads some other number",
                key.name
            ),
        )
        .with_help(format!("give at most {}", i32::MAX)),
    );
}
