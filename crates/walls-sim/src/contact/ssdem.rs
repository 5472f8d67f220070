//! The soft-sphere (SSDEM) contact of a particle with a wall (docs/spec.md §3): a linear
//! spring–dashpot along the normal, and a tangential spring that follows the contact,
//! capped by Coulomb friction. The wall counts as infinitely massive and flat: the
//! reduced mass and radius are the particle's.
//!
//! Rolling and twisting resistance (docs/spec.md §3) oppose the relative spin: rolling
//! with torque μ_r·|F_n|·l against the spin across the normal (l the lever: the
//! particle's radius against a wall, the reduced radius between particles), twisting with
//! μ_t·|F_n|·a against the spin about the normal, a = √(2Rx − x²) being the radius of the
//! contact circle of a sphere of radius R overlapping by x. Each is capped so that it
//! cannot reverse the spin within a step.
//!
//! [`dashpot_contact`] is pkdgrav's own law instead (its default `DEM_ROTATION_DASHPOT`
//! build, docs/pkdgrav-physics.md §1.3–§1.5), which `Integrator::Pkdgrav` runs for walls
//! and pairs: the springs kept in a [`Record`] turn with the contact, the shear spring
//! resets when the contact slides (or, as an option, [`Sliding::Clamp`], is held at the
//! Coulomb limit), and rolling and twisting are spring–dashpot–sliders
//! scaled by (β_s R*)². [`dashpot_contact_with`] adds what pkdgrav's optional builds
//! change in it ([`Optional`]): cohesion (§7) and two-layer springs ([`Layers`], §8).
//!
//! Damping from restitution: C = −2·ln ε·√(m·k/(π² + ln²ε)), 0 when ε is 0 or 1. The
//! contact lasts π/ω_d with ω_d² = k/m − (C/2m)².

use nalgebra::Vector3;

type Vec3 = Vector3<f64>;

/// Material values of one contact, with the walls' 99 and −1 already replaced by the
/// particles' values ([`Material::against`]).
pub use walls_geometry::Material;

/// The damping coefficient for restitution `eps` of a spring `k` on mass `m`.
pub fn damping(eps: f64, k: f64, m: f64) -> f64 {
    Restitution::new(eps).damping(k, m)
}

/// A restitution ε with ln ε and π² + ln²ε worked out once: the damping coefficient of
/// any spring and mass is then [`damping`]'s, bit for bit, without a logarithm per
/// contact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Restitution {
    /// ε ≤ 0 or ε ≥ 1: no damping.
    undamped: bool,
    ln: f64,
    denominator: f64,
}

impl Restitution {
    /// The restitution `eps`.
    pub fn new(eps: f64) -> Restitution {
        let undamped = eps <= 0.0 || eps >= 1.0;
        let ln = if undamped { 0.0 } else { eps.ln() };
        Restitution {
            undamped,
            ln,
            denominator: std::f64::consts::PI.powi(2) + ln * ln,
        }
    }

    /// The damping coefficient of a spring `k` on mass `m`.
    #[inline]
    pub fn damping(&self, k: f64, m: f64) -> f64 {
        if self.undamped {
            return 0.0;
        }
        -2.0 * self.ln * (m * k / self.denominator).sqrt()
    }
}

/// The force and torque on a particle from one wall contact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactForce {
    /// Force on the particle.
    pub force: Vec3,
    /// Torque on the particle about its centre.
    pub torque: Vec3,
}

/// Where and how a particle touches a wall.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Touch {
    /// How far the particle's surface overlaps the wall.
    pub overlap: f64,
    /// Unit normal from the wall to the particle.
    pub normal: Vec3,
    /// Velocity of the particle's contact point relative to the wall's material there.
    pub velocity: Vec3,
}

/// The damping coefficient divided by √m: C = √m · this, for restitution `eps` of a
/// spring `k` (so that it can be worked out once per material, not per contact).
pub fn damping_per_root_mass(eps: f64, k: f64) -> f64 {
    damping(eps, k, 1.0)
}

