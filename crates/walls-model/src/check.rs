//! The checker: rules about whole walls, blocks and files (SPEC §1 "Checks users expect"
//! and the wall-type and contact-model rules), on top of the value rules the resolver
//! applies as it reads.

use crate::codes;
use crate::fix;
use crate::scene::{Place, Scene, Setting, Source, Vec3, Wall, direction};
use crate::{Mode, Options};
use std::collections::{HashMap, HashSet};
use std::ops::Range;
use walls_diagnostics::{Applicability, Diagnostic, Edit, MAX_LABELS};
use walls_keywords::{Keyword, Role, Types, WallType};
use walls_syntax::{Item, Statement, SyntaxTree, TokenKind};

/// Above this |cos| a rectangle's sides are not perpendicular (SPEC §1).
pub const RECTANGLE_COS_TOLERANCE: f64 = 0.001;
/// Principal axes with |cos| above this are not orthogonal.
pub const AXES_COS_TOLERANCE: f64 = 0.001;
/// A wall may move this fraction of the smallest particle radius in one step.
pub const STEP_TRAVEL_FRACTION: f64 = 0.03;

/// Runs the block and wall rules.
pub(crate) fn check(tree: &SyntaxTree, scene: &Scene, options: &Options) -> Vec<Diagnostic> {
    let mut c = Checker {
        tree,
        options,
        out: Vec::new(),
        seen: HashSet::new(),
    };
    c.blocks();
    c.walls(scene);
    c.file(scene);
    c.out
}

struct Checker<'a> {
    tree: &'a SyntaxTree,
    options: &'a Options,
    out: Vec<Diagnostic>,
    /// Code, span and (for codes about several keywords) keyword of what was reported,
    /// so a `defaults` line shared by many walls is reported once.
    seen: HashSet<(&'static str, usize, usize, Option<Keyword>)>,
}

