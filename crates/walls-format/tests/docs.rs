//! The examples of `docs/formatting.md` are true: each "Before" text formats to the
//! "After" text under the options its line names, and the "After" text is stable.

use walls_format::{FormatOptions, format_text};

/// The ```walls block after a line starting with `label`, from `at` on, with the rest.
fn block<'a>(doc: &'a str, label: &str) -> Option<(&'a str, &'a str, &'a str)> {
    let start = doc.find(&format!("\n{label}"))? + 1;
    let line_end = start + doc[start..].find('\n')?;
    let line = &doc[start..line_end];
    let body_start = line_end + 1 + "```walls\n".len();
    if !doc[line_end + 1..].starts_with("```walls\n") {
        return None;
    }
    let body_end = body_start + doc[body_start..].find("```")?;
    Some((line, &doc[body_start..body_end], &doc[body_end..]))
}

fn options(line: &str) -> FormatOptions {
    let mut o = FormatOptions::default();
    let words: Vec<&str> = line
        .split(|c: char| c.is_whitespace() || c == '`' || c == ')')
        .collect();
    for (i, w) in words.iter().enumerate() {
        match *w {
            "--indent-width" => o.indent_width = words[i + 1].parse().unwrap(),
            "--align-trailing-comments" => o.align_trailing_comments = true,
            "--keep-blank-lines" => o.keep_blank_lines = words[i + 1].parse().unwrap(),
            _ => {}
        }
    }
    o
}

#[test]
fn examples_in_the_docs_are_true() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../../docs/formatting.md");
    let doc = std::fs::read_to_string(path).unwrap();
    let mut rest = doc.as_str();
    let mut count = 0;
    while let Some((line, before, after_rest)) = block(rest, "Before") {
        let (_, after, next) = block(after_rest, "After").expect("every Before has an After");
        let opts = options(line);
        assert_eq!(
            format_text(before, &opts).unwrap(),
            after,
            "example {}",
            count + 1
        );
        assert_eq!(
            format_text(after, &opts).unwrap(),
            after,
            "example {} is not stable",
            count + 1
        );
        rest = next;
        count += 1;
    }
    assert_eq!(count, 5, "examples found");
}
