//! The repository's documents stay inside it: what a clone has is all a reader needs.
//!
//! Over the files git tracks (`git ls-files`, from the workspace root):
//! * no file mentions the folder beside the clone that the project's first drafts were
//!   written from (its name is built in [`outside_folder`], so this file does not mention
//!   it either); `.ci/run` alone may, as CI lays that folder out;
//! * no file cites the contract or pkdgrav's physics by their old names (`SPEC` or
//!   `physics.md` and a section sign, [`OLD_CITATIONS`]): they are `docs/spec.md` and
//!   `docs/pkdgrav-physics.md`;
//! * every relative link and image of every Markdown file (parsed with pulldown-cmark,
//!   so code spans and blocks are not links) names a tracked file, or a folder holding
//!   tracked files, and its `#anchor`, when it points into a Markdown file, is the
//!   GitHub anchor of one of that file's headings.
//!
//! Each failure is one line, `path:line: what`, all of them in one message.

use pulldown_cmark::{Event, HeadingLevel, Options, Parser, Tag, TagEnd};
use std::collections::{BTreeMap, BTreeSet};
use std::path::{Component, Path, PathBuf};
use std::process::Command;

/// The workspace root, where `git ls-files` is run and paths are resolved from.
fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../..")
        .canonicalize()
        .expect("the workspace root")
}

