//! walls-sim against LAMMPS and LIGGGHTS: particle-steps per second against particle
//! count, on scenes of one count, and the cost of a particle-step against the cup's
//! triangles (docs/performance.md, "Against LAMMPS and LIGGGHTS").
//!
//! It measures nothing: `scripts/bench-peers run` times the tools and writes
//! `docs/charts/peers.csv` (tool, scene, particles, steps, seconds, particle_steps_per_s,
//! max_rss_mib, round), and this binary draws that file in docs/charts: for a scene
//! measured at several particle counts, the median over the rounds of each tool and
//! count (`peers.{svg,png}` for the drop, `peers_<scene>.{svg,png}` for another, the
//! oscillating floor); the scenes of one count side by side, a dot for each round
//! (`peers_scenes.{svg,png}`). `run --scenes cup --triangles …` writes
//! `peers_triangles.csv` (the same columns, the scene `cup-<triangles>`) and, with
//! `--steps 1 --csv docs/charts/peers_triangles_setup.csv`, the set-up of each
//! (a run of one step): `peers_triangles.{svg,png}` draws the nanoseconds a
//! particle-step of each tool, the whole run's and, where the set-up was measured, the
//! run's less the run of one step's. So it runs where LAMMPS is not installed.

use std::collections::BTreeMap;
use std::io;
use std::path::Path;
use walls_charts::{Chart, Mark, Series, out_dir, write_named_pictures, write_pictures};

