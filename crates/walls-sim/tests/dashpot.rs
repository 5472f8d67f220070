//! pkdgrav's contact law with its `DEM_ROTATION_DASHPOT` rolling and twisting
//! (`contact::ssdem::dashpot_contact`, docs/pkdgrav-physics.md §1.3–§1.5), on the details
//! the golden scenes do not pin one by one: the shear spring's reset when the contact
//! slides, the capped dashpot that remains, the Coulomb clamp that can replace the reset
//! (`Sliding::Clamp`), the turn of the springs with the normal (the other way for a
//! wall), the rolling and twisting sliders (the twisting limit's extra μ_s), and where
//! β_s and the contact radius come from.

use nalgebra::Vector3;
use walls_geometry::{BETA_S_DEFAULT, Material};
use walls_sim::config::{Flags, resolve};
use walls_sim::contact::ssdem::{
    Dashpot, Optional, Record, Sliding, damping, dashpot_contact, dashpot_contact_with,
};
use walls_sim::io::par::{Params, read_par};
use walls_test_support::{ball, scene};

type Vec3 = Vector3<f64>;

const DT: f64 = 1e-3;

fn material() -> Material {
    Material {
        eps_n: 0.5,
        eps_t: 0.5,
        k_n: 1e4,
        k_t: 2e3,
        mu_s: 0.5,
        mu_r: 0.1,
        mu_t: 0.1,
        beta_s: 1.0,
    }
}

/// A pair contact along +z, partner 2 above particle 1, overlapping by 1e-3, the
/// partner's contact point moving at `u` and spinning at `spin` relative to particle 1.
fn pair(u: Vec3, spin: Vec3) -> Dashpot {
    Dashpot {
        overlap: 1e-3,
        normal: Vec3::z(),
        velocity: u,
        spin,
        turn: Vec3::zeros(),
        levers: (0.0995, 0.0995),
        mass: 0.5,
        radius: 0.05,
        wall: false,
        constant_torque: None,
        sliding: Sliding::Reset,
    }
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-12 * a.abs().max(b.abs()).max(1e-300)
}

#[test]
fn a_stuck_contact_stretches_its_spring_and_adds_the_dashpot() {
    let mat = material();
    let u = Vec3::new(1e-3, 0.0, 0.0);
    let mut record = Record::default();
    let c = dashpot_contact(&pair(u, Vec3::zeros()), &mut record, DT, &mat);
    assert_eq!(record.spring, u * DT);
    assert_eq!(record.normal, Vec3::z());
    let c_t = damping(mat.eps_t, mat.k_t, 0.5);
    let f_t = c.force - Vec3::z() * c.force.z;
    assert!(close(f_t.x, mat.k_t * 1e-6 + c_t * 1e-3), "{f_t}");
    // The normal spring pushes particle 1 away from its partner.
    assert!(close(c.force.z, -mat.k_n * 1e-3));
    // Torques: l₁ n̂ × F_t on particle 1, l₂ n̂ × F_t on the partner (equal levers).
    assert_eq!(c.torque, c.partner_torque);
}

#[test]
fn damping_worked_out_beforehand_gives_the_same_contact_bit_for_bit() {
    // The stepper works out C_n and C_t once for contacts of one reduced mass.
    let mat = material();
    let c = pair(Vec3::new(1e-3, 2e-4, -3e-3), Vec3::new(0.5, -0.2, 0.1));
    let worked_out = Optional {
        damping: Some((
            damping(mat.eps_n, mat.k_n, c.mass),
            damping(mat.eps_t, mat.k_t, c.mass),
        )),
        ..Optional::default()
    };
    let (mut a, mut b) = (Record::default(), Record::default());
    for _ in 0..3 {
        let per_contact = dashpot_contact(&c, &mut a, DT, &mat);
        assert_eq!(
            dashpot_contact_with(&c, &mut b, DT, &mat, &worked_out),
            per_contact
        );
        assert_eq!(a, b);
    }
}

