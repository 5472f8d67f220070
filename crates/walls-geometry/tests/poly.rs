//! The first downward zero crossing of a polynomial of degree ≤ 4 (`poly::first_entry`):
//! against exact roots, grazes, edge cases, random real roots and ray–torus hits.

use proptest::prelude::*;
use walls_geometry::poly::first_entry;

/// Coefficients (lowest degree first) of `scale`·∏(t − rᵢ).
fn from_roots(scale: f64, roots: &[f64]) -> Vec<f64> {
    let mut c = vec![scale];
    for &r in roots {
        let mut next = vec![0.0; c.len() + 1];
        for (i, &x) in c.iter().enumerate() {
            next[i + 1] += x;
            next[i] -= r * x;
        }
        c = next;
    }
    c
}

fn eval(c: &[f64], t: f64) -> f64 {
    c.iter().rev().fold(0.0, |acc, &x| acc * t + x)
}

/// Σ|cᵢ|·|t|ⁱ: the scale against which f(t) is rounded.
fn magnitude(c: &[f64], t: f64) -> f64 {
    c.iter().rev().fold(0.0, |acc, &x| acc * t.abs() + x.abs())
}

/// The first root of `scale`·∏(t − rᵢ) (simple, distinct roots) in [0, t_max] where it
/// goes from positive to negative: at a root, the product changes sign by the parity of
/// the number of roots above it.
fn expected(scale: f64, roots: &[f64], t_max: f64) -> Option<f64> {
    let mut sorted = roots.to_vec();
    sorted.sort_by(f64::total_cmp);
    (0..sorted.len())
        .filter(|&k| (0.0..=t_max).contains(&sorted[k]))
        .find(|&k| {
            let above = sorted.len() - 1 - k;
            let slope_sign = if above.is_multiple_of(2) {
                scale
            } else {
                -scale
            };
            slope_sign < 0.0
        })
        .map(|k| sorted[k])
}

fn relative_error(got: f64, want: f64) -> f64 {
    (got - want).abs() / want.abs()
}

#[track_caller]
fn assert_root(c: &[f64], t_max: f64, want: f64, tolerance: f64) {
    let got =
        first_entry(c, t_max).unwrap_or_else(|| panic!("{c:?} on [0, {t_max}]: None, want {want}"));
    let error = if want == 0.0 {
        got.abs()
    } else {
        relative_error(got, want)
    };
    assert!(
        error <= tolerance,
        "{c:?} on [0, {t_max}]: {got}, want {want} (relative error {error:e})"
    );
}

#[test]
fn roots_one_to_four() {
    let f = [24.0, -50.0, 35.0, -10.0, 1.0];
    assert_eq!(f, from_roots(1.0, &[1.0, 2.0, 3.0, 4.0])[..]);
    assert!(eval(&f, 0.0) > 0.0);
    // Positive before 1, negative between 1 and 2: enters at 1.
    assert_root(&f, 5.0, 1.0, 1e-15);
    assert_eq!(first_entry(&f, 0.5), None);
    // Negated, it starts negative: up through 1, down through 2.
    let g = f.map(|x| -x);
    assert!(eval(&g, 0.0) < 0.0);
    assert_root(&g, 5.0, 2.0, 1e-15);
    assert_eq!(first_entry(&g, 1.5), None);
    // Shifted by 1.5 (roots −0.5, 0.5, 1.5, 2.5): negative at 0, up at 0.5, down at 1.5.
    let shifted = from_roots(1.0, &[-0.5, 0.5, 1.5, 2.5]);
    assert!(eval(&shifted, 0.0) < 0.0);
    assert_root(&shifted, 5.0, 1.5, 1e-15);
    let shifted_negated = from_roots(-1.0, &[-0.5, 0.5, 1.5, 2.5]);
    assert_root(&shifted_negated, 5.0, 0.5, 1e-15);
}

