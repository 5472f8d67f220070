//! The two text files pkdgrav writes for reactive walls (docs/spec.md §3 "Reactive
//! walls"; walls document §7.4): `WALLSREACTdata.out`, one line per output step with each
//! assembly's state, and `WALLSREACTviz.out`, one line per output step with the
//! placement of every finite wall, for redrawing the assembly frame by frame.
//!
//! pkdgrav appends to both files: a run that is continued adds lines after the old ones.
//! `walls-sim run --out` does the same, or empties them first with `--fresh`, which is
//! what a new run wants (the document tells pkdgrav users to delete the old files by
//! hand); [`ReactiveOutput`] writes the lines to whatever it is given.
//!
//! # Line formats
//!
//! Fields are separated by one space; a line ends with `\n` and has no trailing space.
//! The step and the integer fields (the orientation flag and the wall id) are printed
//! as plain decimal integers; every real number is printed as C's `printf("%.16e")`
//! does ([`c_exp`]), so the files match pkdgrav's byte for byte and every value reads
//! back to the same `f64`.
//!
//! * `WALLSREACTdata.out`: `step`, then per assembly, in order, `cog(3) velocity(3)
//!   rot-vec(3) pxj(3) pyj(3) pzj(3)`, where `rot-vec` is the angular velocity in the
//!   body (principal) frame and `pxj`, `pyj`, `pzj` are the principal axes in the space
//!   frame: 1 + 18·(assemblies) fields (19 for one assembly, as the document says).
//! * `WALLSREACTviz.out`: `step`, then per finite wall (triangle, rectangle,
//!   cylinder-finite, disk, shell), in walls-file order, `0 id origin(3) vertex1(3)
//!   vertex2(3)` for triangles and rectangles or `1 id origin(3) orient(3)` for the
//!   others: 1 + Σ(11 per triangle or rectangle, 8 per other wall) fields. `id` is the
//!   wall's index in the walls file, counting from 0. (The document's "12 numbers" and
//!   "9 numbers" per wall count one more than its own field list gives; its example line
//!   and docs/spec.md agree with 11 and 8.)
//!
//! [`viz_line`] writes a viz line and [`parse_viz_line`] reads it back as the same
//! [`VizWall`]s; [`last_viz_step`] reads the last line of a viz file, where a run left
//! its walls.

use std::fmt::Write as _;
use std::io::{self, Write};

use nalgebra::Vector3;

type Vec3 = Vector3<f64>;

/// The name of the per-assembly data file, as pkdgrav spells it.
pub const DATA_FILE: &str = "WALLSREACTdata.out";

/// The name of the wall-placement file, as pkdgrav spells it.
pub const VIZ_FILE: &str = "WALLSREACTviz.out";

/// One assembly's state at an output step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AssemblyState {
    /// Centre of mass (space frame).
    pub cog: Vec3,
    /// Velocity of the centre of mass (space frame).
    pub velocity: Vec3,
    /// Angular velocity in the body (principal) frame.
    pub rot_vec: Vec3,
    /// The principal axes `pxj`, `pyj`, `pzj`, as unit vectors in the space frame.
    pub axes: [Vec3; 3],
}

/// One finite wall's placement at an output step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum VizWall {
    /// A triangle or rectangle (orientation type 0): origin and its two vertices.
    Polygon {
        /// The wall's index in the walls file, counting from 0.
        id: usize,
        /// The wall's origin (space frame).
        origin: Vec3,
        /// `vertex1`, as the walls file defines it (relative to the origin).
        vertex1: Vec3,
        /// `vertex2`, as the walls file defines it (relative to the origin).
        vertex2: Vec3,
    },
    /// A finite cylinder, disk or shell (orientation type 1): origin and axis.
    Round {
        /// The wall's index in the walls file, counting from 0.
        id: usize,
        /// The wall's origin (space frame).
        origin: Vec3,
        /// The wall's orient vector.
        orient: Vec3,
    },
}

impl VizWall {
    /// The wall's index in the walls file.
    pub fn id(&self) -> usize {
        match *self {
            VizWall::Polygon { id, .. } | VizWall::Round { id, .. } => id,
        }
    }

    /// The orientation-type flag written before the id: 0 for polygons, 1 otherwise.
    pub fn kind(&self) -> u8 {
        match self {
            VizWall::Polygon { .. } => 0,
            VizWall::Round { .. } => 1,
        }
    }

    /// How many fields this wall adds to a viz line (11 or 8).
    pub fn field_count(&self) -> usize {
        match self {
            VizWall::Polygon { .. } => 11,
            VizWall::Round { .. } => 8,
        }
    }
}

