//! C304 `mass-without-assembly`: a wall has a mass but no assembly (an error).
//!
//! Checked over the reactive walls in SSDEM: walls are gathered by the token that gave
//! them their mass, and each token is reported once, after every wall. A mass from a
//! `defaults` line is reported on that line, with the walls it reaches as labels (the
//! first [`MAX_LABELS`]; the message gives their count).
//!
//! The fix gives assembly 0 to exactly the walls the diagnostic names: one `assembly 0`
//! after a `defaults` mass when it reaches those walls and no other, else one for each
//! wall (its own `assembly` set to 0, or `assembly 0` added to its block).

use super::{ByPlace, walls_named};
use crate::check::Checker;
use crate::fix::append;
use crate::scene::{Place, Scene, Source, Wall};
use std::collections::{HashMap, HashSet};
use std::ops::Range;
use walls_diagnostics::{Applicability, Code, Diagnostic, Edit, MAX_LABELS};
use walls_keywords::Keyword;
use walls_syntax::BlockKind;

/// A wall has a mass but no assembly.
pub static MASS_WITHOUT_ASSEMBLY: Code = Code {
    id: "C304",
    name: "mass-without-assembly",
    summary: "a wall has a mass but no assembly",
    explanation: "A wall with a mass reacts to the particles that hit it, and pkdgrav keeps the
motion of reactive walls per assembly. A wall with a mass but no `assembly` keeps the
assembly −1, and pkdgrav then writes its per-assembly arrays at index −1, memory it does
not own: the run is silently corrupted. Give every inertial wall an assembly, 0 or 1. A
`mass` on a `defaults` line reaches every later wall that does not set its own: the
diagnostic is on that line and lists the walls. The fix (unsafe: check that the walls
belong together) puts exactly those walls in assembly 0: it adds `assembly 0` after the
`mass` when that reaches no other wall, and otherwise to each wall (or sets the wall's own
`assembly` to 0).

Bad:
```walls
wall type disk
  mass 1
```

Good:
```walls
wall type disk
  mass 1
  assembly 0
```
",
};

/// The reactive walls with no assembly, by the start of the `mass` values that gave
/// them their mass.
#[derive(Default)]
pub(crate) struct NoAssembly<'w>(ByPlace<'w, usize>);

impl<'w> NoAssembly<'w> {
    /// Notes `wall`, a reactive wall, if it has no assembly.
    pub(crate) fn note(&mut self, wall: &'w Wall) {
        if wall.integer(Keyword::Assembly) >= 0 {
            return;
        }
        let key = wall
            .setting(Keyword::Mass)
            .and_then(|s| s.source.span())
            .map_or(wall.span.start, |s| s.start);
        self.0.add(key, wall);
    }

    /// Reports each `mass` token, in the order of its first wall.
    pub(crate) fn report(self, cx: &mut Checker, scene: &Scene) {
        let mut reach = None;
        for (_, walls) in self.0.into_groups() {
            report(cx, scene, &mut reach, &walls);
        }
    }
}

/// Where the `assembly` a wall takes is set, if it is set at `place`: in the wall's own
/// block, or in `defaults`.
fn assembly_set(wall: &Wall, at: Place) -> Option<Range<usize>> {
    match wall.settings.get(Keyword::Assembly).map(|s| &s.source) {
        Some(Source::Set { place, values, .. }) if *place == at => Some(values.range()),
        _ => None,
    }
}

/// Where a wall sets its own `assembly`, if it does.
fn own_assembly(wall: &Wall) -> Option<Range<usize>> {
    assembly_set(wall, Place::Wall)
}

/// Where the `defaults` assembly a wall takes is set, if it takes one.
fn inherited_assembly(wall: &Wall) -> Option<Range<usize>> {
    assembly_set(wall, Place::Defaults)
}

/// Who reads which `assembly`, made once per file (when a mass is reported).
struct Reach {
    /// Where each `defaults` sets `assembly`, in file order.
    defaults: Vec<usize>,
    /// How many of the first i walls set their own `assembly`.
    own: Vec<usize>,
    /// The walls that take each `defaults` assembly, by where its values start.
    users: HashMap<usize, Vec<usize>>,
    /// The `defaults` assemblies that a wall without a mass takes (no fix of this code
    /// takes such a wall from one), by where their values start.
    steady: HashSet<usize>,
}

impl Reach {
    fn new(scene: &Scene) -> Self {
        let mut own = Vec::with_capacity(scene.walls.len() + 1);
        own.push(0);
        let mut users: HashMap<usize, Vec<usize>> = HashMap::new();
        let mut steady = HashSet::new();
        for w in &scene.walls {
            own.push(own[own.len() - 1] + usize::from(own_assembly(w).is_some()));
            if let Some(s) = inherited_assembly(w) {
                users.entry(s.start).or_default().push(w.index);
                if !w.is_reactive() {
                    steady.insert(s.start);
                }
            }
        }
        Reach {
            defaults: scene
                .defaults
                .iter()
                .filter(|(k, _)| *k == Keyword::Assembly)
                .map(|(_, span)| span.start)
                .collect(),
            own,
            users,
            steady,
        }
    }

