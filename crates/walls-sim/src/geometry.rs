//! The seven wall shapes and their degenerate forms, with nearest-point queries.
//!
//! Every query answers the nearest point of the wall's material to a point p, the unit
//! normal there pointing from the wall towards p (the surface normal when p lies on the
//! wall), the distance, and which feature of the shape it is. Degenerate forms are the
//! document's: a disk of radius 0 is a point, a cylinder of radius 0 a line (or a
//! segment), a finite cylinder of length 0 a ring, taper 1 a cone to a point, a shell of
//! radius 0 or opening 180° a point.

use nalgebra::Vector3;
use walls_keywords::{Keyword, WallType};
use walls_model::{Wall, direction};

type Vec3 = Vector3<f64>;

/// The part of a shape a nearest point lies on.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Feature {
    /// The flat face of a plane, triangle, rectangle or disk, or a shell's sphere.
    Face,
    /// The side of a cylinder or cone.
    Side,
    /// An edge of a triangle or rectangle, numbered from the origin's first edge.
    Edge(u8),
    /// A vertex of a triangle or rectangle: 0 is the origin, then vertex1, vertex2, …
    Vertex(u8),
    /// A circular rim: a disk's outer edge, a finite cylinder's end (0 at −length/2,
    /// 1 at +length/2), or a shell's opening.
    Rim(u8),
    /// The rim of a disk's hole.
    HoleRim,
    /// A shape that is a single point.
    Point,
}

/// The answer to a nearest-point query.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Nearest {
    /// The nearest point of the wall.
    pub point: Vec3,
    /// Unit vector from the wall towards the query point.
    pub normal: Vec3,
    /// Distance from the query point to the wall.
    pub distance: f64,
    /// Which feature the point lies on.
    pub feature: Feature,
}

/// A wall's shape, placed in space. Field names follow the walls-file tokens.
#[derive(Debug, Clone, PartialEq)]
#[allow(missing_docs)]
pub enum Shape {
    /// An infinite plane through `origin` with unit `normal`.
    Plane { origin: Vec3, normal: Vec3 },
    /// The triangle origin, origin + e1, origin + e2.
    Triangle { origin: Vec3, e1: Vec3, e2: Vec3 },
    /// The rectangle spanned from origin by perpendicular e1 and e2.
    Rectangle { origin: Vec3, e1: Vec3, e2: Vec3 },
    /// A disk of `radius` with a hole of `hole` around `center`, facing `normal`.
    Disk {
        center: Vec3,
        normal: Vec3,
        radius: f64,
        hole: f64,
    },
    /// An infinite tube of `radius` around the line through `origin` along `axis`.
    InfiniteCylinder {
        origin: Vec3,
        axis: Vec3,
        radius: f64,
    },
    /// A finite open tube centred on `center` along `axis`: radius `radius` at −length/2
    /// narrowing to radius·(1 − taper) at +length/2.
    FiniteCylinder {
        center: Vec3,
        axis: Vec3,
        radius: f64,
        length: f64,
        taper: f64,
    },
    /// A sphere of `radius` around `center` minus the cap within `open` radians of `axis`.
    Shell {
        center: Vec3,
        axis: Vec3,
        radius: f64,
        open: f64,
    },
}

impl Shape {
    /// The shape of `wall` with its origin moved to `origin` (its position at some time).
    pub fn of(wall: &Wall, origin: Vec3) -> Shape {
        Shape::turned(wall, origin, &nalgebra::Rotation3::identity())
    }

    /// The shape of `wall` with its origin at `origin` and its directions (orient,
    /// vertex1, vertex2) turned by `turn`: a reactive wall, which its assembly has
    /// rotated since the start.
    pub fn turned(wall: &Wall, origin: Vec3, turn: &nalgebra::Rotation3<f64>) -> Shape {
        let axis = turn * wall.vector(Keyword::Orient);
        let number = |k| wall.number(k);
        match wall.wall_type() {
            WallType::Plane => Shape::Plane {
                origin,
                normal: axis,
            },
            WallType::Triangle => Shape::Triangle {
                origin,
                e1: turn * wall.vector(Keyword::Vertex1),
                e2: turn * wall.vector(Keyword::Vertex2),
            },
            WallType::Rectangle => Shape::Rectangle {
                origin,
                e1: turn * wall.vector(Keyword::Vertex1),
                e2: turn * wall.vector(Keyword::Vertex2),
            },
            WallType::Disk => Shape::Disk {
                center: origin,
                normal: axis,
                radius: number(Keyword::Radius),
                hole: number(Keyword::HoleRadius),
            },
            WallType::CylinderInfinite => Shape::InfiniteCylinder {
                origin,
                axis,
                radius: number(Keyword::Radius),
            },
            WallType::CylinderFinite => Shape::FiniteCylinder {
                center: origin,
                axis,
                radius: number(Keyword::Radius),
                length: number(Keyword::Length),
                taper: number(Keyword::Taper),
            },
            WallType::Shell => Shape::Shell {
                center: origin,
                axis,
                radius: number(Keyword::Radius),
                open: number(Keyword::OpenAngle).to_radians(),
            },
        }
    }

