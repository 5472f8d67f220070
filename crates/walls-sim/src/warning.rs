//! What a run warns about, as data: one [`Warning`] variant per kind, each with a stable
//! code ([`Warning::code`]) and the text pkdgrav users read ([`std::fmt::Display`]).
//!
//! The codes come in families (docs/run-warnings.md says what each means and what to
//! do):
//!
//! * `W1xx`, contacts during a soft-sphere run: overlaps past pkdgrav's levels and the
//!   stop past `dErrorFrac`, crowded wall contacts, a particle too fast for its timestep, a contact
//!   that gained energy;
//! * `W2xx`, checks before a soft-sphere run (the stability checks): the timestep
//!   against the stiffest contact, and walls that move too far in a step;
//! * `W3xx`, the hard-sphere run: walls its code does not support, restitution left at
//!   99, the collision cap;
//! * `W4xx`, reactive walls: assemblies that cannot turn, wall masses a build ignores,
//!   an assembly's rotation integrator at its minimum substep or failing;
//! * `W5xx`, pkdgrav's optional builds: walls-file tokens the run does not follow;
//! * `W6xx`, aggregates: members the run does not follow, what stops an aggregate run,
//!   an aggregate's rotation integrator at its minimum substep or failing;
//! * `W7xx`, the run's inputs: numbers pkdgrav reads, but not as written.

use crate::contact::hsdem::COLLISION_CAP;
use crate::dynamics::euler_rigid::Failure;
use std::fmt;
use walls_keywords::WallType;

/// What overlaps in an overlap warning.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Overlapping {
    /// Two particles, by index.
    Particles(usize, usize),
    /// A particle and a wall.
    Wall {
        /// The particle's index.
        particle: usize,
        /// The wall's index.
        wall: usize,
    },
}

impl Overlapping {
    /// The radius pkdgrav measures the overlap against (docs/pkdgrav-physics.md §15), as
    /// the warnings say it: the smaller of a pair's, the particle's against a wall.
    pub fn radius(&self) -> &'static str {
        match self {
            Overlapping::Particles(..) => "of the smaller radius",
            Overlapping::Wall { .. } => "of the particle's radius",
        }
    }
}

impl fmt::Display for Overlapping {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Overlapping::Particles(i, j) => write!(f, "particles {i} and {j}"),
            Overlapping::Wall { particle, wall } => write!(f, "particle {particle}, wall {wall}"),
        }
    }
}

/// A body that turns as a whole, whose rotation the adaptive integrator steps
/// (docs/pkdgrav-physics.md §9.3, §10, §17).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Rigid {
    /// A reactive assembly of walls, by its `assembly` number.
    Assembly(i64),
    /// An aggregate of particles, by its number (−1 − org_idx).
    Aggregate(u32),
}

impl fmt::Display for Rigid {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Rigid::Assembly(n) => write!(f, "reactive assembly {n}"),
            Rigid::Aggregate(n) => write!(f, "aggregate {n}"),
        }
    }
}

/// The stiffest contact of a run, which the timestep is checked against.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Stiffest {
    /// Against a wall, with its k_n.
    Wall {
        /// The wall's index.
        wall: usize,
        /// Its normal spring constant.
        k_n: f64,
    },
    /// Between particles, with their k_n.
    Pairs {
        /// The particles' normal spring constant.
        k_n: f64,
    },
}

impl fmt::Display for Stiffest {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Stiffest::Wall { wall, k_n } => write!(f, "wall {wall}, k_n = {k_n}"),
            Stiffest::Pairs { k_n } => write!(f, "particle pairs, k_n = {k_n}"),
        }
    }
}

