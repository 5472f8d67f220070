//! Times of impact for the hard-sphere model (docs/spec.md §3 "HSDEM"): when a sphere
//! moving in a straight line first comes within its radius of a plane, a point, a
//! segment, a cylinder's side or a circle. The shapes' `hit` functions combine them per
//! feature.

use nalgebra::Vector3;

type Vec3 = Vector3<f64>;

/// When a sphere on the side of the plane through `q` with unit normal `n` where it
/// starts comes within `r` of it, moving towards it.
pub(crate) fn slab_entry(p: &Vec3, d: &Vec3, r: f64, q: &Vec3, n: &Vec3) -> Option<f64> {
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
pub(crate) fn sphere_exit(a: &Vec3, b: &Vec3, s: f64) -> Option<f64> {
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
pub(crate) fn point_entry(p: &Vec3, d: &Vec3, r: f64, q: &Vec3) -> Option<f64> {
    sphere_entry(&(p - q), d, r)
}

/// A sphere meeting the segment a–b away from its ends (the ends are points).
pub(crate) fn segment_entry(p: &Vec3, d: &Vec3, r: f64, a: &Vec3, b: &Vec3) -> Option<f64> {
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
/// inside by the later (docs/spec.md §3).
pub(crate) fn side_entry(
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
/// the ray against the torus of tube radius r, a quartic (docs/pkdgrav-physics.md §11).
/// Moving along the axis itself the quartic has only double roots, so that case is the
/// point quadratic with the distance √(r² − radius²); near the axis, a search on the
/// distance to the circle backs the quartic up.
pub(crate) fn ring_entry(
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
