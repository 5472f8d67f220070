//! Triangle meshes as walls (docs/meshes.md): reading STL (binary and ASCII) and OBJ
//! files, and turning each face into a triangle wall, optionally wound consistently and
//! turned outward or inward, and with pairs of triangles that make a rectangle merged
//! into one rectangle wall.

mod obj;
mod orient;
mod stl;

use crate::wall::Wall;
use std::fmt;
use std::path::Path;
use walls_keywords::WallType;

pub use orient::MERGE_TOLERANCE;

/// A triangle mesh: points, and faces naming three of them each.
#[derive(Debug, Clone, PartialEq)]
pub struct Mesh {
    /// The points.
    pub vertices: Vec<[f64; 3]>,
    /// The triangles, wound so that the right-hand rule gives the side they face.
    pub faces: Vec<Face>,
    /// The number messages give the first vertex: 1 for files (as OBJ counts; STL's
    /// vertices are counted in the order they first appear), 0 for arrays.
    pub first_index: usize,
}

/// One triangle of a mesh.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Face {
    /// Indices into [`Mesh::vertices`], from 0.
    pub vertices: [usize; 3],
    /// Where it was read from.
    pub origin: Origin,
}

/// Where a face, or a problem, is in its input.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Origin {
    /// A line of a text file (OBJ, ASCII STL), from 1.
    Line(usize),
    /// A facet of a binary STL file, from 1.
    Facet(usize),
    /// A face of arrays given by a program, from 0.
    Face(usize),
}

impl fmt::Display for Origin {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Origin::Line(n) => write!(f, "line {n}"),
            Origin::Facet(n) => write!(f, "facet {n}"),
            Origin::Face(n) => write!(f, "face {n}"),
        }
    }
}

/// Something wrong (or worth a warning) in a mesh, and where.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Problem {
    /// Where, when it is at one place.
    pub at: Option<Origin>,
    /// What, in one sentence.
    pub message: String,
}

impl Problem {
    pub(crate) fn at(origin: Origin, message: impl Into<String>) -> Problem {
        Problem {
            at: Some(origin),
            message: message.into(),
        }
    }

    pub(crate) fn whole(message: impl Into<String>) -> Problem {
        Problem {
            at: None,
            message: message.into(),
        }
    }

    /// The problem as a message about the file `path`: `cube.obj:12: …` for a line,
    /// `cube.stl: facet 3: …` for a facet.
    pub fn in_file(&self, path: &str) -> String {
        match self.at {
            Some(Origin::Line(n)) => format!("{path}:{n}: {}", self.message),
            Some(at) => format!("{path}: {at}: {}", self.message),
            None => format!("{path}: {}", self.message),
        }
    }
}

impl fmt::Display for Problem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.at {
            Some(at) => write!(f, "{at}: {}", self.message),
            None => f.write_str(&self.message),
        }
    }
}

impl std::error::Error for Problem {}

/// A mesh read from a file, and the lines of it that were skipped.
#[derive(Debug, Clone, PartialEq)]
pub struct ReadMesh {
    /// The mesh.
    pub mesh: Mesh,
    /// Statements that were not read (OBJ's lines, points, unknown words), and subnormal
    /// numbers (read as they are, as pkdgrav reads them from the walls file).
    pub warnings: Vec<Problem>,
}

/// Reads an STL (binary or ASCII) or OBJ file, chosen by its extension.
pub fn read_mesh(path: &Path) -> Result<ReadMesh, Problem> {
    let extension = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    let parse: fn(&[u8]) -> Result<ReadMesh, Problem> = match extension.as_deref() {
        Some("stl") => parse_stl,
        Some("obj") => parse_obj,
        _ => {
            return Err(Problem::whole(
                "not a mesh file walls can read: the name must end in .stl or .obj",
            ));
        }
    };
    let bytes =
        std::fs::read(path).map_err(|e| Problem::whole(format!("cannot read the file: {e}")))?;
    parse(&bytes)
}

/// Reads an STL file: binary when its size is the 84 + 50 × facets its header announces,
/// else ASCII (`solid` … `endsolid`). Identical vertices are welded into one.
pub fn parse_stl(bytes: &[u8]) -> Result<ReadMesh, Problem> {
    stl::parse(bytes)
}

/// Reads an OBJ file's `v` and `f` statements (polygons become fans of triangles).
pub fn parse_obj(bytes: &[u8]) -> Result<ReadMesh, Problem> {
    obj::parse(bytes)
}

impl Mesh {
    /// A mesh from a program's arrays: points, and triangles as indices from 0.
    pub fn from_arrays(vertices: Vec<[f64; 3]>, faces: &[[usize; 3]]) -> Result<Mesh, Problem> {
        for (i, v) in vertices.iter().enumerate() {
            if v.iter().any(|x| !x.is_finite()) {
                return Err(Problem::whole(format!(
                    "vertex {i} is not finite: {} {} {}",
                    v[0], v[1], v[2]
                )));
            }
        }
        let faces = faces
            .iter()
            .enumerate()
            .map(|(i, f)| Face {
                vertices: *f,
                origin: Origin::Face(i),
            })
            .collect();
        let mesh = Mesh {
            vertices,
            faces,
            first_index: 0,
        };
        mesh.check_indices()?;
        Ok(mesh)
    }

