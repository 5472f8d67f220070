//! A pkdgrav run's outputs as a movie (`walls-sim preview --particles`): the particles
//! of a series of `.ss` files or of a `particles.csv` (or of a `walls-sim run --out`
//! folder), one snapshot per output, and the frames built from them: the walls where
//! they were at each snapshot's time, reactive walls placed from the run's
//! `WALLSREACTviz.out` by step.
//!
//! A run's outputs can be thousands (a step's worth each): a movie shows at most
//! [`MOVIE_FRAMES`] of them, evenly spaced, unless more are asked for ([`Pick`]).

use nalgebra::Vector3;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use walls_geometry::Particle;
use walls_model::Scene;
use walls_preview::MovieFrame;
use walls_preview::mesh::Placement;
use walls_sim::io::particles::{read_csv, read_ss};
use walls_sim::io::trajectory::{PARTICLE_COLUMNS, read_particles};
use walls_sim::io::wallsreact::{VIZ_FILE, VizWall, parse_viz_line};

/// The particles of one output.
#[derive(Debug, Clone, PartialEq)]
pub struct Snapshot {
    /// The time (pkdgrav units), when the file says it (`.ss` headers and
    /// `particles.csv` rows do; a particle CSV does not).
    pub t: Option<f64>,
    /// pkdgrav's step, when the file says it: a `.ss` file's name (`ss.00100`) or the
    /// step column of a `particles.csv`.
    pub step: Option<u64>,
    /// The particles.
    pub particles: Vec<Particle>,
}

/// What a `walls-sim run --out` folder (or pkdgrav's) holds for a movie.
#[derive(Debug, Clone, PartialEq)]
pub struct RunFolder {
    /// The particle files: its `particles.csv` (every output of `walls-sim run --out`,
    /// with the particles' colours), else its `.ss` series (the files whose extension
    /// is a number, `ss.00000`…), in name order.
    pub particles: Vec<PathBuf>,
    /// Its `WALLSREACTviz.out`, if it has one.
    pub viz: Option<PathBuf>,
}

/// What the folder `dir` holds for a movie: its `particles.csv` when it has one (a
/// `walls-sim run --out --ss-output` folder has both, and the CSV holds every output,
/// the first too), else its `.ss` series; an error when it has neither.
pub fn run_folder(dir: &Path) -> Result<RunFolder, String> {
    let csv = dir.join("particles.csv");
    let viz = Some(dir.join(VIZ_FILE)).filter(|p| p.is_file());
    if csv.is_file() {
        return Ok(RunFolder {
            particles: vec![csv],
            viz,
        });
    }
    let entries =
        std::fs::read_dir(dir).map_err(|e| format!("cannot read {}: {e}", dir.display()))?;
    let mut series: Vec<PathBuf> = entries
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.is_file() && trailing_step(p).is_some())
        .collect();
    if series.is_empty() {
        return Err(format!(
            "{}: no particles.csv and no .ss outputs (ss.00000…)",
            dir.display()
        ));
    }
    series.sort();
    Ok(RunFolder {
        particles: series,
        viz,
    })
}

/// The step in a pkdgrav output's name: the digits after its last dot (`ss.00100`).
pub fn trailing_step(path: &Path) -> Option<u64> {
    let name = path.file_name()?.to_str()?;
    let (_, digits) = name.rsplit_once('.')?;
    if digits.is_empty() || !digits.bytes().all(|b| b.is_ascii_digit()) {
        return None;
    }
    digits.parse().ok()
}