/// The normal force alone, for scenes without sliding friction: what [`contact`] gives
/// when μ_s = 0, without keeping a tangential spring, with the damping coefficient `c_n`
/// worked out beforehand.
pub fn normal_contact(touch: &Touch, k_n: f64, c_n: f64) -> ContactForce {
    let un = touch.normal * touch.normal.dot(&touch.velocity);
    ContactForce {
        force: touch.normal * (k_n * touch.overlap) - un * c_n,
        torque: Vec3::zeros(),
    }
}

/// The contact force on a particle of mass `m` and radius `r` touching a wall. `spring`
/// is the contact's tangential spring: it is turned into the tangent plane, stretched by
/// the tangential motion over `dt`, and reset when the contact slides.
pub fn contact(
    m: f64,
    r: f64,
    touch: &Touch,
    spring: &mut Vec3,
    dt: f64,
    mat: &Material,
) -> ContactForce {
    let (overlap, normal, u) = (touch.overlap, &touch.normal, &touch.velocity);
    let un = normal * normal.dot(u);
    let ut = u - un;
    let c_n = damping(mat.eps_n, mat.k_n, m);
    let c_t = damping(mat.eps_t, mat.k_t, m);
    let f_n = normal * (mat.k_n * overlap) - un * c_n;
    // Keep the spring in the tangent plane (the contact turns), then stretch it.
    let along = normal * normal.dot(spring);
    let length = spring.norm();
    *spring -= along;
    if let Some(d) = spring.try_normalize(0.0) {
        *spring = d * length;
    }
    *spring += ut * dt;
    let mut f_t = -(*spring * mat.k_t) - ut * c_t;
    let cap = mat.mu_s * f_n.norm();
    if f_t.norm() > cap {
        // Sliding: the friction is the cap, and the spring starts again (docs/spec.md
        // §3).
        f_t = match f_t.try_normalize(0.0) {
            Some(d) => d * cap,
            None => Vec3::zeros(),
        };
        *spring = Vec3::zeros();
    }
    // The tangential force acts at the contact point, −r·n̂ from the centre.
    let torque = (-normal * r).cross(&f_t);
    ContactForce {
        force: f_n + f_t,
        torque,
    }
}

/// Where a rolling and twisting resistance acts.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rolling {
    /// Spin of the particle relative to what it touches.
    pub spin: Vec3,
    /// Unit normal from what it touches to the particle.
    pub normal: Vec3,
    /// The size of the normal force.
    pub normal_force: f64,
    /// The rolling lever.
    pub lever: f64,
    /// The radius of the contact circle.
    pub contact_radius: f64,
    /// The moment of inertia that the torque turns (for the cap).
    pub inertia: f64,
}

/// The rolling and twisting resistance torque on a particle over a step of `dt`.
pub fn resistance(c: &Rolling, mu_r: f64, mu_t: f64, dt: f64) -> Vec3 {
    let n = &c.normal;
    let about = n * n.dot(&c.spin);
    let across = c.spin - about;
    // The largest torque that stops, without reversing, a spin w within the step.
    let stop = |w: f64| c.inertia * w / dt;
    let mut torque = Vec3::zeros();
    if mu_r > 0.0
        && let Some((axis, w)) = nalgebra::Unit::try_new_and_get(across, 0.0)
    {
        torque -= axis.into_inner() * (mu_r * c.normal_force * c.lever).min(stop(w));
    }
    if mu_t > 0.0
        && let Some((axis, w)) = nalgebra::Unit::try_new_and_get(about, 0.0)
    {
        torque -= axis.into_inner() * (mu_t * c.normal_force * c.contact_radius).min(stop(w));
    }
    torque
}

/// The radius of the circle where a sphere of radius `r` overlaps a flat wall by `x`.
pub fn contact_radius(r: f64, x: f64) -> f64 {
    (2.0 * r * x - x * x).max(0.0).sqrt()
}

/// pkdgrav's contact radius (`bUseContactRadius`, docs/pkdgrav-physics.md §1.4):
/// √(r² − l²), the radius of the circle a sphere of radius `r` cuts on the plane `lever`
/// l from its centre (l = r − x against a wall, the distance to the plane of
/// intersection between particles).
pub fn lever_contact_radius(r: f64, lever: f64) -> f64 {
    (r * r - lever * lever).max(0.0).sqrt()
}

