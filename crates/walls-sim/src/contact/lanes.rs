//! pkdgrav's contact law between two particles ([`super::ssdem::dashpot_contact`]) for
//! four contacts at once, each in a lane of its own: the same operations on each lane
//! in the same order, so each lane's numbers are bit for bit those of the law on its
//! contact alone (`tests/lanes.rs` holds the two side by side), but for the sign and
//! payload of a NaN, which Rust leaves unspecified (a NaN stops a run whatever its
//! sign). The lanes are plain
//! arrays, which the compiler turns into vector instructions (two or four numbers an
//! instruction, as the processor allows): a branch of the law becomes both arms and a
//! choice between them in each lane.
//!
//! Only the common case runs here: two free particles, the `DEM_ROTATION_DASHPOT` build
//! without its optional parts (no cohesion, no two layers, no contact radius). The run
//! takes any other contact to the law itself.

use super::ssdem::{Record, Restitution, SERIES_UP_TO, Sliding, sin_cos_series};
use walls_geometry::Material;

/// How many contacts go together.
pub const LANES: usize = 4;

/// One number in each lane.
pub type L = [f64; LANES];

/// One boolean in each lane.
type Mask = [bool; LANES];

/// Each lane's `f(a, b)`.
#[inline(always)]
fn zip(a: L, b: L, f: impl Fn(f64, f64) -> f64) -> L {
    std::array::from_fn(|l| f(a[l], b[l]))
}

/// Each lane's `f(a)`.
#[inline(always)]
fn map(a: L, f: impl Fn(f64) -> f64) -> L {
    std::array::from_fn(|l| f(a[l]))
}

/// Each lane's `f(a)` as a mask.
#[inline(always)]
fn is(a: L, f: impl Fn(f64) -> bool) -> Mask {
    std::array::from_fn(|l| f(a[l]))
}

/// Each lane's `f(a, b)` as a mask.
#[inline(always)]
fn test(a: L, b: L, f: impl Fn(f64, f64) -> bool) -> Mask {
    std::array::from_fn(|l| f(a[l], b[l]))
}

#[inline(always)]
fn add(a: L, b: L) -> L {
    zip(a, b, |a, b| a + b)
}

#[inline(always)]
fn sub(a: L, b: L) -> L {
    zip(a, b, |a, b| a - b)
}

#[inline(always)]
fn mul(a: L, b: L) -> L {
    zip(a, b, |a, b| a * b)
}

#[inline(always)]
fn div(a: L, b: L) -> L {
    zip(a, b, |a, b| a / b)
}

/// The same number in every lane.
#[inline(always)]
pub fn splat(x: f64) -> L {
    [x; LANES]
}

