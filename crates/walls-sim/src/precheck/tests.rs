//! Each rule on the run directory its code's explanation describes: the bad example's
//! `.par` (with its walls and particles) gives the code, at the place and severity
//! stated, the good one nothing.

use super::rules::{self, ALL};
use super::{Findings, Run, SsFile, WallPlace, WallsFile, check};
use nalgebra::Vector3;
use walls_diagnostics::{Code, Diagnostic, Severity};
use walls_geometry::Particle;
use walls_par::Build;

/// The ```par block after the line starting with `label` in `code`'s explanation.
fn example(code: &Code, label: &str) -> String {
    let e = code.explanation;
    let at = e.find(&format!("\n{label}")).expect("the example") + 1;
    let rest = &e[at..];
    let body = &rest[rest.find("```par\n").expect("a par block") + 7..];
    body[..body.find("```").expect("its end")].to_string()
}

/// A particle of radius `r` at (x, y, z), at rest.
fn at(r: f64, x: f64, y: f64, z: f64, k: usize) -> Particle {
    Particle::at_rest(r, Vector3::new(x, y, z), k)
}

/// The findings of the run directory of `par`, `walls` and `particles` (at time 0), for
/// `build`.
fn findings(par: &str, walls: &str, particles: &[Particle], build: &Build) -> Findings {
    findings_at(par, walls, particles, build, 0.0)
}

/// [`findings`] with the `.ss` header's `time`.
fn findings_at(
    par: &str,
    walls: &str,
    particles: &[Particle],
    build: &Build,
    time: f64,
) -> Findings {
    let file = walls_par::check::File::read(par, build, &mut Vec::new());
    let parse = walls_syntax::parse(walls);
    let (scene, _) = walls_model::resolve(&parse.tree, walls_model::ContactModel::Ssdem);
    let decoded = walls_geometry::decode(&scene);
    let places: Vec<WallPlace> = (scene.walls.iter())
        .map(|w| WallPlace {
            wall: w.span.clone(),
            tokens: walls_geometry::token_spans(w),
        })
        .collect();
    let run = Run {
        par: &file,
        walls: Some(WallsFile {
            name: "walls.dat",
            text: walls,
            walls: &decoded,
            places: &places,
        }),
        particles: Some(SsFile {
            name: "ss.ic",
            particles,
            time,
        }),
    };
    check(&run)
}

/// Every finding, each with the file it is in (`par`, `walls`, `ss`).
fn all(f: &Findings) -> Vec<(&'static str, &Diagnostic)> {
    let each = |name, list: &'static [Diagnostic]| list.iter().map(move |d| (name, d));
    // (The lists live as long as `f`; the names are static.)
    let f: &'static Findings = Box::leak(Box::new(Findings {
        par: f.par.clone(),
        walls: f.walls.clone(),
        particles: f.particles.clone(),
    }));
    each("par", &f.par)
        .chain(each("walls", &f.walls))
        .chain(each("ss", &f.particles))
        .collect()
}

/// The one finding of `f`, which must be of `code`: (file, span, severity, message).
fn one(f: &Findings, code: &Code) -> (&'static str, std::ops::Range<usize>, Severity, String) {
    let found = all(f);
    assert_eq!(found.len(), 1, "{found:#?}");
    let (file, d) = found[0];
    assert_eq!(d.code.id, code.id, "{d:#?}");
    (file, d.span.clone(), d.severity, d.message.clone())
}

const PLANE: &str = "wall\n  type plane\n  origin 0 0 0\n  orient 0 0 1\n";
const NONE: &str = "";

/// The span of particle `k`'s standard record.
fn record(k: usize) -> std::ops::Range<usize> {
    16 + 96 * k..16 + 96 * (k + 1)
}

fn span_of(text: &str, what: &str) -> std::ops::Range<usize> {
    let at = text.find(what).expect("in the text");
    at..at + what.len()
}

