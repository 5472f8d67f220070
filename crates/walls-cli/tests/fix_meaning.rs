//! Fixes keep the meaning of a walls file, by construction (docs/diagnostics.md,
//! "Fixing"): for every diagnostic that carries a fix, safe or unsafe, applying that fix
//! alone leaves the resolved scene as it was except the one thing the diagnostic names
//! (see [`allowed`]: a removed token that has no effect leaves the typed walls
//! identical; a changed value changes only that setting, as the code says), and the
//! fixed file has no finding the original did not have. `walls-lint --fix` and
//! `--unsafe-fixes` (several fixes a round, round after round) are held to the same, each
//! round to the union of what its fixes may change, and a fixed file stays fixed under
//! walls-fmt (fmt, fix, fmt: the same findings and scene, nothing left to fix).
//!
//! Checked over every walls file of the repository, the Bad and Good examples of every
//! code, and generated files that carry every fixable diagnostic
//! (`walls_test_support::arbitrary::fixable_file`); the generated run must apply every
//! code's fix at least [`MIN_APPLIED`] times, and prints how many it applied per code.

use proptest::test_runner::{Config, TestCaseError, TestRunner};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::sync::Mutex;
use walls_cli::commands::lint::fix_text;
use walls_diagnostics::{Applicability, Diagnostic, Edit, apply_fixes};
use walls_ide::{Checked, check_text};
use walls_keywords::{Keyword, Role};
use walls_model::{ContactModel, Options, Scene, Vec3, direction};

/// Every code whose diagnostics carry a fix. A fix of a code not listed fails the test
/// ([`allowed`] must say what it may change).
const FIXED_CODES: &[&str] = &[
    "S002", "S004", "S005", "S006", "S107", "C106", "C113", "C201", "C202", "C205", "C207", "C304",
    "C306", "L003",
];

/// The fewest fixes of each code the generated run must apply.
const MIN_APPLIED: usize = 20;

/// Each finding of a check, as `(code, message)`, with how many times it occurs.
fn findings(c: &Checked) -> BTreeMap<(&'static str, String), usize> {
    let mut out = BTreeMap::new();
    for d in &c.diagnostics {
        *out.entry((d.code.id, d.message.clone())).or_insert(0) += 1;
    }
    out
}

/// What a fix may change: these keywords (of one wall, or of any), and whether the typed
/// walls must stay identical.
struct Allowed {
    keys: Vec<(Option<usize>, Keyword)>,
    typed: bool,
}

/// The wall whose block holds byte `offset`.
fn wall_at(scene: &Scene, offset: usize) -> Option<usize> {
    scene
        .walls
        .iter()
        .position(|w| w.block.range().contains(&offset))
}

/// The keyword of the statement holding byte `offset`.
fn keyword_at(c: &Checked, offset: usize) -> Keyword {
    let tree = &c.parse.tree;
    tree.statement_containing(offset)
        .and_then(|s| tree.keyword(&s))
        .expect("the diagnostic is on a statement")
}

/// The walls of `before` whose value of `k` was set at `span`.
fn set_at(before: &Checked, k: Keyword, span: &std::ops::Range<usize>) -> Vec<usize> {
    before
        .scene
        .walls
        .iter()
        .filter(|w| w.setting(k).and_then(|s| s.source.span()).as_ref() == Some(span))
        .map(|w| w.index)
        .collect()
}