/// C's `printf("%.16e")` of `x`, exactly: 17 significant digits, correctly rounded
/// (exact ties to even, as glibc does in the default rounding mode), an exponent with
/// its sign and at least two digits (`1.0000000000000000e+00`, `4.9406564584124654e-324`),
/// `-0.0000000000000000e+00` for negative zero, and `inf`, `-inf`, `nan`, `-nan` as
/// glibc prints them (the sign of a NaN is its sign bit).
pub fn c_exp(x: f64) -> String {
    let mut out = String::with_capacity(24);
    push_c_exp(&mut out, x);
    out
}

/// Appends [`c_exp`]`(x)` to `out`.
fn push_c_exp(out: &mut String, x: f64) {
    if !x.is_finite() {
        if x.is_sign_negative() {
            out.push('-');
        }
        out.push_str(if x.is_nan() { "nan" } else { "inf" });
        return;
    }
    // Rust's `{:.16e}` gives the same correctly rounded digits (exact decimal expansion,
    // ties to even; checked against glibc in tests/reactive_output.rs) but writes the
    // exponent bare (`e0`, `e-5`): rewrite it as C does.
    let rust = format!("{x:.16e}");
    let (mantissa, exponent) = rust
        .split_once('e')
        .expect("Rust's {:e} formatting always has an exponent");
    let exponent: i32 = exponent
        .parse()
        .expect("Rust's {:e} exponent is an integer");
    out.push_str(mantissa);
    out.push('e');
    out.push(if exponent < 0 { '-' } else { '+' });
    // Writing to a String cannot fail.
    let _ = write!(out, "{:02}", exponent.unsigned_abs());
}

/// Appends a space and the three components of `v`.
fn push_vec(out: &mut String, v: &Vec3) {
    for &c in v.iter() {
        out.push(' ');
        push_c_exp(out, c);
    }
}

/// The `WALLSREACTdata.out` line for one step, with its `\n`.
pub fn data_line(step: u64, assemblies: &[AssemblyState]) -> String {
    let mut out = String::with_capacity(20 + assemblies.len() * 18 * 25);
    out.push_str(&step.to_string());
    for a in assemblies {
        push_vec(&mut out, &a.cog);
        push_vec(&mut out, &a.velocity);
        push_vec(&mut out, &a.rot_vec);
        for axis in &a.axes {
            push_vec(&mut out, axis);
        }
    }
    out.push('\n');
    out
}

/// The `WALLSREACTviz.out` line for one step, with its `\n`.
pub fn viz_line(step: u64, walls: &[VizWall]) -> String {
    let mut out = String::with_capacity(20 + walls.len() * 11 * 25);
    out.push_str(&step.to_string());
    for wall in walls {
        // Writing to a String cannot fail.
        let _ = write!(out, " {} {}", wall.kind(), wall.id());
        match wall {
            VizWall::Polygon {
                origin,
                vertex1,
                vertex2,
                ..
            } => {
                push_vec(&mut out, origin);
                push_vec(&mut out, vertex1);
                push_vec(&mut out, vertex2);
            }
            VizWall::Round { origin, orient, .. } => {
                push_vec(&mut out, origin);
                push_vec(&mut out, orient);
            }
        }
    }
    out.push('\n');
    out
}

/// Reads a `WALLSREACTviz.out` line back: its step and walls, or `None` if it is not a
/// viz line (a field is not a number the tools' rule reads: `nan`, `inf`, `1e-400`). A
/// wall whose orientation flag is 0 is a polygon, any other a round wall.
pub fn parse_viz_line(line: &str) -> Option<(u64, Vec<VizWall>)> {
    let fields: Vec<f64> = line
        .split_whitespace()
        .map(|x| walls_keywords::number::read(x).ok())
        .collect::<Option<_>>()?;
    let step = *fields.first()?;
    let v3 = |k: usize| -> Option<Vec3> {
        (k + 3 <= fields.len()).then(|| Vec3::new(fields[k], fields[k + 1], fields[k + 2]))
    };
    let mut walls = Vec::new();
    let mut k = 1; // after the step
    while k < fields.len() {
        let (kind, id) = (fields[k], *fields.get(k + 1)? as usize);
        let origin = v3(k + 2)?;
        if kind == 0.0 {
            walls.push(VizWall::Polygon {
                id,
                origin,
                vertex1: v3(k + 5)?,
                vertex2: v3(k + 8)?,
            });
            k += 11;
        } else {
            walls.push(VizWall::Round {
                id,
                origin,
                orient: v3(k + 5)?,
            });
            k += 8;
        }
    }
    Some((step as u64, walls))
}

