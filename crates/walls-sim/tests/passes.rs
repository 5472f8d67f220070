//! The passes over the particles must not change what a run does.
//!
//! - **Threads.** The passes, the search for touching pairs and their forces run in
//!   parallel from 1,024 particles up, and everything is merged in particle and pair
//!   order: a run on one thread and on three ends bit for bit the same (positions,
//!   velocities, events, contacts, warnings).
//! - **Owed kicks.** The soft stepper gives a free particle clear of the walls its
//!   closing kick in the next step's drift, and gives the kicks still owed when an
//!   observer looks at the particles, when the run ends, and when an owed kick might
//!   overflow. An observer that looks now and then sees, at those steps, exactly what
//!   one looking every step sees; a run nobody looks at ends exactly as one looked at
//!   every step; and a kick that overflows stops the run at its own step.
//! - **Places.** The soft stepper keeps the particles in the pair grid's order, not the
//!   file's ([`Places`]): a run kept either way ends bit for bit the same, seen at
//!   every step and on any number of threads, its events, warnings and stops naming
//!   the file's particles in the file's order.
//! - **Chunks.** The wall pass keeps a chunk's lists of open wall contacts only once one
//!   of its particles has touched a wall: a sphere sliding on the floor slides the same
//!   alone and kept last of a crowd.
//! - **Asking ahead.** The soft stepper's passes may ask the processor for the memory
//!   they will read a few particles or pairs on ([`Ahead`]): a hint, which changes
//!   nothing a run does, on one thread or three, looked at or not.
//! - **Contacts through rebuilds.** The candidate list keeps each pair's slot among the
//!   open contacts only while some contact is open: a contact is carried through every
//!   rebuild while it lasts, and one that opens after none was is counted once.
//!
//! The scene of the others: two thousand spheres of assorted sizes (radii 0.8–1 mm, so that each
//! particle's mass and inertia are its own in every pass) dropped into a box of five
//! planes, with friction (many clear of the walls, many in contact), for 600 steps.

use nalgebra::Vector3;
use walls_geometry::Particle;
use walls_sim::run::{
    Ahead, EventKind, Integrator, Outcome, Overlapping, ParticleMaterial, Places, Settings, State,
    Stop, Warning, defaults, run, run_observed,
};
use walls_test_support::scene;
use walls_test_support::scenes::{ball, box_of_spheres};

/// The dropped box on `threads` threads, looked at on the steps `looks` says; the
/// states seen at each fiftieth step.
fn dropped(
    threads: usize,
    looks: impl Fn(u64) -> bool + Sync,
) -> (Outcome, Vec<(u64, Vec<State>)>) {
    dropped_with(threads, looks, |_| {})
}

/// [`dropped`] with its settings changed by `change`.
fn dropped_with(
    threads: usize,
    looks: impl Fn(u64) -> bool + Sync,
    change: impl Fn(&mut Settings),
) -> (Outcome, Vec<(u64, Vec<State>)>) {
    let (scene, mut particles) = box_of_spheres(2000, 2.0);
    for (k, p) in particles.iter_mut().enumerate() {
        let size = 0.8 + 0.2 * (k as f64 * 0.618_034).fract();
        p.radius *= size;
        p.mass *= size * size * size;
    }
    let material = ParticleMaterial {
        eps_n: 0.5,
        mu_s: 0.5,
        ..defaults::default_material(1000.0)
    };
    let dt = 5e-6;
    let mut settings = Settings {
        gravity: Vector3::new(0.0, 0.0, -9.81),
        ..Settings::new(dt, 600.0 * dt, material)
    };
    change(&mut settings);
    let mut seen = Vec::new();
    let mut observe = |step: u64, _: f64, snapshot: &mut dyn walls_sim::run::Snapshot| {
        if looks(step) {
            let (states, _) = snapshot.look();
            if step.is_multiple_of(50) {
                seen.push((step, states.to_vec()));
            }
        }
    };
    let out = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .expect("a thread pool")
        .install(|| run_observed(&scene, particles, &settings, &mut observe));
    (out, seen)
}

#[test]
fn one_thread_and_three_end_the_same() {
    let (one, _) = dropped(1, |_| false);
    assert!(
        one.pair_contacts > 1000,
        "{} particle contacts",
        one.pair_contacts
    );
    assert!(!one.events.is_empty());
    assert_eq!(one, dropped(3, |_| false).0);
}

