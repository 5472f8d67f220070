//! The infinite cylinder: a tube of `radius` around the line through its origin along
//! `orient` (a line when the radius is 0). Nearest point on its side; contact in the
//! hard-sphere model from outside or inside; for previews the tube cut to the scene's box
//! along its axis. It has no box of its own.

use super::{Earliest, Feature, Nearest, Ray, answer, any_perpendicular, around};
use crate::impact::side_entry;
use crate::mesh::{Mesh, basis, tube};
use nalgebra::Vector3;
use walls_model::direction;

type Vec3 = Vector3<f64>;

/// An infinite tube of `radius` around the line through `origin` along `axis`.
#[derive(Debug, Clone, PartialEq)]
pub struct InfiniteCylinder {
    /// A point of its axis (`origin`).
    pub origin: Vec3,
    /// Its unit axis (`orient`).
    pub axis: Vec3,
    /// Its radius.
    pub radius: f64,
}

impl InfiniteCylinder {
    /// The scene's extent: its origin ± its radius.
    pub fn extent(&self) -> (Vec3, Vec3) {
        around(&self.origin, self.radius)
    }

    /// The nearest point of the tube to `p`.
    #[inline]
    pub fn nearest(&self, p: &Vec3) -> Nearest {
        let (origin, axis, radius) = (&self.origin, &self.axis, self.radius);
        let d = p - origin;
        let along = axis * axis.dot(&d);
        let radial = d - along;
        if radius == 0.0 {
            let q = origin + along;
            return answer(p, q, any_perpendicular(axis), Feature::Side);
        }
        let out = direction(&radial).unwrap_or_else(|| any_perpendicular(axis));
        answer(p, origin + along + out * radius, -out, Feature::Side)
    }

    /// A sphere reaching the tube's side.
    pub(crate) fn hit(&self, ray: &Ray, best: &mut Earliest) {
        let (origin, axis, radius) = (&self.origin, &self.axis, self.radius);
        best.consider(
            side_entry(ray.p, ray.d, ray.r, origin, axis, radius, f64::INFINITY),
            Feature::Side,
        );
    }

    /// The tube cut to the scene's box `bounds` along its axis: from the box's lowest
    /// to its highest corner along the axis (nothing for radius 0).
    pub(crate) fn tessellate(&self, m: &mut Mesh, bounds: &(Vec3, Vec3), segments: usize) {
        let (o, axis, radius) = (&self.origin, &self.axis, self.radius);
        if radius > 0.0 {
            let (lo, hi) = bounds;
            let (mut low, mut high) = (f64::INFINITY, f64::NEG_INFINITY);
            for k in 0..8 {
                let corner = Vec3::new(
                    if k & 1 == 0 { lo.x } else { hi.x },
                    if k & 2 == 0 { lo.y } else { hi.y },
                    if k & 4 == 0 { lo.z } else { hi.z },
                );
                let h = axis.dot(&(corner - o));
                (low, high) = (low.min(h), high.max(h));
            }
            let (u, v) = basis(axis);
            let c = o + axis * ((low + high) / 2.0);
            tube(m, &c, axis, &u, &v, (radius, radius), high - low, segments);
        }
    }
}