    /// An axis-aligned box `(lo, hi)` holding every point the shape's [`Shape::nearest`]
    /// can answer, or `None` for a shape with no such box: planes and infinite
    /// cylinders, and the degenerate polygons whose nearest point is not confined to
    /// their vertices (a triangle whose edges are parallel, a rectangle with a zero
    /// edge; the model flags both).
    ///
    /// The boxes are tight, not merely safe: a triangle's or rectangle's is its
    /// vertices'; a disk's is its rim circle's, centre ± radius·√(1 − nᵢ²) on each axis
    /// i (the hole does not narrow it); a finite cylinder's or cone's covers its two end
    /// rims (its side lies between them); a shell's is its whole sphere.
    pub fn bounds(&self) -> Option<(Vec3, Vec3)> {
        match self {
            Shape::Plane { .. } | Shape::InfiniteCylinder { .. } => None,
            Shape::Triangle { origin, e1, e2 } => {
                direction(&e1.cross(e2))?;
                Some(corners(&[*origin, origin + e1, origin + e2]))
            }
            Shape::Rectangle { origin, e1, e2 } => {
                if e1.norm_squared() == 0.0 || e2.norm_squared() == 0.0 {
                    return None;
                }
                Some(corners(&[
                    *origin,
                    origin + e1,
                    origin + e2,
                    origin + e1 + e2,
                ]))
            }
            Shape::Disk {
                center,
                normal,
                radius,
                ..
            } => Some(rim_bounds(center, normal, radius.abs())),
            Shape::FiniteCylinder {
                center,
                axis,
                radius,
                length,
                taper,
            } => {
                let half = axis * (length / 2.0);
                let (lo0, hi0) = rim_bounds(&(center - half), axis, radius.abs());
                let (lo1, hi1) = rim_bounds(&(center + half), axis, (radius * (1.0 - taper)).abs());
                Some((lo0.inf(&lo1), hi0.sup(&hi1)))
            }
            Shape::Shell { center, radius, .. } => {
                let r = Vec3::repeat(radius.abs());
                Some((center - r, center + r))
            }
        }
    }

    /// The nearest point of the shape to `p`.
    pub fn nearest(&self, p: &Vec3) -> Nearest {
        match self {
            Shape::Plane { origin, normal } => {
                let h = normal.dot(&(p - origin));
                answer(p, p - normal * h, *normal, Feature::Face)
            }
            Shape::Triangle { origin, e1, e2 } => triangle(p, origin, e1, e2),
            Shape::Rectangle { origin, e1, e2 } => rectangle(p, origin, e1, e2),
            Shape::Disk {
                center,
                normal,
                radius,
                hole,
            } => disk(p, center, normal, *radius, *hole),
            Shape::InfiniteCylinder {
                origin,
                axis,
                radius,
            } => {
                let d = p - origin;
                let along = axis * axis.dot(&d);
                let radial = d - along;
                if *radius == 0.0 {
                    let q = origin + along;
                    return answer(p, q, any_perpendicular(axis), Feature::Side);
                }
                let out = direction(&radial).unwrap_or_else(|| any_perpendicular(axis));
                answer(p, origin + along + out * *radius, -out, Feature::Side)
            }
            Shape::FiniteCylinder {
                center,
                axis,
                radius,
                length,
                taper,
            } => cone(p, center, axis, *radius, *length, *taper),
            Shape::Shell {
                center,
                axis,
                radius,
                open,
            } => shell(p, center, axis, *radius, *open),
        }
    }
}

/// The box of a few points.
fn corners(points: &[Vec3]) -> (Vec3, Vec3) {
    points
        .iter()
        .skip(1)
        .fold((points[0], points[0]), |(lo, hi), q| (lo.inf(q), hi.sup(q)))
}