#[test]
fn every_code_is_listed_once_in_order() {
    let ids: Vec<_> = ALL.iter().map(|c| c.id).collect();
    assert_eq!(
        ids,
        [
            "R001", "R002", "R003", "R004", "R005", "R006", "R007", "R008", "R009"
        ]
    );
}

#[test]
fn pairs_at_each_level_strictly_above_it() {
    let code = &rules::pair_overlap::PAIR_OVERLAP;
    let par = example(code, "Bad");
    let build = Build::default();
    // Centres 0.9 apart: x = 1.1, 110 % of the radius: pkdgrav aborts.
    let bad = [at(1.0, 0.0, 0.0, 0.0, 0), at(1.0, 0.9, 0.0, 0.0, 1)];
    let f = findings(&par, NONE, &bad, &build);
    let (file, span, severity, message) = one(&f, code);
    assert_eq!((file, span, severity), ("ss", record(0), Severity::Error));
    assert_eq!(
        message,
        "particles 0 and 1 overlap by 110 % of the smaller radius at the start, above dErrorFrac = 0.5: pkdgrav aborts at step 0 (an assertion, nothing written)"
    );
    assert_eq!(
        f.particles[0].record.map(|r| r.to_string()),
        Some("particle 0".into())
    );
    assert_eq!(f.particles[0].labels[0].span, record(1));
    assert_eq!(f.particles[0].labels[0].message, "particle 1");
    // Exactly at the error level (x = 0.5 r): a warning, the comparison is strict.
    for (d, expected) in [
        (1.5, Some(Severity::Warning)),
        (1.8, Some(Severity::Warning)),
        (1.9, Some(Severity::Info)),
        (1.98, None),
        (2.0, None),
    ] {
        let ps = [at(1.0, 0.0, 0.0, 0.0, 0), at(1.0, d, 0.0, 0.0, 1)];
        let f = findings(&par, NONE, &ps, &build);
        assert_eq!(f.particles.first().map(|d| d.severity), expected, "d = {d}");
    }
    // The smaller radius counts: radii 1 and 0.1, x = 0.06 is 60 % of 0.1.
    let ps = [at(1.0, 0.0, 0.0, 0.0, 0), at(0.1, 1.04, 0.0, 0.0, 1)];
    assert_eq!(
        findings(&par, NONE, &ps, &build).particles[0].severity,
        Severity::Error
    );
    // The `.par`'s levels: dErrorFrac raised above the overlap.
    let raised = format!("{par}dErrorFrac           = 2\n");
    assert_eq!(
        findings(&raised, NONE, &bad, &build).particles[0].severity,
        Severity::Warning
    );
    // The good example's particles.
    let good = [at(1.0, 0.0, 0.0, 0.0, 0), at(1.0, 2.0, 0.0, 0.0, 1)];
    assert!(all(&findings(&example(code, "Good"), NONE, &good, &build)).is_empty());
}

#[test]
fn members_of_one_aggregate_and_stuck_pairs_are_skipped() {
    let code = &rules::pair_overlap::PAIR_OVERLAP;
    let par = example(code, "Bad");
    let member = |x: f64, aggregate: i32| Particle {
        index: -1 - aggregate,
        ..at(1.0, x, 0.0, 0.0, 0)
    };
    let aggs = Build::parse("AGGS DEM DEM_FIXED_BALL DEM_ROTATION_DASHPOT").unwrap();
    let same = [member(0.0, 0), member(0.9, 0)];
    assert!(findings(&par, NONE, &same, &aggs).particles.is_empty());
    // Without AGGS they are free spheres, and two aggregates meet.
    assert_eq!(
        findings(&par, NONE, &same, &Build::default())
            .particles
            .len(),
        1
    );
    // (Two aggregates of one member each are also R009 errors, A127.)
    let two = [member(0.0, 0), member(0.9, 1)];
    let pairs = findings(&par, NONE, &two, &aggs).particles;
    assert_eq!(pairs.iter().filter(|d| d.code.id == "R001").count(), 1);
    let stuck = |x: f64| Particle {
        color: -1,
        ..at(1.0, x, 0.0, 0.0, 0)
    };
    assert!(
        findings(&par, NONE, &[stuck(0.0), stuck(0.9)], &Build::default())
            .particles
            .is_empty()
    );
}

