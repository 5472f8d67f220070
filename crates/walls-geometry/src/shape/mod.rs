//! The seven wall shapes and their degenerate forms, with every query by kind: the
//! nearest point (SSDEM), the time of impact (HSDEM), bounds, and tessellation. Each
//! wall type is a struct in its own module ([`plane`], [`triangle`], [`rectangle`],
//! [`disk`], [`infinite_cylinder`], [`finite_cylinder`], [`shell`]) holding all of its
//! geometry; [`Shape`] is the enum over them that dispatches, and this module holds the
//! answers' types and the helpers the shapes share.
//!
//! Every nearest-point query answers the nearest point of the wall's material to a point
//! p, the unit normal there pointing from the wall towards p (the surface normal when p
//! lies on the wall), the distance, and which feature of the shape it is. Degenerate
//! forms are the document's: a disk of radius 0 is a point, a cylinder of radius 0 a
//! line (or a segment), a finite cylinder of length 0 a ring, taper 1 a cone to a point,
//! a shell of radius 0 or opening 180° a point.

pub mod cull;
pub mod disk;
pub mod finite_cylinder;
pub mod infinite_cylinder;
pub mod plane;
pub mod rectangle;
pub mod shell;
pub mod triangle;

pub use cull::Cull;
pub use disk::Disk;
pub use finite_cylinder::FiniteCylinder;
pub use infinite_cylinder::InfiniteCylinder;
pub use plane::Plane;
pub use rectangle::Rectangle;
pub use shell::Shell;
pub use triangle::Triangle;

use crate::mesh::Mesh;
use nalgebra::{Rotation3, Vector3};
use walls_keywords::WallType;
use walls_model::direction;

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

/// A predicted contact: when it begins, and on which feature of the shape.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Hit {
    /// Time from the start of the prediction.
    pub t: f64,
    /// The feature touched.
    pub feature: Feature,
}

/// A wall's shape, placed in space: one variant per wall type.
#[derive(Debug, Clone, PartialEq)]
pub enum Shape {
    /// `plane`.
    Plane(Plane),
    /// `triangle`.
    Triangle(Triangle),
    /// `rectangle`.
    Rectangle(Rectangle),
    /// `disk`.
    Disk(Disk),
    /// `cylinder-infinite`.
    InfiniteCylinder(InfiniteCylinder),
    /// `cylinder-finite`, a cone when tapered.
    FiniteCylinder(FiniteCylinder),
    /// `shell`.
    Shell(Shell),
}

/// Calls the same method on whichever shape `$shape` holds.
macro_rules! each {
    ($shape:expr, $s:ident => $call:expr) => {
        match $shape {
            Shape::Plane($s) => $call,
            Shape::Triangle($s) => $call,
            Shape::Rectangle($s) => $call,
            Shape::Disk($s) => $call,
            Shape::InfiniteCylinder($s) => $call,
            Shape::FiniteCylinder($s) => $call,
            Shape::Shell($s) => $call,
        }
    };
}

impl Shape {
    /// The wall type this shape is.
    pub fn wall_type(&self) -> WallType {
        match self {
            Shape::Plane(_) => WallType::Plane,
            Shape::Triangle(_) => WallType::Triangle,
            Shape::Rectangle(_) => WallType::Rectangle,
            Shape::Disk(_) => WallType::Disk,
            Shape::InfiniteCylinder(_) => WallType::CylinderInfinite,
            Shape::FiniteCylinder(_) => WallType::CylinderFinite,
            Shape::Shell(_) => WallType::Shell,
        }
    }

    /// The point its `origin` token places: a plane's or infinite cylinder's point, a
    /// polygon's first vertex, a round shape's centre.
    pub fn origin(&self) -> Vec3 {
        match self {
            Shape::Plane(s) => s.origin,
            Shape::Triangle(s) => s.origin,
            Shape::Rectangle(s) => s.origin,
            Shape::InfiniteCylinder(s) => s.origin,
            Shape::Disk(s) => s.center,
            Shape::FiniteCylinder(s) => s.center,
            Shape::Shell(s) => s.center,
        }
    }

