//! The disk: a flat ring between its hole and its rim around its origin, facing
//! `orient`. Nearest point on its face, rim or hole rim; contact in the hard-sphere
//! model (rims by the ray–torus quartic); mesh as a ring of quads (a fan without a
//! hole). Its box is the rim circle's ([`super::rim_bounds`]).

use super::{Earliest, Feature, Nearest, Ray, answer, any_perpendicular, on_axis};
use crate::impact::{point_entry, ring_entry, slab_entry};
use crate::mesh::{Mesh, basis, ring};
use nalgebra::Vector3;
use walls_model::direction;

type Vec3 = Vector3<f64>;

pub(crate) fn nearest(p: &Vec3, c: &Vec3, n: &Vec3, radius: f64, hole: f64) -> Nearest {
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
#[allow(clippy::too_many_arguments)]
pub(crate) fn hit(
    ray: &Ray,
    center: &Vec3,
    normal: &Vec3,
    radius: f64,
    hole: f64,
    edges: bool,
    best: &mut Earliest,
) {
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
pub(crate) fn tessellate(
    m: &mut Mesh,
    o: &Vec3,
    axis: &Vec3,
    radius: f64,
    hole: f64,
    segments: usize,
) {
    if radius > 0.0 {
        let (u, v) = basis(axis);
        ring(m, o, &u, &v, hole.min(radius), radius, segments);
    }
}
