//! pkdgrav's aggregates (its `AGGS` build, docs/pkdgrav-physics.md §9) against what the
//! facts and mechanics say: a falling aggregate's members show the half-step velocity
//! pkdgrav writes, a torque-free asymmetric aggregate keeps its angular momentum and
//! energy to the integrator's tolerance, the set-up gives the mass, centre and inertia of
//! known shapes, an AGGS build has no rolling or twisting between particles, and the runs
//! pkdgrav refuses stop with a warning.

use nalgebra::{Matrix3, Vector3};
use walls_geometry::{Particle, Wall};
use walls_sim::build::Build;
use walls_sim::dynamics::aggregate::{Aggregate, Aggregates, SetupError, jacobi};
use walls_sim::run::{Integrator, Outcome, Settings, State, Warning, run_observed};
use walls_test_support::scene;

type Vec3 = Vector3<f64>;

/// A sphere of unit density; `org_idx` is −1 − aggregate for a member, else ≥ 0.
fn sphere(radius: f64, pos: [f64; 3], vel: [f64; 3], spin: [f64; 3], org_idx: i32) -> Particle {
    Particle {
        mass: 4.0 / 3.0 * std::f64::consts::PI * radius.powi(3),
        radius,
        pos: Vec3::from(pos),
        vel: Vec3::from(vel),
        spin: Vec3::from(spin),
        color: 3,
        index: org_idx,
    }
}

/// pkdgrav's way with the build given (`AGGS` or not): its integrator, `steps` steps of
/// `dt`, gravity `g`, friction coefficients `mu` (sliding, rolling, twisting); springs
/// soft enough for dt (no W2xx).
fn settings(build: &str, dt: f64, steps: u64, g: [f64; 3], mu: f64) -> Settings {
    let k_n = if dt > 1e-4 { 100.0 } else { 1e6 };
    let mut s = Settings::new(
        dt,
        dt * steps as f64,
        walls_sim::run::ParticleMaterial {
            mu_s: mu,
            mu_r: mu,
            mu_t: mu,
            beta_s: 1.0,
            ..walls_sim::run::defaults::default_material(k_n)
        },
    );
    s.build = Build::parse(build).expect("a build");
    s.integrator = Integrator::Pkdgrav;
    s.last_step = Some(steps);
    s.gravity = Vec3::from(g);
    s
}

const AGGS: &str = "DEM DEM_ROTATION_DASHPOT AGGS";
const PLAIN: &str = "DEM DEM_ROTATION_DASHPOT";

/// Runs, keeping every step's states.
fn run_all(walls: &[Wall], particles: Vec<Particle>, s: &Settings) -> (Outcome, Vec<Vec<State>>) {
    let mut seen = Vec::new();
    let out = run_observed(walls, particles, s, &mut |_, _, snapshot| {
        seen.push(snapshot.look().0.to_vec())
    });
    (out, seen)
}

/// A dumbbell-like body of three unequal, overlapping spheres (aggregate 0), moving
/// rigidly: spinning at `omega` about its centre of mass, which moves at `v`.
fn lumpy(omega: Vec3, v: Vec3) -> Vec<Particle> {
    let raw = [
        sphere(0.10, [0.0, 0.0, 0.0], [0.0; 3], [0.0; 3], -1),
        sphere(0.07, [0.12, 0.03, 0.0], [0.0; 3], [0.0; 3], -1),
        sphere(0.05, [-0.02, 0.09, 0.06], [0.0; 3], [0.0; 3], -1),
    ];
    let m: f64 = raw.iter().map(|p| p.mass).sum();
    let com = raw.iter().map(|p| p.pos * p.mass).sum::<Vec3>() / m;
    raw.into_iter()
        .map(|mut p| {
            p.pos += Vec3::new(0.0, 0.0, 5.0);
            p.vel = v + omega.cross(&(p.pos - Vec3::new(0.0, 0.0, 5.0) - com));
            p.spin = omega;
            p
        })
        .collect()
}

