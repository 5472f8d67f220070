//! A contact's material values, and pkdgrav's fall-backs from a wall's values to the
//! particles' (docs/spec.md §3): a wall's `epsn`/`epst` of 99 and its `k_n`, `k_t`,
//! `mu_s`, `mu_r`, `mu_t`, `beta_s` of −1 mean "the particles' value".

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
    /// (pkdgrav's `dBetaS`, a wall's `beta_s`; docs/pkdgrav-physics.md §1.4).
    pub beta_s: f64,
}

/// pkdgrav's β_s when the `.par` file leaves `dBetaS` out (its default build,
/// `DEM_ROTATION_DASHPOT`; docs/pkdgrav-physics.md §4).
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

/// A wall's values for the contact physics of pkdgrav's optional builds, as written:
/// cohesion (`DEM_COHESION`, docs/pkdgrav-physics.md §7) and two-layer contacts
/// (`DEM_TWOLAYERS`, §8). Every value left at −1 means "the `.par` value"; a `k_n_*`
/// written resets its `k_t_*` to 2/7 of it (the scene's resolution does that, in file
/// order).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OptionalMaterial {
    /// `cohesion_model`: 0 microscopic contact, 1 granular bridge, −1 the `.par`'s.
    pub cohesion_model: i64,
    /// `cohesive_coeff`, in raw pkdgrav units of stress.
    pub cohesive_coeff: f64,
    /// `inner_overlap_boundary`: the two-layer boundary as a fraction of the radius.
    pub inner_overlap_boundary: f64,
    /// `k_n_outer`.
    pub k_n_outer: f64,
    /// `k_t_outer`.
    pub k_t_outer: f64,
    /// `k_n_inner`.
    pub k_n_inner: f64,
    /// `k_t_inner`.
    pub k_t_inner: f64,
}

impl Default for OptionalMaterial {
    /// Every value at −1: the `.par` values throughout.
    fn default() -> Self {
        OptionalMaterial {
            cohesion_model: -1,
            cohesive_coeff: VALUE_FALLBACK,
            inner_overlap_boundary: VALUE_FALLBACK,
            k_n_outer: VALUE_FALLBACK,
            k_t_outer: VALUE_FALLBACK,
            k_n_inner: VALUE_FALLBACK,
            k_t_inner: VALUE_FALLBACK,
        }
    }
}

impl OptionalMaterial {
    /// The cohesion tokens this wall sets (not −1), by name.
    pub fn cohesion_tokens(&self) -> Vec<&'static str> {
        let mut out = Vec::new();
        if self.cohesion_model != -1 {
            out.push("cohesion_model");
        }
        if self.cohesive_coeff != VALUE_FALLBACK {
            out.push("cohesive_coeff");
        }
        out
    }

    /// The two-layer tokens this wall sets (not −1), by name.
    pub fn two_layer_tokens(&self) -> Vec<&'static str> {
        [
            ("inner_overlap_boundary", self.inner_overlap_boundary),
            ("k_n_outer", self.k_n_outer),
            ("k_t_outer", self.k_t_outer),
            ("k_n_inner", self.k_n_inner),
            ("k_t_inner", self.k_t_inner),
        ]
        .into_iter()
        .filter(|&(_, x)| x != VALUE_FALLBACK)
        .map(|(name, _)| name)
        .collect()
    }
}
