//! The settings of a run (`walls-sim run` and `plan`): each value from the command
//! line's flags if given, else from the pkdgrav parameter file (`.par`), else the
//! evaluator's default ([`crate::run::defaults`]).
//!
//! The walls file is the command line's, else the `.par` file's `achWallsFile`; the
//! particles come from `--particles`, else from the `.par` file's `achInFile`; both
//! `.par` paths are relative to the `.par` file's folder. Without particles from a file,
//! nine particles are dropped onto the scene (or, with `--no-particles`, none: the walls
//! run alone); gravity defaults to −z only for those two. A particle file with no
//! particles runs the walls alone too.
//!
//! A run from a `.par` file is pkdgrav's run (docs/pkdgrav-physics.md §3–4): a
//! material key the file leaves out takes pkdgrav's default (ε 1, no friction,
//! k_t = 2/7·k_n), except `dKn`, whose default 0 would let particles through every wall
//! (the evaluator derives it from the scene, with a warning); `nSteps` is the number of
//! the last step, counted exactly from `iStartStep`, which also sets the start time.
//! [`read_par`] and [`load`] read the files; [`resolve`] applies the precedence.

use crate::OscillationStepping;
use crate::build::Build;
use crate::contact::ssdem::Sliding;
use crate::io::par::Params;
use crate::io::{FileError, par, particles};
use crate::run::defaults;
use crate::run::{ContactModel, Integrator, ParticleMaterial, Planning, Settings, Warning};
use nalgebra::Vector3;
use walls_geometry::Particle;
use walls_geometry::Wall;
use walls_keywords::number::EXACT_COUNT;

type Vec3 = Vector3<f64>;

/// What the command line gives: `None` (or `false`) where a flag is absent.
#[derive(Debug, Clone, Default)]
pub struct Flags {
    /// `--particles`: a CSV or `.ss` file.
    pub particles: Option<String>,
    /// `--no-particles`: the walls alone, instead of the embedded particles.
    pub no_particles: bool,
    /// `--par`: a pkdgrav parameter file.
    pub par: Option<String>,
    /// `--method`.
    pub method: ContactModel,
    /// `--pkdgrav-build` (default pkdgrav's default build, with `DEM` as `--method`
    /// says); when given, it decides the contact model.
    pub build: Option<Build>,
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
    /// `--sliding` (pkdgrav's reset unless given; the `.par` file has no such key).
    pub sliding: Sliding,
    /// `--all-parts`.
    pub planning: Planning,
    /// `--max-steps` (default [`MAX_STEPS`]).
    pub max_steps: Option<u64>,
    /// `--every` (else the `.par` file's `iOutInterval`, else [`EVERY`]).
    pub every: Option<u64>,
}

impl Flags {
    /// The pkdgrav build the run follows: `--pkdgrav-build`, else pkdgrav's default build
    /// with `DEM` as `--method` says. Its [`Build::contact_model`] is the run's contact
    /// model, the mode its walls file is checked in.
    pub fn build(&self) -> Build {
        self.build
            .clone()
            .unwrap_or_else(|| Build::default_for(self.method))
    }

    /// Where [`Flags::build`] came from, as `walls-sim plan` says it.
    pub fn build_origin(&self) -> &'static str {
        match (&self.build, self.method) {
            (Some(_), _) => "as --pkdgrav-build gives it",
            (None, ContactModel::Ssdem) => "pkdgrav's default build; --pkdgrav-build names another",
            (None, ContactModel::Hsdem) => {
                "pkdgrav's default build without DEM, as --method hsdem; --pkdgrav-build names another"
            }
        }
    }
}

/// Steps between outputs when neither `--every` nor the `.par` file says.
pub const EVERY: u64 = 100;

/// How a run's outputs are named and spaced, from the options and the `.par` file.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Outputs {
    /// Steps between outputs: `--every`, else the `.par` file's `iOutInterval`, else
    /// [`EVERY`]; 0 (`iOutInterval = 0`) for none but the last step's.
    pub every: u64,
    /// The `.ss` outputs' base name and digits (`achOutName`'s last part, `nDigits`).
    pub ss: SsNames,
    /// Why `achOutName`'s folder part is not followed, when it has one.
    pub ss_warning: Option<String>,
}

