//! pkdgrav's aggregates (its `AGGS` build, docs/pkdgrav-physics.md §9): rigid bodies made
//! of particles. A particle whose `.ss` `org_idx` is negative belongs to aggregate
//! −1 − org_idx; members may overlap, and members of one aggregate never interact.
//!
//! - **Set-up** ([`Aggregate::new`], §9.2): mass, centre and centre velocity; the inertia
//!   about the centre Σ m[(0.4R² + |ρ|²)1 − ρρᵀ] with elements below 10⁻¹² of the largest
//!   set to 0; its principal moments and axes Λ (body → space) by the cyclic Jacobi method
//!   without sorting ([`jacobi`]); the body-frame spin ω_k = (ΛᵀL)_k / I_k; the members'
//!   body positions Λᵀρ.
//! - **Kicks** ([`Aggregate::kick`]): the centre velocity only; ω is not kicked.
//! - **Drift** ([`Aggregate::advance`]): ω and Λ together by Euler's equations under the
//!   body-frame torque of the last force evaluation, by Numerical Recipes' adaptive
//!   Cash–Karp ([`euler_rigid::integrate`], shared with reactive walls): tolerance 10⁻⁶,
//!   first step dt, minimum 10⁻³ dt, yscal = |y| + |hẏ| + 10⁻¹⁵; then each row of Λ
//!   renormalised to unit length
//!   (what pkdgrav's "orthonormalise" does), and the centre moved with its half-step
//!   velocity.
//! - **Members** ([`Aggregate::place`]): r = Λ r_body + r_com, v = v_com + Λ(ω × r_body)
//!   (the half-step v_com: pkdgrav's outputs show it), w = Λω, and the velocities and spins
//!   their contacts see, v^pred = v_com + ½dt a_com + (Ω + ½dt Ω̇) × (ρ + ½dt(v − v_com)),
//!   w^pred = Ω + ½dt Ω̇ (Ω = Λω, Ω̇ = Λω̇).
//! - **Forces** ([`Aggregate::gather`], §9.4): a_com = Σ m_i a_i / M over the members'
//!   accelerations (gravity and contact forces); the torque about the centre is each
//!   contact force's moment at its contact point, the twisting torques, the moment of the
//!   rolling torque's pseudo-force ([`rolling_push`]) and gravity's moment; it is taken to
//!   the body frame with Λ as it stands at the force evaluation.

use crate::bodies::State;
use crate::dynamics::euler_rigid;
use crate::dynamics::rigid::Rotation;
use nalgebra::{Matrix3, Vector3};
use walls_geometry::Particle;

type Vec3 = Vector3<f64>;
/// Inertia elements below this fraction of the largest are set to 0.
pub const INERTIA_CUT: f64 = 1e-12;

/// The aggregate a particle belongs to, from its `.ss` `org_idx` (its
/// [`Particle::index`]): −1 − org_idx when org_idx is negative.
pub fn aggregate_of(p: &Particle) -> Option<u32> {
    (p.index < 0).then(|| (-1 - p.index as i64) as u32)
}

/// Why the aggregates of a set of particles cannot be set up.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum SetupError {
    /// An aggregate with one member: pkdgrav aborts (`msrAggsFind`).
    SingleMember {
        /// The aggregate's number (−1 − org_idx).
        aggregate: u32,
        /// The member's index in the input.
        particle: usize,
    },
}

/// One rigid aggregate.
#[derive(Debug, Clone, PartialEq)]
pub struct Aggregate {
    /// Its number, −1 − org_idx.
    pub number: u32,
    /// Its members' indices in the input, in input order.
    pub members: Vec<usize>,
    /// The members' positions in the body frame, Λᵀρ.
    pub body: Vec<Vec3>,
    /// The total mass M.
    pub mass: f64,
    /// The centre of mass.
    pub com: Vec3,
    /// The centre's velocity (half-step after the opening kick).
    pub vel: Vec3,
    /// The centre's acceleration at the last force evaluation.
    pub acc: Vec3,
    /// The principal moments I₁, I₂, I₃ (in Jacobi's order).
    pub moments: Vec3,
    /// The principal axes: columns, body → space.
    pub axes: Matrix3<f64>,
    /// The spin in the body frame.
    pub omega: Vec3,
    /// The torque about the centre at the last force evaluation, in the body frame.
    pub torque: Vec3,
}