#[test]
fn roots_spread_over_nine_decades() {
    let roots = [1e-9, 1e-6, 1e-3, 1.0];
    for (scale, t_max) in [
        (1.0, 2.0),
        (-1.0, 2.0),
        (1e-7, 2.0),
        (-3e5, 2.0),
        (1.0, 1e-4),
    ] {
        let c = from_roots(scale, &roots);
        let want = expected(scale, &roots, t_max).unwrap();
        assert_root(&c, t_max, want, 1e-13);
    }
    // The smaller roots one at a time, as the first entry after the others.
    assert_root(
        &from_roots(1.0, &[-1e-9, 1e-6, 1e-3, 1.0]),
        2.0,
        1e-3,
        1e-13,
    );
    assert_root(
        &from_roots(-1.0, &[-1e-9, -1e-6, 1e-3, 1.0]),
        2.0,
        1.0,
        1e-13,
    );
}

#[test]
fn clustered_roots() {
    // Roots 2, 2.001, 2.002, 2.003 are ill conditioned (κ ≈ 10¹⁰): rounding the
    // coefficients (each to within 4ε, all terms of one sign) moves them by up to
    // 4ε·Σ|cᵢ|tⁱ / |f′| ≈ 1e−4. The answer must be the right member of the cluster, within
    // that.
    let roots = [2.0, 2.001, 2.002, 2.003];
    for scale in [1.0, -1.0] {
        let c = from_roots(scale, &roots);
        let want = expected(scale, &roots, 3.0).unwrap();
        let slope: f64 = roots
            .iter()
            .filter(|&&r| r != want)
            .map(|r| want - r)
            .product();
        let bound = 4.0 * f64::EPSILON * magnitude(&c, want) / slope.abs();
        assert!(bound < 2.5e-4, "{bound}: cannot tell the roots apart");
        assert_root(&c, 3.0, want, bound / want);
    }
    // Dyadic roots 2 + k/1024: the coefficients are exact, only the evaluation rounds, and
    // values too near zero for plain Horner are recomputed compensated: to the ulp.
    let roots = [
        2.0,
        2.0 + 1.0 / 1024.0,
        2.0 + 2.0 / 1024.0,
        2.0 + 3.0 / 1024.0,
    ];
    for scale in [1.0, -1.0] {
        let c = from_roots(scale, &roots);
        let want = expected(scale, &roots, 3.0).unwrap();
        assert_root(&c, 3.0, want, 1e-15);
    }
}

#[test]
fn roots_outside_the_interval() {
    for roots in [
        [-5.0, -3.0, 20.0, 30.0],
        [-1.0, 12.0, 15.0, 100.0],
        [1e6, 2e6, 3e6, 4e6],
        [-4e6, -3e6, -2e6, -1e6],
    ] {
        for scale in [1.0, -1.0] {
            assert_eq!(
                first_entry(&from_roots(scale, &roots), 10.0),
                None,
                "{roots:?} × {scale}"
            );
        }
    }
    // The same with the interval long enough: the first downward one of them.
    let roots = [-5.0, -3.0, 20.0, 30.0];
    assert_root(&from_roots(1.0, &roots), 100.0, 20.0, 1e-14);
    assert_root(&from_roots(-1.0, &roots), 100.0, 30.0, 1e-14);
}

#[test]
fn complex_pairs_never_cross() {
    // (t² + 1)(t² + 2), positive everywhere, and its negation, negative everywhere.
    assert_eq!(first_entry(&[2.0, 0.0, 3.0, 0.0, 1.0], 100.0), None);
    assert_eq!(first_entry(&[-2.0, 0.0, -3.0, 0.0, -1.0], 100.0), None);
    // (t² + 1) on its own, and a pair near the interval: (t − 1)² + 1e−6.
    assert_eq!(first_entry(&[1.0, 0.0, 1.0], 100.0), None);
    assert_eq!(first_entry(&[1.0 + 1e-6, -2.0, 1.0], 100.0), None);
    // A complex pair times two real roots: only the real ones count.
    let mut c = [0.0; 5];
    let real = from_roots(1.0, &[1.0, 2.0]);
    for (i, &a) in [1.0, 0.0, 1.0].iter().enumerate() {
        for (j, &b) in real.iter().enumerate() {
            c[i + j] += a * b;
        }
    }
    assert_root(&c, 5.0, 1.0, 1e-15);
}

