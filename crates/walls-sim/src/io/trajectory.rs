//! Trajectory output (`walls-sim run --out DIR --every N`): the particles and the walls'
//! origins at step 0 and every N steps after, as two CSV files in DIR.
//!
//! * `particles.csv`: `step,t,particle,alive,mass,radius,x,y,z,vx,vy,vz,wx,wy,wz,color`,
//!   one row per particle per output step, `color` pkdgrav's colour (ssdraw's palette,
//!   docs/pkdgrav-physics.md §16, as the input particles gave it; a file written before
//!   the column was added reads with [`DEFAULT_COLOR`]);
//! * `walls.csv`: `step,t,wall,x,y,z`, where each wall's origin is (docs/spec.md §1
//!   "Motion"; a reactive wall's where its assembly has moved it).
//!
//! One long table per kind loads in one call into pandas, ParaView's CSV reader or a
//! spreadsheet, and a particle's path is a filter on its index. Numbers are written with
//! Rust's shortest round-trip formatting, so nothing is lost.
//!
//! A row of each file is one record, [`ParticleRow`] or [`WallRow`]: [`Trajectory`]
//! writes them and [`read_particles`] and [`read_walls`] read them back.

use crate::bodies::State;
use crate::io::particles::{COLOR_MAX, DEFAULT_COLOR};
use nalgebra::Vector3;
use std::io::{self, Write};
use walls_geometry::{Particle, Wall};

type Vec3 = Vector3<f64>;

/// The columns of `particles.csv`.
pub const PARTICLE_COLUMNS: [&str; 16] = [
    "step", "t", "particle", "alive", "mass", "radius", "x", "y", "z", "vx", "vy", "vz", "wx",
    "wy", "wz", "color",
];

/// The columns of `walls.csv`.
pub const WALL_COLUMNS: [&str; 6] = ["step", "t", "wall", "x", "y", "z"];

/// One row of `particles.csv`: a particle at an output step.
#[derive(Debug, Clone, PartialEq)]
pub struct ParticleRow {
    /// The step.
    pub step: u64,
    /// The time.
    pub t: f64,
    /// The particle's index in the run's input.
    pub particle: usize,
    /// Whether it is still in the run (written as 1 or 0).
    pub alive: bool,
    /// Its mass.
    pub mass: f64,
    /// Its radius.
    pub radius: f64,
    /// Its position.
    pub pos: Vec3,
    /// Its velocity.
    pub vel: Vec3,
    /// Its spin.
    pub spin: Vec3,
    /// Its pkdgrav colour (negative: stuck to wall −1 − color).
    pub color: i32,
}

impl ParticleRow {
    /// The row for particle `particle` in `state` at `step`, time `t`.
    pub fn new(step: u64, t: f64, particle: usize, state: &State) -> Self {
        Self::of(step, t, particle, state.alive, &state.particle)
    }

    /// The row for particle number `particle`, `p`, alive or not, at `step`, time `t`.
    fn of(step: u64, t: f64, particle: usize, alive: bool, p: &Particle) -> Self {
        ParticleRow {
            step,
            t,
            particle,
            alive,
            mass: p.mass,
            radius: p.radius,
            pos: p.pos,
            vel: p.vel,
            spin: p.spin,
            color: p.color,
        }
    }

    fn cells(&self) -> Vec<String> {
        let mut row = vec![
            self.step.to_string(),
            self.t.to_string(),
            self.particle.to_string(),
            u8::from(self.alive).to_string(),
            self.mass.to_string(),
            self.radius.to_string(),
        ];
        for v in [&self.pos, &self.vel, &self.spin] {
            row.extend(v.iter().map(f64::to_string));
        }
        row.push(self.color.to_string());
        row
    }
}

/// One row of `walls.csv`: a wall's origin at an output step.
#[derive(Debug, Clone, PartialEq)]
pub struct WallRow {
    /// The step.
    pub step: u64,
    /// The time.
    pub t: f64,
    /// The wall's index in the walls file, counting from 0.
    pub wall: usize,
    /// Its origin.
    pub origin: Vec3,
}

impl WallRow {
    fn cells(&self) -> Vec<String> {
        let mut row = vec![
            self.step.to_string(),
            self.t.to_string(),
            self.wall.to_string(),
        ];
        row.extend(self.origin.iter().map(f64::to_string));
        row
    }
}

/// The name of the particles' file.
pub const PARTICLES_FILE: &str = "particles.csv";

/// The name of the walls' file.
pub const WALLS_FILE: &str = "walls.csv";