/// Every aggregate of a run, and each particle's aggregate (its place in `list`).
#[derive(Debug, Clone, PartialEq)]
pub struct Aggregates {
    /// The aggregates, by number.
    pub list: Vec<Aggregate>,
    /// Each particle's aggregate, as its place in `list`.
    pub of: Vec<Option<u32>>,
}

impl Aggregates {
    /// The aggregates of `particles` (None when no particle is a member).
    pub fn find(particles: &[Particle]) -> Result<Option<Aggregates>, SetupError> {
        let mut numbers: Vec<u32> = particles.iter().filter_map(aggregate_of).collect();
        if numbers.is_empty() {
            return Ok(None);
        }
        numbers.sort_unstable();
        numbers.dedup();
        let mut of = vec![None; particles.len()];
        let mut members = vec![Vec::new(); numbers.len()];
        for (i, p) in particles.iter().enumerate() {
            if let Some(a) = aggregate_of(p) {
                let k = numbers.binary_search(&a).expect("listed");
                of[i] = Some(k as u32);
                members[k].push(i);
            }
        }
        let mut list = Vec::with_capacity(numbers.len());
        for (number, members) in numbers.into_iter().zip(members) {
            if members.len() < 2 {
                return Err(SetupError::SingleMember {
                    aggregate: number,
                    particle: members[0],
                });
            }
            list.push(Aggregate::new(number, members, particles));
        }
        Ok(Some(Aggregates { list, of }))
    }

    /// Where member `i` at `pos` is relative to its aggregate's centre (zero for a
    /// particle that is not a member).
    pub fn offset(&self, i: usize, pos: &Vec3) -> Vec3 {
        match self.of[i] {
            Some(a) => pos - self.list[a as usize].com,
            None => Vec3::zeros(),
        }
    }

    /// Whether particles `i` and `j` are members of the same aggregate.
    #[inline]
    pub fn same(&self, i: usize, j: usize) -> bool {
        matches!((self.of[i], self.of[j]), (Some(a), Some(b)) if a == b)
    }
}

impl Aggregate {
    /// The aggregate `number` of the particles `members` (input order), set up as pkdgrav
    /// does (docs/pkdgrav-physics.md §9.2).
    pub fn new(number: u32, members: Vec<usize>, particles: &[Particle]) -> Aggregate {
        let mut mass = 0.0;
        let mut mr = Vec3::zeros();
        let mut mv = Vec3::zeros();
        for &i in &members {
            let p = &particles[i];
            mass += p.mass;
            mr += p.pos * p.mass;
            mv += p.vel * p.mass;
        }
        let com = mr / mass;
        let vel = mv / mass;
        let mut inertia = Matrix3::<f64>::zeros();
        let mut momentum = Vec3::zeros();
        for &i in &members {
            let p = &particles[i];
            let rho = p.pos - com;
            let own = 0.4 * p.radius * p.radius;
            let diag = own + rho.norm_squared();
            for a in 0..3 {
                for b in 0..3 {
                    let d = if a == b { diag } else { 0.0 };
                    inertia[(a, b)] += p.mass * (d - rho[a] * rho[b]);
                }
            }
            momentum += (rho.cross(&(p.vel - vel)) + p.spin * own) * p.mass;
        }
        let largest: f64 = inertia.amax();
        for x in inertia.iter_mut() {
            if x.abs() < INERTIA_CUT * largest {
                *x = 0.0;
            }
        }
        let (moments, axes) = jacobi(inertia);
        let lm = axes.transpose() * momentum;
        let omega = lm.component_div(&moments);
        let body = members
            .iter()
            .map(|&i| axes.transpose() * (particles[i].pos - com))
            .collect();
        Aggregate {
            number,
            members,
            body,
            mass,
            com,
            vel,
            acc: Vec3::zeros(),
            moments,
            axes,
            omega,
            torque: Vec3::zeros(),
        }
    }

