//! A contact's material values, and pkdgrav's fall-backs from a wall's values to the
//! particles' (SPEC §3): a wall's `epsn`/`epst` of 99 and its `k_n`, `k_t`, `mu_s`,
//! `mu_r`, `mu_t`, `beta_s` of −1 mean "the particles' value".

/// The material values of a contact, or of a wall as written.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Material {
    /// Normal coefficient of restitution.
    pub eps_n: f64,
    /// Tangential coefficient of restitution.
    pub eps_t: f64,
    /// Normal spring constant.
    pub k_n: f64,
    /// Tangential spring constant.
    pub k_t: f64,
    /// Static friction coefficient (0: frictionless).
    pub mu_s: f64,
    /// Rolling friction coefficient (0: none).
    pub mu_r: f64,
    /// Twisting friction coefficient (0: none).
    pub mu_t: f64,
    /// The shape parameter β_s of the rolling and twisting spring–dashpot–slider
    /// (pkdgrav's `dBetaS`, a wall's `beta_s`; physics.md §1.4).
    pub beta_s: f64,
}

/// pkdgrav's β_s when the `.par` file leaves `dBetaS` out (its default build,
/// `DEM_ROTATION_DASHPOT`; physics.md §4).
pub const BETA_S_DEFAULT: f64 = 0.5;

/// The restitution value that means "the particles' value".
pub const EPS_FALLBACK: f64 = 99.0;

/// The spring and friction value that means "the particles' value".
pub const VALUE_FALLBACK: f64 = -1.0;

impl Material {
    /// This wall material with its fall-backs replaced by the particles' values: what a
    /// particle meets at this wall.
    pub fn against(&self, particles: &Material) -> Material {
        let own = |x: f64, fallback: f64| if x == VALUE_FALLBACK { fallback } else { x };
        let eps = |x: f64, fallback: f64| if x == EPS_FALLBACK { fallback } else { x };
        Material {
            eps_n: eps(self.eps_n, particles.eps_n),
            eps_t: eps(self.eps_t, particles.eps_t),
            k_n: own(self.k_n, particles.k_n),
            k_t: own(self.k_t, particles.k_t),
            mu_s: own(self.mu_s, particles.mu_s),
            mu_r: own(self.mu_r, particles.mu_r),
            mu_t: own(self.mu_t, particles.mu_t),
            beta_s: own(self.beta_s, particles.beta_s),
        }
    }

    /// Whether either restitution is left at 99 (the hard-sphere run reports it).
    pub fn restitution_falls_back(&self) -> bool {
        self.eps_n == EPS_FALLBACK || self.eps_t == EPS_FALLBACK
    }
}