#[test]
fn a_falling_aggregate_shows_the_half_step_velocity_as_pkdgrav_writes_it() {
    // §9.3: members' velocities are not refreshed at the closing kick, so in free fall
    // they read v_z = −g(n − ½)dt after step n, while the centre falls as the leapfrog
    // does, z = z₀ − ½g(n dt)². The members overlap by far more than half a radius and
    // must not stop the run (§12).
    let (g, dt, steps) = (9.81, 1e-3, 400);
    let particles = vec![
        sphere(0.1, [0.0, 0.0, 1.0], [0.0; 3], [0.0; 3], -1),
        sphere(0.1, [0.05, 0.0, 1.0], [0.0; 3], [0.0; 3], -1),
        sphere(0.1, [0.0, 0.05, 1.0], [0.0; 3], [0.0; 3], -1),
    ];
    let s = settings(AGGS, dt, steps, [0.0, 0.0, -g], 0.0);
    let (out, seen) = run_all(&[], particles.clone(), &s);
    assert_eq!(out.steps, steps, "{:?}", out.warnings);
    assert!(out.warnings.is_empty(), "{:?}", out.warnings);
    for (k, states) in seen.iter().enumerate() {
        let n = (k + 1) as f64;
        for (i, st) in states.iter().enumerate() {
            let p = &st.particle;
            let vz = -g * (n - 0.5) * dt;
            assert!(
                (p.vel.z - vz).abs() <= 1e-13 * g * n * dt,
                "step {n}, member {i}: v_z {} against {vz}",
                p.vel.z
            );
            // Gravity's moment about the centre is zero but for rounding.
            assert!(p.vel.xy().norm() < 1e-30, "{:?}", p.vel);
            let z = 1.0 - 0.5 * g * (n * dt).powi(2);
            assert!(
                (p.pos.z - z).abs() <= 1e-13,
                "step {n}: z {} against {z}",
                p.pos.z
            );
            assert!((p.pos.xy() - particles[i].pos.xy()).norm() < 1e-15);
        }
    }
}

#[test]
fn without_aggs_the_members_run_free_with_a_warning() {
    // The same file under a build without AGGS: W601, and the members, which overlap by
    // 75 % of a radius, stop the run at pkdgrav's first force evaluation (W103).
    let particles = vec![
        sphere(0.1, [0.0, 0.0, 1.0], [0.0; 3], [0.0; 3], -1),
        sphere(0.1, [0.05, 0.0, 1.0], [0.0; 3], [0.0; 3], -1),
    ];
    let out = run_observed(
        &[],
        particles.clone(),
        &settings(PLAIN, 1e-3, 10, [0.0, 0.0, -9.81], 0.0),
        &mut |_, _, _| {},
    );
    assert_eq!(out.warnings[0].code(), "W601", "{:?}", out.warnings);
    assert!(
        out.warnings[0]
            .to_string()
            .contains("2 particles are members of 1 aggregates")
    );
    assert!(out.warnings.iter().any(|w| w.code() == "W103"));
    // Apart, they fall freely, each with its own full-step velocity.
    let apart = vec![
        sphere(0.1, [0.0, 0.0, 1.0], [0.0; 3], [0.0; 3], -1),
        sphere(0.1, [0.5, 0.0, 1.0], [0.0; 3], [0.0; 3], -1),
    ];
    let out = run_observed(
        &[],
        apart,
        &settings(PLAIN, 1e-3, 10, [0.0, 0.0, -9.81], 0.0),
        &mut |_, _, _| {},
    );
    assert_eq!(out.steps, 10);
    assert_eq!(out.warnings.len(), 1);
    let vz = out.particles[0].particle.vel.z;
    assert!((vz + 9.81 * 10.0 * 1e-3).abs() < 1e-15, "{vz}");
    // The hard-sphere model does not follow aggregates either.
    let mut hard = settings("AGGS", 1e-3, 10, [0.0; 3], 0.0);
    hard.build = hard.build.with_model(walls_sim::run::ContactModel::Hsdem);
    let out = walls_sim::run::run(&[], particles, &hard);
    assert_eq!(out.warnings[0].code(), "W601");
    assert!(out.warnings[0].to_string().contains("soft-sphere"));
}