/// The snapshots of the particle file at `path` (`-`: standard input; the format by its
/// extension, else its content): one for a `.ss` file or a particle CSV, one per output
/// step for a `particles.csv` of `walls-sim run --out`. Errors name the file and the
/// line or byte.
pub fn read_snapshots(path: &Path) -> Result<Vec<Snapshot>, String> {
    use walls_sim::io::particles::{Format, Opened, format_of, open_input};
    let name = path.display();
    let given = path.to_string_lossy();
    // A `.ss` file is read header first: one whose header does not match its length is
    // refused before its records are read.
    let (bytes, ss) = match open_input(&given).map_err(|e| e.to_string())? {
        Opened::Ss(t, read) => (Vec::new(), Some((t, read))),
        Opened::Bytes(bytes) => (bytes, None),
    };
    let format = (ss.is_some())
        .then_some(Format::Ss)
        .or_else(|| format_of(&given, &bytes))
        .ok_or_else(|| {
        format!(
            "{name}: neither a particle CSV (a text header row) nor a pkdgrav .ss file (a binary header with the magic number -1 or -10101 at byte 12)"
        )
    })?;
    // The numbers pkdgrav reads with fewer digits (W701) are shown, located.
    let warn = |warnings: &[walls_sim::run::Warning]| {
        for w in warnings {
            crate::errln!("walls-sim: warning: {name}: {w}");
        }
    };
    // A file of no particles draws the walls alone: said, not silent.
    let empty = |particles: &[Particle]| {
        if particles.is_empty() {
            crate::errln!("walls-sim: warning: {name}: it holds no particles");
        }
    };
    if format == Format::Ss {
        let (t, read) = match ss {
            Some(read) => read,
            None => read_ss(&bytes).map_err(|e| format!("{name}: {e}"))?,
        };
        warn(&read.warnings);
        empty(&read.particles);
        return Ok(vec![Snapshot {
            t: Some(t),
            step: trailing_step(path),
            particles: read.particles,
        }]);
    }
    let text = String::from_utf8_lossy(&bytes);
    if text.starts_with(&PARTICLE_COLUMNS[..3].join(",")) {
        let rows = read_particles(&text).map_err(|e| match e.line() {
            Some(line) => format!("{name}:{line}: {}", e.message()),
            None => format!("{name}: {e}"),
        })?;
        if rows.is_empty() {
            crate::errln!(
                "walls-sim: warning: {name}: no rows after its header: the run wrote no output into it"
            );
        }
        let (snapshots, twice) = trajectory_snapshots(&rows);
        if let Some((particle, step)) = twice {
            crate::errln!(
                "walls-sim: warning: {name}: particle {particle} is in output step {step} twice (two runs written into one file?); both are drawn"
            );
        }
        return Ok(snapshots);
    }
    let read = read_csv(&text).map_err(|e| format!("{name}: {e}"))?;
    warn(&read.warnings);
    empty(&read.particles);
    Ok(vec![Snapshot {
        t: None,
        step: None,
        particles: read.particles,
    }])
}

/// The rows of a `particles.csv` as one snapshot per output step (consecutive rows of
/// one step), with the particles still in the run; a row's particle is its index. The
/// first particle found twice in one step, with the step, if any is.
fn trajectory_snapshots(
    rows: &[walls_sim::io::trajectory::ParticleRow],
) -> (Vec<Snapshot>, Option<(usize, u64)>) {
    let mut out: Vec<Snapshot> = Vec::new();
    let mut seen = std::collections::HashSet::new();
    let mut twice = None;
    for row in rows {
        let same = out
            .last()
            .is_some_and(|s| s.step == Some(row.step) && s.t == Some(row.t));
        if !same {
            seen.clear();
            out.push(Snapshot {
                t: Some(row.t),
                step: Some(row.step),
                particles: Vec::new(),
            });
        }
        // Looked for until the first is found, then no longer hashed.
        if twice.is_none() && !seen.insert(row.particle) {
            twice = Some((row.particle, row.step));
        }
        if row.alive {
            let last = out.last_mut().expect("pushed above");
            last.particles.push(Particle {
                mass: row.mass,
                radius: row.radius,
                pos: row.pos,
                vel: row.vel,
                spin: row.spin,
                color: row.color,
                index: i32::try_from(row.particle).unwrap_or(i32::MAX),
            });
        }
    }
    (out, twice)
}

/// The most frames a movie of a run's outputs shows unless more are asked for
/// (`walls-sim preview --frames N`, `--every N`; the preview's help says this number):
/// ten seconds at 30 frames a second, an animated SVG of a few MB for a few hundred
/// particles (all 4,882 outputs of a two-second run made one of 340 MB).
pub const MOVIE_FRAMES: usize = 300;

/// The most frames a movie or a span of the walls' motion may be asked for
/// (`walls-sim preview --frames`, `walls.preview(frames=)`), or may make (`--every`).
pub const MOST_FRAMES: usize = 10_000;

/// Which of a run's outputs a movie shows.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Pick {
    /// At most this many (at least 1), evenly spaced, the first and the last among them
    /// (all of them when there are no more).
    AtMost(usize),
    /// Every Nth (N at least 1): the first, the N+1th, the 2N+1th…
    Every(usize),
}

