//! Properties of formatting over generated files (valid statements in any case, with
//! `,`/`=` separators, values spread over lines, comments everywhere, blank lines, and
//! control characters in comments and between words):
//! formatting twice changes nothing, the scene is the same, every comment and every
//! number's text survives in order, and range formatting agrees with whole-file
//! formatting.

use proptest::prelude::*;
use walls_format::{FormatOptions, format, format_range, format_text};
use walls_keywords::{Keyword, Role, ValueShape, WallType};
use walls_model::{Options, Value, analyze};
use walls_syntax::{TokenKind, lex, parse};

fn sep() -> impl Strategy<Value = &'static str> {
    prop::sample::select(vec![
        " ",
        "  ",
        "\t",
        ",",
        "=",
        " = ",
        ", ",
        "\n  ",
        "\n\n",
        " # inside\n",
        " !x\n  ",
        // Control characters pkdgrav reads as white space (S006).
        "\x0b",
        " \x0c",
        "\r ",
    ])
}

fn comment() -> impl Strategy<Value = String> {
    // With control characters and a bidirectional override (S006), kept as they are.
    "[#!][ a-zA-Z0-9μ#!,=.\\x1b\\x07\\x7f\\x{85}\\x{202e}-]{0,12}"
}

fn statement() -> impl Strategy<Value = String> {
    let number = "[-+]?([0-9]{1,3}(\\.[0-9]{0,3})?|\\.[0-9]{1,3})([eE][-+]?[0-9]{1,2})?";
    let props: Vec<Keyword> = Keyword::ALL
        .iter()
        .copied()
        .filter(|k| k.role() == Role::Property)
        .collect();
    (
        prop::sample::select(props),
        prop::collection::vec(number, 3),
        "[-+]?[0-9]{1,3}",
        0..8usize,
        prop::collection::vec(sep(), 3),
        any::<bool>(),
    )
        .prop_map(|(k, nums, int, t, seps, upper)| {
            let name = if upper {
                k.name().to_uppercase()
            } else {
                k.name().to_string()
            };
            let values: Vec<String> = match k.shape() {
                ValueShape::Number => vec![nums[0].clone()],
                ValueShape::Integer => vec![int],
                ValueShape::Vector => nums,
                ValueShape::TypeName => vec![WallType::SPELLINGS[t].0.to_string()],
                ValueShape::None => vec![],
            };
            // Values may sit on later lines, after comments (the formatter joins them).
            let mut s = name;
            for (v, sep) in values.iter().zip(seps) {
                s.push_str(sep);
                s.push_str(v);
            }
            s
        })
}

fn file() -> impl Strategy<Value = String> {
    let line = (
        statement(),
        prop::option::of(comment()),
        prop::option::of(comment()),
        prop::sample::select(vec!["\n", "\n\n", "\n\n\n", " ", "\r\n"]),
    )
        .prop_map(|(st, trailing, own, end)| {
            let mut s = String::new();
            if let Some(c) = own {
                s.push_str(&c);
                s.push('\n');
            }
            s.push_str(&st);
            if let Some(c) = trailing {
                s.push(' ');
                s.push_str(&c);
                s.push('\n');
            } else {
                s.push_str(end);
            }
            s
        });
    let block = (
        prop::sample::select(vec!["wall", "defaults", "WALL", "wall\n", "defaults\n"]),
        prop::collection::vec(line, 0..6),
    )
        .prop_map(|(head, lines)| format!("{head} {}\n", lines.concat()));
    // Units and `time` go between blocks: inside a wall block they would close it.
    let general = (
        prop::sample::select(vec!["lengthunit", "TimeUnit", "massunit", "time"]),
        "[1-9][0-9]{0,2}(\\.[0-9]{1,2})?",
    )
        .prop_map(|(k, v)| format!("{k} {v}\n"));
    let item = prop_oneof![4 => block, 1 => general];
    (
        prop::collection::vec(item, 0..7),
        prop::option::of(comment()),
    )
        .prop_map(|(items, tail)| format!("{}{}\n", items.concat(), tail.unwrap_or_default()))
}

/// The effective values of every wall, bit for bit.
fn scene(text: &str) -> Vec<Vec<(Keyword, String)>> {
    let tree = parse(text).tree;
    let analysis = analyze(&tree, &Options::default());
    analysis
        .scene
        .walls
        .iter()
        .map(|w| {
            Keyword::ALL
                .iter()
                .filter_map(|&k| {
                    let v = w.value(k)?;
                    Some((
                        k,
                        match v {
                            Value::Number(x) => format!("{:x}", x.to_bits()),
                            Value::Vector(v) => {
                                v.iter().map(|x| format!("{:x}", x.to_bits())).collect()
                            }
                            other => format!("{other:?}"),
                        },
                    ))
                })
                .collect()
        })
        .collect()
}

/// The texts of the tokens of the given kinds, in order.
fn texts(text: &str, keep: fn(TokenKind) -> bool) -> Vec<String> {
    let tokens = lex(text);
    let mut out = Vec::new();
    for i in 0..tokens.len() {
        let start = tokens.starts()[i] as usize;
        let end = tokens
            .starts()
            .get(i + 1)
            .map_or(text.len(), |&s| s as usize);
        if keep(tokens.kinds()[i]) {
            out.push(text[start..end].to_string());
        }
    }
    out
}

fn options() -> impl Strategy<Value = FormatOptions> {
    (0..5usize, any::<bool>(), any::<bool>()).prop_map(|(indent_width, align, keep)| {
        FormatOptions {
            indent_width,
            align_trailing_comments: align,
            keep_blank_lines: keep,
        }
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(1000))]

    #[test]
    fn formatting_keeps_meaning_comments_and_numbers(text in file(), opts in options()) {
        let once = format_text(&text, &opts).map_err(|e| TestCaseError::fail(format!("{text:?}: {:?}", e.diagnostics)))?;
        let twice = format_text(&once, &opts).expect("formatted text formats");
        prop_assert_eq!(&twice, &once, "not idempotent for {:?}", text);
        prop_assert_eq!(scene(&once), scene(&text), "meaning changed: {:?} -> {:?}", text, once);
        let comment = |k| matches!(k, TokenKind::Comment | TokenKind::GluedComment);
        prop_assert_eq!(texts(&once, comment), texts(&text, comment));
        prop_assert_eq!(texts(&once, |k| k == TokenKind::Number), texts(&text, |k| k == TokenKind::Number));
        // The result is clean for pkdgrav's reader: no value off its line, final newline;
        // control characters are left only in comments.
        let syntax: Vec<_> = parse(once.as_str())
            .diagnostics
            .into_iter()
            .filter(|d| !(d.code.id == "S006" && d.message.ends_with("in a comment")))
            .collect();
        prop_assert!(syntax.is_empty(), "{:?}: {:?}", once, syntax);
    }

    #[test]
    fn range_formatting_agrees_with_the_whole(text in file(), at in 0..1000usize, len in 0..200usize) {
        let parsed = parse(text.as_str());
        let opts = FormatOptions::default();
        let whole = format(&parsed, &opts).expect("formats").text;
        let start = at.min(text.len());
        let range = start..(start + len).min(text.len());
        let mut edited = text.clone();
        if let Some(edit) = format_range(&parsed, range, &opts).expect("formats") {
            edited.replace_range(edit.span.clone(), &edit.replacement);
        }
        // Formatting the rest afterwards gives the same text as formatting at once.
        prop_assert_eq!(format_text(&edited, &opts).expect("formats"), whole);
    }
}