#[test]
fn a_torque_free_asymmetric_aggregate_keeps_its_angular_momentum_and_energy() {
    // Three unequal spheres spinning about an axis that is not principal: the body
    // tumbles (its members' positions relative to the centre turn far from a rotation
    // about a fixed axis), but the angular momentum and the kinetic energy stay what
    // they were to the integrator's tolerance (Cash–Karp at 10⁻⁶ a step; far better here).
    let omega = Vec3::new(3.0, -1.0, 2.0);
    let v = Vec3::new(0.1, 0.0, -0.2);
    let particles = lumpy(omega, v);
    let (dt, steps) = (1e-3, 3000);
    let s = settings(AGGS, dt, steps, [0.0; 3], 0.0);
    let aggs = Aggregates::find(&particles).unwrap().unwrap();
    let a0 = &aggs.list[0];
    let (l0, e0) = (a0.angular_momentum(), a0.energy(&Vec3::zeros()));
    // The set-up recovers the rigid motion it was given.
    assert!(
        (a0.spin() - omega).norm() < 1e-12 * omega.norm(),
        "{:?}",
        a0.spin()
    );
    assert!((a0.vel - v).norm() < 1e-15);
    let (out, seen) = run_all(&[], particles.clone(), &s);
    assert_eq!(out.steps, steps);
    // From the members' states: L about the centre (each member's orbital and own spin
    // momentum) and the kinetic energy, the centre's half-step velocity being v.
    let moments = |states: &[State]| {
        let m: f64 = states.iter().map(|s| s.particle.mass).sum();
        let com = states
            .iter()
            .map(|s| s.particle.pos * s.particle.mass)
            .sum::<Vec3>()
            / m;
        let vcom = states
            .iter()
            .map(|s| s.particle.vel * s.particle.mass)
            .sum::<Vec3>()
            / m;
        let mut l = Vec3::zeros();
        let mut e = 0.5 * m * vcom.norm_squared();
        for s in states {
            let p = &s.particle;
            let own = 0.4 * p.mass * p.radius * p.radius;
            let rel = p.vel - vcom;
            l += (p.pos - com).cross(&rel) * p.mass + p.spin * own;
            e += 0.5 * p.mass * rel.norm_squared() + 0.5 * own * p.spin.norm_squared();
        }
        (l, e, com, vcom)
    };
    let mut turned = 0.0f64;
    for (k, states) in seen.iter().enumerate() {
        let (l, e, com, vcom) = moments(states);
        assert!(
            (l - l0).norm() <= 1e-9 * l0.norm(),
            "step {}: L {l:?} against {l0:?}",
            k + 1
        );
        assert!(
            (e - e0).abs() <= 1e-9 * e0,
            "step {}: E {e} against {e0}",
            k + 1
        );
        assert!((vcom - v).norm() < 1e-13);
        let t = (k + 1) as f64 * dt;
        assert!((com - (a0.com + v * t)).norm() < 1e-11, "{com:?}");
        // How far the body has tumbled: the spin's direction in space is not constant.
        turned = turned.max(states[0].particle.spin.angle(&omega));
    }
    assert!(turned > 0.1, "the body hardly tumbled: {turned}");
}