/// The box of the circle of `radius` around `center` perpendicular to `normal`: on
/// axis i it reaches radius·√(1 − nᵢ²) each side, computed as √(n_j² + n_k²)/|n| so
/// that an axis nearly along the normal keeps its few digits. A zero normal (which
/// [`Shape::nearest`] treats as every direction) gets the whole ball.
fn rim_bounds(center: &Vec3, normal: &Vec3, radius: f64) -> (Vec3, Vec3) {
    let len2 = normal.norm_squared();
    let reach = if len2 > 0.0 {
        let sq = normal.component_mul(normal);
        Vec3::new(sq.y + sq.z, sq.z + sq.x, sq.x + sq.y)
            .map(|s| radius * (s / len2).sqrt().min(1.0))
    } else {
        Vec3::repeat(radius)
    };
    (center - reach, center + reach)
}

/// The answer for nearest point `q` of a surface whose own normal there is `surface`.
fn answer(p: &Vec3, q: Vec3, surface: Vec3, feature: Feature) -> Nearest {
    let d = p - q;
    let distance = d.norm();
    let normal = if distance > 0.0 {
        d / distance
    } else {
        surface
    };
    Nearest {
        point: q,
        normal,
        distance,
        feature,
    }
}

/// Some unit vector perpendicular to unit `a`.
fn any_perpendicular(a: &Vec3) -> Vec3 {
    let helper = if a.x.abs() < 0.9 {
        Vec3::x()
    } else {
        Vec3::y()
    };
    direction(&a.cross(&helper)).unwrap_or_else(Vec3::x)
}

/// Nearest point of segment a–b to p, as the parameter t in [0, 1].
fn segment_t(p: &Vec3, a: &Vec3, b: &Vec3) -> f64 {
    let ab = b - a;
    let len2 = ab.norm_squared();
    if len2 == 0.0 {
        return 0.0;
    }
    ((p - a).dot(&ab) / len2).clamp(0.0, 1.0)
}

fn triangle(p: &Vec3, o: &Vec3, e1: &Vec3, e2: &Vec3) -> Nearest {
    let normal = direction(&e1.cross(e2)).unwrap_or_else(Vec3::z);
    let (a, b, c) = (*o, o + e1, o + e2);
    // Inside the prism over the face: the projection.
    let ap = p - a;
    let h = normal.dot(&ap);
    let q = p - normal * h;
    let inside = [(a, b), (b, c), (c, a)]
        .iter()
        .all(|(u, v)| (v - u).cross(&(q - u)).dot(&normal) >= 0.0);
    if inside {
        return answer(p, q, normal, Feature::Face);
    }
    // Otherwise the nearest of the three edges (an end of it is a vertex).
    let vertices = [a, b, c];
    let mut best: Option<Nearest> = None;
    for (i, (u, v)) in [(0usize, 1usize), (1, 2), (2, 0)].into_iter().enumerate() {
        let t = segment_t(p, &vertices[u], &vertices[v]);
        let feature = if t == 0.0 {
            Feature::Vertex(u as u8)
        } else if t == 1.0 {
            Feature::Vertex(v as u8)
        } else {
            Feature::Edge(i as u8)
        };
        let q = vertices[u] + (vertices[v] - vertices[u]) * t;
        let n = answer(p, q, normal, feature);
        if best.is_none_or(|b| n.distance < b.distance) {
            best = Some(n);
        }
    }
    best.expect("a triangle has edges")
}

fn rectangle(p: &Vec3, o: &Vec3, e1: &Vec3, e2: &Vec3) -> Nearest {
    let normal = direction(&e1.cross(e2)).unwrap_or_else(Vec3::z);
    let (l1, l2) = (e1.norm(), e2.norm());
    let (u1, u2) = (e1 / l1, e2 / l2);
    let d = p - o;
    let (s, t) = (u1.dot(&d), u2.dot(&d));
    let (cs, ct) = (s.clamp(0.0, l1), t.clamp(0.0, l2));
    let q = o + u1 * cs + u2 * ct;
    let clamped_s = cs != s;
    let clamped_t = ct != t;
    let feature = match (clamped_s, clamped_t) {
        (false, false) => Feature::Face,
        // Edges: 0 along e1 from the origin, 1 along e2 at the end of e1, 2 along e1 at
        // the end of e2, 3 along e2 from the origin.
        (false, true) => Feature::Edge(if ct == 0.0 { 0 } else { 2 }),
        (true, false) => Feature::Edge(if cs == 0.0 { 3 } else { 1 }),
        // Vertices: 0 origin, 1 origin + e1, 2 origin + e2, 3 origin + e1 + e2.
        (true, true) => Feature::Vertex(match (cs == 0.0, ct == 0.0) {
            (true, true) => 0,
            (false, true) => 1,
            (true, false) => 2,
            (false, false) => 3,
        }),
    };
    answer(p, q, normal, feature)
}