/// What pkdgrav keeps of one contact from step to step (`dem.h DEM_ELEMENT`, physics.md
/// §1.3): the shear spring, the normal it was last turned to (pkdgrav's: towards the
/// partner; zero in a new contact), the rolling spring and the twist angle.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Record {
    /// The shear spring S.
    pub spring: Vec3,
    /// The previous normal n_old, from the particle towards its partner.
    pub normal: Vec3,
    /// The rolling spring.
    pub roll: Vec3,
    /// The twist angle.
    pub twist: f64,
    /// Two-layer contacts (docs/pkdgrav-physics.md §8): the layer the contact was in last
    /// step, positive the outer, negative the inner; 0 in a new contact.
    pub layer: i8,
}

/// The spring constants of a two-layer contact (`DEM_TWOLAYERS`, docs/pkdgrav-physics.md
/// §8).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Layers {
    /// The overlap b where the inner layer begins (the fraction times R_eff).
    pub boundary: f64,
    /// The outer layer's normal spring constant.
    pub k_n_outer: f64,
    /// The outer layer's tangential spring constant.
    pub k_t_outer: f64,
    /// The inner layer's normal spring constant.
    pub k_n_inner: f64,
    /// The inner layer's tangential spring constant.
    pub k_t_inner: f64,
}

/// What pkdgrav's optional builds add to one [`Dashpot`] contact: the cohesion force
/// (`DEM_COHESION`, docs/pkdgrav-physics.md §7; 0 for none) and the two layers
/// (`DEM_TWOLAYERS`, §8).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Optional {
    /// The size of the cohesive force, pulling particle 1 towards its partner.
    pub cohesion: f64,
    /// The two-layer spring constants, which replace the material's k_n and k_t.
    pub layers: Option<Layers>,
    /// The material's normal and tangential restitutions, worked out beforehand (else
    /// from the material, per contact).
    pub restitution: Option<(Restitution, Restitution)>,
    /// The normal and tangential damping coefficients C_n and C_t of this contact's
    /// springs and reduced mass, worked out beforehand (the same for every contact
    /// between two particles of one mass; else from the restitutions, per contact).
    /// Never with `layers`, whose springs depend on the overlap.
    pub damping: Option<(f64, f64)>,
}

impl Layers {
    /// The layer of an overlap `x` (1 outer, −1 inner), its normal and tangential spring
    /// constants, and the size of the normal spring force: k_n,out·x in the outer layer,
    /// k_n,in·(x − b) + k_n,out·b in the inner.
    pub fn at(&self, x: f64) -> (i8, f64, f64, f64) {
        if x > self.boundary {
            (
                -1,
                self.k_n_inner,
                self.k_t_inner,
                self.k_n_inner * (x - self.boundary) + self.k_n_outer * self.boundary,
            )
        } else {
            (1, self.k_n_outer, self.k_t_outer, self.k_n_outer * x)
        }
    }

    /// The factor the shear spring takes on crossing from layer `from` into layer `to`
    /// (√(k_t,from/k_t,to), which keeps ½k_t·S²); 1 without a crossing or in a new
    /// contact (`from` 0).
    pub fn rescale(&self, from: i8, to: i8) -> f64 {
        match (from, to) {
            (1, -1) => (self.k_t_outer / self.k_t_inner).sqrt(),
            (-1, 1) => (self.k_t_inner / self.k_t_outer).sqrt(),
            _ => 1.0,
        }
    }
}