#[test]
fn a_double_root_is_a_graze() {
    // (t − 1)²(t + 3) = t³ + t² − 5t + 3 touches zero at 1 and stays positive.
    let c = [3.0, -5.0, 1.0, 1.0];
    assert_eq!(from_roots(1.0, &[1.0, 1.0, -3.0]), c);
    for t_max in [0.5, 1.0, 5.0] {
        assert_eq!(first_entry(&c, t_max), None, "t_max {t_max}");
    }
    // (t − 1)²: the quadratic graze; (t − 1)²(t − 2)²: the quartic one.
    assert_eq!(first_entry(&[1.0, -2.0, 1.0], 5.0), None);
    assert_eq!(
        first_entry(&from_roots(1.0, &[1.0, 1.0, 2.0, 2.0]), 5.0),
        None
    );
    // A graze first, then a real crossing: (t − 1)²(t − 3)(t − 4) enters at 3.
    assert_root(&from_roots(1.0, &[1.0, 1.0, 3.0, 4.0]), 5.0, 3.0, 1e-15);
    // Nearly double but truly dipping, with exact coefficients: (t − 1)² − 2⁻⁵² enters at
    // 1 − 2⁻²⁶, and ((t − 1)(t − 2))² − 2⁻⁴⁰ at (3 − √(1 + 2⁻¹⁸))/2 (plain Horner alone
    // would place the quartic's only to ~1e−10).
    assert_root(
        &[1.0 - f64::EPSILON, -2.0, 1.0],
        5.0,
        1.0 - 2f64.powi(-26),
        1e-15,
    );
    let c = [4.0 - 2f64.powi(-40), -12.0, 13.0, -6.0, 1.0];
    let want = 2.0 * (2.0 - 2f64.powi(-20)) / (3.0 + (1.0 + 2f64.powi(-18)).sqrt());
    assert_root(&c, 5.0, want, 1e-15);
    // A triple root is a crossing: −(t − 1)³ falls through zero at 1.
    let c = from_roots(-1.0, &[1.0, 1.0, 1.0]);
    assert_eq!(first_entry(&c, 5.0), Some(1.0));
    assert_eq!(first_entry(&c, 1.0), Some(1.0));
}

#[test]
fn linear() {
    assert_root(&[2.0, -1.0], 5.0, 2.0, 0.0);
    assert_root(&[1.0, -3.0], 5.0, 1.0 / 3.0, 0.0);
    assert_eq!(first_entry(&[2.0, -1.0], 1.0), None);
    // Increasing: leaves zero upwards, never enters.
    assert_eq!(first_entry(&[-2.0, 1.0], 5.0), None);
    // Negative and falling: already inside, no later entry.
    assert_eq!(first_entry(&[-2.0, -1.0], 5.0), None);
}

#[test]
fn quadratic() {
    // (t − 1)(t − 3): enters at 1; negated: up at 1, enters at 3.
    assert_root(&[3.0, -4.0, 1.0], 5.0, 1.0, 1e-15);
    assert_root(&[-3.0, 4.0, -1.0], 5.0, 3.0, 1e-15);
    assert_eq!(first_entry(&[-3.0, 4.0, -1.0], 2.0), None);
    // Roots 1e−8 and 1e8: the small one without cancellation.
    let c = from_roots(1.0, &[1e-8, 1e8]);
    assert_root(&c, 1.0, 1e-8, 1e-15);
    assert_root(&from_roots(-1.0, &[1e-8, 1e8]), 2e8, 1e8, 1e-15);
    // A sphere meeting a point: |p + v·t|² − r² with p = (3, 0.5, 0), v = (−1, 0, 0),
    // r = 1: enters at t = 3 − √0.75.
    let c = [9.25 - 1.0, -6.0, 1.0];
    assert_root(&c, 10.0, 3.0 - 0.75_f64.sqrt(), 1e-15);
}