    /// The unit direction its `orient` gives it (a plane's or disk's normal, a
    /// cylinder's, cone's or shell's axis; zero when degenerate), or `None` for the
    /// polygons, which [`Shape::edges`] describe.
    pub fn axis(&self) -> Option<Vec3> {
        match self {
            Shape::Plane(s) => Some(s.normal),
            Shape::Disk(s) => Some(s.normal),
            Shape::InfiniteCylinder(s) => Some(s.axis),
            Shape::FiniteCylinder(s) => Some(s.axis),
            Shape::Shell(s) => Some(s.axis),
            Shape::Triangle(_) | Shape::Rectangle(_) => None,
        }
    }

    /// A triangle's or rectangle's edge vectors from its origin (`vertex1`, `vertex2`),
    /// or `None` for the other shapes.
    pub fn edges(&self) -> Option<(Vec3, Vec3)> {
        match self {
            Shape::Triangle(s) => Some((s.e1, s.e2)),
            Shape::Rectangle(s) => Some((s.e1, s.e2)),
            _ => None,
        }
    }

    /// Whether the shape is unbounded: a plane or an infinite cylinder.
    pub fn is_infinite(&self) -> bool {
        matches!(self, Shape::Plane(_) | Shape::InfiniteCylinder(_))
    }

    /// The same shape with its origin moved to `origin` (its position at some time).
    pub fn at(&self, origin: Vec3) -> Shape {
        let mut moved = self.clone();
        match &mut moved {
            Shape::Plane(s) => s.origin = origin,
            Shape::Triangle(s) => s.origin = origin,
            Shape::Rectangle(s) => s.origin = origin,
            Shape::InfiniteCylinder(s) => s.origin = origin,
            Shape::Disk(s) => s.center = origin,
            Shape::FiniteCylinder(s) => s.center = origin,
            Shape::Shell(s) => s.center = origin,
        }
        moved
    }

    /// The shape in coordinates (p − `centre`)/`size`: every point moved and every
    /// length divided, directions kept. POV-Ray needs numbers near 1 (ssdraw's
    /// "Renormalize?"): a 5 cm tube in AU is 3.7e-13 long.
    pub fn renormalised(&self, centre: &Vec3, size: f64) -> Shape {
        let p = |q: &Vec3| (q - centre) / size;
        let mut s = self.clone();
        match &mut s {
            Shape::Plane(s) => s.origin = p(&s.origin),
            Shape::Triangle(s) => (s.origin, s.e1, s.e2) = (p(&s.origin), s.e1 / size, s.e2 / size),
            Shape::Rectangle(s) => {
                (s.origin, s.e1, s.e2) = (p(&s.origin), s.e1 / size, s.e2 / size)
            }
            Shape::InfiniteCylinder(s) => (s.origin, s.radius) = (p(&s.origin), s.radius / size),
            Shape::Disk(s) => {
                (s.center, s.radius, s.hole) = (p(&s.center), s.radius / size, s.hole / size)
            }
            Shape::FiniteCylinder(s) => {
                (s.center, s.radius, s.length) = (p(&s.center), s.radius / size, s.length / size)
            }
            Shape::Shell(s) => (s.center, s.radius) = (p(&s.center), s.radius / size),
        }
        s
    }

    /// The shape with its origin at `origin` and its directions (orient, vertex1,
    /// vertex2) turned by `turn`: a reactive wall, which its assembly has rotated since
    /// the start.
    pub fn turned(&self, origin: Vec3, turn: &Rotation3<f64>) -> Shape {
        let mut moved = self.at(origin);
        match &mut moved {
            Shape::Plane(s) => s.normal = turn * s.normal,
            Shape::Disk(s) => s.normal = turn * s.normal,
            Shape::InfiniteCylinder(s) => s.axis = turn * s.axis,
            Shape::FiniteCylinder(s) => s.axis = turn * s.axis,
            Shape::Shell(s) => s.axis = turn * s.axis,
            Shape::Triangle(s) => (s.e1, s.e2) = (turn * s.e1, turn * s.e2),
            Shape::Rectangle(s) => (s.e1, s.e2) = (turn * s.e1, turn * s.e2),
        }
        moved
    }