/// One contact as pkdgrav's `DEM_ROTATION_DASHPOT` build sees it (docs/pkdgrav-physics.md
/// §1.1–§1.4), in its own frame: particle 1 and its partner 2 (a particle or a wall).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Dashpot {
    /// The overlap x.
    pub overlap: f64,
    /// The unit normal n̂ from particle 1 towards its partner.
    pub normal: Vec3,
    /// The partner's contact-point velocity relative to particle 1's, predicted (u).
    pub velocity: Vec3,
    /// The partner's spin less particle 1's, predicted (ω).
    pub spin: Vec3,
    /// The sum of the two spins as they are (the half-step spins; a wall's own spin),
    /// which turn the springs about the mean normal.
    pub turn: Vec3,
    /// The levers l₁ and l₂ (a wall: d = r − x, and 0).
    pub levers: (f64, f64),
    /// The reduced mass μ.
    pub mass: f64,
    /// The rolling radius R* (r₁r₂/(r₁+r₂) between particles, r₁ against a wall).
    pub radius: f64,
    /// Whether the partner is a wall (the spring follows the normal the other way, and
    /// κ = ½/d).
    pub wall: bool,
    /// Builds without `DEM_ROTATION_DASHPOT`: rolling and twisting as the directional
    /// constant torques of docs/pkdgrav-physics.md §1.6 instead of §1.4's springs
    /// (`None`: springs).
    pub constant_torque: Option<ConstantTorque>,
    /// What the shear spring does when the contact slides: pkdgrav's reset, or the
    /// Coulomb clamp.
    pub sliding: Sliding,
}

/// What the shear spring of a sliding contact does, when |k_t S + C_t u_t| > μ_s N
/// (docs/accuracy.md, "Sliding friction"); `--sliding` of `walls-sim run`: each
/// variant's first paragraph is its help.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
pub enum Sliding {
    /// pkdgrav's rule: the spring is reset to zero, the force is the dashpot's capped at
    /// μ_s·N (docs/pkdgrav-physics.md §1.3).
    ///
    /// §1.3 step 5. The spring rebuilds over the next steps, during which the force is
    /// below the cap: a slow slip decelerates less than μ_s g.
    #[default]
    Reset,
    /// The Coulomb clamp: the spring is rescaled so that the force is exactly μ_s·N.
    ///
    /// As LAMMPS's `gran/hooke/history` and LIGGGHTS do, along the force it had:
    /// S ← (μ_s N/|F_t|)(S + C_t u_t/k_t) − C_t u_t/k_t.
    Clamp,
}

/// What the directional constant torques of a build without `DEM_ROTATION_DASHPOT`
/// need (docs/pkdgrav-physics.md §1.6), besides the [`Dashpot`] contact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ConstantTorque {
    /// The predicted spins of particle 1 and of its partner (zero for a wall).
    pub spins: (Vec3, Vec3),
    /// The rolling levers of particle 1 and its partner: the reduced radius (r₁ against
    /// a wall) for both by default; l₁, l₂ (d) with `bUseLegacyRoll`; the contact radius
    /// with `bUseContactRadius`.
    pub roll_levers: (f64, f64),
    /// The twisting radius: the contact radius with `bUseContactRadius`, else 0 (no
    /// twisting torque).
    pub twist_radius: f64,
    /// The moments of inertia of particle 1 and its partner (infinite for a wall or a
    /// stuck particle): through their reduced value they cap the rolling torques so
    /// that they cannot reverse the relative spin across the normal within the step.
    pub inertias: (f64, f64),
}

/// The directional constant rolling and twisting torques on particle 1 and its partner
/// (docs/pkdgrav-physics.md §1.6): rolling μ_r·N·(r̂ × n̂) times each one's lever, with r
/// the rolling velocity l₁ w₁ × n̂ − l₂ w₂ × n̂ (d w × n̂ against a wall), capped so that
/// their impulses over `dt` cannot reverse the relative spin across the normal; twisting
/// μ_t·N·sign(ω_t)·n̂ times the twisting radius, ω_t the partner's spin less particle 1's
/// along n̂. Returns the torques on particle 1 and its partner, and the rolling torque on
/// particle 1 alone.
fn constant_torques(
    c: &Dashpot,
    t: &ConstantTorque,
    normal_force: f64,
    mat: &Material,
    dt: f64,
) -> (Vec3, Vec3, Vec3) {
    let n = &c.normal;
    let (l1, l2) = c.levers;
    let (w1, w2) = t.spins;
    let mut on = (Vec3::zeros(), Vec3::zeros());
    let mut rolling = Vec3::zeros();
    if mat.mu_r != 0.0 {
        let roll = if c.wall {
            w1.cross(n) * l1
        } else {
            w1.cross(n) * l1 - w2.cross(n) * l2
        };
        if let Some(dir) = roll.try_normalize(0.0) {
            // Capped so that the pair's torques cannot reverse the spin of one against
            // the other across the normal (through the reduced inertia) within the step.
            let (i1, i2) = t.inertias;
            let reduced = if i2.is_finite() {
                i1 * i2 / (i1 + i2)
            } else {
                i1
            };
            let relative = w1 - w2;
            let across = (relative - n * n.dot(&relative)).norm();
            let wanted = mat.mu_r * normal_force * t.roll_levers.0;
            let scale = if wanted > 0.0 {
                (reduced * across / dt / wanted).min(1.0)
            } else {
                0.0
            };
            let per_lever = dir.cross(n) * (mat.mu_r * normal_force * scale);
            rolling = per_lever * t.roll_levers.0;
            on.0 += rolling;
            if !c.wall {
                on.1 -= per_lever * t.roll_levers.1;
            }
        }
    }
    if mat.mu_t != 0.0 && t.twist_radius > 0.0 {
        let rate = c.spin.dot(n);
        if rate != 0.0 {
            let m_t = n * (mat.mu_t * normal_force * t.twist_radius).copysign(rate);
            on.0 += m_t;
            on.1 -= m_t;
        }
    }
    (on.0, on.1, rolling)
}