/// What the fix of `d` may change in the scene of `before`: the one thing it names.
fn allowed(before: &Checked, d: &Diagnostic) -> Allowed {
    let nothing = Allowed {
        keys: Vec::new(),
        typed: true,
    };
    let of = |walls: Vec<usize>, keys: &[Keyword]| Allowed {
        keys: walls
            .iter()
            .flat_map(|&w| keys.iter().map(move |&k| (Some(w), k)))
            .collect(),
        typed: false,
    };
    let edited = || d.fix.as_ref().expect("a fix").edits[0].span.clone();
    match d.code.id {
        // Text the scene does not see (a newline, a space, a mark, a line break, a
        // comment, white space written as control characters), or a token a later one
        // overrides.
        "S002" | "S004" | "S005" | "S006" | "S107" | "L003" | "C202" => nothing,
        // A token the wall's type does not read: that wall's value of it, not its walls.
        "C201" => Allowed {
            keys: vec![(
                Some(wall_at(&before.scene, d.span.start).expect("C201 is in a wall")),
                keyword_at(before, d.span.start),
            )],
            typed: true,
        },
        // A default no wall reads: the walls that inherit it without reading it.
        "C207" => Allowed {
            keys: vec![(None, keyword_at(before, d.span.start))],
            typed: true,
        },
        // The same motion written with a positive frequency, for the walls that take the
        // frequency (checked in `post`).
        "C113" => of(
            set_at(before, Keyword::OscFreq, &d.span),
            &[Keyword::OscFreq, Keyword::OscAmpl, Keyword::OscPhase],
        ),
        // The vertex or axis the fix rewrites, for the walls that take it.
        "C106" => of(
            set_at(before, Keyword::Vertex2, &edited()),
            &[Keyword::Vertex2],
        ),
        "C306" => {
            let k = keyword_at(before, d.span.start);
            of(set_at(before, k, &edited()), &[k])
        }
        // The oscillation's direction of the wall whose `orient` it follows.
        "C205" => {
            let at = edited().start;
            let walls = before
                .scene
                .walls
                .iter()
                .filter(|w| {
                    w.setting(Keyword::Orient)
                        .and_then(|s| s.source.span())
                        .is_some_and(|s| s.end == at)
                })
                .map(|w| w.index)
                .collect();
            of(walls, &[Keyword::OscVec])
        }
        // The assembly of the walls that take the mass.
        "C304" => {
            let mut walls = set_at(before, Keyword::Mass, &d.span);
            walls.retain(|&w| before.scene.walls[w].integer(Keyword::Assembly) < 0);
            of(walls, &[Keyword::Assembly])
        }
        other => {
            panic!("{other} has a fix this test does not know: say in `allowed` what it may change")
        }
    }
}

/// The typed walls as the back end uses them: the axis of a wall's spin (its `orient`)
/// matters only when it spins (walls-geometry's `Motion::spin`).
fn typed(scene: &Scene) -> Vec<walls_geometry::Wall> {
    let mut walls = walls_geometry::decode(scene);
    for w in &mut walls {
        if w.motion.ang_speed == 0.0 {
            w.motion.spin_axis = Vec3::zeros();
        }
    }
    walls
}

/// The positions of each wall's origin at a few times.
fn positions(scene: &Scene) -> Vec<Vec<Option<Vec3>>> {
    walls_geometry::decode(scene)
        .iter()
        .map(|w| {
            [0.0, 0.3, 1.1, 2.7]
                .iter()
                .map(|&t| w.motion.position(t))
                .collect()
        })
        .collect()
}

fn close(a: &Vec3, b: &Vec3) -> bool {
    (a - b).norm() <= 1e-9 * (1.0 + a.norm())
}