#[test]
fn d_soft_replaces_every_radius() {
    let code = &rules::pair_overlap::PAIR_OVERLAP;
    let par = format!("{}dSoft                = 0.5\n", example(code, "Bad"));
    // Radii 1 read, 0.5 used: centres 0.9 apart overlap by 0.1, 20 % of 0.5.
    let ps = [at(1.0, 0.0, 0.0, 0.0, 0), at(1.0, 0.9, 0.0, 0.0, 1)];
    let f = findings(&par, NONE, &ps, &Build::default());
    assert_eq!(f.particles[0].severity, Severity::Warning);
}

#[test]
fn hard_sphere_builds_have_no_overlap_levels() {
    let code = &rules::pair_overlap::PAIR_OVERLAP;
    let hs = Build::parse("").unwrap();
    let ps = [at(1.0, 0.0, 0.0, 0.0, 0), at(1.0, 0.9, 0.0, 0.0, 1)];
    let par = "achInFile = ss.ic\nachWallsFile = walls.dat\nnSteps = 10\n";
    let f = findings(par, PLANE, &ps, &hs);
    assert!(
        all(&f)
            .iter()
            .all(|(_, d)| d.code.id != code.id && d.code.id != "R002")
    );
}

#[test]
fn walls_in_order_death_and_sticky_walls_first() {
    let code = &rules::wall_overlap::WALL_OVERLAP;
    let par = example(code, "Bad");
    let build = Build::default();
    let bad = [at(1.0, 0.0, 0.0, 0.4, 0)];
    let (file, span, severity, message) = one(&findings(&par, PLANE, &bad, &build), code);
    assert_eq!((file, span, severity), ("ss", record(0), Severity::Error));
    assert_eq!(
        message,
        "particle 0 overlaps wall 0 (walls.dat line 1) by 60 % of its radius at the start, above dErrorFrac = 0.5: pkdgrav aborts at step 0 (an assertion, nothing written)"
    );
    let good = [at(1.0, 0.0, 0.0, 1.0, 0)];
    assert!(all(&findings(&example(code, "Good"), PLANE, &good, &build)).is_empty());
    // A death wall first deletes it; a sticky one holds it at its own overlap.
    let death = format!("{PLANE}  epsn -1\n{PLANE}");
    assert!(findings(&par, &death, &bad, &build).particles.is_empty());
    let later = format!("wall\n  type plane\n  origin 0 0 -5\n  orient 0 0 1\n  epsn 0\n{PLANE}");
    let f = findings(&par, &later, &bad, &build);
    assert_eq!(
        f.particles[0].message.split(" by ").next(),
        Some("particle 0 overlaps wall 1 (walls.dat line 6)")
    );
    let sticky_first =
        format!("{PLANE}  epsn 0\nwall\n  type plane\n  origin 0 0 0.9\n  orient 0 0 1\n");
    // Sticky wall 0 at 60 %, and wall 1 (at 50 %) never reached.
    let f = findings(&par, &sticky_first, &bad, &build);
    assert_eq!(f.particles.len(), 1);
    assert!(f.particles[0].message.contains("wall 0 "));
}

