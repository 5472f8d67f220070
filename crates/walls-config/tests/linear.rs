//! Every list of a settings file is read and applied in time linear in its length:
//! `ignore`, the globs of `per-file-ignores` and a glob's codes, `include` and
//! `exclude`, each with 100,000 entries (a quarter of that in a debug build;
//! `WALLS_LINEAR_SCALE` sets the factor), and [`Lint::filter`] over 100,000 diagnostics
//! with 100,000 ignores. Four times the entries must take less than eight times as long
//! (linear time gives four, quadratic sixteen), the best of three runs each; times under
//! 20 ms count as 20 ms, so that noise on a busy machine is no failure. The times are
//! printed (`--nocapture`). Before, every entry's line and column was counted from the
//! start of the file, and every diagnostic compared with every ignore: 40,000 `ignore`
//! entries took 1.5 s, and 5,000 to 10,000 `per-file-ignores` 0.3 to 1.0 s.

use std::fmt::Write;
use std::path::Path;
use std::time::{Duration, Instant};
use walls_config::{Lint, load};
use walls_diagnostics::Diagnostic;

/// Times below this are noise: they count as this.
const FLOOR: Duration = Duration::from_millis(20);

/// The sizes' factor: `WALLS_LINEAR_SCALE`, else 1 in an optimised build and 0.25 in a
/// debug build.
fn scale() -> f64 {
    std::env::var("WALLS_LINEAR_SCALE")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(if cfg!(debug_assertions) { 0.25 } else { 1.0 })
}

/// A settings file with `n` entries in the list `list` names.
fn settings(list: &str, n: usize) -> String {
    let mut text = String::new();
    let codes = ["C201", "unused-default", "C202", "S103"];
    let quoted = |i: usize| format!("\"{}\"", codes[i % codes.len()]);
    let globs = |i: usize| format!("\"g{i}/*.walls\"");
    let joined = |f: &dyn Fn(usize) -> String| (0..n).map(f).collect::<Vec<_>>().join(", ");
    match list {
        "ignore" => writeln!(text, "[lint]\nignore = [{}]", joined(&quoted)),
        "per-file globs" => {
            text.push_str("[lint.per-file-ignores]\n");
            (0..n).try_for_each(|i| writeln!(text, "\"g{i}/*.walls\" = [\"C201\"]"))
        }
        "per-file codes" => writeln!(
            text,
            "[lint.per-file-ignores]\n\"*.walls\" = [{}]",
            joined(&quoted)
        ),
        "include" => writeln!(text, "[lint]\ninclude = [{}]", joined(&globs)),
        "exclude" => writeln!(text, "[lint]\nexclude = [{}]", joined(&globs)),
        _ => unreachable!(),
    }
    .unwrap();
    text
}

/// `n` warnings of a few codes.
fn diagnostics(n: usize) -> Vec<Diagnostic> {
    let codes = ["C201", "C202", "C203", "S103"].map(|c| walls_ide::find_code(c).unwrap());
    (0..n)
        .map(|i| Diagnostic::warning(codes[i % codes.len()], i..i + 1, "a warning"))
        .collect()
}

/// The time to read `text` as a settings file, and to apply it to `n` diagnostics of a
/// file it matches; how many diagnostics are left.
fn time(dir: &Path, text: &str, n: usize) -> (Duration, usize) {
    let path = dir.join("walls.toml");
    std::fs::write(&path, text).unwrap();
    let file = walls_config::absolute(dir).join("g1/a.walls");
    let mut d = diagnostics(n);
    let start = Instant::now();
    let lint: Lint = load(&path).unwrap().lint;
    lint.filter(Some(&file), &mut d);
    let elapsed = start.elapsed();
    (elapsed, d.len())
}

#[test]
fn every_list_is_linear() {
    let n = ((100_000.0 * scale()) as usize).max(1000);
    let dir = tempfile::tempdir().unwrap();
    let mut slow = Vec::new();
    for list in [
        "ignore",
        "per-file codes",
        "include",
        "exclude",
        "per-file globs",
    ] {
        let (small, large) = (settings(list, n / 4), settings(list, n));
        let mut best = [Duration::MAX; 2];
        let mut left = [0; 2];
        for _ in 0..3 {
            for (k, (text, count)) in [(&small, n / 4), (&large, n)].into_iter().enumerate() {
                let (t, l) = time(dir.path(), text, count);
                best[k] = best[k].min(t);
                left[k] = l;
            }
        }
        println!(
            "{list}: {} entries {:.2?} ({} of {} diagnostics left), {} entries {:.2?} ({} of {} left)",
            n / 4,
            best[0],
            left[0],
            n / 4,
            n,
            best[1],
            left[1],
            n
        );
        if best[1].max(FLOOR) >= best[0].max(FLOOR) * 8 {
            slow.push(format!("{list}: {:?} then {:?}", best[0], best[1]));
        }
    }
    assert!(slow.is_empty(), "not linear: {slow:?}");
}