/// What a [`Dashpot`] contact does: the force on particle 1 (−it on a particle partner)
/// and the torques on both.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DashpotForce {
    /// The force on particle 1, F_n + F_t.
    pub force: Vec3,
    /// The torque on particle 1.
    pub torque: Vec3,
    /// The torque on a particle partner.
    pub partner_torque: Vec3,
    /// The rolling and twisting torque on particle 1, M_r + M_t (the partner feels
    /// −it).
    pub resistance: Vec3,
    /// The rolling torque M_r alone (part of `resistance`), which pkdgrav's aggregates
    /// turn into a pseudo-force (docs/pkdgrav-physics.md §9.4).
    pub rolling: Vec3,
}

/// `v` turned right-handedly about the unit `axis` by the angle whose sine and cosine are
/// given.
fn turn(v: &Vec3, axis: &Vec3, sin: f64, cos: f64) -> Vec3 {
    v * cos + axis.cross(v) * sin + axis * (axis.dot(v) * (1.0 - cos))
}

/// The shear force k_t S + C_t u_t of a contact whose spring `spring` has been stretched
/// this step and whose tangential velocity is `ut`, limited to `cap` (μ_s N) as `rule`
/// says when it exceeds it: pkdgrav's reset (the spring to zero, the force the dashpot's
/// capped at `cap`) or the Coulomb clamp (the spring rescaled so that the force is `cap`
/// along the force it had). Inlined always, with [`turn_springs`]: the springs stay in
/// registers through the contact law ([`dashpot_contact_with`]).
#[inline(always)]
fn slide(spring: &mut Vec3, ut: &Vec3, k_t: f64, c_t: f64, cap: f64, rule: Sliding) -> Vec3 {
    let f_t = *spring * k_t + ut * c_t;
    if f_t.norm_squared() <= cap * cap {
        return f_t;
    }
    match rule {
        Sliding::Reset => {
            *spring = Vec3::zeros();
            let speed = ut.norm();
            if speed > 0.0 {
                ut * (cap.min(c_t * speed) / speed)
            } else {
                Vec3::zeros()
            }
        }
        Sliding::Clamp => {
            let scale = cap / f_t.norm();
            if k_t > 0.0 {
                let dashpot = ut * (c_t / k_t);
                *spring = (*spring + dashpot) * scale - dashpot;
            }
            f_t * scale
        }
    }
}

/// Below this size (2⁻⁷) an angle's sine and cosine are [`sin_cos_series`]'s.
pub(crate) const SERIES_UP_TO: f64 = 0.0078125;

/// The sine and cosine of an angle: for the small angles a contact turns by in a step
/// (|x| < `SERIES_UP_TO`, 2⁻⁷), a Taylor series (`sin_cos_series`), at a tenth of the
/// library's cost; else the library's.
#[inline]
pub fn small_sin_cos(x: f64) -> (f64, f64) {
    if x.abs() >= SERIES_UP_TO {
        return x.sin_cos();
    }
    sin_cos_series(x)
}

