//! The plane: an infinite flat face through its origin with unit normal `orient`.
//! Nearest point by projection, contact by the slab entry, and for previews the polygon
//! where it cuts the scene's box (a square of twice the scene's size when it misses it).
//! It has no box.

use super::{Earliest, Feature, Nearest, Ray, answer, around};
use crate::impact::slab_entry;
use crate::mesh::{Mesh, basis};
use nalgebra::Vector3;

type Vec3 = Vector3<f64>;

/// An infinite plane through `origin` with unit `normal` (`orient`).
#[derive(Debug, Clone, PartialEq)]
pub struct Plane {
    /// A point of the plane (`origin`).
    pub origin: Vec3,
    /// Its unit normal (`orient`; zero when degenerate).
    pub normal: Vec3,
}

impl Plane {
    /// The nearest point of the plane to `p`.
    #[inline]
    pub fn nearest(&self, p: &Vec3) -> Nearest {
        let (origin, normal) = (&self.origin, &self.normal);
        let h = normal.dot(&(p - origin));
        answer(p, p - normal * h, *normal, Feature::Face)
    }

    /// The scene's extent: its origin alone.
    pub fn extent(&self) -> (Vec3, Vec3) {
        around(&self.origin, 0.0)
    }

    /// A sphere reaching the plane.
    pub(crate) fn hit(&self, ray: &Ray, best: &mut Earliest) {
        let (origin, normal) = (&self.origin, &self.normal);
        best.consider(
            slab_entry(ray.p, ray.d, ray.r, origin, normal),
            Feature::Face,
        );
    }

    /// The plane cut to the scene's box `bounds`, or a square of twice the scene's size
    /// centred where the scene's centre projects onto it when it misses the box.
    pub(crate) fn tessellate(&self, m: &mut Mesh, bounds: &(Vec3, Vec3)) {
        let (o, axis) = (&self.origin, &self.normal);
        let centre = &((bounds.0 + bounds.1) / 2.0);
        let size = (bounds.1 - bounds.0).max();
        let (u, v) = basis(axis);
        let polygon = clipped_plane(o, axis, &u, &v, bounds).unwrap_or_else(|| {
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
