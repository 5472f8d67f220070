//! `walls-sim preview`: draws the walls (and particles) at a time, or their motion over
//! a span: SVG, POV-Ray, VTK or an interactive HTML page ([`walls_preview`]). Reactive
//! walls where a run left them and particle trajectories are read with
//! [`walls_sim::io`] and converted here to walls-preview's types.

use super::{error, exit_status, read_walls, ruled};
use crate::ContactModel;
use std::io::Write;
use std::process::ExitCode;
use walls_preview::html::Particles;
use walls_preview::mesh::Placement;
use walls_sim::io::par::Rule;
use walls_sim::io::trajectory::{ParticleRow, read_particles};
use walls_sim::io::wallsreact::{VizWall, last_viz_step};

/// `walls-sim preview`: pictures of the walls at a time, or over a span.
#[derive(clap::Args)]
pub struct PreviewArgs {
    /// The walls file; `-` reads standard input.
    #[arg(value_name = "FILE")]
    pub file: String,
    /// Where the walls are: at this time (pkdgrav units).
    #[arg(long, value_name = "T", default_value_t = 0.0, allow_negative_numbers = true, value_parser = ruled(Rule::Any))]
    pub time: f64,
    /// The picture, by its extension: .svg (the default, on standard output without
    /// --out), .pov (POV-Ray, with walls.inc beside it), .vtp (VTK, for ParaView) or
    /// .html (an interactive page over [--time, --until]).
    #[arg(long, value_name = "FILE")]
    pub out: Option<std::path::PathBuf>,
    /// Particles to draw too: CSV or .ss.
    #[arg(long, value_name = "FILE")]
    pub particles: Option<String>,
    /// Draw reactive walls where a run left them: the WALLSREACTviz.out that
    /// `walls-sim run --out` (or pkdgrav) wrote; its last step.
    #[arg(long, value_name = "FILE")]
    pub reactive: Option<String>,
    /// HTML: particle trajectories to play, the particles.csv that `walls-sim run --out`
    /// writes.
    #[arg(long, value_name = "FILE")]
    pub trajectory: Option<String>,
    /// The direction to look from (towards the scene).
    #[arg(long, num_args = 3, value_names = ["X", "Y", "Z"], allow_negative_numbers = true, value_parser = ruled(Rule::Any))]
    pub view: Option<Vec<f64>>,
    /// Which way is up in the picture.
    #[arg(long, num_args = 3, value_names = ["X", "Y", "Z"], allow_negative_numbers = true, value_parser = ruled(Rule::Any))]
    pub up: Option<Vec<f64>>,
    /// The picture's size in pixels.
    #[arg(long, num_args = 2, value_names = ["W", "H"], value_parser = clap::value_parser!(u32).range(16..=16384))]
    pub size: Option<Vec<u32>>,
    /// Frames from --time to --until: numbered pictures FILE-000.svg… and FILE.svg
    /// animated.
    #[arg(long, value_name = "N", default_value_t = 1, value_parser = clap::value_parser!(u64).range(1..=10000))]
    pub frames: u64,
    /// The end of the span the frames cover.
    #[arg(long, value_name = "T", allow_negative_numbers = true, value_parser = ruled(Rule::Any))]
    pub until: Option<f64>,
    /// Seconds the animation takes to play once.
    #[arg(long, value_name = "S", default_value_t = 4.0, value_parser = ruled(Rule::Positive))]
    pub seconds: f64,
    /// Segments around round shapes.
    #[arg(long, value_name = "N", default_value_t = 48, value_parser = clap::value_parser!(u64).range(3..=4096))]
    pub segments: u64,
}

/// Draws what `args` ask for; the exit status.
pub fn run(args: &PreviewArgs) -> ExitCode {
    draw(args).unwrap_or_else(error)
}

