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
#[cfg(feature = "clap")]
use crate::{cli, io::par::Rule};
use nalgebra::Vector3;
use walls_geometry::Particle;
use walls_geometry::Wall;
use walls_keywords::number::EXACT_COUNT;

type Vec3 = Vector3<f64>;

/// What the command line gives: `None` (or `false`) where an option is absent. The
/// options of `walls-sim run` and `plan`, in three groups that derive `clap::Args` (the
/// `clap` feature), each flattened by the command where its options come in `--help`,
/// between the command's own (`--out`, `--fresh`, ...).
#[derive(Debug, Clone, Default)]
pub struct Flags {
    /// The inputs: the files, the contact model, the timestep and end time, gravity, the
    /// particles' material and which contacts count.
    pub inputs: Inputs,
    /// How the run steps: the walls' oscillation, the integrator, the sliding rule and
    /// the parts of the model it runs.
    pub stepping: Stepping,
    /// How many steps the run may take, and between outputs.
    pub counts: Counts,
}

/// The run's inputs (`--particles` to `--no-edges`); the doc comments are their help.
#[derive(Debug, Clone, Default)]
#[cfg_attr(feature = "clap", derive(clap::Args))]
pub struct Inputs {
    /// Particles: a CSV file (mass,radius,x,y,z,vx,vy,vz[,wx,wy,wz,color]) or a pkdgrav
    /// .ss file (by the extension .csv or .ss, else by the content); `-` reads standard
    /// input. Without it, nine particles are dropped inside the scene's container
    /// (or onto the scene when it has none).
    #[allow(
        rustdoc::broken_intra_doc_links,
        reason = "the brackets are --help's optional columns"
    )]
    #[cfg_attr(feature = "clap", arg(long, value_name = "FILE"))]
    pub particles: Option<String>,
    /// Run the walls alone, with no particles (instead of the nine dropped onto the
    /// scene, or the --par file's achInFile): oscillating walls move, reactive walls
    /// fall.
    #[cfg_attr(feature = "clap", arg(long, conflicts_with = "particles"))]
    pub no_particles: bool,
    /// A pkdgrav parameter file: timestep, steps, output interval, material, gravity,
    /// and the walls file (achWallsFile) and particle file (achInFile) when not given
    /// here. Keys the evaluator does not follow are warned about.
    #[cfg_attr(feature = "clap", arg(long, value_name = "FILE"))]
    pub par: Option<String>,
    /// The contact model (with --pkdgrav-build, the build's: DEM or not).
    #[cfg_attr(feature = "clap", arg(long, value_enum, default_value_t = ContactModel::Ssdem))]
    pub method: ContactModel,
    /// The pkdgrav build to follow: its compile options, space or comma separated
    /// (default pkdgrav's own, "DEM DEM_FIXED_BALL DEM_ROTATION_DASHPOT"; no DEM:
    /// hard-sphere walls). DEM_COHESION, DEM_TWOLAYERS, DEM_WALLS_REACT and AGGS turn
    /// on their physics.
    #[cfg_attr(feature = "clap", arg(long = "pkdgrav-build", value_name = "OPTIONS", value_parser = cli::build, conflicts_with = "method"))]
    pub build: Option<Build>,
    /// The timestep (default: π·√(m/(2k_n))/100 for the lightest particle, no more than
    /// lets anything move 2 % of the smallest radius, and shortened so that whole steps
    /// end on --t-end).
    #[cfg_attr(feature = "clap", arg(long, value_parser = cli::ruled(Rule::Positive)))]
    pub dt: Option<f64>,
    /// When to stop (default: three free falls over the scene; without particles, two
    /// oscillation periods).
    #[cfg_attr(feature = "clap", arg(long, value_parser = cli::ruled(Rule::Positive)))]
    pub t_end: Option<f64>,
    /// Uniform gravity.
    #[cfg_attr(feature = "clap", arg(long, num_args = 3, value_names = ["GX", "GY", "GZ"], allow_negative_numbers = true, value_parser = cli::ruled(Rule::Any)))]
    pub gravity: Option<Vec<f64>>,
    /// The particles' normal restitution (what walls' 99 means).
    #[cfg_attr(feature = "clap", arg(long = "epsn", value_name = "EPSN", value_parser = cli::ruled(Rule::Restitution)))]
    pub eps_n: Option<f64>,
    /// The particles' tangential restitution.
    #[cfg_attr(feature = "clap", arg(long = "epst", value_name = "EPST", value_parser = cli::ruled(Rule::Tangential)))]
    pub eps_t: Option<f64>,
    /// The particles' normal spring constant.
    #[cfg_attr(feature = "clap", arg(long = "k-n", value_parser = cli::ruled(Rule::Positive)))]
    pub k_n: Option<f64>,
    /// The particles' tangential spring constant (default 2/7 of k_n).
    #[cfg_attr(feature = "clap", arg(long = "k-t", value_parser = cli::ruled(Rule::NonNegative)))]
    pub k_t: Option<f64>,
    /// The particles' static friction.
    #[cfg_attr(feature = "clap", arg(long = "mu-s", value_parser = cli::ruled(Rule::NonNegative)))]
    pub mu_s: Option<f64>,
    /// The particles' rolling friction (SSDEM).
    #[cfg_attr(feature = "clap", arg(long = "mu-r", value_parser = cli::ruled(Rule::NonNegative)))]
    pub mu_r: Option<f64>,
    /// The particles' twisting friction (SSDEM).
    #[cfg_attr(feature = "clap", arg(long = "mu-t", value_parser = cli::ruled(Rule::NonNegative)))]
    pub mu_t: Option<f64>,
    /// Particles pass through each other (they still meet walls).
    #[cfg_attr(feature = "clap", arg(long))]
    pub no_particle_contacts: bool,
    /// HSDEM: only faces and cylinder sides count, not edges, corners and rims
    /// (pkdgrav's bWallsEdgeDetect = 0).
    // Absent, the `.par` file's bWallsEdgeDetect decides, else edges count.
    #[cfg_attr(feature = "clap", arg(long))]
    pub no_edges: bool,
}