/// The base name and digits of the `.ss` outputs (pkdgrav's `achOutName`, `nDigits`).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SsNames {
    /// The base name, without a folder.
    pub base: String,
    /// The least number of digits of the step.
    pub digits: usize,
}

/// How the run that `flags` and `par` (read by [`read_par`]) describe names and spaces its
/// outputs.
pub fn outputs(flags: &Flags, par: Option<&Params>) -> Outputs {
    let (base, ss_warning) = ss_base(par.and_then(|p| p.out_name.as_deref()));
    Outputs {
        every: flags.every.or_else(|| par?.out_interval).unwrap_or(EVERY),
        ss: SsNames {
            base,
            digits: par.and_then(|p| p.digits).unwrap_or(5),
        },
        ss_warning,
    }
}

/// The `.ss` outputs' base name from `achOutName` (`None`: pkdgrav's `ss`), and a warning
/// when its folder part is not followed: the outputs go to `--out`, named by the last part
/// of the path (`../../e` and `/scratch/run/e` give `e`; `..` alone gives `ss`).
pub fn ss_base(out_name: Option<&str>) -> (String, Option<String>) {
    let Some(name) = out_name else {
        return ("ss".into(), None);
    };
    let last = std::path::Path::new(name)
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .filter(|n| n != "." && n != "..");
    match last {
        Some(base) if base == name => (base, None),
        Some(base) => {
            let warning = format!(
                "achOutName = {name}: its folder is not followed: the .ss outputs are \
                 written in --out as {base}.NNNNN"
            );
            (base, Some(warning))
        }
        None => (
            "ss".into(),
            Some(format!(
                "achOutName = {name} names no file: the .ss outputs are written in --out as ss.NNNNN"
            )),
        ),
    }
}

/// The most steps a run takes unless `--max-steps` says more: a hundred million, a few
/// minutes for a few particles, past which a mistyped timestep or end time is likelier
/// than a wanted run (docs/evaluator.md).
pub const MAX_STEPS: u64 = 100_000_000;

/// A run's particles and settings.
#[derive(Debug, Clone, PartialEq)]
pub struct Run {
    /// The particles.
    pub particles: Vec<Particle>,
    /// The settings.
    pub settings: Settings,
    /// The `.par` lines the run does not follow because of its build or integrator
    /// (cohesion's and two-layer contacts' keys without `DEM_COHESION` or
    /// `DEM_TWOLAYERS`, or without pkdgrav's integrator), in line order; the `.par`
    /// file's own warnings are in [`Params::warnings`].
    pub warnings: Vec<par::ParWarning>,
    /// The subnormal numbers of the run's inputs (W701), each with where it is: the
    /// options', the `.par` file's, the particle file's, then the cohesion file's.
    pub numbers: Vec<Warning>,
}

/// Why a run cannot be set up.
#[derive(Debug)]
pub enum ConfigError {
    /// The `.par` file or the particle file could not be read, or is wrong (the error
    /// names the file and the line or byte).
    File(FileError),
    /// The values read are each fine, but the run they make cannot be computed (its
    /// timestep or spring overflows, or it would take more steps than allowed): what,
    /// and what to give instead.
    Unusable(String),
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
            ConfigError::Unusable(why) => f.write_str(why),
        }
    }
}

impl std::error::Error for ConfigError {}

/// Reads the `.par` file that `flags` name, if any.
pub fn read_par(flags: &Flags) -> Result<Option<Params>, ConfigError> {
    Ok(flags.par.as_deref().map(par::read_file).transpose()?)
}

