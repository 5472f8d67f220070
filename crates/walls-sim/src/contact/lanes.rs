//! pkdgrav's contact law between two particles ([`super::ssdem::dashpot_contact`]) for
//! four contacts at once, each in a lane of its own: the same operations on each lane
//! in the same order, so each lane's numbers are bit for bit those of the law on its
//! contact alone (`tests/lanes.rs` holds the two side by side), but for the sign and
//! payload of a NaN, which Rust leaves unspecified (a NaN stops a run whatever its
//! sign). The lanes are the processor's own vectors, four numbers an instruction
//! (AVX2, through `pulp`'s safe `V3` operations, each the IEEE operation on each lane):
//! plain arrays, which the compiler vectorised as it chose, ran mostly two lanes an
//! instruction. A branch of the law becomes both arms and a choice between them in each
//! lane. [`Simd::new`] says whether the processor has the instructions; without them, or
//! off x86-64, there are no lanes and the run takes every contact one at a time. The
//! code that calls [`pair`] or [`dashpot`] must be compiled for AVX2 (the run's pair
//! loops are, with `multiversion`), or each operation would be a call; so must a
//! closure that holds vector operations, which is compiled for the target features of
//! the function it is written in (none here): this file keeps them out of closures.
//!
//! Only the common case runs here: two free particles, the `DEM_ROTATION_DASHPOT` build
//! without its optional parts (no cohesion, no two layers, no contact radius). The run
//! takes any other contact to the law itself.

use super::ssdem::{Record, Restitution, SERIES_UP_TO, Sliding};
use pulp::{f64x4, m64x4};
use walls_geometry::Material;

#[cfg(not(target_arch = "x86_64"))]
use elsewhere::Token;
#[cfg(target_arch = "x86_64")]
use pulp::x86::V3 as Token;

/// How many contacts go together.
pub const LANES: usize = 4;

/// One number in each lane.
pub type L = f64x4;

/// One boolean in each lane.
type Mask = m64x4;

/// The lanes' numbers, lane `l`'s `f(l)` (each read straight into its lane).
#[inline(always)]
pub fn gather(f: impl Fn(usize) -> f64) -> L {
    f64x4(f(0), f(1), f(2), f(3))
}

/// The lanes' numbers as an array.
#[inline(always)]
pub fn to_array(a: L) -> [f64; LANES] {
    [a.0, a.1, a.2, a.3]
}

/// The lanes' booleans as an array.
#[inline(always)]
fn bools(m: Mask) -> [bool; LANES] {
    [m.0.is_set(), m.1.is_set(), m.2.is_set(), m.3.is_set()]
}

/// The processor's vector instructions the lanes compute with, four numbers an
/// instruction: `pulp`'s `V3`, x86-64-v3 (AVX2, FMA, BMI1 and 2, LZCNT, POPCNT), whose
/// operations are the processor's own, each the IEEE operation on each lane. Held only
/// where the processor has them.
#[derive(Clone, Copy)]
pub struct Simd(Token);

impl Simd {
    /// The vector instructions, if this processor has them.
    pub fn new() -> Option<Simd> {
        Token::try_new().map(Simd)
    }

    #[inline(always)]
    fn add(self, a: L, b: L) -> L {
        self.0.add_f64x4(a, b)
    }

    #[inline(always)]
    fn sub(self, a: L, b: L) -> L {
        self.0.sub_f64x4(a, b)
    }

    #[inline(always)]
    fn mul(self, a: L, b: L) -> L {
        self.0.mul_f64x4(a, b)
    }

    #[inline(always)]
    fn div(self, a: L, b: L) -> L {
        self.0.div_f64x4(a, b)
    }

    #[inline(always)]
    fn sqrt(self, a: L) -> L {
        self.0.sqrt_f64x4(a)
    }

    /// `-a`: the sign bit flipped, as Rust's negation does.
    #[inline(always)]
    fn neg(self, a: L) -> L {
        self.0.xor_f64x4(a, self.splat(-0.0))
    }