impl Inputs {
    /// `--gravity` as a vector (its three numbers, x, y and z, as clap takes them); an
    /// error if it holds another count (only a caller that builds `Inputs` itself can
    /// give one).
    pub fn gravity(&self) -> Result<Option<Vec3>, ConfigError> {
        match self.gravity.as_deref() {
            None => Ok(None),
            Some(&[x, y, z]) => Ok(Some(Vec3::new(x, y, z))),
            Some(other) => Err(ConfigError::Unusable(format!(
                "--gravity takes three numbers (x, y, z), not {}",
                other.len()
            ))),
        }
    }
}

/// How the run steps (`--oscillation` to `--all-parts`); the doc comments are their help.
#[derive(Debug, Clone, Copy, Default)]
#[cfg_attr(feature = "clap", derive(clap::Args))]
pub struct Stepping {
    /// How oscillating walls move: step by step as pkdgrav does (the default), or on
    /// the exact sinusoid (for comparison; --integrator pkdgrav always steps SSDEM
    /// walls as pkdgrav does).
    #[cfg_attr(feature = "clap", arg(long, value_enum, default_value_t = OscillationStepping::Pkdgrav))]
    pub oscillation: OscillationStepping,
    /// SSDEM: the integrator: pkdgrav's own step and contact law (the default); or,
    /// for comparison, kick-drift-kick leapfrog with the summary's contact law, the same
    /// with the dashpot velocity predicted to the step's end, or explicit Euler.
    #[cfg_attr(feature = "clap", arg(long, value_enum, default_value_t = Integrator::Pkdgrav))]
    pub integrator: Integrator,
    /// SSDEM with --integrator pkdgrav: what the shear spring of a sliding contact does:
    /// pkdgrav's reset (the default), or the Coulomb clamp of LAMMPS and LIGGGHTS (a
    /// sliding contact's friction is exactly μ_s·N). Not a .par key: pkdgrav has none.
    #[cfg_attr(feature = "clap", arg(long, value_enum, default_value_t = Sliding::Reset))]
    pub sliding: Sliding,
    /// Run every part of the model, whatever the scene needs (for comparison; see
    /// `walls-sim plan`).
    #[cfg_attr(feature = "clap", arg(long = "all-parts", action = clap::ArgAction::SetTrue, value_parser = cli::all_parts()))]
    pub planning: Planning,
}