    /// A rough box around the shape's finite part, `(lo, hi)`, from which the scene's
    /// size is taken ([`crate::scene_bounds`]): a polygon's corners (for a triangle,
    /// those of the parallelogram on its edges), a round shape's centre ± its radius (a
    /// finite cylinder's ± the larger of its radius and half its length), and a plane's
    /// or infinite cylinder's origin alone (± the radius for the cylinder).
    pub fn extent(&self) -> (Vec3, Vec3) {
        each!(self, s => s.extent())
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
            Shape::Plane(_) | Shape::InfiniteCylinder(_) => None,
            Shape::Triangle(s) => s.bounds(),
            Shape::Rectangle(s) => s.bounds(),
            Shape::Disk(s) => s.bounds(),
            Shape::FiniteCylinder(s) => s.bounds(),
            Shape::Shell(s) => s.bounds(),
        }
    }

    /// The nearest point of the shape to `p`.
    #[inline]
    pub fn nearest(&self, p: &Vec3) -> Nearest {
        each!(self, s => s.nearest(p))
    }

    /// Whether pkdgrav's hard-sphere code handles the shape: not triangles, shells or
    /// tapered cylinders (its collision code asserts on them).
    pub fn hard_sphere_supported(&self) -> bool {
        match self {
            Shape::Triangle(_) | Shape::Shell(_) => false,
            Shape::FiniteCylinder(s) => s.taper == 0.0,
            _ => true,
        }
    }

    /// When, within `[0, t_max]`, a sphere of radius `r` at `p` moving in a straight
    /// line at `d` relative to the wall first touches the shape, and where (docs/spec.md
    /// §3 "HSDEM"): faces by a linear equation, cylinder sides, segment edges and points
    /// by a quadratic, rings (disk rims, hole rims, cylinder ends) by a quartic
    /// ([`crate::impact`]). With `edges` off (pkdgrav's `bWallsEdgeDetect = 0`) only
    /// faces and sides count. A sphere already touching the shape is not a new contact:
    /// the caller deals with overlaps that exist at the start. Shapes outside
    /// [`Shape::hard_sphere_supported`] give `None`.
    pub fn first_hit(&self, p: &Vec3, d: &Vec3, r: f64, t_max: f64, edges: bool) -> Option<Hit> {
        let mut best = Earliest::new(t_max);
        let ray = Ray { p, d, r, t_max };
        match self {
            Shape::Plane(s) => s.hit(&ray, &mut best),
            Shape::Rectangle(s) => s.hit(&ray, edges, &mut best),
            Shape::Disk(s) => s.hit(&ray, edges, &mut best),
            Shape::InfiniteCylinder(s) => s.hit(&ray, &mut best),
            Shape::FiniteCylinder(s) => s.hit(&ray, edges, &mut best),
            Shape::Triangle(_) | Shape::Shell(_) => {}
        }
        best.hit
    }

    /// The shape as triangles, for previews: `scene` is the box around the scene's
    /// finite walls ([`crate::scene_bounds`]), which cuts planes and infinite cylinders,
    /// and `segments` the number of segments around round shapes (at least 3). Shapes
    /// of no area (zero radius, zero length, opening 180°) give empty meshes. Each
    /// triangle's vertices run counter-clockwise seen from the side its `orient` (or
    /// vertex1 × vertex2) points to, and outwards for cylinders and shells.
    pub fn tessellate(&self, scene: &(Vec3, Vec3), segments: usize) -> Mesh {
        let segments = segments.max(3);
        let mut m = Mesh::default();
        match self {
            Shape::Plane(s) => s.tessellate(&mut m, scene),
            Shape::Triangle(s) => s.tessellate(&mut m),
            Shape::Rectangle(s) => s.tessellate(&mut m),
            Shape::Disk(s) => s.tessellate(&mut m, segments),
            Shape::InfiniteCylinder(s) => s.tessellate(&mut m, scene, segments),
            Shape::FiniteCylinder(s) => s.tessellate(&mut m, segments),
            Shape::Shell(s) => s.tessellate(&mut m, segments),
        }
        m
    }
}

