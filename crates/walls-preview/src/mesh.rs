//! Each wall, placed where it is at a time (SPEC §1 "Motion"), as a mesh of triangles:
//!
//! - a plane as the polygon where it cuts the scene's box (the box around the finite
//!   walls, at least a unit across); a plane clear of the box as a square twice the
//!   scene's size;
//! - a triangle and a rectangle as themselves;
//! - a disk as a ring of `segments` quads between its hole and its rim (a fan without
//!   a hole);
//! - a finite cylinder as the open cone from radius R at −length/2 to R(1 − taper) at
//!   +length/2; an infinite one as a tube twice the scene's size long, centred where the
//!   scene's centre projects onto its axis;
//! - a shell as a sphere without the cap within `open-angle` of its axis.
//!
//! Shapes of no area (zero radius, zero length, opening 180°) give empty meshes. Each
//! triangle's vertices run counter-clockwise seen from the side its `orient` (or
//! vertex1 × vertex2) points to, and outwards for cylinders and shells.

use crate::palette;
use nalgebra::Vector3;
use walls_keywords::{Keyword, WallType};
use walls_model::{Scene, Wall, direction, motion::position};

type Vec3 = Vector3<f64>;

/// Triangles over shared vertices.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Mesh {
    /// The vertices.
    pub positions: Vec<Vec3>,
    /// Each triangle as three indices into `positions`.
    pub triangles: Vec<[u32; 3]>,
}

impl Mesh {
    fn vertex(&mut self, p: Vec3) -> u32 {
        self.positions.push(p);
        (self.positions.len() - 1) as u32
    }

    fn quad(&mut self, a: u32, b: u32, c: u32, d: u32) {
        self.triangles.push([a, b, c]);
        self.triangles.push([a, c, d]);
    }
}

/// One wall's mesh with how ssdraw draws it.
#[derive(Debug, Clone, PartialEq)]
pub struct WallMesh {
    /// The wall's index in the scene.
    pub wall: usize,
    /// Its type.
    pub wall_type: WallType,
    /// Its colour index (SPEC §3: 0 is not drawn).
    pub color: i64,
    /// Red, green, blue from 0 to 1, or `None` when not drawn.
    pub rgb: Option<[f64; 3]>,
    /// 1 − transparency.
    pub opacity: f64,
    /// Where its origin is at the time asked.
    pub origin: Vec3,
    /// Its triangles.
    pub mesh: Mesh,
}

/// Every wall of `scene` at time `t`, with `segments` segments around round shapes.
pub fn wall_meshes(scene: &Scene, t: f64, segments: usize) -> Vec<WallMesh> {
    let (lo, hi) = walls_sim::setup::bounds(scene);
    let size = (hi - lo).max();
    let segments = segments.max(3);
    scene
        .walls
        .iter()
        .enumerate()
        .map(|(w, wall)| {
            let origin = position(wall, t).unwrap_or_else(|| wall.vector(Keyword::Origin));
            let color = wall.integer(Keyword::Color);
            WallMesh {
                wall: w,
                wall_type: wall.wall_type(),
                color,
                rgb: palette::rgb(color),
                opacity: (1.0 - wall.number(Keyword::Transparency)).clamp(0.0, 1.0),
                origin,
                mesh: tessellate(wall, origin, &(lo, hi), size, segments),
            }
        })
        .collect()
}

/// Two unit vectors perpendicular to unit `n` and to each other, with u × v = n.
pub(crate) fn basis(n: &Vec3) -> (Vec3, Vec3) {
    let helper = if n.x.abs() < 0.9 {
        Vec3::x()
    } else {
        Vec3::y()
    };
    let u = direction(&n.cross(&helper)).unwrap_or_else(Vec3::x);
    (u, n.cross(&u))
}

