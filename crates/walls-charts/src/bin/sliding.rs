//! Sliding friction under pkdgrav's shear-spring reset and under the Coulomb clamp
//! (`walls_sim::contact::ssdem::Sliding`, docs/accuracy.md "Sliding friction"): a sphere
//! of radius 1 mm and 2500 kg/m³ resting on a plane under g = 9.81 m/s², k_n = 1000 N/m,
//! k_t = 2/7 k_n, ε_n = 0.5, μ_s = 0.5, dt = 5·10⁻⁶ s, given 0.01, 0.1 or 1 m/s along
//! the plane, with ε_t = 0.5 and with pkdgrav's default ε_t = 1 (no tangential dashpot).
//!
//! Coulomb friction decelerates the centre at μ_s g until the sphere rolls at 5/7 of its
//! speed, after 2v₀/(7μ_s g). Each chart draws v/v₀ against t·μ_s g/v₀ (so that the
//! three speeds share the axes) with that line dashed; the table printed gives each
//! run's deceleration while it slides: the least-squares slope of v(t) up to the first
//! step at which the contact point's slip stops being forward.
//!
//! Charts: `sliding` (ε_t = 0.5) and `sliding_no_dashpot` (ε_t = 1).

use nalgebra::Vector3;
use walls_charts::{Chart, Mark, Series, out_dir, write};
use walls_geometry::{BETA_S_DEFAULT, Material, Particle};
use walls_sim::contact::ssdem::Sliding;
use walls_sim::run::{Settings, run_observed};
use walls_test_support::scene;

type Vec3 = Vector3<f64>;

const G: f64 = 9.81;
const MU_S: f64 = 0.5;
const RADIUS: f64 = 1e-3;

/// One run: the time, the centre's speed and the contact point's slip at each step.
fn run_slide(v0: f64, eps_t: f64, rule: Sliding) -> Vec<[f64; 3]> {
    let k_n = 1000.0;
    let material = Material {
        eps_n: 0.5,
        eps_t,
        k_n,
        k_t: k_n * 2.0 / 7.0,
        mu_s: MU_S,
        mu_r: 0.0,
        mu_t: 0.0,
        beta_s: BETA_S_DEFAULT,
    };
    let mass = 2500.0 * 4.0 / 3.0 * std::f64::consts::PI * RADIUS.powi(3);
    // Until the time Coulomb friction takes to bring it to rolling, and as long again.
    let t_end = 4.0 * v0 / (7.0 * MU_S * G);
    let mut settings = Settings::new(5e-6, t_end, material);
    settings.gravity = Vec3::new(0.0, 0.0, -G);
    settings.sliding = rule;
    let sphere = Particle {
        pos: Vec3::new(0.0, 0.0, RADIUS - mass * G / k_n),
        vel: Vec3::new(v0, 0.0, 0.0),
        mass,
        ..Particle::at_rest(RADIUS, Vec3::zeros(), 0)
    };
    let floor = scene("wall type plane origin 0 0 0 orient 0 0 1\n");
    let mut steps = vec![[0.0, v0, v0]];
    run_observed(&floor, vec![sphere], &settings, &mut |_, t, snapshot| {
        let p = &snapshot.look().0[0].particle;
        steps.push([t, p.vel.x, p.vel.x - RADIUS * p.spin.y]);
    });
    steps
}

/// The least-squares slope of the speed against time, negated, over the steps before
/// the slip stops being forward.
fn sliding_deceleration(steps: &[[f64; 3]]) -> f64 {
    let slides: Vec<&[f64; 3]> = steps.iter().take_while(|s| s[2] > 0.0).collect();
    let count = slides.len() as f64;
    let mean = |k: usize| slides.iter().map(|s| s[k]).sum::<f64>() / count;
    let (t0, v0) = (mean(0), mean(1));
    let covariance: f64 = slides.iter().map(|s| (s[0] - t0) * (s[1] - v0)).sum();
    let variance: f64 = slides.iter().map(|s| (s[0] - t0).powi(2)).sum();
    -covariance / variance
}

fn main() -> std::io::Result<()> {
    let mu_g = MU_S * G;
    println!("ε_t | v₀ (m/s) | rule | deceleration while sliding (m/s²) | ÷ μ_s g");
    for (eps_t, name, title) in [
        (0.5, "sliding", "ε_t = 0.5"),
        (
            1.0,
            "sliding_no_dashpot",
            "ε_t = 1 (pkdgrav's default: no tangential dashpot)",
        ),
    ] {
        let mut series = Vec::new();
        for rule in [Sliding::Reset, Sliding::Clamp] {
            for v0 in [0.01, 0.1, 1.0] {
                let steps = run_slide(v0, eps_t, rule);
                let a = sliding_deceleration(&steps);
                println!("{eps_t} | {v0} | {rule:?} | {a:.4} | {:.4}", a / mu_g);
                // About 60 points a series, so that the files stay small.
                let scale = mu_g / v0;
                let points = steps
                    .iter()
                    .step_by((steps.len() / 60).max(1))
                    .map(|s| (s[0] * scale, s[1] / v0))
                    .collect();
                let label = match rule {
                    Sliding::Reset => "pkdgrav's reset",
                    Sliding::Clamp => "Coulomb clamp",
                };
                series.push(Series::new(
                    format!("{label}, v₀ = {v0} m/s"),
                    points,
                    Mark::Line,
                ));
            }
        }
        series.push(Series::new(
            "μ_s g, then rolling at 5/7 v₀",
            vec![(0.0, 1.0), (2.0 / 7.0, 5.0 / 7.0), (4.0 / 7.0, 5.0 / 7.0)],
            Mark::Dashed,
        ));
        let chart = Chart {
            name: name.into(),
            title: format!("A sphere sliding on a plane, μ_s = 0.5, {title}"),
            x_label: "t·μ_s g / v₀".into(),
            y_label: "v / v₀".into(),
            log_x: false,
            log_y: false,
        };
        write(&out_dir(), &chart, &series)?;
    }
    Ok(())
}