/// The trajectory, written as two CSV tables to `W`s: [`PARTICLES_FILE`]'s and
/// [`WALLS_FILE`]'s (the command line opens the files).
pub struct Trajectory<W: Write> {
    particles: W,
    walls: W,
}

impl<W: Write> Trajectory<W> {
    /// The trajectory written to `particles` and `walls`, each begun with its header.
    pub fn new(particles: W, walls: W) -> io::Result<Trajectory<W>> {
        let mut trajectory = Trajectory { particles, walls };
        write_row(&mut trajectory.particles, &PARTICLE_COLUMNS)?;
        write_row(&mut trajectory.walls, &WALL_COLUMNS)?;
        Ok(trajectory)
    }

    /// Writes the particles and the walls at `step`, time `t`: each wall where its
    /// motion puts it, or where its reactive `assemblies` have moved it.
    pub fn record(
        &mut self,
        step: u64,
        t: f64,
        states: &[State],
        scene: &[Wall],
        assemblies: &[crate::dynamics::reactive::Assembly],
    ) -> io::Result<()> {
        let rows = states
            .iter()
            .enumerate()
            .map(|(i, s)| ParticleRow::new(step, t, i, s));
        self.write_step(step, t, rows, scene, assemblies)
    }

    /// Writes `particles` as a run starts with them (all alive), and the walls, at
    /// `step`, time `t`: what [`Trajectory::record`] writes for their first states,
    /// without making them.
    pub fn record_start(
        &mut self,
        step: u64,
        t: f64,
        particles: &[impl AsRef<Particle>],
        scene: &[Wall],
    ) -> io::Result<()> {
        let rows = particles
            .iter()
            .enumerate()
            .map(|(i, p)| ParticleRow::of(step, t, i, true, p.as_ref()));
        self.write_step(step, t, rows, scene, &[])
    }

    /// Writes the particles' `rows`, then the walls at `step`, time `t`.
    fn write_step(
        &mut self,
        step: u64,
        t: f64,
        rows: impl Iterator<Item = ParticleRow>,
        scene: &[Wall],
        assemblies: &[crate::dynamics::reactive::Assembly],
    ) -> io::Result<()> {
        for row in rows {
            self.write_particle(&row)?;
        }
        for (w, wall) in scene.iter().enumerate() {
            let moved = assemblies.iter().find_map(|a| {
                let k = a.walls.iter().position(|x| *x == w)?;
                Some(a.origin(k))
            });
            let origin = moved.unwrap_or_else(|| wall.motion.position_or_origin(t));
            self.write_wall(&WallRow {
                step,
                t,
                wall: w,
                origin,
            })?;
        }
        Ok(())
    }

    /// Writes one row of `particles.csv`.
    pub fn write_particle(&mut self, row: &ParticleRow) -> io::Result<()> {
        write_row(&mut self.particles, &row.cells())
    }

    /// Writes one row of `walls.csv`.
    pub fn write_wall(&mut self, row: &WallRow) -> io::Result<()> {
        write_row(&mut self.walls, &row.cells())
    }

    /// Writes out what is buffered (to the `W`s, which it flushes too).
    pub fn flush(&mut self) -> io::Result<()> {
        self.particles.flush()?;
        self.walls.flush()
    }

    /// The particles' and the walls' `W`.
    pub fn writers_mut(&mut self) -> [&mut W; 2] {
        [&mut self.particles, &mut self.walls]
    }

    /// Flushes both and gives back the particles' and the walls' `W`.
    pub fn finish(mut self) -> io::Result<(W, W)> {
        self.flush()?;
        Ok((self.particles, self.walls))
    }
}

/// Writes one CSV row of `cells` (numbers and column names, which need no quoting).
fn write_row(out: &mut impl Write, cells: &[impl AsRef<str>]) -> io::Result<()> {
    for (k, cell) in cells.iter().enumerate() {
        if k > 0 {
            out.write_all(b",")?;
        }
        out.write_all(cell.as_ref().as_bytes())?;
    }
    out.write_all(b"\n")
}

/// Why a trajectory file could not be read.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum ReadError {
    /// The header is not the one [`Trajectory`] writes (`what` names the file).
    NotATrajectory {
        /// `particles.csv` or `walls.csv`.
        what: &'static str,
    },
    /// A cell is not a finite number.
    NotANumber {
        /// The line, counting from 1 (the header is line 1).
        line: usize,
        /// The column, counting from 1.
        column: usize,
    },
    /// A `color` cell is not one of pkdgrav's colours: an integer up to
    /// [`COLOR_MAX`] (negative for a particle stuck to a wall).
    NotAColor {
        /// The line, counting from 1 (the header is line 1).
        line: usize,
        /// The cell as written.
        cell: String,
    },
}