#[test]
fn the_set_up_gives_mass_centre_and_inertia_of_known_shapes() {
    // Two equal spheres (radius r, mass m) at ±a along (1, 1, 0)/√2: M = 2m, the centre
    // between them, moments 0.8 m r² along the axis and 0.8 m r² + 2 m a² across it.
    let (r, a) = (0.1, 0.3);
    let d = Vec3::new(1.0, 1.0, 0.0).normalize() * a;
    let c = Vec3::new(1.0, 2.0, 3.0);
    let ps = vec![
        sphere(r, (c + d).into(), [0.0; 3], [0.0; 3], -3),
        sphere(r, (c - d).into(), [0.0; 3], [0.0; 3], -3),
        sphere(r, [9.0, 9.0, 9.0], [0.0; 3], [0.0; 3], 5),
    ];
    let aggs = Aggregates::find(&ps).unwrap().unwrap();
    assert_eq!(aggs.of, vec![Some(0), Some(0), None]);
    assert!(aggs.same(0, 1) && !aggs.same(0, 2) && !aggs.same(2, 2));
    let g = &aggs.list[0];
    assert_eq!(g.number, 2);
    assert_eq!(g.members, vec![0, 1]);
    let m = ps[0].mass;
    assert!((g.mass - 2.0 * m).abs() < 1e-15);
    assert!((g.com - c).norm() < 1e-15);
    let along = 0.8 * m * r * r;
    let across = along + 2.0 * m * a * a;
    // Jacobi leaves the moments in the order its rotations give (unsorted): the axis
    // of the small moment is ±(1, 1, 0)/√2, and the axes are orthonormal.
    let mut sorted: Vec<f64> = g.moments.iter().copied().collect();
    sorted.sort_by(f64::total_cmp);
    assert!((sorted[0] - along).abs() < 1e-14 * across);
    assert!((sorted[1] - across).abs() < 1e-14 * across);
    assert!((sorted[2] - across).abs() < 1e-14 * across);
    let k = g.moments.imin();
    let axis: Vec3 = g.axes.column(k).into_owned();
    assert!(
        (axis.dot(&d.normalize()).abs() - 1.0).abs() < 1e-14,
        "{axis:?}"
    );
    assert!((g.axes.transpose() * g.axes - Matrix3::identity()).amax() < 1e-15);
    // The members' body positions are Λᵀρ.
    assert!((g.axes * g.body[0] - d).norm() < 1e-15);
    // An aggregate of one member is refused, as pkdgrav aborts.
    let single = vec![sphere(r, [0.0; 3], [0.0; 3], [0.0; 3], -1)];
    assert_eq!(
        Aggregates::find(&single),
        Err(SetupError::SingleMember {
            aggregate: 0,
            particle: 0
        })
    );
    assert_eq!(Aggregates::find(&ps[2..]), Ok(None));
}

#[test]
fn the_set_up_cuts_tiny_inertia_elements_and_finds_the_body_spin() {
    // A body along x spinning about z: the tiny off-axis offset makes off-diagonal
    // elements 10⁻¹⁴ of the largest, which the set-up sets to 0, so the axes stay the
    // coordinate axes exactly; the body spin is (Λᵀ L)_k / I_k.
    let w = Vec3::new(0.0, 0.0, 2.0);
    let ps: Vec<Particle> = [[-0.2, 1e-15, 0.0], [0.2, 0.0, 0.0]]
        .iter()
        .map(|x| {
            let pos = Vec3::from(*x);
            sphere(0.1, *x, w.cross(&pos).into(), w.into(), -1)
        })
        .collect();
    let g = Aggregate::new(0, vec![0, 1], &ps);
    assert_eq!(g.axes, Matrix3::identity());
    assert!((g.omega - w).norm() < 1e-14, "{:?}", g.omega);
}

#[test]
fn jacobi_diagonalises_without_sorting() {
    let a = Matrix3::new(4.0, 1.0, -2.0, 1.0, 2.0, 0.5, -2.0, 0.5, 3.0);
    let (d, v) = jacobi(a);
    let back = v * Matrix3::from_diagonal(&d) * v.transpose();
    assert!((back - a).amax() < 1e-14, "{back}");
    assert!((v.transpose() * v - Matrix3::identity()).amax() < 1e-15);
    // A diagonal matrix is left as it is, in its own order.
    let (d, v) = jacobi(Matrix3::from_diagonal(&Vec3::new(3.0, 1.0, 2.0)));
    assert_eq!(d, Vec3::new(3.0, 1.0, 2.0));
    assert_eq!(v, Matrix3::identity());
}

