//! The hard-sphere (HSDEM) collision of a particle with a wall or another particle
//! (SPEC §3): when, within a step, a particle moving in a straight line first touches a
//! wall's face, side, edge, corner or rim, and how it bounces.
//!
//! Bounce, with u the velocity of the particle's contact point relative to the wall and
//! n̂ the normal: v′ = v − (1 + εn)·u_n − (2/7)(1 − εt)·u_t and
//! ω′ = ω − (5/(7R²))(1 − εt)·((−R·n̂) × u).

use crate::geometry::{Feature, Shape};
use nalgebra::Vector3;

type Vec3 = Vector3<f64>;

/// A particle's velocity and spin after bouncing off a wall.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bounce {
    /// Velocity after.
    pub velocity: Vec3,
    /// Spin after.
    pub spin: Vec3,
}

/// The bounce of a particle of radius `r` with velocity `v` and spin `w` off a wall whose
/// material at the contact moves at `wall_velocity`, along unit normal `n` (from the wall
/// to the particle), with restitution `eps_n`, `eps_t`.
pub fn bounce(
    r: f64,
    v: &Vec3,
    w: &Vec3,
    wall_velocity: &Vec3,
    n: &Vec3,
    eps_n: f64,
    eps_t: f64,
) -> Bounce {
    let arm = -n * r;
    let u = v + w.cross(&arm) - wall_velocity;
    let un = n * n.dot(&u);
    let ut = u - un;
    Bounce {
        velocity: v - un * (1.0 + eps_n) - ut * (2.0 / 7.0 * (1.0 - eps_t)),
        spin: w - arm.cross(&u) * (5.0 / (7.0 * r * r) * (1.0 - eps_t)),
    }
}

/// A sphere's mass, radius, velocity and spin.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Body {
    /// Mass.
    pub mass: f64,
    /// Radius.
    pub radius: f64,
    /// Velocity.
    pub velocity: Vec3,
    /// Spin.
    pub spin: Vec3,
}

/// The collision of two solid spheres touching along unit `n` (from `b` to `a`): the
/// same rule with the reduced mass (Richardson 1994). The factor 2/7 holds for any pair
/// of solid spheres, since each one's tangential response is 1/m + R²/I = 7/(2m).
pub fn pair_bounce(a: &Body, b: &Body, n: &Vec3, eps_n: f64, eps_t: f64) -> (Bounce, Bounce) {
    let (arm_a, arm_b) = (-n * a.radius, n * b.radius);
    let u = a.velocity + a.spin.cross(&arm_a) - b.velocity - b.spin.cross(&arm_b);
    let un = n * n.dot(&u);
    let ut = u - un;
    // An infinite mass (a particle stuck to a wall) is a wall to the other.
    let reduced = if b.mass.is_infinite() {
        a.mass
    } else {
        a.mass * b.mass / (a.mass + b.mass)
    };
    // The impulse on a; b gets the opposite.
    let normal = -un * (reduced * (1.0 + eps_n));
    let tangential = -ut * (reduced * 2.0 / 7.0 * (1.0 - eps_t));
    let impulse = normal + tangential;
    let turn = |arm: &Vec3, j: &Vec3, body: &Body| {
        body.spin + arm.cross(j) / (0.4 * body.mass * body.radius * body.radius)
    };
    (
        Bounce {
            velocity: a.velocity + impulse / a.mass,
            spin: turn(&arm_a, &tangential, a),
        },
        Bounce {
            velocity: b.velocity - impulse / b.mass,
            spin: turn(&arm_b, &-tangential, b),
        },
    )
}

/// A predicted contact: when it begins, and on which feature of the shape.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Hit {
    /// Time from the start of the prediction.
    pub t: f64,
    /// The feature touched.
    pub feature: Feature,
}

/// Whether pkdgrav's hard-sphere code handles `shape`: not triangles, shells or tapered
/// cylinders (its collision code asserts on them).
pub fn supported(shape: &Shape) -> bool {
    match shape {
        Shape::Triangle { .. } | Shape::Shell { .. } => false,
        Shape::FiniteCylinder { taper, .. } => *taper == 0.0,
        _ => true,
    }
}