    /// `|a|`: the sign bit cleared.
    #[inline(always)]
    fn abs(self, a: L) -> L {
        self.0.abs_f64x4(a)
    }

    /// `a.copysign(sign)`: `a`'s size with `sign`'s sign bit.
    #[inline(always)]
    fn copysign(self, a: L, sign: L) -> L {
        let bit = self.0.and_f64x4(sign, self.splat(-0.0));
        self.0.or_f64x4(self.abs(a), bit)
    }

    /// The same number in every lane.
    #[inline(always)]
    fn splat(self, x: f64) -> L {
        self.0.splat_f64x4(x)
    }

    /// `yes` in the lanes of `mask`, else `no`.
    #[inline(always)]
    fn pick(self, mask: Mask, yes: L, no: L) -> L {
        self.0.select_f64x4(mask, yes, no)
    }

    /// `a == b` (a NaN equals nothing).
    #[inline(always)]
    fn eq(self, a: L, b: L) -> Mask {
        self.0.cmp_eq_f64x4(a, b)
    }

    /// `a > b` (false with a NaN).
    #[inline(always)]
    fn gt(self, a: L, b: L) -> Mask {
        self.0.cmp_gt_f64x4(a, b)
    }

    /// `a <= b` (false with a NaN).
    #[inline(always)]
    fn le(self, a: L, b: L) -> Mask {
        self.0.cmp_le_f64x4(a, b)
    }

    #[inline(always)]
    fn and(self, a: Mask, b: Mask) -> Mask {
        self.0.and_m64x4(a, b)
    }

    #[inline(always)]
    fn not(self, a: Mask) -> Mask {
        self.0.not_m64x4(a)
    }

    /// A term of the sine's and cosine's series: `1 − x²·f·rest`.
    #[inline(always)]
    fn term(self, x2: L, f: f64, rest: L) -> L {
        self.sub(self.splat(1.0), self.mul(self.mul(x2, self.splat(f)), rest))
    }

    /// Whether any lane of `m` is set.
    #[inline(always)]
    fn any(self, m: Mask) -> bool {
        bools(m).iter().any(|&b| b)
    }

    /// Whether every lane of `m` is set.
    #[inline(always)]
    fn all(self, m: Mask) -> bool {
        bools(m).iter().all(|&b| b)
    }
}

/// A vector in each lane, as nalgebra's `Vector3<f64>` computes with it (the same
/// operations in the same order: `x·x' + y·y'` then `+ z·z'`, and so on).
#[derive(Clone, Copy)]
pub struct V {
    /// The x components.
    pub x: L,
    /// The y components.
    pub y: L,
    /// The z components.
    pub z: L,
}

impl V {
    /// Zero in every lane.
    #[inline(always)]
    pub fn zeros() -> V {
        let z = f64x4(0.0, 0.0, 0.0, 0.0);
        V { x: z, y: z, z }
    }

    /// Lane `l`'s vector `f(l)` in each lane.
    #[inline(always)]
    pub fn gather(f: impl Fn(usize) -> [f64; 3]) -> V {
        let each: [[f64; 3]; LANES] = std::array::from_fn(f);
        V {
            x: gather(|l| each[l][0]),
            y: gather(|l| each[l][1]),
            z: gather(|l| each[l][2]),
        }
    }

    /// Each lane's vector.
    #[inline(always)]
    pub fn each_lane(&self) -> [[f64; 3]; LANES] {
        let (x, y, z) = (to_array(self.x), to_array(self.y), to_array(self.z));
        std::array::from_fn(|l| [x[l], y[l], z[l]])
    }
}

/// The lanes' vector operations.
impl Simd {
    #[inline(always)]
    fn vadd(self, a: V, b: V) -> V {
        V {
            x: self.add(a.x, b.x),
            y: self.add(a.y, b.y),
            z: self.add(a.z, b.z),
        }
    }

