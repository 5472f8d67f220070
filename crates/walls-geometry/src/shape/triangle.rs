//! The triangle origin, origin + vertex1, origin + vertex2: nearest point on its face,
//! edges or vertices, its box, and its one mesh triangle. pkdgrav's hard-sphere code
//! does not handle triangles.

use super::{Feature, Nearest, answer, corners, parallelogram, segment_t};
use crate::mesh::Mesh;
use nalgebra::Vector3;
use walls_model::direction;

type Vec3 = Vector3<f64>;

/// The triangle `origin`, `origin + e1`, `origin + e2`.
#[derive(Debug, Clone, PartialEq)]
pub struct Triangle {
    /// Its first vertex (`origin`).
    pub origin: Vec3,
    /// The edge to its second vertex (`vertex1`).
    pub e1: Vec3,
    /// The edge to its third vertex (`vertex2`).
    pub e2: Vec3,
}

impl Triangle {
    /// The box of its three vertices, or `None` when its edges are parallel.
    pub fn bounds(&self) -> Option<(Vec3, Vec3)> {
        let (origin, e1, e2) = (&self.origin, &self.e1, &self.e2);
        direction(&e1.cross(e2))?;
        Some(corners(&[*origin, origin + e1, origin + e2]))
    }

    /// The scene's extent: the corners of the parallelogram on its edges.
    pub fn extent(&self) -> (Vec3, Vec3) {
        parallelogram(&self.origin, &self.e1, &self.e2)
    }

    /// The nearest point of the triangle to `p`: on its face, an edge or a vertex.
    #[inline]
    pub fn nearest(&self, p: &Vec3) -> Nearest {
        let (o, e1, e2) = (&self.origin, &self.e1, &self.e2);
        let normal = direction(&e1.cross(e2)).unwrap_or_else(Vec3::z);
        let (a, b, c) = (*o, o + e1, o + e2);
        // Inside the prism over the face: the projection.
        let ap = p - a;
        let h = normal.dot(&ap);
        let q = p - normal * h;
        let inside = [(a, b), (b, c), (c, a)]
            .iter()
            .all(|(u, v)| (v - u).cross(&(q - u)).dot(&normal) >= 0.0);
        if inside {
            return answer(p, q, normal, Feature::Face);
        }
        // Otherwise the nearest of the three edges (an end of it is a vertex).
        let vertices = [a, b, c];
        let mut best: Option<Nearest> = None;
        for (i, (u, v)) in [(0usize, 1usize), (1, 2), (2, 0)].into_iter().enumerate() {
            let t = segment_t(p, &vertices[u], &vertices[v]);
            let feature = if t == 0.0 {
                Feature::Vertex(u as u8)
            } else if t == 1.0 {
                Feature::Vertex(v as u8)
            } else {
                Feature::Edge(i as u8)
            };
            let q = vertices[u] + (vertices[v] - vertices[u]) * t;
            let n = answer(p, q, normal, feature);
            if best.is_none_or(|b| n.distance < b.distance) {
                best = Some(n);
            }
        }
        best.expect("a triangle has edges")
    }

    /// The triangle itself.
    pub(crate) fn tessellate(&self, m: &mut Mesh) {
        let (o, a, b) = (&self.origin, &self.e1, &self.e2);
        let ids = [*o, o + a, o + b].map(|p| m.vertex(p));
        m.triangles.push(ids);
    }
}