#[test]
fn leading_zeros_lower_the_degree() {
    assert_root(&[3.0, -1.0, 0.0, 0.0, 0.0], 5.0, 3.0, 0.0);
    assert_root(&[3.0, -4.0, 1.0, 0.0, 0.0], 5.0, 1.0, 1e-15);
    assert_eq!(first_entry(&[3.0, -5.0, 1.0, 1.0, 0.0], 5.0), None);
    assert_eq!(first_entry(&[0.0; 5], 5.0), None);
    assert_eq!(first_entry(&[], 5.0), None);
    assert_eq!(first_entry(&[5.0], 5.0), None);
    assert_eq!(first_entry(&[-1.0, 0.0, 0.0], 5.0), None);
    assert_eq!(first_entry(&[-0.0, 0.0, -0.0, 0.0, 0.0], 5.0), None);
}

#[test]
fn t_max_exactly_at_a_root() {
    let f = [24.0, -50.0, 35.0, -10.0, 1.0];
    assert_eq!(first_entry(&f, 1.0), Some(1.0));
    assert_eq!(first_entry(&f.map(|x| -x), 2.0), Some(2.0));
    assert_eq!(first_entry(&f.map(|x| -x), 1.0), None);
    assert_eq!(first_entry(&[3.0, -4.0, 1.0], 1.0), Some(1.0));
    assert_eq!(first_entry(&[2.0, -1.0], 2.0), Some(2.0));
    // Dyadic roots: exact coefficients, f(t_max) exactly 0.
    let c = from_roots(1.0, &[0.125, 0.5, 2.0, 3.0]);
    assert_eq!(first_entry(&c, 0.125), Some(0.125));
    assert_eq!(first_entry(&c, 2.0), Some(0.125));
    // Negated: negative at 0, up through 0.125, down through 0.5.
    assert_eq!(
        first_entry(&c.iter().map(|x| -x).collect::<Vec<_>>(), 0.5),
        Some(0.5)
    );
}

#[test]
fn zero_at_the_start() {
    // f(0) = 0 and falling: the contact begins at once.
    assert_eq!(first_entry(&[0.0, -1.0, 0.0, 0.0, 1.0], 5.0), Some(0.0));
    assert_eq!(first_entry(&[0.0, -3.0], 5.0), Some(0.0));
    assert_eq!(first_entry(&[0.0, 0.0, -1.0], 5.0), Some(0.0));
    assert_eq!(first_entry(&[0.0, -1.0, 0.0, 0.0, 1.0], 0.0), Some(0.0));
    // f(0) = 0 and rising: 0 does not count; t − t² comes back down through 1.
    assert_root(&[0.0, 1.0, -1.0], 5.0, 1.0, 1e-15);
    assert_eq!(first_entry(&[0.0, 1.0, -1.0], 0.0), None);
    assert_eq!(first_entry(&[0.0, 0.0, 1.0], 5.0), None);
}

#[test]
fn a_tiny_positive_start_is_not_missed() {
    // f(0) = 1e−300 and the root right after it, whatever the degree and convexity.
    for c in [
        &[1e-300, -1.0][..],
        &[1e-300, -1.0, 1.0],
        &[1e-300, -1.0, -1.0],
        &[1e-300, -1.0, 0.0, 1.0],
        &[1e-300, -1.0, 0.0, -1.0],
        &[1e-300, -1.0, 0.0, 0.0, 1.0],
        &[1e-300, -1.0, 0.0, 0.0, -1.0],
        &[1e-300, -1.0, 3.0, -2.0, 1.0],
    ] {
        assert_root(c, 1.0, 1e-300, 1e-15);
        assert_root(c, 1e-300, 1e-300, 1e-15);
    }
    // Tiny values all round: root 1e−290.
    assert_root(&[1e-300, -1e-10, 0.0, 0.0, 1.0], 1.0, 1e-290, 1e-15);
}