    /// A kick of the centre's velocity over `h` with the last acceleration.
    pub fn kick(&mut self, h: f64) {
        self.vel += self.acc * h;
    }

    /// The drift over `dt`: the rotation by Euler's equations under the held body-frame
    /// torque (adaptive Cash–Karp), Λ's rows renormalised, the centre moved with its
    /// velocity. Returns what the rotation's integration cost, whether it reached the
    /// minimum step and whether it failed ([`euler_rigid::Cost`]).
    pub fn advance(&mut self, dt: f64) -> euler_rigid::Cost {
        let mut rot = Rotation {
            omega: self.omega,
            axes: [0, 1, 2].map(|c| self.axes.column(c).into_owned()),
        };
        let cost = euler_rigid::integrate(&mut rot, &self.moments, &self.torque, dt);
        self.omega = rot.omega;
        for (c, axis) in rot.axes.iter().enumerate() {
            self.axes.set_column(c, axis);
        }
        for mut row in self.axes.row_iter_mut() {
            // pkdgrav scales by the reciprocal of the length (not a division).
            let scale = 1.0 / row.norm();
            row *= scale;
        }
        self.com += self.vel * dt;
        cost
    }

    /// The body-frame angular acceleration by Euler's equations with the held torque.
    pub fn omega_dot(&self) -> Vec3 {
        let (w, i, t) = (&self.omega, &self.moments, &self.torque);
        Vec3::new(
            (t.x + (i.y - i.z) * w.y * w.z) / i.x,
            (t.y + (i.z - i.x) * w.z * w.x) / i.y,
            (t.z + (i.x - i.y) * w.x * w.y) / i.z,
        )
    }

    /// The spin in the space frame, Λω.
    pub fn spin(&self) -> Vec3 {
        self.axes * self.omega
    }

    /// The members placed where the aggregate now is, with their velocities and spins,
    /// and the velocities and spins their contacts will see (as the last acceleration
    /// `acc`, `alpha` of each [`State`] predicting them half a step on).
    pub fn place(&self, states: &mut [State], dt: f64) {
        let h = 0.5 * dt;
        let spin = self.spin();
        let spin_pred = spin + (self.axes * self.omega_dot()) * h;
        let v_pred = self.vel + self.acc * h;
        for (k, &i) in self.members.iter().enumerate() {
            let s = &mut states[i];
            let b = &self.body[k];
            let rel = self.axes * self.omega.cross(b);
            s.particle.pos = self.axes * b + self.com;
            s.particle.vel = self.vel + rel;
            s.particle.spin = spin;
            let rho = s.particle.pos - self.com;
            let vp = v_pred + spin_pred.cross(&(rho + rel * h));
            s.acc = (vp - s.particle.vel) / h;
            s.alpha = (spin_pred - spin) / h;
        }
    }

    /// The centre's acceleration and the torque from the members' loads: each member's
    /// total force (gravity included), and its torque: about its own centre, the
    /// contact forces' moments at their contact points and the twisting torques, and,
    /// about the aggregate's centre, the moments of the rolling pseudo-forces
    /// ([`rolling_push`]) at their contact points.
    pub fn gather(&mut self, states: &[State], load: impl Fn(usize) -> (Vec3, Vec3), g: &Vec3) {
        let mut ma = Vec3::zeros();
        let mut torque = Vec3::zeros();
        for &i in &self.members {
            let s = &states[i];
            // A member a death wall deleted pulls no more; the aggregate keeps its mass
            // (docs/pkdgrav-physics.md §17).
            if !s.alive {
                continue;
            }
            let m = s.particle.mass;
            let (force, own) = load(i);
            let a = g + (force - g * m) / m;
            ma += a * m;
            let rho = s.particle.pos - self.com;
            torque += rho.cross(&force) + own;
        }
        self.acc = ma / self.mass;
        self.torque = self.axes.transpose() * torque;
    }

