//! Each wall, placed where it is at a time (docs/spec.md §1 "Motion"), as a mesh of
//! triangles ([`walls_geometry::Shape::tessellate`]), with how ssdraw draws it:
//!
//! - a plane as the polygon where it cuts the scene's box (the box around the finite
//!   walls and the particles, [`walls_geometry::scene_bounds`]); a plane clear of the box as a square twice the
//!   scene's size;
//! - a triangle and a rectangle as themselves;
//! - a disk as a ring of `segments` quads between its hole and its rim (a fan without
//!   a hole);
//! - a finite cylinder as the open cone from radius R at −length/2 to R(1 − taper) at
//!   +length/2; an infinite one as the tube cut to the scene's box along its axis;
//! - a shell as a sphere without the cap within `open-angle` of its axis.
//!
//! Shapes of no area (zero radius, zero length, opening 180°) give empty meshes. Each
//! triangle's vertices run counter-clockwise seen from the side its `orient` (or
//! vertex1 × vertex2) points to, and outwards for cylinders and shells.

use crate::palette;
use nalgebra::Vector3;
use std::collections::BTreeMap;
pub use walls_geometry::Mesh;
use walls_geometry::mesh::basis;
use walls_geometry::{Wall, decode, scene_bounds};
use walls_keywords::WallType;
use walls_model::{Scene, direction};

type Vec3 = Vector3<f64>;

/// One wall's mesh with how ssdraw draws it.
#[derive(Debug, Clone, PartialEq)]
pub struct WallMesh {
    /// The wall's index in the scene.
    pub wall: usize,
    /// Its type.
    pub wall_type: WallType,
    /// Its colour index (docs/spec.md §3: 0 is not drawn).
    pub color: i64,
    /// Red, green, blue from 0 to 1, or `None` when not drawn.
    pub rgb: Option<[f64; 3]>,
    /// 1 − transparency.
    pub opacity: f64,
    /// Where its origin is at the time asked.
    pub origin: Vec3,
    /// How it is turned from its orientation as written: the identity unless a run
    /// turned it ([`place`]). The mesh is the one as written, turned by `turn` about
    /// the origin and moved to `origin`.
    pub turn: nalgebra::Rotation3<f64>,
    /// Its triangles.
    pub mesh: Mesh,
}

/// Every wall of `scene` at time `t`, with `segments` segments around round shapes;
/// planes and infinite cylinders cut to the box around the walls.
pub fn wall_meshes(scene: &Scene, t: f64, segments: usize) -> Vec<WallMesh> {
    let walls = decode(scene);
    let scene_box = scene_bounds(&walls, &[]);
    wall_meshes_in(&walls, t, segments, &scene_box)
}

/// Every wall of a scene (decoded once by [`walls_geometry::decode`], for every frame)
/// at time `t`, with planes and infinite cylinders cut to `scene_box` (the box around the
/// walls and particles of a picture, or of every frame of a movie,
/// [`walls_geometry::scene_bounds_at`]).
pub fn wall_meshes_in(
    walls: &[Wall],
    t: f64,
    segments: usize,
    scene_box: &(Vec3, Vec3),
) -> Vec<WallMesh> {
    walls
        .iter()
        .enumerate()
        .map(|(w, wall)| {
            let origin = wall.motion.position_or_origin(t);
            let color = wall.appearance.color;
            WallMesh {
                wall: w,
                wall_type: wall.shape.wall_type(),
                color,
                rgb: palette::wall(color),
                opacity: (1.0 - wall.appearance.transparency).clamp(0.0, 1.0),
                origin,
                turn: nalgebra::Rotation3::identity(),
                mesh: wall.shape.at(origin).tessellate(scene_box, segments),
            }
        })
        .collect()
}

/// Where a run has moved a reactive wall (a line of `WALLSREACTviz.out`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Placement {
    /// A triangle or rectangle: its origin and edge vectors now.
    Polygon {
        /// The wall's index.
        wall: usize,
        /// Its origin now.
        origin: Vec3,
        /// vertex1 now.
        vertex1: Vec3,
        /// vertex2 now.
        vertex2: Vec3,
    },
    /// A disk, finite cylinder or shell: its origin and orient now.
    Round {
        /// The wall's index.
        wall: usize,
        /// Its origin now.
        origin: Vec3,
        /// orient now.
        orient: Vec3,
    },
}

/// Moves each placed wall's mesh in `meshes` (made from `walls`) to its placement: the
/// rigid turn that takes the wall's own vectors to the placed ones, about its origin,
/// then to the placed origin. A round wall turns by the shortest rotation from its
/// orient to the placed one (its shape is the same about the axis; half a turn about a
/// perpendicular when the two are opposite).
pub fn place(meshes: &mut [WallMesh], walls: &[Wall], placed: &[Placement]) {
    use nalgebra::{Matrix3, Rotation3};
    // Each wall's mesh by index, found once (a reactive hull of 10⁴ triangles).
    let at: BTreeMap<usize, usize> = meshes
        .iter()
        .enumerate()
        .map(|(i, m)| (m.wall, i))
        .collect();
    for p in placed {
        let (w, origin, turn) = match *p {
            Placement::Polygon {
                wall,
                origin,
                vertex1,
                vertex2,
            } => {
                let Some((e1, e2)) = walls.get(wall).and_then(|w| w.shape.edges()) else {
                    continue;
                };
                let frame = |a: Vec3, b: Vec3| {
                    let x = direction(&a).unwrap_or_else(Vec3::x);
                    let z = direction(&a.cross(&b)).unwrap_or_else(Vec3::z);
                    Matrix3::from_columns(&[x, z.cross(&x), z])
                };
                let then = frame(e1, e2);
                let now = frame(vertex1, vertex2);
                (
                    wall,
                    origin,
                    Rotation3::from_matrix_unchecked(now * then.transpose()),
                )
            }
            Placement::Round {
                wall,
                origin,
                orient,
            } => {
                let Some(from) = walls.get(wall).and_then(|w| w.shape.axis()) else {
                    continue;
                };
                // Antiparallel axes have no shortest turn: half a turn about any
                // perpendicular does.
                let turn = Rotation3::rotation_between(&from, &orient).unwrap_or_else(|| {
                    if from.dot(&orient) < 0.0 {
                        let (u, _) = basis(&from);
                        Rotation3::from_axis_angle(
                            &nalgebra::Unit::new_normalize(u),
                            std::f64::consts::PI,
                        )
                    } else {
                        Rotation3::identity()
                    }
                });
                (wall, origin, turn)
            }
        };
        let Some(m) = at.get(&w).map(|&i| &mut meshes[i]) else {
            continue;
        };
        let from = m.origin;
        for q in &mut m.mesh.positions {
            *q = origin + turn * (*q - from);
        }
        m.origin = origin;
        m.turn = turn * m.turn;
    }
}