/// How many steps the run may take, and between outputs (`--max-steps`, `--every`); the
/// doc comments are their help.
#[derive(Debug, Clone, Copy)]
#[cfg_attr(feature = "clap", derive(clap::Args))]
pub struct Counts {
    /// The most steps the run may take: a run that would take more is refused before it
    /// starts (a mistyped --dt or --t-end), saying how many it needs.
    #[cfg_attr(feature = "clap", arg(long, value_name = "N", default_value_t = MAX_STEPS))]
    pub max_steps: u64,
    /// Steps between trajectory rows (default: the --par file's iOutInterval, else 100).
    #[cfg_attr(feature = "clap", arg(long, value_name = "N", value_parser = clap::value_parser!(u64).range(1..)))]
    pub every: Option<u64>,
}

impl Default for Counts {
    /// At most [`MAX_STEPS`]; outputs as the `.par` file says, else every [`EVERY`].
    fn default() -> Self {
        Counts {
            max_steps: MAX_STEPS,
            every: None,
        }
    }
}

impl Flags {
    /// The pkdgrav build the run follows: `--pkdgrav-build`, else pkdgrav's default build
    /// with `DEM` as `--method` says. Its [`Build::contact_model`] is the run's contact
    /// model, the mode its walls file is checked in.
    pub fn build(&self) -> Build {
        let given = &self.inputs;
        given
            .build
            .clone()
            .unwrap_or_else(|| Build::default_for(given.method))
    }

    /// Where [`Flags::build`] came from, as `walls-sim plan` says it.
    pub fn build_origin(&self) -> &'static str {
        match (&self.inputs.build, self.inputs.method) {
            (Some(_), _) => "as --pkdgrav-build gives it",
            (None, ContactModel::Ssdem) => "pkdgrav's default build; --pkdgrav-build names another",
            (None, ContactModel::Hsdem) => {
                "pkdgrav's default build without DEM, as --method hsdem; --pkdgrav-build names another"
            }
        }
    }
}