fn tessellate(wall: &Wall, o: Vec3, bounds: &(Vec3, Vec3), size: f64, segments: usize) -> Mesh {
    let centre = &((bounds.0 + bounds.1) / 2.0);
    let mut m = Mesh::default();
    let axis = wall.vector(Keyword::Orient);
    let (u, v) = basis(&axis);
    let number = |k| wall.number(k);
    match wall.wall_type() {
        WallType::Plane => {
            let polygon = clipped_plane(&o, &axis, &u, &v, bounds).unwrap_or_else(|| {
                // Clear of the scene's box: a square of twice the scene's size.
                let c = centre - axis * axis.dot(&(centre - o));
                let h = size;
                [(-h, -h), (h, -h), (h, h), (-h, h)]
                    .iter()
                    .map(|(a, b)| c + u * *a + v * *b)
                    .collect()
            });
            let ids: Vec<u32> = polygon.into_iter().map(|p| m.vertex(p)).collect();
            for k in 1..ids.len() - 1 {
                m.triangles.push([ids[0], ids[k], ids[k + 1]]);
            }
        }
        WallType::Triangle => {
            let (a, b) = (wall.vector(Keyword::Vertex1), wall.vector(Keyword::Vertex2));
            let ids = [o, o + a, o + b].map(|p| m.vertex(p));
            m.triangles.push(ids);
        }
        WallType::Rectangle => {
            let (a, b) = (wall.vector(Keyword::Vertex1), wall.vector(Keyword::Vertex2));
            let ids = [o, o + a, o + a + b, o + b].map(|p| m.vertex(p));
            m.quad(ids[0], ids[1], ids[2], ids[3]);
        }
        WallType::Disk => {
            let (radius, hole) = (number(Keyword::Radius), number(Keyword::HoleRadius));
            if radius > 0.0 {
                ring(&mut m, &o, &u, &v, hole.min(radius), radius, segments);
            }
        }
        WallType::CylinderFinite => {
            let (radius, length) = (number(Keyword::Radius), number(Keyword::Length));
            let top = radius * (1.0 - number(Keyword::Taper));
            if radius > 0.0 && length > 0.0 {
                tube(&mut m, &o, &axis, &u, &v, (radius, top), length, segments);
            }
        }
        WallType::CylinderInfinite => {
            let radius = number(Keyword::Radius);
            if radius > 0.0 {
                let c = o + axis * axis.dot(&(centre - o));
                tube(
                    &mut m,
                    &c,
                    &axis,
                    &u,
                    &v,
                    (radius, radius),
                    2.0 * size,
                    segments,
                );
            }
        }
        WallType::Shell => {
            let radius = number(Keyword::Radius);
            let open = number(Keyword::OpenAngle).to_radians();
            if radius > 0.0 && open < std::f64::consts::PI {
                shell(&mut m, &o, &axis, &u, &v, radius, open, segments);
            }
        }
    }
    m
}

/// The flat ring between radii `inner` and `outer` around `c` in the plane of u and v.
fn ring(m: &mut Mesh, c: &Vec3, u: &Vec3, v: &Vec3, inner: f64, outer: f64, segments: usize) {
    let at = |k: usize, r: f64| {
        let a = std::f64::consts::TAU * k as f64 / segments as f64;
        c + (u * a.cos() + v * a.sin()) * r
    };
    if inner <= 0.0 {
        let centre = m.vertex(*c);
        let rim: Vec<u32> = (0..segments).map(|k| m.vertex(at(k, outer))).collect();
        for k in 0..segments {
            m.triangles.push([centre, rim[k], rim[(k + 1) % segments]]);
        }
        return;
    }
    let ids: Vec<(u32, u32)> = (0..segments)
        .map(|k| (m.vertex(at(k, inner)), m.vertex(at(k, outer))))
        .collect();
    for k in 0..segments {
        let (a, b) = ids[k];
        let (c2, d) = ids[(k + 1) % segments];
        m.quad(a, b, d, c2);
    }
}

/// The open cone around `c` along `axis` from radius `radii.0` at −length/2 to `radii.1`
/// at +length/2.
#[allow(clippy::too_many_arguments)]
fn tube(
    m: &mut Mesh,
    c: &Vec3,
    axis: &Vec3,
    u: &Vec3,
    v: &Vec3,
    radii: (f64, f64),
    length: f64,
    segments: usize,
) {
    let ids: Vec<(u32, u32)> = (0..segments)
        .map(|k| {
            let a = std::f64::consts::TAU * k as f64 / segments as f64;
            let out = u * a.cos() + v * a.sin();
            (
                m.vertex(c - axis * (length / 2.0) + out * radii.0),
                m.vertex(c + axis * (length / 2.0) + out * radii.1),
            )
        })
        .collect();
    for k in 0..segments {
        let (a, b) = ids[k];
        let (c2, d) = ids[(k + 1) % segments];
        m.quad(a, c2, d, b);
    }
}

