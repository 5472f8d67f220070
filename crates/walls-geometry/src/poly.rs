//! The first moment a polynomial of degree at most 4 falls through zero: the root finder of
//! the hard-sphere (HSDEM) collision predictor. For a particle moving in a straight line
//! near a wall feature, the overlap function f(t) is linear (faces), quadratic (points,
//! lines, cylinders) or quartic (a sphere against a ring: ray–torus), negative while the
//! sphere overlaps the feature; a contact begins where f goes from positive to negative.
//!
//! Method: root isolation by recursive derivatives (C. Yuksel, "High-Performance
//! Polynomial Root Finding for Graphics", HPG 2022). The real roots of f′ in [0, t_max]
//! cut the interval into pieces on which f is monotone; they are found the same way one
//! degree down (closed form for the linear and quadratic levels, with the
//! cancellation-free q = −½(b + sgn(b)·√D)). Which piece holds the answer is decided by
//! the signs of f at the cut points alone, so a simple root is never missed, however close
//! it lies to 0 or to t_max. On that piece the root is found by Newton's method kept
//! inside the bracket, with false position and bisection as fallbacks (a quadratic f
//! starts from its closed-form root), to convergence. Everything lives in fixed-size
//! arrays on the stack: no allocation.
//!
//! Accuracy. Horner's rule rounds f(t) by up to γ₂ₙ·Σ|cᵢ|·|t|ⁱ. Wherever a value is
//! within that bound of zero (always near a root), it is recomputed by compensated Horner,
//! as accurate as Horner in twice the precision; so signs are right and Newton converges
//! on the root of the given coefficients to about an ulp even when the root is ill
//! conditioned (clustered or nearly double roots), not just somewhere in the rounding
//! noise. What remains is the rounding the caller made in forming the coefficients.
//!
//! Grazing. A root of even multiplicity (the path touches the feature and leaves) is not a
//! sign change and gives no answer: a cut point (a root of f′) lands on it, f is zero
//! there and positive on both sides. f at a cut point that is within the compensated
//! rounding bound of zero (about 1e−30·Σ|cᵢ|·|t|ⁱ) is taken as exactly zero, so the
//! rounding of evaluating f does not turn a double root into a crossing. Rounding the
//! *coefficients* of an exact double root is another matter: about half the time it
//! leaves a real shallow crossing in the polynomial given (372 of 758 cases of
//! (t−a)²(t−3a)(t−4a) in docs/accuracy.md's test set), and that is returned, as it
//! should be for those coefficients; the contact it gives has a normal speed near zero
//! (the caller checks the normal velocity). A dip narrower than the accuracy of the cut
//! point (a few ulps) can be stepped over, which reads as a graze.

/// The highest degree handled.
const MAX_DEGREE: usize = 4;

/// Safeguard on the Newton–bisection loop for one root; a handful of steps is typical.
const MAX_ITERATIONS: usize = 100;

/// Coefficients, lowest degree first.
type Poly = [f64; MAX_DEGREE + 1];

/// Up to three points (the real roots of a derivative) in increasing order, on the stack.
#[derive(Clone, Copy)]
struct Points {
    x: [f64; MAX_DEGREE - 1],
    len: usize,
}

impl Points {
    const EMPTY: Points = Points {
        x: [0.0; MAX_DEGREE - 1],
        len: 0,
    };

    /// Appends `t`, which is not below the last point.
    fn push(&mut self, t: f64) {
        if self.len < self.x.len() {
            self.x[self.len] = t;
            self.len += 1;
        }
    }
}

