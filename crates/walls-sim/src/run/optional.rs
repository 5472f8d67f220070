//! What pkdgrav's optional builds add to a soft-sphere run's contacts: cohesion
//! (`DEM_COHESION`, docs/pkdgrav-physics.md §7) and two-layer contacts (`DEM_TWOLAYERS`,
//! §8). Each is on when the run's build has its option and the integrator is
//! [`Integrator::Pkdgrav`] (pkdgrav's contact law); [`OptionalPhysics::new`] resolves
//! the walls' values against the `.par` file's once, and the steppers ask it for each
//! contact's [`Optional`] (nothing, at the cost of a test, when both are off).
//!
//! A walls file that sets cohesion or two-layer tokens for a run that does not follow
//! them is warned about ([`token_warnings`], W501 and W502).

use super::{Integrator, Settings, State, Warning};
use crate::contact::cohesion::{self, Cohesion, Model};
use crate::contact::ssdem::{Layers, Material, Optional};
use crate::io::par::{KT_PER_KN, TwoLayer};
use walls_geometry::Wall;

/// Whether the run follows cohesion: a `DEM_COHESION` build with pkdgrav's law.
pub fn cohesion_on(settings: &Settings) -> bool {
    settings.build.cohesion && settings.integrator == Integrator::Pkdgrav
}

/// Whether the run follows two-layer contacts: a `DEM_TWOLAYERS` build with pkdgrav's
/// law.
pub fn two_layer_on(settings: &Settings) -> bool {
    settings.build.two_layers && settings.integrator == Integrator::Pkdgrav
}

/// pkdgrav's two-layer constants when the `.par` file gives none: no boundary, and
/// every constant from `k_n` (`dKnOuter = dKnInner = -1`, `dKt… = -1`).
pub fn default_two_layer(k_n: f64) -> TwoLayer {
    TwoLayer {
        boundary: 0.0,
        k_n_outer: k_n,
        k_t_outer: KT_PER_KN * k_n,
        k_n_inner: k_n,
        k_t_inner: KT_PER_KN * k_n,
    }
}

/// One wall's cohesion and two-layer values, resolved against the `.par` file's.
#[derive(Debug, Clone, Copy)]
struct WallValues {
    model: Model,
    /// The wall's own coefficient; `None` (its −1): the `.par` file's `dCohesiveCoeff`,
    /// never the colour table (docs/pkdgrav-physics.md §17).
    coefficient: Option<f64>,
    layers: TwoLayer,
}

/// A run's cohesion and two-layer values, ready for its contacts.
pub struct OptionalPhysics {
    cohesion: Option<Cohesion>,
    layers: Option<TwoLayer>,
    walls: Vec<WallValues>,
    /// Each particle's colour and own coefficient.
    colours: Vec<i32>,
    coefficients: Vec<f64>,
}

impl OptionalPhysics {
    /// The values of a run of `states` against `walls` with `settings`.
    pub fn new(walls: &[Wall], states: &[State], settings: &Settings) -> OptionalPhysics {
        let cohesion = cohesion_on(settings).then(|| settings.cohesion.clone());
        let layers = two_layer_on(settings).then(|| {
            settings
                .two_layer
                .unwrap_or_else(|| default_two_layer(settings.material.k_n))
        });
        let (colours, coefficients) = match &cohesion {
            Some(c) => states
                .iter()
                .map(|s| (s.particle.color, c.of_colour(s.particle.color)))
                .unzip(),
            None => (Vec::new(), Vec::new()),
        };
        let par_layers = layers.unwrap_or_else(|| default_two_layer(settings.material.k_n));
        let walls = walls
            .iter()
            .map(|w| {
                let o = &w.optional;
                let own = |x: f64, par: f64| if x == -1.0 { par } else { x };
                WallValues {
                    model: Model::from_number(o.cohesion_model).unwrap_or(settings.cohesion.model),
                    coefficient: (o.cohesive_coeff != -1.0).then_some(o.cohesive_coeff),
                    layers: TwoLayer {
                        boundary: own(o.inner_overlap_boundary, par_layers.boundary),
                        k_n_outer: own(o.k_n_outer, par_layers.k_n_outer),
                        k_t_outer: own(o.k_t_outer, par_layers.k_t_outer),
                        k_n_inner: own(o.k_n_inner, par_layers.k_n_inner),
                        k_t_inner: own(o.k_t_inner, par_layers.k_t_inner),
                    },
                }
            })
            .collect();
        OptionalPhysics {
            cohesion,
            layers,
            walls,
            colours,
            coefficients,
        }
    }