#[test]
fn a_particle_outside_the_cylinder_that_holds_the_others() {
    let code = &rules::outside_container::OUTSIDE_CONTAINER;
    let par = example(code, "Bad");
    let build = Build::default();
    let tube = "wall\n  type cylinder-infinite\n  origin 0 0 0\n  orient 0 0 1\n  radius 10\n";
    let mut ps: Vec<Particle> = (0..9)
        .map(|k| at(1.0, 0.0, 0.0, 3.0 * k as f64, k))
        .collect();
    ps.push(at(1.0, 20.0, 0.0, 0.0, 9));
    let (file, span, severity, message) = one(&findings(&par, tube, &ps, &build), code);
    assert_eq!((file, span, severity), ("ss", record(9), Severity::Warning));
    assert_eq!(
        message,
        "particle 9 lies outside wall 0 (walls.dat line 1), which holds 9 of the 10 particles: it never meets them"
    );
    ps[9] = at(1.0, 5.0, 0.0, 0.0, 9);
    assert!(all(&findings(&example(code, "Good"), tube, &ps, &build)).is_empty());
    // Two outside of ten: no container holds nine in ten, no finding.
    ps[8] = at(1.0, -20.0, 0.0, 0.0, 8);
    ps[9] = at(1.0, 20.0, 0.0, 0.0, 9);
    assert!(findings(&par, tube, &ps, &build).particles.is_empty());
    // An open shell closes nothing.
    let bowl =
        "wall\n  type shell\n  origin 0 0 0\n  orient 0 0 1\n  radius 100\n  open-angle 90\n";
    let mut ps: Vec<Particle> = (0..9)
        .map(|k| at(1.0, 0.0, 0.0, 3.0 * k as f64, k))
        .collect();
    ps.push(at(1.0, 200.0, 0.0, 0.0, 9));
    assert!(findings(&par, bowl, &ps, &build).particles.is_empty());
}

#[test]
fn few_steps_per_contact_at_d_delta() {
    let code = &rules::few_steps::FEW_STEPS;
    let par = example(code, "Bad");
    let build = Build::default();
    let heavy = |x: f64, k: usize| Particle {
        mass: 1.0,
        ..at(1.0, x, 0.0, 0.0, k)
    };
    let ps = [heavy(0.0, 0), heavy(10.0, 1)];
    let (file, span, severity, message) = one(&findings(&par, NONE, &ps, &build), code);
    let value = par.find("1e-3").unwrap();
    assert_eq!(
        (file, span, severity),
        ("par", value..value + 4, Severity::Warning)
    );
    assert!(message.starts_with("dDelta = 1e-3 gives 7.02 steps per contact for the stiffest contact, two bodies as light as particle 0 (m = 1e0) with dKn = 1e5; fewer than 10"), "{message}");
    assert!(all(&findings(&example(code, "Good"), NONE, &ps, &build)).is_empty());
    // With AGGS, an aggregate of two members moves its whole mass: √2 more steps, and
    // no pair of members meets.
    let aggs = Build::parse("AGGS DEM DEM_FIXED_BALL DEM_ROTATION_DASHPOT").unwrap();
    let members = [
        Particle {
            index: -1,
            ..heavy(0.0, 0)
        },
        Particle {
            index: -1,
            ..heavy(1.5, 1)
        },
    ];
    let walls = format!("{PLANE}  k_n 1e5\n");
    let f = findings(&par, &walls, &members, &aggs);
    // 14 steps a contact against the wall (a particle alone would have 9.9).
    assert!(f.par.is_empty(), "{:?}", f.par);
    let few = par.replace("1e-3", "3e-3");
    let f = findings(&few, &walls, &members, &aggs);
    assert!(
        f.par[0].message.starts_with("dDelta = 3e-3 gives 4.68 steps per contact for the stiffest contact, aggregate 0 (particle 0's, m = 2e0) against wall 0"),
        "{}",
        f.par[0].message
    );
}

#[test]
fn a_wall_too_fast_for_the_smallest_particle() {
    let code = &rules::wall_too_fast::WALL_TOO_FAST;
    let par = example(code, "Bad");
    let build = Build::default();
    let walls = format!("{PLANE}  velocity 0 0 1000\n");
    let ps = [at(1.0, 0.0, 0.0, 5.0, 0)];
    let (file, span, severity, message) = one(&findings(&par, &walls, &ps, &build), code);
    assert_eq!((file, span, severity), ("walls", 0..4, Severity::Warning));
    assert!(
        message.starts_with("wall 0 (walls.dat line 1) moves up to 1e0 in one step"),
        "{message}"
    );
    assert!(all(&findings(&example(code, "Good"), &walls, &ps, &build)).is_empty());
}