/// The Taylor series of an angle's sine and cosine to x⁷ and x⁸, whose first term left
/// out is below 10⁻²² of the value for |x| < [`SERIES_UP_TO`] (an ulp is 1.1·10⁻¹⁶).
/// The law four contacts at a time ([`super::lanes`]) runs the same operations in the
/// same order in vector instructions (`tests/lanes.rs` holds the two together).
#[inline(always)]
fn sin_cos_series(x: f64) -> (f64, f64) {
    let x2 = x * x;
    let sin = x * (1.0 - x2 * (1.0 / 6.0) * (1.0 - x2 * (1.0 / 20.0) * (1.0 - x2 * (1.0 / 42.0))));
    let cos = 1.0
        - x2 * 0.5
            * (1.0 - x2 * (1.0 / 12.0) * (1.0 - x2 * (1.0 / 30.0) * (1.0 - x2 * (1.0 / 56.0))));
    (sin, cos)
}

/// Whether each of `v`'s components is zero (`v == Vec3::zeros()`, component by
/// component as nalgebra compares them, so −0 is zero and a NaN is not), stopping at the
/// first that is not: as compiled, nalgebra's comparison loads and compares all three,
/// up to five times in a contact (875 → 847 instructions a pair contact on the
/// oscillating floor). `num_traits::Zero::is_zero`, which nalgebra implements, gives
/// the same answers but cost 16 instructions a contact more and the oscillating floor
/// 3–4 % more time (two sets of six alternating runs).
#[inline]
fn is_zero(v: &Vec3) -> bool {
    v.x == 0.0 && v.y == 0.0 && v.z == 0.0
}

/// The shear and rolling springs of `record` turned about `axis` (a zero spring stays
/// zero: it is left alone).
#[inline(always)]
fn turn_springs(record: &mut Record, axis: &Vec3, sin: f64, cos: f64) {
    if !is_zero(&record.spring) {
        record.spring = turn(&record.spring, axis, sin, cos);
    }
    if !is_zero(&record.roll) {
        record.roll = turn(&record.roll, axis, sin, cos);
    }
}

/// pkdgrav's contact law with its `DEM_ROTATION_DASHPOT` rolling and twisting
/// (docs/pkdgrav-physics.md §1.2–§1.5): the springs in `record` turned with the contact
/// (about the mean normal by the mean spin over `dt`, then with the normal's change, the
/// other way for a wall), stretched, and limited (the shear spring reset when the contact
/// slides, or clamped at the Coulomb limit as [`Dashpot::sliding`] says; the rolling and
/// twisting springs held at their slider limits).
pub fn dashpot_contact(c: &Dashpot, record: &mut Record, dt: f64, mat: &Material) -> DashpotForce {
    dashpot_contact_with(c, record, dt, mat, &Optional::default())
}

/// [`dashpot_contact`] with what pkdgrav's optional builds add (`extra`): the two-layer
/// spring constants chosen by the overlap, the shear spring rescaled when the contact
/// crosses from one layer into the other (docs/pkdgrav-physics.md §8), and the cohesive
/// force added to the normal force after the friction limits (§7: the limits' N excludes
/// it). Inlined always (into the pair and the wall contact): the [`Dashpot`] and
/// [`Optional`] their callers fill in are then read where they were worked out, not
/// written out and read back, 3 % of a pair contact's instructions.
#[inline(always)]
pub fn dashpot_contact_with(
    c: &Dashpot,
    kept: &mut Record,
    dt: f64,
    mat: &Material,
    extra: &Optional,
) -> DashpotForce {
    // The record in a local, written back once at the end: its springs are turned,
    // stretched and limited one after the other, and through the reference each step
    // read back what the last had just stored, in other widths, and waited for it
    // (`slide` alone, called with the spring just stretched, was 8 % of the
    // oscillating floor's time).
    let mut record = *kept;
    let force = dashpot_law(c, &mut record, dt, mat, extra);
    *kept = record;
    force
}