/// The first time t in [0, t_max] at which f(t) = `c[0] + c[1]·t + …` (lowest degree first,
/// at most degree 4) falls through zero: f(t) = 0 with f changing sign from positive to
/// negative there (a root of odd multiplicity where f decreases). A touching root of even
/// multiplicity (a graze) does not count. `None` if there is none, or if the coefficients
/// or t_max are not finite.
///
/// - If f(0) < 0 already, the answer is the first *later* downward crossing, after f has
///   come back above zero (the caller deals with existing overlaps itself).
/// - If f(0) = 0 exactly, the answer is 0 when f is negative right after 0 (its first
///   nonzero coefficient after `c[0]` is negative); otherwise 0 does not count.
/// - A root at t_max counts when f is positive before it and the root has odd
///   multiplicity (f is negative right after t_max).
/// - Leading zero coefficients lower the degree; all zero (or a constant) gives `None`. An
///   empty interval (t_max < 0) gives `None`.
/// - The answer is the root of the given coefficients to about an ulp (see the module
///   documentation), and so within a few ulps of the intended root where that is well
///   conditioned; near-double roots (grazes at rounding level) are described there too.
/// - Values of f at t_max must not overflow (|c|·t_max⁴ well below 1e308).
///
/// # Panics
///
/// If `c` has more than five coefficients (degree above 4).
pub fn first_entry(c: &[f64], t_max: f64) -> Option<f64> {
    assert!(
        c.len() <= MAX_DEGREE + 1,
        "first_entry: degree at most {MAX_DEGREE} ({} coefficients given)",
        c.len()
    );
    if !t_max.is_finite() || c.iter().any(|x| !x.is_finite()) || t_max < 0.0 {
        return None;
    }
    let mut f: Poly = std::array::from_fn(|i| c.get(i).copied().unwrap_or(0.0));
    let n = f.iter().rposition(|&x| x != 0.0)?;
    if n == 0 {
        return None;
    }
    scale(&mut f);

    // Exactly zero at 0: the first nonzero coefficient says which way f leaves 0.
    if f[0] == 0.0 {
        let k = f[1..=n].iter().position(|&x| x != 0.0)? + 1;
        if f[k] < 0.0 {
            return Some(0.0);
        }
    }
    if t_max == 0.0 {
        return None;
    }

    // The chain of derivatives d[j] = f⁽ʲ⁾ (degree n − j) and their roots in (0, t_max),
    // from the linear one up: roots[j] cut d[j − 1] into monotone pieces.
    let [_, c1, c2, c3, c4] = f;
    let d: [Poly; MAX_DEGREE + 1] = [
        f,
        [c1, 2.0 * c2, 3.0 * c3, 4.0 * c4, 0.0],
        [2.0 * c2, 6.0 * c3, 12.0 * c4, 0.0, 0.0],
        [6.0 * c3, 24.0 * c4, 0.0, 0.0, 0.0],
        [24.0 * c4, 0.0, 0.0, 0.0, 0.0],
    ];
    // (Filled in place: building them elsewhere and copying costs more than the search.)
    let mut roots = [Points::EMPTY; MAX_DEGREE];
    for j in (1..n).rev() {
        let (done, todo) = roots.split_at_mut(j + 1);
        match n - j {
            1 => linear_root(&d[j], t_max, &mut done[j]),
            2 => quadratic_roots(&d[j], t_max, &mut done[j]),
            m => isolate(&d[j], m, &todo[0], t_max, &mut done[j]),
        }
    }
    let cuts = &roots[1];

    // Walk the pieces in time order. `above`: f is positive just before the current cut
    // point (the last nonzero sign seen).
    let mut above = f[0] >= 0.0;
    let (mut a, mut fa) = (0.0, f[0]);
    for k in 0..=cuts.len {
        let b = if k < cuts.len { cuts.x[k] } else { t_max };
        let fb = eval_sure(&f, n, b);
        if fb < 0.0 && above {
            return Some(if fa > 0.0 {
                root_on_piece(&f, n, a, b, fa, fb)
            } else {
                // f was 0 at a, positive before it and negative after.
                a
            });
        }
        if fb == 0.0 && above && k == cuts.len && descends_through_zero(&d, n, b) {
            return Some(b);
        }
        if fb != 0.0 {
            above = fb > 0.0;
        }
        (a, fa) = (b, fb);
    }
    None
}

/// Rescales f by a power of two (exactly) when its coefficients are so large or small that
/// squares or derivatives of them could overflow or underflow. The roots do not change.
fn scale(f: &mut Poly) {
    const TINY: f64 = f64::from_bits((1023 - 500) << 52); // 2⁻⁵⁰⁰
    const HUGE: f64 = f64::from_bits((1023 + 500) << 52); // 2⁵⁰⁰
    let max = f.iter().fold(0.0_f64, |m, x| m.max(x.abs()));
    if (TINY..=HUGE).contains(&max) {
        return;
    }
    let exponent = ((max.to_bits() >> 52) & 0x7ff) as i64 - 1023;
    let exponent = exponent.clamp(-1022, 1022);
    let factor = f64::from_bits(((1023 - exponent) as u64) << 52);
    for x in f.iter_mut() {
        *x *= factor;
    }
}

/// Whether f, zero at t, changes sign there going down: its first nonzero derivative at t
/// has odd order and is negative.
fn descends_through_zero(d: &[Poly; MAX_DEGREE + 1], n: usize, t: f64) -> bool {
    (1..=n)
        .map(|k| (k, eval(&d[k], n - k, t)))
        .find(|&(_, v)| v != 0.0)
        .is_some_and(|(k, v)| k % 2 == 1 && v < 0.0)
}

