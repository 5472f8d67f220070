//! Quartic solvers compared on what the hard-sphere evaluator asks of one: the first time
//! in [0, t_max] at which a quartic f falls through zero (f > 0 before, < 0 after; a
//! double root, a graze, does not count), as when a sphere moving in a line meets a ring
//! (ray against torus).
//!
//! Solvers:
//! - `ours`: `walls_geometry::poly::first_entry` (root isolation by recursive derivatives,
//!   safeguarded Newton, compensated Horner near roots);
//! - `ferrari`: the textbook closed form — depressed quartic, largest root of the
//!   resolvent cubic by Cardano or the trigonometric form, two quadratics (each by the
//!   cancellation-free q = −½(b + sgn b·√D)) — for all real roots;
//! - `ferrari + newton`: the same, each real root then polished by up to two Newton steps
//!   on the original coefficients (kept only while |f| decreases; Boost's `quartic_roots`
//!   does one Halley step);
//! - `eigen`: eigenvalues of the 4 × 4 companion matrix (nalgebra's real Schur form, no
//!   balancing); an eigenvalue is real when |Im| ≤ 4·10⁻¹²·|Re| (pkdgrav's test);
//! - `eigen + newton`: the same, polished like `ferrari + newton`.
//!
//! The root-list solvers pick their answer the same way: sort the real roots, group equal
//! values (a pair counted twice is a double root); the sign of f just after a root is the
//! leading coefficient's sign times (−1)^(number of roots above it); the answer is the
//! first root in [0, t_max] with f positive before and negative after.
//!
//! Families (4,000 random instances each, fixed seed):
//! 1. spread: roots ±{10⁻⁹, 10⁻⁶, 10⁻³, 1}·(1 + U(0, ½))·s, random signs, s = 10^U(−4, 4);
//! 2. clustered: roots s·{2, 2 + h, 2 + 2h, 2 + 3h}, h = 10^U(−4, −2), s = 10^U(−2, 2)
//!    (h = 10⁻³ is Flocke's and Strobach's {2, 2.001, 2.002, 2.003});
//! 3. repeated: (t − a)²(t − 3a)(t − 4a) before 2a (a graze: no entry), (t − a)²(t − 2a)(t − 3a)
//!    (entry at 2a after a graze), (t − a)³(t − 3a) (entry at a triple root), (t − a)⁴,
//!    −(t − a)²(t − 3a)(t − 4a) (a touch from below, then entry at 4a);
//! 4. complex: two real roots and a complex pair, or two pairs (no entry), pairs
//!    u ± i·v with v/u = 10^U(−7, 0) (down to near misses that are nearly double roots);
//! 5. ring: random rays against the torus of a ring (ring radius R = 1, sphere radius
//!    r = 0.1) aimed near its tube, hits and misses;
//! 6. ring, near-tangent: rays tangent to the tube, moved 10^U(−9, −3) into it (a shallow
//!    hit) or out of it (a near miss);
//! 7. ring, imminent: spheres starting 10^U(−10, −4) outside the tube, moving into it —
//!    a very early first root among roots of order one, as after a contact;
//! 8. ring, near axis: rings narrower than the sphere (R = U(0.02, 0.07)) met with the
//!    sphere's centre 10^U(−13, −6) from the axis, where the quartic's roots are nearly
//!    double (the evaluator polishes those on the distance; this chart compares raw
//!    solvers).
//!
//! Coefficients: families 1–4 are built from their exact roots in double-double and
//! rounded once to f64; families 5–8 the way `hsdem::ring_entry` forms them, in f64.
//!
//! References. Families 1–4: the true first entry of the *rounded* coefficients, found by
//! the same isolation (recursive derivatives) with every root bisected to adjacent floats
//! in double-double (about 32 digits), so no solver is charged for rounding it cannot
//! undo. At a root meant to be double (or quadruple), rounding may leave a shallow
//! crossing or none: both answers are accepted there — no entry (the intended graze:
//! crossings within 10^(−12/m) of a root of multiplicity m are ignored) or the rounded
//! coefficients' own crossing — and the times accepted only as the latter are counted as
//! grazes taken. Families 5–8: geometric, the first fall below zero of (ρ − R)² + z² − r²
//! (the sign of the distance from the centre to the ring's circle less r), located on a
//! grid of 2,048 steps plus points converging geometrically on the construction's contact
//! time and bisected to adjacent floats, evaluated in double-double (well conditioned off
//! the axis and near it). It is checked against the exact quartic (coefficients formed in
//! double-double, isolated as above). "perfect" rows score the exact first entry of the
//! rounded coefficients: the floor no solver of them can beat (zero for 1–4 by
//! construction; for 5–8, what forming the coefficients in f64 costs).
//!
//! Measured per solver and family: maximum and median relative error of the answer where
//! it and the reference both are times; the entries missed (reference a time, answer
//! none) and spurious (the other way round); and the time per solve: the median of 15
//! loops of about 2 ms over the family's instances (`black_box`ed, release build), the
//! loops taking turns among the solvers so that a busy moment of the machine falls on all
//! alike.
//!
//! Writes to `docs/charts`: `quartic` (each solver's worst max error over families 1–7
//! against its mean ns per solve, with the Pareto front; family 8 fails every solver
//! through its coefficients), `quartic_families` (max error per family and solver, and
//! the perfect solver's, dashed; errors below 10⁻¹⁷, exact answers included, drawn at
//! 10⁻¹⁷) and `quartic_cost` (ns per
//! solve per family and solver); and prints the table.

use nalgebra::{Matrix4, Vector3};
use std::hint::black_box;
use std::ops::{Add, Mul, Neg, Sub};
use std::time::Instant;
use walls_charts::{Chart, Mark, Series, out_dir, pareto_front, write};
use walls_geometry::poly::first_entry;

/// Coefficients, lowest degree first.
type Coeffs = [f64; 5];

type Vec3 = Vector3<f64>;

/// Instances per family.
const INSTANCES: usize = 4000;

/// The x axis of the charts by family.
const FAMILY_AXIS: &str = "1 spread, 2 clustered, 3 repeated, 4 complex, 5 ring, \
                           6 ring near-tangent, 7 ring imminent, 8 ring near axis";

/// Errors below this are drawn at it (a log axis has no zero).
const FLOOR_DRAWN: f64 = 1e-17;

// ---------------------------------------------------------------------------------------
// The solvers.

/// Short names, in order.
const SOLVERS: [&str; 5] = [
    "ours",
    "ferrari",
    "ferrari + newton",
    "eigen",
    "eigen + newton",
];

/// Solver `k` of [`SOLVERS`] on `c` over [0, t_max].
fn solve(k: usize, c: &Coeffs, t_max: f64) -> Option<f64> {
    match k {
        0 => ours(c, t_max),
        1 => ferrari(c, t_max),
        2 => ferrari_newton(c, t_max),
        3 => eigen(c, t_max),
        _ => eigen_newton(c, t_max),
    }
}