/// pkdgrav's overlap levels as the `.par` file sets them (`dMinorFrac`, `dMajorFrac`,
/// `dErrorFrac`), its defaults for those it leaves out.
fn overlap_levels(par: Option<&Params>) -> crate::run::OverlapLevels {
    let given = par.map_or([None; 3], |p| p.overlap_fracs);
    let default = crate::run::OverlapLevels::default();
    crate::run::OverlapLevels {
        minor: given[0].unwrap_or(default.minor),
        major: given[1].unwrap_or(default.major),
        error: given[2].unwrap_or(default.error),
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
    /// The `.par` file's `iRedOutInterval` when above 0: pkdgrav's reduced outputs, at the
    /// start step and every so many steps after it, where it writes its reactive-wall
    /// lines (docs/pkdgrav-physics.md §10); `None`: those lines come at the output steps.
    pub reduced: Option<u64>,
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
        every: flags
            .counts
            .every
            .or_else(|| par?.out_interval)
            .unwrap_or(EVERY),
        reduced: par.and_then(|p| p.red_out_interval).filter(|&n| n > 0),
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

/// A run's particles and settings: the particles as [`Particle`]s, or as the states a
/// run starts from ([`load_as`]).
#[derive(Debug, Clone, PartialEq)]
pub struct Run<P = Particle> {
    /// The particles.
    pub particles: Vec<P>,
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

/// The `.par` keys the command line `inputs` sets over the file's (its values win,
/// [`resolve`]): the file's word on them is not judged.
fn overridden(inputs: &Inputs) -> Vec<&'static str> {
    let set = |given: bool, keys: &[&'static str]| if given { keys.to_vec() } else { Vec::new() };
    [
        set(
            inputs.particles.is_some() || inputs.no_particles,
            &["achInFile"],
        ),
        set(inputs.dt.is_some(), &["dDelta"]),
        set(inputs.t_end.is_some(), &["nSteps"]),
        set(
            inputs.gravity.is_some(),
            &["dxUnifGrav", "dyUnifGrav", "dzUnifGrav"],
        ),
        set(inputs.eps_n.is_some(), &["dEpsN"]),
        set(inputs.eps_t.is_some(), &["dEpsT"]),
        set(inputs.k_n.is_some(), &["dKn"]),
        set(inputs.k_t.is_some(), &["dKt"]),
        set(inputs.mu_s.is_some(), &["dMuS"]),
        set(inputs.mu_r.is_some(), &["dMuR"]),
        set(inputs.mu_t.is_some(), &["dMuT"]),
    ]
    .concat()
}

/// Reads the `.par` file that `flags` name, if any, refused where the run's pkdgrav build
/// would refuse it ([`par::read_file_for`]).
pub fn read_par(flags: &Flags) -> Result<Option<Params>, ConfigError> {
    let Some(path) = flags.inputs.par.as_deref() else {
        return Ok(None);
    };
    let build = walls_par::Build::parse(&flags.build().names())
        .expect("the evaluator's options are pkdgrav's");
    Ok(Some(par::read_file_for(
        path,
        &build,
        &overridden(&flags.inputs),
    )?))
}

/// Reads the particle file that `flags` and `par` (read by [`read_par`]) name, and
/// settles the run's settings against `scene`.
pub fn load(flags: &Flags, par: Option<&Params>, scene: &[Wall]) -> Result<Run, ConfigError> {
    load_as(flags, par, scene)
}

/// [`load`], each particle made a `P` as it is read: `walls-sim run` reads them straight
/// into the [`crate::run::State`]s its run starts from
/// ([`crate::io::particles::read_file_as`]).
pub fn load_as<P: AsRef<Particle> + From<Particle>>(
    flags: &Flags,
    par: Option<&Params>,
    scene: &[Wall],
) -> Result<Run<P>, ConfigError> {
    let read = match particle_file(flags, par) {
        Some(f) => Some(particles::read_file_as(&f)?),
        None => None,
    };
    let (particles, numbers) = match read {
        Some(read) => (Some(read.particles), read.warnings),
        None => (None, Vec::new()),
    };
    let mut run = resolve_as(flags, par, scene, particles)?;
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
    beside_par(flags, par?.cohesion.file.as_deref()?)
}

/// `name`, a path written in the `.par` file, as a path from here: relative to the
/// `.par` file's folder.
fn beside_par(flags: &Flags, name: &str) -> Option<String> {
    let par_dir = std::path::Path::new(flags.inputs.par.as_deref()?).parent()?;
    Some(par_dir.join(name).to_string_lossy().into_owned())
}

/// The particle file to read: `--particles`, else (unless `--no-particles`) the `.par`
/// file's `achInFile`, taken relative to the `.par` file's folder; `None` for the
/// default particles or none.
pub fn particle_file(flags: &Flags, par: Option<&Params>) -> Option<String> {
    if flags.inputs.no_particles {
        return flags.inputs.particles.clone();
    }
    flags
        .inputs
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
    resolve_as(flags, par, scene, particles)
}

/// [`resolve`] for particles held as `P`s ([`load_as`]).
pub fn resolve_as<P: AsRef<Particle> + From<Particle>>(
    flags: &Flags,
    par: Option<&Params>,
    scene: &[Wall],
    particles: Option<Vec<P>>,
) -> Result<Run<P>, ConfigError> {
    let given = &flags.inputs;
    let (particles, embedded) = match particles {
        _ if given.no_particles && given.particles.is_none() => (Vec::new(), true),
        Some(ps) => (ps, false),
        None => {
            let embedded = defaults::default_particles(scene);
            (embedded.into_iter().map(P::from).collect(), true)
        }
    };
    // pkdgrav's `bDoGravity = 0`: no forces at all, uniform gravity included.
    let forces = par.and_then(|p| p.do_gravity).unwrap_or(true);
    let gravity = match (given.gravity()?, par.and_then(|p| p.gravity)) {
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
    let k_n = given
        .k_n
        .or(from_par(|p| p.k_n))
        .unwrap_or_else(derived_k_n);
    // A run from a `.par` file takes pkdgrav's defaults for what the file leaves out.
    let default = match par {
        Some(_) => pkdgrav_material(k_n),
        None => defaults::default_material(k_n),
    };
    let material = ParticleMaterial {
        eps_n: given
            .eps_n
            .or(from_par(|p| p.eps_n))
            .unwrap_or(default.eps_n),
        eps_t: given
            .eps_t
            .or(from_par(|p| p.eps_t))
            .unwrap_or(default.eps_t),
        k_n,
        k_t: given.k_t.or(from_par(|p| p.k_t)).unwrap_or(default.k_t),
        mu_s: given.mu_s.or(from_par(|p| p.mu_s)).unwrap_or(default.mu_s),
        mu_r: given.mu_r.or(from_par(|p| p.mu_r)).unwrap_or(default.mu_r),
        mu_t: given.mu_t.or(from_par(|p| p.mu_t)).unwrap_or(default.mu_t),
        beta_s: from_par(|p| p.beta_s).unwrap_or(default.beta_s),
    };
    let start_step = par.and_then(|p| p.start_step).unwrap_or(0);
    let last_step = match given.t_end {
        Some(_) => None,
        None => par.and_then(|p| p.steps),
    };
    // The timestep's default needs a spring: with dKn = 0, the scene's.
    let dt_k_n = if k_n > 0.0 { k_n } else { derived_k_n() };
    let given_dt = given.dt.or(from_par(|p| p.dt));
    let default_dt = |t_end: f64| match method {
        ContactModel::Ssdem => {
            defaults::default_soft_dt(scene, &particles, &gravity, dt_k_n, t_end)
        }
        ContactModel::Hsdem => defaults::default_hard_dt(scene, &particles, &gravity, t_end),
    };
    // A timestep of the run's own ends on the end time after a whole number of steps.
    let dt_for =
        |t_end: f64| given_dt.unwrap_or_else(|| defaults::whole_steps(default_dt(t_end), t_end));
    let (dt, t_end) = match (given.t_end, last_step) {
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
            .and_then(|p| p.cohesion.model)
            .and_then(crate::contact::cohesion::Model::from_number)
            .unwrap_or_default(),
        coefficient: from_par(|p| p.cohesion.coefficient).unwrap_or(0.0),
        colours: None,
    };
    let two_layer = par.and_then(|p| p.two_layer);
    let warnings = optional_key_warnings(par, &build, flags.stepping.integrator);
    let settings = Settings {
        build,
        cohesion,
        two_layer,
        gravity,
        particle_contacts: !given.no_particle_contacts,
        edges: !given.no_edges && par.and_then(|p| p.edge_detect).unwrap_or(true),
        contact_radius: par.and_then(|p| p.contact_radius).unwrap_or(false),
        legacy_roll: par.and_then(|p| p.legacy_roll).unwrap_or(false),
        forces,
        acc_crit: par.and_then(|p| p.acc_crit).unwrap_or(0.0),
        overlap_levels: overlap_levels(par),
        stepping: flags.stepping.oscillation,
        integrator: flags.stepping.integrator,
        sliding: flags.stepping.sliding,
        planning: flags.stepping.planning,
        start_step,
        last_step,
        dt_given: given_dt.is_some(),
        ..Settings::new(dt, t_end, material)
    };
    let mut numbers = option_subnormals(given);
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
fn option_subnormals(given: &Inputs) -> Vec<Warning> {
    let gravity = given
        .gravity
        .iter()
        .flatten()
        .map(|&g| ("--gravity", Some(g)));
    let options = [("--dt", given.dt), ("--t-end", given.t_end)]
        .into_iter()
        .chain(gravity)
        .chain([
            ("--epsn", given.eps_n),
            ("--epst", given.eps_t),
            ("--k-n", given.k_n),
            ("--k-t", given.k_t),
            ("--mu-s", given.mu_s),
            ("--mu-r", given.mu_r),
            ("--mu-t", given.mu_t),
        ]);
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
    run: &Run<impl AsRef<Particle>>,
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
    let k_from = if flags.inputs.k_n.is_some() {
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
    let dt_from = if flags.inputs.dt.is_some() {
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
    let t_end_from = if flags.inputs.t_end.is_some() {
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
    let limit = flags.counts.max_steps;
    let steps = s.end_step().saturating_sub(s.start_step);
    if steps > limit {
        return fail(format!(
            "the run would take {steps} steps of {:e} ({dt_from}) to t = {:e} ({t_end_from}), more than the limit of {limit}: give a longer --dt or a shorter --t-end, or raise the limit with --max-steps",
            s.dt, s.t_end
        ));
    }
    let g = s.gravity.norm();
    for (i, p) in run.particles.iter().map(AsRef::as_ref).enumerate() {
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