/// When, within `[0, t_max]`, a sphere of radius `r` at `p` moving in a straight line at
/// `d` relative to the wall first touches `shape`, and where (SPEC §3 "HSDEM"): faces by
/// a linear equation, cylinder sides, segment edges and points by a quadratic, rings
/// (disk rims, hole rims, cylinder ends) by a quartic. With `edges` off (pkdgrav's
/// `bWallsEdgeDetect = 0`) only faces and sides count. A sphere already touching the
/// shape is not a new contact: the caller deals with overlaps that exist at the start.
/// Shapes outside [`supported`] give `None`.
pub fn first_hit(
    shape: &Shape,
    p: &Vec3,
    d: &Vec3,
    r: f64,
    t_max: f64,
    edges: bool,
) -> Option<Hit> {
    let mut best: Option<Hit> = None;
    let mut consider = |t: Option<f64>, feature: Feature| {
        if let Some(t) = t
            && t <= t_max
            && best.is_none_or(|b| t < b.t)
        {
            best = Some(Hit { t, feature });
        }
    };
    match shape {
        Shape::Plane { origin, normal } => {
            consider(slab_entry(p, d, r, origin, normal), Feature::Face);
        }
        Shape::Rectangle { origin, e1, e2 } => {
            let normal = e1.cross(e2).normalize();
            let (l1, l2) = (e1.norm(), e2.norm());
            let (u1, u2) = (e1 / l1, e2 / l2);
            let t = slab_entry(p, d, r, origin, &normal).filter(|t| {
                let q = p + d * *t - origin;
                (0.0..=l1).contains(&u1.dot(&q)) && (0.0..=l2).contains(&u2.dot(&q))
            });
            consider(t, Feature::Face);
            if edges {
                // Walked origin → +e1 → +e1+e2 → +e2, edge k runs from corner k: the
                // numbering of [`Feature::Edge`].
                let corners = [*origin, origin + e1, origin + e1 + e2, origin + e2];
                let vertex_number = [0, 1, 3, 2];
                for k in 0..4 {
                    let (a, b) = (corners[k], corners[(k + 1) % 4]);
                    consider(segment_entry(p, d, r, &a, &b), Feature::Edge(k as u8));
                    consider(point_entry(p, d, r, &a), Feature::Vertex(vertex_number[k]));
                }
            }
        }
        Shape::Disk {
            center,
            normal,
            radius,
            hole,
        } => {
            if *radius == 0.0 {
                consider(point_entry(p, d, r, center), Feature::Point);
                return best;
            }
            let t = slab_entry(p, d, r, center, normal).filter(|t| {
                let q = p + d * *t - center;
                let rho = (q - normal * normal.dot(&q)).norm();
                *hole <= rho && rho <= *radius
            });
            consider(t, Feature::Face);
            if edges {
                consider(
                    ring_entry(p, d, r, center, normal, *radius, t_max),
                    Feature::Rim(0),
                );
                if *hole > 0.0 {
                    consider(
                        ring_entry(p, d, r, center, normal, *hole, t_max),
                        Feature::HoleRim,
                    );
                }
            }
        }
        Shape::InfiniteCylinder {
            origin,
            axis,
            radius,
        } => {
            consider(
                side_entry(p, d, r, origin, axis, *radius, f64::INFINITY),
                Feature::Side,
            );
        }
        Shape::FiniteCylinder {
            center,
            axis,
            radius,
            length,
            taper,
        } => {
            if *taper != 0.0 {
                return None;
            }
            let half = length / 2.0;
            consider(
                side_entry(p, d, r, center, axis, *radius, half),
                Feature::Side,
            );
            if edges {
                for (k, end) in [-half, half].into_iter().enumerate() {
                    let c = center + axis * end;
                    let t = if *radius == 0.0 {
                        point_entry(p, d, r, &c)
                    } else {
                        ring_entry(p, d, r, &c, axis, *radius, t_max)
                    };
                    consider(t, Feature::Rim(k as u8));
                }
            }
        }
        Shape::Triangle { .. } | Shape::Shell { .. } => {}
    }
    best
}