/// Reads the particle file that `flags` and `par` (read by [`read_par`]) name, and
/// settles the run's settings against `scene`.
pub fn load(flags: &Flags, par: Option<&Params>, scene: &[Wall]) -> Result<Run, ConfigError> {
    let read = match particle_file(flags, par) {
        Some(f) => Some(particles::read_file(&f)?),
        None => None,
    };
    let (particles, numbers) = match read {
        Some(read) => (Some(read.particles), read.warnings),
        None => (None, Vec::new()),
    };
    let mut run = resolve(flags, par, scene, particles)?;
    run.numbers.extend(numbers);
    if crate::run::optional::cohesion_on(&run.settings)
        && let Some(file) = cohesion_file(flags, par)
    {
        let (colours, numbers) = crate::io::cohesion::read_file(&file)?;
        run.settings.cohesion.colours = Some(colours);
        run.numbers.extend(numbers);
    }
    Ok(run)
}

/// The cohesion file to read: the `.par` file's `achCohesionFile`, taken relative to the
/// `.par` file's folder.
pub fn cohesion_file(flags: &Flags, par: Option<&Params>) -> Option<String> {
    beside_par(flags, par?.cohesion_file.as_deref()?)
}

/// `name`, a path written in the `.par` file, as a path from here: relative to the
/// `.par` file's folder.
fn beside_par(flags: &Flags, name: &str) -> Option<String> {
    let par_dir = std::path::Path::new(flags.par.as_deref()?).parent()?;
    Some(par_dir.join(name).to_string_lossy().into_owned())
}

/// The particle file to read: `--particles`, else (unless `--no-particles`) the `.par`
/// file's `achInFile`, taken relative to the `.par` file's folder; `None` for the
/// default particles or none.
pub fn particle_file(flags: &Flags, par: Option<&Params>) -> Option<String> {
    if flags.no_particles {
        return flags.particles.clone();
    }
    flags
        .particles
        .clone()
        .or_else(|| beside_par(flags, par?.in_file.as_deref()?))
}

/// The walls file to read: `file` (the command line's), else the `.par` file's
/// `achWallsFile`, taken relative to the `.par` file's folder; `None` when neither names
/// one.
pub fn walls_file(file: Option<&str>, flags: &Flags, par: Option<&Params>) -> Option<String> {
    file.map(str::to_string)
        .or_else(|| beside_par(flags, par?.walls_file.as_deref()?))
}

