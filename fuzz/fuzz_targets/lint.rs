//! Fuzz target: arbitrary bytes through decoding, lexing, parsing, the model checks and
//! every renderer. Checks that nothing panics or hangs, that the tree is lossless, that
//! the significant tokens are covered by statements exactly once in order, and that
//! every span lies inside the text on character boundaries.
#![no_main]

use libfuzzer_sys::fuzz_target;
use walls_diagnostics::render::{self, FileReport, ToolInfo};
use walls_model::{ContactModel, Options};

fuzz_target!(|data: &[u8]| {
    let options = Options { mode: ContactModel::Hsdem, min_radius: Some(0.01), dt: Some(1e-3), ..Options::default() };
    let checked = walls_cli::check_bytes(data.to_vec(), &options);
    let (text, diagnostics) = (checked.text, checked.diagnostics);
    let mut scene = Vec::new();
    walls_geometry::json::write_scene(&mut scene, &checked.scene, &text, Some(1.5)).unwrap();
    let scene: serde_json::Value = serde_json::from_slice(&scene).expect("scene JSON parses");
    // NaN and infinities would be written as null: only an infinite mass may be null.
    for wall in scene["walls"].as_array().expect("walls") {
        for (key, value) in wall.as_object().expect("wall object") {
            let numbers: Vec<&serde_json::Value> = match value {
                serde_json::Value::Array(a) => a.iter().collect(),
                v => vec![v],
            };
            // An overflowing position is null by contract; every value is finite.
            assert!(key == "mass" || key == "position" || numbers.iter().all(|v| !v.is_null()), "{key} is not finite");
        }
    }
    for d in &diagnostics {
        let spans = std::iter::once(&d.span).chain(d.labels.iter().map(|l| &l.span));
        for s in spans.chain(d.fix.iter().flat_map(|f| f.edits.iter().map(|e| &e.span))) {
            assert!(s.start <= s.end && s.end <= text.len(), "span {s:?} outside text");
            assert!(text.is_char_boundary(s.start) && text.is_char_boundary(s.end));
        }
    }
    if let Ok(valid) = std::str::from_utf8(data) {
        let parsed = walls_syntax::parse(valid);
        assert_eq!(parsed.tree.to_string(), valid, "tree is not lossless");
        let sig = parsed.tree.significant();
        let mut next = 0;
        for (stmt, _) in parsed.tree.statements() {
            for id in parsed.tree.statement_tokens(stmt) {
                assert_eq!(Some(id), sig.get(next), "statements skip or repeat tokens");
                next += 1;
            }
        }
        assert_eq!(next, sig.len(), "tokens left outside statements");
    }
    if let Ok(valid) = std::str::from_utf8(data) {
        check_formatting(valid);
    }
    let file = FileReport { path: "fuzz.walls", source: &text, diagnostics: &diagnostics };
    let files = [file];
    let mut sink = Vec::new();
    render::human(&mut sink, &files[0], false).unwrap();
    render::github(&mut sink, &files, &[]).unwrap();
    render::gitlab(&mut sink, &files, &[]).unwrap();
    render::json(&mut sink, &files, &[]).unwrap();
    let tool = ToolInfo { name: "walls-lint", version: "0", information_uri: None };
    let rules: Vec<_> = walls_cli::all_codes().collect();
    render::sarif(&mut sink, &files, &[], &tool, &rules).unwrap();
});

/// Formatting either declines (syntax errors) or gives a stable text with the same
/// comments and numbers, in order, that pkdgrav reads without a syntax error (but a
/// line too long, when a comment is).
fn check_formatting(text: &str) {
    let options = walls_format::FormatOptions::default();
    let Ok(once) = walls_format::format_text(text, &options) else {
        return;
    };
    let twice = walls_format::format_text(&once, &options).expect("formatted text formats");
    assert_eq!(twice, once, "formatting is not idempotent");
    let texts = |t: &str, keep: fn(walls_syntax::TokenKind) -> bool| -> Vec<String> {
        let tokens = walls_syntax::lex(t);
        (0..tokens.len())
            .filter(|&i| keep(tokens.kinds()[i]))
            .map(|i| {
                let end = tokens.starts().get(i + 1).map_or(t.len(), |&s| s as usize);
                t[tokens.starts()[i] as usize..end].to_string()
            })
            .collect()
    };
    use walls_syntax::TokenKind as K;
    let comment = |k| matches!(k, K::Comment | K::GluedComment);
    assert_eq!(texts(&once, comment), texts(text, comment), "comments changed");
    assert_eq!(texts(&once, |k| k == K::Number), texts(text, |k| k == K::Number), "numbers changed");
    // Only a line too long for pkdgrav may remain (a long comment cannot be shortened).
    let left = walls_syntax::parse(once.as_str()).diagnostics;
    assert!(
        left.iter().all(|d| std::ptr::eq(d.code, &walls_syntax::codes::LINE_TOO_LONG)),
        "formatted text has syntax errors: {left:?}"
    );
}