/// One warning of a run.
#[derive(Debug, Clone, PartialEq)]
pub enum Warning {
    /// W101: the first overlap past pkdgrav's minor level, `dMinorFrac` of the radius
    /// (the smaller radius of a pair, the particle's against a wall), and not past the
    /// major one.
    OverlapMinor {
        /// The overlap as a fraction of the radius.
        fraction: f64,
        /// `dMinorFrac`.
        level: f64,
        /// What overlaps.
        what: Overlapping,
        /// When.
        t: f64,
    },
    /// W102: the first overlap past pkdgrav's major level, `dMajorFrac` of the radius,
    /// and not past the error one.
    OverlapMajor {
        /// The overlap as a fraction of the radius.
        fraction: f64,
        /// `dMajorFrac`.
        level: f64,
        /// What overlaps.
        what: Overlapping,
        /// When.
        t: f64,
    },
    /// W103: an overlap past pkdgrav's error level, `dErrorFrac` of the radius: pkdgrav
    /// aborts, and the run stops.
    OverlapStop {
        /// The overlap as a fraction of the radius.
        fraction: f64,
        /// `dErrorFrac`.
        level: f64,
        /// What overlaps.
        what: Overlapping,
        /// When.
        t: f64,
    },
    /// W104: a particle touching more than 3 walls at once (the first time).
    Crowded {
        /// The particle's index.
        particle: usize,
        /// How many walls it touches.
        walls: usize,
        /// When.
        t: f64,
    },
    /// W105: a particle moving more than its radius in a step (the first time).
    TooFast {
        /// The particle's index.
        particle: usize,
        /// Radii moved in the step.
        radii: f64,
        /// When.
        t: f64,
    },
    /// W106: a bounce off a wall that neither oscillates nor spins leaving faster than it came
    /// (the first time).
    EnergyGain {
        /// The particle's index.
        particle: usize,
        /// The wall's index.
        wall: usize,
        /// Normal speed towards the wall when the contact began.
        vn_in: f64,
        /// Normal speed away from it when it ended.
        vn_out: f64,
        /// When.
        t: f64,
    },
    /// W201: the timestep at or above the stability limit 2/ω₀ of the stiffest contact.
    AboveStabilityLimit {
        /// The timestep.
        dt: f64,
        /// The limit 2/ω₀.
        limit: f64,
        /// The stiffest contact.
        stiffest: Stiffest,
    },
    /// W202: fewer than 10 steps per contact for the stiffest contact.
    FewStepsPerContact {
        /// Steps per contact.
        steps: f64,
        /// The worst rebound error to expect, in percent.
        error_percent: f64,
        /// The stiffest contact.
        stiffest: Stiffest,
    },
    /// W203: a wall whose surface moves more than a tenth of the smallest radius in a
    /// step (the first such wall).
    WallTooFast {
        /// The wall's index.
        wall: usize,
        /// How far it can move in a step (or in one jump of its `step`).
        travel: f64,
        /// The smallest particle radius.
        smallest: f64,
    },
    /// W301: a wall pkdgrav's hard-sphere code does not support.
    UnsupportedWall {
        /// The wall's index.
        wall: usize,
        /// Its type.
        wall_type: WallType,
        /// Whether it is a cylinder with a taper.
        taper: bool,
    },
    /// W302: `epsn` or `epst` left at 99 on walls in a hard-sphere run.
    RestitutionAt99 {
        /// The walls' indices.
        walls: Vec<usize>,
    },
    /// W303: a particle reaching [`COLLISION_CAP`] collisions within one step (the first
    /// time).
    CollisionCap {
        /// The particle's index.
        particle: usize,
        /// The time at the start of that step.
        t: f64,
    },
    /// W401: reactive assemblies with a principal moment of inertia not above 0: they
    /// stay where they are.
    ImmovableAssemblies {
        /// The assemblies' numbers.
        assemblies: Vec<i64>,
    },
    /// W403 (a reactive assembly) or W604 (an aggregate): the adaptive integrator of a
    /// rigid body's rotation reached its minimum substep, 0.001·dt, for the first time
    /// in the run: pkdgrav warns and goes on, and so does the run.
    StepFloor {
        /// The body.
        body: Rigid,
        /// The time at the end of the step.
        t: f64,
    },
    /// W404 (a reactive assembly) or W605 (an aggregate): the adaptive integrator of a
    /// rigid body's rotation failed (more than 10,000 substeps, or a substep too small to
    /// move the clock): pkdgrav exits with status 1, and the run stops.
    StepFailed {
        /// The body.
        body: Rigid,
        /// How it failed.
        failure: Failure,
        /// The time at the end of the step.
        t: f64,
    },
    /// W501: walls set cohesion tokens (`cohesion_model`, `cohesive_coeff`) that the run
    /// does not follow (a build without `DEM_COHESION`, or not pkdgrav's integrator).
    CohesionTokensIgnored {
        /// The walls' indices.
        walls: Vec<usize>,
        /// The tokens set.
        tokens: Vec<&'static str>,
        /// Why the run does not follow them.
        reason: String,
    },
    /// W502: walls set two-layer tokens (`inner_overlap_boundary`, `k_n_outer`, …) that
    /// the run does not follow (a build without `DEM_TWOLAYERS`, or not pkdgrav's
    /// integrator).
    TwoLayerTokensIgnored {
        /// The walls' indices.
        walls: Vec<usize>,
        /// The tokens set.
        tokens: Vec<&'static str>,
        /// Why the run does not follow them.
        reason: String,
    },
    /// W107: particles whose `.ss` colour is negative, which pkdgrav reads as stuck to
    /// wall −1 − colour, where the scene has no such wall: they run free.
    StuckToNoWall {
        /// The particles' indices.
        particles: Vec<usize>,
        /// How many walls the scene has.
        walls: usize,
    },
    /// W108: the timestep given does not divide the end time: the run takes whole
    /// steps, and its last ends after `--t-end`.
    EndsAfterTEnd {
        /// The number of the last step.
        step: u64,
        /// Its time, `step`·dt.
        t: f64,
        /// The end time asked for.
        t_end: f64,
    },
    /// W402: walls with a mass (and an assembly) in a soft-sphere run whose pkdgrav build
    /// lacks `DEM_WALLS_REACT`: pkdgrav then reads the masses and ignores them, and so
    /// does the run; the walls move as their motion tokens say.
    MassesIgnored {
        /// The walls' indices.
        walls: Vec<usize>,
    },
    /// W601: particles with a negative `org_idx` (members of aggregates) in a run that
    /// does not follow aggregates (a build without `AGGS`, or not pkdgrav's integrator):
    /// they run as free spheres, as pkdgrav without `AGGS` runs them.
    AggregatesIgnored {
        /// How many particles are members.
        members: usize,
        /// How many aggregates they make.
        aggregates: usize,
        /// Why the run does not follow them.
        reason: &'static str,
    },
    /// W602: an aggregate with a single member: pkdgrav aborts (`msrAggsFind`), and the
    /// run stops before its first step.
    SingleMemberAggregate {
        /// The aggregate's number (−1 − org_idx).
        aggregate: u32,
        /// The member's index in the input.
        particle: usize,
    },
    /// W606: a death wall deleted a member of an aggregate: pkdgrav deletes the member
    /// alone and warns that mass is not conserved; the aggregate keeps its mass and shape
    /// (docs/pkdgrav-physics.md §17).
    MemberDeleted {
        /// The member's index in the input.
        particle: usize,
        /// The aggregate's number (−1 − org_idx).
        aggregate: u32,
        /// The death wall.
        wall: usize,
        /// When.
        t: f64,
    },
    /// W607: death walls deleted every member of an aggregate: pkdgrav fails an
    /// assertion, and the run stops.
    AggregateDeleted {
        /// The aggregate's number (−1 − org_idx).
        aggregate: u32,
        /// When.
        t: f64,
    },
    /// W603: a member of an aggregate reached a sticky wall: pkdgrav asserts that
    /// aggregates cannot stick, and the run stops.
    AggregateHeld {
        /// The member's index in the input.
        particle: usize,
        /// The wall.
        wall: usize,
        /// When.
        t: f64,
    },
    /// W701: a number of the run's inputs (an option, a `.par` value, a particle or
    /// cohesion file) below the smallest normal double: read as it is, with fewer
    /// significant digits, as pkdgrav reads it ([`walls_keywords::number`]).
    SubnormalInput {
        /// Where: the option, or the file with its line (or byte) and field.
        at: String,
        /// The value read.
        value: f64,
    },
}