#[test]
fn looking_now_and_then_sees_what_looking_every_step_sees() {
    let (every, seen_every) = dropped(1, |_| true);
    assert_eq!(seen_every.len(), 12);
    let (sometimes, seen_sometimes) = dropped(1, |step| step.is_multiple_of(50));
    assert_eq!(seen_sometimes, seen_every);
    assert_eq!(sometimes, every);
}

#[test]
fn a_run_nobody_looks_at_ends_as_one_looked_at_every_step() {
    let (every, _) = dropped(1, |_| true);
    let (never, seen) = dropped(1, |_| false);
    assert!(seen.is_empty());
    assert_eq!(never, every);
}

#[test]
fn every_integrator_and_pkdgravs_acc_crit_owe_kicks_without_a_trace() {
    // The other steps (their kicks of other fractions: explicit Euler's closing kick is
    // none) and dAccCrit's zeroing (at 20 m/s², of some particles near their turning
    // points, in the wall pass: no owed kick here meets its test; the next test has
    // one that does).
    for integrator in [
        Integrator::Leapfrog,
        Integrator::LeapfrogPredicted,
        Integrator::ExplicitEuler,
        Integrator::Pkdgrav,
    ] {
        let change = |s: &mut Settings| {
            s.integrator = integrator;
            s.acc_crit = 20.0;
        };
        let (every, _) = dropped_with(1, |_| true, change);
        let (never, _) = dropped_with(1, |_| false, change);
        assert!(every.pair_contacts > 1000, "{integrator:?}");
        assert_eq!(never, every, "{integrator:?}");
    }
}

#[test]
fn an_owed_kick_stops_a_ball_at_its_turning_point_as_the_wall_pass_does() {
    // One ball rising at 1.2·10⁻⁴ m/s against gravity, with no wall: clear of
    // everything, so its closing kick is owed to the next drift. dAccCrit's test stops a
    // ball with a·v < 0, |a| = 9.81 < 20 m/s² and |v| < 20 m/s² × 5 µs = 10⁻⁴ m/s: not
    // at the start (pkdgrav's forces before the first step leave it alone), but at its
    // first closing kick, owed, after the first opening kick (the leapfrogs and pkdgrav:
    // 9.5·10⁻⁵ m/s) or explicit Euler's late kick (7.1·10⁻⁵ m/s).
    for integrator in [
        Integrator::Leapfrog,
        Integrator::LeapfrogPredicted,
        Integrator::ExplicitEuler,
        Integrator::Pkdgrav,
    ] {
        let dt = 5e-6;
        let settings = |acc_crit: f64| Settings {
            integrator,
            acc_crit,
            gravity: Vector3::new(0.0, 0.0, -9.81),
            ..Settings::new(dt, 10.0 * dt, defaults::default_material(1000.0))
        };
        let rising = || vec![ball([0.0; 3], [0.0, 0.0, 1.2e-4])];
        let looked_at = |settings: &Settings| {
            let mut look = |_: u64, _: f64, snapshot: &mut dyn walls_sim::run::Snapshot| {
                snapshot.look();
            };
            run_observed(&[], rising(), settings, &mut look)
        };
        let owed = run(&[], rising(), &settings(20.0));
        assert_eq!(owed, looked_at(&settings(20.0)), "{integrator:?}");
        let never_stopped = run(&[], rising(), &settings(0.0));
        assert_ne!(
            owed.particles[0].particle.vel, never_stopped.particles[0].particle.vel,
            "{integrator:?}"
        );
    }
}

#[test]
fn an_owed_kick_that_overflows_stops_the_run_at_its_step() {
    // Two light balls overlapping by a tenth of their radius, with no wall, on springs
    // so stiff that the closing kick of step 1 overflows (the leapfrog: no force before
    // the first drift, so each is clear and finite when the drift marks its kick
    // owed): the run stops after step 1, the first of the two named.
    let settings = Settings {
        integrator: Integrator::Leapfrog,
        ..Settings::new(1e-3, 1.0, defaults::default_material(1e300))
    };
    let light = |x: f64, index: i32| walls_geometry::Particle {
        mass: 1e-20,
        index,
        ..ball([x, 0.0, 0.0], [0.0; 3])
    };
    let balls = vec![light(0.0, 0), light(0.19, 1)];
    let out = run(&[], balls, &settings);
    assert_eq!((out.steps, out.stopped), (1, Some(Stop::NotFinite(0))));
    assert!(!out.particles[0].particle.vel.x.is_finite());
}

