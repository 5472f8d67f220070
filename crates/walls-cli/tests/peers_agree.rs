//! walls-sim's leapfrog against LAMMPS on the peer benchmark's scenes with friction off
//! (docs/performance.md, "Against LAMMPS and LIGGGHTS"): 27 spheres dropped into the box
//! (2,000 steps) and on the oscillating floor (8,000 steps), run with `--integrator
//! leapfrog --oscillation exact`, end where LAMMPS's `gran/hooke/history` and
//! `wall/gran` left them, to round-off. LAMMPS's final states are stored beside the
//! inputs (`tests/data/peers-agree/<scene>/`, written by `scripts/bench-peers check
//! --keep`; its README says how), so that CI, which has no LAMMPS, still catches a
//! change that moves walls-sim away from the peers (the first steps' loads without
//! gravity, found only by running `check`, moved them in the fourth digit).

use std::path::{Path, PathBuf};
use std::process::Command;

/// Position and velocity of one particle.
type Motion = [f64; 6];

fn scene_dir(scene: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/peers-agree")
        .join(scene)
}

/// The particles of a LAMMPS dump's last snapshot (`id x y z vx vy vz`), in id order.
fn lammps_final(path: &Path) -> Vec<Motion> {
    let text = std::fs::read_to_string(path).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    let start = lines
        .iter()
        .rposition(|l| l.starts_with("ITEM: ATOMS"))
        .expect("a snapshot");
    assert_eq!(lines[start], "ITEM: ATOMS id x y z vx vy vz");
    let mut rows: Vec<(u32, Motion)> = lines[start + 1..]
        .iter()
        .take_while(|l| !l.starts_with("ITEM:"))
        .map(|l| {
            let fields: Vec<&str> = l.split_whitespace().collect();
            assert_eq!(fields.len(), 7, "{path:?}: {l}");
            let mut motion = [0.0; 6];
            for (m, f) in motion.iter_mut().zip(&fields[1..]) {
                *m = f.parse().unwrap();
            }
            (fields[0].parse().unwrap(), motion)
        })
        .collect();
    rows.sort_by_key(|r| r.0);
    rows.into_iter().map(|r| r.1).collect()
}

/// walls-sim's final particles on the scene's own inputs, with the leapfrog and the
/// exact oscillation the peers use.
fn walls_sim_final(dir: &Path) -> Vec<Motion> {
    let args = std::fs::read_to_string(dir.join("args")).unwrap();
    let run = Command::new(env!("CARGO_BIN_EXE_walls-sim"))
        .args(args.split_whitespace())
        .args([
            "--json",
            "--integrator",
            "leapfrog",
            "--oscillation",
            "exact",
        ])
        .current_dir(dir)
        .output()
        .unwrap();
    assert_eq!(run.status.code(), Some(0), "{run:?}");
    let report: serde_json::Value = serde_json::from_slice(&run.stdout).unwrap();
    let particles = report["particles"].as_array().unwrap();
    particles
        .iter()
        .map(|p| {
            let v = |key: &str, k: usize| p[key][k].as_f64().unwrap();
            [
                v("pos", 0),
                v("pos", 1),
                v("pos", 2),
                v("vel", 0),
                v("vel", 1),
                v("vel", 2),
            ]
        })
        .collect()
}

/// The largest distance between a particle's two final positions, in radii (1 mm), and
/// the relative difference of the two kinetic energies (the spheres are of one mass).
fn differences(a: &[Motion], b: &[Motion]) -> (f64, f64) {
    const RADIUS: f64 = 0.001;
    let distance = |p: &Motion, q: &Motion| {
        ((p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2) + (p[2] - q[2]).powi(2)).sqrt()
    };
    let worst = a
        .iter()
        .zip(b)
        .map(|(p, q)| distance(p, q) / RADIUS)
        .fold(0.0, f64::max);
    let energy = |s: &[Motion]| {
        s.iter()
            .map(|p| p[3] * p[3] + p[4] * p[4] + p[5] * p[5])
            .sum::<f64>()
    };
    let (ea, eb) = (energy(a), energy(b));
    (worst, (ea - eb).abs() / ea.max(eb))
}

/// walls-sim's leapfrog ends within `position` radii of LAMMPS's every particle, and
/// with its kinetic energy within `energy` of LAMMPS's, relatively.
fn agrees_with_lammps(scene: &str, position: f64, energy: f64) {
    let dir = scene_dir(scene);
    let lammps = lammps_final(&dir.join("lammps-final.dump"));
    let walls_sim = walls_sim_final(&dir);
    assert_eq!(lammps.len(), 27);
    assert_eq!(walls_sim.len(), 27);
    let (worst, energy_difference) = differences(&walls_sim, &lammps);
    assert!(
        worst <= position && energy_difference <= energy,
        "{scene}: positions differ by up to {worst:e} radii (at most {position:e}), kinetic \
         energies by {energy_difference:e} (at most {energy:e})"
    );
}

#[test]
fn the_leapfrog_ends_the_drop_where_lammps_does() {
    // Measured: 1.0e-14 radii, energies 5e-15 apart.
    agrees_with_lammps("drop", 1e-12, 1e-12);
}

#[test]
fn the_leapfrog_ends_the_oscillating_floor_where_lammps_does() {
    // Measured: 2.7e-11 radii, energies 5.5e-12 apart (8,000 steps of a floor that
    // shakes the pile; round-off grows with it).
    agrees_with_lammps("oscillating", 1e-9, 1e-9);
}
