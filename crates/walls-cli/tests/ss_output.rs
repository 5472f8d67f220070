//! `walls-sim run --par params.par --out DIR --ss-output` on one of pkdgrav's golden run
//! directories: the `.ss` files it writes are pkdgrav's, named as pkdgrav names them
//! (`achOutName`.NNNNNN with this scene's `nDigits = 6`, at every `iOutInterval` and at
//! `nSteps`, none at the start), with the accumulated time in the header, and hold what
//! pkdgrav wrote to 1e-9 of the scene's scales.

use std::collections::BTreeSet;
use std::path::Path;
use std::process::Command;
use walls_sim::io::particles::read_ss;

/// The golden scene's folder.
fn scene(name: &str) -> std::path::PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../walls-sim/tests/golden")
        .join(name)
}

#[test]
fn ss_outputs_are_pkdgrav_s() {
    let dir = tempfile::tempdir().unwrap();
    for file in ["params.par", "walls.dat", "particles.ss"] {
        std::fs::copy(scene("pair_oblique").join(file), dir.path().join(file)).unwrap();
    }
    let out = Command::new(env!("CARGO_BIN_EXE_walls-sim"))
        .current_dir(dir.path())
        .args(["run", "--par", "params.par", "--out", "out", "--ss-output"])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let written: BTreeSet<String> = std::fs::read_dir(dir.path().join("out"))
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.starts_with("ss."))
        .collect();
    let expected_csv = std::fs::read_to_string(scene("pair_oblique").join("expected.csv")).unwrap();
    let rows: Vec<Vec<f64>> = expected_csv
        .lines()
        .skip(1)
        .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
        .collect();
    let steps: BTreeSet<u64> = rows.iter().map(|r| r[0] as u64).collect();
    assert_eq!(
        written,
        steps
            .iter()
            .map(|s| format!("ss.{s:06}"))
            .collect::<BTreeSet<_>>()
    );
    // Scales: the largest position, speed and spin pkdgrav wrote (the golden README's
    // L, V, W are at least these).
    let largest = |cols: std::ops::Range<usize>| {
        rows.iter()
            .flat_map(|r| r[cols.clone()].iter().map(|x| x.abs()))
            .fold(0.0, f64::max)
    };
    let scales = [largest(3..6), largest(6..9), largest(9..12)];
    for step in steps {
        let bytes = std::fs::read(dir.path().join("out").join(format!("ss.{step:06}"))).unwrap();
        let (time, read) = read_ss(&bytes).unwrap();
        let particles = read.particles;
        let at_step: Vec<&Vec<f64>> = rows.iter().filter(|r| r[0] as u64 == step).collect();
        assert_eq!(time, at_step[0][1], "the header time after step {step}");
        assert_eq!(particles.len(), at_step.len());
        for row in at_step {
            let p = &particles[row[2] as usize];
            let ours = [p.pos, p.vel, p.spin];
            for (k, (v, scale)) in ours.iter().zip(scales).enumerate() {
                for axis in 0..3 {
                    let theirs = row[3 + 3 * k + axis];
                    assert!(
                        (v[axis] - theirs).abs() <= 1e-9 * scale,
                        "step {step}, particle {}, column {}: {} vs {theirs}",
                        row[2],
                        3 + 3 * k + axis,
                        v[axis]
                    );
                }
            }
        }
    }
}