/// The run's settings from `flags`, then `par`, then the defaults for `scene` and the
/// `particles` read from the particle file (`None`: the default particles, or none with
/// `--no-particles`).
///
/// A default timestep is shortened so that a whole number of steps ends on the end
/// time ([`defaults::whole_steps`]); a given one is kept, and a run whose end time is
/// not a whole number of them ends after it (W108).
pub fn resolve(
    flags: &Flags,
    par: Option<&Params>,
    scene: &[Wall],
    particles: Option<Vec<Particle>>,
) -> Result<Run, ConfigError> {
    let (particles, embedded) = match particles {
        _ if flags.no_particles && flags.particles.is_none() => (Vec::new(), true),
        Some(ps) => (ps, false),
        None => (defaults::default_particles(scene), true),
    };
    // pkdgrav's `bDoGravity = 0`: no forces at all, uniform gravity included.
    let forces = par.and_then(|p| p.do_gravity).unwrap_or(true);
    let gravity = match (flags.gravity, par.and_then(|p| p.gravity)) {
        (None, _) if !forces => Vec3::zeros(),
        (Some(g), _) => g,
        (None, Some(g)) => g,
        (None, None) if embedded => Vec3::new(0.0, 0.0, -1.0),
        (None, None) => Vec3::zeros(),
    };
    let from_par = |f: fn(&Params) -> Option<f64>| par.and_then(f);
    let build = flags.build();
    let method = build.contact_model();
    let derived_k_n = || defaults::default_k_n(scene, &particles, &gravity);
    let k_n = flags
        .k_n
        .or(from_par(|p| p.k_n))
        .unwrap_or_else(derived_k_n);
    // A run from a `.par` file takes pkdgrav's defaults for what the file leaves out.
    let default = match par {
        Some(_) => pkdgrav_material(k_n),
        None => defaults::default_material(k_n),
    };
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
        beta_s: from_par(|p| p.beta_s).unwrap_or(default.beta_s),
    };
    let start_step = par.and_then(|p| p.start_step).unwrap_or(0);
    let last_step = match flags.t_end {
        Some(_) => None,
        None => par.and_then(|p| p.steps),
    };
    // The timestep's default needs a spring: with dKn = 0, the scene's.
    let dt_k_n = if k_n > 0.0 { k_n } else { derived_k_n() };
    let given_dt = flags.dt.or(from_par(|p| p.dt));
    let default_dt = |t_end: f64| match method {
        ContactModel::Ssdem => {
            defaults::default_soft_dt(scene, &particles, &gravity, dt_k_n, t_end)
        }
        ContactModel::Hsdem => defaults::default_hard_dt(scene, &particles, &gravity, t_end),
    };
    // A timestep of the run's own ends on the end time after a whole number of steps.
    let dt_for =
        |t_end: f64| given_dt.unwrap_or_else(|| defaults::whole_steps(default_dt(t_end), t_end));
    let (dt, t_end) = match (flags.t_end, last_step) {
        (Some(t_end), _) => (dt_for(t_end), t_end),
        (None, Some(last)) => {
            // pkdgrav's steps are counted; the time span follows from the timestep.
            let dt = given_dt.unwrap_or_else(|| {
                default_dt(defaults::default_duration(scene, &particles, &gravity))
            });
            (dt, last as f64 * dt)
        }
        (None, None) => {
            let t_end = defaults::default_duration(scene, &particles, &gravity);
            (dt_for(t_end), t_end)
        }
    };
    let cohesion = crate::contact::cohesion::Cohesion {
        model: par
            .and_then(|p| p.cohesion_model)
            .and_then(crate::contact::cohesion::Model::from_number)
            .unwrap_or_default(),
        coefficient: from_par(|p| p.cohesive_coeff).unwrap_or(0.0),
        colours: None,
    };
    let two_layer = par.and_then(|p| p.two_layer);
    let warnings = optional_key_warnings(par, &build, flags.integrator);
    let settings = Settings {
        build,
        cohesion,
        two_layer,
        gravity,
        particle_contacts: !flags.no_particle_contacts,
        edges: !flags.no_edges && par.and_then(|p| p.edge_detect).unwrap_or(true),
        contact_radius: par.and_then(|p| p.contact_radius).unwrap_or(false),
        legacy_roll: par.and_then(|p| p.legacy_roll).unwrap_or(false),
        forces,
        acc_crit: par.and_then(|p| p.acc_crit).unwrap_or(0.0),
        stepping: flags.stepping,
        integrator: flags.integrator,
        sliding: flags.sliding,
        planning: flags.planning,
        start_step,
        last_step,
        dt_given: given_dt.is_some(),
        ..Settings::new(dt, t_end, material)
    };
    let mut numbers = option_subnormals(flags);
    numbers.extend(par.iter().flat_map(|p| p.subnormals.iter().cloned()));
    let run = Run {
        particles,
        settings,
        warnings,
        numbers,
    };
    check(flags, par, &run, embedded)?;
    Ok(run)
}

/// The options given with a subnormal value (W701), in the order of `--help`.
fn option_subnormals(flags: &Flags) -> Vec<Warning> {
    let gravity = flags.gravity.map(|g| [g.x, g.y, g.z]).unwrap_or_default();
    let options = [
        ("--dt", flags.dt),
        ("--t-end", flags.t_end),
        ("--gravity", flags.gravity.map(|_| gravity[0])),
        ("--gravity", flags.gravity.map(|_| gravity[1])),
        ("--gravity", flags.gravity.map(|_| gravity[2])),
        ("--epsn", flags.eps_n),
        ("--epst", flags.eps_t),
        ("--k-n", flags.k_n),
        ("--k-t", flags.k_t),
        ("--mu-s", flags.mu_s),
        ("--mu-r", flags.mu_r),
        ("--mu-t", flags.mu_t),
    ];
    let mut warnings = Vec::new();
    for (option, value) in options {
        if let Some(x) = value {
            crate::io::subnormal(x, || option.to_string(), &mut warnings);
        }
    }
    warnings
}