#[test]
fn sliding_resets_the_spring_and_keeps_only_the_capped_dashpot() {
    let mat = material();
    let n_force = mat.k_n * 1e-3;
    // A spring far past μ_s·N: the contact slides.
    let mut record = Record {
        spring: Vec3::new(1.0, 0.0, 0.0),
        normal: Vec3::z(),
        ..Record::default()
    };
    // A slow slip: the dashpot C_t|u_t| is below the cap and is all that remains.
    let slow = Vec3::new(0.0, 1e-4, 0.0);
    let c = dashpot_contact(&pair(slow, Vec3::zeros()), &mut record, DT, &mat);
    assert_eq!(
        record.spring,
        Vec3::zeros(),
        "the spring is reset, not rescaled"
    );
    let c_t = damping(mat.eps_t, mat.k_t, 0.5);
    let f_t = c.force - Vec3::z() * c.force.z;
    assert!(c_t * 1e-4 < mat.mu_s * n_force);
    assert!(close(f_t.y, c_t * 1e-4) && f_t.x == 0.0, "{f_t}");
    // A fast slip: the dashpot is capped at μ_s·N, along the slip.
    let mut record = Record::default();
    let fast = Vec3::new(0.0, 10.0, 0.0);
    let c = dashpot_contact(&pair(fast, Vec3::zeros()), &mut record, DT, &mat);
    let f_t = c.force - Vec3::z() * c.force.z;
    assert_eq!(record.spring, Vec3::zeros());
    assert!(close(f_t.y, mat.mu_s * n_force) && f_t.x == 0.0, "{f_t}");
}

/// A contact of [`pair`] slipping at `u` under `rule`, with its shear spring at
/// `spring` before the step: the force, and the spring after.
fn slid(u: Vec3, spring: Vec3, rule: Sliding) -> (Vec3, Vec3) {
    let mut record = Record {
        spring,
        normal: Vec3::z(),
        ..Record::default()
    };
    let c = Dashpot {
        sliding: rule,
        ..pair(u, Vec3::zeros())
    };
    let f = dashpot_contact(&c, &mut record, DT, &material()).force;
    (f, record.spring)
}

#[test]
fn the_clamp_holds_a_sliding_force_at_mu_n_along_the_force_it_had() {
    let mat = material();
    let c_t = damping(mat.eps_t, mat.k_t, 0.5);
    let (u, spring) = (Vec3::new(0.3, 0.1, 0.0), Vec3::new(4e-3, -1e-3, 0.0));
    let (force, after) = slid(u, spring, Sliding::Clamp);
    let cap = mat.mu_s * force.z.abs();
    let stretched = spring + u * DT;
    let unlimited = stretched * mat.k_t + u * c_t;
    assert!(unlimited.norm() > cap, "it slides");
    let f_t = force - Vec3::z() * force.z;
    assert!(close(f_t.norm(), cap), "{f_t} against μ_s·N = {cap}");
    assert!((f_t.normalize() - unlimited.normalize()).norm() < 1e-14);
    // The spring is rescaled (LAMMPS's rule), so that with this step's dashpot it gives
    // that force: S ← (μ_s N/|F_t|)(S + C_t u_t/k_t) − C_t u_t/k_t.
    let lag = u * (c_t / mat.k_t);
    let expected = (stretched + lag) * (cap / unlimited.norm()) - lag;
    assert!(
        (after - expected).norm() < 1e-15,
        "{after} against {expected}"
    );
    assert!((after * mat.k_t + u * c_t - f_t).norm() < 1e-14 * cap);
}

#[test]
fn below_the_cap_the_reset_and_the_clamp_agree() {
    let (u, spring) = (Vec3::new(1e-3, 0.0, 0.0), Vec3::new(1e-5, 2e-5, 0.0));
    let reset = slid(u, spring, Sliding::Reset);
    assert_eq!(reset, slid(u, spring, Sliding::Clamp));
    assert_eq!(reset.1, spring + u * DT, "stretched, not limited");
}

#[test]
fn the_spring_turns_with_the_normal_and_the_other_way_for_a_wall() {
    let mat = Material {
        mu_s: 1e9,
        ..material()
    };
    // Last step's normal was tilted from +z by a small angle about x; the spring lay in
    // its tangent plane.
    let angle: f64 = 1e-2;
    let (sin, cos) = angle.sin_cos();
    let start = Record {
        spring: Vec3::new(0.0, cos, sin) * 1e-6,
        normal: Vec3::new(0.0, -sin, cos),
        ..Record::default()
    };
    let still = |wall: bool| {
        let mut record = start;
        let mut c = pair(Vec3::zeros(), Vec3::zeros());
        c.wall = wall;
        c.levers = if wall { (0.099, 0.0) } else { c.levers };
        dashpot_contact(&c, &mut record, DT, &mat);
        record.spring
    };
    // A pair carries the spring with the normal into the new tangent plane; a wall
    // turns it as far the other way (docs/pkdgrav-physics.md §1.3 step 2), with no
    // re-projection.
    let (p, w) = (still(false), still(true));
    assert!(close(p.y, 1e-6) && p.z.abs() < 1e-20, "{p}");
    let (sin2, cos2) = (2.0 * angle).sin_cos();
    assert!(close(w.y, 1e-6 * cos2) && close(w.z, 1e-6 * sin2), "{w}");
}