    #[inline(always)]
    fn vsub(self, a: V, b: V) -> V {
        V {
            x: self.sub(a.x, b.x),
            y: self.sub(a.y, b.y),
            z: self.sub(a.z, b.z),
        }
    }

    /// Each component times the lane's `s`.
    #[inline(always)]
    fn scale(self, v: V, s: L) -> V {
        V {
            x: self.mul(v.x, s),
            y: self.mul(v.y, s),
            z: self.mul(v.z, s),
        }
    }

    /// Each component over the lane's `s`.
    #[inline(always)]
    fn unscale(self, v: V, s: L) -> V {
        V {
            x: self.div(v.x, s),
            y: self.div(v.y, s),
            z: self.div(v.z, s),
        }
    }

    #[inline(always)]
    fn vneg(self, v: V) -> V {
        V {
            x: self.neg(v.x),
            y: self.neg(v.y),
            z: self.neg(v.z),
        }
    }

    #[inline(always)]
    fn dot(self, a: V, b: V) -> L {
        self.add(
            self.add(self.mul(a.x, b.x), self.mul(a.y, b.y)),
            self.mul(a.z, b.z),
        )
    }

    #[inline(always)]
    fn norm_squared(self, v: V) -> L {
        self.dot(v, v)
    }

    #[inline(always)]
    fn norm(self, v: V) -> L {
        self.sqrt(self.norm_squared(v))
    }

    #[inline(always)]
    fn cross(self, a: V, b: V) -> V {
        V {
            x: self.sub(self.mul(a.y, b.z), self.mul(a.z, b.y)),
            y: self.sub(self.mul(a.z, b.x), self.mul(a.x, b.z)),
            z: self.sub(self.mul(a.x, b.y), self.mul(a.y, b.x)),
        }
    }

    /// Whether each lane's vector is zero (component by component: −0 is, NaN is not).
    #[inline(always)]
    fn is_zero(self, v: V) -> Mask {
        let zero = self.splat(0.0);
        self.and(
            self.and(self.eq(v.x, zero), self.eq(v.y, zero)),
            self.eq(v.z, zero),
        )
    }

    /// `yes` in the lanes of `mask`, else `no`.
    #[inline(always)]
    fn vpick(self, mask: Mask, yes: V, no: V) -> V {
        V {
            x: self.pick(mask, yes.x, no.x),
            y: self.pick(mask, yes.y, no.y),
            z: self.pick(mask, yes.z, no.z),
        }
    }
}

/// Four [`super::ssdem::Dashpot`] contacts between free particles, lane by lane.
pub struct Contacts {
    /// The overlaps.
    pub overlap: L,
    /// The unit normals from particle 1 towards its partner.
    pub normal: V,
    /// The partners' contact-point velocities relative to particle 1's, predicted.
    pub velocity: V,
    /// The partners' spins less particle 1's, predicted.
    pub spin: V,
    /// The sums of the two spins as they are.
    pub turn: V,
    /// The levers l₁ and l₂.
    pub levers: (L, L),
    /// The rolling radii R*.
    pub radius: L,
    /// The normal and tangential damping coefficients C_n and C_t.
    pub damping: (L, L),
}

/// What four contacts do: the forces on particle 1 and the torques on both.
pub struct Forces {
    /// The forces on particle 1.
    pub force: V,
    /// The torques on particle 1.
    pub torque: V,
    /// The torques on the partners.
    pub partner_torque: V,
}

/// The records of four contacts, lane by lane.
struct Records {
    spring: V,
    normal: V,
    roll: V,
    twist: L,
}

impl Records {
    #[inline(always)]
    fn gather(records: &[&mut Record; LANES]) -> Records {
        Records {
            spring: V::gather(|l| records[l].spring.into()),
            normal: V::gather(|l| records[l].normal.into()),
            roll: V::gather(|l| records[l].roll.into()),
            twist: gather(|l| records[l].twist),
        }
    }