/// `snapshots` sorted as [`frames`] sorts them (by time, a snapshot without one at
/// `t0`), and of them those `pick` keeps.
pub fn pick(snapshots: Vec<Snapshot>, t0: f64, pick: Pick) -> Vec<Snapshot> {
    let sorted = by_time(snapshots, t0).into_iter().map(|(_, s)| s);
    let m = sorted.len();
    match pick {
        Pick::Every(n) => sorted.step_by(n.max(1)).collect(),
        Pick::AtMost(n) if n >= m => sorted.collect(),
        Pick::AtMost(n) => {
            // Output k·(m − 1)/(n − 1) rounded, k = 0 … n − 1 (the first for n = 1):
            // increasing by at least one, as m > n.
            let (n, last) = (n.max(1) as u128, m as u128 - 1);
            let at = |k: u128| (k * last + (n - 1) / 2).checked_div(n - 1).unwrap_or(0);
            let mut next = (0..n).map(at).peekable();
            sorted
                .enumerate()
                .filter(|&(i, _)| next.next_if_eq(&(i as u128)).is_some())
                .map(|(_, s)| s)
                .collect()
        }
    }
}

/// `snapshots` by time (a snapshot without one at `t0`), then by step, each with its
/// time.
fn by_time(snapshots: Vec<Snapshot>, t0: f64) -> Vec<(f64, Snapshot)> {
    let mut snapshots: Vec<(f64, Snapshot)> = snapshots
        .into_iter()
        .map(|s| (s.t.unwrap_or(t0), s))
        .collect();
    snapshots.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.step.cmp(&b.1.step)));
    snapshots
}

/// The steps of a `WALLSREACTviz.out`: its walls' placements by step label (a label on
/// more than one line, as in a file a later run appended to, keeps its last line), and
/// the last line's label.
#[derive(Debug, Clone, PartialEq)]
pub struct VizSteps {
    steps: BTreeMap<u64, Vec<Placement>>,
    last: u64,
}

impl VizSteps {
    /// Reads the text of a `WALLSREACTviz.out`; the error says the line that is not a
    /// viz line.
    pub fn parse(text: &str) -> Result<VizSteps, String> {
        let mut steps = BTreeMap::new();
        let mut last = None;
        for (n, line) in text.lines().enumerate() {
            if line.trim().is_empty() {
                continue;
            }
            let (step, walls) = parse_viz_line(line)
                .ok_or_else(|| format!("line {}: not a {VIZ_FILE} line", n + 1))?;
            steps.insert(step, walls.into_iter().map(placement).collect());
            last = Some(step);
        }
        let last = last.ok_or("no steps")?;
        Ok(VizSteps { steps, last })
    }

    /// The placements of the last line.
    pub fn last(&self) -> &[Placement] {
        &self.steps[&self.last]
    }

    /// The placements for `step`: the line labelled `step`, whether exactly; else the
    /// last line with the greatest label before it (none when every label is after).
    pub fn at(&self, step: u64) -> (Option<&[Placement]>, bool) {
        match self.steps.range(..=step).next_back() {
            Some((&s, p)) => (Some(p), s == step),
            None => (None, false),
        }
    }
}

/// walls-preview's placement of a wall as the viz file gives it.
pub fn placement(wall: VizWall) -> Placement {
    match wall {
        VizWall::Polygon {
            id,
            origin,
            vertex1,
            vertex2,
        } => Placement::Polygon {
            wall: id,
            origin,
            vertex1,
            vertex2,
        },
        VizWall::Round { id, origin, orient } => Placement::Round {
            wall: id,
            origin,
            orient,
        },
    }
}

/// A movie's frames, the box around them, and what to warn of.
#[derive(Debug, Clone, PartialEq)]
pub struct Movie {
    /// The frames, by time.
    pub frames: Vec<MovieFrame>,
    /// The one box around every frame's walls and particles, to which planes are cut
    /// and which pictures fit.
    pub bounds: (Vector3<f64>, Vector3<f64>),
    /// Frames whose step has no line of the `WALLSREACTviz.out`, if any.
    pub warning: Option<String>,
}