/// `yes` in the lanes of `mask`, else `no`.
#[inline(always)]
fn pick(mask: Mask, yes: L, no: L) -> L {
    std::array::from_fn(|l| if mask[l] { yes[l] } else { no[l] })
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
        V {
            x: splat(0.0),
            y: splat(0.0),
            z: splat(0.0),
        }
    }

    #[inline(always)]
    fn each(self, other: V, f: impl Fn(L, L) -> L) -> V {
        V {
            x: f(self.x, other.x),
            y: f(self.y, other.y),
            z: f(self.z, other.z),
        }
    }

    #[inline(always)]
    fn add(self, o: V) -> V {
        self.each(o, add)
    }

    #[inline(always)]
    fn sub(self, o: V) -> V {
        self.each(o, sub)
    }

    /// Each component times the lane's `s`.
    #[inline(always)]
    fn scale(self, s: L) -> V {
        V {
            x: mul(self.x, s),
            y: mul(self.y, s),
            z: mul(self.z, s),
        }
    }

    /// Each component over the lane's `s`.
    #[inline(always)]
    fn unscale(self, s: L) -> V {
        V {
            x: div(self.x, s),
            y: div(self.y, s),
            z: div(self.z, s),
        }
    }

    #[inline(always)]
    fn neg(self) -> V {
        V {
            x: map(self.x, |a| -a),
            y: map(self.y, |a| -a),
            z: map(self.z, |a| -a),
        }
    }

    #[inline(always)]
    fn dot(self, o: V) -> L {
        add(add(mul(self.x, o.x), mul(self.y, o.y)), mul(self.z, o.z))
    }

    #[inline(always)]
    fn norm_squared(self) -> L {
        self.dot(self)
    }

    #[inline(always)]
    fn norm(self) -> L {
        map(self.norm_squared(), f64::sqrt)
    }

    #[inline(always)]
    fn cross(self, b: V) -> V {
        V {
            x: sub(mul(self.y, b.z), mul(self.z, b.y)),
            y: sub(mul(self.z, b.x), mul(self.x, b.z)),
            z: sub(mul(self.x, b.y), mul(self.y, b.x)),
        }
    }

    /// Whether each lane's vector is zero (component by component: −0 is, NaN is not).
    #[inline(always)]
    fn is_zero(self) -> Mask {
        std::array::from_fn(|l| self.x[l] == 0.0 && self.y[l] == 0.0 && self.z[l] == 0.0)
    }

    /// `yes` in the lanes of `mask`, else `no`.
    #[inline(always)]
    fn pick(mask: Mask, yes: V, no: V) -> V {
        V {
            x: pick(mask, yes.x, no.x),
            y: pick(mask, yes.y, no.y),
            z: pick(mask, yes.z, no.z),
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
    fn gather(records: &[Record; LANES]) -> Records {
        let v = |f: fn(&Record) -> [f64; 3]| {
            let each: [[f64; 3]; LANES] = std::array::from_fn(|l| f(&records[l]));
            V {
                x: std::array::from_fn(|l| each[l][0]),
                y: std::array::from_fn(|l| each[l][1]),
                z: std::array::from_fn(|l| each[l][2]),
            }
        };
        Records {
            spring: v(|r| r.spring.into()),
            normal: v(|r| r.normal.into()),
            roll: v(|r| r.roll.into()),
            twist: std::array::from_fn(|l| records[l].twist),
        }
    }

    #[inline(always)]
    fn scatter(&self, records: &mut [Record; LANES]) {
        for (l, r) in records.iter_mut().enumerate() {
            r.spring = [self.spring.x[l], self.spring.y[l], self.spring.z[l]].into();
            r.normal = [self.normal.x[l], self.normal.y[l], self.normal.z[l]].into();
            r.roll = [self.roll.x[l], self.roll.y[l], self.roll.z[l]].into();
            r.twist = self.twist[l];
        }
    }
}

/// `v` turned about the unit `axis` by the angle whose sine and cosine are given, in the
/// lanes of `mask` where `v` is not zero (a zero spring is left alone).
#[inline(always)]
fn turn(v: V, axis: V, (sin, cos): (L, L), mask: Mask) -> V {
    let one_less = map(cos, |c| 1.0 - c);
    let turned = v
        .scale(cos)
        .add(axis.cross(v).scale(sin))
        .add(axis.scale(mul(axis.dot(v), one_less)));
    let zero = v.is_zero();
    V::pick(std::array::from_fn(|l| mask[l] && !zero[l]), turned, v)
}

/// [`super::ssdem::small_sin_cos`] in each lane: its series in all lanes at once, the library's in a
/// lane whose angle is too large for it.
#[inline(always)]
fn sin_cos(x: L) -> (L, L) {
    let series = std::array::from_fn(|l| sin_cos_series(x[l]));
    let (mut sin, mut cos): (L, L) = (series.map(|s| s.0), series.map(|s| s.1));
    for l in 0..LANES {
        if x[l].abs() >= SERIES_UP_TO {
            (sin[l], cos[l]) = x[l].sin_cos();
        }
    }
    (sin, cos)
}

/// pkdgrav's contact law ([`super::ssdem::dashpot_contact_with`], with the damping
/// given and nothing else optional) on four contacts between free particles, with their
/// records, in material `mat` over `dt`, the shear spring limited as `sliding` says.
#[inline(always)]
pub fn dashpot(
    c: &Contacts,
    records: &mut [Record; LANES],
    dt: f64,
    mat: &Material,
    sliding: Sliding,
) -> Forces {
    let mut r = Records::gather(records);
    let n = c.normal;
    let (k_n, k_t) = (mat.k_n, mat.k_t);
    let spring_force = map(c.overlap, |x| k_n * x);
    let old = r.normal.is_zero();
    let old: Mask = std::array::from_fn(|l| !old[l]);
    // §1.3 step 1: about the mean normal, by the mean spin of the two over the step.
    let mean = r.normal.add(n);
    let size = mean.norm();
    let mean = mean.unscale(size);
    let angle = map(c.turn.dot(mean), |t| 0.5 * dt * t);
    // (A mean of zero length is no axis; one whose length is not a number is, as
    // `try_normalize(0.0)` has it: none only when the length is at most 0.)
    let axis = is(size, |s| s > 0.0 || s.is_nan());
    let first: Mask = std::array::from_fn(|l| old[l] && axis[l] && angle[l] != 0.0);
    // (A zero rolling spring, in every lane without rolling resistance, stays zero.)
    let rolls = !r.roll.is_zero().iter().all(|&z| z);
    if first.iter().any(|&b| b) {
        let sc = sin_cos(angle);
        r.spring = turn(r.spring, mean, sc, first);
        if rolls {
            r.roll = turn(r.roll, mean, sc, first);
        }
    }
    // Step 2: with the change of normal.
    let a = r.normal.cross(n);
    let sin = a.norm();
    let second: Mask = std::array::from_fn(|l| old[l] && sin[l] > 0.0);
    if second.iter().any(|&b| b) {
        let axis = a.unscale(sin);
        let cos = n.dot(r.normal);
        r.spring = turn(r.spring, axis, (sin, cos), second);
        if rolls {
            r.roll = turn(r.roll, axis, (sin, cos), second);
        }
    }
    r.normal = n;
    let u = c.velocity;
    let un = n.scale(n.dot(u));
    let ut = u.sub(un);
    let (c_n, c_t) = c.damping;
    let f_n = n.scale(map(spring_force, |f| -f)).add(un.scale(c_n));
    let normal_force = f_n.norm();
    // Step 4 and 5: the shear spring, and the slide.
    r.spring = r.spring.add(ut.scale(splat(dt)));
    let cap = map(normal_force, |f| mat.mu_s * f);
    let f_t = r.spring.scale(splat(k_t)).add(ut.scale(c_t));
    let sticks = test(f_t.norm_squared(), cap, |f2, cap| f2 <= cap * cap);
    let f_t = if sticks.iter().all(|&b| b) {
        f_t
    } else {
        let (spring, slid) = match sliding {
            Sliding::Reset => {
                let speed = ut.norm();
                let scale: L = std::array::from_fn(|l| {
                    if speed[l] > 0.0 {
                        cap[l].min(c_t[l] * speed[l]) / speed[l]
                    } else {
                        0.0
                    }
                });
                let moving = is(speed, |s| s > 0.0);
                let slid = V::pick(moving, ut.scale(scale), V::zeros());
                (V::zeros(), slid)
            }
            Sliding::Clamp => {
                let scale = div(cap, f_t.norm());
                let spring = if k_t > 0.0 {
                    let dashpot = ut.scale(map(c_t, |c| c / k_t));
                    r.spring.add(dashpot).scale(scale).sub(dashpot)
                } else {
                    r.spring
                };
                (spring, f_t.scale(scale))
            }
        };
        r.spring = V::pick(sticks, r.spring, spring);
        V::pick(sticks, f_t, slid)
    };
    let shear = n.cross(f_t);
    // No cohesion: zero added after the limits, as the law adds it.
    let force = f_n.add(f_t).add(V::zeros());
    // §1.4: rolling and twisting, spring–dashpot–sliders scaled by (β_s R*)².
    let b = map(c.radius, |r| (mat.beta_s * r).powi(2));
    let mut resistance = V::zeros();
    let (l1, l2) = c.levers;
    if mat.mu_r != 0.0 {
        let kappa = zip(l1, l2, |l1, l2| 0.5 * (l2 - l1) / (l1 * l2));
        let rate = c
            .spin
            .sub(n.scale(n.dot(c.spin)))
            .add(n.cross(u).scale(kappa));
        let step = rate.scale(splat(dt));
        r.roll = r.roll.add(step);
        let mut m_r = r.roll.scale(map(b, |b| k_n * b));
        let limit: L =
            std::array::from_fn(|l| mat.mu_r * mat.beta_s * c.radius[l] * normal_force[l]);
        let size = m_r.norm();
        let over = test(size, limit, |s, lim| s > lim);
        let capped = m_r.scale(div(limit, size));
        let damped = m_r.add(rate.scale(mul(c_n, b)));
        m_r = V::pick(over, capped, damped);
        r.roll = V::pick(over, r.roll.sub(step), r.roll);
        resistance = resistance.add(m_r);
    }
    if mat.mu_t != 0.0 {
        let rate = c.spin.dot(n);
        let step = mul(rate, splat(dt));
        r.twist = add(r.twist, step);
        let torque: L = std::array::from_fn(|l| 2.0 * k_t * b[l] * r.twist[l]);
        let limit: L = std::array::from_fn(|l| {
            mat.mu_t * mat.beta_s * c.radius[l] * mat.mu_s * normal_force[l]
        });
        let over = test(torque, limit, |t, lim| t.abs() > lim);
        let m_t: L = std::array::from_fn(|l| {
            if over[l] {
                limit[l].copysign(torque[l])
            } else {
                torque[l] + 2.0 * c_t[l] * b[l] * rate[l]
            }
        });
        r.twist = pick(over, sub(r.twist, step), r.twist);
        resistance = resistance.add(n.scale(m_t));
    }
    r.scatter(records);
    Forces {
        force,
        torque: shear.scale(l1).add(resistance),
        partner_torque: shear.scale(l2).sub(resistance),
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
pub fn pair(p: &Pairs, records: &mut [Record; LANES], s: &Setting) -> Forces {
    let (ci, cj) = p.centres;
    let (ri, rj) = p.radii;
    let d = ci.sub(cj);
    let distance = d.norm();
    let overlap = sub(add(ri, rj), distance);
    let ahead = is(distance, |d| d > 0.0);
    let up = V {
        x: splat(0.0),
        y: splat(0.0),
        z: splat(1.0),
    };
    let n = V::pick(ahead, d.unscale(distance), up);
    let seen = |vel: V, spin: V, acc: V, alpha: V| {
        if s.predict != 0.0 {
            let h = splat(s.dt * s.predict);
            (vel.add(acc.scale(h)), spin.add(alpha.scale(h)))
        } else {
            (vel, spin)
        }
    };
    let (vi, wi) = seen(p.vel.0, p.spin.0, p.acc.0, p.alpha.0);
    let (vj, wj) = seen(p.vel.1, p.spin.1, p.acc.1, p.alpha.1);
    let equal = test(ri, rj, |a, b| a == b);
    let half = map(distance, |d| 0.5 * d);
    let li: L = std::array::from_fn(|l| {
        let (a, b, d) = (ri[l], rj[l], distance[l]);
        (a * a - b * b + d * d) / (2.0 * d)
    });
    let (li, lj) = (pick(equal, half, li), pick(equal, half, sub(distance, li)));
    let u = vi
        .add(wi.cross(n.neg().scale(li)))
        .sub(vj)
        .sub(wj.cross(n.scale(lj)));
    let (mi, mj) = p.mass;
    let reduced = div(mul(mi, mj), add(mi, mj));
    let radius = div(mul(ri, rj), add(ri, rj));
    let (eps_n, eps_t) = s.restitution;
    let mut c_n = [0.0; LANES];
    let mut c_t = [0.0; LANES];
    for l in 0..LANES {
        (c_n[l], c_t[l]) = match s.damping {
            Some((mass, damping)) if mass == reduced[l] => damping,
            _ => (
                eps_n.damping(s.mat.k_n, reduced[l]),
                eps_t.damping(s.mat.k_t, reduced[l]),
            ),
        };
    }
    let contacts = Contacts {
        overlap,
        normal: n.neg(),
        velocity: u.neg(),
        spin: wj.sub(wi),
        turn: p.spin.0.add(p.spin.1),
        levers: (li, lj),
        radius,
        damping: (c_n, c_t),
    };
    dashpot(&contacts, records, s.dt, s.mat, s.sliding)
}