    /// Whether `assembly 0` added after the `defaults` mass at `mass` reaches exactly
    /// `needing`: the mass's block sets no assembly, and the walls made after it until a
    /// `defaults` next sets one, less those that set their own, are `needing`.
    fn exactly(&self, cx: &Checker, scene: &Scene, mass: &Range<usize>, needing: &[&Wall]) -> bool {
        let tree = cx.tree;
        let Some(block) = cx.block_at(mass.start) else {
            return false;
        };
        let sets_assembly = tree
            .body(block)
            .iter()
            .any(|s| tree.keyword(s) == Some(Keyword::Assembly));
        if block.kind != BlockKind::Defaults || sets_assembly {
            return false;
        }
        let next = self.defaults.partition_point(|&d| d < mass.start);
        let until = self.defaults.get(next).copied().unwrap_or(usize::MAX);
        let first = scene.walls.partition_point(|w| w.span.start < mass.start);
        let last = scene.walls.partition_point(|w| w.span.start < until);
        let reached = (last - first) - (self.own[last] - self.own[first]);
        reached == needing.len() && needing.iter().all(|w| (first..last).contains(&w.index))
    }
}

/// The fix that puts exactly `walls` (the walls with no assembly that take their mass
/// from the `mass` values at `mass`) in assembly 0: what it does, and its edits.
///
/// A wall that sets its own `assembly` gets it set to 0, and a `defaults` assembly that
/// only these walls take is set to 0 where it is written. The other walls get one
/// `assembly 0` after the mass when the mass is in their block, or is in `defaults` and
/// that reaches them and no other wall; else `assembly 0` at the end of each one's block.
/// The `defaults` assembly such a wall took keeps a wall that no fix of this code takes
/// from it (one without a mass, else the last that takes it, whose fix waits until it is
/// the only one and then sets it in place), so that none is left that no wall takes,
/// whichever of these fixes are applied together; `None` where that cannot be.
fn fix(
    cx: &Checker,
    scene: &Scene,
    reach: &mut Option<Reach>,
    mass: &Range<usize>,
    from_defaults: bool,
    walls: &[&Wall],
) -> Option<(String, Vec<Edit>)> {
    let reach = reach.get_or_insert_with(|| Reach::new(scene));
    let mut edits = Vec::new();
    let mut inherit: Vec<&Wall> = Vec::new();
    // The `defaults` assemblies these walls take, with how many of them take each.
    let mut sources: HashMap<usize, (Range<usize>, usize)> = HashMap::new();
    for &w in walls {
        if let Some(values) = own_assembly(w) {
            edits.push(Edit {
                span: values,
                replacement: "0".into(),
            });
            continue;
        }
        inherit.push(w);
        if let Some(s) = inherited_assembly(w) {
            sources.entry(s.start).or_insert((s, 0)).1 += 1;
        }
    }
    let users = |s: &Range<usize>| reach.users.get(&s.start).map_or(&[][..], Vec::as_slice);
    let only_theirs = |s: &Range<usize>, n: usize| users(s).len() == n;
    let named = |w: &usize| walls.binary_search_by_key(w, |x| x.index).is_ok();
    for (s, n) in sources.values() {
        let kept = reach.steady.contains(&s.start) || users(s).last().is_some_and(|w| !named(w));
        if !only_theirs(s, *n) && !kept {
            return None;
        }
    }
    let mut message = match walls {
        [w] => format!("put wall {} in assembly 0", w.index),
        _ => format!("put these {} walls in assembly 0", walls.len()),
    };
    let set_in_place: HashSet<usize> = sources
        .values()
        .filter(|(s, n)| only_theirs(s, *n))
        .map(|(s, _)| s.start)
        .collect();
    edits.extend(set_in_place.iter().map(|s| Edit {
        span: sources[s].0.clone(),
        replacement: "0".into(),
    }));
    inherit.retain(|w| inherited_assembly(w).is_none_or(|s| !set_in_place.contains(&s.start)));
    if !inherit.is_empty() {
        if !from_defaults || reach.exactly(cx, scene, mass, &inherit) {
            if edits.is_empty() {
                message = "add `assembly 0` after the mass".into();
            }
            edits.push(append(cx.tree.text(), mass.end, " assembly 0".into()));
        } else {
            for w in inherit {
                edits.push(append(
                    cx.tree.text(),
                    w.block.range().end,
                    " assembly 0".into(),
                ));
            }
        }
    }
    edits.sort_by_key(|e| e.span.start);
    Some((message, edits))
}

/// One error for the `mass` token that gave `walls` their mass.
fn report(cx: &mut Checker, scene: &Scene, reach: &mut Option<Reach>, walls: &[&Wall]) {
    let first = walls[0];
    let setting = first.setting(Keyword::Mass);
    let from_defaults = matches!(
        setting.as_ref().map(|s| &s.source),
        Some(Source::Set {
            place: Place::Defaults,
            ..
        })
    );
    let span = cx.mass_span(first);
    let mut d = if from_defaults {
        let mut d = Diagnostic::error(
            &MASS_WITHOUT_ASSEMBLY,
            span.clone(),
            format!(
                "this `defaults` mass gives {} a mass but no assembly",
                walls_named(walls)
            ),
        );
        for w in walls.iter().take(MAX_LABELS) {
            d = d.with_label(w.span.clone(), format!("wall {} has this mass", w.index));
        }
        d
    } else {
        Diagnostic::error(
            &MASS_WITHOUT_ASSEMBLY,
            span.clone(),
            format!("wall {} has a mass but no assembly", first.index),
        )
    };
    d = d.with_help(
        "pkdgrav would index its per-assembly arrays at -1 and corrupt the run: give every inertial wall an assembly, 0 or 1",
    );
    if let Some((message, edits)) = setting
        .is_some()
        .then(|| fix(cx, scene, reach, &span, from_defaults, walls))
        .flatten()
    {
        d = d.with_fix(Applicability::Unsafe, message, edits);
    }
    cx.push_about(d, Some(Keyword::Mass));
}
