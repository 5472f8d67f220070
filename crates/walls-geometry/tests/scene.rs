//! Tests as data: under `tests/data/scene`, each `.walls` file's resolved scene as JSON
//! (what `walls-sim scene` prints), followed by its model diagnostics, is compared with
//! the `.snap` file beside it. A first-line comment `# time: T` adds each wall's
//! position at T. Update with `INSTA_UPDATE=always cargo test -p walls-geometry` and
//! review the diff.

use std::fmt::Write as _;
use walls_model::{Options, analyze};
use walls_test_support::{render, snapshot_beside};

#[test]
fn scene_cases() {
    insta::glob!("data/scene/*.walls", |path| {
        let text = std::fs::read_to_string(path).unwrap();
        let time = text
            .lines()
            .next()
            .and_then(|l| l.strip_prefix("# time:"))
            .map(|t| t.trim().parse::<f64>().unwrap());
        let parsed = walls_syntax::parse(text.as_str());
        let analysis = analyze(&parsed.tree, &Options::default());
        let mut json = Vec::new();
        walls_geometry::json::write_scene(&mut json, &analysis.scene, &text, time).unwrap();
        let mut out = String::from_utf8(json).unwrap();
        writeln!(out, "--- diagnostics ---").unwrap();
        out.push_str(&render(&text, &analysis.diagnostics));
        snapshot_beside(path, &out);
    });
}
