//! The shell: a sphere of `radius` around its origin without the cap within
//! `open-angle` of `orient`. Nearest point on its sphere or opening rim; its box is the
//! whole sphere; mesh as latitude rings from the opening down to the opposite pole.
//! pkdgrav's hard-sphere code does not handle shells.

use super::{Feature, Nearest, answer, any_perpendicular, around};
use crate::mesh::{Mesh, basis};
use nalgebra::Vector3;
use walls_model::direction;

type Vec3 = Vector3<f64>;

/// A sphere of `radius` around `center` minus the cap within `open` radians of `axis`.
#[derive(Debug, Clone, PartialEq)]
pub struct Shell {
    /// Its centre (`origin`).
    pub center: Vec3,
    /// The unit axis of its opening (`orient`).
    pub axis: Vec3,
    /// Its radius.
    pub radius: f64,
    /// The opening's half-angle in radians (`open-angle`, given in degrees).
    pub open: f64,
}

impl Shell {
    /// The box of its whole sphere.
    pub fn bounds(&self) -> Option<(Vec3, Vec3)> {
        let r = Vec3::repeat(self.radius.abs());
        Some((self.center - r, self.center + r))
    }

    /// The scene's extent: its centre ± its radius.
    pub fn extent(&self) -> (Vec3, Vec3) {
        around(&self.center, self.radius)
    }

    /// The nearest point of the shell to `p`: on its sphere or its opening's rim (a point
    /// when its radius is 0 or its opening 180°).
    #[inline]
    pub fn nearest(&self, p: &Vec3) -> Nearest {
        let (c, axis, radius, open) = (&self.center, &self.axis, self.radius, self.open);
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
        let sideways =
            direction(&(u - axis * axis.dot(&u))).unwrap_or_else(|| any_perpendicular(axis));
        let q = c + (axis * open.cos() + sideways * open.sin()) * radius;
        let feature = if open >= std::f64::consts::PI {
            Feature::Point
        } else {
            Feature::Rim(0)
        };
        answer(p, q, u, feature)
    }

    /// The sphere without its cap (nothing for radius 0 or an opening of 180°).
    pub(crate) fn tessellate(&self, m: &mut Mesh, segments: usize) {
        let (o, axis, radius, open) = (&self.center, &self.axis, self.radius, self.open);
        if radius > 0.0 && open < std::f64::consts::PI {
            let (u, v) = basis(axis);
            cap(m, o, axis, &u, &v, radius, open, segments);
        }
    }
}

/// The sphere of `radius` around `c` without the cap within `open` of `axis`: latitude
/// rings from the opening's rim down to the pole opposite it.
#[allow(clippy::too_many_arguments)]
fn cap(
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