    /// Whether every face names vertices that exist.
    fn check_indices(&self) -> Result<(), Problem> {
        for face in &self.faces {
            if let Some(&v) = face.vertices.iter().find(|&&v| v >= self.vertices.len()) {
                return Err(Problem::at(
                    face.origin,
                    format!(
                        "vertex {} does not exist: the mesh has {} vert{}",
                        self.vertex_name(v),
                        self.vertices.len(),
                        if self.vertices.len() == 1 {
                            "ex"
                        } else {
                            "ices"
                        }
                    ),
                ));
            }
        }
        Ok(())
    }

    /// The vertex `i` as messages number it.
    pub(crate) fn vertex_name(&self, i: usize) -> usize {
        i + self.first_index
    }
}

/// Which way the walls of a mesh face.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Orientation {
    /// Each face as it is wound in the input.
    #[default]
    Keep,
    /// Wound consistently, each closed piece facing out of the volume it encloses.
    Outward,
    /// Wound consistently, each closed piece facing into the volume it encloses.
    Inward,
}

impl Orientation {
    /// Every orientation, with its name.
    pub const ALL: &'static [(&'static str, Orientation)] = &[
        ("keep", Orientation::Keep),
        ("outward", Orientation::Outward),
        ("inward", Orientation::Inward),
    ];

    /// The orientation named `name` (any case).
    pub fn named(name: &str) -> Option<Orientation> {
        crate::value::named(Orientation::ALL, name)
    }
}

/// How a mesh becomes walls.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct MeshOptions {
    /// Which way the walls face.
    pub orientation: Orientation,
    /// Merge two triangles that make a rectangle into one rectangle wall.
    pub merge_rectangles: bool,
}

/// The walls of a mesh: face (a, b, c) becomes the triangle wall `origin a`, `vertex1
/// b − a`, `vertex2 c − a`, whose normal vertex1 × vertex2 keeps the face's right-hand
/// normal. A face with no area is an error naming it; so is a mesh asked to be oriented
/// that is open, or whose faces cannot be wound consistently, naming the edge.
pub fn to_walls(mesh: &Mesh, options: &MeshOptions) -> Result<Vec<Wall>, Problem> {
    mesh.check_indices()?;
    for face in &mesh.faces {
        let [a, b, c] = face.vertices.map(|i| mesh.vertices[i]);
        let edges = (sub(b, a), sub(c, a));
        let why = if !edges.0.iter().chain(&edges.1).all(|x| x.is_finite()) {
            "spans more than a double holds"
        } else if !has_area(edges) {
            "has no area"
        } else {
            continue;
        };
        let [i, j, k] = face.vertices.map(|i| mesh.vertex_name(i));
        return Err(Problem::at(
            face.origin,
            format!("the face with vertices {i}, {j} and {k} {why}"),
        ));
    }
    let windings = match options.orientation {
        Orientation::Keep => mesh.faces.iter().map(|f| f.vertices).collect(),
        outward_or_inward => orient::orient(mesh, outward_or_inward == Orientation::Outward)?,
    };
    let pairs = if options.merge_rectangles {
        orient::rectangles(mesh, &windings)
    } else {
        vec![None; windings.len()]
    };
    let mut walls = Vec::with_capacity(windings.len());
    for (f, w) in windings.iter().enumerate() {
        let [a, b, c] = w.map(|i| mesh.vertices[i]);
        match pairs[f] {
            Some(orient::Pair::First { corner }) => {
                // The right angle at `y`: the rectangle's sides run from it to the
                // diagonal's ends, in the order that keeps the face's normal.
                let [x, y, z] = [0, 1, 2].map(|k| mesh.vertices[w[(corner + 2 + k) % 3]]);
                walls.push(Wall::polygon(WallType::Rectangle, y, sub(z, y), sub(x, y)));
            }
            Some(orient::Pair::Second) => {}
            None => walls.push(Wall::polygon(WallType::Triangle, a, sub(b, a), sub(c, a))),
        }
    }
    Ok(walls)
}

/// Whether a triangle of finite edges has an area, by the test of walls-lint's C105
/// (its two edges' directions, found as the checker finds them, whatever their length,
/// are not parallel), so that no wall made from a face fails it.
fn has_area((e1, e2): ([f64; 3], [f64; 3])) -> bool {
    let direction = |e: [f64; 3]| walls_model::scene::direction(&e.into());
    let (Some(d1), Some(d2)) = (direction(e1), direction(e2)) else {
        return false;
    };
    d1.cross(&d2).norm() > 1e-12
}

pub(crate) fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

pub(crate) fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

pub(crate) fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

pub(crate) fn norm(a: [f64; 3]) -> f64 {
    dot(a, a).sqrt()
}
