//! The rectangle spanned from its origin by perpendicular vertex1 and vertex2: nearest
//! point on its face, edges or corners, its box, its contact in the hard-sphere model,
//! and its two mesh triangles.

use super::{Earliest, Feature, Nearest, Ray, answer, corners, parallelogram};
use crate::impact::{point_entry, segment_entry, slab_entry};
use crate::mesh::Mesh;
use nalgebra::Vector3;
use walls_model::direction;

type Vec3 = Vector3<f64>;

/// The rectangle spanned from `origin` by perpendicular `e1` and `e2`.
#[derive(Debug, Clone, PartialEq)]
pub struct Rectangle {
    /// One corner (`origin`).
    pub origin: Vec3,
    /// One edge from it (`vertex1`).
    pub e1: Vec3,
    /// The other edge from it (`vertex2`).
    pub e2: Vec3,
}

impl Rectangle {
    /// The box of its four corners, or `None` when an edge is zero.
    pub fn bounds(&self) -> Option<(Vec3, Vec3)> {
        let (origin, e1, e2) = (&self.origin, &self.e1, &self.e2);
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

    /// The scene's extent: its four corners.
    pub fn extent(&self) -> (Vec3, Vec3) {
        parallelogram(&self.origin, &self.e1, &self.e2)
    }

    /// The nearest point of the rectangle to `p`: on its face, an edge or a corner.
    #[inline]
    pub fn nearest(&self, p: &Vec3) -> Nearest {
        let (o, e1, e2) = (&self.origin, &self.e1, &self.e2);
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

    /// A sphere reaching the rectangle's face, or with `edges` its edges and corners.
    pub(crate) fn hit(&self, ray: &Ray, edges: bool, best: &mut Earliest) {
        let (origin, e1, e2) = (&self.origin, &self.e1, &self.e2);
        let (p, d, r) = (ray.p, ray.d, ray.r);
        let normal = e1.cross(e2).normalize();
        let (l1, l2) = (e1.norm(), e2.norm());
        let (u1, u2) = (e1 / l1, e2 / l2);
        let t = slab_entry(p, d, r, origin, &normal).filter(|t| {
            let q = p + d * *t - origin;
            (0.0..=l1).contains(&u1.dot(&q)) && (0.0..=l2).contains(&u2.dot(&q))
        });
        best.consider(t, Feature::Face);
        if edges {
            // Walked origin → +e1 → +e1+e2 → +e2, edge k runs from corner k: the
            // numbering of [`Feature::Edge`].
            let corners = [*origin, origin + e1, origin + e1 + e2, origin + e2];
            let vertex_number = [0, 1, 3, 2];
            for k in 0..4 {
                let (a, b) = (corners[k], corners[(k + 1) % 4]);
                best.consider(segment_entry(p, d, r, &a, &b), Feature::Edge(k as u8));
                best.consider(point_entry(p, d, r, &a), Feature::Vertex(vertex_number[k]));
            }
        }
    }

    /// The rectangle as two triangles.
    pub(crate) fn tessellate(&self, m: &mut Mesh) {
        let (o, a, b) = (&self.origin, &self.e1, &self.e2);
        let ids = [*o, o + a, o + a + b, o + b].map(|p| m.vertex(p));
        m.quad(ids[0], ids[1], ids[2], ids[3]);
    }
}