#[test]
fn an_aggs_build_has_no_rolling_or_twisting_between_particles() {
    // Two free spheres pressed together along x, one spinning about x (the normal):
    // only a twisting torque could slow it. Under AGGS (μ_r = μ_t = 0 for every pair,
    // §9.6) the spin is kept exactly; without AGGS the twisting slider slows it.
    let make = || {
        vec![
            sphere(0.1, [-0.099, 0.0, 0.0], [0.0; 3], [5.0, 0.0, 0.0], 0),
            sphere(0.1, [0.099, 0.0, 0.0], [0.0; 3], [0.0; 3], 1),
        ]
    };
    let spin_after = |build: &str| {
        let out = walls_sim::run::run(&[], make(), &settings(build, 1e-5, 50, [0.0; 3], 0.5));
        assert_eq!(out.steps, 50);
        out.particles[0].particle.spin
    };
    assert_eq!(spin_after(AGGS), Vec3::new(5.0, 0.0, 0.0));
    assert!(spin_after(PLAIN).x < 5.0 - 1e-6, "{:?}", spin_after(PLAIN));
}

#[test]
fn an_aggregate_of_one_member_stops_the_run() {
    let ps = vec![
        sphere(0.1, [0.0, 0.0, 1.0], [0.0; 3], [0.0; 3], -2),
        sphere(0.1, [0.5, 0.0, 1.0], [0.0; 3], [0.0; 3], 0),
    ];
    let out = walls_sim::run::run(&[], ps, &settings(AGGS, 1e-3, 10, [0.0; 3], 0.0));
    assert_eq!(out.steps, 0);
    assert_eq!(out.warnings.last().map(Warning::code), Some("W602"));
    assert!(
        out.warnings
            .last()
            .unwrap()
            .to_string()
            .contains("aggregate 1 (org_idx -2) has a single member, particle 0")
    );
}

#[test]
fn an_aggregate_reaching_a_sticky_wall_stops_the_run() {
    // pkdgrav asserts that aggregates cannot stick (§9.5).
    let floor = scene("wall type plane origin 0 0 0 orient 0 0 1 epsn 0\n");
    let ps = vec![
        sphere(0.1, [0.0, 0.0, 0.12], [0.0, 0.0, -1.0], [0.0; 3], -1),
        sphere(0.1, [0.05, 0.0, 0.12], [0.0, 0.0, -1.0], [0.0; 3], -1),
    ];
    let out = walls_sim::run::run(&floor, ps, &settings(AGGS, 1e-3, 100, [0.0; 3], 0.0));
    assert!(out.steps < 100);
    let w = out.warnings.last().unwrap();
    assert_eq!(w.code(), "W603", "{:?}", out.warnings);
    assert!(w.to_string().contains("wall 0"));
    assert!(
        out.particles
            .iter()
            .all(|s| s.alive && s.stuck_to.is_none())
    );
}

#[test]
fn a_death_wall_deletes_a_member_alone_and_the_last_stops_the_run() {
    // pkdgrav deletes the member alone, warns that mass is not conserved, and keeps the
    // aggregate's mass and shape; deleting every member fails an assertion (§17). A
    // death wall at x = 0.3 (facing −x) that only the outer member reaches, a floor
    // far below.
    let wall = scene("wall type plane origin 0.3 0 0 orient -1 0 0 epsn -1\n");
    let ps = vec![
        sphere(0.1, [0.0, 0.0, 1.0], [0.5, 0.0, 0.0], [0.0; 3], -1),
        sphere(0.1, [0.15, 0.0, 1.0], [0.5, 0.0, 0.0], [0.0; 3], -1),
        sphere(0.1, [0.15, 0.15, 1.0], [0.5, 0.0, 0.0], [0.0; 3], -1),
    ];
    let out = walls_sim::run::run(&wall, ps.clone(), &settings(AGGS, 1e-3, 200, [0.0; 3], 0.0));
    assert_eq!(out.steps, 200, "{:?}", out.warnings);
    let deleted: Vec<_> = (out.warnings.iter())
        .filter(|w| w.code() == "W606")
        .map(ToString::to_string)
        .collect();
    assert_eq!(deleted.len(), 2, "{:?}", out.warnings);
    assert!(deleted[0].contains("death wall 0 deleted particle 1, a member of aggregate 0"));
    assert!(out.particles[0].alive && !out.particles[1].alive && !out.particles[2].alive);
    // The member left moves on at the aggregate's speed (no force on it).
    assert!((out.particles[0].particle.vel.x - 0.5).abs() < 1e-12);
    // Every member at the wall: the run stops when the last goes.
    let out = walls_sim::run::run(&wall, ps, &settings(AGGS, 1e-3, 2000, [0.0; 3], 0.0));
    assert!(out.steps < 2000);
    let last = out.warnings.last().unwrap();
    assert_eq!(last.code(), "W607", "{:?}", out.warnings);
    assert!(last.to_string().contains("every member of aggregate 0"));
}