fn ours(c: &Coeffs, t_max: f64) -> Option<f64> {
    first_entry(c, t_max)
}

fn ferrari(c: &Coeffs, t_max: f64) -> Option<f64> {
    let (mut roots, n) = ferrari_roots(c);
    first_entering(&mut roots[..n], c[4], t_max)
}

fn ferrari_newton(c: &Coeffs, t_max: f64) -> Option<f64> {
    let (mut roots, n) = ferrari_roots(c);
    for r in &mut roots[..n] {
        *r = polish(c, *r);
    }
    first_entering(&mut roots[..n], c[4], t_max)
}

fn eigen(c: &Coeffs, t_max: f64) -> Option<f64> {
    let (mut roots, n) = eigen_roots(c);
    first_entering(&mut roots[..n], c[4], t_max)
}

fn eigen_newton(c: &Coeffs, t_max: f64) -> Option<f64> {
    let (mut roots, n) = eigen_roots(c);
    for r in &mut roots[..n] {
        *r = polish(c, *r);
    }
    first_entering(&mut roots[..n], c[4], t_max)
}

/// The first of the real roots `roots` (of a polynomial with leading coefficient `lead`,
/// all its real roots, counted with multiplicity) in [0, t_max] where the polynomial goes
/// from positive to negative. Equal values are one root of that multiplicity.
fn first_entering(roots: &mut [f64], lead: f64, t_max: f64) -> Option<f64> {
    roots.sort_unstable_by(f64::total_cmp);
    let k = roots.len();
    let mut i = 0;
    while i < k {
        let mut j = i + 1;
        while j < k && roots[j] == roots[i] {
            j += 1;
        }
        // The sign just after the root: the leading coefficient's, flipped once for each
        // root above it; just before it, flipped once more for each copy of it.
        let after_positive = (lead > 0.0) == (k - j).is_multiple_of(2);
        let before_positive = (lead > 0.0) == (k - i).is_multiple_of(2);
        if before_positive && !after_positive && (0.0..=t_max).contains(&roots[i]) {
            return Some(roots[i]);
        }
        i = j;
    }
    None
}

/// The real roots of the quartic `c` (c[4] ≠ 0) by Ferrari's method, unordered.
fn ferrari_roots(c: &Coeffs) -> ([f64; 4], usize) {
    let mut out = [0.0; 4];
    let mut n = 0;
    let (a, b, cc, d) = (c[3] / c[4], c[2] / c[4], c[1] / c[4], c[0] / c[4]);
    // x = y − a/4: y⁴ + p·y² + q·y + r.
    let a2 = a * a;
    let p = b - 0.375 * a2;
    let q = cc - 0.5 * a * b + 0.125 * a2 * a;
    let r = d - 0.25 * a * cc + a2 * b / 16.0 - 3.0 / 256.0 * a2 * a2;
    let shift = -0.25 * a;
    // (y² + p/2 + m)² = (s·y − q/(2s))² with s = √(2m), m a root of the resolvent
    // m³ + p·m² + (p²/4 − r)·m − q²/8 (its largest, positive when q ≠ 0).
    let m = if q == 0.0 {
        0.0
    } else {
        cubic_largest_root(p, 0.25 * p * p - r, -0.125 * q * q)
    };
    let mut push = |y: f64| {
        if y.is_finite() {
            out[n] = y + shift;
            n += 1;
        }
    };
    if m > 0.0 {
        let s = (2.0 * m).sqrt();
        let t = q / (2.0 * s);
        for (b1, c1) in [(-s, 0.5 * p + m + t), (s, 0.5 * p + m - t)] {
            if let Some((y1, y2)) = quadratic(b1, c1) {
                push(y1);
                push(y2);
            }
        }
    } else if let Some((z1, z2)) = quadratic(p, r) {
        // q = 0: the biquadratic z² + p·z + r, y = ±√z.
        for z in [z1, z2] {
            if z >= 0.0 {
                push(z.sqrt());
                push(-z.sqrt());
            }
        }
    }
    (out, n)
}

/// The real roots of y² + b·y + c, by the cancellation-free formula.
fn quadratic(b: f64, c: f64) -> Option<(f64, f64)> {
    let disc = b * b - 4.0 * c;
    if disc < 0.0 || disc.is_nan() {
        return None;
    }
    let q = -0.5 * (b + disc.sqrt().copysign(b));
    if q == 0.0 {
        return Some((0.0, 0.0));
    }
    Some((q, c / q))
}

/// The largest real root of m³ + a·m² + b·m + c: Cardano's formula with one real root,
/// the trigonometric form with three.
fn cubic_largest_root(a: f64, b: f64, c: f64) -> f64 {
    let shift = -a / 3.0;
    let p = b - a * a / 3.0;
    let q = 2.0 * a * a * a / 27.0 - a * b / 3.0 + c;
    let disc = 0.25 * q * q + p * p * p / 27.0;
    let u = if disc > 0.0 || p >= 0.0 {
        let s = disc.max(0.0).sqrt();
        (-0.5 * q + s).cbrt() + (-0.5 * q - s).cbrt()
    } else {
        let rt = (-p / 3.0).sqrt();
        let cos3 = (-0.5 * q / (rt * rt * rt)).clamp(-1.0, 1.0);
        2.0 * rt * (cos3.acos() / 3.0).cos()
    };
    u + shift
}

/// The real eigenvalues of the companion matrix of `c` (c[4] ≠ 0).
fn eigen_roots(c: &Coeffs) -> ([f64; 4], usize) {
    let l = c[4];
    #[rustfmt::skip]
    let companion = Matrix4::from_row_slice(&[
        -c[3] / l, -c[2] / l, -c[1] / l, -c[0] / l,
        1.0, 0.0, 0.0, 0.0,
        0.0, 1.0, 0.0, 0.0,
        0.0, 0.0, 1.0, 0.0,
    ]);
    let mut out = [0.0; 4];
    let mut n = 0;
    for z in companion.complex_eigenvalues().iter() {
        if z.re.is_finite() && z.im.abs() <= 4e-12 * z.re.abs() {
            out[n] = z.re;
            n += 1;
        }
    }
    (out, n)
}

/// f(x) and f′(x) by Horner's rule.
fn horner(c: &Coeffs, x: f64) -> (f64, f64) {
    let mut value = c[4];
    let mut slope = 0.0;
    for &ci in c[..4].iter().rev() {
        slope = slope * x + value;
        value = value * x + ci;
    }
    (value, slope)
}

/// Up to two Newton steps on `c` from `x`, each kept only if it lowers |f|.
fn polish(c: &Coeffs, mut x: f64) -> f64 {
    for _ in 0..2 {
        let (f, slope) = horner(c, x);
        if f == 0.0 || slope == 0.0 {
            break;
        }
        let next = x - f / slope;
        if horner(c, next).0.abs() >= f.abs() || next.is_nan() {
            break;
        }
        x = next;
    }
    x
}