    /// The kinetic energy (translation and rotation) and gravitational energy.
    pub fn energy(&self, g: &Vec3) -> f64 {
        let w = &self.omega;
        0.5 * self.mass * self.vel.norm_squared() + 0.5 * self.moments.component_mul(w).dot(w)
            - self.mass * g.dot(&self.com)
    }

    /// The angular momentum about the centre, in the space frame.
    pub fn angular_momentum(&self) -> Vec3 {
        self.axes * self.moments.component_mul(&self.omega)
    }
}

/// The pseudo-force pkdgrav turns a rolling torque `m_r` into at a contact with unit
/// normal `n` (from the member towards its partner) at lever `l` (docs/pkdgrav-physics.md
/// §9.4): of size |M_r|/l along M_r × l n̂. Zero when there is no rolling torque.
pub fn rolling_push(m_r: &Vec3, n: &Vec3, l: f64) -> Vec3 {
    let size = m_r.norm();
    if size == 0.0 {
        return Vec3::zeros();
    }
    let dir = m_r.cross(&(n * l));
    let d = dir.norm();
    if d == 0.0 {
        return Vec3::zeros();
    }
    dir * (size / l / d)
}

/// The eigenvalues and eigenvectors (columns) of the symmetric `a` by the cyclic Jacobi
/// method of Numerical Recipes' `jacobi`, unsorted: the eigenvectors come in the order
/// the rotations leave them.
pub fn jacobi(mut a: Matrix3<f64>) -> (Vec3, Matrix3<f64>) {
    const N: usize = 3;
    let mut v = Matrix3::<f64>::identity();
    let mut d = Vec3::new(a[(0, 0)], a[(1, 1)], a[(2, 2)]);
    let mut b = d;
    let mut z = Vec3::zeros();
    let rotate =
        |m: &mut Matrix3<f64>, i: usize, j: usize, k: usize, l: usize, s: f64, tau: f64| {
            let g = m[(i, j)];
            let h = m[(k, l)];
            m[(i, j)] = g - s * (h + g * tau);
            m[(k, l)] = h + s * (g - h * tau);
        };
    for sweep in 1..=50 {
        let mut sm = 0.0;
        for ip in 0..N - 1 {
            for iq in ip + 1..N {
                sm += a[(ip, iq)].abs();
            }
        }
        if sm == 0.0 {
            return (d, v);
        }
        let tresh = if sweep < 4 {
            0.2 * sm / (N * N) as f64
        } else {
            0.0
        };
        for ip in 0..N - 1 {
            for iq in ip + 1..N {
                let g = 100.0 * a[(ip, iq)].abs();
                if sweep > 4 && d[ip].abs() + g == d[ip].abs() && d[iq].abs() + g == d[iq].abs() {
                    a[(ip, iq)] = 0.0;
                } else if a[(ip, iq)].abs() > tresh {
                    let h = d[iq] - d[ip];
                    let t = if h.abs() + g == h.abs() {
                        a[(ip, iq)] / h
                    } else {
                        let theta = 0.5 * h / a[(ip, iq)];
                        let t = 1.0 / (theta.abs() + (1.0 + theta * theta).sqrt());
                        if theta < 0.0 { -t } else { t }
                    };
                    let c = 1.0 / (1.0 + t * t).sqrt();
                    let s = t * c;
                    let tau = s / (1.0 + c);
                    let h = t * a[(ip, iq)];
                    z[ip] -= h;
                    z[iq] += h;
                    d[ip] -= h;
                    d[iq] += h;
                    a[(ip, iq)] = 0.0;
                    for j in 0..ip {
                        rotate(&mut a, j, ip, j, iq, s, tau);
                    }
                    for j in ip + 1..iq {
                        rotate(&mut a, ip, j, j, iq, s, tau);
                    }
                    for j in iq + 1..N {
                        rotate(&mut a, ip, j, iq, j, s, tau);
                    }
                    for j in 0..N {
                        rotate(&mut v, j, ip, j, iq, s, tau);
                    }
                }
            }
        }
        for ip in 0..N {
            b[ip] += z[ip];
            d[ip] = b[ip];
            z[ip] = 0.0;
        }
    }
    (d, v)
}