#[test]
fn tokens_the_build_lacks_at_the_token() {
    let code = &rules::build_lacks::BUILD_LACKS;
    let par = example(code, "Bad");
    let walls = format!("{PLANE}  cohesive_coeff 1e-3\n");
    let ps = [at(1.0, 0.0, 0.0, 5.0, 0)];
    let (file, span, severity, message) =
        one(&findings(&par, &walls, &ps, &Build::default()), code);
    assert_eq!(
        (file, span, severity),
        ("walls", span_of(&walls, "1e-3"), Severity::Warning)
    );
    assert!(message.starts_with("`cohesive_coeff` of wall 0 (walls.dat line 1) needs DEM_COHESION (cohesion), which the build ("), "{message}");
    let cohesion = Build::parse("DEM DEM_FIXED_BALL DEM_ROTATION_DASHPOT DEM_COHESION").unwrap();
    assert!(all(&findings(&example(code, "Good"), &walls, &ps, &cohesion)).is_empty());
}

#[test]
fn no_step_and_only_the_last_step() {
    let code = &rules::no_output::NO_OUTPUT;
    let par = example(code, "Bad");
    let ps = [at(1.0, 0.0, 0.0, 5.0, 0)];
    // The `.ss` written at iStartStep·dDelta, as pkdgrav wants it (else R009).
    let t0 = 1000.0 * 1e-7;
    let (file, span, severity, message) =
        one(&findings_at(&par, NONE, &ps, &Build::default(), t0), code);
    let value = par.find("1000\niStartStep").unwrap();
    assert_eq!(
        (file, span, severity),
        ("par", value..value + 4, Severity::Warning)
    );
    assert_eq!(
        message,
        "nSteps = 1000 is not above iStartStep = 1000: pkdgrav runs no step and writes no output (it exits with status 0)"
    );
    assert!(
        all(&findings_at(
            &example(code, "Good"),
            NONE,
            &ps,
            &Build::default(),
            t0
        ))
        .is_empty()
    );
    // iOutInterval 0: the last step alone, an info at its value.
    let zero = par
        .replace("iOutInterval         = 100", "iOutInterval         = 0")
        .replace("iStartStep           = 1000\n", "");
    let (_, span, severity, _) = one(&findings(&zero, NONE, &ps, &Build::default()), code);
    let value = zero.find("= 0\n").unwrap() + 2;
    assert_eq!((span, severity), (value..value + 1, Severity::Info));
}

#[test]
fn step_numbers_wider_than_n_digits() {
    let code = &rules::wide_steps::WIDE_STEPS;
    let par = example(code, "Bad");
    let ps = [at(1.0, 0.0, 0.0, 5.0, 0)];
    let (file, span, severity, message) = one(&findings(&par, NONE, &ps, &Build::default()), code);
    assert_eq!(
        (file, span, severity),
        ("par", span_of(&par, "200000"), Severity::Warning)
    );
    assert_eq!(
        message,
        "nSteps = 200000 has 6 digits, more than nDigits = 5 (the default): the last outputs' names are wider than the first ones' and sort before them"
    );
    assert!(
        all(&findings(
            &example(code, "Good"),
            NONE,
            &ps,
            &Build::default()
        ))
        .is_empty()
    );
}