impl Warning {
    /// The warning's stable code.
    pub fn code(&self) -> &'static str {
        match self {
            Warning::OverlapMinor { .. } => "W101",
            Warning::OverlapMajor { .. } => "W102",
            Warning::OverlapStop { .. } => "W103",
            Warning::Crowded { .. } => "W104",
            Warning::TooFast { .. } => "W105",
            Warning::EnergyGain { .. } => "W106",
            Warning::AboveStabilityLimit { .. } => "W201",
            Warning::FewStepsPerContact { .. } => "W202",
            Warning::WallTooFast { .. } => "W203",
            Warning::UnsupportedWall { .. } => "W301",
            Warning::RestitutionAt99 { .. } => "W302",
            Warning::CollisionCap { .. } => "W303",
            Warning::ImmovableAssemblies { .. } => "W401",
            Warning::StepFloor {
                body: Rigid::Assembly(_),
                ..
            } => "W403",
            Warning::StepFailed {
                body: Rigid::Assembly(_),
                ..
            } => "W404",
            Warning::StepFloor {
                body: Rigid::Aggregate(_),
                ..
            } => "W604",
            Warning::StepFailed {
                body: Rigid::Aggregate(_),
                ..
            } => "W605",
            Warning::CohesionTokensIgnored { .. } => "W501",
            Warning::TwoLayerTokensIgnored { .. } => "W502",
            Warning::MassesIgnored { .. } => "W402",
            Warning::StuckToNoWall { .. } => "W107",
            Warning::EndsAfterTEnd { .. } => "W108",
            Warning::AggregatesIgnored { .. } => "W601",
            Warning::SingleMemberAggregate { .. } => "W602",
            Warning::AggregateHeld { .. } => "W603",
            Warning::MemberDeleted { .. } => "W606",
            Warning::AggregateDeleted { .. } => "W607",
            Warning::SubnormalInput { .. } => "W701",
        }
    }
}