/// [`dashpot_contact_with`] on a record held in a local.
#[inline(always)]
fn dashpot_law(
    c: &Dashpot,
    record: &mut Record,
    dt: f64,
    mat: &Material,
    extra: &Optional,
) -> DashpotForce {
    let n = &c.normal;
    let (k_n, k_t, spring_force) = match &extra.layers {
        None => (mat.k_n, mat.k_t, mat.k_n * c.overlap),
        Some(layers) => {
            let (layer, k_n, k_t, force) = layers.at(c.overlap);
            record.spring *= layers.rescale(record.layer, layer);
            record.layer = layer;
            (k_n, k_t, force)
        }
    };
    if !is_zero(&record.normal) {
        // §1.3 step 1: about the mean normal, by the mean spin of the two over the step.
        if let Some(mean) = (record.normal + n).try_normalize(0.0) {
            let angle = 0.5 * dt * c.turn.dot(&mean);
            if angle != 0.0 {
                let (sin, cos) = small_sin_cos(angle);
                turn_springs(record, &mean, sin, cos);
            }
        }
        // Step 2: with the change of normal (against it for a wall).
        let a = if c.wall {
            n.cross(&record.normal)
        } else {
            record.normal.cross(n)
        };
        let sin = a.norm();
        if sin > 0.0 {
            let axis = a / sin;
            let cos = n.dot(&record.normal);
            turn_springs(record, &axis, sin, cos);
        }
    }
    record.normal = *n;
    let u = &c.velocity;
    let un = n * n.dot(u);
    let ut = u - un;
    let (c_n, c_t) = extra.damping.unwrap_or_else(|| {
        let (eps_n, eps_t) = extra
            .restitution
            .unwrap_or_else(|| (Restitution::new(mat.eps_n), Restitution::new(mat.eps_t)));
        (eps_n.damping(k_n, c.mass), eps_t.damping(k_t, c.mass))
    });
    let f_n = n * -spring_force + un * c_n;
    let normal_force = f_n.norm();
    // Step 4 and 5: the shear spring, and the slide.
    record.spring += ut * dt;
    let f_t = slide(
        &mut record.spring,
        &ut,
        k_t,
        c_t,
        mat.mu_s * normal_force,
        c.sliding,
    );
    let shear = n.cross(&f_t);
    // §7: cohesion pulls along n̂, added after the limits.
    let cohesion = if extra.cohesion != 0.0 {
        n * extra.cohesion
    } else {
        Vec3::zeros()
    };
    if let Some(t) = &c.constant_torque {
        let (on_1, on_2, rolling) = constant_torques(c, t, normal_force, mat, dt);
        return DashpotForce {
            force: f_n + f_t + cohesion,
            torque: shear * c.levers.0 + on_1,
            partner_torque: shear * c.levers.1 + on_2,
            resistance: on_1,
            rolling,
        };
    }
    // §1.4: rolling and twisting, spring–dashpot–sliders scaled by (β_s R*)².
    let b = (mat.beta_s * c.radius).powi(2);
    let mut resistance = Vec3::zeros();
    let mut rolling = Vec3::zeros();
    let (l1, l2) = c.levers;
    if mat.mu_r != 0.0 {
        let kappa = if c.wall {
            0.5 / l1
        } else {
            0.5 * (l2 - l1) / (l1 * l2)
        };
        let rate = c.spin - n * n.dot(&c.spin) + n.cross(u) * kappa;
        record.roll += rate * dt;
        let mut m_r = record.roll * (k_n * b);
        let limit = mat.mu_r * mat.beta_s * c.radius * normal_force;
        let size = m_r.norm();
        if size > limit {
            m_r *= limit / size;
            record.roll -= rate * dt;
        } else {
            m_r += rate * (c_n * b);
        }
        resistance += m_r;
        rolling = m_r;
    }
    if mat.mu_t != 0.0 {
        let rate = c.spin.dot(n);
        record.twist += rate * dt;
        let torque = 2.0 * k_t * b * record.twist;
        let limit = mat.mu_t * mat.beta_s * c.radius * mat.mu_s * normal_force;
        let m_t = if torque.abs() > limit {
            record.twist -= rate * dt;
            limit.copysign(torque)
        } else {
            torque + 2.0 * c_t * b * rate
        };
        resistance += n * m_t;
    }
    DashpotForce {
        force: f_n + f_t + cohesion,
        torque: shear * l1 + resistance,
        partner_torque: shear * l2 - resistance,
        resistance,
        rolling,
    }
}