#[test]
fn many_findings_are_capped_with_a_count() {
    let code = &rules::pair_overlap::PAIR_OVERLAP;
    let par = example(code, "Bad");
    // 150 pairs far apart from each other, each overlapping.
    let ps: Vec<Particle> = (0..300)
        .map(|k| {
            at(
                1.0,
                10.0 * (k / 2) as f64 + 0.9 * (k % 2) as f64,
                0.0,
                0.0,
                k,
            )
        })
        .collect();
    let f = findings(&par, NONE, &ps, &Build::default());
    assert_eq!(f.particles.len(), super::MAX_REPORTED + 1);
    let last = f
        .particles
        .iter()
        .find(|d| d.severity == Severity::Info)
        .unwrap();
    assert_eq!(
        last.message,
        "50 more overlapping pairs (the first 100 are reported)"
    );
    assert_eq!(last.span, record(200));
    assert_eq!(last.record.map(|r| r.index), Some(200));
}

#[test]
fn a_huge_particle_is_measured_to_each_other_not_binned_with_them() {
    let code = &rules::pair_overlap::PAIR_OVERLAP;
    let par = example(code, "Bad");
    // 20,000 small particles apart on a line, one huge sphere over the first ten (a
    // grid as big as it would make every pair of small ones a candidate), and two small
    // ones overlapping far along.
    let mut ps: Vec<Particle> = (0..20_000)
        .map(|k| at(1.0, 3.0 * k as f64, 0.0, 0.0, k))
        .collect();
    ps[19_999] = at(1.0, 3.0 * 19_998.0 + 1.8, 0.0, 0.0, 19_999);
    ps.push(at(1e4, 0.0, 0.0, 1e4 + 0.9, 20_000));
    let f = findings(&par, NONE, &ps, &Build::default());
    let pairs: Vec<_> = (f.particles.iter())
        .map(|d| {
            (
                d.record.unwrap().index,
                d.labels[0].message.clone(),
                d.severity,
            )
        })
        .collect();
    // The huge one's overlaps, measured here one by one: those above 3 % of 1.
    let huge = &ps[20_000];
    let expected = (0..20_000)
        .filter(|&k| 1e4 + 1.0 - (ps[k].pos - huge.pos).norm() > 0.03)
        .count();
    assert!(expected > 5, "{expected}");
    assert_eq!(pairs.len(), expected + 1, "{pairs:?}");
    assert_eq!(pairs[0], (0, "particle 20000".to_string(), Severity::Info));
    assert!(
        pairs.contains(&(19_998, "particle 19999".to_string(), Severity::Warning)),
        "{pairs:?}"
    );
}

/// The attack's findings: many coincident particles are counted in bounded memory; many
/// big ones are found on their own grid; walls stand where they are at pkdgrav's t₀;
/// a `dSoft` of 0 or less overlaps nothing.
#[test]
fn the_attack_s_breaks_stay_fixed() {
    let code = &rules::pair_overlap::PAIR_OVERLAP;
    let par = example(code, "Bad");
    let build = Build::default();
    // 3,000 particles at one point: 4,498,500 overlapping pairs, 100 reported.
    let same: Vec<Particle> = (0..3000).map(|k| at(1.0, 0.0, 0.0, 0.0, k)).collect();
    let f = findings(&par, NONE, &same, &build);
    assert_eq!(f.particles.len(), super::MAX_REPORTED + 1);
    assert_eq!(
        f.particles.last().unwrap().message,
        "4498400 more overlapping pairs (the first 100 are reported)"
    );
    // 20,000 on a line, 600 big ones far apart (each over none): no finding, at once.
    let mut many: Vec<Particle> = (0..20_000)
        .map(|k| at(1.0, 3.0 * k as f64, 0.0, 0.0, k))
        .collect();
    many.extend((0..600).map(|k| at(1e4, 1e7 * (k + 1) as f64, 1e7, 0.0, 20_000 + k)));
    // And one big one over particle 0.
    many.push(at(1e4, 0.0, 0.0, 1e4 + 0.9, 20_600));
    let started = std::time::Instant::now();
    let f = findings(&par, NONE, &many, &build);
    assert!(started.elapsed().as_secs() < 20, "{:?}", started.elapsed());
    assert!(!f.particles.is_empty());
    assert!(
        f.particles
            .iter()
            .all(|d| d.labels[0].message == "particle 20600")
    );
    // A plane moving up at 1 from z = 0, and iStartStep·dDelta = 1: at t₀ it is at
    // z = 1, 60 % into a particle at z = 1.4.
    let moving = "wall\n  type plane\n  origin 0 0 0\n  orient 0 0 1\n  velocity 0 0 1\n";
    let wall_par = format!(
        "{}dDelta               = 1e-3\niStartStep           = 1000\nnSteps               = 2000\n",
        example(&rules::wall_overlap::WALL_OVERLAP, "Good")
    );
    let lone = [at(1.0, 0.0, 0.0, 1.4, 0)];
    let f = findings(&wall_par, moving, &lone, &build);
    assert_eq!(f.particles.len(), 1, "{:?}", all(&f));
    assert!(
        f.particles[0].message.contains("by 60 %"),
        "{}",
        f.particles[0].message
    );
    // dSoft = 0 and below: no sphere to overlap.
    let ps = [at(1.0, 0.0, 0.0, 0.0, 0), at(1.0, 0.9, 0.0, 0.0, 1)];
    for soft in ["0", "-0.5"] {
        let par = format!("{par}dSoft                = {soft}\n");
        assert!(
            findings(&par, NONE, &ps, &build).particles.is_empty(),
            "dSoft {soft}"
        );
    }
}