#[test]
fn huge_and_tiny_coefficients() {
    let f = [24.0, -50.0, 35.0, -10.0, 1.0];
    // Powers of two scale exactly: the same roots to the ulp.
    for scale in [
        2f64.powi(1000),
        2f64.powi(-1000),
        2f64.powi(1018),
        f64::MIN_POSITIVE,
    ] {
        assert_root(&f.map(|x| x * scale), 5.0, 1.0, 1e-15);
        assert_root(&f.map(|x| -x * scale), 5.0, 2.0, 1e-15);
    }
    // Other scales round the coefficients, which moves the roots by ~κ·ε.
    for scale in [1e300, 1e-300, 1e306, 3e-308] {
        assert_root(&f.map(|x| x * scale), 5.0, 1.0, 1e-13);
        assert_root(&f.map(|x| -x * scale), 5.0, 2.0, 1e-13);
    }
}

#[test]
fn not_finite_or_empty() {
    let f = [24.0, -50.0, 35.0, -10.0, 1.0];
    for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        for i in 0..5 {
            let mut c = f;
            c[i] = bad;
            assert_eq!(first_entry(&c, 5.0), None, "{c:?}");
        }
        assert_eq!(first_entry(&f, bad), None);
    }
    assert_eq!(first_entry(&f, -1.0), None);
}

#[test]
#[should_panic(expected = "degree at most 4")]
fn degree_five_panics() {
    first_entry(&[1.0, 0.0, 0.0, 0.0, 0.0, 1.0], 1.0);
}

/// Ring of radius `big` in the xy-plane about the origin, tube radius `small`: f(t) of the
/// point p + d·t, lowest degree first, negative inside the tube.
fn torus(p: [f64; 3], d: [f64; 3], big: f64, small: f64) -> [f64; 5] {
    let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    let alpha = dot(d, d);
    let beta = 2.0 * dot(p, d);
    let gamma = dot(p, p) - small * small - big * big;
    let r2 = big * big;
    [
        gamma * gamma + 4.0 * r2 * (p[2] * p[2] - small * small),
        2.0 * beta * gamma + 8.0 * r2 * p[2] * d[2],
        beta * beta + 2.0 * alpha * gamma + 4.0 * r2 * d[2] * d[2],
        2.0 * alpha * beta,
        alpha * alpha,
    ]
}

/// Distance of p + d·t from the ring of radius `big`.
fn ring_distance(p: [f64; 3], d: [f64; 3], t: f64, big: f64) -> f64 {
    let x = [p[0] + d[0] * t, p[1] + d[1] * t, p[2] + d[2] * t];
    (x[0].hypot(x[1]) - big).hypot(x[2])
}

const BIG: f64 = 1.0;
const SMALL: f64 = 0.1;

/// The entry of p + d·t into the tube: on its surface, and (when p is outside) outside it
/// all the way there.
#[track_caller]
fn assert_torus_entry(p: [f64; 3], d: [f64; 3], t_max: f64) -> f64 {
    let c = torus(p, d, BIG, SMALL);
    let t = first_entry(&c, t_max).unwrap_or_else(|| panic!("{p:?} + {d:?}·t misses"));
    let distance = ring_distance(p, d, t, BIG);
    assert!(
        (distance - SMALL).abs() <= 1e-12,
        "{p:?} + {d:?}·{t}: {distance} from the ring"
    );
    if ring_distance(p, d, 0.0, BIG) > SMALL {
        for k in 0..1000 {
            let s = t * k as f64 / 1000.0;
            assert!(
                ring_distance(p, d, s, BIG) >= SMALL - 1e-12,
                "{p:?} + {d:?}·{s} is inside before {t}"
            );
        }
    }
    t
}