/// The checks of what the fix of `d` did to the values it may change (`allowed`).
fn post(
    d: &Diagnostic,
    allowed: &Allowed,
    before: &Checked,
    after: &Checked,
) -> Result<(), String> {
    let mut walls: Vec<usize> = allowed.keys.iter().filter_map(|(w, _)| *w).collect();
    walls.dedup();
    let pairs = walls
        .iter()
        .map(|&i| (&before.scene.walls[i], &after.scene.walls[i]));
    match d.code.id {
        "C113" => {
            for (b, a) in pairs {
                let [ab, fb, pb] =
                    [Keyword::OscAmpl, Keyword::OscFreq, Keyword::OscPhase].map(|k| b.number(k));
                let [aa, fa, pa] =
                    [Keyword::OscAmpl, Keyword::OscFreq, Keyword::OscPhase].map(|k| a.number(k));
                let rewritten =
                    aa == -ab && fa == -fb && pa == (1.0 - pb).rem_euclid(1.0) && fa >= 0.0;
                let still = ab == 0.0 && aa == 0.0 && fa == -fb;
                if !(rewritten || still) {
                    return Err(format!(
                        "wall {}: (A, ω, φ) = ({ab}, {fb}, {pb}) became ({aa}, {fa}, {pa}), not the same motion",
                        b.index
                    ));
                }
            }
            let (pb, pa) = (positions(&before.scene), positions(&after.scene));
            for &i in &walls {
                // Where another fix of the round turned the oscillation, it moves
                // elsewhere (that fix's own check says how).
                let turned = before.scene.walls[i].vector(Keyword::OscVec)
                    != after.scene.walls[i].vector(Keyword::OscVec);
                if turned {
                    continue;
                }
                // The phase (1 − φ) mod 1 is rounded to a double: the wall is where it was
                // to the last bits of its amplitude.
                let amplitude = before.scene.walls[i].number(Keyword::OscAmpl).abs();
                for (x, y) in pb[i].iter().zip(&pa[i]) {
                    if let (Some(x), Some(y)) = (x, y)
                        && (x - y).norm() > 1e-9 * (1.0 + x.norm() + amplitude)
                    {
                        return Err(format!("wall {i} is at {x:?} before and {y:?} after"));
                    }
                }
            }
        }
        "C106" => {
            for (b, a) in pairs {
                let (v1, v2) = (a.vector(Keyword::Vertex1), a.vector(Keyword::Vertex2));
                let cos = direction(&v1)
                    .zip(direction(&v2))
                    .map(|(x, y)| x.dot(&y).abs());
                if !cos.is_some_and(|c| c <= walls_model::RECTANGLE_COS_TOLERANCE) {
                    return Err(format!(
                        "wall {}: vertex2 {v2:?} is not across {v1:?}",
                        b.index
                    ));
                }
            }
        }
        "C306" => {
            let k = keyword_at(before, d.span.start);
            for (b, a) in pairs {
                let (vb, va) = (b.vector(k), a.vector(k));
                let same_way = direction(&vb).is_some_and(|u| close(&u, &(va / va.norm())));
                if (va.norm() - 1.0).abs() > walls_model::AXIS_LENGTH_TOLERANCE || !same_way {
                    return Err(format!("wall {}: {k:?} {vb:?} became {va:?}", b.index));
                }
            }
        }
        "C205" => {
            for (b, a) in pairs {
                let oscillates =
                    a.number(Keyword::OscAmpl) != 0.0 && a.number(Keyword::OscFreq) != 0.0;
                if !oscillates || !close(&a.vector(Keyword::OscVec), &a.normal()) {
                    return Err(format!(
                        "wall {}: osc-vec {:?} is not its normal {:?}, or it does not oscillate",
                        b.index,
                        a.vector(Keyword::OscVec),
                        a.normal()
                    ));
                }
            }
        }
        "C304" => {
            for (b, a) in pairs {
                let (xb, xa) = (b.integer(Keyword::Assembly), a.integer(Keyword::Assembly));
                if xb >= 0 || xa != 0 || !b.is_reactive() {
                    return Err(format!(
                        "wall {}: assembly {xb} became {xa} (mass {})",
                        b.index,
                        b.number(Keyword::Mass)
                    ));
                }
            }
        }
        _ => {}
    }
    Ok(())
}

