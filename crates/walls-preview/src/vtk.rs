//! VTK XML PolyData (`.vtp`) for ParaView and other VTK readers: the walls' triangles
//! and the particles in one ASCII file.
//!
//! # Layout
//!
//! One `<Piece>` holds everything, so ParaView opens a single dataset:
//!
//! - **Points** (Float64): first one point per particle, in the order given (particle
//!   `i` is point `i`), then every wall's mesh vertices, wall after wall.
//! - **Verts**: one vertex cell per particle (cell `i` is particle `i`).
//! - **Polys**: every wall's triangles, wall after wall, in the order of `walls`.
//!
//! VTK numbers a PolyData's cells Verts first, then Lines, Strips and Polys, and every
//! cell-data array spans all of them; so the cell data below has the particles' values
//! first and the triangles' after.
//!
//! Cell data (one value per cell):
//!
//! - `wall` (Int32): the wall's index in the scene; −1 for particles.
//! - `color` (Int32): the ssdraw colour index, the wall's or the particle's. Walls
//!   ssdraw does not draw (colour 0) are written all the same, with colour 0, so that
//!   every wall can be inspected; a Threshold on `color` ≥ 1 hides them.
//! - `opacity` (Float64): 1 − the wall's transparency; 1 for particles.
//!
//! Point data (one value per point; wall vertices get the neutral values):
//!
//! - `radius` (Float64): the particle's radius; 0 on walls. Scaling sphere glyphs by
//!   `radius` draws the particles.
//! - `velocity` (Float64, 3 components): the particle's velocity; 0 on walls.
//! - `spin` (Float64, 3 components): the particle's spin; 0 on walls.
//! - `mass` (Float64): the particle's mass; 0 on walls.
//! - `particle` (Int32): the particle's index in its original file; −1 on walls.
//!
//! Field data (one tuple each, for the whole file):
//!
//! - `TIME` (Float64): the time of the picture, as ParaView reads it.
//! - `length_unit`, `mass_unit`, `time_unit` (String): the units of every number in the
//!   file: `m`, `kg`, `s` (SI), `cm`, `g`, `s` (cgs), or pkdgrav's own `AU`, `Msun` and
//!   `yr/2pi` (its time unit, a year over 2π). Velocities are in length/time units and spin
//!   in 1/time units.
//!
//! Numbers are written in Rust's shortest exponent form (`1.5e-3`; +0 as `0`), which
//! reads back to the same `f64`; a frame with a number that is not finite, or beyond
//! ±1e150, is refused ([`crate::finite`]); connectivity and offsets are Int64. Walls whose mesh
//! is empty (shapes of no area) have no cells and no points.

use crate::WallMesh;
use std::io::{self, Write};
use walls_geometry::Particle;
use walls_geometry::units::Scale;

/// The names written for `scale`'s length, mass and time units: its own, or pkdgrav's
/// (AU, solar masses and a year over 2π) where it has none.
pub fn unit_names(scale: &Scale) -> [&'static str; 3] {
    let or = |name: &'static str, pkdgrav| if name.is_empty() { pkdgrav } else { name };
    [
        or(scale.length.name, "AU"),
        or(scale.mass.name, "Msun"),
        or(scale.time.name, "yr/2pi"),
    ]
}