/// One measured run: its tool, scene, particle count, steps, wall time, rate and peak
/// memory.
#[derive(Debug, Clone, PartialEq)]
struct Run {
    tool: String,
    scene: String,
    particles: u64,
    steps: u64,
    seconds: f64,
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
    let (tool, scene, particles, steps, seconds, rate, mib) = (
        column("tool")?,
        column("scene")?,
        column("particles")?,
        column("steps")?,
        column("seconds")?,
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
            seconds: r[seconds].parse().map_err(|e| bad("seconds", &e))?,
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

/// The runs of the CSV at `path`, or none if `optional` and it does not exist.
fn read(path: &Path, optional: bool) -> io::Result<Vec<Run>> {
    let text = match std::fs::read_to_string(path) {
        Err(e) if optional && e.kind() == io::ErrorKind::NotFound => return Ok(Vec::new()),
        read => read.map_err(|e| {
            io::Error::other(format!(
                "{}: {e} (write it with scripts/bench-peers run)",
                path.display()
            ))
        })?,
    };
    parse(&text).map_err(|e| io::Error::other(format!("{}: {e}", path.display())))
}

fn main() -> io::Result<()> {
    let dir = out_dir();
    let runs = read(&dir.join("peers.csv"), false)?;
    let medians = medians(&runs);
    let mut by_scene: BTreeMap<&str, Vec<Series>> = BTreeMap::new();
    // Scenes measured at one particle count are drawn side by side instead.
    let swept = |scene: &str| {
        medians
            .iter()
            .any(|((s, _), by)| s == scene && by.len() > 1)
    };
    for ((scene, tool), by_count) in medians.iter().filter(|((s, _), _)| swept(s)) {
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
    let single: Vec<Run> = runs.into_iter().filter(|r| !swept(&r.scene)).collect();
    let (names, series) = side_by_side(&single);
    if !names.is_empty() {
        write_named_pictures(
            &dir,
            &Chart {
                name: "peers_scenes".into(),
                title: "scenes of one count: walls-sim, LAMMPS, LIGGGHTS (a dot a round)".into(),
                x_label: "scene: particles × steps".into(),
                y_label: "particle-steps per second".into(),
                log_x: false,
                log_y: true,
            },
            &names,
            &series,
        )?;
    }
    let sweep = read(&dir.join("peers_triangles.csv"), true)?;
    if !sweep.is_empty() {
        let set_up = read(&dir.join("peers_triangles_setup.csv"), true)?;
        // One sweep is one count of spheres: the first row's; rows of another count are
        // left out, and named.
        let spheres = sweep[0].particles;
        let of = |runs: Vec<Run>| -> Vec<Run> {
            let (kept, other): (Vec<Run>, Vec<Run>) =
                runs.into_iter().partition(|r| r.particles == spheres);
            for r in &other {
                println!(
                    "{} {} of {} spheres: not the sweep's {spheres}: left out",
                    r.tool, r.scene, r.particles
                );
            }
            kept
        };
        let (sweep, set_up) = (of(sweep), of(set_up));
        let series = triangle_costs(&sweep, &set_up);
        for s in &series {
            for (triangles, ns) in &s.points {
                println!(
                    "cup of {triangles:>6} triangles  {:36} {ns:7.1} ns a particle-step",
                    s.name
                );
            }
        }
        write_pictures(
            &dir,
            &Chart {
                name: "peers_triangles".into(),
                title: format!(
                    "the cup's {} spheres: cost against triangles (median of the rounds)",
                    grouped(spheres)
                ),
                x_label: "triangles".into(),
                y_label: "ns per particle-step".into(),
                log_x: true,
                log_y: true,
            },
            &series,
        )?;
    }
    Ok(())
}

/// `n` with a comma between each three digits: 10,640.
fn grouped(n: u64) -> String {
    let digits = n.to_string();
    let mut out = String::new();
    for (k, c) in digits.chars().enumerate() {
        if k > 0 && (digits.len() - k).is_multiple_of(3) {
            out.push(',');
        }
        out.push(c);
    }
    out
}

/// The scenes of `runs` by particle count, named with their counts, and a series of dots
/// for each tool, each round's particle-steps per second at its scene's place, the tools
/// side by side around it.
fn side_by_side(runs: &[Run]) -> (Vec<String>, Vec<Series>) {
    let mut scenes: Vec<(u64, &str, u64)> = runs
        .iter()
        .map(|r| (r.particles, r.scene.as_str(), r.steps))
        .collect();
    scenes.sort();
    scenes.dedup();
    let tools: std::collections::BTreeSet<&str> = runs.iter().map(|r| r.tool.as_str()).collect();
    let names = (scenes.iter())
        .map(|(n, scene, steps)| format!("{scene}: {} × {}", grouped(*n), grouped(*steps)))
        .collect();
    let series = (tools.iter().enumerate())
        .map(|(k, tool)| {
            let offset = (k as f64 - (tools.len() - 1) as f64 / 2.0) * 0.15;
            let points = (runs.iter())
                .filter(|r| r.tool == *tool)
                .filter_map(|r| {
                    let place = scenes.iter().position(|s| {
                        (s.0, s.1, s.2) == (r.particles, r.scene.as_str(), r.steps)
                    })?;
                    Some((place as f64 + offset, r.rate))
                })
                .collect();
            Series::new(*tool, points, Mark::Dots)
        })
        .collect();
    (names, series)
}

/// The cup's triangles in a scene's name, `cup-<triangles>`.
fn triangles(scene: &str) -> Option<u64> {
    scene.strip_prefix("cup-")?.parse().ok()
}

/// A tool's runs of the cup of some triangles: the particles, the steps, the median
/// time over the rounds and the rounds' spread (the largest time less the smallest), s.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Timed {
    particles: u64,
    steps: u64,
    median: f64,
    spread: f64,
}

/// Each tool's runs by the cup's triangles.
fn median_times(runs: &[Run]) -> BTreeMap<(String, u64), Timed> {
    let mut groups: BTreeMap<(String, u64), Vec<&Run>> = BTreeMap::new();
    for r in runs {
        if let Some(t) = triangles(&r.scene) {
            groups.entry((r.tool.clone(), t)).or_default().push(r);
        }
    }
    (groups.into_iter())
        .map(|(key, group)| {
            let mut seconds: Vec<f64> = group.iter().map(|r| r.seconds).collect();
            let median = median(&mut seconds);
            let timed = Timed {
                particles: group[0].particles,
                steps: group[0].steps,
                median,
                spread: seconds[seconds.len() - 1] - seconds[0],
            };
            (key, timed)
        })
        .collect()
}

/// The nanoseconds a particle-step against the cup's triangles, for each tool: the
/// whole run's median time over its particle-steps, then, for each tool whose run of one
/// step is in `set_up`, the difference of the medians over the steps past the first,
/// unless that difference is within the rounds' spread of the two (then the set-up hides
/// the steps, and the point is left out and named).
fn triangle_costs(sweep: &[Run], set_up: &[Run]) -> Vec<Series> {
    let whole = median_times(sweep);
    let one = median_times(set_up);
    let mut series: BTreeMap<String, Vec<(f64, f64)>> = BTreeMap::new();
    for ((tool, t), run) in &whole {
        let ns = 1e9 / (run.particles * run.steps) as f64;
        (series.entry(tool.clone()).or_default()).push((*t as f64, run.median * ns));
        let Some(first) = one.get(&(tool.clone(), *t)) else {
            continue;
        };
        if first.steps != 1 || run.steps < 2 {
            continue;
        }
        let steps = run.median - first.median;
        if steps <= run.spread + first.spread {
            println!(
                "{tool} on the cup of {t} triangles: its steps ({steps:.2} s) are within \
                 the rounds' spread ({:.2} s and {:.2} s): left out",
                run.spread, first.spread
            );
            continue;
        }
        let less = 1e9 * steps / (run.particles * (run.steps - 1)) as f64;
        (series
            .entry(format!("{tool}, less its run of one step"))
            .or_default())
        .push((*t as f64, less));
    }
    (series.into_iter())
        .map(|(name, points)| Series::new(name, points, Mark::Line))
        .collect()
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
    fn the_scenes_of_one_count_stand_side_by_side_by_particle_count() {
        let text = "\
tool,scene,particles,steps,seconds,particle_steps_per_s,max_rss_mib,round
walls-sim,poly,100000,1000,3.0,3.3e7,73.6,1
lammps,poly,100000,1000,8.0,1.2e7,83.5,1
walls-sim,cup,10640,1000,0.35,3e7,30.3,1
walls-sim,cup,10640,1000,0.34,3.1e7,30.3,2
";
        let (names, series) = side_by_side(&parse(text).unwrap());
        assert_eq!(names, ["cup: 10,640 × 1,000", "poly: 100,000 × 1,000"]);
        assert_eq!(series[0].name, "lammps");
        assert_eq!(series[0].points, [(1.0 - 0.075, 1.2e7)]);
        assert_eq!(
            series[1].points,
            [(1.075, 3.3e7), (0.075, 3e7), (0.075, 3.1e7)]
        );
    }

    #[test]
    fn the_triangle_costs_are_the_whole_runs_and_less_the_run_of_one_step() {
        let sweep = "\
tool,scene,particles,steps,seconds,particle_steps_per_s,max_rss_mib,round
liggghts,cup-99,1000,1001,3.0,0,1,1
liggghts,cup-99,1000,1001,2.9,0,1,2
liggghts,cup-99,1000,1001,3.1,0,1,3
walls-sim,cup-99975,1000,1001,1.0,0,1,1
walls-sim,cup-99975,1000,1001,1.5,0,1,2
";
        // walls-sim's steps (0.25 s) are within its rounds' spread (0.5 s): left out.
        let one = "\
tool,scene,particles,steps,seconds,particle_steps_per_s,max_rss_mib,round
liggghts,cup-99,1000,1,1.0,0,1,1
walls-sim,cup-99975,1000,1,1.0,0,1,1
";
        let series = triangle_costs(&parse(sweep).unwrap(), &parse(one).unwrap());
        let named: Vec<(&str, &[(f64, f64)])> = (series.iter())
            .map(|s| (s.name.as_str(), s.points.as_slice()))
            .collect();
        assert_eq!(
            named,
            [
                ("liggghts", &[(99.0, 3.0 * (1e9 / 1_001_000.0))][..]),
                ("liggghts, less its run of one step", &[(99.0, 2000.0)][..]),
                ("walls-sim", &[(99975.0, 1.25 * (1e9 / 1_001_000.0))][..]),
            ]
        );
    }

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
