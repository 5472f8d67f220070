//! The disk: a flat ring between its hole and its rim around its origin, facing
//! `orient`. Nearest point on its face, rim or hole rim; its box (the rim circle's);
//! contact in the hard-sphere model (rims by the ray–torus quartic); mesh as a ring of
//! quads (a fan without a hole).

use super::{
    Earliest, Feature, Nearest, Ray, answer, any_perpendicular, around, on_axis, rim_bounds,
};
use crate::impact::{point_entry, ring_entry, slab_entry};
use crate::mesh::{Mesh, basis, ring};
use nalgebra::Vector3;
use walls_model::direction;

type Vec3 = Vector3<f64>;

/// A disk of `radius` with a hole of `hole` around `center`, facing `normal`.
#[derive(Debug, Clone, PartialEq)]
pub struct Disk {
    /// Its centre (`origin`).
    pub center: Vec3,
    /// Its unit normal (`orient`).
    pub normal: Vec3,
    /// Its radius.
    pub radius: f64,
    /// The radius of its hole (`hole-radius`).
    pub hole: f64,
}

impl Disk {
    /// The box of its rim circle (the hole does not narrow it).
    pub fn bounds(&self) -> Option<(Vec3, Vec3)> {
        Some(rim_bounds(&self.center, &self.normal, self.radius.abs()))
    }

    /// The scene's extent: its centre ± its radius.
    pub fn extent(&self) -> (Vec3, Vec3) {
        around(&self.center, self.radius)
    }

    /// The nearest point of the disk to `p`: on its face, rim or hole rim (a point when
    /// its radius is 0).
    #[inline]
    pub fn nearest(&self, p: &Vec3) -> Nearest {
        let (c, n, radius, hole) = (&self.center, &self.normal, self.radius, self.hole);
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

    /// A sphere reaching the disk's face between its hole and rim, or with `edges` its rim
    /// and its hole's rim (a disk of radius 0 is a point).
    pub(crate) fn hit(&self, ray: &Ray, edges: bool, best: &mut Earliest) {
        let (center, normal, radius, hole) = (&self.center, &self.normal, self.radius, self.hole);
        let (p, d, r, t_max) = (ray.p, ray.d, ray.r, ray.t_max);
        if radius == 0.0 {
            best.consider(point_entry(p, d, r, center), Feature::Point);
            return;
        }
        let t = slab_entry(p, d, r, center, normal).filter(|t| {
            let q = p + d * *t - center;
            let rho = (q - normal * normal.dot(&q)).norm();
            hole <= rho && rho <= radius
        });
        best.consider(t, Feature::Face);
        if edges {
            best.consider(
                ring_entry(p, d, r, center, normal, radius, t_max),
                Feature::Rim(0),
            );
            if hole > 0.0 {
                best.consider(
                    ring_entry(p, d, r, center, normal, hole, t_max),
                    Feature::HoleRim,
                );
            }
        }
    }

    /// The ring between the hole and the rim (nothing for a disk of radius 0).
    pub(crate) fn tessellate(&self, m: &mut Mesh, segments: usize) {
        let (o, axis, radius, hole) = (&self.center, &self.normal, self.radius, self.hole);
        if radius > 0.0 {
            let (u, v) = basis(axis);
            ring(m, o, &u, &v, hole.min(radius), radius, segments);
        }
    }
}
