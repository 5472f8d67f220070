//! Error against pkdgrav per golden scene, before and after issue 15 (docs/fidelity.md).
//!
//! The errors are measured by the golden tests: `GOLDEN_CSV=docs/charts/golden_errors.csv
//! cargo test -p walls-sim --test golden` runs each of the 30 scenes twice and appends
//! one row per scene (scene, bar, before, after; no header) to that file:
//! - before: as `walls-sim run --par` ran a pkdgrav run directory before the issue:
//!   kick-drift-kick leapfrog with the summary's contact law, the exact oscillation,
//!   reactive walls followed (the evaluator always moved them) but the build's cohesion,
//!   two-layer contacts and aggregates not;
//! - after: the default today: pkdgrav's step, contact law and wall motion, and the
//!   build named in the scene's `params.par`.
//!
//! This binary draws them: one point per scene and run, on a log axis, with the bar a
//! faithful scene must meet (1e-9). A run that stops (the aggregate before the issue) or
//! an error below round-off is drawn at the axis's end (10 and 1e-17). Writes `golden`
//! to docs/charts.

use walls_charts::{Chart, Mark, Series, out_dir, write};

fn main() -> std::io::Result<()> {
    let dir = out_dir();
    let path = dir.join("golden_errors.csv");
    let mut reader = csv::ReaderBuilder::new()
        .has_headers(false)
        .from_path(&path)
        .map_err(|e| {
            std::io::Error::other(format!(
                "{}: {e} (write it with GOLDEN_CSV={} cargo test -p walls-sim --test golden)",
                path.display(),
                path.display()
            ))
        })?;
    let mut rows: Vec<(String, f64, f64, f64)> = Vec::new();
    for record in reader.records() {
        let r = record.map_err(std::io::Error::other)?;
        let number = |k: usize| r[k].parse::<f64>().map_err(std::io::Error::other);
        rows.push((r[0].to_string(), number(1)?, number(2)?, number(3)?));
    }
    rows.sort_by(|a, b| a.0.cmp(&b.0));
    let shown = |e: f64| e.clamp(1e-17, 10.0);
    let mut before = Vec::new();
    let mut after = Vec::new();
    for (k, (scene, bar, b, a)) in rows.iter().enumerate() {
        let x = (k + 1) as f64;
        before.push((x, shown(*b)));
        after.push((x, shown(*a)));
        println!(
            "{:2} {scene:22} before {b:9.2e}  after {a:9.2e}  (bar {bar:.0e})",
            k + 1
        );
    }
    let n = rows.len() as f64;
    write(
        &dir,
        &Chart {
            name: "golden".into(),
            title: "error against pkdgrav per golden scene (bar 1e-9; cylinder_test 1e-6)".into(),
            x_label: "scene, alphabetical (docs/fidelity.md numbers them)".into(),
            y_label: "largest relative error over the outputs".into(),
            log_x: false,
            log_y: true,
        },
        &[
            Series::new(
                "before issue 15 (leapfrog, summary's law)",
                before,
                Mark::Dots,
            ),
            Series::new("after (pkdgrav's step, law and build)", after, Mark::Dots),
            Series::new("faithful: 1e-9", vec![(1.0, 1e-9), (n, 1e-9)], Mark::Dashed),
        ],
    )
}