#[test]
fn the_initial_conditions_as_pkdgrav_checks_them_at_start_up() {
    let code = &rules::initial_conditions::INITIAL_CONDITIONS;
    let build = Build::default();
    let ps = [at(1.0, 0.0, 0.0, 0.0, 0), at(1.0, 5.0, 0.0, 0.0, 1)];
    let bad = example(code, "Bad");
    // Written at t = 0.001 for a run of step 0: reset to 0 (B45).
    let (file, span, severity, message) = one(&findings_at(&bad, NONE, &ps, &build, 1e-3), code);
    assert_eq!((file, span, severity), ("par", 0..0, Severity::Warning));
    assert!(message.contains("(B45)"), "{message}");
    // Continued from step 100, its time written as 100·dDelta: nothing.
    let good = example(code, "Good");
    let f = findings_at(&good, NONE, &ps, &build, 100.0 * 1e-5);
    assert!(
        all(&f).iter().all(|(_, d)| d.code.id != code.id),
        "{:?}",
        all(&f)
    );
    // A time of 0 for step 100 (B44), and another time (B46), at `iStartStep`.
    let (_, span, _, message) = one(&findings_at(&good, NONE, &ps, &build, 0.0), code);
    let value = good.find("iStartStep           = 100").unwrap() + 23;
    assert_eq!(span, value..value + 3);
    assert!(message.contains("(B44)"), "{message}");
    let (_, _, _, message) = one(&findings_at(&good, NONE, &ps, &build, 2e-3), code);
    assert!(message.contains("(B46)"), "{message}");
    // An aggregate of one particle stops an AGGS build (A127), at that particle.
    let aggs = Build::parse("DEM DEM_FIXED_BALL DEM_ROTATION_DASHPOT AGGS").unwrap();
    let mut members = vec![
        at(1.0, 0.0, 0.0, 0.0, 0),
        at(1.0, 10.0, 0.0, 0.0, 1),
        at(1.0, 11.5, 0.0, 0.0, 2),
    ];
    members[0].index = -1;
    members[1].index = -2;
    members[2].index = -2;
    let f = findings(
        &good.replace("iStartStep           = 100\n", ""),
        NONE,
        &members,
        &aggs,
    );
    let (file, span, severity, message) = one(&f, code);
    assert_eq!((file, span, severity), ("ss", record(0), Severity::Error));
    assert_eq!(
        message,
        "particle 0 is the only member of aggregate 0 (org_idx -1): pkdgrav stops at start-up (exit status 1) on an aggregate of one particle"
    );
    assert!(
        findings(&good, NONE, &members, &build)
            .particles
            .iter()
            .all(|d| d.code.id != code.id)
    );
}
