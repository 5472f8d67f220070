//! The infinite cylinder: a tube of `radius` around the line through its origin along
//! `orient` (a line when the radius is 0). Nearest point on its side; contact in the
//! hard-sphere model from outside or inside; for previews a tube twice the scene's size
//! long, centred where the scene's centre projects onto its axis. It has no box.

use super::{Earliest, Feature, Nearest, Ray, answer, any_perpendicular};
use crate::impact::side_entry;
use crate::mesh::{Mesh, basis, tube};
use nalgebra::Vector3;
use walls_model::direction;

type Vec3 = Vector3<f64>;

/// The nearest point of the tube to `p`.
pub(crate) fn nearest(p: &Vec3, origin: &Vec3, axis: &Vec3, radius: f64) -> Nearest {
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
pub(crate) fn hit(ray: &Ray, origin: &Vec3, axis: &Vec3, radius: f64, best: &mut Earliest) {
    best.consider(
        side_entry(ray.p, ray.d, ray.r, origin, axis, radius, f64::INFINITY),
        Feature::Side,
    );
}

/// A tube twice the scene's size long (nothing for radius 0).
pub(crate) fn tessellate(
    m: &mut Mesh,
    o: &Vec3,
    axis: &Vec3,
    radius: f64,
    bounds: &(Vec3, Vec3),
    segments: usize,
) {
    if radius > 0.0 {
        let centre = (bounds.0 + bounds.1) / 2.0;
        let size = (bounds.1 - bounds.0).max();
        let (u, v) = basis(axis);
        let c = o + axis * axis.dot(&(centre - o));
        tube(m, &c, axis, &u, &v, (radius, radius), 2.0 * size, segments);
    }
}
