//! Triangle meshes of walls for previews ([`crate::Shape::tessellate`]), and the pieces
//! the round shapes are built from: flat rings and open cones.

use nalgebra::Vector3;
use walls_model::direction;

type Vec3 = Vector3<f64>;

/// Triangles over shared vertices.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Mesh {
    /// The vertices.
    pub positions: Vec<Vec3>,
    /// Each triangle as three indices into `positions`.
    pub triangles: Vec<[u32; 3]>,
}

impl Mesh {
    pub(crate) fn vertex(&mut self, p: Vec3) -> u32 {
        self.positions.push(p);
        (self.positions.len() - 1) as u32
    }

    pub(crate) fn quad(&mut self, a: u32, b: u32, c: u32, d: u32) {
        self.triangles.push([a, b, c]);
        self.triangles.push([a, c, d]);
    }
}

/// Two unit vectors perpendicular to unit `n` and to each other, with u × v = n.
pub fn basis(n: &Vec3) -> (Vec3, Vec3) {
    let helper = if n.x.abs() < 0.9 {
        Vec3::x()
    } else {
        Vec3::y()
    };
    let u = direction(&n.cross(&helper)).unwrap_or_else(Vec3::x);
    (u, n.cross(&u))
}

/// The flat ring between radii `inner` and `outer` around `c` in the plane of u and v.
pub(crate) fn ring(
    m: &mut Mesh,
    c: &Vec3,
    u: &Vec3,
    v: &Vec3,
    inner: f64,
    outer: f64,
    segments: usize,
) {
    let at = |k: usize, r: f64| {
        let a = std::f64::consts::TAU * k as f64 / segments as f64;
        c + (u * a.cos() + v * a.sin()) * r
    };
    if inner <= 0.0 {
        let centre = m.vertex(*c);
        let rim: Vec<u32> = (0..segments).map(|k| m.vertex(at(k, outer))).collect();
        for k in 0..segments {
            m.triangles.push([centre, rim[k], rim[(k + 1) % segments]]);
        }
        return;
    }
    let ids: Vec<(u32, u32)> = (0..segments)
        .map(|k| (m.vertex(at(k, inner)), m.vertex(at(k, outer))))
        .collect();
    for k in 0..segments {
        let (a, b) = ids[k];
        let (c2, d) = ids[(k + 1) % segments];
        m.quad(a, b, d, c2);
    }
}

/// The open cone around `c` along `axis` from radius `radii.0` at −length/2 to `radii.1`
/// at +length/2.
#[allow(clippy::too_many_arguments)]
pub(crate) fn tube(
    m: &mut Mesh,
    c: &Vec3,
    axis: &Vec3,
    u: &Vec3,
    v: &Vec3,
    radii: (f64, f64),
    length: f64,
    segments: usize,
) {
    let ids: Vec<(u32, u32)> = (0..segments)
        .map(|k| {
            let a = std::f64::consts::TAU * k as f64 / segments as f64;
            let out = u * a.cos() + v * a.sin();
            (
                m.vertex(c - axis * (length / 2.0) + out * radii.0),
                m.vertex(c + axis * (length / 2.0) + out * radii.1),
            )
        })
        .collect();
    for k in 0..segments {
        let (a, b) = ids[k];
        let (c2, d) = ids[(k + 1) % segments];
        m.quad(a, c2, d, b);
    }
}