/// The root of p(t) = p[0] + p[1]·t in (0, t_max), if any, into `out`.
fn linear_root(p: &Poly, t_max: f64, out: &mut Points) {
    let t = -p[0] / p[1];
    if t > 0.0 && t < t_max {
        out.push(t);
    }
}

/// Both real roots of p[0] + p[1]·t + p[2]·t², p[2] ≠ 0, in increasing order (a double
/// root twice), by the cancellation-free formula; `None` when they are complex.
fn quadratic(p: &Poly) -> Option<(f64, f64)> {
    let (c, b, a) = (p[0], p[1], p[2]);
    let disc = b * b - 4.0 * a * c;
    if disc < 0.0 {
        return None;
    }
    let q = -0.5 * (b + disc.sqrt().copysign(b));
    if q == 0.0 {
        // b = 0 and then c = 0: p = a·t².
        return Some((0.0, 0.0));
    }
    let (r1, r2) = (q / a, c / q);
    Some(if r1 <= r2 { (r1, r2) } else { (r2, r1) })
}

/// The real roots of the quadratic p in (0, t_max), in increasing order, into `out`.
fn quadratic_roots(p: &Poly, t_max: f64, out: &mut Points) {
    if let Some((r1, r2)) = quadratic(p) {
        for t in [r1, r2] {
            if t > 0.0 && t < t_max {
                out.push(t);
            }
        }
    }
}

/// The roots of p (degree m ≥ 3) in (0, t_max) where it changes sign, in increasing order,
/// given the cut points (the roots of p′) between which it is monotone, into `out`. A cut
/// point where p is 0 is included.
fn isolate(p: &Poly, m: usize, cuts: &Points, t_max: f64, out: &mut Points) {
    let (mut a, mut fa) = (0.0, p[0]);
    for k in 0..=cuts.len {
        let b = if k < cuts.len { cuts.x[k] } else { t_max };
        let fb = eval_sure(p, m, b);
        if (fa < 0.0 && fb > 0.0) || (fa > 0.0 && fb < 0.0) {
            out.push(newton(p, m, a, b, fa, fb, None));
        } else if fb == 0.0 && k < cuts.len {
            out.push(b);
        }
        (a, fa) = (b, fb);
    }
}

/// The root of f (degree n) on [a, b], where f is monotone with f(a) = `fa` and f(b) = `fb`
/// of strictly opposite signs.
fn root_on_piece(f: &Poly, n: usize, a: f64, b: f64, fa: f64, fb: f64) -> f64 {
    match n {
        // Correctly rounded.
        1 => (-f[0] / f[1]).clamp(a, b),
        // The closed form, polished (it loses digits when the roots are close).
        2 => {
            let start = match quadratic(f) {
                // The piece lies on one side of the vertex: take the root nearer to it.
                Some((r1, r2)) => {
                    let outside = |t: f64| (a - t).max(t - b).max(0.0);
                    if outside(r1) <= outside(r2) { r1 } else { r2 }.clamp(a, b)
                }
                // Rounding disagrees with the signs at the ends: trust the signs.
                None => 0.5 * (a + b),
            };
            newton(f, n, a, b, fa, fb, Some(start))
        }
        _ => newton(f, n, a, b, fa, fb, None),
    }
}

/// The root of p (degree m) in [lo, hi], where p(lo) = `flo` and p(hi) = `fhi` have
/// strictly opposite signs and p is monotone. Newton's method from `start`, or else from
/// the false-position point of the ends, each step kept strictly inside the shrinking
/// bracket; when a Newton step would leave it, or is not under 0.8 of the Newton step
/// before it (far from a root of a degree-m polynomial Newton gains only a factor
/// 1 − 1/m), false position instead (Newton also stalls when rounding hides a root very
/// near one end of a wide bracket: f(0) = 1e−300 and the other end 1e−20 away), and
/// bisection when that fails too or was the last step. Values of p whose sign plain
/// Horner cannot vouch for are recomputed with compensated Horner, so the iterates
/// converge to the root itself, not somewhere in the rounding noise around it. Stops when
/// a Newton step is within an ulp, p is 0, or the bracket cannot shrink.
#[allow(clippy::too_many_arguments)]
fn newton(
    p: &Poly,
    m: usize,
    mut lo: f64,
    mut hi: f64,
    mut flo: f64,
    mut fhi: f64,
    start: Option<f64>,
) -> f64 {
    #[derive(Clone, Copy, PartialEq)]
    enum Step {
        Newton,
        FalsePosition,
        Bisection,
    }
    let mut x = start.unwrap_or_else(|| lo - flo * ((hi - lo) / (fhi - flo)));
    if !(x >= lo && x <= hi) {
        x = lo + 0.5 * (hi - lo);
    }
    let mut last = Step::Bisection;
    let mut last_step = f64::INFINITY;
    for _ in 0..MAX_ITERATIONS {
        let (fx, slope) = eval_sure_with_slope(p, m, x);
        if fx == 0.0 {
            return x;
        }
        if (fx > 0.0) == (flo > 0.0) {
            (lo, flo) = (x, fx);
        } else {
            (hi, fhi) = (x, fx);
        }
        let newton = x - fx / slope;
        let newton_step = (newton - x).abs();
        if newton_step <= f64::EPSILON * x.abs() && newton >= lo && newton <= hi {
            return newton;
        }
        let inside = |t: f64| t > lo && t < hi;
        let (next, step) =
            if inside(newton) && (last != Step::Newton || newton_step <= 0.8 * last_step) {
                (newton, Step::Newton)
            } else {
                let secant = lo - flo * ((hi - lo) / (fhi - flo));
                if last != Step::FalsePosition && inside(secant) {
                    (secant, Step::FalsePosition)
                } else {
                    let mid = lo + 0.5 * (hi - lo);
                    if mid <= lo || mid >= hi {
                        return x;
                    }
                    (mid, Step::Bisection)
                }
            };
        (last, last_step) = (step, (next - x).abs());
        x = next;
    }
    x
}