/// Every file git tracks, relative to the root, with `/` separators.
fn tracked() -> Vec<String> {
    let out = Command::new("git")
        .args(["ls-files", "-z"])
        .current_dir(root())
        .output()
        .expect("git runs (this test reads the files git tracks)");
    assert!(
        out.status.success(),
        "git ls-files failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout)
        .expect("tracked paths are UTF-8")
        .split('\0')
        .filter(|p| !p.is_empty())
        .map(str::to_string)
        .collect()
}

/// The folder beside the clone that readers do not have, as it is written in a path.
fn outside_folder() -> String {
    format!("../{}", "shared")
}

/// The one tracked file that may name [`outside_folder`]: CI lays the folder out.
const MAY_NAME_THE_OUTSIDE_FOLDER: &str = ".ci/run";

/// Old citations and what replaces them (`\u{a7}` is the section sign, so that this file
/// does not cite them itself). A mention of `physics.md` counts only when `pkdgrav-` (in a
/// man page, `pkdgrav\-`) does not come right before it.
const OLD_CITATIONS: &[(&str, &str)] = &[
    ("SPEC \u{a7}", "docs/spec.md \u{a7}"),
    ("physics.md \u{a7}", "docs/pkdgrav-physics.md \u{a7}"),
];

/// The 1-based line of byte `offset` in `text`.
fn line_of(text: &str, offset: usize) -> usize {
    text[..offset].bytes().filter(|&b| b == b'\n').count() + 1
}

/// A tracked file's text, or `None` for a binary file or one that is not UTF-8.
fn text_of(path: &str) -> Option<String> {
    let bytes = std::fs::read(root().join(path)).ok()?;
    if bytes.contains(&0) {
        return None;
    }
    String::from_utf8(bytes).ok()
}

/// The offences against the first two rules in one file.
fn mentions(path: &str, text: &str) -> Vec<String> {
    let mut found = Vec::new();
    let outside = outside_folder();
    if path != MAY_NAME_THE_OUTSIDE_FOLDER {
        for (at, _) in text.match_indices(&outside) {
            found.push(format!(
                "{path}:{}: names `{outside}`, which a clone does not have: bring what \
                 readers need into docs/ and link it there",
                line_of(text, at)
            ));
        }
    }
    for (old, new) in OLD_CITATIONS {
        for (at, _) in text.match_indices(old) {
            let before = &text[..at];
            if old.starts_with("physics")
                && (before.ends_with("pkdgrav-") || before.ends_with("pkdgrav\\-"))
            {
                continue;
            }
            found.push(format!(
                "{path}:{}: cites `{old}`: write `{new}` (the file in this repository)",
                line_of(text, at)
            ));
        }
    }
    found
}

/// GitHub's anchor of a heading: lower case, every character but letters, digits, `-`,
/// `_` and spaces dropped, spaces turned into `-`.
fn slug(heading: &str) -> String {
    heading
        .to_lowercase()
        .chars()
        .filter_map(|c| match c {
            ' ' => Some('-'),
            '-' | '_' => Some(c),
            c if c.is_alphanumeric() => Some(c),
            _ => None,
        })
        .collect()
}

/// One Markdown file's headings' anchors (a repeated heading's later anchors get `-1`,
/// `-2`, … as on GitHub) and its links, each with its byte offset.
struct Markdown {
    anchors: BTreeSet<String>,
    links: Vec<(usize, String)>,
}

fn parse_markdown(text: &str) -> Markdown {
    let mut anchors = BTreeSet::new();
    let mut seen: BTreeMap<String, usize> = BTreeMap::new();
    let mut links = Vec::new();
    let mut heading: Option<String> = None;
    let options =
        Options::ENABLE_TABLES | Options::ENABLE_FOOTNOTES | Options::ENABLE_STRIKETHROUGH;
    for (event, range) in Parser::new_ext(text, options).into_offset_iter() {
        match event {
            Event::Start(Tag::Heading { level, .. }) if level <= HeadingLevel::H6 => {
                heading = Some(String::new());
            }
            Event::End(TagEnd::Heading(_)) => {
                let base = slug(&heading.take().unwrap_or_default());
                let n = seen.entry(base.clone()).or_insert(0);
                anchors.insert(if *n == 0 { base } else { format!("{base}-{n}") });
                *n += 1;
            }
            Event::Text(t) | Event::Code(t) => {
                if let Some(h) = heading.as_mut() {
                    h.push_str(&t);
                }
            }
            Event::Start(Tag::Link { dest_url, .. } | Tag::Image { dest_url, .. }) => {
                links.push((range.start, dest_url.to_string()));
            }
            _ => {}
        }
    }
    Markdown { anchors, links }
}

/// `dir/../x` and `./x` folded, so a link resolves to a tracked path.
fn normalise(path: &Path) -> Option<String> {
    let mut parts: Vec<String> = Vec::new();
    for c in path.components() {
        match c {
            Component::Normal(p) => parts.push(p.to_str()?.to_string()),
            Component::ParentDir => {
                parts.pop()?;
            }
            Component::CurDir => {}
            Component::RootDir | Component::Prefix(_) => return None,
        }
    }
    Some(parts.join("/"))
}

/// Whether a link leaves the repository (a URL with a scheme, such as `https:` or
/// `mailto:`), and so is not checked.
fn is_external(dest: &str) -> bool {
    dest.split_once(':').is_some_and(|(scheme, _)| {
        !scheme.is_empty()
            && scheme
                .chars()
                .all(|c| c.is_ascii_alphanumeric() || "+-.".contains(c))
    })
}

/// The offences against the last rule in one Markdown file.
fn broken_links(
    path: &str,
    text: &str,
    files: &BTreeSet<String>,
    markdown: &mut BTreeMap<String, Markdown>,
) -> Vec<String> {
    let mut found = Vec::new();
    let dir = Path::new(path).parent().unwrap_or(Path::new(""));
    let links = parse_markdown(text).links;
    for (at, dest) in links {
        if is_external(&dest) {
            continue;
        }
        let line = line_of(text, at);
        let (file, anchor) = match dest.split_once('#') {
            Some((f, a)) => (f, Some(a)),
            None => (dest.as_str(), None),
        };
        let target = if file.is_empty() {
            Some(path.to_string())
        } else if let Some(from_root) = file.strip_prefix('/') {
            normalise(Path::new(from_root))
        } else {
            normalise(&dir.join(file))
        };
        let Some(target) = target else {
            found.push(format!("{path}:{line}: `{dest}` leaves the repository"));
            continue;
        };
        let target = target.trim_end_matches('/').to_string();
        let is_file = files.contains(&target);
        let is_folder = files.iter().any(|f| f.starts_with(&format!("{target}/")));
        if !is_file && !is_folder {
            found.push(format!(
                "{path}:{line}: `{dest}`: no tracked file or folder `{target}`"
            ));
            continue;
        }
        let Some(anchor) = anchor.filter(|_| is_file && target.ends_with(".md")) else {
            continue;
        };
        let headings = markdown
            .entry(target.clone())
            .or_insert_with(|| parse_markdown(&text_of(&target).unwrap_or_default()));
        if !headings.anchors.contains(anchor) {
            found.push(format!(
                "{path}:{line}: `{dest}`: `{target}` has no heading with the anchor `#{anchor}`"
            ));
        }
    }
    found
}

#[test]
fn documents_link_only_inside_the_repository() {
    let paths = tracked();
    let files: BTreeSet<String> = paths.iter().cloned().collect();
    let mut markdown = BTreeMap::new();
    let mut found = Vec::new();
    for path in &paths {
        let Some(text) = text_of(path) else { continue };
        found.extend(mentions(path, &text));
        if path.ends_with(".md") {
            found.extend(broken_links(path, &text, &files, &mut markdown));
        }
    }
    assert!(
        found.is_empty(),
        "{} problem(s) with links and citations:\n{}",
        found.len(),
        found.join("\n")
    );
}

#[test]
fn anchors_are_githubs() {
    let md = parse_markdown(
        "# Walls — a design\n\n## 1. Contact force model (SSDEM), `smoothfcn.c DoDEM`\n\n\
         ## Notes\n\n## Notes\n\n## Where SPEC and the reference document differ\n",
    );
    let expected = [
        "walls--a-design",
        "1-contact-force-model-ssdem-smoothfcnc-dodem",
        "notes",
        "notes-1",
        "where-spec-and-the-reference-document-differ",
    ];
    assert_eq!(
        md.anchors,
        expected
            .iter()
            .map(|s| s.to_string())
            .collect::<BTreeSet<_>>()
    );
}

#[test]
fn each_rule_reports_its_line() {
    let outside = outside_folder();
    let text = format!(
        "fine, as a man page has it: pkdgrav\\-physics.md \u{a7}1\nsee {outside}/SPEC.md\nSPEC \u{a7}2 and physics.md \u{a7}7, pkdgrav-physics.md \u{a7}7\n\
         as reference/pkdgrav/physics.md \u{a7}4 says\n"
    );
    assert_eq!(
        mentions("docs/x.md", &text),
        [
            format!(
                "docs/x.md:2: names `{outside}`, which a clone does not have: bring what \
                 readers need into docs/ and link it there"
            ),
            "docs/x.md:3: cites `SPEC \u{a7}`: write `docs/spec.md \u{a7}` (the file in this \
             repository)"
                .to_string(),
            "docs/x.md:3: cites `physics.md \u{a7}`: write `docs/pkdgrav-physics.md \u{a7}` (the \
             file in this repository)"
                .to_string(),
            "docs/x.md:4: cites `physics.md \u{a7}`: write `docs/pkdgrav-physics.md \u{a7}` (the \
             file in this repository)"
                .to_string(),
        ]
    );
    assert!(mentions(MAY_NAME_THE_OUTSIDE_FOLDER, &outside).is_empty());

    let files: BTreeSet<String> = ["README.md", "docs/spec.md", "docs/images/a.svg"]
        .iter()
        .map(|s| s.to_string())
        .collect();
    let mut markdown = BTreeMap::new();
    markdown.insert(
        "docs/spec.md".to_string(),
        parse_markdown("# Spec\n\n## 2. Command-line contract\n"),
    );
    let text = "[ok](spec.md#2-command-line-contract) [folder](images/) \
                [web](https://example.org/x.md) `[code](nothing.md)`\n\
                [gone](missing.md)\n[bad anchor](spec.md#3-evaluator)\n\n```\n[block](nothing.md)\n```\n\
                ![picture](images/b.svg) [up](../../x.md)\n";
    assert_eq!(
        broken_links("docs/guide.md", text, &files, &mut markdown),
        [
            "docs/guide.md:2: `missing.md`: no tracked file or folder `docs/missing.md`",
            "docs/guide.md:3: `spec.md#3-evaluator`: `docs/spec.md` has no heading with the \
             anchor `#3-evaluator`",
            "docs/guide.md:8: `images/b.svg`: no tracked file or folder `docs/images/b.svg`",
            "docs/guide.md:8: `../../x.md` leaves the repository",
        ]
    );
}