    #[inline(always)]
    fn scatter(&self, records: [&mut Record; LANES]) {
        let (spring, normal, roll) = (
            self.spring.each_lane(),
            self.normal.each_lane(),
            self.roll.each_lane(),
        );
        let twist = to_array(self.twist);
        for (l, r) in records.into_iter().enumerate() {
            r.spring = spring[l].into();
            r.normal = normal[l].into();
            r.roll = roll[l].into();
            r.twist = twist[l];
        }
    }
}

/// `v` turned about the unit `axis` by the angle whose sine and cosine are given, in the
/// lanes of `mask` where `v` is not zero (a zero spring is left alone).
#[inline(always)]
fn turn(k: Simd, v: V, axis: V, (sin, cos): (L, L), mask: Mask) -> V {
    let one_less = k.sub(k.splat(1.0), cos);
    let turned = k.vadd(
        k.vadd(k.scale(v, cos), k.scale(k.cross(axis, v), sin)),
        k.scale(axis, k.mul(k.dot(axis, v), one_less)),
    );
    let zero = k.is_zero(v);
    k.vpick(k.and(mask, k.not(zero)), turned, v)
}

/// [`super::ssdem::small_sin_cos`] in each lane: its series (`ssdem::sin_cos_series`, the
/// same operations in the same order) in all lanes at once, the library's in a lane
/// whose angle is too large for it.
#[inline(always)]
fn sin_cos(k: Simd, x: L) -> (L, L) {
    let (one, x2) = (k.splat(1.0), k.mul(x, x));
    let sin = k.mul(
        x,
        k.term(
            x2,
            1.0 / 6.0,
            k.term(x2, 1.0 / 20.0, k.term(x2, 1.0 / 42.0, one)),
        ),
    );
    let cos = k.term(
        x2,
        0.5,
        k.term(
            x2,
            1.0 / 12.0,
            k.term(x2, 1.0 / 30.0, k.term(x2, 1.0 / 56.0, one)),
        ),
    );
    let far = k.le(k.splat(SERIES_UP_TO), k.abs(x));
    if !k.any(far) {
        return (sin, cos);
    }
    let (mut sin, mut cos, x) = (to_array(sin), to_array(cos), to_array(x));
    for (l, far) in bools(far).into_iter().enumerate() {
        if far {
            (sin[l], cos[l]) = x[l].sin_cos();
        }
    }
    (gather(|l| sin[l]), gather(|l| cos[l]))
}