/// Whether the run can be computed in doubles: a finite spring, a positive finite
/// timestep and end time, no more steps than `--max-steps` (else [`MAX_STEPS`]), and,
/// for each particle, a spring force, acceleration and change of speed in one step
/// (k_n·r, k_n·r/m, k_n·r/m·dt) and a gravitational energy that are finite. The
/// messages name where the value came from and what to give instead.
fn check(
    flags: &Flags,
    par: Option<&Params>,
    run: &Run,
    embedded: bool,
) -> Result<(), ConfigError> {
    let s = &run.settings;
    let m = &s.material;
    let fail = |why: String| Err(ConfigError::Unusable(why));
    if s.sliding == Sliding::Clamp {
        if s.method() == ContactModel::Hsdem {
            return fail(
                "--sliding clamp is a rule of the soft-sphere shear spring; hard spheres have none: leave it out, or run --method ssdem".to_string(),
            );
        }
        if s.integrator != Integrator::Pkdgrav {
            return fail(
                "--sliding clamp changes pkdgrav's contact law, which only --integrator pkdgrav runs (the comparison integrators' law resets the spring): leave one of them out".to_string(),
            );
        }
    }
    let k_from = if flags.k_n.is_some() {
        "--k-n"
    } else if par.is_some_and(|p| p.k_n.is_some()) {
        "the .par file's dKn"
    } else {
        "the default, derived from the particles' size and speed"
    };
    if !(m.k_n.is_finite() && m.k_t.is_finite()) {
        return fail(format!(
            "the spring constant k_n comes to {:e} ({k_from}), beyond what a double holds: give a smaller --k-n",
            m.k_n
        ));
    }
    let dt_from = if flags.dt.is_some() {
        "--dt"
    } else if par.is_some_and(|p| p.dt.is_some()) {
        "the .par file's dDelta"
    } else {
        "the default, from k_n and the particles' mass, size and speed"
    };
    if !(s.dt > 0.0 && s.dt.is_finite()) {
        return fail(format!(
            "the timestep comes to {:e} ({dt_from}, with k_n = {:e} from {k_from}): it must be a positive finite number; give --dt",
            s.dt, m.k_n
        ));
    }
    let t_end_from = if flags.t_end.is_some() {
        "--t-end"
    } else if s.last_step.is_some() {
        "the .par file's nSteps times the timestep"
    } else {
        "the default, from the scene"
    };
    if !(s.t_end.is_finite() && s.t_end >= 0.0) {
        return fail(format!(
            "the end time comes to {:e} ({t_end_from}): give --t-end",
            s.t_end
        ));
    }
    steps_fit(s, dt_from, t_end_from)?;
    let limit = flags.max_steps.unwrap_or(MAX_STEPS);
    let steps = s.end_step().saturating_sub(s.start_step);
    if steps > limit {
        return fail(format!(
            "the run would take {steps} steps of {:e} ({dt_from}) to t = {:e} ({t_end_from}), more than the limit of {limit}: give a longer --dt or a shorter --t-end, or raise the limit with --max-steps",
            s.dt, s.t_end
        ));
    }
    let g = s.gravity.norm();
    for (i, p) in run.particles.iter().enumerate() {
        let which = if embedded {
            format!("default particle {i} (sized to the scene)")
        } else {
            format!("particle {i}")
        };
        if embedded && let Err(says) = particles::check(p) {
            return fail(format!("{which}: {says}"));
        }
        let force = m.k_n * p.radius;
        let acc = force / p.mass;
        let kick = acc * s.dt;
        let potential = p.mass * g * p.pos.norm();
        if ![force, acc, kick, potential].iter().all(|x| x.is_finite()) {
            return fail(format!(
                "{which}: with k_n = {:e} ({k_from}), dt = {:e} and |g| = {g:e}, its contact force k_n·r = {force:e}, acceleration k_n·r/m = {acc:e}, change of speed in a step {kick:e} or gravitational energy {potential:e} is beyond what a double holds: check the values' scale (pkdgrav units)",
                m.k_n, s.dt
            ));
        }
    }
    Ok(())
}