/// Whether `after`, made from `before` by the fixes `fixes`, keeps the meaning, and
/// (with `findings`) has no finding `before` did not have.
fn compare(
    before: &Checked,
    after: &Checked,
    fixes: &[&Diagnostic],
    findings: bool,
) -> Result<(), String> {
    let mut edits: Vec<&Edit> = fixes
        .iter()
        .flat_map(|d| d.fix.iter().flat_map(|f| &f.edits))
        .collect();
    edits.sort_by_key(|e| e.span.start);
    let (wb, wa) = (&before.scene.walls, &after.scene.walls);
    if wb.len() != wa.len() {
        return Err(format!("{} walls became {}", wb.len(), wa.len()));
    }
    if before.scene.units != after.scene.units {
        return Err("the units changed".into());
    }
    let allowed: Vec<Allowed> = fixes.iter().map(|d| allowed(before, d)).collect();
    for (i, (b, a)) in wb.iter().zip(wa).enumerate() {
        if b.units != a.units {
            return Err(format!("wall {i}: its units changed"));
        }
        for &k in Keyword::ALL.iter().filter(|k| k.role() == Role::Property) {
            let (vb, va) = (b.value(k), a.value(k));
            let may = allowed.iter().any(|x| {
                x.keys
                    .iter()
                    .any(|&(w, key)| key == k && w.is_none_or(|w| w == i))
            });
            if vb != va && !may {
                return Err(format!("wall {i}: {} {vb:?} became {va:?}", k.name()));
            }
        }
    }
    if allowed.iter().all(|a| a.typed) {
        let (tb, ta) = (typed(&before.scene), typed(&after.scene));
        if let Some((b, a)) = tb.iter().zip(&ta).find(|(b, a)| b != a) {
            return Err(format!("a typed wall changed:\n{b:?}\n{a:?}"));
        }
    }
    for (d, allowed) in fixes.iter().zip(&allowed) {
        post(d, allowed, before, after)?;
    }
    if findings {
        no_new_finding(before, after, fixes, &|p| back(p, &edits))?;
    }
    Ok(())
}

/// Where byte `p` of a text made by `edits` (sorted, not overlapping) was before them:
/// the range of places it may come from (a byte an edit wrote, or one at an edit's
/// either end, comes from anywhere the edit replaced).
fn back(p: usize, edits: &[&Edit]) -> (usize, usize) {
    let mut delta = 0isize;
    let mut within: Option<(usize, usize)> = None;
    for e in edits {
        let start = (e.span.start as isize + delta) as usize;
        if p < start {
            break;
        }
        if p <= start + e.replacement.len() {
            // Edits that meet share the place: it comes from any of them.
            let lo = within.map_or(e.span.start, |w| w.0);
            within = Some((lo, e.span.end));
        }
        delta += e.replacement.len() as isize - e.span.len() as isize;
    }
    within.unwrap_or_else(|| {
        let p = (p as isize - delta) as usize;
        (p, p)
    })
}

/// Whether `after`, made from `before` by `fixes` (`back` maps its offsets to ranges of
/// `before`'s), has no finding `before` did not have: each of its findings is one of
/// `before`'s (not a fixed one) with the same code at the same place, whatever the
/// messages say of the values. A finding's places are its span and its labels' (a
/// missing value is reported at the token after it, and labelled at its keyword).
fn no_new_finding(
    before: &Checked,
    after: &Checked,
    fixes: &[&Diagnostic],
    back: &dyn Fn(usize) -> (usize, usize),
) -> Result<(), String> {
    // A suppression's code that tried to silence an error (L004) silences nothing once
    // the error is fixed (L003): one finding, that the code has no use.
    let code = |d: &Diagnostic| match d.code.id {
        "L004" => "L003",
        id => id,
    };
    let places = |d: &Diagnostic| -> Vec<usize> {
        std::iter::once(d.span.start)
            .chain(d.labels.iter().map(|l| l.span.start))
            .collect()
    };
    let fixed = |d: &Diagnostic| {
        fixes
            .iter()
            .any(|f| f.code.id == d.code.id && f.span == d.span && f.message == d.message)
    };
    let mut left: Vec<(&str, Vec<usize>)> = before
        .diagnostics
        .iter()
        .filter(|d| !fixed(d))
        .map(|d| (code(d), places(d)))
        .collect();
    // A suppression comment's code whose finding a fix removed silences nothing now: that
    // finding (L003, with its own safe fix) is the suppression's, not a new one.
    let stale = |d: &Diagnostic, at: usize| {
        let text = &before.text;
        let line = text[..at].rfind('\n').map_or(0, |n| n + 1);
        d.code.id == "L003"
            && text[line..at].contains("walls-lint:")
            && text[at..].starts_with(&text_of(after, d))
    };
    for d in &after.diagnostics {
        let ranges: Vec<(usize, usize)> = places(d).into_iter().map(back).collect();
        if ranges.first().is_some_and(|&(lo, _)| stale(d, lo)) {
            continue;
        }
        // The same code at the same span first, else at any of its places.
        let (lo, hi) = ranges[0];
        let found = left
            .iter()
            .position(|(c, at)| *c == code(d) && (lo..=hi).contains(&at[0]))
            .or_else(|| {
                left.iter().position(|(c, at)| {
                    *c == code(d)
                        && at
                            .iter()
                            .any(|p| ranges.iter().any(|(lo, hi)| (lo..=hi).contains(&p)))
                })
            });
        match found {
            Some(i) => {
                left.remove(i);
            }
            None => {
                return Err(format!(
                    "a new finding: {} {} (at bytes {ranges:?} before)",
                    d.code.id, d.message
                ));
            }
        }
    }
    Ok(())
}