/// pkdgrav's contact law ([`super::ssdem::dashpot_contact_with`], with the damping
/// given and nothing else optional) on four contacts between free particles, with their
/// records, in material `mat` over `dt`, the shear spring limited as `sliding` says.
#[inline(always)]
pub fn dashpot(
    k: Simd,
    c: &Contacts,
    records: [&mut Record; LANES],
    dt: f64,
    mat: &Material,
    sliding: Sliding,
) -> Forces {
    let mut r = Records::gather(&records);
    let n = c.normal;
    let (k_n, k_t) = (mat.k_n, mat.k_t);
    let spring_force = k.mul(k.splat(k_n), c.overlap);
    let old = k.not(k.is_zero(r.normal));
    // §1.3 step 1: about the mean normal, by the mean spin of the two over the step.
    let mean = k.vadd(r.normal, n);
    let size = k.norm(mean);
    let mean = k.unscale(mean, size);
    let angle = k.mul(k.splat(0.5 * dt), k.dot(c.turn, mean));
    // (A mean of zero length is no axis; one whose length is not a number is, as
    // `try_normalize(0.0)` has it: none only when the length is at most 0.)
    let axis = k.not(k.le(size, k.splat(0.0)));
    let first = k.and(k.and(old, axis), k.not(k.eq(angle, k.splat(0.0))));
    // (A zero rolling spring, in every lane without rolling resistance, stays zero.)
    let rolls = !k.all(k.is_zero(r.roll));
    if k.any(first) {
        let sc = sin_cos(k, angle);
        r.spring = turn(k, r.spring, mean, sc, first);
        if rolls {
            r.roll = turn(k, r.roll, mean, sc, first);
        }
    }
    // Step 2: with the change of normal.
    let a = k.cross(r.normal, n);
    let sin = k.norm(a);
    let second = k.and(old, k.gt(sin, k.splat(0.0)));
    if k.any(second) {
        let axis = k.unscale(a, sin);
        let cos = k.dot(n, r.normal);
        r.spring = turn(k, r.spring, axis, (sin, cos), second);
        if rolls {
            r.roll = turn(k, r.roll, axis, (sin, cos), second);
        }
    }
    r.normal = n;
    let u = c.velocity;
    let un = k.scale(n, k.dot(n, u));
    let ut = k.vsub(u, un);
    let (c_n, c_t) = c.damping;
    let f_n = k.vadd(k.scale(n, k.neg(spring_force)), k.scale(un, c_n));
    let normal_force = k.norm(f_n);
    // Step 4 and 5: the shear spring, and the slide.
    r.spring = k.vadd(r.spring, k.scale(ut, k.splat(dt)));
    let cap = k.mul(k.splat(mat.mu_s), normal_force);
    let f_t = k.vadd(k.scale(r.spring, k.splat(k_t)), k.scale(ut, c_t));
    let sticks = k.le(k.norm_squared(f_t), k.mul(cap, cap));
    let f_t = if k.all(sticks) {
        f_t
    } else {
        let (spring, slid) = match sliding {
            Sliding::Reset => {
                let speed = k.norm(ut);
                // `f64::min`: the other number where one is a NaN.
                let (cap, ct) = (to_array(cap), to_array(k.mul(c_t, speed)));
                let least = gather(|l| cap[l].min(ct[l]));
                let moving = k.gt(speed, k.splat(0.0));
                let scale = k.pick(moving, k.div(least, speed), k.splat(0.0));
                let slid = k.vpick(moving, k.scale(ut, scale), V::zeros());
                (V::zeros(), slid)
            }
            Sliding::Clamp => {
                let scale = k.div(cap, k.norm(f_t));
                let spring = if k_t > 0.0 {
                    let dashpot = k.scale(ut, k.div(c_t, k.splat(k_t)));
                    k.vsub(k.scale(k.vadd(r.spring, dashpot), scale), dashpot)
                } else {
                    r.spring
                };
                (spring, k.scale(f_t, scale))
            }
        };
        r.spring = k.vpick(sticks, r.spring, spring);
        k.vpick(sticks, f_t, slid)
    };
    let shear = k.cross(n, f_t);
    // No cohesion: zero added after the limits, as the law adds it.
    let force = k.vadd(k.vadd(f_n, f_t), V::zeros());
    // §1.4: rolling and twisting, spring–dashpot–sliders scaled by (β_s R*)².
    let b = k.mul(k.splat(mat.beta_s), c.radius);
    let b = k.mul(b, b);
    let mut resistance = V::zeros();
    let (l1, l2) = c.levers;
    if mat.mu_r != 0.0 {
        let kappa = k.div(k.mul(k.splat(0.5), k.sub(l2, l1)), k.mul(l1, l2));
        let rate = k.vadd(
            k.vsub(c.spin, k.scale(n, k.dot(n, c.spin))),
            k.scale(k.cross(n, u), kappa),
        );
        let step = k.scale(rate, k.splat(dt));
        r.roll = k.vadd(r.roll, step);
        let mut m_r = k.scale(r.roll, k.mul(k.splat(k_n), b));
        let limit = k.mul(
            k.mul(k.splat(mat.mu_r * mat.beta_s), c.radius),
            normal_force,
        );
        let size = k.norm(m_r);
        let over = k.gt(size, limit);
        let capped = k.scale(m_r, k.div(limit, size));
        let damped = k.vadd(m_r, k.scale(rate, k.mul(c_n, b)));
        m_r = k.vpick(over, capped, damped);
        r.roll = k.vpick(over, k.vsub(r.roll, step), r.roll);
        resistance = k.vadd(resistance, m_r);
    }
    if mat.mu_t != 0.0 {
        let rate = k.dot(c.spin, n);
        let step = k.mul(rate, k.splat(dt));
        r.twist = k.add(r.twist, step);
        let torque = k.mul(k.mul(k.splat(2.0 * k_t), b), r.twist);
        let limit = k.mul(
            k.mul(
                k.mul(k.splat(mat.mu_t * mat.beta_s), c.radius),
                k.splat(mat.mu_s),
            ),
            normal_force,
        );
        let over = k.gt(k.abs(torque), limit);
        let signed = k.copysign(limit, torque);
        let damped = k.add(torque, k.mul(k.mul(k.mul(k.splat(2.0), c_t), b), rate));
        let m_t = k.pick(over, signed, damped);
        r.twist = k.pick(over, k.sub(r.twist, step), r.twist);
        resistance = k.vadd(resistance, k.scale(n, m_t));
    }
    r.scatter(records);
    Forces {
        force,
        torque: k.vadd(k.scale(shear, l1), resistance),
        partner_torque: k.vsub(k.scale(shear, l2), resistance),
    }
}