impl fmt::Display for Warning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Warning::OverlapMinor {
                fraction,
                level,
                what,
                t,
            } => write!(
                f,
                "overlap of {:.1}% {} ({what}, t = {t}): above dMinorFrac = {level} {}; pkdgrav prints such an overlap only when its count of them (pairs and walls apart, every level) is 1 or a multiple of 1,000,000: the run warns of the first and counts them all",
                fraction * 100.0,
                what.radius(),
                what.radius(),
            ),
            Warning::OverlapMajor {
                fraction,
                level,
                what,
                t,
            } => write!(
                f,
                "overlap of {:.1}% {} ({what}, t = {t}): above dMajorFrac = {level} {}; pkdgrav prints every such overlap: the run warns of the first and counts them all",
                fraction * 100.0,
                what.radius(),
                what.radius(),
            ),
            Warning::OverlapStop {
                fraction,
                level,
                what,
                t,
            } => write!(
                f,
                "overlap of {:.1}% {} ({what}, t = {t}): above dErrorFrac = {level} {}, where pkdgrav prints it and aborts; the run stops",
                fraction * 100.0,
                what.radius(),
                what.radius(),
            ),
            Warning::Crowded { particle, walls, t } => write!(
                f,
                "particle {particle} touches {walls} walls at once (t = {t}); pkdgrav handles at most 3"
            ),
            Warning::TooFast { particle, radii, t } => write!(
                f,
                "particle {particle} moves {radii:.1} radii in a step (t = {t}): it can pass through a thin wall without touching it; take a smaller timestep"
            ),
            Warning::EnergyGain {
                particle,
                wall,
                vn_in,
                vn_out,
                t,
            } => write!(
                f,
                "particle {particle} left wall {wall} faster than it came ({vn_in} → {vn_out}, t = {t}): the contact gained energy; the timestep is too large for the springs"
            ),
            Warning::AboveStabilityLimit {
                dt,
                limit,
                stiffest,
            } => write!(
                f,
                "the timestep {dt} is above the stability limit 2/ω₀ = {limit:.3e} of the stiffest contact ({stiffest}): contacts will gain energy; pkdgrav's dDelta = π·√(m/2k_n)/N with N ≥ 10"
            ),
            Warning::FewStepsPerContact {
                steps,
                error_percent,
                stiffest,
            } => write!(
                f,
                "only {steps:.1} steps per contact for the stiffest contact ({stiffest}): rebound speeds may be off by up to {error_percent:.0}%; take N ≥ 10 (100 for 1%)"
            ),
            Warning::WallTooFast {
                wall,
                travel,
                smallest,
            } => write!(
                f,
                "wall {wall} moves up to {travel:.3e} in a step ({:.0}% of the smallest radius {smallest}): particles can be struck deep or passed through; take a smaller timestep (or step)",
                100.0 * travel / smallest
            ),
            Warning::UnsupportedWall {
                wall,
                wall_type,
                taper,
            } => write!(
                f,
                "wall {wall} ({}{}) is not supported by pkdgrav's hard-sphere code; particles pass through it",
                wall_type.name(),
                if *taper { " with taper" } else { "" }
            ),
            Warning::RestitutionAt99 { walls } => {
                f.write_str("epsn or epst left at 99 on walls ")?;
                for (k, w) in walls.iter().enumerate() {
                    if k > 0 {
                        f.write_str(", ")?;
                    }
                    write!(f, "{w}")?;
                }
                f.write_str(": pkdgrav's hard-sphere code would use 99 as the coefficient; this run uses the particles' values")
            }
            Warning::CollisionCap { particle, t } => write!(
                f,
                "particle {particle} had {COLLISION_CAP} collisions within one step (t = {t}): inelastic collapse, or jammed between walls; it was held where it was for the rest of that step"
            ),
            Warning::ImmovableAssemblies { assemblies } => write!(
                f,
                "assemblies {assemblies:?} have a principal moment of inertia that is not above 0 (ixj-vec, iyj-vec, izj-vec): they stay where they are"
            ),
            Warning::StepFloor { body, t } => write!(
                f,
                "the adaptive (Cash–Karp) integrator of {body}'s rotation reached its minimum substep, 0.001·dt (t = {t}): there it takes substeps whatever their error, above its accuracy of 1e-6; pkdgrav warns and goes on, and so does the run (warned of once); a smaller timestep keeps the rotation accurate"
            ),
            Warning::StepFailed { body, failure, t } => write!(
                f,
                "the adaptive (Cash–Karp) integrator of {body}'s rotation failed in the step ending at t = {t}: {failure}; pkdgrav exits with status 1; the run stops"
            ),
            Warning::CohesionTokensIgnored {
                walls,
                tokens,
                reason,
            } => write!(
                f,
                "walls {walls:?} set {}: {reason}, so the run has no cohesion and ignores them",
                tokens.join(", ")
            ),
            Warning::TwoLayerTokensIgnored {
                walls,
                tokens,
                reason,
            } => write!(
                f,
                "walls {walls:?} set {}: {reason}, so the run's contacts have one layer and ignore them",
                tokens.join(", ")
            ),
            Warning::StuckToNoWall { particles, walls } => write!(
                f,
                "particles {particles:?} have a negative colour, which pkdgrav reads as stuck to wall -1 - colour, but the scene has {walls} walls: they run free"
            ),
            Warning::EndsAfterTEnd { step, t, t_end } => write!(
                f,
                "the end time {t_end} is not a whole number of timesteps: the run ends at step {step}, t = {t}, not at --t-end (give a timestep that divides it, or leave --dt out)"
            ),
            Warning::MassesIgnored { walls } => write!(
                f,
                "walls {walls:?} have a mass, but the pkdgrav build lacks DEM_WALLS_REACT: pkdgrav without it ignores wall masses, and so does this run (the walls move as their motion tokens say); add DEM_WALLS_REACT to --pkdgrav-build for reactive walls"
            ),
            Warning::AggregatesIgnored {
                members,
                aggregates,
                reason,
            } => write!(
                f,
                "{members} particles are members of {aggregates} aggregates (negative org_idx), which need a build with AGGS and pkdgrav's integrator; {reason}: they run as free spheres, as pkdgrav without AGGS runs them"
            ),
            Warning::SingleMemberAggregate {
                aggregate,
                particle,
            } => write!(
                f,
                "aggregate {aggregate} (org_idx {}) has a single member, particle {particle}: pkdgrav aborts; the run stops before its first step",
                -1 - *aggregate as i64
            ),
            Warning::AggregateHeld { particle, wall, t } => write!(
                f,
                "particle {particle}, a member of an aggregate, reached sticky wall {wall} (t = {t}): pkdgrav asserts that aggregates cannot stick; the run stops"
            ),
            Warning::MemberDeleted {
                particle,
                aggregate,
                wall,
                t,
            } => write!(
                f,
                "death wall {wall} deleted particle {particle}, a member of aggregate {aggregate} (t = {t}): pkdgrav deletes the member alone and warns that mass is not conserved; the aggregate keeps its mass and shape, moved by the members left"
            ),
            Warning::AggregateDeleted { aggregate, t } => write!(
                f,
                "death walls deleted every member of aggregate {aggregate} (t = {t}): pkdgrav fails an assertion; the run stops"
            ),
            Warning::SubnormalInput { at, value } => write!(
                f,
                "{at}: `{value:e}` is {}",
                walls_keywords::number::Subnormal(*value)
            ),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// One warning of each kind.
    fn one_of_each() -> Vec<Warning> {
        let what = Overlapping::Wall {
            particle: 0,
            wall: 1,
        };
        let stiffest = Stiffest::Pairs { k_n: 1e5 };
        vec![
            Warning::OverlapMinor {
                fraction: 0.04,
                level: 0.03,
                what,
                t: 0.1,
            },
            Warning::OverlapMajor {
                fraction: 0.2,
                level: 0.15,
                what,
                t: 0.1,
            },
            Warning::OverlapStop {
                fraction: 0.6,
                level: 0.5,
                what,
                t: 0.1,
            },
            Warning::Crowded {
                particle: 0,
                walls: 4,
                t: 0.1,
            },
            Warning::TooFast {
                particle: 0,
                radii: 1.5,
                t: 0.1,
            },
            Warning::EnergyGain {
                particle: 0,
                wall: 1,
                vn_in: 1.0,
                vn_out: 2.0,
                t: 0.1,
            },
            Warning::AboveStabilityLimit {
                dt: 0.1,
                limit: 0.01,
                stiffest,
            },
            Warning::FewStepsPerContact {
                steps: 5.0,
                error_percent: 24.0,
                stiffest,
            },
            Warning::WallTooFast {
                wall: 0,
                travel: 0.05,
                smallest: 0.1,
            },
            Warning::UnsupportedWall {
                wall: 0,
                wall_type: WallType::Triangle,
                taper: false,
            },
            Warning::RestitutionAt99 { walls: vec![0] },
            Warning::CollisionCap {
                particle: 0,
                t: 0.0,
            },
            Warning::ImmovableAssemblies {
                assemblies: vec![1],
            },
            Warning::StepFloor {
                body: Rigid::Assembly(0),
                t: 0.5,
            },
            Warning::StepFailed {
                body: Rigid::Assembly(0),
                failure: Failure::TooManySteps,
                t: 0.5,
            },
            Warning::StepFloor {
                body: Rigid::Aggregate(2),
                t: 0.5,
            },
            Warning::StepFailed {
                body: Rigid::Aggregate(2),
                failure: Failure::Underflow,
                t: 0.5,
            },
            Warning::CohesionTokensIgnored {
                walls: vec![1],
                tokens: vec!["cohesive_coeff"],
                reason: "the build lacks DEM_COHESION".into(),
            },
            Warning::TwoLayerTokensIgnored {
                walls: vec![0],
                tokens: vec!["k_n_outer"],
                reason: "the build lacks DEM_TWOLAYERS".into(),
            },
            Warning::MassesIgnored { walls: vec![0, 2] },
            Warning::EndsAfterTEnd {
                step: 4,
                t: 1.2,
                t_end: 1.0,
            },
            Warning::StuckToNoWall {
                particles: vec![3],
                walls: 2,
            },
            Warning::AggregatesIgnored {
                members: 2,
                aggregates: 1,
                reason: "the build has no AGGS",
            },
            Warning::SingleMemberAggregate {
                aggregate: 0,
                particle: 3,
            },
            Warning::AggregateHeld {
                particle: 0,
                wall: 1,
                t: 0.5,
            },
            Warning::MemberDeleted {
                particle: 0,
                aggregate: 0,
                wall: 1,
                t: 0.5,
            },
            Warning::AggregateDeleted {
                aggregate: 0,
                t: 0.5,
            },
            Warning::SubnormalInput {
                at: "--gravity".into(),
                value: 1e-310,
            },
        ]
    }

    #[test]
    fn codes_are_unique_and_documented() {
        let doc = include_str!("../../../docs/run-warnings.md");
        let mut seen = std::collections::HashSet::new();
        for w in one_of_each() {
            let code = w.code();
            assert!(seen.insert(code), "{code} twice");
            assert!(
                doc.contains(&format!("| {code} |")),
                "{code} is not in docs/run-warnings.md"
            );
        }
        let listed = doc.lines().filter(|l| l.starts_with("| W")).count();
        assert_eq!(listed, seen.len(), "docs/run-warnings.md lists other codes");
    }

    #[test]
    fn overlap_warnings_name_the_level_and_its_key() {
        let w = Warning::OverlapMajor {
            fraction: 0.2,
            level: 0.15,
            what: Overlapping::Particles(1, 2),
            t: 0.5,
        };
        assert_eq!(
            w.to_string(),
            "overlap of 20.0% of the smaller radius (particles 1 and 2, t = 0.5): above dMajorFrac = 0.15 of the smaller radius; pkdgrav prints every such overlap: the run warns of the first and counts them all"
        );
        assert_eq!(w.code(), "W102");
        let w = Warning::OverlapMinor {
            fraction: 0.04,
            level: 0.03,
            what: Overlapping::Wall {
                particle: 0,
                wall: 3,
            },
            t: 1.0,
        };
        assert!(w.to_string().starts_with(
            "overlap of 4.0% of the particle's radius (particle 0, wall 3, t = 1): above dMinorFrac = 0.03 of the particle's radius; pkdgrav prints such an overlap only when its count of them (pairs and walls apart, every level) is 1 or a multiple of 1,000,000"
        ));
        let w = Warning::OverlapStop {
            fraction: 0.3,
            level: 0.25,
            what: Overlapping::Particles(0, 1),
            t: 0.0,
        };
        assert!(w.to_string().contains("above dErrorFrac = 0.25 of the smaller radius, where pkdgrav prints it and aborts; the run stops"));
    }

    #[test]
    fn lists_print_as_before() {
        let w = Warning::RestitutionAt99 {
            walls: vec![0, 1, 7],
        };
        assert!(
            w.to_string()
                .starts_with("epsn or epst left at 99 on walls 0, 1, 7: ")
        );
        let a = Warning::ImmovableAssemblies {
            assemblies: vec![0, 3],
        };
        assert!(a.to_string().starts_with("assemblies [0, 3] have"));
    }
}