#[test]
fn an_aggregate_striking_a_free_sphere_keeps_the_momentum() {
    // A two-sphere aggregate moving along x strikes a free sphere off its centre line:
    // the pair force moves the aggregate's centre and turns it, and once they have
    // parted the total momentum (members: the centre's velocity plus their turning,
    // which sums to zero) is what it was, and the aggregate spins.
    let v = 0.5;
    let ps = vec![
        sphere(0.1, [0.0, 0.0, 0.0], [v, 0.0, 0.0], [0.0; 3], -1),
        sphere(0.1, [-0.15, 0.0, 0.0], [v, 0.0, 0.0], [0.0; 3], -1),
        sphere(0.1, [0.25, 0.08, 0.0], [0.0; 3], [0.0; 3], 0),
    ];
    let p0: Vec3 = ps.iter().map(|p| p.vel * p.mass).sum();
    let s = settings(AGGS, 1e-5, 40_000, [0.0; 3], 0.0);
    let out = walls_sim::run::run(&[], ps, &s);
    assert_eq!(out.steps, 40_000, "{:?}", out.warnings);
    assert!(out.pair_contacts == 1, "{}", out.pair_contacts);
    let p1: Vec3 = out
        .particles
        .iter()
        .map(|s| s.particle.vel * s.particle.mass)
        .sum();
    assert!(
        (p1 - p0).norm() < 1e-12 * p0.norm(),
        "{p1:?} against {p0:?}"
    );
    let free = &out.particles[2].particle;
    assert!(free.vel.x > 0.1 && free.vel.y > 0.0, "{:?}", free.vel);
    let spin = out.particles[0].particle.spin;
    assert!(
        spin.z.abs() > 0.1 && spin.x == 0.0 && spin.y == 0.0,
        "{spin:?}"
    );
    assert_eq!(out.particles[1].particle.spin, spin);
}

#[test]
fn an_aggregate_turning_too_far_in_a_step_reaches_the_minimum_substep_and_goes_on() {
    // The lumpy body tumbling at ~2000 rad per unit time with steps of 0.1: 200 rad a
    // step, 0.2 rad a substep at the minimum of 0.001·dt, coarser than Cash–Karp's
    // 10⁻⁶ allows. pkdgrav warns and goes on (docs/pkdgrav-physics.md §17): W604 once,
    // every step taken.
    let omega = Vec3::new(1500.0, -500.0, 1000.0);
    let particles = lumpy(omega, Vec3::zeros());
    let s = settings(AGGS, 0.1, 3, [0.0; 3], 0.0);
    let (out, seen) = run_all(&[], particles, &s);
    assert_eq!((out.stopped, out.steps, seen.len()), (None, 3, 3));
    let floors: Vec<_> = out.warnings.iter().filter(|w| w.code() == "W604").collect();
    assert_eq!(floors.len(), 1, "{:?}", out.warnings);
    assert_eq!(
        floors[0],
        &Warning::StepFloor {
            body: walls_sim::warning::Rigid::Aggregate(0),
            t: 0.1
        }
    );
    // At a hundredth of the spin, no step comes near the minimum.
    let (out, _) = run_all(&[], lumpy(omega / 100.0, Vec3::zeros()), &s);
    assert!(
        out.warnings.iter().all(|w| w.code() != "W604"),
        "{:?}",
        out.warnings
    );
}