/// When a sphere on the side of the plane through `q` with unit normal `n` where it
/// starts comes within `r` of it, moving towards it.
fn slab_entry(p: &Vec3, d: &Vec3, r: f64, q: &Vec3, n: &Vec3) -> Option<f64> {
    let h = n.dot(&(p - q));
    let rate = n.dot(d);
    let (gap, closing) = if h >= 0.0 {
        (h - r, -rate)
    } else {
        (-h - r, rate)
    };
    (gap > 0.0 && closing > 0.0).then(|| gap / closing)
}

/// When |a + b·t| first falls to `s` from above: a sphere entering a ball (points, other
/// particles) or a tube (lines and cylinders, in the plane across the axis). The smaller root of
/// |b|²t² + 2(a·b)t + |a|² − s², in the form that does not cancel.
pub fn sphere_entry(a: &Vec3, b: &Vec3, s: f64) -> Option<f64> {
    let c = a.norm_squared() - s * s;
    let half_b = a.dot(b);
    if c <= 0.0 || half_b >= 0.0 {
        return None;
    }
    // A double root is a graze: the sphere touches without moving into the surface.
    let disc = half_b * half_b - b.norm_squared() * c;
    (disc > 0.0).then(|| c / (-half_b + disc.sqrt()))
}

/// When |a + b·t|, below `s` now, first rises to `s`: a sphere inside a tube reaching its
/// inner wall. The positive root of the same quadratic, in the form that does not cancel.
fn sphere_exit(a: &Vec3, b: &Vec3, s: f64) -> Option<f64> {
    let c = a.norm_squared() - s * s;
    let bb = b.norm_squared();
    if c >= 0.0 || bb == 0.0 {
        return None;
    }
    let half_b = a.dot(b);
    let q = -(half_b + half_b.signum() * (half_b * half_b - bb * c).sqrt());
    // The roots q/|b|² and c/q have opposite signs (their product c/|b|² is negative).
    let t = (q / bb).max(c / q);
    t.is_finite().then_some(t)
}

/// A sphere meeting a point.
fn point_entry(p: &Vec3, d: &Vec3, r: f64, q: &Vec3) -> Option<f64> {
    sphere_entry(&(p - q), d, r)
}

/// A sphere meeting the segment a–b away from its ends (the ends are points).
fn segment_entry(p: &Vec3, d: &Vec3, r: f64, a: &Vec3, b: &Vec3) -> Option<f64> {
    let length = (b - a).norm();
    if length == 0.0 {
        return None;
    }
    let u = (b - a) / length;
    let across = |v: &Vec3| v - u * u.dot(v);
    let rel = p - a;
    let t = sphere_entry(&across(&rel), &across(d), r)?;
    (0.0..=length).contains(&u.dot(&(rel + d * t))).then_some(t)
}

/// A sphere meeting the side of a cylinder of `radius` around the axis through `c` along
/// unit `axis`, within `half` of `c` along it: from outside by the earlier root, from
/// inside by the later (SPEC §3).
fn side_entry(
    p: &Vec3,
    d: &Vec3,
    r: f64,
    c: &Vec3,
    axis: &Vec3,
    radius: f64,
    half: f64,
) -> Option<f64> {
    let across = |v: &Vec3| v - axis * axis.dot(v);
    let rel = p - c;
    let (a, b) = (across(&rel), across(d));
    let t = if radius > 0.0 && a.norm() < radius {
        if radius <= r {
            return None;
        }
        sphere_exit(&a, &b, radius - r)?
    } else {
        sphere_entry(&a, &b, radius + r)?
    };
    (axis.dot(&(rel + d * t)).abs() <= half).then_some(t)
}