/// The text a diagnostic's span covers.
fn text_of(c: &Checked, d: &Diagnostic) -> String {
    c.text[d.span.clone()].to_string()
}

/// What went wrong with one text, if anything, described for a failure message.
fn explain(text: &str, options: &Options, what: &str, fixed: &str, why: &str) -> String {
    format!(
        "{what} ({:?}):\n--- before ---\n{text}--- after ---\n{fixed}--- why ---\n{why}\n",
        options.mode
    )
}

/// Each fix of `text` applied alone.
fn each_fix(
    text: &str,
    options: &Options,
    counts: &mut BTreeMap<&'static str, usize>,
) -> Vec<String> {
    let before = check_text(text, options);
    let mut failed = Vec::new();
    for d in before.diagnostics.iter().filter(|d| d.fix.is_some()) {
        let fixed = apply_fixes(&before.text, std::slice::from_ref(d), Applicability::Unsafe);
        let after = check_text(fixed.as_str(), options);
        *counts.entry(d.code.id).or_insert(0) += 1;
        if let Err(why) = compare(&before, &after, &[d], true) {
            let what = format!("the fix of {} {:?}", d.code.id, d.message);
            failed.push(explain(text, options, &what, &fixed, &why));
        }
    }
    failed
}

/// Two edits conflict when they share a byte or insert at one place (as
/// `apply_fixes` decides).
fn overlap(a: &Edit, b: &Edit) -> bool {
    (a.span.start < b.span.end && b.span.start < a.span.end) || a.span.start == b.span.start
}

/// `walls-lint --fix` (or `--unsafe-fixes`) round by round, each round held to the union
/// of what its fixes may change and to no new finding, and the last text to no finding
/// the first did not have; the last text must be what the tool writes.
fn all_fixes(text: &str, options: &Options, level: Applicability) -> Vec<String> {
    let first = check_text(text, options);
    let mut current = first.clone();
    let mut failed = Vec::new();
    let mut rounds: Vec<Vec<Edit>> = Vec::new();
    for _ in 0..walls_cli::commands::lint::MAX_FIX_ROUNDS {
        let mut taken: Vec<&Edit> = Vec::new();
        let mut applied: Vec<&Diagnostic> = Vec::new();
        for d in &current.diagnostics {
            let Some(fix) = &d.fix else { continue };
            if level == Applicability::Safe && fix.applicability == Applicability::Unsafe {
                continue;
            }
            let malformed = fix
                .edits
                .iter()
                .enumerate()
                .any(|(i, e)| fix.edits[..i].iter().any(|t| overlap(e, t)));
            if !malformed
                && !fix
                    .edits
                    .iter()
                    .any(|e| taken.iter().any(|t| overlap(e, t)))
            {
                taken.extend(&fix.edits);
                applied.push(d);
            }
        }
        if applied.is_empty() {
            break;
        }
        let owned: Vec<Diagnostic> = applied.iter().map(|d| (*d).clone()).collect();
        let fixed = apply_fixes(&current.text, &owned, level);
        if *fixed == *current.text {
            break;
        }
        let after = check_text(fixed.as_str(), options);
        if let Err(why) = compare(&current, &after, &applied, true) {
            let what = format!("a round of {level:?} fixes");
            failed.push(explain(&current.text, options, &what, &fixed, &why));
            return failed;
        }
        let mut edits: Vec<Edit> = taken.into_iter().cloned().collect();
        edits.sort_by_key(|e| e.span.start);
        rounds.push(edits);
        current = after;
    }
    let to_first = |p: usize| {
        rounds.iter().rev().fold((p, p), |(lo, hi), edits| {
            let edits: Vec<&Edit> = edits.iter().collect();
            (back(lo, &edits).0, back(hi, &edits).1)
        })
    };
    if let Err(why) = no_new_finding(&first, &current, &[], &to_first) {
        let what = format!("{level:?} fixing");
        failed.push(explain(text, options, &what, &current.text, &why));
    }
    let (tool, _) = fix_text(text, options, level);
    if tool != *current.text {
        failed.push(explain(
            text,
            options,
            "walls-lint's fixing",
            &tool,
            "not the rounds' text",
        ));
    }
    failed
}