impl ReadError {
    /// The line it is at, counting from 1 (none for a header that is not a
    /// trajectory's).
    pub fn line(&self) -> Option<usize> {
        match self {
            ReadError::NotATrajectory { .. } => None,
            ReadError::NotANumber { line, .. } | ReadError::NotAColor { line, .. } => Some(*line),
        }
    }

    /// What is wrong, without the line.
    pub fn message(&self) -> String {
        match self {
            ReadError::NotATrajectory { what } => {
                format!("not a trajectory (the {what} of walls-sim run --out)")
            }
            ReadError::NotANumber { column, .. } => format!("column {column} is not a number"),
            ReadError::NotAColor { cell, .. } => format!(
                "`color` is `{cell}`, not one of pkdgrav's colours (an integer up to {COLOR_MAX}; negative: stuck to wall −1 − color)"
            ),
        }
    }
}

impl std::fmt::Display for ReadError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self.line() {
            Some(line) => write!(f, "line {line}: {}", self.message()),
            None => f.write_str(&self.message()),
        }
    }
}

impl std::error::Error for ReadError {}

/// The rows of a CSV trajectory file whose header starts with `header`, each as its
/// first `width` numbers (every one finite).
fn numbers<'a>(
    text: &'a str,
    header: &[&str],
    width: usize,
    what: &'static str,
) -> Result<impl Iterator<Item = Result<Vec<f64>, ReadError>> + 'a, ReadError> {
    let mut lines = text.lines().enumerate();
    match lines.next() {
        Some((_, first)) if first.starts_with(&header.join(",")) => {}
        _ => return Err(ReadError::NotATrajectory { what }),
    }
    Ok(lines.map(move |(n, line)| {
        let cells: Vec<&str> = line.split(',').collect();
        (0..width)
            .map(|k| {
                cells
                    .get(k)
                    .and_then(|c| walls_keywords::number::read(c).ok())
                    .ok_or(ReadError::NotANumber {
                        line: n + 1,
                        column: k + 1,
                    })
            })
            .collect()
    }))
}

/// Reads the rows of a `particles.csv`, in file order: row k is on line k + 2. The
/// header must start with the columns up to `z`; a file without the `color` column
/// (written before it was added) reads with [`DEFAULT_COLOR`].
pub fn read_particles(text: &str) -> Result<Vec<ParticleRow>, ReadError> {
    let header = text.lines().next().unwrap_or_default();
    let colored = header.starts_with(&PARTICLE_COLUMNS.join(","));
    let width = PARTICLE_COLUMNS.len() - usize::from(!colored);
    numbers(text, &PARTICLE_COLUMNS[..9], width, "particles.csv")?
        .enumerate()
        .map(|(k, row)| {
            // The colour's cell, as written, for its error.
            let not_a_color = |line: usize| ReadError::NotAColor {
                line,
                cell: (text.lines().nth(line - 1))
                    .and_then(|l| l.split(',').nth(15))
                    .unwrap_or_default()
                    .chars()
                    .take(40)
                    .collect(),
            };
            let x = row.map_err(|e| match e {
                ReadError::NotANumber { line, column: 16 } => not_a_color(line),
                e => e,
            })?;
            let v = |k: usize| Vec3::new(x[k], x[k + 1], x[k + 2]);
            let color = match x.get(15) {
                Some(&c) => color(c).ok_or_else(|| not_a_color(k + 2))?,
                None => DEFAULT_COLOR,
            };
            Ok(ParticleRow {
                step: x[0] as u64,
                t: x[1],
                particle: x[2] as usize,
                alive: x[3] != 0.0,
                mass: x[4],
                radius: x[5],
                pos: v(6),
                vel: v(9),
                spin: v(12),
                color,
            })
        })
        .collect()
}

/// `c` as a pkdgrav colour: an integer up to [`COLOR_MAX`] (negative: stuck to a wall).
fn color(c: f64) -> Option<i32> {
    (c.fract() == 0.0 && c >= f64::from(i32::MIN) && c <= f64::from(COLOR_MAX)).then_some(c as i32)
}

/// Reads the rows of a `walls.csv`, in file order: row k is on line k + 2.
pub fn read_walls(text: &str) -> Result<Vec<WallRow>, ReadError> {
    numbers(text, &WALL_COLUMNS, WALL_COLUMNS.len(), "walls.csv")?
        .map(|row| {
            let x = row?;
            Ok(WallRow {
                step: x[0] as u64,
                t: x[1],
                wall: x[2] as usize,
                origin: Vec3::new(x[3], x[4], x[5]),
            })
        })
        .collect()
}