/// A sphere meeting the circle of `radius` around `c` in the plane across unit `axis`:
/// the ray against the torus of tube radius r, a quartic (notes-dem-physics §2). Moving
/// along the axis itself the quartic has only double roots, so that case is the point
/// quadratic with the distance √(r² − radius²); near the axis, a search on the distance
/// to the circle backs the quartic up.
fn ring_entry(
    p: &Vec3,
    d: &Vec3,
    r: f64,
    c: &Vec3,
    axis: &Vec3,
    radius: f64,
    t_max: f64,
) -> Option<f64> {
    let rel = p - c;
    let (pz, dz) = (axis.dot(&rel), axis.dot(d));
    let (pxy, dxy) = (rel - axis * pz, d - axis * dz);
    if pxy.norm() <= 1e-12 * radius && dxy.norm() <= 1e-12 * d.norm() {
        if r <= radius {
            return None;
        }
        let s = (r * r - radius * radius).sqrt();
        return sphere_entry(&Vec3::new(0.0, 0.0, pz), &Vec3::new(0.0, 0.0, dz), s);
    }
    let alpha = d.norm_squared();
    let beta = 2.0 * rel.dot(d);
    let gamma = rel.norm_squared() - r * r - radius * radius;
    let rr4 = 4.0 * radius * radius;
    // The constant term γ² + 4R²(z² − r²) is (G·H) with G = (ρ − R)² + z² − r² and
    // H = (ρ + R)² + z² − r²: formed that way it does not cancel when the sphere starts
    // just outside the tube (an imminent contact), where the sum loses up to 8e−7.
    let rho = pxy.norm();
    let near_side = (rho - radius).powi(2) + pz * pz - r * r;
    let far_side = (rho + radius).powi(2) + pz * pz - r * r;
    let coefficients = [
        near_side * far_side,
        2.0 * beta * gamma + 2.0 * rr4 * pz * dz,
        beta * beta + 2.0 * alpha * gamma + rr4 * dz * dz,
        2.0 * alpha * beta,
        alpha * alpha,
    ];
    let quartic = crate::poly::first_entry(&coefficients, t_max);
    if radius >= 2.0 * r || !t_max.is_finite() {
        return quartic;
    }
    // A sphere wider than the ring meets it with its centre near the axis, where both
    // of the quartic's roots are nearly double: rounding blurs the root and can hide
    // the crossing. The squared distance to the circle less r², (ρ − R)² + z² − r², is
    // well conditioned there: polish the quartic's root on it by Newton's method, or,
    // without a root, look at it at the times nearest the ring's plane and its axis and
    // at 32 more across the step, and bisect its first fall below zero.
    let gap = |t: f64| {
        let rho = (pxy + dxy * t).norm();
        let z = pz + dz * t;
        (rho - radius).powi(2) + z * z - r * r
    };
    if let Some(mut t) = quartic {
        for _ in 0..4 {
            let q = pxy + dxy * t;
            let rho = q.norm();
            let slope = 2.0 * (rho - radius) * q.dot(&dxy) / rho + 2.0 * (pz + dz * t) * dz;
            let next = t - gap(t) / slope;
            if !(0.0..=t_max).contains(&next) || gap(next).abs() >= gap(t).abs() {
                break;
            }
            t = next;
        }
        return Some(t);
    }
    if gap(0.0) <= 0.0 {
        return None;
    }
    let mut times: Vec<f64> = (1..=32).map(|k| t_max * f64::from(k) / 32.0).collect();
    for t in [-pz / dz, -pxy.dot(&dxy) / dxy.norm_squared()] {
        if t.is_finite() && (0.0..=t_max).contains(&t) {
            times.push(t);
        }
    }
    times.sort_by(f64::total_cmp);
    let mut lo = 0.0;
    let mut hi = None;
    for t in times {
        if gap(t) <= 0.0 {
            hi = Some(t);
            break;
        }
        lo = t;
    }
    let mut hi = hi?;
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        if gap(mid) > 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Some(hi)
}