/// Four pairs of free particles as they stand: particle 1's and its partner's sphere
/// (centre and radius), velocity, spin, acceleration, angular acceleration and mass.
pub struct Pairs {
    /// The centres of particle 1 and of its partner.
    pub centres: (V, V),
    /// Their radii.
    pub radii: (L, L),
    /// Their velocities.
    pub vel: (V, V),
    /// Their spins.
    pub spin: (V, V),
    /// Their accelerations.
    pub acc: (V, V),
    /// Their angular accelerations.
    pub alpha: (V, V),
    /// Their masses.
    pub mass: (L, L),
}

/// How the run's pair contacts are worked out, the same for every contact.
pub struct Setting<'a> {
    /// The vector instructions.
    pub simd: Simd,
    /// The step.
    pub dt: f64,
    /// How far ahead of the step's start velocities and spins are predicted, in steps
    /// (0: as they are).
    pub predict: f64,
    /// The particles' material.
    pub mat: &'a Material,
    /// What the shear spring does when the contact slides.
    pub sliding: Sliding,
    /// The particles' normal and tangential restitutions.
    pub restitution: (Restitution, Restitution),
    /// A reduced mass and the damping coefficients of a contact of that mass.
    pub damping: Option<(f64, (f64, f64))>,
}

/// What four contacts between free particles do (the force on particle 1, the torques on
/// both), their records stepped on: `PairContext::force` in the run, lane by lane, for
/// pkdgrav's levers and law. The vector from the partner's centre to particle 1's, its
/// length and the overlap; the normal; the predicted velocities and spins; the levers to
/// the plane of the contact; the contact-point velocity; the reduced mass and radius;
/// and the law.
#[inline(always)]
pub fn pair(p: &Pairs, records: [&mut Record; LANES], s: &Setting) -> Forces {
    let k = s.simd;
    let (ci, cj) = p.centres;
    let (ri, rj) = p.radii;
    let d = k.vsub(ci, cj);
    let distance = k.norm(d);
    let overlap = k.sub(k.add(ri, rj), distance);
    let ahead = k.gt(distance, k.splat(0.0));
    let up = V {
        x: k.splat(0.0),
        y: k.splat(0.0),
        z: k.splat(1.0),
    };
    let n = k.vpick(ahead, k.unscale(d, distance), up);
    let (vi, wi, vj, wj) = if s.predict != 0.0 {
        let h = k.splat(s.dt * s.predict);
        (
            k.vadd(p.vel.0, k.scale(p.acc.0, h)),
            k.vadd(p.spin.0, k.scale(p.alpha.0, h)),
            k.vadd(p.vel.1, k.scale(p.acc.1, h)),
            k.vadd(p.spin.1, k.scale(p.alpha.1, h)),
        )
    } else {
        (p.vel.0, p.spin.0, p.vel.1, p.spin.1)
    };
    let equal = k.eq(ri, rj);
    let half = k.mul(k.splat(0.5), distance);
    let li = k.div(
        k.add(
            k.sub(k.mul(ri, ri), k.mul(rj, rj)),
            k.mul(distance, distance),
        ),
        k.mul(k.splat(2.0), distance),
    );
    let (li, lj) = (
        k.pick(equal, half, li),
        k.pick(equal, half, k.sub(distance, li)),
    );
    let u = k.vsub(
        k.vsub(k.vadd(vi, k.cross(wi, k.scale(k.vneg(n), li))), vj),
        k.cross(wj, k.scale(n, lj)),
    );
    let (mi, mj) = p.mass;
    let reduced = k.div(k.mul(mi, mj), k.add(mi, mj));
    let radius = k.div(k.mul(ri, rj), k.add(ri, rj));
    let (eps_n, eps_t) = s.restitution;
    let damping = match s.damping {
        Some((mass, (c_n, c_t))) if k.all(k.eq(reduced, k.splat(mass))) => {
            (k.splat(c_n), k.splat(c_t))
        }
        _ => {
            let reduced = to_array(reduced);
            let each: [(f64, f64); LANES] = std::array::from_fn(|l| match s.damping {
                Some((mass, damping)) if mass == reduced[l] => damping,
                _ => (
                    eps_n.damping(s.mat.k_n, reduced[l]),
                    eps_t.damping(s.mat.k_t, reduced[l]),
                ),
            });
            (gather(|l| each[l].0), gather(|l| each[l].1))
        }
    };
    let contacts = Contacts {
        overlap,
        normal: k.vneg(n),
        velocity: k.vneg(u),
        spin: k.vsub(wj, wi),
        turn: k.vadd(p.spin.0, p.spin.1),
        levers: (li, lj),
        radius,
        damping,
    };
    dashpot(k, &contacts, records, s.dt, s.mat, s.sliding)
}