// ---------------------------------------------------------------------------------------
// Double-double arithmetic (about 106 bits), for the references.

/// hi + lo, |lo| ≤ ½ ulp(hi).
#[derive(Clone, Copy, Debug, Default)]
struct Dd {
    hi: f64,
    lo: f64,
}

/// a + b exactly.
fn two_sum(a: f64, b: f64) -> Dd {
    let s = a + b;
    let bb = s - a;
    Dd {
        hi: s,
        lo: (a - (s - bb)) + (b - bb),
    }
}

/// a + b exactly, |a| ≥ |b|.
fn quick_two_sum(a: f64, b: f64) -> Dd {
    let s = a + b;
    Dd {
        hi: s,
        lo: b - (s - a),
    }
}

/// a = hi + lo, each of at most 26 significant bits (Veltkamp).
fn split(a: f64) -> (f64, f64) {
    let scaled = 134_217_729.0 * a;
    let hi = scaled - (scaled - a);
    (hi, a - hi)
}

/// a·b exactly (Dekker; no FMA needed).
fn two_prod(a: f64, b: f64) -> Dd {
    let p = a * b;
    let (ah, al) = split(a);
    let (bh, bl) = split(b);
    Dd {
        hi: p,
        lo: ((ah * bh - p) + ah * bl + al * bh) + al * bl,
    }
}

impl Dd {
    const ZERO: Dd = Dd { hi: 0.0, lo: 0.0 };

    fn from(x: f64) -> Dd {
        Dd { hi: x, lo: 0.0 }
    }

    fn mul_f(self, b: f64) -> Dd {
        let p = two_prod(self.hi, b);
        quick_two_sum(p.hi, p.lo + self.lo * b)
    }

    fn sqrt(self) -> Dd {
        if self.hi <= 0.0 {
            return Dd::ZERO;
        }
        let x = self.hi.sqrt();
        let rest = self - two_prod(x, x);
        quick_two_sum(x, rest.hi / (2.0 * x))
    }

    fn signum(self) -> f64 {
        if self.hi > 0.0 {
            1.0
        } else if self.hi < 0.0 {
            -1.0
        } else {
            0.0
        }
    }

    fn abs(self) -> f64 {
        (self.hi + self.lo).abs()
    }
}

impl Add for Dd {
    type Output = Dd;
    fn add(self, o: Dd) -> Dd {
        let s = two_sum(self.hi, o.hi);
        let t = two_sum(self.lo, o.lo);
        let s = quick_two_sum(s.hi, s.lo + t.hi);
        quick_two_sum(s.hi, s.lo + t.lo)
    }
}

impl Neg for Dd {
    type Output = Dd;
    fn neg(self) -> Dd {
        Dd {
            hi: -self.hi,
            lo: -self.lo,
        }
    }
}

impl Sub for Dd {
    type Output = Dd;
    fn sub(self, o: Dd) -> Dd {
        self + -o
    }
}

impl Mul for Dd {
    type Output = Dd;
    fn mul(self, o: Dd) -> Dd {
        let p = two_prod(self.hi, o.hi);
        quick_two_sum(p.hi, p.lo + (self.hi * o.lo + self.lo * o.hi))
    }
}

/// p(t), p of degree m, by Horner's rule in double-double.
fn dd_eval(p: &[Dd; 5], m: usize, t: f64) -> Dd {
    let mut acc = p[m];
    for i in (0..m).rev() {
        acc = acc.mul_f(t) + p[i];
    }
    acc
}

/// The points of [0, t_max] where p (degree m, monotone between the sorted `cuts`) crosses
/// or touches zero, with its sign just before and just after each.
fn dd_crossings(p: &[Dd; 5], m: usize, cuts: &[f64], t_max: f64) -> Vec<(f64, f64, f64)> {
    let mut points = vec![0.0];
    points.extend(cuts.iter().copied().filter(|&t| t > 0.0 && t < t_max));
    points.push(t_max);
    points.dedup();
    let signs: Vec<f64> = points.iter().map(|&t| dd_eval(p, m, t).signum()).collect();
    let mut out = Vec::new();
    // At 0 itself, as in `first_entry`: f = 0 there counts as coming from above.
    let mut last = if signs[0] == 0.0 { 1.0 } else { signs[0] };
    if signs[0] == 0.0 && points.len() > 1 {
        out.push((0.0, 1.0, signs[1]));
    }
    for k in 0..points.len() - 1 {
        let (a, b, sa, sb) = (points[k], points[k + 1], signs[k], signs[k + 1]);
        if sa != 0.0 && sb != 0.0 && sa != sb {
            out.push((dd_bisect(p, m, a, b, sa), sa, sb));
        } else if sb == 0.0 {
            // p is monotone past b, so its sign at the next point is its sign just after.
            let after = match signs.get(k + 2) {
                Some(&s) => s,
                None => dd_eval(p, m, b + b.abs().max(1e-300) * 1e-9).signum(),
            };
            out.push((b, last, after));
        }
        if sb != 0.0 {
            last = sb;
        }
    }
    out
}

