//! A cheap, conservative test of whether a point is out of a wall's reach, before any
//! nearest-point query: the soft-sphere run asks it for every particle and wall on every
//! step, and most answers are "clear". A plane is one dot product (its slab); a finite
//! shape is its box ([`Shape::bounds`]); an infinite cylinder is the distance from its
//! axis, squared. The test never says "clear" of a point the shape's nearest point is
//! within the reach of (the tests in `tests/cull.rs` check it against
//! [`Shape::nearest`] on every shape).

use super::Shape;
use nalgebra::Vector3;

type Vec3 = Vector3<f64>;

/// The relative margin every test keeps, so that round-off in it never hides a point
/// that the nearest-point query would find within reach.
const MARGIN: f64 = 1e-9;

/// What the cheap test of one shape needs, worked out once per placement of the shape.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Cull {
    /// Within reach only inside the slab |n·(p − origin)| ≤ reach (a plane).
    Slab {
        /// A point of the plane.
        origin: Vec3,
        /// Its unit normal.
        normal: Vec3,
    },
    /// Within reach only inside the box (lo, hi) grown by the reach (a finite shape).
    Box {
        /// The box's lower corner.
        lo: Vec3,
        /// Its upper corner.
        hi: Vec3,
    },
    /// Within reach only where the distance ρ from the axis is within reach of the
    /// radius (an infinite cylinder).
    Tube {
        /// A point of the axis.
        origin: Vec3,
        /// The axis's unit direction.
        axis: Vec3,
        /// The radius.
        radius: f64,
    },
    /// No cheap test: always ask the nearest-point query.
    Never,
}

impl Cull {
    /// The cheap test for `shape` where it stands.
    pub fn of(shape: &Shape) -> Cull {
        match shape {
            Shape::Plane(s) if s.normal != Vec3::zeros() => Cull::Slab {
                origin: s.origin,
                normal: s.normal,
            },
            Shape::InfiniteCylinder(s) if s.axis != Vec3::zeros() => Cull::Tube {
                origin: s.origin,
                axis: s.axis,
                radius: s.radius.abs(),
            },
            _ => match shape.bounds() {
                Some((lo, hi)) => Cull::Box { lo, hi },
                None => Cull::Never,
            },
        }
    }

    /// Whether `p` is surely farther than `reach` from the shape (`false` when unsure).
    /// Inlined always: the evaluator's drift asks it for every particle near a wall,
    /// every step.
    #[inline(always)]
    pub fn clear_of(&self, p: &Vec3, reach: f64) -> bool {
        match self {
            Cull::Slab { origin, normal } => {
                let h = normal.dot(&(p - origin)).abs();
                h > reach * (1.0 + MARGIN) + h * MARGIN
            }
            Cull::Box { lo, hi } => {
                let out = |x: f64, lo: f64, hi: f64| {
                    let grow = reach * (1.0 + MARGIN) + (lo.abs() + hi.abs()) * MARGIN;
                    x < lo - grow || x > hi + grow
                };
                out(p.x, lo.x, hi.x) || out(p.y, lo.y, hi.y) || out(p.z, lo.z, hi.z)
            }
            Cull::Tube {
                origin,
                axis,
                radius,
            } => {
                let d = p - origin;
                let along = axis.dot(&d);
                let rho2 = (d.norm_squared() - along * along).max(0.0);
                let scale = d.norm_squared() * MARGIN;
                let far = radius + reach * (1.0 + MARGIN);
                let near = radius - reach * (1.0 + MARGIN);
                rho2 > far * far + scale || (near > 0.0 && rho2 + scale < near * near)
            }
            Cull::Never => false,
        }
    }
}