#[test]
fn the_mean_spin_about_the_normal_turns_the_springs() {
    let mat = Material {
        mu_s: 1e9,
        ..material()
    };
    let mut record = Record {
        spring: Vec3::new(1e-6, 0.0, 0.0),
        normal: Vec3::z(),
        ..Record::default()
    };
    let mut c = pair(Vec3::zeros(), Vec3::zeros());
    // The two spins sum to 2 rad/s about the normal: a turn by ½·dt·2 = dt.
    c.turn = Vec3::new(0.0, 0.0, 2.0);
    dashpot_contact(&c, &mut record, DT, &mat);
    assert!(close(record.spring.x, 1e-6 * DT.cos()));
    assert!(close(record.spring.y, 1e-6 * DT.sin()));
}

#[test]
fn rolling_and_twisting_hold_at_their_slider_limits() {
    let mat = material();
    let n_force = mat.k_n * 1e-3;
    let (beta, r) = (mat.beta_s, 0.05);
    // A rolling spring far past its limit: the torque is the limit, and this step's
    // increment is undone.
    let roll = Vec3::new(10.0, 0.0, 0.0);
    let mut record = Record {
        roll,
        twist: -10.0,
        normal: Vec3::z(),
        ..Record::default()
    };
    let spin = Vec3::new(3.0, 0.0, 5.0);
    let c = dashpot_contact(&pair(Vec3::zeros(), spin), &mut record, DT, &mat);
    assert_eq!(record.roll, roll);
    assert_eq!(record.twist, -10.0);
    let rolling = mat.mu_r * beta * r * n_force;
    // The twisting limit carries an extra μ_s (docs/pkdgrav-physics.md §1.4), with the
    // spring's sign.
    let twisting = mat.mu_t * beta * r * mat.mu_s * n_force;
    assert!(close(c.resistance.x, rolling), "{}", c.resistance);
    assert!(close(c.resistance.z, -twisting), "{}", c.resistance);
    // Particle 1 feels +M, its partner −M, besides the shear torques (none here).
    assert_eq!(c.torque, c.resistance);
    assert_eq!(c.partner_torque, -c.resistance);
}

#[test]
fn below_the_limits_rolling_and_twisting_are_spring_dashpots_scaled_by_beta_r_squared() {
    let mat = Material {
        beta_s: 0.5,
        mu_r: 1e9,
        mu_t: 1e9,
        ..material()
    };
    let mut record = Record::default();
    let spin = Vec3::new(2.0, 0.0, 4.0);
    let c = dashpot_contact(&pair(Vec3::zeros(), spin), &mut record, DT, &mat);
    let b = (0.5f64 * 0.05).powi(2);
    let (c_n, c_t) = (
        damping(mat.eps_n, mat.k_n, 0.5),
        damping(mat.eps_t, mat.k_t, 0.5),
    );
    assert_eq!(record.roll, Vec3::new(2.0 * DT, 0.0, 0.0));
    assert_eq!(record.twist, 4.0 * DT);
    assert!(close(
        c.resistance.x,
        mat.k_n * b * 2.0 * DT + c_n * b * 2.0
    ));
    assert!(close(
        c.resistance.z,
        2.0 * mat.k_t * b * 4.0 * DT + 2.0 * c_t * b * 4.0
    ));
}

#[test]
fn beta_s_defaults_to_pkdgravs_half_and_walls_fall_back_to_it() {
    assert_eq!(BETA_S_DEFAULT, 0.5);
    // A run from a .par file that leaves dBetaS out takes pkdgrav's default; one that
    // gives it takes its value.
    let floor = scene("wall type plane origin 0 0 0\n");
    let particles = Some(vec![ball([0.0, 0.0, 0.3], [0.0, 0.0, -2.0])]);
    let par = Params {
        dt: Some(1e-5),
        k_n: Some(1e5),
        ..Params::default()
    };
    let run = resolve(&Flags::default(), Some(&par), &floor, particles.clone()).unwrap();
    assert_eq!(run.settings.material.beta_s, BETA_S_DEFAULT);
    assert!(!run.settings.contact_radius);
    let par = read_par("dKn = 1e5\ndBetaS = 0.8\nbUseContactRadius = 1\n").unwrap();
    assert_eq!(par.beta_s, Some(0.8));
    assert_eq!(par.contact_radius, Some(true));
    let run = resolve(&Flags::default(), Some(&par), &floor, particles).unwrap();
    assert_eq!(run.settings.material.beta_s, 0.8);
    assert!(run.settings.contact_radius);
    // A wall's beta_s: −1 (the default) is the particles' value; its own otherwise.
    let particles = material();
    let wall = |text: &str| scene(text)[0].material.against(&particles).beta_s;
    assert_eq!(wall("wall type plane origin 0 0 0\n"), 1.0);
    assert_eq!(wall("wall type plane origin 0 0 0 beta_s 0.25\n"), 0.25);
}