/// The root of p in [a, b], where p(a) has sign `sa` and p(b) the other, bisected to
/// adjacent floats: whichever of them has the smaller |p|.
fn dd_bisect(p: &[Dd; 5], m: usize, a: f64, b: f64, sa: f64) -> f64 {
    let (mut lo, mut hi) = (a, b);
    for _ in 0..3000 {
        let mid = lo + 0.5 * (hi - lo);
        if mid <= lo || mid >= hi {
            break;
        }
        let s = dd_eval(p, m, mid).signum();
        if s == 0.0 {
            return mid;
        }
        if s == sa {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    if dd_eval(p, m, lo).abs() <= dd_eval(p, m, hi).abs() {
        lo
    } else {
        hi
    }
}

/// Every crossing or touching of zero of the polynomial `c` in [0, t_max], with the signs
/// before and after: recursive-derivative isolation, each root bisected in double-double.
fn dd_roots(c: &[Dd; 5], t_max: f64) -> Vec<(f64, f64, f64)> {
    let n = match (0..5).rev().find(|&i| c[i].hi != 0.0) {
        Some(n) if n > 0 => n,
        _ => return Vec::new(),
    };
    let mut d = [[Dd::ZERO; 5]; 5];
    d[0] = *c;
    for j in 1..=n {
        for i in 0..=n - j {
            d[j][i] = d[j - 1][i + 1].mul_f((i + 1) as f64);
        }
    }
    let mut cuts: Vec<f64> = Vec::new();
    for j in (1..n).rev() {
        cuts = dd_crossings(&d[j], n - j, &cuts, t_max)
            .into_iter()
            .map(|x| x.0)
            .collect();
    }
    dd_crossings(&d[0], n, &cuts, t_max)
}

/// The first entry of `c` in [0, t_max] in double-double, sign changes near any of
/// `grazes` not counted: within 10^(−12/m) of a root g of even multiplicity m (relative:
/// 10⁻⁶ of a double root, 10⁻³ of a quadruple one), well beyond how far rounding the
/// coefficients moves it (about ε^(1/m)).
fn dd_first_entry(c: &[Dd; 5], t_max: f64, grazes: &[(f64, usize)]) -> Option<f64> {
    let near =
        |t: f64, (g, m): (f64, usize)| (t - g).abs() <= 10f64.powf(-12.0 / m as f64) * g.abs();
    dd_roots(c, t_max)
        .into_iter()
        .filter(|&(t, _, _)| !grazes.iter().any(|&g| near(t, g)))
        .find(|&(_, before, after)| before > 0.0 && after < 0.0)
        .map(|x| x.0)
}

// ---------------------------------------------------------------------------------------
// Instances.

/// One problem: coefficients, interval and the answers to judge by.
struct Instance {
    c: Coeffs,
    t_max: f64,
    /// The reference first entry.
    reference: Option<f64>,
    /// The ideal answer: from the intended roots (families 1–4), or geometric (5–7,
    /// where it is the reference).
    ideal: Option<f64>,
    /// The exact answer for the rounded coefficients, grazes or not: what a perfect solver
    /// would give.
    rounded: Option<f64>,
    /// Where a root is meant to be double (a graze), the rounded coefficients' own answer,
    /// also accepted: rounding may have made the graze a shallow crossing.
    alternative: Option<Option<f64>>,
    /// Which kind of instance within the family.
    case: usize,
}

/// A family of instances.
struct Family {
    name: &'static str,
    instances: Vec<Instance>,
    /// For the ring families: (geometric, exact-quartic) references, to check each other.
    checks: Vec<(Option<f64>, Option<f64>)>,
}

/// SplitMix64.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// Uniform in [a, b).
    fn uniform(&mut self, a: f64, b: f64) -> f64 {
        a + (b - a) * ((self.next() >> 11) as f64 * (1.0 / (1u64 << 53) as f64))
    }

    /// 10^U(a, b).
    fn log_uniform(&mut self, a: f64, b: f64) -> f64 {
        10f64.powf(self.uniform(a, b))
    }

    /// ±1.
    fn sign(&mut self) -> f64 {
        if self.next() & 1 == 0 { 1.0 } else { -1.0 }
    }

    fn below(&mut self, n: u64) -> u64 {
        self.next() % n
    }
}

/// The instance lead·Π(t − rᵢ)·Π(t² − 2u·t + u² + v²): coefficients exact in
/// double-double, then rounded to f64. Roots in `real` appearing an even number of times
/// are grazes.
fn from_roots(lead: f64, real: &[f64], pairs: &[(f64, f64)], t_max: f64, case: usize) -> Instance {
    let mut p = [Dd::ZERO; 5];
    p[0] = Dd::from(lead);
    let mut degree = 0;
    for &r in real {
        let mut next = [Dd::ZERO; 5];
        for i in 0..=degree + 1 {
            let shifted = if i > 0 { p[i - 1] } else { Dd::ZERO };
            next[i] = shifted - p[i].mul_f(r);
        }
        p = next;
        degree += 1;
    }
    for &(u, v) in pairs {
        let q0 = two_prod(u, u) + two_prod(v, v);
        let q1 = -2.0 * u;
        let mut next = [Dd::ZERO; 5];
        for i in 0..=degree + 2 {
            let mut x = p[i] * q0;
            if i > 0 {
                x = x + p[i - 1].mul_f(q1);
            }
            if i > 1 {
                x = x + p[i - 2];
            }
            next[i] = x;
        }
        p = next;
        degree += 2;
    }
    assert_eq!(degree, 4);
    let c: Coeffs = p.map(|x| x.hi);
    let grazes: Vec<(f64, usize)> = real
        .iter()
        .map(|r| (*r, real.iter().filter(|&&x| x == *r).count()))
        .filter(|&(_, m)| m % 2 == 0)
        .collect();
    let exact = dd_first_entry(&c.map(Dd::from), t_max, &[]);
    Instance {
        c,
        t_max,
        reference: dd_first_entry(&c.map(Dd::from), t_max, &grazes),
        ideal: first_entering(&mut real.to_vec(), lead, t_max),
        rounded: exact,
        alternative: (!grazes.is_empty()).then_some(exact),
        case,
    }
}

fn spread(rng: &mut Rng) -> Family {
    let instances = (0..INSTANCES)
        .map(|_| {
            let s = rng.log_uniform(-4.0, 4.0);
            let roots: Vec<f64> = [1e-9, 1e-6, 1e-3, 1.0]
                .iter()
                .map(|m| rng.sign() * m * s * rng.uniform(1.0, 1.5))
                .collect();
            let lead = rng.sign() * rng.log_uniform(-2.0, 2.0);
            from_roots(lead, &roots, &[], 2.0 * s, 0)
        })
        .collect();
    Family {
        name: "spread",
        instances,
        checks: Vec::new(),
    }
}

fn clustered(rng: &mut Rng) -> Family {
    let instances = (0..INSTANCES)
        .map(|_| {
            let s = rng.log_uniform(-2.0, 2.0);
            let h = rng.log_uniform(-4.0, -2.0);
            let roots: Vec<f64> = (0..4).map(|k| s * (2.0 + f64::from(k) * h)).collect();
            let lead = rng.sign() * rng.log_uniform(-2.0, 2.0);
            from_roots(lead, &roots, &[], 3.0 * s, 0)
        })
        .collect();
    Family {
        name: "clustered",
        instances,
        checks: Vec::new(),
    }
}

fn repeated(rng: &mut Rng) -> Family {
    let instances = (0..INSTANCES)
        .map(|_| {
            let a = rng.log_uniform(-2.0, 2.0) * rng.uniform(0.5, 1.5);
            let lead = rng.log_uniform(-2.0, 2.0);
            let (a2, a3, a4) = (2.0 * a, 3.0 * a, 4.0 * a);
            match rng.below(5) {
                0 => from_roots(lead, &[a, a, a3, a4], &[], a2, 0),
                1 => from_roots(lead, &[a, a, a2, a3], &[], 2.5 * a, 1),
                2 => from_roots(lead, &[a, a, a, a3], &[], a2, 2),
                3 => from_roots(lead, &[a, a, a, a], &[], a2, 3),
                _ => from_roots(-lead, &[a, a, a3, a4], &[], 5.0 * a, 4),
            }
        })
        .collect();
    Family {
        name: "repeated",
        instances,
        checks: Vec::new(),
    }
}

fn complex(rng: &mut Rng) -> Family {
    let instances = (0..INSTANCES)
        .map(|_| {
            let s = rng.log_uniform(-2.0, 2.0);
            let lead = rng.sign() * rng.log_uniform(-2.0, 2.0);
            let pair = |rng: &mut Rng| {
                let u = rng.uniform(0.1, 1.0) * s;
                (u, u * rng.log_uniform(-7.0, 0.0))
            };
            if rng.below(2) == 0 {
                let p = pair(rng);
                let real = [
                    rng.sign() * rng.uniform(0.1, 1.0) * s,
                    rng.sign() * rng.uniform(0.1, 1.0) * s,
                ];
                from_roots(lead, &real, &[p], 1.5 * s, 0)
            } else {
                let (p, q) = (pair(rng), pair(rng));
                from_roots(lead, &[], &[p, q], 1.5 * s, 1)
            }
        })
        .collect();
    Family {
        name: "complex",
        instances,
        checks: Vec::new(),
    }
}

/// The ring quartic of a sphere of radius r at p moving with velocity d against a ring of
/// radius `radius` about the z axis through the origin, formed as `hsdem::ring_entry`
/// forms it.
fn torus_coefficients(p: &Vec3, d: &Vec3, r: f64, radius: f64) -> Coeffs {
    let axis = Vec3::z();
    let rel = *p;
    let (pz, dz) = (axis.dot(&rel), axis.dot(d));
    let alpha = d.norm_squared();
    let beta = 2.0 * rel.dot(d);
    let gamma = rel.norm_squared() - r * r - radius * radius;
    let rr4 = 4.0 * radius * radius;
    [
        gamma * gamma + rr4 * (pz * pz - r * r),
        2.0 * beta * gamma + 2.0 * rr4 * pz * dz,
        beta * beta + 2.0 * alpha * gamma + rr4 * dz * dz,
        2.0 * alpha * beta,
        alpha * alpha,
    ]
}

/// The same quartic with its coefficients formed in double-double.
fn torus_dd(p: &Vec3, d: &Vec3, r: f64, radius: f64) -> [Dd; 5] {
    let dot = |a: &Vec3, b: &Vec3| two_prod(a.x, b.x) + two_prod(a.y, b.y) + two_prod(a.z, b.z);
    let alpha = dot(d, d);
    let beta = dot(p, d).mul_f(2.0);
    let gamma = dot(p, p) - two_prod(r, r) - two_prod(radius, radius);
    let rr4 = two_prod(radius, radius).mul_f(4.0);
    let (pz, dz) = (Dd::from(p.z), Dd::from(d.z));
    [
        gamma * gamma + rr4 * (pz * pz - two_prod(r, r)),
        (beta * gamma).mul_f(2.0) + (rr4 * pz * dz).mul_f(2.0),
        beta * beta + (alpha * gamma).mul_f(2.0) + rr4 * dz * dz,
        (alpha * beta).mul_f(2.0),
        alpha * alpha,
    ]
}

/// (ρ − R)² + z² − r² at p + d·t in double-double: the sign of the distance from the
/// centre to the ring's circle less r.
fn gap_dd(p: &Vec3, d: &Vec3, t: f64, r: f64, radius: f64) -> Dd {
    let x = Dd::from(p.x) + two_prod(d.x, t);
    let y = Dd::from(p.y) + two_prod(d.y, t);
    let z = Dd::from(p.z) + two_prod(d.z, t);
    let rho = (x * x + y * y).sqrt();
    let s = rho - Dd::from(radius);
    s * s + z * z - two_prod(r, r)
}

/// The first time in [0, t_max] the gap falls below zero, on a grid of 2,048 steps and
/// points converging on `hint` geometrically (ratio 10^⅛ down to 10⁻¹⁶·hint), bisected to
/// adjacent floats.
fn geometric_first_entry(
    p: &Vec3,
    d: &Vec3,
    r: f64,
    radius: f64,
    t_max: f64,
    hint: f64,
) -> Option<f64> {
    let mut times: Vec<f64> = (0..=2048).map(|k| t_max * f64::from(k) / 2048.0).collect();
    for k in 0..=128 {
        let o = 10f64.powf(-f64::from(k) / 8.0);
        times.push(hint * (1.0 - o));
        times.push(hint * (1.0 + o));
    }
    times.retain(|t| (0.0..=t_max).contains(t));
    times.sort_by(f64::total_cmp);
    times.dedup();
    let outside = |t: f64| gap_dd(p, d, t, r, radius).signum() > 0.0;
    assert!(outside(0.0), "a ring instance starts inside the tube");
    let mut lo = 0.0;
    for &t in &times[1..] {
        if !outside(t) {
            let mut hi = t;
            loop {
                let mid = lo + 0.5 * (hi - lo);
                if mid <= lo || mid >= hi {
                    break;
                }
                if outside(mid) {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            let gap = |t: f64| gap_dd(p, d, t, r, radius).abs();
            return Some(if gap(lo) <= gap(hi) { lo } else { hi });
        }
        lo = t;
    }
    None
}

/// A ring instance: the evaluator's coefficients, the geometric reference, and the exact
/// root of the rounded coefficients; with the check of the geometric reference against
/// the quartic formed exactly.
fn ring_instance(
    p: &Vec3,
    d: &Vec3,
    r: f64,
    radius: f64,
    t_max: f64,
    hint: f64,
) -> (Instance, (Option<f64>, Option<f64>)) {
    let c = torus_coefficients(p, d, r, radius);
    let reference = geometric_first_entry(p, d, r, radius, t_max, hint);
    let exact = dd_first_entry(&torus_dd(p, d, r, radius), t_max, &[]);
    (
        Instance {
            c,
            t_max,
            reference,
            ideal: reference,
            rounded: dd_first_entry(&c.map(Dd::from), t_max, &[]),
            alternative: None,
            case: 0,
        },
        (reference, exact),
    )
}

/// Whether p is outside the tube (of radius r about the circle of radius R).
fn outside_tube(p: &Vec3, r: f64, radius: f64) -> bool {
    gap_dd(p, &Vec3::zeros(), 0.0, r, radius).signum() > 0.0
}

/// A point of the tube's surface and the surface's outward normal there.
fn tube_point(rng: &mut Rng, r: f64, radius: f64) -> (Vec3, Vec3) {
    let phi = rng.uniform(0.0, std::f64::consts::TAU);
    let theta = rng.uniform(0.0, std::f64::consts::TAU);
    let radial = Vec3::new(phi.cos(), phi.sin(), 0.0);
    let normal = radial * theta.cos() + Vec3::z() * theta.sin();
    (radial * radius + normal * r, normal)
}

/// A unit vector, uniform on the sphere.
fn random_direction(rng: &mut Rng) -> Vec3 {
    let z = rng.uniform(-1.0, 1.0);
    let phi = rng.uniform(0.0, std::f64::consts::TAU);
    let s = (1.0 - z * z).sqrt();
    Vec3::new(s * phi.cos(), s * phi.sin(), z)
}

fn ring_family(name: &'static str, make: impl Fn(&mut Rng) -> Option<[f64; 10]>) -> Family {
    let mut rng = Rng(0x5eed_0000 + name.len() as u64);
    let mut instances = Vec::new();
    let mut checks = Vec::new();
    while instances.len() < INSTANCES {
        if let Some([px, py, pz, dx, dy, dz, r, radius, t_max, hint]) = make(&mut rng) {
            let (p, d) = (Vec3::new(px, py, pz), Vec3::new(dx, dy, dz));
            if !outside_tube(&p, r, radius) {
                continue;
            }
            let (instance, check) = ring_instance(&p, &d, r, radius, t_max, hint);
            instances.push(instance);
            checks.push(check);
        }
    }
    Family {
        name,
        instances,
        checks,
    }
}

/// Random rays aimed near the tube of the ring R = 1, r = 0.1.
fn ring_ordinary() -> Family {
    ring_family("ring", |rng| {
        let (r, radius) = (0.1, 1.0);
        let p = Vec3::new(
            rng.uniform(-2.0, 2.0),
            rng.uniform(-2.0, 2.0),
            rng.uniform(-1.0, 1.0),
        );
        let (q, _) = tube_point(rng, r, radius);
        let aim = q + random_direction(rng) * rng.uniform(0.0, 0.1);
        let speed = rng.log_uniform(-1.0, 1.0);
        let distance = (aim - p).norm();
        let d = (aim - p) / distance * speed;
        let t = distance / speed;
        let t_max = t * rng.uniform(1.0, 3.0);
        Some([p.x, p.y, p.z, d.x, d.y, d.z, r, radius, t_max, t])
    })
}

/// Rays tangent to the tube of the ring R = 1, r = 0.1, moved in (a shallow hit) or out
/// (a near miss) by 10^U(−9, −3).
fn ring_tangent() -> Family {
    ring_family("ring, near-tangent", |rng| {
        let (r, radius) = (0.1, 1.0);
        let (q, n) = tube_point(rng, r, radius);
        // Two unit vectors spanning the tangent plane.
        let e1 = Vec3::z().cross(&n);
        let e1 = if e1.norm() > 1e-6 {
            e1.normalize()
        } else {
            Vec3::x()
        };
        let e2 = n.cross(&e1);
        let psi = rng.uniform(0.0, std::f64::consts::TAU);
        let dir = e1 * psi.cos() + e2 * psi.sin();
        let depth = rng.log_uniform(-9.0, -3.0) * rng.sign();
        let touch = q - n * depth;
        let distance = rng.uniform(0.3, 1.5);
        let speed = rng.log_uniform(-1.0, 1.0);
        let p = touch - dir * distance;
        let t = distance / speed;
        let d = dir * speed;
        Some([p.x, p.y, p.z, d.x, d.y, d.z, r, radius, 2.0 * t, t])
    })
}

/// Spheres starting 10^U(−10, −4) outside the tube of the ring R = 1, r = 0.1, moving
/// into it at up to 1.4 rad from its normal: the first entry comes very early, the roots
/// spread widely.
fn ring_imminent() -> Family {
    ring_family("ring, imminent", |rng| {
        let (r, radius) = (0.1, 1.0);
        let (q, n) = tube_point(rng, r, radius);
        let gap = rng.log_uniform(-10.0, -4.0);
        let p = q + n * gap;
        let across = random_direction(rng);
        let across = (across - n * across.dot(&n)).normalize();
        let angle = rng.uniform(0.0, 1.4);
        let dir = -n * angle.cos() + across * angle.sin();
        let speed = rng.log_uniform(-1.0, 1.0);
        let d = dir * speed;
        let t = gap / (speed * angle.cos());
        let t_max = rng.uniform(0.1, 0.6) / speed;
        Some([p.x, p.y, p.z, d.x, d.y, d.z, r, radius, t_max, t])
    })
}

/// Rings narrower than the sphere (R = U(0.02, 0.07), r = 0.1) met with the sphere's
/// centre 10^U(−13, −6) from the axis, coming down at up to 0.5 rad from it.
fn ring_near_axis() -> Family {
    ring_family("ring, near axis", |rng| {
        let r = 0.1;
        let radius = rng.uniform(0.02, 0.07);
        let offset = rng.log_uniform(-13.0, -6.0);
        let a = rng.uniform(0.0, std::f64::consts::TAU);
        let z = (r * r - (radius - offset).powi(2)).sqrt();
        let contact = Vec3::new(offset * a.cos(), offset * a.sin(), z);
        let (beta, gamma) = (
            rng.uniform(0.0, 0.5),
            rng.uniform(0.0, std::f64::consts::TAU),
        );
        let dir = Vec3::new(
            beta.sin() * gamma.cos(),
            beta.sin() * gamma.sin(),
            -beta.cos(),
        );
        let distance = rng.uniform(0.02, 0.2);
        let speed = rng.log_uniform(-1.0, 1.0);
        let p = contact - dir * distance;
        let t = distance / speed;
        let d = dir * speed;
        Some([
            p.x,
            p.y,
            p.z,
            d.x,
            d.y,
            d.z,
            r,
            radius,
            t * rng.uniform(1.2, 3.0),
            t,
        ])
    })
}

// ---------------------------------------------------------------------------------------
// Measuring.

/// How one solver did on one family.
#[derive(Clone, Copy, Default)]
struct Score {
    /// Instances where both the answer and the reference are times.
    both: usize,
    max: f64,
    median: f64,
    /// Reference a time, answer none.
    missed: usize,
    /// Reference none, answer a time.
    spurious: usize,
    /// Times accepted only as the rounded coefficients' crossing at a graze (within 1 %).
    grazes: usize,
    /// Time per solve.
    ns: f64,
}

fn relative_error(t: f64, reference: f64) -> f64 {
    if reference == 0.0 {
        t.abs()
    } else {
        ((t - reference) / reference).abs()
    }
}

fn median(values: &mut [f64]) -> f64 {
    if values.is_empty() {
        return f64::NAN;
    }
    values.sort_by(f64::total_cmp);
    values[values.len() / 2]
}

/// Scores answers against references.
fn score(pairs: impl Iterator<Item = (Option<f64>, Option<f64>)>) -> Score {
    let mut errors = Vec::new();
    let mut s = Score::default();
    for (answer, reference) in pairs {
        match (answer, reference) {
            (Some(t), Some(r)) => errors.push(relative_error(t, r)),
            (None, Some(_)) => s.missed += 1,
            (Some(_), None) => s.spurious += 1,
            (None, None) => {}
        }
    }
    s.both = errors.len();
    s.max = errors.iter().copied().fold(0.0, f64::max);
    s.median = median(&mut errors);
    s
}

/// Scores `answers` to `instances`: against the reference, or where that disagrees and
/// the instance has a graze, against the alternative (the better of the two when both are
/// times).
fn judge(answers: impl Iterator<Item = Option<f64>>, instances: &[&Instance]) -> Score {
    let mut errors = Vec::new();
    let mut s = Score::default();
    for (answer, i) in answers.zip(instances) {
        // Some(error, if both are times) when answer and r agree on whether there is one.
        let against = |r: Option<f64>| match (answer, r) {
            (Some(t), Some(r)) => Some(Some(relative_error(t, r))),
            (None, None) => Some(None),
            _ => None,
        };
        let direct = against(i.reference);
        let alternative = i.alternative.and_then(against);
        let chosen = match (direct, alternative) {
            (Some(Some(d)), Some(Some(a))) => Some(Some(d.min(a))),
            (Some(d), _) => Some(d),
            (None, a) => a,
        };
        // A time accepted only as the rounded coefficients' crossing at a graze.
        let close = |x: Option<Option<f64>>| x.is_some_and(|e| e.is_some_and(|e| e <= 1e-2));
        let by_graze = !close(direct) && close(alternative);
        match chosen {
            Some(Some(error)) => errors.push(error),
            Some(None) => {}
            None if answer.is_some() => s.spurious += 1,
            None => s.missed += 1,
        }
        if by_graze {
            s.grazes += 1;
        }
    }
    s.both = errors.len();
    s.max = errors.iter().copied().fold(0.0, f64::max);
    s.median = median(&mut errors);
    s
}

/// Nanoseconds per solve of `f`: one timed loop of `passes` passes over `instances`.
fn time_per_solve(
    f: impl Fn(&Coeffs, f64) -> Option<f64>,
    instances: &[Instance],
    passes: usize,
) -> f64 {
    let start = Instant::now();
    for _ in 0..passes {
        for i in instances {
            black_box(f(black_box(&i.c), black_box(i.t_max)));
        }
    }
    start.elapsed().as_secs_f64() * 1e9 / (passes * instances.len()) as f64
}

/// [`time_per_solve`] of solver `k`, each solver called directly (not through a pointer).
fn time_solver(k: usize, instances: &[Instance], passes: usize) -> f64 {
    match k {
        0 => time_per_solve(ours, instances, passes),
        1 => time_per_solve(ferrari, instances, passes),
        2 => time_per_solve(ferrari_newton, instances, passes),
        3 => time_per_solve(eigen, instances, passes),
        _ => time_per_solve(eigen_newton, instances, passes),
    }
}

/// Repeats of each timing.
const REPEATS: usize = 15;

/// Nanoseconds per solve of every solver on `instances`, as (median, fastest) of
/// [`REPEATS`] loops of about 2 ms each. The repeats go round the solvers in turn, so
/// that a busy moment of the machine falls on all of them alike.
fn time_solvers(instances: &[Instance]) -> Vec<(f64, f64)> {
    let passes: Vec<usize> = (0..SOLVERS.len())
        .map(|k| {
            let once = time_solver(k, instances, 1) * instances.len() as f64;
            ((2e6 / once).ceil() as usize).max(1)
        })
        .collect();
    let mut times = vec![Vec::new(); SOLVERS.len()];
    for _ in 0..REPEATS {
        for (k, t) in times.iter_mut().enumerate() {
            t.push(time_solver(k, instances, passes[k]));
        }
    }
    times
        .into_iter()
        .map(|mut t| {
            let fastest = t.iter().copied().fold(f64::INFINITY, f64::min);
            (median(&mut t), fastest)
        })
        .collect()
}

/// Every solver must get the easy case right: (t − 1)(t − 2)(t − 3)(t − 4), and its
/// negative, over several intervals.
fn check_easy_case() {
    let c: Coeffs = [24.0, -50.0, 35.0, -10.0, 1.0];
    let minus = c.map(|x| -x);
    for (k, name) in SOLVERS.iter().enumerate() {
        let near = |got: Option<f64>, want: f64| got.is_some_and(|t| (t - want).abs() < 1e-12);
        assert!(near(solve(k, &c, 5.0), 1.0), "{name}: roots 1, 2, 3, 4");
        assert!(
            near(solve(k, &c, 1.5), 1.0),
            "{name}: roots 1, 2, 3, 4 up to 1.5"
        );
        assert_eq!(
            solve(k, &c, 0.5),
            None,
            "{name}: roots 1, 2, 3, 4 up to 0.5"
        );
        assert!(
            near(solve(k, &minus, 5.0), 2.0),
            "{name}: −(roots 1, 2, 3, 4)"
        );
        assert_eq!(
            solve(k, &minus, 1.5),
            None,
            "{name}: −(roots 1…4) up to 1.5"
        );
    }
}

/// The kinds of instance within the families that have several.
fn case_name(family: &str, case: usize) -> &'static str {
    match (family, case) {
        ("repeated", 0) => "(t−a)²(t−3a)(t−4a) on [0, 2a]: graze, no entry",
        ("repeated", 1) => "(t−a)²(t−2a)(t−3a) on [0, 2.5a]: graze, entry at 2a",
        ("repeated", 2) => "(t−a)³(t−3a) on [0, 2a]: entry at a triple root",
        ("repeated", 3) => "(t−a)⁴ on [0, 2a]: graze, no entry",
        ("repeated", _) => "−(t−a)²(t−3a)(t−4a) on [0, 5a]: touch from below, entry at 4a",
        ("complex", 0) => "two real roots and a pair",
        ("complex", _) => "two pairs, no entry",
        _ => "",
    }
}

fn main() -> std::io::Result<()> {
    check_easy_case();
    let mut rng = Rng(0x51ab_50f4);
    let families = vec![
        spread(&mut rng),
        clustered(&mut rng),
        repeated(&mut rng),
        complex(&mut rng),
        ring_ordinary(),
        ring_tangent(),
        ring_imminent(),
        ring_near_axis(),
    ];

    // scores[k][f]: solver k on family f, with (median, fastest) ns.
    let mut scores = vec![vec![Score::default(); families.len()]; SOLVERS.len()];
    let mut fastest = vec![vec![0.0; families.len()]; SOLVERS.len()];
    for (f, family) in families.iter().enumerate() {
        let times = time_solvers(&family.instances);
        for (k, row) in scores.iter_mut().enumerate() {
            let all: Vec<&Instance> = family.instances.iter().collect();
            let mut s = judge(all.iter().map(|i| solve(k, &i.c, i.t_max)), &all);
            (s.ns, fastest[k][f]) = times[k];
            row[f] = s;
        }
    }

    println!(
        "Quartic solvers: the first entering root. {INSTANCES} instances a family. Relative \
         error where the answer and the reference are both times; entries missed and \
         spurious; ns per solve (median of {REPEATS} repeats, fastest in brackets). \
         \"perfect\": the exact first entry of the rounded coefficients, what no solver of \
         them can beat.\n"
    );
    println!(
        "| family | solver | max error | median error | missed | spurious | grazes taken | ns |"
    );
    println!("|---|---|---|---|---|---|---|---|");
    let e = |x: f64| format!("{x:.1e}");
    let mut perfect_max = Vec::new();
    for (f, family) in families.iter().enumerate() {
        let all: Vec<&Instance> = family.instances.iter().collect();
        let perfect = judge(all.iter().map(|i| i.rounded), &all);
        perfect_max.push(perfect.max);
        println!(
            "| {} | perfect | {} | {} | {} | {} | {} | |",
            family.name,
            e(perfect.max),
            e(perfect.median),
            perfect.missed,
            perfect.spurious,
            perfect.grazes
        );
        for (k, name) in SOLVERS.iter().enumerate() {
            let s = scores[k][f];
            println!(
                "| {} | {name} | {} | {} | {} | {} | {} | {:.0} ({:.0}) |",
                family.name,
                e(s.max),
                e(s.median),
                s.missed,
                s.spurious,
                s.grazes,
                s.ns,
                fastest[k][f]
            );
        }
    }

    println!(
        "\nBy kind of instance (entries missed / spurious / grazes taken as entries, max \
         error):"
    );
    for family in &families {
        let cases = family.instances.iter().map(|i| i.case).max().unwrap_or(0);
        if cases == 0 {
            continue;
        }
        for case in 0..=cases {
            let of_case: Vec<&Instance> =
                family.instances.iter().filter(|i| i.case == case).collect();
            print!(
                "  {} {} ({}):",
                family.name,
                case_name(family.name, case),
                of_case.len()
            );
            let perfect = judge(of_case.iter().map(|i| i.rounded), &of_case);
            print!(
                " perfect {}/{}/{} {};",
                perfect.missed,
                perfect.spurious,
                perfect.grazes,
                e(perfect.max)
            );
            for (k, name) in SOLVERS.iter().enumerate() {
                let s = judge(of_case.iter().map(|i| solve(k, &i.c, i.t_max)), &of_case);
                print!(
                    " {name} {}/{}/{} {};",
                    s.missed,
                    s.spurious,
                    s.grazes,
                    e(s.max)
                );
            }
            println!();
        }
    }

    println!();
    for family in &families {
        let with_entry = family
            .instances
            .iter()
            .filter(|i| i.reference.is_some())
            .count();
        print!(
            "{}: {with_entry} of {} have an entry",
            family.name,
            family.instances.len()
        );
        if family.checks.is_empty() {
            let shift = score(family.instances.iter().map(|i| (i.ideal, i.rounded)));
            print!(
                "; rounding the coefficients moves the intended first entry by up to {} \
                 (median {}), makes {} / {} entries disappear / appear",
                e(shift.max),
                e(shift.median),
                shift.spurious,
                shift.missed
            );
        } else {
            let check = score(family.checks.iter().copied());
            print!(
                "; the geometric reference and the exact quartic's (formed in \
                 double-double) differ by up to {}, disagree on {} / {}",
                e(check.max),
                check.missed,
                check.spurious
            );
        }
        println!();
    }

    // Chart: each solver's worst family against its cost, and the Pareto front. The worst
    // is over every family but the last (near the axis, where the coefficients themselves
    // fail every solver and the evaluator does not use them alone); the cost is the mean
    // over all families.
    let covered = families.len() - 1;
    let summary: Vec<((f64, f64), usize)> = scores
        .iter()
        .map(|row| {
            let ns = row.iter().map(|s| s.ns).sum::<f64>() / row.len() as f64;
            let err = row[..covered].iter().map(|s| s.max).fold(0.0, f64::max);
            let wrong = row[..covered].iter().map(|s| s.missed + s.spurious).sum();
            ((ns, err.max(FLOOR_DRAWN)), wrong)
        })
        .collect();
    println!();
    for (k, name) in SOLVERS.iter().enumerate() {
        let ((ns, err), wrong) = summary[k];
        println!(
            "{name}: mean {ns:.0} ns; over families 1–{covered}: worst max error {}, {wrong} \
             entries missed or spurious",
            e(err)
        );
    }
    let mut series: Vec<Series> = SOLVERS
        .iter()
        .zip(&summary)
        .map(|(name, &(point, wrong))| {
            Series::new(
                format!("{name}: {wrong} entries missed or spurious"),
                vec![point],
                Mark::Dots,
            )
        })
        .collect();
    let points: Vec<(f64, f64)> = summary.iter().map(|s| s.0).collect();
    series.push(Series::new(
        "Pareto front",
        pareto_front(&points),
        Mark::Dashed,
    ));
    write(
        &out_dir(),
        &Chart {
            name: "quartic".into(),
            title: format!("Quartic solvers, first entering root: worst of families 1–{covered}"),
            x_label: "ns per solve (mean over the families)".into(),
            y_label: "max relative error (worst family)".into(),
            log_x: true,
            log_y: true,
        },
        &series,
    )?;

    let mut by_family: Vec<Series> = SOLVERS
        .iter()
        .enumerate()
        .map(|(k, name)| {
            Series::new(
                *name,
                scores[k]
                    .iter()
                    .enumerate()
                    .map(|(f, s)| ((f + 1) as f64, s.max.max(FLOOR_DRAWN)))
                    .collect(),
                Mark::Line,
            )
        })
        .collect();
    by_family.push(Series::new(
        "perfect (exact root of the rounded coefficients)",
        perfect_max
            .iter()
            .enumerate()
            .map(|(f, &max)| ((f + 1) as f64, max.max(FLOOR_DRAWN)))
            .collect(),
        Mark::Dashed,
    ));
    write(
        &out_dir(),
        &Chart {
            name: "quartic_families".into(),
            title: "Quartic solvers: max relative error of the first entering root".into(),
            x_label: FAMILY_AXIS.into(),
            y_label: "max relative error".into(),
            log_x: false,
            log_y: true,
        },
        &by_family,
    )?;
    let cost: Vec<Series> = SOLVERS
        .iter()
        .enumerate()
        .map(|(k, name)| {
            Series::new(
                *name,
                scores[k]
                    .iter()
                    .enumerate()
                    .map(|(f, s)| ((f + 1) as f64, s.ns))
                    .collect(),
                Mark::Line,
            )
        })
        .collect();
    write(
        &out_dir(),
        &Chart {
            name: "quartic_cost".into(),
            title: "Quartic solvers: time per solve".into(),
            x_label: FAMILY_AXIS.into(),
            y_label: "ns per solve (median of repeats)".into(),
            log_x: false,
            log_y: true,
        },
        &cost,
    )?;
    Ok(())
}