/// fmt, fix, fmt: the fixed file formats to the same findings and scene, and leaves
/// nothing to fix.
fn fmt_fix_fmt(text: &str, options: &Options) -> Vec<String> {
    let format = |t: &str| {
        walls_format::format(&walls_syntax::parse(t), &Default::default())
            .ok()
            .map(|f| f.text.to_string())
    };
    let Some(formatted) = format(text) else {
        return Vec::new();
    };
    let (fixed, _) = fix_text(&formatted, options, Applicability::Safe);
    let Some(again) = format(&fixed) else {
        return vec![explain(
            text,
            options,
            "fmt -> fix",
            &fixed,
            "no longer formats",
        )];
    };
    let (b, a) = (
        check_text(fixed.as_str(), options),
        check_text(again.as_str(), options),
    );
    let mut failed = Vec::new();
    if findings(&b) != findings(&a) {
        failed.push(explain(
            &fixed,
            options,
            "fix -> fmt",
            &again,
            "the findings changed",
        ));
    }
    if let Err(why) = compare(&b, &a, &[], false) {
        failed.push(explain(&fixed, options, "fix -> fmt", &again, &why));
    }
    let (left, n) = fix_text(&again, options, Applicability::Safe);
    if n > 0 {
        failed.push(explain(
            &again,
            options,
            "fmt -> fix -> fmt -> fix",
            &left,
            "fixed again",
        ));
    }
    failed
}

/// Everything this test checks of one text under `options`.
fn check_all(
    text: &str,
    options: &Options,
    counts: &mut BTreeMap<&'static str, usize>,
) -> Vec<String> {
    let mut failed = each_fix(text, options, counts);
    failed.extend(all_fixes(text, options, Applicability::Safe));
    failed.extend(all_fixes(text, options, Applicability::Unsafe));
    failed.extend(fmt_fix_fmt(text, options));
    failed
}

fn options(mode: ContactModel, speeds: bool) -> Options {
    Options {
        mode,
        min_radius: speeds.then_some(0.05),
        dt: speeds.then_some(0.01),
        ..Options::default()
    }
}

/// The walls files of the repository: every `*.walls` and the golden runs' `walls.dat`.
fn repository_files() -> Vec<PathBuf> {
    fn walk(dir: &Path, out: &mut Vec<PathBuf>) {
        for entry in std::fs::read_dir(dir).unwrap() {
            let path = entry.unwrap().path();
            let name = path.file_name().unwrap().to_string_lossy().to_string();
            if path.is_dir() {
                if !matches!(name.as_str(), "target" | ".git" | "node_modules" | "fuzz") {
                    walk(&path, out);
                }
            } else if name.ends_with(".walls") || name == "walls.dat" {
                out.push(path);
            }
        }
    }
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let mut out = Vec::new();
    walk(&root, &mut out);
    out.sort();
    out
}