fn draw(args: &PreviewArgs) -> Result<ExitCode, String> {
    use nalgebra::Vector3;
    use walls_preview::svg::{Frame, View, write};
    let (checked, errors) = read_walls(&args.file, ContactModel::Ssdem, "drawing")?;
    let scene = &checked.scene;
    let particles = match &args.particles {
        Some(f) => walls_sim::io::particles::read_file(f).map_err(|e| e.to_string())?,
        None => Vec::new(),
    };
    let v3 = |v: &Option<Vec<f64>>, default: Vector3<f64>| {
        v.as_ref()
            .map_or(default, |v| Vector3::new(v[0], v[1], v[2]))
    };
    let default = View::default();
    let view = View {
        from: v3(&args.view, default.from),
        up: v3(&args.up, default.up),
        width: args.size.as_ref().map_or(default.width, |s| s[0]),
        height: args.size.as_ref().map_or(default.height, |s| s[1]),
    };
    let segments = args.segments as usize;
    let n = args.frames as usize;
    let until = args.until.unwrap_or(args.time);
    let times: Vec<f64> = (0..n)
        .map(|k| {
            if n == 1 {
                args.time
            } else {
                args.time + (until - args.time) * k as f64 / (n - 1) as f64
            }
        })
        .collect();
    let bounds =
        walls_geometry::scene_bounds_at(&walls_geometry::decode(scene), &particles, &times);
    let mut meshes: Vec<_> = times
        .iter()
        .map(|t| walls_preview::wall_meshes_in(scene, *t, segments, &bounds))
        .collect();
    if let Some(f) = &args.reactive {
        // Reactive walls where a run moved them: the last step of WALLSREACTviz.out.
        let placed = read_reactive_viz(f)?;
        for frame in &mut meshes {
            walls_preview::mesh::place(frame, scene, &placed);
        }
    }
    let frames: Vec<Frame> = times
        .iter()
        .zip(&meshes)
        .map(|(t, walls)| Frame {
            t: *t,
            walls,
            particles: &particles,
        })
        .collect();
    let kind = args
        .out
        .as_ref()
        .and_then(|p| p.extension())
        .map(|e| e.to_string_lossy().to_ascii_lowercase());
    if args.reactive.is_some() && !matches!(kind.as_deref(), None | Some("svg") | Some("vtp")) {
        return Err("--reactive is drawn in .svg and .vtp pictures only".into());
    }
    match kind.as_deref() {
        None => {
            let mut out = std::io::BufWriter::new(std::io::stdout().lock());
            write(&mut out, &frames, &view, bounds, args.seconds)
                .and_then(|()| out.flush())
                .map_err(|e| format!("cannot write the picture: {e}"))?;
        }
        Some("svg") => {
            let path = args.out.as_ref().expect("an extension comes from a path");
            let save = |path: &std::path::Path, frames: &[Frame]| {
                let mut out = std::io::BufWriter::new(
                    std::fs::File::create(path)
                        .map_err(|e| format!("cannot write {}: {e}", path.display()))?,
                );
                write(&mut out, frames, &view, bounds, args.seconds)
                    .and_then(|()| out.flush())
                    .map_err(|e| format!("cannot write {}: {e}", path.display()))
            };
            save(path, &frames)?;
            if n > 1 {
                let stem = path.with_extension("");
                for (k, frame) in frames.iter().enumerate() {
                    let numbered = format!("{}-{k:03}.svg", stem.display());
                    save(std::path::Path::new(&numbered), std::slice::from_ref(frame))?;
                }
            }
        }
        Some("pov") => {
            let path = args.out.as_ref().expect("an extension comes from a path");
            let pov_view = walls_preview::pov::View {
                from: view.from,
                aspect: f64::from(view.width) / f64::from(view.height),
                ..walls_preview::pov::View::default()
            };
            walls_preview::pov::write_file(path, scene, args.time, &particles, &pov_view)
                .map_err(|e| format!("cannot write {}: {e}", path.display()))?;
        }
        Some("vtp") => {
            let path = args.out.as_ref().expect("an extension comes from a path");
            let mut out = std::io::BufWriter::new(
                std::fs::File::create(path)
                    .map_err(|e| format!("cannot write {}: {e}", path.display()))?,
            );
            walls_preview::vtk::write(&mut out, &meshes[0], &particles)
                .and_then(|()| out.flush())
                .map_err(|e| format!("cannot write {}: {e}", path.display()))?;
        }
        Some("html") => {
            let path = args.out.as_ref().expect("an extension comes from a path");
            let moving = match &args.trajectory {
                Some(f) => Some(read_trajectory(f)?),
                None if !particles.is_empty() => Some(Particles {
                    radii: particles.iter().map(|p| p.radius).collect(),
                    colors: particles.iter().map(|p| i64::from(p.color)).collect(),
                    times: vec![args.time],
                    frames: vec![particles.iter().map(|p| p.pos).collect()],
                }),
                None => None,
            };
            let mut out = std::io::BufWriter::new(
                std::fs::File::create(path)
                    .map_err(|e| format!("cannot write {}: {e}", path.display()))?,
            );
            walls_preview::html::write(&mut out, scene, moving.as_ref(), until, n.max(101))
                .and_then(|()| out.flush())
                .map_err(|e| format!("cannot write {}: {e}", path.display()))?;
        }
        Some(other) => {
            return Err(format!(
                "cannot draw .{other} files: use .svg, .pov, .vtp or .html (or no --out for SVG on standard output)"
            ));
        }
    }
    Ok(exit_status(errors))
}

