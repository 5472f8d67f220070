//! The settings of a run (`walls-sim run` and `plan`): each value from the command
//! line's flags if given, else from the pkdgrav parameter file (`.par`), else the
//! evaluator's default ([`crate::run::defaults`]).
//!
//! The particles come from `--particles`, else from the `.par` file's `achInFile`
//! (relative to the `.par` file's folder), else nine particles dropped onto the scene;
//! gravity defaults to −z only for those dropped particles. [`load`] reads the files;
//! [`resolve`] applies the precedence to what was read.

use crate::OscillationStepping;
use crate::io::par::Params;
use crate::io::{FileError, par, particles};
use crate::run::defaults;
use crate::run::{ContactModel, Integrator, ParticleMaterial, Planning, Settings, default_dt};
use nalgebra::Vector3;
use walls_geometry::Particle;
use walls_geometry::Wall;

type Vec3 = Vector3<f64>;

/// What the command line gives: `None` (or `false`) where a flag is absent.
#[derive(Debug, Clone, Default)]
pub struct Flags {
    /// `--particles`: a CSV or `.ss` file.
    pub particles: Option<String>,
    /// `--par`: a pkdgrav parameter file.
    pub par: Option<String>,
    /// `--method`.
    pub method: ContactModel,
    /// `--dt`.
    pub dt: Option<f64>,
    /// `--t-end`.
    pub t_end: Option<f64>,
    /// `--gravity`.
    pub gravity: Option<Vec3>,
    /// `--epsn`.
    pub eps_n: Option<f64>,
    /// `--epst`.
    pub eps_t: Option<f64>,
    /// `--k-n`.
    pub k_n: Option<f64>,
    /// `--k-t`.
    pub k_t: Option<f64>,
    /// `--mu-s`.
    pub mu_s: Option<f64>,
    /// `--mu-r`.
    pub mu_r: Option<f64>,
    /// `--mu-t`.
    pub mu_t: Option<f64>,
    /// `--no-particle-contacts`.
    pub no_particle_contacts: bool,
    /// `--no-edges` (else the `.par` file's `bWallsEdgeDetect`, else on).
    pub no_edges: bool,
    /// `--oscillation`.
    pub stepping: OscillationStepping,
    /// `--integrator`.
    pub integrator: Integrator,
    /// `--all-parts`.
    pub planning: Planning,
}

/// A run's particles and settings.
#[derive(Debug, Clone, PartialEq)]
pub struct Run {
    /// The particles.
    pub particles: Vec<Particle>,
    /// The settings.
    pub settings: Settings,
}

/// Why a run cannot be set up.
#[derive(Debug)]
pub enum ConfigError {
    /// The `.par` file or the particle file could not be read, or is wrong (the error
    /// names the file and the line or byte).
    File(FileError),
    /// The particle file has no particles.
    NoParticles,
}

impl From<FileError> for ConfigError {
    fn from(e: FileError) -> Self {
        ConfigError::File(e)
    }
}

impl std::fmt::Display for ConfigError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            ConfigError::File(e) => e.fmt(f),
            ConfigError::NoParticles => write!(f, "no particles to run"),
        }
    }
}

impl std::error::Error for ConfigError {}

/// Reads the `.par` file and the particle file that `flags` name, and settles the run's
/// settings against `scene`.
pub fn load(flags: &Flags, scene: &[Wall]) -> Result<Run, ConfigError> {
    let par = flags.par.as_deref().map(par::read_file).transpose()?;
    let particles = match particle_file(flags, par.as_ref()) {
        Some(f) => Some(particles::read_file(&f)?),
        None => None,
    };
    resolve(flags, par.as_ref(), scene, particles)
}

/// The particle file to read: `--particles`, else the `.par` file's `achInFile`, taken
/// relative to the `.par` file's folder; `None` for the default particles.
pub fn particle_file(flags: &Flags, par: Option<&Params>) -> Option<String> {
    flags.particles.clone().or_else(|| {
        let par_dir = std::path::Path::new(flags.par.as_deref()?)
            .parent()?
            .to_path_buf();
        par?.in_file
            .as_ref()
            .map(|f| par_dir.join(f).to_string_lossy().into_owned())
    })
}

/// The run's settings from `flags`, then `par`, then the defaults for `scene` and the
/// `particles` read from the particle file (`None`: the default particles).
pub fn resolve(
    flags: &Flags,
    par: Option<&Params>,
    scene: &[Wall],
    particles: Option<Vec<Particle>>,
) -> Result<Run, ConfigError> {
    let (particles, embedded) = match particles {
        Some(ps) => (ps, false),
        None => (defaults::default_particles(scene), true),
    };
    if particles.is_empty() {
        return Err(ConfigError::NoParticles);
    }
    let gravity = match (flags.gravity, par.and_then(|p| p.gravity)) {
        (Some(g), _) => g,
        (None, Some(g)) => g,
        (None, None) if embedded => Vec3::new(0.0, 0.0, -1.0),
        (None, None) => Vec3::zeros(),
    };
    let from_par = |f: fn(&Params) -> Option<f64>| par.and_then(f);
    let method = flags.method;
    let k_n = flags
        .k_n
        .or(from_par(|p| p.k_n))
        .unwrap_or_else(|| defaults::default_k_n(scene, &particles, &gravity));
    let default = defaults::default_material(k_n);
    let material = ParticleMaterial {
        eps_n: flags
            .eps_n
            .or(from_par(|p| p.eps_n))
            .unwrap_or(default.eps_n),
        eps_t: flags
            .eps_t
            .or(from_par(|p| p.eps_t))
            .unwrap_or(default.eps_t),
        k_n,
        k_t: flags.k_t.or(from_par(|p| p.k_t)).unwrap_or(default.k_t),
        mu_s: flags.mu_s.or(from_par(|p| p.mu_s)).unwrap_or(default.mu_s),
        mu_r: flags.mu_r.or(from_par(|p| p.mu_r)).unwrap_or(default.mu_r),
        mu_t: flags.mu_t.or(from_par(|p| p.mu_t)).unwrap_or(default.mu_t),
    };
    let t_end = flags
        .t_end
        .or_else(|| par.and_then(|p| Some(p.steps? as f64 * p.dt?)))
        .unwrap_or_else(|| defaults::default_duration(scene, &particles, &gravity));
    let dt = flags
        .dt
        .or(from_par(|p| p.dt))
        .unwrap_or_else(|| match method {
            ContactModel::Ssdem => default_dt(&particles, k_n),
            ContactModel::Hsdem => defaults::default_hard_dt(&particles, &gravity, t_end),
        });
    let settings = Settings {
        method,
        gravity,
        particle_contacts: !flags.no_particle_contacts,
        edges: !flags.no_edges && par.and_then(|p| p.edge_detect).unwrap_or(true),
        stepping: flags.stepping,
        integrator: flags.integrator,
        planning: flags.planning,
        ..Settings::new(dt, t_end, material)
    };
    Ok(Run {
        particles,
        settings,
    })
}
