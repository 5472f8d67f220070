//! Cohesion (pkdgrav's `DEM_COHESION` build, docs/pkdgrav-physics.md §7): while two
//! bodies overlap, a force pulls them together along the normal. Its size depends on the
//! model and the coefficient c (raw pkdgrav units of stress):
//!
//! | | particle–particle | particle–wall |
//! |---|---|---|
//! | 0, microscopic contact | c·4β_s²R*², R* = r₁r₂/(r₁+r₂); with `bUseContactRadius` c·πβ_s²a² | c·4β_s²r² (c·πβ_s²a²) |
//! | 1, granular bridge | c·2π r₁²r₂²/(r₁²+r₂²) | c·2πr² |
//!
//! The force is added to the normal force after the friction limits
//! ([`crate::contact::ssdem::dashpot_contact_with`]), so it does not raise them.
//! Per-colour coefficients come from a cohesion file ([`crate::io::cohesion`]).

use std::f64::consts::PI;

/// The cohesion model (`iCohesionModel`, a wall's `cohesion_model`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Model {
    /// 0: the microscopic contact model, scaled by β_s.
    #[default]
    Contact,
    /// 1: the granular (liquid) bridge model.
    Bridge,
}

impl Model {
    /// The model's code as pkdgrav numbers them (`iCohesionModel`).
    pub fn code(self) -> i64 {
        match self {
            Model::Contact => 0,
            Model::Bridge => 1,
        }
    }

    /// The model numbered `n` (0 or 1) as pkdgrav numbers them.
    pub fn from_number(n: i64) -> Option<Model> {
        match n {
            0 => Some(Model::Contact),
            1 => Some(Model::Bridge),
            _ => None,
        }
    }
}

/// How two particles of different colours combine their coefficients (the cohesion
/// file's rule).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Rule {
    /// 0: no combination: particles of different colours do not cohere.
    None,
    /// 1: the mean of the two.
    Mean,
    /// 2: the larger.
    Max,
    /// 3: the smaller.
    Min,
}

impl Rule {
    /// The rule numbered `n` (0 to 3).
    pub fn from_number(n: i64) -> Option<Rule> {
        match n {
            0 => Some(Rule::None),
            1 => Some(Rule::Mean),
            2 => Some(Rule::Max),
            3 => Some(Rule::Min),
            _ => None,
        }
    }

    /// The coefficient between two particles whose coefficients are `a` and `b`, of
    /// different colours.
    pub fn combine(self, a: f64, b: f64) -> f64 {
        match self {
            Rule::None => 0.0,
            Rule::Mean => 0.5 * (a + b),
            Rule::Max => a.max(b),
            Rule::Min => a.min(b),
        }
    }
}

/// Per-colour coefficients (`achCohesionFile`): the rule, and each colour listed with
/// its coefficient, in file order.
#[derive(Debug, Clone, PartialEq)]
pub struct Colours {
    /// How different colours combine.
    pub rule: Rule,
    /// (colour, coefficient).
    pub coefficients: Vec<(i32, f64)>,
}

/// A run's cohesion values from the `.par` file.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Cohesion {
    /// `iCohesionModel`.
    pub model: Model,
    /// `dCohesiveCoeff`: the coefficient of every particle whose colour the cohesion
    /// file does not list.
    pub coefficient: f64,
    /// `achCohesionFile`, read.
    pub colours: Option<Colours>,
}

impl Cohesion {
    /// The coefficient of a particle of colour `colour`.
    pub fn of_colour(&self, colour: i32) -> f64 {
        self.colours
            .as_ref()
            .and_then(|t| t.coefficients.iter().find(|(c, _)| *c == colour))
            .map_or(self.coefficient, |&(_, x)| x)
    }

    /// The coefficient between particles of colours `a` and `b`: their own when the
    /// colours are the same, else the two combined by the file's rule.
    pub fn between(&self, a: i32, b: i32) -> f64 {
        let (ca, cb) = (self.of_colour(a), self.of_colour(b));
        match &self.colours {
            Some(t) if a != b => t.rule.combine(ca, cb),
            _ => ca,
        }
    }
}

/// The size of the cohesive force between particles of radii `r1` and `r2`, with
/// coefficient `c`, model `model` and shape parameter `beta_s`; `contact_radius` is the
/// contact radius a when pkdgrav's `bUseContactRadius` is on.
pub fn between_particles(
    model: Model,
    c: f64,
    beta_s: f64,
    r1: f64,
    r2: f64,
    contact_radius: Option<f64>,
) -> f64 {
    match (model, contact_radius) {
        (Model::Contact, None) => {
            let r = r1 * r2 / (r1 + r2);
            c * 4.0 * beta_s * beta_s * r * r
        }
        (Model::Contact, Some(a)) => c * PI * beta_s * beta_s * a * a,
        (Model::Bridge, _) => {
            let (s1, s2) = (r1 * r1, r2 * r2);
            c * 2.0 * PI * s1 * s2 / (s1 + s2)
        }
    }
}

/// The size of the cohesive force between a particle of radius `r` and a wall, as
/// [`between_particles`].
pub fn against_wall(model: Model, c: f64, beta_s: f64, r: f64, contact_radius: Option<f64>) -> f64 {
    match (model, contact_radius) {
        (Model::Contact, None) => c * 4.0 * beta_s * beta_s * r * r,
        (Model::Contact, Some(a)) => c * PI * beta_s * beta_s * a * a,
        (Model::Bridge, _) => c * 2.0 * PI * r * r,
    }
}