    /// Whether either is on.
    #[inline]
    pub fn any(&self) -> bool {
        self.cohesion.is_some() || self.layers.is_some()
    }

    /// What they add to the contact of particles `i` and `j` (radii `r1`, `r2`, the
    /// contact radius `a` with `bUseContactRadius`, material `mat`). Inlined: in a run
    /// with neither on, most runs, each contact then pays a test, not a call.
    #[inline]
    pub fn pair(
        &self,
        i: usize,
        j: usize,
        r1: f64,
        r2: f64,
        a: Option<f64>,
        mat: &Material,
    ) -> Optional {
        if !self.any() {
            return Optional::default();
        }
        let cohesion = match &self.cohesion {
            Some(c) => {
                let coefficient = match &c.colours {
                    Some(_) if self.colours[i] != self.colours[j] => {
                        c.between(self.colours[i], self.colours[j])
                    }
                    _ => self.coefficients[i],
                };
                cohesion::between_particles(c.model, coefficient, mat.beta_s, r1, r2, a)
            }
            None => 0.0,
        };
        let layers = self.layers.map(|t| {
            let r_eff = if r1 == r2 { r1 } else { 0.5 * (r1 + r2) };
            layers_of(&t, r_eff)
        });
        Optional {
            cohesion,
            layers,
            restitution: None,
            damping: None,
        }
    }

    /// What they add to the contact of a particle (radius `r`, the contact radius `a`
    /// with `bUseContactRadius`) with wall `w`, whose material against particles is
    /// `mat`: the wall's cohesion, whatever the particle's colour.
    #[inline]
    pub fn wall(&self, w: usize, r: f64, a: Option<f64>, mat: &Material) -> Optional {
        if !self.any() {
            return Optional::default();
        }
        let values = &self.walls[w];
        let cohesion = match &self.cohesion {
            Some(c) => {
                let coefficient = values.coefficient.unwrap_or(c.coefficient);
                cohesion::against_wall(values.model, coefficient, mat.beta_s, r, a)
            }
            None => 0.0,
        };
        let layers = self.layers.map(|_| layers_of(&values.layers, r));
        Optional {
            cohesion,
            layers,
            restitution: None,
            damping: None,
        }
    }
}

/// The layers of a contact whose R_eff is `r_eff`: the boundary at the fraction times it.
fn layers_of(t: &TwoLayer, r_eff: f64) -> Layers {
    Layers {
        boundary: t.boundary * r_eff,
        k_n_outer: t.k_n_outer,
        k_t_outer: t.k_t_outer,
        k_n_inner: t.k_n_inner,
        k_t_inner: t.k_t_inner,
    }
}

/// Why a run does not follow an optional build's physics: the build lacks `option`, or
/// the integrator is not pkdgrav's.
fn why_not(settings: &Settings, has: bool, option: &'static str) -> Option<String> {
    if !has {
        Some(format!("the build lacks {option}"))
    } else if settings.integrator != Integrator::Pkdgrav {
        Some(format!(
            "{option} is followed only with pkdgrav's contact law (--integrator pkdgrav, the default)"
        ))
    } else {
        None
    }
}

/// The tokens of one kind that a wall sets.
type TokensOf = fn(&walls_geometry::OptionalMaterial) -> Vec<&'static str>;

/// The walls' cohesion tokens (W501) and two-layer tokens (W502) that the run does not
/// follow, one warning per kind, naming the walls and tokens.
pub fn token_warnings(walls: &[Wall], settings: &Settings) -> Vec<Warning> {
    let mut out = Vec::new();
    let kinds: [(bool, &str, TokensOf); 2] = [
        (settings.build.cohesion, "DEM_COHESION", |o| {
            o.cohesion_tokens()
        }),
        (settings.build.two_layers, "DEM_TWOLAYERS", |o| {
            o.two_layer_tokens()
        }),
    ];
    for (has, option, tokens_of) in kinds {
        let Some(reason) = why_not(settings, has, option) else {
            continue;
        };
        let mut tokens: Vec<&'static str> = Vec::new();
        let mut which = Vec::new();
        for (w, wall) in walls.iter().enumerate() {
            let these = tokens_of(&wall.optional);
            if these.is_empty() {
                continue;
            }
            which.push(w);
            for t in these {
                if !tokens.contains(&t) {
                    tokens.push(t);
                }
            }
        }
        if which.is_empty() {
            continue;
        }
        out.push(if option == "DEM_COHESION" {
            Warning::CohesionTokensIgnored {
                walls: which,
                tokens,
                reason,
            }
        } else {
            Warning::TwoLayerTokensIgnored {
                walls: which,
                tokens,
                reason,
            }
        });
    }
    out
}