#[test]
fn an_overlap_that_stops_the_run_stops_it_alike_on_one_thread_and_three() {
    // The box's spheres without the box, on springs so soft that two of them sink into
    // each other past half a radius: the run stops at that pair, with the contacts
    // opened before it counted.
    let (_, particles) = box_of_spheres(2000, 2.0);
    let settings = Settings::new(5e-6, 600.0 * 5e-6, defaults::default_material(1e-4));
    let on = |threads: usize| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .expect("a thread pool")
            .install(|| run(&[], particles.clone(), &settings))
    };
    let one = on(1);
    assert_eq!(one.stopped, Some(Stop::Overlap));
    let stop = one.warnings.iter().find_map(|w| match w {
        Warning::OverlapStop { what, .. } => Some(*what),
        _ => None,
    });
    assert!(matches!(stop, Some(Overlapping::Particles(..))), "{stop:?}");
    // At step 186, with 1,972 contacts opened: the figures of the build that checked
    // each overlap as it opened the contacts in turn (the opened counted up to the
    // deep pair, not past it).
    assert_eq!((one.steps, one.pair_contacts), (186, 1972));
    assert_eq!(one, on(3));
}

#[test]
fn an_overlap_stop_counts_the_contacts_opened_before_it_and_no_others() {
    // Four pairs of balls along x, in the list's order. The first touches in step 1
    // and still does in step 2; the second begins to touch in step 2; the third, apart
    // in step 1, sinks past half a radius in step 2; the fourth would begin to touch in
    // step 2, after it. The run stops in step 2 with two contacts counted: the first
    // pair's (once) and the second's.
    let settings = Settings {
        integrator: Integrator::Leapfrog,
        ..Settings::new(1.0, 10.0, defaults::default_material(1.0))
    };
    let pair = |x: f64, gap: f64, closing: f64, first: i32| {
        let a = ball([x, 0.0, 0.0], [0.0; 3]);
        let b = ball([x + 0.2 + gap, 0.0, 0.0], [-closing, 0.0, 0.0]);
        [a, b].map(|mut p| {
            p.index += first;
            p
        })
    };
    let balls = [
        pair(0.0, 0.01, 0.012, 0),
        pair(10.0, 0.01, 0.006, 2),
        pair(20.0, 0.06, 0.059, 4),
        pair(30.0, 0.01, 0.006, 6),
    ]
    .concat();
    let out = run(&[], balls, &settings);
    assert_eq!(out.stopped, Some(Stop::Overlap));
    assert_eq!((out.steps, out.pair_contacts), (2, 2));
}

/// Whether two runs (outcome and states seen) are the same bit for bit: their numbers
/// as Debug writes them (the shortest text that reads back to the same bits).
fn same_bits<T: std::fmt::Debug>(a: &T, b: &T) -> bool {
    format!("{a:?}") == format!("{b:?}")
}

#[test]
fn where_the_particles_are_kept_changes_nothing() {
    // The dropped box, numbered x fastest as a lattice is, kept in the grid's cell
    // order (x slowest) and in the file's: the same at every step, on one thread and
    // on three (where the pair and wall passes run in parallel).
    for threads in [1, 3] {
        let file = dropped_with(threads, |_| true, |s| s.places = Places::File);
        let grid = dropped_with(threads, |_| true, |s| s.places = Places::Grid);
        assert!(file.0.pair_contacts > 1000 && !file.0.events.is_empty());
        assert_eq!(file.1.len(), 12);
        assert!(same_bits(&file, &grid), "{threads} threads");
    }
}

#[test]
fn asking_for_memory_ahead_changes_nothing() {
    // The dropped box (2,000 particles: fewer than the default asks from), asking
    // always and never, looked at every step and every fiftieth (when the drift gives
    // the owed kicks), on one thread and on three.
    let every_fiftieth = |step: u64| step.is_multiple_of(50);
    for threads in [1, 3] {
        let always = |s: &mut Settings| s.ahead = Ahead::Always;
        let never = |s: &mut Settings| s.ahead = Ahead::Never;
        let asked = dropped_with(threads, every_fiftieth, always);
        let not = dropped_with(threads, every_fiftieth, never);
        assert!(asked.0.pair_contacts > 1000 && !asked.0.events.is_empty());
        assert_eq!(asked.1.len(), 12);
        assert!(same_bits(&asked, &not), "{threads} threads");
        let asked = dropped_with(threads, |_| true, always);
        assert!(same_bits(&asked, &dropped_with(threads, |_| true, never)));
    }
}

