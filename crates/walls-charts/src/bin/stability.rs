//! Where the contact methods fail, as charts (docs/stability.md): each failure mode that
//! comes by degrees has its points here.
//!
//! - `stability_step`: a particle (m = 1, R = 0.1) meets a plane at speed 1 with k_n for
//!   a 1 % overlap, at timesteps from 10⁻⁴ to 50 times the contact time (its travel per
//!   step from 3·10⁻⁵ to 16 radii): the rebound error |e/ε − 1| (ε = 0.5) for SSDEM and
//!   HSDEM, and whether the run warned. Past π/2 steps per contact the soft contact gains
//!   energy; past two radii a step it jumps over the wall (drawn at error 1: no rebound).
//! - `stability_overlap`: the same particle against a fixed k_n = 10⁴ at impact speeds
//!   from 0.1 to 10: the peak overlap as a fraction of the radius, against pkdgrav's
//!   3 %, 15 % and 50 % levels. Above 50 % the run stops, as pkdgrav aborts.

use nalgebra::Vector3;
use walls_charts::{Chart, Mark, Series, out_dir, write};
use walls_geometry::Particle;
use walls_geometry::Wall;
use walls_sim::contact::ssdem::damping;
use walls_sim::run::{ContactModel, ParticleMaterial, Settings, run, run_observed};

type Vec3 = Vector3<f64>;

const RADIUS: f64 = 0.1;

fn plane() -> Vec<Wall> {
    walls_test_support::scene("wall type plane\n")
}

fn ball(z: f64, v: f64) -> Particle {
    Particle {
        mass: 1.0,
        radius: RADIUS,
        pos: Vec3::new(0.0, 0.0, z),
        vel: Vec3::new(0.0, 0.0, -v),
        spin: Vec3::zeros(),
        color: 3,
        index: 0,
    }
}

fn settings(method: ContactModel, k_n: f64, dt: f64, t_end: f64) -> Settings {
    Settings {
        build: walls_sim::build::Build::default_for(method),
        ..Settings::new(
            dt,
            t_end,
            ParticleMaterial {
                eps_n: 0.5,
                ..walls_sim::run::defaults::default_material(k_n)
            },
        )
    }
}

fn main() -> std::io::Result<()> {
    let dir = out_dir();
    // 1 % overlap at speed 1: k = m·(v/(0.01 R))².
    let k_n = (1.0f64 / (0.01 * RADIUS)).powi(2);
    let c = damping(0.5, k_n, 1.0);
    let t_c = std::f64::consts::PI / (k_n - c * c / 4.0).sqrt();
    let mut soft = Vec::new();
    let mut soft_warned = Vec::new();
    let mut hard = Vec::new();
    println!("travel/R  steps/contact  SSDEM error  warned  HSDEM error");
    for k in 0..=24 {
        // Steps per contact from 10⁴ down to 0.02, geometrically.
        let per_contact = 10f64.powf(4.0 - f64::from(k) * 5.7 / 24.0);
        let dt = t_c / per_contact;
        let travel = dt / RADIUS;
        // Start half a step's travel plus a little above contact, so that the first
        // step does not land inside the wall by construction.
        let z = RADIUS + 0.37 * dt;
        let t_end = (3.0 * t_c).max(4.0 * dt) + z;
        let error = |method: ContactModel| {
            let out = run(
                &plane(),
                vec![ball(z, 1.0)],
                &settings(method, k_n, dt, t_end),
            );
            let v = out.particles[0].particle.vel.z;
            let e = if v > 0.0 { v } else { 0.0 };
            ((e / 0.5 - 1.0).abs().max(1e-16), !out.warnings.is_empty())
        };
        let (e_soft, warned) = error(ContactModel::Ssdem);
        let (e_hard, _) = error(ContactModel::Hsdem);
        println!("{travel:9.2e} {per_contact:14.3e} {e_soft:12.3e} {warned:7} {e_hard:12.3e}");
        soft.push((travel, e_soft));
        if warned {
            soft_warned.push((travel, e_soft));
        }
        hard.push((travel, e_hard));
    }
    write(
        &dir,
        &Chart {
            name: "stability_step".into(),
            title: "Rebound error against travel per step (1 % overlap)".into(),
            x_label: "travel per step, radii (steps per contact = 0.031 / travel)".into(),
            y_label: "rebound error |e/ε − 1|, ε = 0.5 (1: no rebound)".into(),
            log_x: true,
            log_y: true,
        },
        &[
            Series::new("SSDEM (leapfrog)", soft, Mark::Line),
            Series::new("SSDEM: the run warned", soft_warned, Mark::Dots),
            Series::new("HSDEM", hard, Mark::Line),
        ],
    )?;
    // Peak overlap against impact speed at a fixed spring.
    let k_n = 1e4;
    let c = damping(0.5, k_n, 1.0);
    let t_c = std::f64::consts::PI / (k_n - c * c / 4.0).sqrt();
    let dt = t_c / 141.0;
    let mut peaks = Vec::new();
    let mut stopped = Vec::new();
    println!("speed  peak overlap/R  stopped");
    for k in 0..=20 {
        let v = 10f64.powf(-1.0 + f64::from(k) * 2.0 / 20.0);
        let mut deepest = 0.0f64;
        let out = run_observed(
            &plane(),
            vec![ball(RADIUS, v)],
            &settings(ContactModel::Ssdem, k_n, dt, 3.0 * t_c),
            &mut |_, _, snapshot| {
                deepest = deepest.max(RADIUS - snapshot.look().0[0].particle.pos.z)
            },
        );
        let stop = out
            .warnings
            .iter()
            .any(|w| matches!(w, walls_sim::run::Warning::OverlapStop { .. }));
        println!("{v:6.3} {:14.4} {stop}", deepest / RADIUS);
        peaks.push((v, deepest / RADIUS));
        if stop {
            stopped.push((v, deepest / RADIUS));
        }
    }
    let level = |f: f64| vec![(0.1, f), (10.0, f)];
    write(
        &dir,
        &Chart {
            name: "stability_overlap".into(),
            title: "Peak overlap against impact speed (k_n = 10⁴, m = 1, R = 0.1)".into(),
            x_label: "impact speed".into(),
            y_label: "peak overlap / radius".into(),
            log_x: true,
            log_y: true,
        },
        &[
            Series::new("SSDEM peak overlap", peaks, Mark::Line),
            Series::new("the run stopped (above 50 %)", stopped, Mark::Dots),
            Series::new(
                "pkdgrav's levels: 3 %, 15 %, 50 %",
                level(0.03),
                Mark::Dashed,
            ),
            Series::new("15 %", level(0.15), Mark::Dashed),
            Series::new("50 %", level(0.5), Mark::Dashed),
        ],
    )
}