/// A sphere of radius `r` at `p` moving at `d`, looked at over `[0, t_max]`.
pub(crate) struct Ray<'a> {
    pub(crate) p: &'a Vec3,
    pub(crate) d: &'a Vec3,
    pub(crate) r: f64,
    pub(crate) t_max: f64,
}

/// The earliest contact found so far within the step.
pub(crate) struct Earliest {
    t_max: f64,
    hit: Option<Hit>,
}

impl Earliest {
    fn new(t_max: f64) -> Earliest {
        Earliest { t_max, hit: None }
    }

    /// Keeps a contact at `t` on `feature` if it is within the step and the earliest.
    pub(crate) fn consider(&mut self, t: Option<f64>, feature: Feature) {
        if let Some(t) = t
            && t <= self.t_max
            && self.hit.is_none_or(|b| t < b.t)
        {
            self.hit = Some(Hit { t, feature });
        }
    }
}

/// The box of the parallelogram on edges `e1`, `e2` from `o` (a polygon's extent).
pub(crate) fn parallelogram(o: &Vec3, e1: &Vec3, e2: &Vec3) -> (Vec3, Vec3) {
    let (lo, hi) = corners(&[o + e1, o + e2, o + e1 + e2]);
    let (a, b) = around(o, 0.0);
    (lo.inf(&a), hi.sup(&b))
}

/// The box `o` ± `r` on every axis.
pub(crate) fn around(o: &Vec3, r: f64) -> (Vec3, Vec3) {
    (o - Vec3::repeat(r), o + Vec3::repeat(r))
}

/// The box of a few points.
pub(crate) fn corners(points: &[Vec3]) -> (Vec3, Vec3) {
    points
        .iter()
        .skip(1)
        .fold((points[0], points[0]), |(lo, hi), q| (lo.inf(q), hi.sup(q)))
}

/// The box of the circle of `radius` around `center` perpendicular to `normal`: on
/// axis i it reaches radius·√(1 − nᵢ²) each side, computed as √(n_j² + n_k²)/|n| so
/// that an axis nearly along the normal keeps its few digits. A zero normal (which
/// [`Shape::nearest`] treats as every direction) gets the whole ball.
pub(crate) fn rim_bounds(center: &Vec3, normal: &Vec3, radius: f64) -> (Vec3, Vec3) {
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
#[inline]
pub(crate) fn answer(p: &Vec3, q: Vec3, surface: Vec3, feature: Feature) -> Nearest {
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
#[inline]
pub(crate) fn any_perpendicular(a: &Vec3) -> Vec3 {
    let helper = if a.x.abs() < 0.9 {
        Vec3::x()
    } else {
        Vec3::y()
    };
    direction(&a.cross(&helper)).unwrap_or_else(Vec3::x)
}

/// Nearest point of segment a–b to p, as the parameter t in [0, 1].
#[inline]
pub(crate) fn segment_t(p: &Vec3, a: &Vec3, b: &Vec3) -> f64 {
    let ab = b - a;
    let len2 = ab.norm_squared();
    if len2 == 0.0 {
        return 0.0;
    }
    ((p - a).dot(&ab) / len2).clamp(0.0, 1.0)
}

/// A point on the axis of a ring is as near to every point of it: the contact is the
/// whole ring, and its net normal runs along the axis, towards the point's side
/// (`side` > 0: along `axis`). Without this the normal would lean to an arbitrary rim
/// point and push a particle dropped down the axis sideways.
#[inline]
pub(crate) fn on_axis(near: Nearest, symmetric: bool, axis: &Vec3, side: f64) -> Nearest {
    if !symmetric {
        return near;
    }
    Nearest {
        normal: if side < 0.0 { -axis } else { *axis },
        ..near
    }
}
