//! Property tests: the tree is lossless for any text, statements cover the significant
//! tokens exactly once and in order, spans stay inside the text, and well-formed files
//! produce no diagnostic.

use proptest::prelude::*;
use walls_keywords::{Keyword, ValueShape, WallType};
use walls_syntax::{TokenKind, lex, parse};

/// Words, numbers, separators and comment starts: text that looks like a walls file.
fn wallsish() -> impl Strategy<Value = String> {
    let piece = prop_oneof![
        prop::sample::select(Keyword::ALL.iter().map(|k| k.name()).collect::<Vec<_>>())
            .prop_map(str::to_string),
        prop::sample::select(WallType::SPELLINGS.iter().map(|s| s.0).collect::<Vec<_>>())
            .prop_map(str::to_uppercase),
        "[-+]?[0-9]{0,3}(\\.[0-9]{0,3})?([eE][-+]?[0-9]{0,2})?",
        prop::sample::select(vec![
            " ", "  ", "\t", "\n", "\r\n", "\r", ",", "=", "#", "!", "# c\n", "x", "μ", "nan",
            "1.2.3"
        ])
        .prop_map(str::to_string),
    ];
    prop::collection::vec(piece, 0..60).prop_map(|v| v.concat())
}

fn check_invariants(text: &str) {
    let parsed = parse(text);
    let tree = &parsed.tree;
    assert_eq!(tree.to_string(), text, "lossless");
    let tokens = lex(text);
    assert_eq!(tokens.len(), tree.tokens().len());
    for w in tokens.starts().windows(2) {
        assert!(w[0] < w[1], "empty or unordered token");
    }
    let sig = tree.significant().to_vec();
    let covered: Vec<_> = tree
        .statements()
        .flat_map(|(s, _)| tree.statement_tokens(s).iter().copied())
        .collect();
    assert_eq!(
        covered, sig,
        "statements cover the significant tokens once, in order"
    );
    for d in &parsed.diagnostics {
        assert!(d.span.start <= d.span.end && d.span.end <= text.len());
        assert!(text.is_char_boundary(d.span.start) && text.is_char_boundary(d.span.end));
    }
}

/// A statement whose values fit its keyword's shape.
fn valid_statement() -> impl Strategy<Value = String> {
    let number = "[-+]?([0-9]{1,3}(\\.[0-9]{0,3})?|\\.[0-9]{1,3})([eE][-+]?[0-9]{1,2})?";
    let props: Vec<Keyword> = Keyword::ALL
        .iter()
        .copied()
        .filter(|k| k.shape() != ValueShape::None && k.role() == walls_keywords::Role::Property)
        .collect();
    let integer = "[-+]?[0-9]{1,3}";
    (
        prop::sample::select(props),
        prop::collection::vec(number, 3),
        integer,
        0..7usize,
    )
        .prop_map(|(k, nums, int, t)| {
            let value = match k.shape() {
                ValueShape::Number => nums[0].clone(),
                ValueShape::Integer => int,
                ValueShape::Vector => nums.join(" "),
                ValueShape::TypeName => WallType::ALL[t].name().to_string(),
                ValueShape::None => String::new(),
            };
            format!("{} {value}", k.name())
        })
}

fn valid_file() -> impl Strategy<Value = String> {
    let block = (
        any::<bool>(),
        prop::collection::vec(valid_statement(), 0..6),
    )
        .prop_map(|(d, stmts)| {
            let mut s = String::from(if d { "defaults\n" } else { "wall\n" });
            for st in stmts {
                s.push_str("  ");
                s.push_str(&st);
                s.push_str(" # note\n");
            }
            s
        });
    (prop::collection::vec(block, 0..6), "[0-9]{1,2}")
        .prop_map(|(blocks, unit)| format!("lengthunit {unit}\n{}", blocks.concat()))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    #[test]
    fn any_text_is_lossless(text in any::<String>()) {
        check_invariants(&text);
    }

    #[test]
    fn wallsish_text_is_lossless(text in wallsish()) {
        check_invariants(&text);
    }

    #[test]
    fn well_formed_files_have_no_diagnostics(text in valid_file()) {
        check_invariants(&text);
        let parsed = parse(text.as_str());
        prop_assert!(parsed.diagnostics.is_empty(), "{text}\n{:#?}", parsed.diagnostics);
    }
}

#[test]
fn every_keyword_and_type_lexes_in_any_case() {
    for &k in Keyword::ALL {
        for spelling in [
            k.name().to_string(),
            k.name().to_uppercase(),
            mixed_case(k.name()),
        ] {
            let tokens = lex(&spelling);
            assert_eq!(tokens.len(), 1, "{spelling}");
            assert_eq!(tokens.kinds()[0], TokenKind::Keyword(k), "{spelling}");
        }
    }
    for &(name, t) in WallType::SPELLINGS {
        for spelling in [name.to_string(), name.to_uppercase(), mixed_case(name)] {
            assert_eq!(
                lex(&spelling).kinds()[0],
                TokenKind::TypeName(t),
                "{spelling}"
            );
        }
    }
}

#[test]
fn words_split_only_at_separators() {
    let kinds = |s: &str| lex(s).kinds().to_vec();
    use TokenKind::*;
    assert_eq!(kinds("walls"), [Word]);
    assert_eq!(kinds("1.2.3"), [Word]);
    assert_eq!(kinds("1e"), [Word]);
    assert_eq!(kinds("0x1p3"), [Word]);
    assert_eq!(kinds("nan"), [Word]);
    assert_eq!(
        kinds("+3E+2,.5=5."),
        [Number, Separator, Number, Separator, Number]
    );
    assert_eq!(kinds("1#x y\n"), [Number, GluedComment, Newline]);
    assert_eq!(kinds("plane!x"), [TypeName(WallType::Plane), GluedComment]);
    assert_eq!(kinds("1 #x\r\n"), [Number, Whitespace, Comment, Newline]);
    assert_eq!(kinds(",#x"), [Separator, Comment]);
    // A lone carriage return does not end a comment; one before a newline does.
    assert_eq!(kinds("#a\rwall\n"), [Comment, Newline]);
    assert_eq!(kinds("#a\r\n"), [Comment, Newline]);
    assert_eq!(kinds("#\r"), [Comment, Whitespace]);
    assert_eq!(
        kinds("wall\r\n"),
        [Keyword(walls_keywords::Keyword::Wall), Newline]
    );
}

fn mixed_case(s: &str) -> String {
    s.chars()
        .enumerate()
        .map(|(i, c)| {
            if i % 2 == 0 {
                c.to_ascii_uppercase()
            } else {
                c
            }
        })
        .collect()
}