/// The frames of a movie of `scene` with `segments` around round shapes: one per
/// snapshot, sorted by time (a snapshot without one at `t0`), every wall where its
/// motion has it `wall_offset` later (ssdraw's `Wall time offset`, or the walls file's
/// own `time` that its 0 stands for; 0 without an ssdraw.par), in one
/// box around all the walls and particles of the movie;
/// reactive walls placed from `viz` by step (a frame without a step: the last line).
pub fn frames(
    scene: &Scene,
    snapshots: Vec<Snapshot>,
    t0: f64,
    wall_offset: f64,
    viz: Option<&VizSteps>,
    segments: usize,
) -> Movie {
    let snapshots = by_time(snapshots, t0);
    let times: Vec<f64> = snapshots.iter().map(|(t, _)| t + wall_offset).collect();
    let decoded = walls_geometry::decode(scene);
    let all = snapshots.iter().flat_map(|(_, s)| &s.particles);
    let bounds = walls_geometry::scene_bounds_at(&decoded, all, &times);
    let mut unmatched: Vec<u64> = Vec::new();
    let frames = snapshots
        .into_iter()
        .map(|(t, s)| {
            let mut walls =
                walls_preview::wall_meshes_in(&decoded, t + wall_offset, segments, &bounds);
            if let Some(viz) = viz {
                let placed = match s.step {
                    None => Some(viz.last()),
                    Some(step) => {
                        let (placed, exact) = viz.at(step);
                        if !exact {
                            unmatched.push(step);
                        }
                        placed
                    }
                };
                if let Some(placed) = placed {
                    walls_preview::mesh::place(&mut walls, &decoded, placed);
                }
            }
            MovieFrame {
                t,
                step: s.step,
                walls,
                particles: s.particles,
            }
        })
        .collect();
    let warning = unmatched.first().map(|first| {
        format!(
            "{} frame(s) have no {VIZ_FILE} line of their step (the first, step {first}): each takes the last line before its step, or the walls as the walls file places them when there is none",
            unmatched.len()
        )
    });
    Movie {
        frames,
        bounds,
        warning,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use walls_sim::io::particles::write_ss;
    use walls_sim::io::wallsreact::viz_line;

    fn scene(text: &str) -> Scene {
        let options = walls_model::Options::default();
        walls_model::analyze(&walls_syntax::parse(text).tree, &options).scene
    }

    #[test]
    fn steps_come_from_names() {
        assert_eq!(trailing_step(Path::new("out/ss.00100")), Some(100));
        assert_eq!(trailing_step(Path::new("ss.ss")), None);
        assert_eq!(trailing_step(Path::new("ss.")), None);
    }

    #[test]
    fn a_series_reads_as_snapshots_sorted_by_time() {
        let dir = tempfile::tempdir().unwrap();
        let p = |x: f64| Particle::at_rest(0.1, Vector3::new(x, 0.0, 0.0), 0);
        // Written out of order: the frames follow the times in the headers.
        std::fs::write(dir.path().join("ss.00010"), write_ss(0.5, &[p(2.0)])).unwrap();
        std::fs::write(dir.path().join("ss.00000"), write_ss(0.0, &[p(1.0)])).unwrap();
        std::fs::write(dir.path().join("notes.txt"), "not an output").unwrap();
        let folder = run_folder(dir.path()).unwrap();
        assert_eq!(folder.particles.len(), 2);
        assert_eq!(folder.viz, None);
        let mut snapshots = Vec::new();
        for f in folder.particles.iter().rev() {
            snapshots.extend(read_snapshots(f).unwrap());
        }
        let s = scene("wall type disk\n  radius 0.5\n  velocity 0 0 1\n");
        let Movie {
            frames, warning, ..
        } = frames(&s, snapshots, 0.0, 0.0, None, 8);
        assert_eq!(warning, None);
        let ts: Vec<f64> = frames.iter().map(|f| f.t).collect();
        assert_eq!(ts, [0.0, 0.5]);
        assert_eq!(frames[1].step, Some(10));
        assert_eq!(frames[1].particles[0].pos.x, 2.0);
        // The disk moves up at 1: at 0.5 its origin is 0.5 up.
        assert_eq!(frames[1].walls[0].origin.z, 0.5);
    }

    #[test]
    fn a_movie_picks_among_the_outputs() {
        let outputs = |m: u64| -> Vec<Snapshot> {
            // Given last to first: the picks are by time.
            (0..m)
                .rev()
                .map(|k| Snapshot {
                    t: Some(k as f64),
                    step: Some(k),
                    particles: Vec::new(),
                })
                .collect()
        };
        let steps = |m: u64, how: Pick| -> Vec<u64> {
            let picked = pick(outputs(m), 0.0, how);
            picked.iter().map(|s| s.step.unwrap()).collect()
        };
        assert_eq!(steps(10, Pick::AtMost(4)), [0, 3, 6, 9]);
        assert_eq!(steps(10, Pick::AtMost(1)), [0]);
        assert_eq!(steps(3, Pick::AtMost(300)), [0, 1, 2]);
        assert_eq!(steps(10, Pick::Every(4)), [0, 4, 8]);
        assert_eq!(steps(10, Pick::Every(usize::MAX)), [0]);
        assert_eq!(steps(0, Pick::AtMost(5)), Vec::<u64>::new());
        // The default cap: at most MOVIE_FRAMES, distinct, the first and the last.
        let capped = steps(4882, Pick::AtMost(MOVIE_FRAMES));
        assert_eq!(capped.len(), MOVIE_FRAMES);
        assert_eq!((capped[0], capped[MOVIE_FRAMES - 1]), (0, 4881));
        assert!(capped.windows(2).all(|w| w[0] < w[1]));
        assert_eq!(steps(301, Pick::AtMost(300)).len(), 300);
    }

    #[test]
    fn a_bad_file_is_named() {
        let dir = tempfile::tempdir().unwrap();
        let bad = dir.path().join("ss.00100");
        std::fs::write(&bad, [0u8; 20]).unwrap();
        let e = read_snapshots(&bad).unwrap_err();
        assert!(e.starts_with(&bad.display().to_string()), "{e}");
    }

    #[test]
    fn reactive_walls_are_placed_by_step() {
        let s = scene("wall type disk\n  radius 0.5\n");
        let at = |z: f64| VizWall::Round {
            id: 0,
            origin: Vector3::new(0.0, 0.0, z),
            orient: Vector3::z(),
        };
        let text = viz_line(0, &[at(1.0)]) + &viz_line(100, &[at(2.0)]);
        let viz = VizSteps::parse(&text).unwrap();
        let snapshot = |step| Snapshot {
            t: Some(step as f64),
            step: Some(step),
            particles: Vec::new(),
        };
        let snapshots = vec![snapshot(0), snapshot(100), snapshot(150)];
        let Movie {
            frames, warning, ..
        } = frames(&s, snapshots, 0.0, 0.0, Some(&viz), 8);
        let z: Vec<f64> = frames.iter().map(|f| f.walls[0].origin.z).collect();
        // Step 150 has no line: the last before it (step 100) places it, with a warning.
        assert_eq!(z, [1.0, 2.0, 2.0]);
        let warning = warning.unwrap();
        assert!(warning.starts_with("1 frame(s)"), "{warning}");
        assert!(warning.contains("step 150"), "{warning}");
        // A file a second run appended to: a label's last line places it.
        let z_of = |placed: Option<&[Placement]>| match placed {
            Some([Placement::Round { origin, .. }]) => Some(origin.z),
            _ => None,
        };
        let appended = VizSteps::parse(&(text + &viz_line(0, &[at(3.0)]))).unwrap();
        assert_eq!(z_of(Some(appended.last())), Some(3.0));
        assert_eq!(appended.at(0), (Some(appended.last()), true));
        assert_eq!(
            (z_of(appended.at(50).0), appended.at(50).1),
            (Some(3.0), false)
        );
        assert_eq!(
            (z_of(appended.at(100).0), appended.at(100).1),
            (Some(2.0), true)
        );
        let later = VizSteps::parse(&viz_line(10, &[at(1.0)])).unwrap();
        assert_eq!(later.at(5), (None, false));
        assert_eq!(
            VizSteps::parse("0 1 2\nnot a line\n"),
            Err(format!("line 1: not a {VIZ_FILE} line"))
        );
    }

    #[test]
    fn a_trajectory_reads_as_one_snapshot_per_step() {
        let dir = tempfile::tempdir().unwrap();
        let csv = dir.path().join("particles.csv");
        let header = PARTICLE_COLUMNS.join(",");
        std::fs::write(
            &csv,
            format!(
                "{header}\n0,0,0,1,1,0.1,0,0,0,0,0,0,0,0,0,5\n0,0,1,1,1,0.1,1,0,0,0,0,0,0,0,0,2\n5,0.25,0,1,1,0.1,0,0,2,0,0,0,0,0,0,5\n5,0.25,1,0,1,0.1,1,0,0,0,0,0,0,0,0,2\n"
            ),
        )
        .unwrap();
        let snapshots = read_snapshots(&csv).unwrap();
        assert_eq!(snapshots.len(), 2);
        assert_eq!(snapshots[1].step, Some(5));
        assert_eq!(snapshots[1].t, Some(0.25));
        // Particle 1 has left the run by step 5.
        assert_eq!(snapshots[1].particles.len(), 1);
        assert_eq!(snapshots[1].particles[0].pos.z, 2.0);
        // Each keeps its pkdgrav colour.
        assert_eq!(snapshots[0].particles[1].color, 2);
        assert_eq!(snapshots[1].particles[0].color, 5);
    }
}