/// Elsewhere than x86-64 there are no lanes: a token no value has, so [`Simd::new`]
/// gives none and the run takes every contact one at a time; its operations are never
/// called.
#[cfg(not(target_arch = "x86_64"))]
mod elsewhere {
    use pulp::{f64x4, m64x4};

    #[derive(Clone, Copy)]
    enum Never {}

    /// No vector instructions.
    #[derive(Clone, Copy)]
    pub struct Token(Never);

    macro_rules! never {
        ($($name:ident($($ty:ty),*) -> $out:ty;)*) => {
            impl Token {
                /// None: this processor has no lanes here.
                pub fn try_new() -> Option<Token> {
                    None
                }
                $(
                    pub fn $name(self, $(_: $ty),*) -> $out {
                        match self.0 {}
                    }
                )*
            }
        };
    }

    never! {
        add_f64x4(f64x4, f64x4) -> f64x4;
        sub_f64x4(f64x4, f64x4) -> f64x4;
        mul_f64x4(f64x4, f64x4) -> f64x4;
        div_f64x4(f64x4, f64x4) -> f64x4;
        sqrt_f64x4(f64x4) -> f64x4;
        xor_f64x4(f64x4, f64x4) -> f64x4;
        and_f64x4(f64x4, f64x4) -> f64x4;
        or_f64x4(f64x4, f64x4) -> f64x4;
        abs_f64x4(f64x4) -> f64x4;
        splat_f64x4(f64) -> f64x4;
        select_f64x4(m64x4, f64x4, f64x4) -> f64x4;
        cmp_eq_f64x4(f64x4, f64x4) -> m64x4;
        cmp_gt_f64x4(f64x4, f64x4) -> m64x4;
        cmp_le_f64x4(f64x4, f64x4) -> m64x4;
        and_m64x4(m64x4, m64x4) -> m64x4;
        not_m64x4(m64x4) -> m64x4;
    }
}