/// The walls' placements on the last line of a `WALLSREACTviz.out`: for each wall id,
/// its origin and either (vertex1, vertex2) or orient.
fn read_reactive_viz(f: &str) -> Result<Vec<Placement>, String> {
    let text = std::fs::read_to_string(f).map_err(|e| format!("cannot read {f}: {e}"))?;
    let (_, walls) = last_viz_step(&text).map_err(|e| format!("{f}: {e}"))?;
    Ok(walls.into_iter().map(placement).collect())
}

/// walls-preview's placement of a wall as the viz file gives it.
fn placement(wall: VizWall) -> Placement {
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

/// Particle trajectories from the `particles.csv` of `walls-sim run --out`.
fn read_trajectory(f: &str) -> Result<Particles, String> {
    let text = std::fs::read_to_string(f).map_err(|e| format!("cannot read {f}: {e}"))?;
    let rows = read_particles(&text).map_err(|e| format!("{f}: {e}"))?;
    frames(&rows).map_err(|line| format!("{f}: line {line}: particles out of order"))
}

/// The rows of a `particles.csv` as the frames the HTML page plays: one per output
/// step, each particle's radius from the first (and the default colour); or the line of
/// the first row whose particle is not the next of its step.
fn frames(rows: &[ParticleRow]) -> Result<Particles, usize> {
    let mut out = Particles::default();
    for (k, row) in rows.iter().enumerate() {
        if out.times.last() != Some(&row.t) {
            out.times.push(row.t);
            out.frames.push(Vec::new());
        }
        let frame = out.frames.last_mut().expect("pushed above");
        if row.particle != frame.len() {
            // Row k is on line k + 2, after the header.
            return Err(k + 2);
        }
        frame.push(row.pos);
        if out.frames.len() == 1 {
            out.radii.push(row.radius);
            out.colors.push(3);
        }
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Vector3;

    fn row(t: f64, particle: usize, x: f64, radius: f64) -> ParticleRow {
        ParticleRow {
            step: 0,
            t,
            particle,
            alive: true,
            mass: 1.0,
            radius,
            pos: Vector3::new(x, 0.0, 0.0),
            vel: Vector3::zeros(),
            spin: Vector3::zeros(),
        }
    }

    #[test]
    fn rows_become_frames() {
        let rows = [
            row(0.0, 0, 1.0, 0.1),
            row(0.0, 1, 2.0, 0.2),
            row(0.5, 0, 3.0, 9.0),
            row(0.5, 1, 4.0, 9.0),
        ];
        let x = |x: f64| Vector3::new(x, 0.0, 0.0);
        assert_eq!(
            frames(&rows),
            Ok(Particles {
                radii: vec![0.1, 0.2],
                colors: vec![3, 3],
                times: vec![0.0, 0.5],
                frames: vec![vec![x(1.0), x(2.0)], vec![x(3.0), x(4.0)]],
            })
        );
        // The third row (line 4) skips particle 1.
        let rows = [
            row(0.0, 0, 1.0, 0.1),
            row(0.0, 1, 2.0, 0.1),
            row(0.5, 1, 0.0, 0.1),
        ];
        assert_eq!(frames(&rows), Err(4));
    }

    #[test]
    fn viz_walls_become_placements() {
        let v = |x: f64| Vector3::new(x, -x, 2.0 * x);
        let walls = [
            VizWall::Polygon {
                id: 3,
                origin: v(1.0),
                vertex1: v(2.0),
                vertex2: v(3.0),
            },
            VizWall::Round {
                id: 0,
                origin: v(4.0),
                orient: v(5.0),
            },
        ];
        let placed: Vec<Placement> = walls.into_iter().map(placement).collect();
        assert_eq!(
            placed,
            [
                Placement::Polygon {
                    wall: 3,
                    origin: v(1.0),
                    vertex1: v(2.0),
                    vertex2: v(3.0),
                },
                Placement::Round {
                    wall: 0,
                    origin: v(4.0),
                    orient: v(5.0),
                },
            ]
        );
    }
}