/// Builds without `DEM_ROTATION_DASHPOT` (docs/pkdgrav-physics.md §1.6): rolling is
/// μ_r·N·(r̂ × n̂) times each particle's lever, r = l₁ w₁ × n̂ − l₂ w₂ × n̂, capped so
/// that it cannot reverse a spin across the normal within the step; twisting
/// μ_t·N·a·sign(ω_t)·n̂, with no twisting at all when the radius a is 0 (no
/// `bUseContactRadius`); nothing is kept in the record's rolling spring or twist angle.
#[test]
fn constant_torques_oppose_rolling_and_twisting_with_the_levers_given() {
    use walls_sim::contact::ssdem::ConstantTorque;
    let mat = material();
    let w1 = Vec3::new(0.0, 5e3, 3.0);
    let torque = |levers: (f64, f64), twist_radius: f64| {
        let mut c = pair(Vec3::zeros(), -w1);
        c.constant_torque = Some(ConstantTorque {
            spins: (w1, Vec3::zeros()),
            roll_levers: levers,
            twist_radius,
            inertias: (1.0, 1.0),
        });
        let mut record = Record::default();
        let out = dashpot_contact(&c, &mut record, DT, &mat);
        assert_eq!((record.roll, record.twist), (Vec3::zeros(), 0.0));
        out
    };
    let n_force = mat.k_n * 1e-3;
    let out = torque((0.05, 0.05), 0.0);
    // w₁ × n̂ points along +x: the torque is μ_r N l (x̂ × ẑ) = −μ_r N l ŷ on 1, +ŷ on 2.
    assert!(
        close(out.resistance.y, -mat.mu_r * n_force * 0.05),
        "{out:?}"
    );
    assert_eq!((out.resistance.x, out.resistance.z), (0.0, 0.0));
    let legacy = torque((0.0995, 0.03), 0.0);
    assert!(close(legacy.resistance.y, -mat.mu_r * n_force * 0.0995));
    assert!(close(legacy.partner_torque.y, mat.mu_r * n_force * 0.03,));
    // Twisting with a contact radius: against particle 1's spin about n̂.
    let twisting = torque((0.05, 0.05), 0.01);
    assert!(close(twisting.resistance.z, -mat.mu_t * n_force * 0.01));
    assert!(close(twisting.partner_torque.z, mat.mu_t * n_force * 0.01));
    // A tiny spin: the rolling torque stops it against its partner and no more
    // (reduced inertia · |w⊥|/dt).
    let mut c = pair(Vec3::zeros(), Vec3::zeros());
    let slow = Vec3::new(0.0, 1e-6, 0.0);
    c.spin = -slow;
    c.constant_torque = Some(ConstantTorque {
        spins: (slow, Vec3::zeros()),
        roll_levers: (0.05, 0.05),
        twist_radius: 0.0,
        inertias: (1.0, 1.0),
    });
    let out = dashpot_contact(&c, &mut Record::default(), DT, &mat);
    assert!(close(out.resistance.y, -0.5e-6 / DT), "{out:?}");
}

proptest::proptest! {
    /// The series for the small angles a contact turns by agrees with the library's
    /// sine and cosine to an ulp or two, and is the library's beyond 2⁻⁷.
    #[test]
    fn small_angles_turn_as_the_library_turns(x in -0.02..0.02f64) {
        let (sin, cos) = walls_sim::contact::ssdem::small_sin_cos(x);
        let (want_sin, want_cos) = x.sin_cos();
        proptest::prop_assert!((sin - want_sin).abs() <= 2.0 * f64::EPSILON * want_sin.abs(), "sin {x}: {sin} against {want_sin}");
        proptest::prop_assert!((cos - want_cos).abs() <= 2.0 * f64::EPSILON, "cos {x}: {cos} against {want_cos}");
    }
}