fn disk(p: &Vec3, c: &Vec3, n: &Vec3, radius: f64, hole: f64) -> Nearest {
    let d = p - c;
    let radial = d - n * n.dot(&d);
    let rho = radial.norm();
    if radius == 0.0 {
        return answer(p, *c, *n, Feature::Point);
    }
    let out = direction(&radial).unwrap_or_else(|| any_perpendicular(n));
    if rho > radius {
        answer(p, c + out * radius, *n, Feature::Rim(0))
    } else if rho < hole {
        let near = answer(p, c + out * hole, *n, Feature::HoleRim);
        on_axis(near, radial.norm() == 0.0, n, n.dot(&d))
    } else {
        answer(p, c + radial, *n, Feature::Face)
    }
}

/// A finite cylinder or cone, reduced to the nearest point of a segment in the half-plane
/// through the axis and p.
fn cone(p: &Vec3, c: &Vec3, axis: &Vec3, radius: f64, length: f64, taper: f64) -> Nearest {
    let d = p - c;
    let x = axis.dot(&d);
    let radial = d - axis * x;
    let out = direction(&radial).unwrap_or_else(|| any_perpendicular(axis));
    let half = length / 2.0;
    let (r0, r1) = (radius, radius * (1.0 - taper));
    if radius == 0.0 && length == 0.0 {
        return answer(p, *c, *axis, Feature::Point);
    }
    // Ends of the profile: (−L/2, r0) and (+L/2, r1), in (axial, radial) coordinates.
    let a = Vec3::new(-half, r0, 0.0);
    let b = Vec3::new(half, r1, 0.0);
    let here = Vec3::new(x, radial.norm(), 0.0);
    let t = segment_t(&here, &a, &b);
    let q2 = a + (b - a) * t;
    let feature = if length == 0.0 {
        Feature::Rim(0)
    } else if r1 == 0.0 && t == 1.0 {
        Feature::Point
    } else if t == 0.0 {
        Feature::Rim(0)
    } else if t == 1.0 {
        Feature::Rim(1)
    } else {
        Feature::Side
    };
    let q = c + axis * q2.x + out * q2.y;
    // The side's own normal in the profile plane: perpendicular to the segment, outwards.
    let slope = b - a;
    let side = direction(&(out * slope.x - axis * slope.y)).unwrap_or(out);
    let near = answer(p, q, side, feature);
    let rim = matches!(feature, Feature::Rim(_));
    on_axis(near, rim && radial.norm() == 0.0, axis, x - q2.x)
}

/// A point on the axis of a ring is as near to every point of it: the contact is the
/// whole ring, and its net normal runs along the axis, towards the point's side
/// (`side` > 0: along `axis`). Without this the normal would lean to an arbitrary rim
/// point and push a particle dropped down the axis sideways.
fn on_axis(near: Nearest, symmetric: bool, axis: &Vec3, side: f64) -> Nearest {
    if !symmetric {
        return near;
    }
    Nearest {
        normal: if side < 0.0 { -axis } else { *axis },
        ..near
    }
}

fn shell(p: &Vec3, c: &Vec3, axis: &Vec3, radius: f64, open: f64) -> Nearest {
    if radius == 0.0 {
        return answer(p, *c, *axis, Feature::Point);
    }
    let d = p - c;
    // At the centre every direction is as near: take the bottom, opposite the opening.
    let u = direction(&d).unwrap_or(-*axis);
    let theta = axis.dot(&u).clamp(-1.0, 1.0).acos();
    if theta >= open {
        return answer(p, c + u * radius, u, Feature::Face);
    }
    // Inside the opening's cone: the nearest point of the rim circle.
    let sideways = direction(&(u - axis * axis.dot(&u))).unwrap_or_else(|| any_perpendicular(axis));
    let q = c + (axis * open.cos() + sideways * open.sin()) * radius;
    let feature = if open >= std::f64::consts::PI {
        Feature::Point
    } else {
        Feature::Rim(0)
    };
    answer(p, q, u, feature)
}