impl Checker<'_> {
    fn push(&mut self, d: Diagnostic) {
        self.push_about(d, None);
    }

    /// Reports `d` unless the same code was reported at the same span (about the same
    /// keyword) already.
    fn push_about(&mut self, d: Diagnostic, keyword: Option<Keyword>) {
        if self
            .seen
            .insert((d.code.id, d.span.start, d.span.end, keyword))
        {
            self.out.push(d);
        }
    }

    /// Repeated tokens and `k_t` before `k_n`, block by block.
    fn blocks(&mut self) {
        let tree = self.tree;
        let mut keyed: Vec<(Keyword, &Statement)> = Vec::new();
        for item in tree.items() {
            let Item::Block(block) = item else { continue };
            // The block's property statements by keyword, in source order within a
            // keyword (a stable sort); one buffer serves every block.
            keyed.clear();
            keyed.extend(tree.body(block).iter().filter_map(|s| {
                tree.keyword(s)
                    .filter(|k| k.role() == Role::Property)
                    .map(|k| (k, s))
            }));
            keyed.sort_by_key(|&(k, _)| k);
            let last_of = |k: Keyword| {
                keyed
                    .iter()
                    .rev()
                    .find(|(key, _)| *key == k)
                    .map(|&(_, s)| s)
            };
            let mut repeated: Vec<(&Statement, &Statement)> = keyed
                .windows(2)
                .filter(|w| w[0].0 == w[1].0)
                .map(|w| {
                    (
                        w[0].1,
                        last_of(w[0].0).expect("the keyword is in the block"),
                    )
                })
                .collect();
            repeated.sort_by_key(|(s, _)| tree.span(tree.head(s)).start);
            for (earlier, last) in repeated {
                let head = tree.head(earlier);
                let name = tree.token_text(head);
                self.push(
                    Diagnostic::warning(
                        &codes::REPEATED_TOKEN,
                        tree.span(head),
                        format!(
                            "`{name}` is set again later in this block, so this value has no effect"
                        ),
                    )
                    .with_label(tree.span(tree.head(last)), "the last one wins")
                    .with_fix(
                        Applicability::Safe,
                        format!("remove this `{name}`"),
                        vec![self.delete(earlier)],
                    ),
                );
            }
            for (kt, kn) in [
                (Keyword::KT, Keyword::KN),
                (Keyword::KTOuter, Keyword::KNOuter),
                (Keyword::KTInner, Keyword::KNInner),
            ] {
                let (Some(last_kt), Some(last_kn)) = (last_of(kt), last_of(kn)) else {
                    continue;
                };
                let (kt_span, kn_span) =
                    (tree.span(tree.head(last_kt)), tree.span(tree.head(last_kn)));
                if kt_span.start < kn_span.start {
                    self.push(
                        Diagnostic::warning(
                            &codes::KT_BEFORE_KN,
                            kt_span,
                            format!("`{}` is overwritten by the `{}` after it, which sets it to 2/7 of its value", kt.name(), kn.name()),
                        )
                        .with_label(kn_span, format!("this sets `{}` again", kt.name()))
                        .with_help(format!("write `{}` after `{}`", kt.name(), kn.name())),
                    );
                }
            }
        }
    }

    fn walls(&mut self, scene: &Scene) {
        let mut non_sticky: Option<&Wall> = None;
        let mut hsdem_99: HashMap<(Keyword, Option<usize>), Vec<&Wall>> = HashMap::new();
        for wall in &scene.walls {
            let t = wall.wall_type();
            self.ignored_by_type(wall, t);
            self.geometry(wall, t);
            self.oscillation(wall);
            self.speed(wall, t);
            if self.options.mode == Mode::Ssdem {
                self.reactive(wall, t);
            } else {
                self.hsdem(wall, t);
                for k in [Keyword::Epsn, Keyword::Epst] {
                    if wall.number(k) == 99.0 {
                        let key = wall
                            .setting(k)
                            .and_then(|s| s.source.span())
                            .map(|s| s.start);
                        hsdem_99.entry((k, key)).or_default().push(wall);
                    }
                }
            }
            let epsn = wall.number(Keyword::Epsn);
            match non_sticky {
                Some(first) if epsn == 0.0 => {
                    let mut d = Diagnostic::warning(
                        &codes::STICKY_WALL_ORDER,
                        wall.span.clone(),
                        format!("sticky wall {} (epsn 0) comes after non-sticky wall {}", wall.index, first.index),
                    )
                    .with_label(first.span.clone(), format!("wall {} is not sticky", first.index))
                    .with_help("list sticky walls first and keep their order: pkdgrav stores the index of the wall a particle sticks to");
                    if let Some(span) = wall.setting(Keyword::Epsn).and_then(|s| s.source.span()) {
                        d = d.with_label(span, "epsn 0 makes it sticky");
                    }
                    self.push(d);
                }
                None if epsn != 0.0 => non_sticky = Some(wall),
                _ => {}
            }
        }
        let mut groups: Vec<_> = hsdem_99.into_iter().collect();
        groups.sort_by_key(|((k, _), walls)| (walls[0].index, *k));
        for ((k, source), walls) in groups {
            self.hsdem_particle_value(k, source.is_some(), &walls);
        }
    }

    fn span_of(&self, wall: &Wall, k: Keyword) -> Option<Range<usize>> {
        wall.setting(k).and_then(|s| s.source.span())
    }

    fn ignored_by_type(&mut self, wall: &Wall, t: WallType) {
        let tree = self.tree;
        for (k, setting) in wall.settings.iter() {
            let Source::Set {
                place: Place::Wall,
                values,
                derived_from: None,
            } = &setting.source
            else {
                continue;
            };
            if k.applies_to().contains(t) {
                continue;
            }
            let Some(stmt) = tree.statement_containing(values.range().start) else {
                continue;
            };
            let keyword = tree.span(tree.head(&stmt));
            let mut d = Diagnostic::warning(
                &codes::IGNORED_BY_TYPE,
                keyword.clone(),
                format!(
                    "a {} wall ignores `{}`",
                    t.name(),
                    &tree.text()[keyword.clone()]
                ),
            )
            .with_help(format!(
                "`{}` applies to {}",
                k.name(),
                k.applies_to().names().join(", ")
            ));
            d = d.with_fix(
                Applicability::Safe,
                format!("remove `{}`, which has no effect", k.name()),
                vec![self.delete(&stmt)],
            );
            self.push(d);
        }
    }

    fn geometry(&mut self, wall: &Wall, t: WallType) {
        let (v1, v2) = (wall.vector(Keyword::Vertex1), wall.vector(Keyword::Vertex2));
        let at_vertices = || {
            self.span_of(wall, Keyword::Vertex2)
                .or_else(|| self.span_of(wall, Keyword::Vertex1))
                .unwrap_or_else(|| wall.span.clone())
        };
        // Directions, so that vectors too long for a double still compare.
        let edges = direction(&v1).zip(direction(&v2));
        match (t, edges) {
            (WallType::Triangle, Some((d1, d2))) if d1.cross(&d2).norm() <= 1e-12 => {
                self.push(Diagnostic::error(
                    &codes::DEGENERATE_TRIANGLE,
                    at_vertices(),
                    format!(
                        "triangle wall {} has parallel vertex1 and vertex2: no area, no normal",
                        wall.index
                    ),
                ));
            }
            (WallType::Rectangle, Some((d1, d2))) => {
                let cos = d1.dot(&d2);
                if cos.abs() > RECTANGLE_COS_TOLERANCE {
                    let mut d = Diagnostic::error(
                        &codes::RECTANGLE_NOT_RECTANGULAR,
                        at_vertices(),
                        format!(
                            "rectangle wall {} has vertex1 and vertex2 at {:.3}° (|cos| {:.4} > {RECTANGLE_COS_TOLERANCE})",
                            wall.index,
                            cos.clamp(-1.0, 1.0).acos().to_degrees(),
                            cos.abs()
                        ),
                    );
                    if let Some(Setting {
                        source: Source::Set { values, .. },
                        ..
                    }) = wall.setting(Keyword::Vertex2)
                    {
                        // Back to the units vertex2 was written in: the ratio of its
                        // largest component to that component as written.
                        let written: Vec<f64> = self.tree.text()[values.range()]
                            .split([' ', '\t', ',', '='])
                            .filter_map(|w| w.parse::<f64>().ok())
                            .collect();
                        let written_max = written.iter().fold(0.0f64, |m, x| m.max(x.abs()));
                        let scale = v2.amax() / written_max;
                        let perpendicular: Vec3 = (v2 - d1 * v2.dot(&d1)) / scale;
                        if perpendicular.iter().all(|x| x.is_finite()) {
                            d = d.with_fix(
                                Applicability::Unsafe,
                                "make vertex2 perpendicular to vertex1 (keep its part across vertex1)",
                                vec![Edit {
                                    span: values.range(),
                                    replacement: fix::vector(&perpendicular),
                                }],
                            );
                        }
                    }
                    self.push(d);
                }
            }
            (WallType::Disk, _) => {
                let (r, h) = (
                    wall.number(Keyword::Radius),
                    wall.number(Keyword::HoleRadius),
                );
                if !(h < r || (h == 0.0 && r == 0.0)) && r >= 0.0 && h >= 0.0 {
                    let span = self
                        .span_of(wall, Keyword::HoleRadius)
                        .or_else(|| self.span_of(wall, Keyword::Radius))
                        .unwrap_or_else(|| wall.span.clone());
                    self.push(Diagnostic::error(
                        &codes::HOLE_NOT_INSIDE,
                        span,
                        format!(
                            "disk wall {} has hole-radius {h} not smaller than its radius {r}",
                            wall.index
                        ),
                    ));
                }
            }
            (WallType::CylinderFinite, _) => {
                let taper = wall.number(Keyword::Taper);
                if taper != 0.0 && wall.number(Keyword::Length) == 0.0 {
                    let span = self
                        .span_of(wall, Keyword::Taper)
                        .unwrap_or_else(|| wall.span.clone());
                    let mut d = Diagnostic::error(
                        &codes::TAPER_ON_RING,
                        span,
                        format!(
                            "finite cylinder wall {} has length 0 (a ring), which cannot taper",
                            wall.index
                        ),
                    );
                    if let Some(l) = self.span_of(wall, Keyword::Length) {
                        d = d.with_label(l, "length 0");
                    }
                    self.push(d);
                }
            }
            _ => {}
        }
    }

    fn oscillation(&mut self, wall: &Wall) {
        let (a, w) = (wall.number(Keyword::OscAmpl), wall.number(Keyword::OscFreq));
        if (a != 0.0) != (w != 0.0) {
            let (set, missing) = if a != 0.0 {
                (Keyword::OscAmpl, Keyword::OscFreq)
            } else {
                (Keyword::OscFreq, Keyword::OscAmpl)
            };
            let span = self.span_of(wall, set).unwrap_or_else(|| wall.span.clone());
            self.push(
                Diagnostic::warning(
                    &codes::LONE_OSCILLATION,
                    span,
                    format!(
                        "wall {} has `{}` but no `{}`, so it does not oscillate",
                        wall.index,
                        set.name(),
                        missing.name()
                    ),
                )
                .with_help("the wall moves by osc-ampl · sin(osc-freq · t + 2π · osc-phase)"),
            );
            return;
        }
        if a == 0.0 || wall.settings.get(Keyword::OscVec).is_some() {
            return;
        }
        let normal = wall.normal();
        if normal.norm() == 0.0 || normal.z.abs() > 1.0 - 1e-9 {
            return;
        }
        let polygon = Types::POLYGON.contains(wall.wall_type());
        let orient = (!polygon).then(|| wall.setting(Keyword::Orient)).flatten();
        let mut d = Diagnostic::warning(
            &codes::OSC_VEC_NOT_FOLLOWING_ORIENT,
            orient
                .as_ref()
                .and_then(|s| s.source.span())
                .unwrap_or_else(|| wall.span.clone()),
            format!(
                "wall {} oscillates along 0 0 1 although its normal is {}: osc-vec does not follow orient",
                wall.index,
                fix::vector(&normal)
            ),
        );
        if let Some(span) = self.span_of(wall, Keyword::OscAmpl) {
            d = d.with_label(span, "it oscillates");
        }
        d = match orient.map(|s| s.source) {
            Some(Source::Set { values, .. }) => d.with_fix(
                Applicability::Unsafe,
                "oscillate along the normal: set osc-vec to orient",
                vec![Edit {
                    span: values.range().end..values.range().end,
                    replacement: format!(" osc-vec {}", fix::vector(&normal)),
                }],
            ),
            _ => d.with_help(format!(
                "add `osc-vec {}` to oscillate along the normal",
                fix::vector(&normal)
            )),
        };
        self.push(d);
    }

    fn speed(&mut self, wall: &Wall, t: WallType) {
        let Some(min_radius) = self.options.min_radius else {
            return;
        };
        if self.options.mode != Mode::Ssdem {
            return;
        }
        let step = match wall.number(Keyword::Step) {
            s if s > 0.0 => s,
            _ => match self.options.dt {
                Some(dt) => dt,
                None => return,
            },
        };
        let rim = match t {
            WallType::Disk
            | WallType::CylinderInfinite
            | WallType::CylinderFinite
            | WallType::Shell => {
                wall.number(Keyword::AngSpeed).abs() * wall.number(Keyword::Radius)
            }
            _ => 0.0,
        };
        let linear = wall.vector(Keyword::Velocity).norm();
        let osc = (wall.number(Keyword::OscAmpl) * wall.number(Keyword::OscFreq)).abs();
        let speed = linear + osc + rim;
        let travel = speed * step;
        if travel > STEP_TRAVEL_FRACTION * min_radius {
            self.push(
                Diagnostic::warning(
                    &codes::WALL_TOO_FAST,
                    wall.span.clone(),
                    format!(
                        "wall {} moves up to {} per step ({} × step {}), more than {}% of the smallest particle radius {}",
                        wall.index,
                        fix::rounded(travel),
                        fix::rounded(speed),
                        fix::rounded(step),
                        STEP_TRAVEL_FRACTION * 100.0,
                        fix::rounded(min_radius)
                    ),
                )
                .with_help(format!(
                    "speed = |velocity| {} + |osc-ampl·osc-freq| {} + |ang-speed|·radius {}; use a smaller step",
                    fix::rounded(linear),
                    fix::rounded(osc),
                    fix::rounded(rim)
                )),
            );
        }
    }

    fn reactive(&mut self, wall: &Wall, t: WallType) {
        let assembly = wall.integer(Keyword::Assembly);
        if !wall.is_reactive() {
            if assembly >= 0 {
                let span = self
                    .span_of(wall, Keyword::Assembly)
                    .unwrap_or_else(|| wall.span.clone());
                self.push(Diagnostic::error(
                    &codes::ASSEMBLY_WITHOUT_MASS,
                    span,
                    format!(
                        "wall {} is in assembly {assembly} but has no mass",
                        wall.index
                    ),
                ));
            }
            return;
        }
        let mass = self
            .span_of(wall, Keyword::Mass)
            .unwrap_or_else(|| wall.span.clone());
        if !Types::REACTIVE.contains(t) {
            self.push(Diagnostic::error(
                &codes::REACTIVE_TYPE,
                mass.clone(),
                format!(
                    "wall {} is a {} and cannot have a mass",
                    wall.index,
                    t.name()
                ),
            ));
        }
        if wall.number(Keyword::AngSpeed) != 0.0 {
            let span = self
                .span_of(wall, Keyword::AngSpeed)
                .unwrap_or_else(|| wall.span.clone());
            self.push(
                Diagnostic::error(
                    &codes::REACTIVE_SPINNING,
                    span,
                    format!("reactive wall {} has an ang-speed", wall.index),
                )
                .with_help("a reactive wall turns through rot-vec and the torques on its assembly"),
            );
        }
        if assembly < 0 {
            self.push(
                Diagnostic::warning(
                    &codes::MASS_WITHOUT_ASSEMBLY,
                    mass,
                    format!("wall {} has a mass but no assembly", wall.index),
                )
                .with_help("give every inertial wall an assembly, 0 or 1"),
            );
        }
        let axes = [Keyword::PxjVec, Keyword::PyjVec, Keyword::PzjVec];
        for (i, j) in [(0, 1), (0, 2), (1, 2)] {
            let (a, b) = (wall.vector(axes[i]), wall.vector(axes[j]));
            if a.norm() == 0.0 || b.norm() == 0.0 {
                continue;
            }
            let cos = a.dot(&b) / (a.norm() * b.norm());
            if cos.abs() > AXES_COS_TOLERANCE {
                let span = self
                    .span_of(wall, axes[j])
                    .or_else(|| self.span_of(wall, axes[i]))
                    .unwrap_or_else(|| wall.span.clone());
                self.push(Diagnostic::warning(
                    &codes::AXES_NOT_ORTHOGONAL,
                    span,
                    format!(
                        "principal axes `{}` and `{}` are not orthogonal (|cos| {:.4})",
                        axes[i].name(),
                        axes[j].name(),
                        cos.abs()
                    ),
                ));
            }
        }
    }

    fn hsdem(&mut self, wall: &Wall, t: WallType) {
        if t.ssdem_only() {
            let span = self
                .span_of(wall, Keyword::Type)
                .unwrap_or_else(|| wall.span.clone());
            self.push(
                Diagnostic::error(
                    &codes::NOT_IN_HSDEM,
                    span,
                    format!("pkdgrav's hard-sphere code has no {} walls", t.name()),
                )
                .with_help(
                    "run with SSDEM, or build the shape from rectangles, disks and cylinders",
                ),
            );
        }
        if t == WallType::CylinderFinite && wall.number(Keyword::Taper) != 0.0 {
            let span = self
                .span_of(wall, Keyword::Taper)
                .unwrap_or_else(|| wall.span.clone());
            self.push(
                Diagnostic::error(
                    &codes::NOT_IN_HSDEM,
                    span,
                    "pkdgrav's hard-sphere code does not implement `taper`",
                )
                .with_help("remove `taper`, or run with SSDEM"),
            );
        }
    }

    /// One diagnostic per place that leaves the coefficient at 99 for the walls listed.
    fn hsdem_particle_value(&mut self, k: Keyword, from_token: bool, walls: &[&Wall]) {
        let first = walls[0];
        let mut ids: Vec<String> = walls
            .iter()
            .take(MAX_LABELS)
            .map(|w| w.index.to_string())
            .collect();
        if walls.len() > MAX_LABELS {
            ids.push("…".into());
        }
        let which = match walls.len() {
            1 => format!("wall {} leaves", first.index),
            n => format!("{n} walls ({}) leave", ids.join(", ")),
        };
        let span = if from_token {
            self.span_of(first, k).unwrap_or_else(|| first.span.clone())
        } else {
            first.span.clone()
        };
        let mut d = Diagnostic::error(
            &codes::HSDEM_PARTICLE_VALUE,
            span,
            format!("{which} `{}` at 99, which pkdgrav's hard-sphere code uses as the coefficient itself", k.name()),
        )
        .with_help(format!("set `{}` for every wall, for instance once in a `defaults` block at the top", k.name()));
        if !from_token {
            for w in walls[1..].iter().take(MAX_LABELS) {
                d = d.with_label(w.span.clone(), format!("wall {} too", w.index));
            }
        }
        self.push_about(d, Some(k));
    }

    fn file(&mut self, scene: &Scene) {
        // A default is used by a wall that inherits it and whose type reads it.
        let used: HashSet<usize> = scene
            .walls
            .iter()
            .flat_map(|w| {
                let t = w.wall_type();
                w.settings
                    .iter()
                    .filter(move |(k, _)| k.applies_to().contains(t))
            })
            .filter_map(|(_, s)| match &s.source {
                Source::Set {
                    place: Place::Defaults,
                    values,
                    ..
                } => Some(values.range().start),
                _ => None,
            })
            .collect();
        for (k, span) in &scene.defaults {
            let values = self.tree.statement_at(span.start).and_then(|s| {
                self.tree
                    .values(&s)
                    .first()
                    .map(|&v| self.tree.span(v).start)
            });
            if values.is_some_and(|v| used.contains(&v)) {
                continue;
            }
            let mut d = Diagnostic::warning(
                &codes::UNUSED_DEFAULT,
                span.clone(),
                format!("no wall inherits this default `{}`", k.name()),
            )
            .with_help("a default reaches only walls created after it that do not set the token themselves");
            if let Some(stmt) = self.tree.statement_at(span.start) {
                d = d.with_fix(
                    Applicability::Safe,
                    "remove the unused default",
                    vec![self.delete(&stmt)],
                );
            }
            self.push(d);
        }
        if scene.walls.is_empty() {
            self.push(Diagnostic::warning(
                &codes::NO_WALLS,
                0..0,
                "the file defines no wall",
            ));
        }
        let max = self.options.max_walls;
        if let Some(wall) = scene.walls.get(max) {
            self.push(
                Diagnostic::warning(
                    &codes::TOO_MANY_WALLS,
                    wall.span.clone(),
                    format!("{} walls, more than the {max} pkdgrav holds (MAX_NUM_WALLS); this is wall {}", scene.walls.len(), wall.index),
                )
                .with_help("if your pkdgrav was compiled with a larger MAX_NUM_WALLS, pass it as --max-walls"),
            );
        }
    }

    /// An edit removing a statement: its whole line when nothing else is on it, else the
    /// statement and the blank before it. Comments are never removed.
    fn delete(&self, stmt: &Statement) -> Edit {
        let text = self.tree.text();
        let span = self.tree.statement_span(stmt);
        let line_start = text[..span.start].rfind('\n').map_or(0, |i| i + 1);
        let line_end = text[span.end..]
            .find('\n')
            .map_or(text.len(), |i| span.end + i + 1);
        let before = &text[line_start..span.start];
        let after = &text[span.end..line_end];
        let blank = |s: &str| {
            s.chars()
                .all(|c| matches!(c, ' ' | '\t' | ',' | '=' | '\r' | '\n'))
        };
        if blank(before) && blank(after) {
            return Edit {
                span: line_start..line_end,
                replacement: String::new(),
            };
        }
        if blank(before) {
            // A comment follows on the line: keep the indentation and the comment.
            let gap = after.len() - after.trim_start_matches([' ', '\t', ',', '=']).len();
            return Edit {
                span: span.start..span.end + gap,
                replacement: String::new(),
            };
        }
        let start =
            span.start - before.len() + before.trim_end_matches([' ', '\t', ',', '=']).len();
        Edit {
            span: start..span.end,
            replacement: String::new(),
        }
    }
}

/// Tokens a hard-sphere run ignores, token by token (what a wall's type does with them
/// does not matter: the hard-sphere code never reads them).
pub(crate) fn ignored_in_hsdem(tree: &SyntaxTree) -> Vec<Diagnostic> {
    let mut out = Vec::new();
    for &id in tree.significant() {
        if let TokenKind::Keyword(k) = tree.kind(id)
            && k.ssdem_only()
            && k != Keyword::Taper
        {
            out.push(Diagnostic::warning(
                &codes::IGNORED_IN_HSDEM,
                tree.span(id),
                format!(
                    "`{}` is read only by pkdgrav's soft-sphere code; a hard-sphere run ignores it",
                    tree.token_text(id)
                ),
            ));
        }
    }
    out
}