#[test]
fn ray_torus_hits() {
    // Along the x-axis from −3: into the tube at x = −1.1.
    let t = assert_torus_entry([-3.0, 0.0, 0.0], [1.0, 0.0, 0.0], 10.0);
    assert!((t - 1.9).abs() <= 1e-13, "{t}");
    // Aimed at points of the ring's centre line from several directions and speeds.
    for (phi, u, speed) in [
        (0.3, [0.0, 0.0, 1.0], 1.0),
        (1.7, [0.6, 0.0, 0.8], 0.25),
        (-2.5, [-0.48, 0.6, 0.64], 3.0),
        (4.0, [0.36, 0.48, -0.8], 1e-3),
        (0.0, [1.0, 0.0, 0.0], 2.0),
        (2.2, [0.0, 0.6, 0.8], 10.0),
    ] {
        let q = [f64::cos(phi), f64::sin(phi), 0.0];
        let p = [q[0] + 2.0 * u[0], q[1] + 2.0 * u[1], q[2] + 2.0 * u[2]];
        let d = [-u[0] * speed, -u[1] * speed, -u[2] * speed];
        let t = assert_torus_entry(p, d, 4.0 / speed);
        assert!(t < 2.0 / speed, "{t}: entered after reaching the ring");
    }
    // Starting inside the tube (f(0) < 0): out at t = 0.1 into the hole, across it, and in
    // again at 1.9 — not 0.
    let p = [-1.0, 0.0, 0.0];
    assert!(torus(p, [1.0, 0.0, 0.0], BIG, SMALL)[0] < 0.0);
    let t = assert_torus_entry(p, [1.0, 0.0, 0.0], 10.0);
    assert!((t - 1.9).abs() <= 1e-13, "{t}");
    assert_eq!(
        first_entry(&torus(p, [1.0, 0.0, 0.0], BIG, SMALL), 1.5),
        None
    );
}

#[test]
fn ray_torus_misses() {
    for (p, d, t_max) in [
        // Above the tube.
        ([-3.0, 0.0, 0.5], [1.0, 0.0, 0.0], 6.0),
        // Down the axis through the hole, and slanted through it.
        ([0.0, 0.0, -2.0], [0.0, 0.0, 1.0], 4.0),
        ([0.3, -0.2, -2.0], [-0.1, 0.05, 1.0], 4.0),
        // Across the hole in the plane of the ring, stopping short of the far side.
        ([-0.5, -0.5, 0.0], [1.0, 0.9, 0.0], 1.0),
        // Outside the ring, passing it by.
        ([3.0, -3.0, 0.05], [0.0, 1.0, 0.0], 6.0),
        // Just over the top of the tube (z = 0.1 + 1e−6) across the ring.
        ([-3.0, 0.0, 0.100001], [1.0, 0.0, 0.0], 6.0),
    ] {
        assert_eq!(
            first_entry(&torus(p, d, BIG, SMALL), t_max),
            None,
            "{p:?} + {d:?}·t"
        );
    }
    // Through the hole on the axis with a long interval: still nothing.
    assert_eq!(
        first_entry(&torus([0.0, 0.0, -2.0], [0.0, 0.0, 1.0], BIG, SMALL), 10.0),
        None
    );
}

/// A root of magnitude 1e−4 to 1e2, mostly positive, so that some fall in [0, 10].
fn root() -> impl Strategy<Value = f64> {
    (prop::bool::weighted(0.8), 1.0..10.0f64, -4..=1i32).prop_map(|(positive, m, e)| {
        let r = m * 10f64.powi(e);
        if positive { r } else { -r }
    })
}