/// Writes `walls` and `particles` at time `t` (pkdgrav units) to `out` as one VTK XML
/// PolyData file, every number converted to `scale`'s units (see the module
/// documentation for the arrays and their order). A number that cannot be drawn
/// ([`crate::finite`]) is refused before anything is written, as an
/// [`io::ErrorKind::InvalidData`] error holding its [`crate::finite::NotDrawable`].
pub fn write(
    out: &mut impl Write,
    walls: &[WallMesh],
    particles: &[Particle],
    t: f64,
    scale: &Scale,
) -> io::Result<()> {
    crate::finite::check_frame(t, walls, particles)?;
    let (length, mass, time) = (
        scale.length.per_pkdgrav,
        scale.mass.per_pkdgrav,
        scale.time.per_pkdgrav,
    );
    let speed = length / time;
    let rate = 1.0 / time;
    let wall_points: usize = walls.iter().map(|w| w.mesh.positions.len()).sum();
    let triangles: usize = walls.iter().map(|w| w.mesh.triangles.len()).sum();
    let points = particles.len() + wall_points;

    writeln!(out, r#"<?xml version="1.0"?>"#)?;
    writeln!(
        out,
        r#"<VTKFile type="PolyData" version="1.0" byte_order="LittleEndian" header_type="UInt64">"#
    )?;
    writeln!(out, "  <PolyData>")?;
    writeln!(out, "    <FieldData>")?;
    write!(
        out,
        r#"      <DataArray type="Float64" Name="TIME" NumberOfTuples="1" format="ascii"> "#
    )?;
    (t * time).ascii(out)?;
    writeln!(out, " </DataArray>")?;
    for (name, unit) in ["length_unit", "mass_unit", "time_unit"]
        .iter()
        .zip(unit_names(scale))
    {
        // VTK's ASCII strings: each character's code, then a 0.
        let codes: Vec<String> = unit.bytes().chain([0]).map(|b| b.to_string()).collect();
        writeln!(
            out,
            r#"      <DataArray type="String" Name="{name}" NumberOfTuples="1" format="ascii"> {} </DataArray>"#,
            codes.join(" ")
        )?;
    }
    writeln!(out, "    </FieldData>")?;
    writeln!(
        out,
        r#"    <Piece NumberOfPoints="{points}" NumberOfVerts="{}" NumberOfLines="0" NumberOfStrips="0" NumberOfPolys="{triangles}">"#,
        particles.len()
    )?;

    // Point data: particles, then wall vertices.
    writeln!(
        out,
        r#"      <PointData Scalars="radius" Vectors="velocity">"#
    )?;
    let zeros = |n| std::iter::repeat_n(0.0, n);
    let zero3 = |n| std::iter::repeat_n([0.0; 3], n);
    array(
        out,
        "Float64",
        "radius",
        1,
        particles
            .iter()
            .map(|p| p.radius * length)
            .chain(zeros(wall_points)),
    )?;
    array3(
        out,
        "velocity",
        particles
            .iter()
            .map(|p| (p.vel * speed).into())
            .chain(zero3(wall_points)),
    )?;
    array3(
        out,
        "spin",
        particles
            .iter()
            .map(|p| (p.spin * rate).into())
            .chain(zero3(wall_points)),
    )?;
    array(
        out,
        "Float64",
        "mass",
        1,
        particles
            .iter()
            .map(|p| p.mass * mass)
            .chain(zeros(wall_points)),
    )?;
    array(
        out,
        "Int32",
        "particle",
        1,
        particles
            .iter()
            .map(|p| p.index)
            .chain(std::iter::repeat_n(-1, wall_points)),
    )?;
    writeln!(out, "      </PointData>")?;

    // Cell data: verts (particles), then polys (triangles).
    writeln!(out, r#"      <CellData Scalars="color">"#)?;
    let per_triangle = |f: fn(&WallMesh) -> i64| {
        walls
            .iter()
            .flat_map(move |w| std::iter::repeat_n(f(w), w.mesh.triangles.len()))
    };
    array(
        out,
        "Int32",
        "wall",
        1,
        std::iter::repeat_n(-1, particles.len()).chain(per_triangle(|w| int32(w.wall as i64))),
    )?;
    array(
        out,
        "Int32",
        "color",
        1,
        particles
            .iter()
            .map(|p| i64::from(p.color))
            .chain(per_triangle(|w| int32(w.color))),
    )?;
    array(
        out,
        "Float64",
        "opacity",
        1,
        std::iter::repeat_n(1.0, particles.len()).chain(
            walls
                .iter()
                .flat_map(|w| std::iter::repeat_n(w.opacity, w.mesh.triangles.len())),
        ),
    )?;
    writeln!(out, "      </CellData>")?;

    writeln!(out, "      <Points>")?;
    array3(
        out,
        "Points",
        particles.iter().map(|p| (p.pos * length).into()).chain(
            walls
                .iter()
                .flat_map(|w| w.mesh.positions.iter().map(|p| (p * length).into())),
        ),
    )?;
    writeln!(out, "      </Points>")?;

    if !particles.is_empty() {
        writeln!(out, "      <Verts>")?;
        array(out, "Int64", "connectivity", 1, 0..particles.len() as i64)?;
        array(out, "Int64", "offsets", 1, 1..=particles.len() as i64)?;
        writeln!(out, "      </Verts>")?;
    }

    if triangles > 0 {
        writeln!(out, "      <Polys>")?;
        let mut base = particles.len() as i64;
        let connectivity = walls.iter().flat_map(|w| {
            let first = base;
            base += w.mesh.positions.len() as i64;
            w.mesh
                .triangles
                .iter()
                .flat_map(move |t| t.map(|i| first + i64::from(i)))
        });
        array(out, "Int64", "connectivity", 1, connectivity)?;
        array(
            out,
            "Int64",
            "offsets",
            1,
            (1..=triangles as i64).map(|t| 3 * t),
        )?;
        writeln!(out, "      </Polys>")?;
    }

    writeln!(out, "    </Piece>")?;
    writeln!(out, "  </PolyData>")?;
    writeln!(out, "</VTKFile>")?;
    Ok(())
}

/// `v` as an Int32, saturating (colour indices and wall counts fit in practice).
fn int32(v: i64) -> i64 {
    v.clamp(i64::from(i32::MIN), i64::from(i32::MAX))
}

/// A value as VTK's ASCII reader reads it back exactly.
trait Ascii {
    fn ascii(&self, out: &mut impl Write) -> io::Result<()>;
}

impl Ascii for f64 {
    fn ascii(&self, out: &mut impl Write) -> io::Result<()> {
        // Finite: [`write`] checked every number, and the units' factors keep them so.
        if *self == 0.0 && self.is_sign_positive() {
            write!(out, "0")
        } else {
            write!(out, "{self:e}")
        }
    }
}

impl Ascii for i64 {
    fn ascii(&self, out: &mut impl Write) -> io::Result<()> {
        write!(out, "{self}")
    }
}

impl Ascii for i32 {
    fn ascii(&self, out: &mut impl Write) -> io::Result<()> {
        write!(out, "{self}")
    }
}

/// One `<DataArray>` of `components`-tuples, flattened in `values`, six values a line.
fn array<T: Ascii>(
    out: &mut impl Write,
    vtk_type: &str,
    name: &str,
    components: usize,
    values: impl IntoIterator<Item = T>,
) -> io::Result<()> {
    writeln!(
        out,
        r#"        <DataArray type="{vtk_type}" Name="{name}" NumberOfComponents="{components}" format="ascii">"#
    )?;
    let mut first = true;
    for (i, v) in values.into_iter().enumerate() {
        if i % 6 == 0 {
            if !first {
                writeln!(out)?;
            }
            write!(out, "         ")?;
        }
        first = false;
        write!(out, " ")?;
        v.ascii(out)?;
    }
    if !first {
        writeln!(out)?;
    }
    writeln!(out, "        </DataArray>")
}

/// A Float64 `<DataArray>` of 3-vectors.
fn array3(
    out: &mut impl Write,
    name: &str,
    values: impl IntoIterator<Item = [f64; 3]>,
) -> io::Result<()> {
    array(out, "Float64", name, 3, values.into_iter().flatten())
}