/// The `walls` examples in the codes' explanations.
fn examples() -> Vec<String> {
    let mut out = Vec::new();
    for code in walls_cli::all_codes() {
        let mut rest = code.explanation;
        while let Some(at) = rest.find("```walls\n") {
            rest = &rest[at + 9..];
            let end = rest.find("```").unwrap_or(rest.len());
            out.push(rest[..end].to_string());
            rest = &rest[end..];
        }
    }
    out
}

#[test]
fn fixes_of_the_repository_files_and_the_examples_keep_the_meaning() {
    let files = repository_files();
    assert!(files.len() > 200, "found only {} walls files", files.len());
    let mut texts: Vec<(String, String)> = files
        .iter()
        .filter_map(|p| {
            let bytes = std::fs::read(p).unwrap();
            String::from_utf8(bytes)
                .ok()
                .map(|t| (p.display().to_string(), t))
        })
        .collect();
    texts.extend(
        examples()
            .into_iter()
            .map(|t| ("an example".to_string(), t)),
    );
    let mut counts = BTreeMap::new();
    let mut failed = Vec::new();
    for (name, text) in &texts {
        for mode in [ContactModel::Ssdem, ContactModel::Hsdem] {
            for f in check_all(text, &options(mode, false), &mut counts) {
                failed.push(format!("{name}: {f}"));
            }
        }
    }
    eprintln!(
        "fixes applied alone, per code, in {} texts: {counts:?}",
        texts.len()
    );
    assert!(
        failed.is_empty(),
        "{} failures:\n{}",
        failed.len(),
        failed.join("\n")
    );
}

#[test]
fn fixes_of_generated_files_keep_the_meaning() {
    let cases = std::env::var("PROPTEST_CASES")
        .ok()
        .and_then(|c| c.parse().ok())
        .unwrap_or(600);
    // The same files every run, so that the counts of fixes reached do not vary: a new
    // seed explores (PROPTEST_RNG_SEED, with PROPTEST_CASES for more files).
    let seed = std::env::var("PROPTEST_RNG_SEED")
        .ok()
        .and_then(|s| s.parse::<u64>().ok())
        .unwrap_or(40);
    let mut bytes = [0u8; 32];
    bytes[..8].copy_from_slice(&seed.to_le_bytes());
    let rng = proptest::test_runner::TestRng::from_seed(
        proptest::test_runner::RngAlgorithm::ChaCha,
        &bytes,
    );
    let mut runner = TestRunner::new_with_rng(
        Config {
            cases,
            failure_persistence: None,
            ..Config::default()
        },
        rng,
    );
    let counts = Mutex::new(BTreeMap::new());
    let strategy = (
        walls_test_support::arbitrary::fixable_file(),
        proptest::bool::ANY,
        proptest::bool::weighted(0.3),
    );
    let started = std::time::Instant::now();
    let result = runner.run(&strategy, |(text, hsdem, speeds)| {
        let mode = if hsdem {
            ContactModel::Hsdem
        } else {
            ContactModel::Ssdem
        };
        let mut mine = BTreeMap::new();
        let failed = check_all(&text, &options(mode, speeds), &mut mine);
        let mut all = counts.lock().unwrap();
        for (code, n) in mine {
            *all.entry(code).or_insert(0) += n;
        }
        if failed.is_empty() {
            Ok(())
        } else {
            Err(TestCaseError::fail(failed.join("\n")))
        }
    });
    let counts = counts.into_inner().unwrap();
    eprintln!(
        "{cases} generated files in {:.1} s; fixes applied alone, per code: {counts:?}",
        started.elapsed().as_secs_f64()
    );
    if let Err(e) = result {
        panic!("{e}");
    }
    let short: Vec<String> = FIXED_CODES
        .iter()
        .filter(|c| counts.get(**c).copied().unwrap_or(0) < MIN_APPLIED)
        .map(|c| format!("{c} ({})", counts.get(*c).copied().unwrap_or(0)))
        .collect();
    assert!(
        short.is_empty() || cases < 600,
        "the generator reaches too few fixes of: {}",
        short.join(", ")
    );
}
