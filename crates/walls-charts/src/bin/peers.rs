//! walls-sim against LAMMPS and LIGGGHTS: particle-steps per second against particle
//! count (docs/performance.md, "Against LAMMPS and LIGGGHTS").
//!
//! It measures nothing: `scripts/bench-peers run` times the three tools and writes
//! `docs/charts/peers.csv` (tool, scene, particles, steps, seconds, particle_steps_per_s,
//! max_rss_mib, round), and this binary draws that file, the median over the rounds of
//! each tool, scene and count: `peers.svg` and `peers.png` in docs/charts for the drop,
//! `peers_oscillating.{svg,png}` for the oscillating floor. So it runs where LAMMPS is
//! not installed.

use std::collections::BTreeMap;
use std::io;
use std::path::Path;
use walls_charts::{Chart, Mark, Series, out_dir, write_pictures};

/// One measured run: its tool, scene, particle count, rate and peak memory.
#[derive(Debug, Clone, PartialEq)]
struct Run {
    tool: String,
    scene: String,
    particles: u64,
    steps: u64,
    rate: f64,
    mib: f64,
}

/// The runs of `text` (the CSV with its header), or the first row that cannot be read,
/// by its line.
fn parse(text: &str) -> Result<Vec<Run>, String> {
    let mut reader = csv::Reader::from_reader(text.as_bytes());
    let headers = reader.headers().map_err(|e| e.to_string())?.clone();
    let column = |name: &str| {
        headers
            .iter()
            .position(|h| h == name)
            .ok_or_else(|| format!("no column {name:?} in the header"))
    };
    let (tool, scene, particles, steps, rate, mib) = (
        column("tool")?,
        column("scene")?,
        column("particles")?,
        column("steps")?,
        column("particle_steps_per_s")?,
        column("max_rss_mib")?,
    );
    let mut runs = Vec::new();
    for record in reader.records() {
        let r = record.map_err(|e| e.to_string())?;
        let line = r.position().map_or(0, |p| p.line());
        let bad = |what: &str, e: &dyn std::fmt::Display| format!("line {line}: {what}: {e}");
        runs.push(Run {
            tool: r[tool].to_string(),
            scene: r[scene].to_string(),
            particles: r[particles].parse().map_err(|e| bad("particles", &e))?,
            steps: r[steps].parse().map_err(|e| bad("steps", &e))?,
            rate: r[rate]
                .parse()
                .map_err(|e| bad("particle_steps_per_s", &e))?,
            mib: r[mib].parse().map_err(|e| bad("max_rss_mib", &e))?,
        });
    }
    Ok(runs)
}

/// The median of `values` (the mean of the middle two for an even count).
fn median(values: &mut [f64]) -> f64 {
    values.sort_by(f64::total_cmp);
    let n = values.len();
    if n % 2 == 1 {
        values[n / 2]
    } else {
        (values[n / 2 - 1] + values[n / 2]) / 2.0
    }
}

/// The medians over the rounds: for each (scene, tool), each particle count's steps,
/// rate and memory, by count.
type Medians = BTreeMap<(String, String), BTreeMap<u64, (u64, f64, f64)>>;

fn medians(runs: &[Run]) -> Medians {
    let mut groups: BTreeMap<(String, String, u64), Vec<&Run>> = BTreeMap::new();
    for r in runs {
        groups
            .entry((r.scene.clone(), r.tool.clone(), r.particles))
            .or_default()
            .push(r);
    }
    let mut out = Medians::new();
    for ((scene, tool, n), group) in groups {
        let mut rates: Vec<f64> = group.iter().map(|r| r.rate).collect();
        let mut mib: Vec<f64> = group.iter().map(|r| r.mib).collect();
        out.entry((scene, tool))
            .or_default()
            .insert(n, (group[0].steps, median(&mut rates), median(&mut mib)));
    }
    out
}

fn main() -> io::Result<()> {
    let dir = out_dir();
    let path = dir.join("peers.csv");
    let text = std::fs::read_to_string(&path).map_err(|e| {
        io::Error::other(format!(
            "{}: {e} (write it with scripts/bench-peers run)",
            path.display()
        ))
    })?;
    let runs = parse(&text).map_err(|e| io::Error::other(format!("{}: {e}", path.display())))?;
    let medians = medians(&runs);
    let mut by_scene: BTreeMap<&str, Vec<Series>> = BTreeMap::new();
    for ((scene, tool), by_count) in &medians {
        for (n, (steps, rate, mib)) in by_count {
            println!(
                "{scene:12} {tool:20} {n:>8} particles × {steps:<5} steps: {:7.3} M particle-steps/s, {mib:7.1} MiB",
                rate / 1e6
            );
        }
        let points = by_count.iter().map(|(n, v)| (*n as f64, v.1)).collect();
        by_scene
            .entry(scene)
            .or_default()
            .push(Series::new(tool.as_str(), points, Mark::Line));
    }
    for (scene, series) in by_scene {
        draw(&dir, scene, &series)?;
    }
    Ok(())
}

/// Writes one scene's chart: `peers` for the drop, `peers_<scene>` for another. Each
/// chart lists the tools in the same order, so a tool has the same colour in each.
fn draw(dir: &Path, scene: &str, series: &[Series]) -> io::Result<()> {
    let name = if scene == "drop" {
        "peers".to_string()
    } else {
        format!("peers_{scene}")
    };
    write_pictures(
        dir,
        &Chart {
            name,
            title: format!("scene {scene}: walls-sim, LAMMPS, LIGGGHTS (median of the rounds)"),
            x_label: "particles".into(),
            y_label: "particle-steps per second".into(),
            log_x: true,
            log_y: true,
        },
        series,
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    const CSV: &str = "\
tool,scene,particles,steps,seconds,particle_steps_per_s,max_rss_mib,round
lammps,drop,1000,2000,0.5,4e6,10.0,1
lammps,drop,1000,2000,0.4,5e6,12.0,2
lammps,drop,1000,2000,1.0,2e6,11.0,3
walls-sim,drop,1000,2000,1.0,2e6,9.0,1
";

    #[test]
    fn medians_are_over_the_rounds_of_each_tool_scene_and_count() {
        let m = medians(&parse(CSV).unwrap());
        let lammps = &m[&("drop".to_string(), "lammps".to_string())];
        assert_eq!(lammps[&1000], (2000, 4e6, 11.0));
        let ours = &m[&("drop".to_string(), "walls-sim".to_string())];
        assert_eq!(ours[&1000], (2000, 2e6, 9.0));
    }

    #[test]
    fn a_bad_row_is_named_by_its_line() {
        let text = "tool,scene,particles,steps,seconds,particle_steps_per_s,max_rss_mib,round\n\
                    lammps,drop,many,2000,0.5,4e6,10.0,1\n";
        let e = parse(text).unwrap_err();
        assert_eq!(e, "line 2: particles: invalid digit found in string");
    }

    #[test]
    fn a_missing_column_is_named() {
        let e = parse("tool,scene\nlammps,drop\n").unwrap_err();
        assert_eq!(e, "no column \"particles\" in the header");
    }
}