/// Why the last step of a `WALLSREACTviz.out` could not be read.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum VizError {
    /// The file has no line that is not blank.
    NoSteps,
    /// The last line that is not blank is not a viz line.
    BadLine {
        /// Its number, counting from 1.
        line: usize,
    },
}

impl std::fmt::Display for VizError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            VizError::NoSteps => write!(f, "no steps"),
            VizError::BadLine { line } => {
                write!(f, "line {line}: not a {VIZ_FILE} line")
            }
        }
    }
}

impl std::error::Error for VizError {}

/// The last step of a `WALLSREACTviz.out` (its last line that is not blank): where the
/// run left its finite reactive walls.
pub fn last_viz_step(text: &str) -> Result<(u64, Vec<VizWall>), VizError> {
    let (n, line) = text
        .lines()
        .enumerate()
        .filter(|(_, l)| !l.trim().is_empty())
        .last()
        .ok_or(VizError::NoSteps)?;
    parse_viz_line(line).ok_or(VizError::BadLine { line: n + 1 })
}

/// The two reactive-wall output files of a run, written to `W`s ([`DATA_FILE`]'s and
/// [`VIZ_FILE`]'s; the command line opens the files, for appending as pkdgrav does or
/// emptied first).
///
/// Each [`record`](Self::record) writes one line to each and flushes both, so the files
/// always end with a whole line for every step recorded so far.
#[derive(Debug)]
pub struct ReactiveOutput<W: Write> {
    data: W,
    viz: W,
}

impl<W: Write> ReactiveOutput<W> {
    /// The output written to `data` and `viz`.
    pub fn new(data: W, viz: W) -> Self {
        Self { data, viz }
    }

    /// The data file's and the viz file's `W`.
    pub fn writers_mut(&mut self) -> [&mut W; 2] {
        [&mut self.data, &mut self.viz]
    }

    /// Appends the lines of output step `step`: the assemblies' states to the data file
    /// and the finite walls' placements to the viz file.
    pub fn record(
        &mut self,
        step: u64,
        assemblies: &[AssemblyState],
        walls: &[VizWall],
    ) -> io::Result<()> {
        self.data
            .write_all(data_line(step, assemblies).as_bytes())?;
        self.viz.write_all(viz_line(step, walls).as_bytes())?;
        self.data.flush()?;
        self.viz.flush()
    }

    /// Appends the lines of output step `step` for the reactive `assemblies` of `scene`:
    /// each assembly's state, and every finite wall of an assembly where it now is.
    pub fn record_assemblies(
        &mut self,
        step: u64,
        scene: &[walls_geometry::Wall],
        assemblies: &[crate::dynamics::reactive::Assembly],
    ) -> io::Result<()> {
        use walls_geometry::Shape;
        let states: Vec<AssemblyState> = assemblies
            .iter()
            .map(|a| AssemblyState {
                cog: a.cog,
                velocity: a.velocity,
                rot_vec: a.rotation.omega,
                axes: a.rotation.axes,
            })
            .collect();
        let mut walls: Vec<(usize, VizWall)> = Vec::new();
        for a in assemblies {
            for (k, &w) in a.walls.iter().enumerate() {
                // pkdgrav's viz file holds finite walls only.
                if matches!(
                    scene[w].shape,
                    Shape::Plane { .. } | Shape::InfiniteCylinder { .. }
                ) {
                    continue;
                }
                let now = a.shape(&scene[w].shape, k);
                let origin = now.origin();
                walls.push((
                    w,
                    match (now.edges(), now.axis()) {
                        (Some((vertex1, vertex2)), _) => VizWall::Polygon {
                            id: w,
                            origin,
                            vertex1,
                            vertex2,
                        },
                        (None, axis) => VizWall::Round {
                            id: w,
                            origin,
                            orient: axis.unwrap_or_default(),
                        },
                    },
                ));
            }
        }
        walls.sort_by_key(|(w, _)| *w);
        let walls: Vec<VizWall> = walls.into_iter().map(|(_, v)| v).collect();
        self.record(step, &states, &walls)
    }

    /// Flushes both and gives back the data file's and the viz file's `W`.
    pub fn finish(mut self) -> io::Result<(W, W)> {
        self.data.flush()?;
        self.viz.flush()?;
        Ok((self.data, self.viz))
    }
}