/// p(t) by Horner's rule, p of degree m.
fn eval(p: &Poly, m: usize, t: f64) -> f64 {
    p[..=m].iter().rev().fold(0.0, |acc, &c| acc * t + c)
}

/// The rounding bound of Horner's rule on degree m, relative to Σ|pᵢ|·|t|ⁱ: above γ₂ₘ.
fn horner_bound(m: usize) -> f64 {
    2.0 * m as f64 * f64::EPSILON
}

/// p(t) and p′(t) by Horner's rule, p of degree m, the value made sure of its sign: where
/// it is within Horner's rounding bound of zero it is recomputed by compensated Horner,
/// and where that too is within its bound of zero, it is 0.
fn eval_sure_with_slope(p: &Poly, m: usize, t: f64) -> (f64, f64) {
    let mut value = p[m];
    let mut slope = 0.0;
    let mut magnitude = p[m].abs();
    for &c in p[..m].iter().rev() {
        slope = slope * t + value;
        value = value * t + c;
        magnitude = magnitude * t.abs() + c.abs();
    }
    (sure(p, m, t, value, magnitude), slope)
}

/// p(t), made sure of its sign (see [`eval_sure_with_slope`]).
fn eval_sure(p: &Poly, m: usize, t: f64) -> f64 {
    let mut value = p[m];
    let mut magnitude = p[m].abs();
    for &c in p[..m].iter().rev() {
        value = value * t + c;
        magnitude = magnitude * t.abs() + c.abs();
    }
    sure(p, m, t, value, magnitude)
}

/// The plain Horner value of p(t) if its sign is certain, else the compensated value if
/// that one's is, else 0.
fn sure(p: &Poly, m: usize, t: f64, value: f64, magnitude: f64) -> f64 {
    let bound = horner_bound(m);
    if value.abs() > bound * magnitude {
        return value;
    }
    let accurate = eval_compensated(p, m, t);
    if !accurate.is_finite() {
        value
    } else if accurate.abs() > bound * bound * magnitude {
        accurate
    } else {
        0.0
    }
}

/// p(t) by compensated Horner (Graillat, Langlois & Louvet 2005): as if computed in twice
/// the precision, then rounded; error ≤ u·|p(t)| + γ₂ₘ²·Σ|pᵢ|·|t|ⁱ. Error-free products by
/// Dekker's splitting (no FMA needed).
fn eval_compensated(p: &Poly, m: usize, t: f64) -> f64 {
    let (t_hi, t_lo) = split(t);
    let mut value = p[m];
    let mut correction = 0.0;
    for &c in p[..m].iter().rev() {
        let product = value * t;
        let (v_hi, v_lo) = split(value);
        let product_error = v_lo * t_lo - (((product - v_hi * t_hi) - v_lo * t_hi) - v_hi * t_lo);
        let sum = product + c;
        let b = sum - product;
        let sum_error = (product - (sum - b)) + (c - b);
        value = sum;
        correction = correction * t + (product_error + sum_error);
    }
    value + correction
}

/// a = hi + lo exactly, each with at most 26 significant bits (Veltkamp).
fn split(a: f64) -> (f64, f64) {
    let scaled = 134_217_729.0 * a; // 2²⁷ + 1
    let hi = scaled - (scaled - a);
    (hi, a - hi)
}
