//! A pkdgrav `.par` file in the tools: its one check for a build ([`walls_par::check`]),
//! from its bytes (pkdgrav reads bytes: a file that is not UTF-8 is checked with each
//! such byte read as U+FFFD, and offers no fix), and the editor's features for it,
//! functions of the
//! text and a byte offset: [`par_hover`] (a key's type, default, build and walls-sim's
//! use) and [`par_completion`] (the build's keys).

use crate::{CompletionItem, CompletionKind, Hover};
use std::sync::Arc;
use walls_diagnostics::Diagnostic;
use walls_par::Build;

/// A checked `.par` file.
#[derive(Debug, Clone)]
pub struct ParChecked {
    /// The text the spans refer to (the valid prefix, for bytes that are not UTF-8).
    pub text: Arc<str>,
    /// Its diagnostics, sorted by position.
    pub diagnostics: Vec<Diagnostic>,
}

/// Checks the `.par` text `text` for `build`.
pub fn check_par_text(text: String, build: &Build) -> ParChecked {
    let diagnostics = walls_par::check(&text, build);
    ParChecked {
        text: text.into(),
        diagnostics,
    }
}

/// Checks the `.par` bytes `bytes` for `build`. pkdgrav reads bytes, not characters: a
/// file that is not UTF-8 (a Latin-1 comment) is checked with each such byte read as
/// U+FFFD, and offers no fix (its text is not the file's, so it is never rewritten).
pub fn check_par_bytes(bytes: Vec<u8>, build: &Build) -> ParChecked {
    match String::from_utf8(bytes) {
        Ok(text) => check_par_text(text, build),
        Err(e) => {
            let text = String::from_utf8_lossy(e.as_bytes()).into_owned();
            let mut checked = check_par_text(text, build);
            for d in &mut checked.diagnostics {
                d.fix = None;
            }
            checked
        }
    }
}

/// What walls-sim does with `key`, in words.
fn evaluator_use(key: &str) -> String {
    use walls_par::evaluator::{Use, use_of};
    match use_of(key) {
        Some(Use::Read) => "walls-sim reads it and follows it.".into(),
        Some(Use::NoEffect) => "walls-sim: no effect on what it computes.".into(),
        Some(Use::Only { value, why, .. }) => {
            format!("walls-sim follows it at {value} only: {why}.")
        }
        Some(Use::NotYet(why)) => format!("walls-sim does not model it yet: {why}."),
        None => "walls-sim does not model it: pkdgrav follows it, walls-sim's run does not.".into(),
    }
}

/// A key's documentation in Markdown: its type and default, the compile options that
/// register it (and whether `build` does), and what walls-sim does with it.
fn key_markdown(name: &str, build: &Build) -> Option<String> {
    let registrations: Vec<_> = walls_par::keys::any(name).collect();
    // The build's own registration where it makes one (a key registered twice has a
    // type and default per condition).
    let first = walls_par::keys::registered(name, build).or(registrations.first().copied())?;
    let mut md = format!("**`{name}`** ({}", first.kind.as_str());
    md.push_str(&format!(", default `{}`)\n\n", first.default));
    let conditions: Vec<&str> = registrations.iter().map(|k| k.condition).collect();
    match walls_par::keys::registered(name, build) {
        Some(k) if k.condition == "always" => md.push_str("Registered by every build.\n\n"),
        Some(k) => md.push_str(&format!("Registered with `{}`.\n\n", k.condition)),
        None => md.push_str(&format!(
            "Not registered by this build ({}): pkdgrav stops at start-up on it. Registered with `{}`.\n\n",
            build.names(),
            conditions.join("`, or `")
        )),
    }
    md.push_str(&evaluator_use(name));
    Some(md)
}

/// The key of the `.par` line holding byte `offset`, documented ([`key_markdown`]), with
/// the key's span; `None` off a key.
pub fn par_hover(text: &str, offset: usize, build: &Build) -> Option<Hover> {
    use walls_par::syntax::Kind;
    let line = walls_par::syntax::lines(text)
        .into_iter()
        .find(|l| l.span.start <= offset && offset <= l.span.end)?;
    line.reads.iter().find_map(|read| match &read.kind {
        Kind::Entry { key, .. } if key.start <= offset && offset <= key.end => Some(Hover {
            markdown: key_markdown(&text[key.clone()], build)?,
            range: key.clone(),
        }),
        _ => None,
    })
}

/// The keys `build` registers whose names start with the word before byte `at` (any
/// case), when that word is the start of a line's key: the `.par` completions.
pub fn par_completion(text: &str, at: usize, build: &Build) -> Vec<CompletionItem> {
    let start = text[..at].rfind('\n').map_or(0, |k| k + 1);
    let before = text[start..at].trim_start_matches([' ', '\t']);
    if !before
        .bytes()
        .all(|b| b.is_ascii_alphanumeric() || b == b'_' || b == b'$')
    {
        return Vec::new();
    }
    let prefix = before.to_ascii_lowercase();
    let mut seen = std::collections::HashSet::new();
    walls_par::keys::all()
        .iter()
        .filter(|k| build.meets(k.condition))
        .filter(|k| k.name.to_ascii_lowercase().starts_with(&prefix))
        .filter(|k| seen.insert(k.name))
        .map(|k| CompletionItem {
            label: k.name.to_string(),
            kind: CompletionKind::Property,
            detail: format!("{}, default {}", k.kind.as_str(), k.default),
            documentation: key_markdown(k.name, build),
            sort_text: None,
            snippet: Some(format!("{} = ${{1}}", k.name)),
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_key_hovered_says_its_type_default_build_and_walls_sims_use() {
        let text = "dKt = -1\niCohesionModel = 1\n";
        let build = Build::default();
        let h = par_hover(text, 1, &build).unwrap();
        assert_eq!(h.range, 0..3);
        assert!(
            h.markdown.starts_with("**`dKt`** (double, default `-1;"),
            "{}",
            h.markdown
        );
        assert!(h.markdown.contains("Registered with `DEM`."));
        assert!(h.markdown.contains("walls-sim reads it and follows it."));
        let h = par_hover(text, 12, &build).unwrap();
        assert!(
            h.markdown.contains("Not registered by this build"),
            "{}",
            h.markdown
        );
        assert!(h.markdown.contains("`DEM && DEM_COHESION`"));
        assert_eq!(par_hover(text, 6, &build), None);
    }

    #[test]
    fn keys_are_completed_from_the_build_s_registrations() {
        let build = Build::default();
        let labels = |text: &str| -> Vec<String> {
            par_completion(text, text.len(), &build)
                .into_iter()
                .map(|c| c.label)
                .collect()
        };
        assert_eq!(labels("dku"), Vec::<String>::new());
        assert!(labels("dk").contains(&"dKn".to_string()));
        assert!(!labels("iCoh").contains(&"iCohesionModel".to_string()));
        assert!(labels("dDelta = 1").is_empty());
        let all = labels("");
        // The golden build's 217 less DEM_TRACK_ORIENT's one (pkdgrav-physics §18).
        assert_eq!(all.len(), 216, "the default build's keys, each once");
    }
}