#[test]
fn events_warnings_and_stops_name_the_files_particles_wherever_they_are_kept() {
    // The box's spheres, fast and on soft springs, in a box whose floor is sticky and
    // whose side x = 0 removes them: sticks, removals and bounces, pkdgrav's overlap
    // warnings, in the file's order and naming the file's particles, kept either way.
    let (_, particles) = box_of_spheres(2000, 4.0);
    let side = 11.0 * 2.2e-3;
    let walls = scene(&format!(
        "wall type plane\n  orient 0 0 1\n  epsn 0\n\
         wall type plane\n  orient 1 0 0\n  epsn -1\n\
         wall type plane\n  origin {side} 0 0\n  orient -1 0 0\n\
         wall type plane\n  orient 0 1 0\n\
         wall type plane\n  origin 0 {side} 0\n  orient 0 -1 0\n"
    ));
    let settings = |places: Places| Settings {
        gravity: Vector3::new(0.0, 0.0, -9.81),
        places,
        ..Settings::new(5e-6, 400.0 * 5e-6, defaults::default_material(20.0))
    };
    let on = |threads: usize, places: Places| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .expect("a thread pool")
            .install(|| run(&walls, particles.clone(), &settings(places)))
    };
    let file = on(1, Places::File);
    let kinds = |kind: EventKind| file.events.iter().filter(|e| e.kind == kind).count();
    assert!(kinds(EventKind::Stick) > 10, "{:?}", file.events.len());
    assert!(kinds(EventKind::Remove) > 10, "{:?}", file.events.len());
    assert!(!file.warnings.is_empty());
    for threads in [1, 3] {
        assert!(
            same_bits(&file, &on(threads, Places::Grid)),
            "{threads} threads"
        );
    }
}

#[test]
fn a_run_that_overflows_names_the_files_first_particle_wherever_it_is_kept() {
    // The overflowing pair of `an_owed_kick_that_overflows_stops_the_run_at_its_step`
    // as the file's second and third particles, the second on the right, in the grid's
    // next cell along x, and the first far off: kept in the grid's order the third is
    // first and the first last, and the stop still names the second.
    let light = |x: f64, index: i32| walls_geometry::Particle {
        mass: 1e-20,
        index,
        ..ball([x, 0.0, 0.0], [0.0; 3])
    };
    for places in [Places::File, Places::Grid] {
        let settings = Settings {
            integrator: Integrator::Leapfrog,
            places,
            ..Settings::new(1e-3, 1.0, defaults::default_material(1e300))
        };
        let balls = vec![light(10.0, 0), light(0.30, 1), light(0.11, 2)];
        let out = run(&[], balls, &settings);
        assert_eq!((out.steps, out.stopped), (1, Some(Stop::NotFinite(1))));
        assert!(out.particles[0].particle.vel.x.is_finite());
        assert!(!out.particles[1].particle.vel.x.is_finite());
    }
}

