//! The shipped examples teach what they say: every walls file in `examples/` is
//! lint-clean and formatted except `mistakes.walls`, whose mistakes are found; the drum is
//! a run directory pkdgrav takes, and runs as a drum; the hopper mesh makes clean walls;
//! each example is used by the README or a page of `docs/`.

use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn examples() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples")
}

fn run(bin: &str, args: &[&str]) -> Output {
    Command::new(bin)
        .args(args)
        .current_dir(examples())
        .output()
        .unwrap()
}

/// The walls files under `examples/`, by their paths from it: `*.walls`, and the `.dat`
/// walls files of run directories.
fn walls_files() -> Vec<String> {
    let mut found = Vec::new();
    let mut folders = vec![examples()];
    while let Some(folder) = folders.pop() {
        for entry in std::fs::read_dir(&folder).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                folders.push(path);
            } else if path.extension().is_some_and(|e| e == "walls" || e == "dat") {
                let name = path.strip_prefix(examples()).unwrap();
                found.push(name.to_str().unwrap().to_string());
            }
        }
    }
    found.sort();
    found
}

#[test]
fn every_example_is_clean_and_formatted_but_the_mistakes() {
    let files = walls_files();
    assert!(files.len() >= 4, "{files:?}");
    for file in &files {
        let lint = run(
            env!("CARGO_BIN_EXE_walls-lint"),
            &["--format", "json", file],
        );
        let report: Value = serde_json::from_slice(&lint.stdout).unwrap();
        let found = report["files"][0]["diagnostics"].as_array().unwrap().len();
        let check = run(env!("CARGO_BIN_EXE_walls-fmt"), &["--check", file]);
        if file == "mistakes.walls" {
            assert_eq!(lint.status.code(), Some(1), "{file}");
            assert!(found >= 8, "{file}: {found} findings");
        } else {
            assert_eq!(
                (lint.status.code(), found),
                (Some(0), 0),
                "{file}: {}",
                String::from_utf8_lossy(&lint.stdout)
            );
            assert_eq!(
                check.status.code(),
                Some(0),
                "{file} is not formatted: {}",
                String::from_utf8_lossy(&check.stdout)
            );
        }
    }
}

#[test]
fn the_drum_is_a_run_directory_pkdgrav_takes() {
    let lint = run(
        env!("CARGO_BIN_EXE_walls-lint"),
        &["--format", "json", "drum"],
    );
    assert_eq!(lint.status.code(), Some(0));
    let report: Value = serde_json::from_slice(&lint.stdout).unwrap();
    let files: Vec<&str> = (report["files"].as_array().unwrap().iter())
        .map(|f| f["path"].as_str().unwrap())
        .collect();
    assert_eq!(files, ["drum/ss.par", "drum/walls.dat"]);
    for file in report["files"].as_array().unwrap() {
        assert_eq!(file["diagnostics"], serde_json::json!([]), "{file}");
    }
}

#[test]
fn the_drum_turns_its_beads_up_its_side() {
    // 0.4 s of the 2: 40,000 steps of 10 µs.
    let out = run(
        env!("CARGO_BIN_EXE_walls-sim"),
        &[
            "run",
            "--par",
            "drum/ss.par",
            "--t-end",
            "7.96408e-8",
            "--json",
        ],
    );
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    // Nothing to warn of: not the keys a DEM build needs at one value (`iOutcomes = 0`),
    // not a bead the spinning side speeds up.
    let said = String::from_utf8_lossy(&out.stderr);
    assert!(!said.contains("warning"), "{said}");
    let result: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(result["steps"], 40_000);
    assert_eq!(result["warnings"], serde_json::json!([]));
    for kind in ["pairs", "walls"] {
        assert_eq!(
            result["overlaps"][kind],
            serde_json::json!({"minor": 0, "major": 0, "error": 0}),
            "{kind}"
        );
    }
    // Centimetres, from the walls file's lengthunit.
    let cm = 6.68458e-14;
    let beads: Vec<[f64; 3]> = (result["particles"].as_array().unwrap().iter())
        .map(|p| {
            let at = |k: usize| p["pos"][k].as_f64().unwrap() / cm;
            [at(0), at(1), at(2)]
        })
        .collect();
    assert_eq!(beads.len(), 105);
    for [x, y, z] in &beads {
        // Inside the drum: 5 cm from its axis and 1.6 cm along it, less a bead's radius,
        // no deeper into the drum than dMinorFrac (3 % of the radius).
        assert!(x.hypot(*z) < 4.515 && y.abs() < 1.115, "{x} {y} {z}");
    }
    // The drum turns at +2 rad/s about y: its bottom moves towards −x, and carries the
    // bed up that side (the bed's centre starts at x = 0.00 cm).
    let mean_x = beads.iter().map(|b| b[0]).sum::<f64>() / beads.len() as f64;
    assert!(mean_x < -0.5, "{mean_x}");
}

#[test]
fn every_example_is_used_by_the_readme_or_a_doc() {
    let root = examples().join("..");
    let mut pages = std::fs::read_to_string(root.join("README.md")).unwrap();
    for entry in std::fs::read_dir(root.join("docs")).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_some_and(|e| e == "md") {
            pages.push_str(&std::fs::read_to_string(path).unwrap());
        }
    }
    for entry in std::fs::read_dir(examples()).unwrap() {
        let name = entry.unwrap().file_name().into_string().unwrap();
        if name != "README.md" {
            assert!(
                pages.contains(&format!("examples/{name}")),
                "examples/{name} is used by neither README.md nor docs/"
            );
        }
    }
}

#[test]
fn the_hopper_mesh_is_96_clean_triangle_walls() {
    let out = run(
        env!("CARGO_BIN_EXE_walls-mesh"),
        &["hopper.stl", "--unit", "mm", "--max-walls", "100"],
    );
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(
        text.starts_with("# Made by walls-mesh from hopper.stl: 96 faces as 96 walls"),
        "{text}"
    );
    assert_eq!(text.matches("wall type triangle").count(), 96);
}
