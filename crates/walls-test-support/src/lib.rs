//! Helpers and fixtures shared by the tests and benchmarks of the walls crates.
//!
//! [`render`] writes diagnostics as plain text that shows exactly what a test must pin
//! down: code, severity, 1-based line:column span with the text it covers, labels, help
//! and every fix edit. [`snapshot_beside`] compares such text with a `.snap` file next
//! to the input it came from. [`arbitrary`] makes random walls files for property tests.
//!
//! [`scene`] gives the typed walls of walls-file text that must parse cleanly (also
//! [`scene_in`] a contact model, [`scene_uncapped`] without pkdgrav's cap on the number
//! of walls, and [`model_scene`] the model's scene, for the previews). The fixtures in
//! [`scenes`] are deterministic: [`ball`], the particle most run tests throw;
//! [`scenes::packed`], a crowd of particles at rest packed into a scene, for benchmarks
//! and stress runs; and [`scenes::sphere_hull`], a closed hull of many triangles as
//! walls-file text, for the wall index.
//!
//! [`cli`] checks a tool's command line as shells and `man` see it: its completion
//! scripts, and its man pages in `docs/man/`. [`exact`] compares numbers to the last bit.

pub mod arbitrary;
pub mod cli;
pub mod exact;
pub mod scenes;
mod walls;

pub use scenes::ball;
pub use walls::{model_scene, scene, scene_in, scene_uncapped};

use std::fmt::Write as _;
use std::ops::Range;
use std::path::Path;
use walls_diagnostics::{Diagnostic, LineIndex};

/// Diagnostics of `text` as reviewable plain text, one block each.
pub fn render(text: &str, diagnostics: &[Diagnostic]) -> String {
    let index = LineIndex::new(text);
    let at = |span: &Range<usize>| {
        let a = index.line_col(text, span.start);
        let b = index.line_col(text, span.end);
        let covered = text.get(span.clone()).unwrap_or("<not on char boundaries>");
        format!(
            "{}:{}-{}:{} {covered:?}",
            a.line, a.column, b.line, b.column
        )
    };
    let mut out = String::new();
    for d in diagnostics {
        let _ = writeln!(
            out,
            "{}[{}] {}: {}",
            d.severity.as_str(),
            d.code.id,
            at(&d.span),
            d.message
        );
        for l in &d.labels {
            let _ = writeln!(out, "  label {}: {}", at(&l.span), l.message);
        }
        if let Some(h) = &d.help {
            let _ = writeln!(out, "  help: {h}");
        }
        if let Some(f) = &d.fix {
            let _ = writeln!(out, "  fix ({}): {}", f.applicability.as_str(), f.message);
            for e in &f.edits {
                let _ = writeln!(out, "    {} -> {:?}", at(&e.span), e.replacement);
            }
        }
    }
    out
}

/// Asserts `content` equals the snapshot `NAME@FILE.snap` beside the input file `path`.
pub fn snapshot_beside(path: &Path, content: &str) {
    let name = path
        .file_stem()
        .and_then(|s| s.to_str())
        .expect("test inputs have UTF-8 names")
        .to_string();
    insta::with_settings!({
        snapshot_path => path.parent().expect("inputs live in a folder"),
        prepend_module_to_snapshot => false,
        omit_expression => true,
        input_file => path,
    }, {
        insta::assert_snapshot!(name, content);
    });
}