/// The sphere of `radius` around `c` without the cap within `open` of `axis`: latitude
/// rings from the opening's rim down to the pole opposite it.
#[allow(clippy::too_many_arguments)]
fn shell(
    m: &mut Mesh,
    c: &Vec3,
    axis: &Vec3,
    u: &Vec3,
    v: &Vec3,
    radius: f64,
    open: f64,
    segments: usize,
) {
    let rings = (segments / 2).max(2);
    let pi = std::f64::consts::PI;
    let rows: Vec<Vec<u32>> = (0..=rings)
        .map(|i| {
            let theta = open + (pi - open) * i as f64 / rings as f64;
            (0..segments)
                .map(|k| {
                    let a = std::f64::consts::TAU * k as f64 / segments as f64;
                    let dir = axis * theta.cos() + (u * a.cos() + v * a.sin()) * theta.sin();
                    m.vertex(c + dir * radius)
                })
                .collect()
        })
        .collect();
    for i in 0..rings {
        for k in 0..segments {
            let n = (k + 1) % segments;
            m.quad(rows[i][k], rows[i + 1][k], rows[i + 1][n], rows[i][n]);
        }
    }
}

/// The plane through `o` with unit normal `n` cut to the box `bounds`: the convex
/// polygon where they meet, counter-clockwise about `n` (u × v = n); `None` when the
/// plane misses the box or only touches it.
fn clipped_plane(
    o: &Vec3,
    n: &Vec3,
    u: &Vec3,
    v: &Vec3,
    bounds: &(Vec3, Vec3),
) -> Option<Vec<Vec3>> {
    let (lo, hi) = bounds;
    let corner = |k: usize| {
        Vec3::new(
            if k & 1 == 0 { lo.x } else { hi.x },
            if k & 2 == 0 { lo.y } else { hi.y },
            if k & 4 == 0 { lo.z } else { hi.z },
        )
    };
    let mut points: Vec<Vec3> = Vec::new();
    for a in 0..8 {
        for bit in [1, 2, 4] {
            let b = a | bit;
            if b == a {
                continue;
            }
            let (p, q) = (corner(a), corner(b));
            let (hp, hq) = (n.dot(&(p - o)), n.dot(&(q - o)));
            if (hp <= 0.0) != (hq <= 0.0) {
                points.push(p + (q - p) * (hp / (hp - hq)));
            }
        }
    }
    if points.len() < 3 {
        return None;
    }
    let c = points.iter().sum::<Vec3>() / points.len() as f64;
    let angle = |p: &Vec3| v.dot(&(p - c)).atan2(u.dot(&(p - c)));
    points.sort_by(|a, b| angle(a).total_cmp(&angle(b)));
    // A plane touching the box at a corner or along an edge cuts no area.
    let area: f64 = (1..points.len() - 1)
        .map(|k| {
            (points[k] - points[0])
                .cross(&(points[k + 1] - points[0]))
                .norm()
        })
        .sum();
    (area > 1e-12 * (hi - lo).norm_squared()).then_some(points)
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

/// Moves each placed wall's mesh in `meshes` (made from `scene`) to its placement: the
/// rigid turn that takes the wall's own vectors to the placed ones, about its origin,
/// then to the placed origin. A round wall turns by the shortest rotation from its
/// orient to the placed one (its shape is the same about the axis; half a turn about a
/// perpendicular when the two are opposite).
pub fn place(meshes: &mut [WallMesh], scene: &Scene, placed: &[Placement]) {
    use nalgebra::{Matrix3, Rotation3};
    for p in placed {
        let (w, origin, turn) = match *p {
            Placement::Polygon {
                wall,
                origin,
                vertex1,
                vertex2,
            } => {
                let Some(wl) = scene.walls.get(wall) else {
                    continue;
                };
                let frame = |a: Vec3, b: Vec3| {
                    let x = direction(&a).unwrap_or_else(Vec3::x);
                    let z = direction(&a.cross(&b)).unwrap_or_else(Vec3::z);
                    Matrix3::from_columns(&[x, z.cross(&x), z])
                };
                let then = frame(wl.vector(Keyword::Vertex1), wl.vector(Keyword::Vertex2));
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
                let Some(wl) = scene.walls.get(wall) else {
                    continue;
                };
                let from = wl.vector(Keyword::Orient);
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
        let Some(m) = meshes.iter_mut().find(|m| m.wall == w) else {
            continue;
        };
        let from = m.origin;
        for q in &mut m.mesh.positions {
            *q = origin + turn * (*q - from);
        }
        m.origin = origin;
    }
}
