//! The finite cylinder and the cone (`taper` > 0): an open tube centred on its origin
//! along `orient`, radius R at −length/2 narrowing to R(1 − taper) at +length/2.
//! Nearest point on its side or end rims; its box over both rims; contact in the
//! hard-sphere model (untapered only, as pkdgrav); mesh as an open cone.

use super::{
    Earliest, Feature, Nearest, Ray, answer, any_perpendicular, around, on_axis, rim_bounds,
    segment_t,
};
use crate::impact::{point_entry, ring_entry, side_entry};
use crate::mesh::{Mesh, basis, tube};
use nalgebra::Vector3;
use walls_model::direction;

type Vec3 = Vector3<f64>;

/// A finite open tube centred on `center` along `axis`: radius `radius` at −length/2
/// narrowing to radius·(1 − taper) at +length/2.
#[derive(Debug, Clone, PartialEq)]
pub struct FiniteCylinder {
    /// Its centre (`origin`).
    pub center: Vec3,
    /// Its unit axis (`orient`).
    pub axis: Vec3,
    /// Its radius at −length/2.
    pub radius: f64,
    /// Its length.
    pub length: f64,
    /// How much it narrows towards +length/2 (0: a cylinder, 1: a cone to a point).
    pub taper: f64,
}

impl FiniteCylinder {
    /// The box of its two end rims (its side lies between them).
    pub fn bounds(&self) -> Option<(Vec3, Vec3)> {
        let (center, axis, radius, length, taper) = (
            &self.center,
            &self.axis,
            self.radius,
            self.length,
            self.taper,
        );
        let half = axis * (length / 2.0);
        let (lo0, hi0) = rim_bounds(&(center - half), axis, radius.abs());
        let (lo1, hi1) = rim_bounds(&(center + half), axis, (radius * (1.0 - taper)).abs());
        Some((lo0.inf(&lo1), hi0.sup(&hi1)))
    }

    /// The scene's extent: its centre ± the larger of its radius and half its length.
    pub fn extent(&self) -> (Vec3, Vec3) {
        around(&self.center, self.radius.max(self.length / 2.0))
    }

    /// A finite cylinder or cone, reduced to the nearest point of a segment in the half-plane
    /// through the axis and p.
    #[inline]
    pub fn nearest(&self, p: &Vec3) -> Nearest {
        let (c, axis, radius, length, taper) = (
            &self.center,
            &self.axis,
            self.radius,
            self.length,
            self.taper,
        );
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

    /// A sphere reaching the untapered tube's side, or with `edges` its end rims (points
    /// for radius 0). pkdgrav's hard-sphere code has no tapered cylinders: they give
    /// nothing.
    pub(crate) fn hit(&self, ray: &Ray, edges: bool, best: &mut Earliest) {
        if self.taper != 0.0 {
            return;
        }
        let (center, axis, radius, length) = (&self.center, &self.axis, self.radius, self.length);
        let (p, d, r, t_max) = (ray.p, ray.d, ray.r, ray.t_max);
        let half = length / 2.0;
        best.consider(
            side_entry(p, d, r, center, axis, radius, half),
            Feature::Side,
        );
        if edges {
            for (k, end) in [-half, half].into_iter().enumerate() {
                let c = center + axis * end;
                let t = if radius == 0.0 {
                    point_entry(p, d, r, &c)
                } else {
                    ring_entry(p, d, r, &c, axis, radius, t_max)
                };
                best.consider(t, Feature::Rim(k as u8));
            }
        }
    }

    /// The open cone (nothing for radius or length 0).
    pub(crate) fn tessellate(&self, m: &mut Mesh, segments: usize) {
        let (o, axis, radius, length, taper) = (
            &self.center,
            &self.axis,
            self.radius,
            self.length,
            self.taper,
        );
        let top = radius * (1.0 - taper);
        if radius > 0.0 && length > 0.0 {
            let (u, v) = basis(axis);
            tube(m, o, axis, &u, &v, (radius, top), length, segments);
        }
    }
}