/// Whether the run's steps can be counted: its step numbers, and a run of time's count
/// t_end/dt, at most [`EXACT_COUNT`] (2⁵³: the step numbers are `u64`s and a step's time
/// is `step · dt` in doubles, exact in the step up to there). A quotient that is not
/// finite (`--dt 1e-320`: 6/1e-320 is infinite) or beyond it is refused, naming where the
/// timestep and the end time came from, whatever `--max-steps` says.
fn steps_fit(s: &Settings, dt_from: &str, t_end_from: &str) -> Result<(), ConfigError> {
    let fail = |why: String| Err(ConfigError::Unusable(why));
    let beyond = format!(
        "more than the {EXACT_COUNT} steps a run can count exactly (2^53: its step numbers are whole numbers and a step's time is step·dt in doubles)"
    );
    for (key, step) in [("iStartStep", Some(s.start_step)), ("nSteps", s.last_step)] {
        if let Some(n) = step.filter(|&n| n > EXACT_COUNT) {
            return fail(format!(
                "the .par file's `{key}` is {n}, {beyond}: give at most {EXACT_COUNT}"
            ));
        }
    }
    let count = s.t_end / s.dt;
    let fits = count.is_finite() && count <= EXACT_COUNT as f64;
    if s.last_step.is_none() && !fits {
        let count = if count.is_finite() {
            format!("{count:e}")
        } else {
            "more than 1.8e308".to_string()
        };
        return fail(format!(
            "the run would take {count} steps of {:e} ({dt_from}) to t = {:e} ({t_end_from}), {beyond}: give a longer --dt or a shorter --t-end",
            s.dt, s.t_end
        ));
    }
    Ok(())
}

/// The `.par` keys of optional builds (cohesion, two-layer contacts) that a run with
/// `build` and `integrator` does not follow, each with its line.
fn optional_key_warnings(
    par: Option<&Params>,
    build: &Build,
    integrator: Integrator,
) -> Vec<par::ParWarning> {
    let Some(par) = par else {
        return Vec::new();
    };
    par.optional_keys
        .iter()
        .filter_map(|k| {
            let has = match k.option {
                "DEM_COHESION" => build.cohesion,
                _ => build.two_layers,
            };
            let what = if k.option == "DEM_COHESION" {
                "cohesion (docs/pkdgrav-physics.md §7)"
            } else {
                "two-layer contacts (docs/pkdgrav-physics.md §8)"
            };
            let message = if !has {
                format!(
                    "the build lacks {}, which {what} needs: the run ignores the key (add {} to --pkdgrav-build)",
                    k.option, k.option
                )
            } else if integrator != Integrator::Pkdgrav {
                format!(
                    "{what} is followed only with pkdgrav's contact law (--integrator pkdgrav, the default): the run ignores the key"
                )
            } else {
                return None;
            };
            Some(par::ParWarning {
                line: Some(k.line),
                key: k.key.to_string(),
                message,
            })
        })
        .collect()
}

/// pkdgrav's particle material (`master.c msrInitialize`) with the normal spring
/// `k_n`: ε_n = ε_t = 1, no friction of any kind, k_t = 2/7·k_n (`dKt = -1`).
pub fn pkdgrav_material(k_n: f64) -> ParticleMaterial {
    ParticleMaterial {
        eps_n: 1.0,
        eps_t: 1.0,
        k_n,
        k_t: par::KT_PER_KN * k_n,
        mu_s: 0.0,
        mu_r: 0.0,
        mu_t: 0.0,
        beta_s: walls_geometry::BETA_S_DEFAULT,
    }
}
