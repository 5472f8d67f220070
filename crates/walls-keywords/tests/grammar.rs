//! The normative grammar (`grammar/walls.ebnf`) names every keyword and type name of the
//! table, each in the rule for the value shape the table gives it.

use walls_keywords::{Keyword, Role, ValueShape, WallType};

/// The text of rule `name`: from its line to the next blank line.
fn rule(grammar: &str, name: &str) -> String {
    let start = grammar
        .find(&format!("\n{name} "))
        .unwrap_or_else(|| panic!("no rule {name}"));
    let body = &grammar[start + 1..];
    let end = body.find("\n\n").unwrap_or(body.len());
    body[..end].to_string()
}

#[test]
fn grammar_lists_every_keyword_with_its_shape() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../../grammar/walls.ebnf");
    let grammar = std::fs::read_to_string(path).unwrap();
    for &k in Keyword::ALL {
        let home = match (k.role(), k.shape()) {
            (Role::Block, _) => format!("{}-block", k.name()),
            (Role::General, _) => "general".into(),
            (_, ValueShape::Vector) => "vector-token".into(),
            (_, ValueShape::Number) => "number-token".into(),
            (_, ValueShape::Integer) => "integer-token".into(),
            (_, ValueShape::TypeName | ValueShape::None) => "property".into(),
        };
        let quoted = format!("\"{}\"", k.name());
        assert!(
            rule(&grammar, &home).contains(&quoted),
            "{quoted} missing from rule {home}"
        );
    }
    for &(name, _) in WallType::SPELLINGS {
        assert!(
            rule(&grammar, "type-name").contains(&format!("\"{name}\"")),
            "{name}"
        );
    }
}