#[test]
fn a_wall_contact_is_carried_in_whichever_chunk_its_particle_is_kept() {
    // A sphere sliding and spinning on a floor with friction (the contact's spring carried
    // from step to step), alone and as the last of 1,501 (the others at rest in the air
    // beside it, falling less than their height in the run): in the crowd it is kept
    // last, past the wall pass's first chunks, whose lists of open contacts are made
    // only once one of their particles touches a wall. On one thread and on three, it
    // slides to the same bit, as does the run kept in the file's order.
    let floor = scene("wall type plane\n  origin 0 0 0\n  orient 0 0 1\n");
    let r = 1e-3;
    let slider = Particle {
        mass: 2500.0 * 4.0 / 3.0 * std::f64::consts::PI * r * r * r,
        radius: r,
        pos: Vector3::new(0.2, 0.05, 0.999 * r),
        vel: Vector3::new(0.05, -0.02, 0.0),
        spin: Vector3::new(0.0, 30.0, 10.0),
        color: 3,
        index: 1500,
    };
    let material = ParticleMaterial {
        mu_s: 0.5,
        ..defaults::default_material(1000.0)
    };
    let dt = 5e-6;
    let settings = |places| Settings {
        gravity: Vector3::new(0.0, 0.0, -9.81),
        places,
        ..Settings::new(dt, 400.0 * dt, material)
    };
    let alone = run(&floor, vec![slider.clone()], &settings(Places::Grid));
    let mut crowd: Vec<Particle> = (0..1500)
        .map(|k| Particle {
            pos: Vector3::new((k % 40) as f64 * 3e-3, (k / 40) as f64 * 3e-3, 0.02),
            vel: Vector3::zeros(),
            spin: Vector3::zeros(),
            index: k,
            ..slider.clone()
        })
        .collect();
    crowd.push(slider);
    let slid = &alone.particles[0];
    // It touched the floor throughout: friction slowed it and turned its spin.
    assert!(
        slid.particle.vel.x < 0.049 && slid.particle.spin.y != 30.0,
        "{slid:?}"
    );
    for threads in [1, 3] {
        for places in [Places::Grid, Places::File] {
            let out = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .expect("a thread pool")
                .install(|| run(&floor, crowd.clone(), &settings(places)));
            assert!(
                same_bits(&out.particles[1500], slid),
                "{threads} threads, {places:?}"
            );
        }
    }
}

#[test]
fn a_pair_contact_is_carried_through_rebuilds_and_a_new_one_opens_after_none_was() {
    // Two spheres meet at a glancing angle with friction (the contact's spring carried
    // from step to step) and part; later two others meet. With a runner far away that
    // moves half the skin every four steps, the candidate list is found again about a
    // dozen times while the first two touch, and again between the two contacts, when
    // none is open (and the list keeps no slots for its pairs). The four end as they do
    // without the runner (no rebuild at all while they touch), bit for bit, and each
    // contact is counted once; alike on three threads with a crowd at rest far away
    // (the passes then in parallel).
    let r = 1e-3;
    let sphere = |index: i32, x: f64, vel: [f64; 3]| Particle {
        mass: 2500.0 * 4.0 / 3.0 * std::f64::consts::PI * r * r * r,
        radius: r,
        pos: Vector3::new(x, 0.0, 0.0),
        vel: Vector3::from(vel),
        spin: Vector3::zeros(),
        color: 3,
        index,
    };
    let pairs = vec![
        sphere(0, 0.0, [0.1, 0.01, 0.0]),
        sphere(1, 2.02 * r, [0.0, 0.0, 0.0]),
        sphere(2, 0.1, [0.05, 0.0, 0.0]),
        sphere(3, 0.1 + 2.1 * r, [-0.05, 0.0, 0.0]),
    ];
    let runner = Particle {
        pos: Vector3::new(0.0, 0.5, 0.0),
        vel: Vector3::new(10.0, 0.0, 0.0),
        index: 4,
        ..pairs[0].clone()
    };
    let material = ParticleMaterial {
        mu_s: 0.5,
        ..defaults::default_material(1000.0)
    };
    let dt = 5e-6;
    let settings = Settings::new(dt, 400.0 * dt, material);
    let quiet = run(&[], pairs.clone(), &settings);
    assert_eq!((quiet.pair_contacts, quiet.stopped), (2, None));
    // The first two met and parted, glancing: each turned the other.
    let parted = &quiet.particles[..2];
    assert!(parted[1].particle.vel.x > 0.0 && parted[0].particle.spin.z != 0.0);
    assert!((quiet.particles[2].particle.vel.x + 0.05).abs() < 0.03);
    let mut chased = pairs.clone();
    chased.push(runner.clone());
    let mut crowded = chased.clone();
    crowded.extend((0..1200).map(|k| Particle {
        pos: Vector3::new((k % 40) as f64 * 3e-3, (k / 40) as f64 * 3e-3, 1.0),
        vel: Vector3::zeros(),
        index: 5 + k,
        ..pairs[1].clone()
    }));
    for (particles, threads) in [(chased, 1), (crowded.clone(), 1), (crowded, 3)] {
        let out = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .expect("a thread pool")
            .install(|| run(&[], particles, &settings));
        assert_eq!(out.pair_contacts, 2, "{threads} threads");
        for k in 0..4 {
            assert!(
                same_bits(&out.particles[k], &quiet.particles[k]),
                "particle {k}, {threads} threads"
            );
        }
    }
}
