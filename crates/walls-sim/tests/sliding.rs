//! Sliding friction in a whole run, pkdgrav's shear-spring reset against the Coulomb
//! clamp (`Settings::sliding`, docs/accuracy.md "Sliding friction"): a sphere of radius
//! 1 mm and 2500 kg/m³ resting on a plane under g = 9.81 m/s², k_n = 1000 N/m,
//! k_t = 2/7 k_n, μ_s = 0.5, given a speed along the plane, dt = 5·10⁻⁶ s. While it
//! slides, Coulomb friction decelerates its centre at μ_s g = 4.905 m/s² (and spins it
//! up until it rolls at 5/7 of its speed). The deceleration measured is the
//! least-squares slope of v(t) from the start to the end of the slide, the first step
//! at which the contact point's slip is no longer forward.

use nalgebra::Vector3;
use walls_geometry::{BETA_S_DEFAULT, Material, Particle};
use walls_sim::contact::ssdem::Sliding;
use walls_sim::run::{Settings, run_observed};
use walls_test_support::scene;

type Vec3 = Vector3<f64>;

const G: f64 = 9.81;
const R: f64 = 1e-3;
const MU_G: f64 = 0.5 * G;

/// The time, the speed of the sphere's centre and the slip of its contact point, at the
/// start and after each step of a slide started at `v0` with tangential restitution `eps_t` under `rule`, for long
/// enough to roll.
fn slide(v0: f64, eps_t: f64, rule: Sliding) -> Vec<(f64, f64, f64)> {
    let k_n = 1000.0;
    let mat = Material {
        eps_n: 0.5,
        eps_t,
        k_n,
        k_t: 2.0 / 7.0 * k_n,
        mu_s: 0.5,
        mu_r: 0.0,
        mu_t: 0.0,
        beta_s: BETA_S_DEFAULT,
    };
    let m = 2500.0 * 4.0 / 3.0 * std::f64::consts::PI * R.powi(3);
    // Twice the time Coulomb friction takes to bring it to rolling.
    let rolling = 2.0 / 7.0 * v0 / MU_G;
    let mut settings = Settings::new(5e-6, 2.0 * rolling, mat);
    settings.gravity = Vec3::new(0.0, 0.0, -G);
    settings.sliding = rule;
    // Resting at the overlap where the spring carries its weight.
    let sphere = Particle {
        mass: m,
        radius: R,
        pos: Vec3::new(0.0, 0.0, R - m * G / k_n),
        vel: Vec3::new(v0, 0.0, 0.0),
        spin: Vec3::zeros(),
        color: 3,
        index: 0,
    };
    let walls = scene("wall type plane origin 0 0 0 orient 0 0 1\n");
    let mut rows = vec![(0.0, v0, v0)];
    let out = run_observed(&walls, vec![sphere], &settings, &mut |_, t, snapshot| {
        let (states, _) = snapshot.look();
        let p = &states[0].particle;
        // The contact point, −R ẑ from the centre, moves at v + ω × (−R ẑ).
        rows.push((t, p.vel.x, p.vel.x - p.spin.y * R));
    });
    assert_eq!(out.stopped, None);
    assert!(out.warnings.is_empty(), "{:?}", out.warnings);
    rows
}

/// The deceleration of the centre while it slides: the least-squares slope of v(t),
/// negated, from the start to the step before the slip first stops being forward.
fn deceleration(rows: &[(f64, f64, f64)]) -> f64 {
    let end = rows
        .iter()
        .position(|&(_, _, slip)| slip <= 0.0)
        .unwrap_or(rows.len());
    let sliding = &rows[..end];
    let n = sliding.len() as f64;
    let t_mean = sliding.iter().map(|r| r.0).sum::<f64>() / n;
    let v_mean = sliding.iter().map(|r| r.1).sum::<f64>() / n;
    let (cov, var) = sliding.iter().fold((0.0, 0.0), |(c, v), r| {
        (
            c + (r.0 - t_mean) * (r.1 - v_mean),
            v + (r.0 - t_mean).powi(2),
        )
    });
    -cov / var
}

fn assert_near(measured: f64, expected: f64, tolerance: f64) {
    assert!(
        (measured - expected).abs() <= tolerance,
        "measured {measured}, expected {expected} ± {tolerance}"
    );
}

#[test]
fn at_one_centimetre_a_second_the_reset_decelerates_less_than_the_clamp() {
    // ε_t = 0.5: the dashpot C_t·u alone exceeds μ_s N until the slip falls below
    // μ_s N/C_t = 2.2 mm/s, so the reset slides at the cap until then and weaker after.
    let reset = deceleration(&slide(0.01, 0.5, Sliding::Reset));
    let clamp = deceleration(&slide(0.01, 0.5, Sliding::Clamp));
    assert_near(reset, 4.8203, 5e-5);
    assert_near(clamp, 4.8839, 5e-5);
    assert!((clamp / MU_G - 1.0).abs() < 0.005, "clamp {clamp}");
}

#[test]
fn fast_slides_decelerate_at_mu_g_under_both_rules_with_a_dashpot() {
    for rule in [Sliding::Reset, Sliding::Clamp] {
        for v0 in [0.1, 1.0] {
            let a = deceleration(&slide(v0, 0.5, rule));
            assert!((a / MU_G - 1.0).abs() < 0.001, "{rule:?} at {v0}: {a}");
        }
    }
}

#[test]
fn without_a_tangential_dashpot_the_reset_loses_the_friction() {
    // ε_t = 1 (pkdgrav's default): C_t = 0. After a reset the spring rebuilds from zero;
    // at 1 cm/s it takes four steps to pass the cap, so the mean force is about half
    // of it; at 10 cm/s one step's stretch k_t·u·dt already exceeds μ_s N, so the spring
    // is reset at every step and the force is always zero: the sphere never slows.
    let slow = deceleration(&slide(0.01, 1.0, Sliding::Reset));
    assert_near(slow, 2.2814, 5e-5);
    let fast = slide(0.1, 1.0, Sliding::Reset);
    let slowest = fast.iter().map(|r| r.1).fold(f64::INFINITY, f64::min);
    assert!(
        (slowest / 0.1 - 1.0).abs() < 1e-12,
        "never slows: {slowest}"
    );
    // The clamp keeps μ_s g.
    for v0 in [0.01, 0.1] {
        let a = deceleration(&slide(v0, 1.0, Sliding::Clamp));
        assert!((a / MU_G - 1.0).abs() < 0.005, "clamp at {v0}: {a}");
    }
}
