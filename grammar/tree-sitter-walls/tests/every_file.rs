//! The tree-sitter grammar agrees with the toolkit's parser on every walls file in the
//! repository: where `walls-syntax` finds no syntax error, the tree has no error node,
//! and both see the same walls and defaults blocks. The parser is ABI 14 and the queries
//! compile.

use std::path::{Path, PathBuf};

fn walls_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        let name = path.file_name().unwrap().to_string_lossy();
        if path.is_dir() && !["target", "node_modules", ".git", "fuzz"].contains(&name.as_ref()) {
            walls_files(&path, out);
        } else if name.ends_with(".walls") || name == "stdin" {
            out.push(path);
        }
    }
}

fn count(node: tree_sitter::Node, kind: &str) -> usize {
    let mut cursor = node.walk();
    node.children(&mut cursor)
        .filter(|c| c.kind() == kind)
        .count()
}

#[test]
fn agrees_with_the_toolkit_on_every_file() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let mut files = Vec::new();
    walls_files(&root, &mut files);
    assert!(files.len() > 50, "found {} files", files.len());
    let mut parser = tree_sitter::Parser::new();
    parser
        .set_language(&tree_sitter_walls::LANGUAGE.into())
        .unwrap();
    let mut checked = 0;
    for file in files {
        let Ok(text) = std::fs::read_to_string(&file) else {
            continue; // not UTF-8: the toolkit reports it, editors decode it their way
        };
        let ours = walls_syntax::parse(text.as_str());
        let tree = parser.parse(&text, None).unwrap();
        let top = tree.root_node();
        if ours.diagnostics.is_empty() {
            assert!(!top.has_error(), "{}: {}", file.display(), top.to_sexp());
            checked += 1;
        }
        let blocks = |kind| {
            ours.tree
                .items()
                .iter()
                .filter(|i| matches!(i, walls_syntax::Item::Block(b) if b.kind == kind))
                .count()
        };
        assert_eq!(
            count(top, "wall_block"),
            blocks(walls_syntax::BlockKind::Wall),
            "{}",
            file.display()
        );
        assert_eq!(
            count(top, "defaults_block"),
            blocks(walls_syntax::BlockKind::Defaults),
            "{}",
            file.display()
        );
    }
    assert!(checked > 20, "only {checked} clean files");
}

#[test]
fn the_parser_is_generated_for_abi_14() {
    // ABI 15 parsers are refused by Neovim 0.7 to 0.10 and Helix before 25.07.
    let language: tree_sitter::Language = tree_sitter_walls::LANGUAGE.into();
    assert_eq!(language.abi_version(), 14);
}

#[test]
fn queries_compile() {
    let language: tree_sitter::Language = tree_sitter_walls::LANGUAGE.into();
    tree_sitter::Query::new(&language, tree_sitter_walls::HIGHLIGHTS_QUERY).unwrap();
    tree_sitter::Query::new(&language, tree_sitter_walls::FOLDS_QUERY).unwrap();
}

#[test]
fn grammar_lists_every_keyword() {
    let grammar = include_str!("../grammar.js");
    let names = walls_keywords::Keyword::ALL
        .iter()
        .map(|k| k.name())
        .chain(walls_keywords::WallType::SPELLINGS.iter().map(|s| s.0));
    for name in names {
        assert!(
            grammar.contains(&format!("'{name}'")),
            "{name} missing from grammar.js"
        );
    }
}