/// Whether the roots are apart by 5 % of the larger (so each is well conditioned).
fn separated(roots: &[f64]) -> bool {
    roots.iter().enumerate().all(|(i, a)| {
        roots[i + 1..]
            .iter()
            .all(|b| (a - b).abs() >= 0.05 * a.abs().max(b.abs()))
    })
}

proptest! {
    // Some 5 % of random root sets are rejected as too close together.
    #![proptest_config(ProptestConfig {
        cases: 2000,
        max_global_rejects: 100_000,
        ..ProptestConfig::default()
    })]

    #[test]
    fn four_real_roots(
        roots in [root(), root(), root(), root()],
        scale in (prop::bool::ANY, -3..=3i32).prop_map(|(s, e)| if s { 10f64.powi(e) } else { -(10f64.powi(e)) }),
        t_max in 0.0..12.0f64,
    ) {
        prop_assume!(separated(&roots));
        let c = from_roots(scale, &roots);
        let got = first_entry(&c, t_max);
        match expected(scale, &roots, t_max) {
            None => prop_assert_eq!(got, None, "{:?}", c),
            Some(want) => {
                let got = got.ok_or_else(|| TestCaseError::fail(format!("{c:?}: None, want {want}")))?;
                prop_assert!(relative_error(got, want) <= 1e-9, "{:?}: {} want {}", c, got, want);
                prop_assert!(eval(&c, got).abs() <= 1e-12 * magnitude(&c, got), "{:?}: f({}) = {}", c, got, eval(&c, got));
            }
        }
    }

    #[test]
    fn two_real_roots_and_a_complex_pair(
        roots in [root(), root()],
        (re, im) in (-5.0..5.0f64, 0.01..3.0f64),
        scale in prop_oneof![Just(1.0), Just(-1.0)],
        t_max in 0.0..12.0f64,
    ) {
        prop_assume!(separated(&roots));
        let real = from_roots(scale, &roots);
        let pair = [re * re + im * im, -2.0 * re, 1.0];
        let mut c = [0.0; 5];
        for (i, a) in pair.iter().enumerate() {
            for (j, b) in real.iter().enumerate() {
                c[i + j] += a * b;
            }
        }
        let got = first_entry(&c, t_max);
        match expected(scale, &roots, t_max) {
            None => prop_assert_eq!(got, None, "{:?}", c),
            Some(want) => {
                let got = got.ok_or_else(|| TestCaseError::fail(format!("{c:?}: None, want {want}")))?;
                prop_assert!(relative_error(got, want) <= 1e-9, "{:?}: {} want {}", c, got, want);
            }
        }
    }

    #[test]
    fn ray_torus_entry_is_on_the_surface(
        // Kept to where rounding the coefficients (|p|⁴ and |d|⁴·t⁴ terms cancelling)
        // moves the surface by well under 1e−12: 2e−13 at most in 10⁶ trials.
        p in [-2.0..2.0f64, -2.0..2.0f64, -1.0..1.0f64],
        d in [-1.0..1.0f64, -1.0..1.0f64, -1.0..1.0f64],
        t_max in 0.1..5.0f64,
    ) {
        prop_assume!(ring_distance(p, d, 0.0, BIG) > SMALL + 1e-6);
        let c = torus(p, d, BIG, SMALL);
        let got = first_entry(&c, t_max);
        let end = got.unwrap_or(t_max);
        if let Some(t) = got {
            prop_assert!(t <= t_max);
            let distance = ring_distance(p, d, t, BIG);
            prop_assert!((distance - SMALL).abs() <= 1e-12, "{:?} + {:?}·{}: {} from the ring", p, d, t, distance);
        }
        // Outside the tube before the entry, or all the way when there is none.
        for k in 0..=5000 {
            let s = end * k as f64 / 5000.0;
            prop_assert!(ring_distance(p, d, s, BIG) >= SMALL - 1e-9, "{:?} + {:?}·{} inside before {:?}", p, d, s, got);
        }
    }
}
