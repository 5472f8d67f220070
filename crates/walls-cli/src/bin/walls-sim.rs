//! `walls-sim`: evaluate a walls file. `walls-sim scene FILE [--time T]` prints the
//! resolved scene as JSON (SPEC §2); `walls-sim run` runs particles against it;
//! `walls-sim advise` suggests dKn, dKt and dDelta for the real pkdgrav run.
//!
//! Diagnostics go to standard error. A file with errors still gives the scene resolved
//! from what parsed, with exit status 1; exit status 2 is a usage or I/O error.

use clap::{Parser, Subcommand};

/// mimalloc, as in walls-lint: large files cost a few hundred page faults, not thousands.
#[global_allocator]
static GLOBAL: mimalloc::MiMalloc = mimalloc::MiMalloc;
use std::io::{IsTerminal, Write};
use std::process::ExitCode;
use walls_cli::{ModeArg, check_bytes, input};
use walls_diagnostics::Severity;
use walls_diagnostics::render::{self, FileReport};
use walls_model::Options;
use walls_sim::input::Rule;

#[derive(Parser)]
#[command(
    name = "walls-sim",
    version,
    about = "Evaluate pkdgrav walls files: the resolved scene, wall motion, runs, and advice for pkdgrav's k_n and timestep.",
    after_help = "Exit status: 0 success, 1 the file has errors (the output is what could be resolved), 2 usage or I/O error."
)]
struct Args {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Run particles against the walls (SSDEM or HSDEM) and report where they end up,
    /// what happened at walls, the energy and pkdgrav's warnings.
    Run(Box<RunArgs>),
    /// List the parts of the model a run would use (moving walls, spin, friction terms,
    /// edges, particle contacts, reactive walls, sticky and death walls, gravity), with
    /// the reason for each; takes the same options as `run`.
    Plan(Box<RunArgs>),
    /// Suggest the spring constants and timestep (dKn, dKt, dDelta) for the real
    /// pkdgrav run from the particles' size, mass and speed, and print the .par lines.
    Advise(Box<AdviseArgs>),
    /// Draw the walls (and particles) at a time, or their motion over a span: SVG
    /// (the default), POV-Ray, VTK or an interactive HTML page.
    Preview(Box<PreviewArgs>),
    /// Print the resolved scene as JSON: every wall with the effective value of every
    /// token, in pkdgrav units.
    Scene {
        /// The walls file; `-` reads standard input.
        #[arg(value_name = "FILE")]
        file: String,
        /// Also give each wall's `position` at this time (pkdgrav units).
        #[arg(long, value_name = "T", allow_negative_numbers = true, value_parser = ruled(Rule::Any))]
        time: Option<f64>,
        /// The contact model the file is for (it decides which values are errors).
        #[arg(long, value_enum, default_value_t = ModeArg::Ssdem)]
        mode: ModeArg,
    },
}

/// `walls-sim run`: the SPEC §2 command line.
#[derive(clap::Args)]
struct RunArgs {
    /// The walls file.
    #[arg(value_name = "FILE")]
    file: String,
    /// Particles: a CSV file (mass,radius,x,y,z,vx,vy,vz[,wx,wy,wz,color]) or a pkdgrav
    /// .ss file. Without it, nine particles are dropped onto the scene.
    #[arg(long, value_name = "FILE")]
    particles: Option<String>,
    /// A pkdgrav parameter file: timestep, steps, material, gravity, and the particle
    /// file (achInFile) when --particles is not given.
    #[arg(long, value_name = "FILE")]
    par: Option<String>,
    /// The contact model.
    #[arg(long, value_enum, default_value_t = ModeArg::Ssdem)]
    method: ModeArg,
    /// The timestep (default: π·√(m/(2k_n))/100 for the lightest particle).
    #[arg(long, value_parser = ruled(Rule::Positive))]
    dt: Option<f64>,
    /// When to stop (default: three free falls over the scene).
    #[arg(long, value_parser = ruled(Rule::Positive))]
    t_end: Option<f64>,
    /// Uniform gravity.
    #[arg(long, num_args = 3, value_names = ["GX", "GY", "GZ"], allow_negative_numbers = true, value_parser = ruled(Rule::Any))]
    gravity: Option<Vec<f64>>,
    /// The particles' normal restitution (what walls' 99 means).
    #[arg(long, value_parser = ruled(Rule::Restitution))]
    epsn: Option<f64>,
    /// The particles' tangential restitution.
    #[arg(long, value_parser = ruled(Rule::Tangential))]
    epst: Option<f64>,
    /// The particles' normal spring constant.
    #[arg(long = "k-n", value_parser = ruled(Rule::Positive))]
    k_n: Option<f64>,
    /// The particles' tangential spring constant (default 2/7 of k_n).
    #[arg(long = "k-t", value_parser = ruled(Rule::NonNegative))]
    k_t: Option<f64>,
    /// The particles' static friction.
    #[arg(long = "mu-s", value_parser = ruled(Rule::NonNegative))]
    mu_s: Option<f64>,
    /// The particles' rolling friction (SSDEM).
    #[arg(long = "mu-r", value_parser = ruled(Rule::NonNegative))]
    mu_r: Option<f64>,
    /// The particles' twisting friction (SSDEM).
    #[arg(long = "mu-t", value_parser = ruled(Rule::NonNegative))]
    mu_t: Option<f64>,
    /// Particles pass through each other (they still meet walls).
    #[arg(long)]
    no_particle_contacts: bool,
    /// HSDEM: only faces and cylinder sides count, not edges, corners and rims
    /// (pkdgrav's bWallsEdgeDetect = 0).
    #[arg(long)]
    no_edges: bool,
    /// Write the trajectory to DIR: particles.csv and walls.csv, at step 0 and every
    /// --every steps.
    #[arg(long, value_name = "DIR")]
    out: Option<std::path::PathBuf>,
    /// How oscillating walls move: on the exact sinusoid, or step by step at the
    /// oscillation velocity of each step's start, as pkdgrav does.
    #[arg(long, value_enum, default_value_t = Oscillation::Exact)]
    oscillation: Oscillation,
    /// SSDEM: the integrator: kick-drift-kick leapfrog; the same with pkdgrav's dashpot
    /// velocity predicted to the step's end; or explicit Euler (for comparison).
    #[arg(long, value_enum, default_value_t = IntegratorArg::Leapfrog)]
    integrator: IntegratorArg,
    /// Run every part of the model, whatever the scene needs (for comparison; see
    /// `walls-sim plan`).
    #[arg(long)]
    all_parts: bool,
    /// Empty pkdgrav's WALLSREACTdata.out and WALLSREACTviz.out in --out first, rather
    /// than appending to them as pkdgrav does.
    #[arg(long)]
    fresh: bool,
    /// Steps between trajectory rows.
    #[arg(long, value_name = "N", default_value_t = 100, value_parser = clap::value_parser!(u64).range(1..))]
    every: u64,
    /// Print the result as JSON on standard output.
    #[arg(long)]
    json: bool,
}

/// The SSDEM integrator.
#[derive(Clone, Copy, clap::ValueEnum)]
enum IntegratorArg {
    /// Kick-drift-kick leapfrog.
    Leapfrog,
    /// Kick-drift-kick with the dashpot at the velocity predicted to the step's end.
    Pkdgrav,
    /// Explicit Euler.
    Euler,
}

/// `walls-sim advise`: physical inputs in, pkdgrav parameters out (docs/evaluator.md,
/// "Advice for the real run").
#[derive(clap::Args)]
#[command(
    group(clap::ArgGroup::new("amount").required(true).args(["mass", "density"])),
    after_help = "k_n is the larger of m·(v/x)² (the fastest impact stops within the overlap x) and φ·ρ·g·H·s²/x (the pile's bottom bears its weight within x); k_t = 2/7·k_n; dDelta = π·√(m/(2k_n))/N. Values are SI unless --units pkdgrav; the output gives both."
)]
struct AdviseArgs {
    /// The typical (most energetic) particle's mass: kg, or M_sun with --units pkdgrav.
    #[arg(long, value_name = "M", value_parser = ruled(Rule::Positive))]
    mass: Option<f64>,
    /// Or its density: kg/m^3, or M_sun/AU^3.
    #[arg(long, value_name = "RHO", value_parser = ruled(Rule::Positive))]
    density: Option<f64>,
    /// The typical particle's radius: m, or AU.
    #[arg(long, value_name = "S", value_parser = ruled(Rule::Positive))]
    radius: f64,
    /// The maximum expected speed, of a particle at a wall or of two particles towards
    /// each other: m/s, or AU/(yr/2pi).
    #[arg(long, value_name = "V", value_parser = ruled(Rule::Positive))]
    speed: f64,
    /// The allowed overlap, as a fraction of the radius (pkdgrav warns at 0.03 and 0.15).
    #[arg(long, value_name = "FRACTION", default_value_t = walls_sim::advise::DEFAULT_OVERLAP, value_parser = ruled(Rule::Overlap))]
    overlap: f64,
    /// Gravity (uniform, or at the surface), for the static criterion with --height:
    /// m/s^2, or AU/(yr/2pi)^2.
    #[arg(long, value_name = "G", requires = "height", value_parser = ruled(Rule::Positive))]
    gravity: Option<f64>,
    /// The pile's height (or the body's radius), for the static criterion: m, or AU.
    #[arg(long, value_name = "H", requires = "gravity", value_parser = ruled(Rule::Positive))]
    height: Option<f64>,
    /// The pile's packing fraction (static criterion).
    #[arg(long, value_name = "PHI", default_value_t = walls_sim::advise::DEFAULT_PACKING, value_parser = ruled(Rule::Fraction))]
    packing: f64,
    /// Steps per contact (pkdgrav's demparams uses 30; 50 for a closer restitution).
    #[arg(long, value_name = "N", default_value_t = walls_sim::advise::DEFAULT_STEPS_PER_CONTACT, value_parser = ruled(Rule::Positive))]
    steps_per_contact: f64,
    /// The shortest contact the timestep must resolve: between particles (reduced mass
    /// m/2), or only against walls (m, √2 longer).
    #[arg(long, value_enum, default_value_t = ContactArg::Pair)]
    contact: ContactArg,
    /// The walls file, for an achWallsFile line.
    #[arg(long, value_name = "FILE", value_parser = par_name)]
    walls: Option<String>,
    /// The units of the inputs.
    #[arg(long, value_enum, default_value_t = UnitsArg::Si)]
    units: UnitsArg,
    /// Print the advice as JSON on standard output.
    #[arg(long)]
    json: bool,
}

/// The shortest contact of a run.
#[derive(Clone, Copy, clap::ValueEnum)]
enum ContactArg {
    /// Particles touch each other (and walls).
    Pair,
    /// Particles touch only walls.
    Wall,
}

/// The units of `advise`'s inputs.
#[derive(Clone, Copy, clap::ValueEnum)]
enum UnitsArg {
    /// kg, m, s.
    Si,
    /// pkdgrav's: M_sun, AU, yr/2pi (G = 1).
    Pkdgrav,
}

/// How oscillating walls advance in a run.
#[derive(Clone, Copy, clap::ValueEnum)]
enum Oscillation {
    /// The exact sinusoid of SPEC §1 at every step.
    Exact,
    /// pkdgrav's steps: each moves by the oscillation velocity at its start times dt.
    Pkdgrav,
}

fn main() -> ExitCode {
    let args = Args::parse();
    match args.command {
        Command::Scene { file, time, mode } => scene(&file, time, mode),
        Command::Run(run) => simulate(&run),
        Command::Plan(run) => plan(&run),
        Command::Preview(args) => preview(&args),
        Command::Advise(args) => advise(&args),
    }
}

fn plan(args: &RunArgs) -> ExitCode {
    let prepared = match prepare(args) {
        Ok(p) => p,
        Err(e) => {
            eprintln!("walls-sim: error: {e}");
            return ExitCode::from(2);
        }
    };
    let (_, parts) =
        walls_sim::plan::parts(&prepared.walls, &prepared.particles, &prepared.settings);
    if args.json {
        let list: Vec<_> = parts
            .iter()
            .map(|p| serde_json::json!({"part": p.name, "used": p.used, "reason": p.reason}))
            .collect();
        println!("{}", serde_json::json!({ "plan": list }));
    } else {
        for p in &parts {
            let mark = if p.used { "uses" } else { "skips" };
            println!("{mark:5} {}: {}", p.name, p.reason);
        }
    }
    if prepared.errors > 0 {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    }
}

/// A file name pkdgrav's parameter reader reads back as written.
fn par_name(s: &str) -> Result<String, String> {
    walls_sim::advise::par_string(s)
        .map(str::to_string)
        .map_err(|why| format!("pkdgrav cannot read that name: {why}"))
}

fn advise(args: &AdviseArgs) -> ExitCode {
    use walls_sim::advise::{self, Amount, Column, Contact, Inputs, UnitSystem};
    let inputs = Inputs {
        units: match args.units {
            UnitsArg::Si => UnitSystem::Si,
            UnitsArg::Pkdgrav => UnitSystem::Pkdgrav,
        },
        amount: match (args.mass, args.density) {
            (Some(m), _) => Amount::Mass(m),
            (None, Some(rho)) => Amount::Density(rho),
            (None, None) => unreachable!("clap requires --mass or --density"),
        },
        radius: args.radius,
        speed: args.speed,
        overlap: args.overlap,
        column: match (args.gravity, args.height) {
            (Some(gravity), Some(height)) => Some(Column {
                gravity,
                height,
                packing: args.packing,
            }),
            _ => None,
        },
        steps_per_contact: args.steps_per_contact,
        contact: match args.contact {
            ContactArg::Pair => Contact::Pair,
            ContactArg::Wall => Contact::Wall,
        },
    };
    let advice = match advise::advise(&inputs) {
        Ok(a) => a,
        Err(e) => {
            eprintln!("walls-sim: error: --{e}");
            return ExitCode::from(2);
        }
    };
    let text = if args.json {
        advice_json(&advice, args)
    } else {
        advice_text(&advice, args)
    };
    let mut out = std::io::stdout().lock();
    if let Err(e) = out.write_all(text.as_bytes()).and_then(|()| out.flush()) {
        if e.kind() != std::io::ErrorKind::BrokenPipe {
            eprintln!("walls-sim: error: cannot write output: {e}");
        }
        return ExitCode::from(2);
    }
    if !args.json {
        for w in &advice.warnings {
            eprintln!("walls-sim: warning: {w}");
        }
    }
    ExitCode::SUCCESS
}

/// The advice for people: inputs, derivation, units, then the .par lines.
fn advice_text(a: &walls_sim::advise::Advice, args: &AdviseArgs) -> String {
    use std::fmt::Write as _;
    use walls_sim::advise::{Contact, Criterion, Dimension, Quantity, significant as g};
    let si = |q: &Quantity| format!("{} {}", g(q.si, 6), q.dimension.si_unit());
    let pkd = |q: &Quantity| format!("{} {}", g(q.pkdgrav, 6), q.dimension.pkdgrav_unit());
    let mut o = String::new();
    let row = |o: &mut String, name: &str, q: &Quantity, note: &str| {
        let line = format!("  {name:<22}{:<24}{:<30}{note}", si(q), pkd(q));
        let _ = writeln!(o, "{}", line.trim_end());
    };
    let given = match args.units {
        UnitsArg::Si => "given in SI",
        UnitsArg::Pkdgrav => "given in pkdgrav units",
    };
    let _ = writeln!(o, "Inputs ({given})\n  {:<22}{:<24}pkdgrav units", "", "SI");
    let (mass_note, density_note) = if args.mass.is_some() {
        ("", "derived: m/(4/3·π·s³)")
    } else {
        ("derived: 4/3·π·s³·ρ", "")
    };
    row(&mut o, "mass m", &a.mass, mass_note);
    row(&mut o, "radius s", &a.radius, "");
    row(&mut o, "density ρ", &a.density, density_note);
    row(&mut o, "maximum speed v", &a.speed, "");
    row(
        &mut o,
        "allowed overlap x",
        &a.max_overlap,
        &format!("{} % of s", g(100.0 * a.overlap_fraction, 6)),
    );
    if let Some(c) = &a.column {
        row(&mut o, "gravity g", &c.gravity, "");
        row(&mut o, "pile height H", &c.height, "");
        let _ = writeln!(o, "  {:<22}{}", "packing φ", g(c.packing, 6));
    }
    let _ = writeln!(
        o,
        "  {:<22}{}",
        "steps per contact N",
        g(a.steps_per_contact, 6)
    );
    let _ = writeln!(o, "\nDerivation");
    let eq = |o: &mut String, what: &str, formula: &str, q: &Quantity| {
        let _ = writeln!(o, "  {what:<24}{formula:<18}= {}", si(q));
    };
    eq(&mut o, "kinetic k_n", "m·(v/x)²", &a.k_n_kinetic);
    match &a.column {
        Some(c) => eq(&mut o, "static k_n", "φ·ρ·g·H·s²/x", &c.k_n),
        None => {
            let _ = writeln!(
                o,
                "  {:<24}(no --gravity and --height: not estimated)",
                "static k_n"
            );
        }
    }
    let _ = writeln!(
        o,
        "  → k_n = {}: the {} criterion governs (the larger)",
        si(&a.k_n),
        match a.governs {
            Criterion::Kinetic => "kinetic",
            Criterion::Static => "static",
        }
    );
    eq(&mut o, "k_t", "2/7·k_n", &a.k_t);
    eq(
        &mut o,
        "contact, pair (μ = m/2)",
        "π·√(m/(2k_n))",
        &a.contact_time_pair,
    );
    eq(
        &mut o,
        "contact, wall (μ = m)",
        "π·√(m/k_n)",
        &a.contact_time_wall,
    );
    let resolved = match a.contact {
        Contact::Pair => "pair",
        Contact::Wall => "wall",
    };
    let _ = writeln!(
        o,
        "  {:<24}{:<18}= {} ({} steps per wall contact)",
        "dt",
        format!("{resolved} contact/{}", g(a.steps_per_contact, 6)),
        si(&a.dt),
        g(a.steps_per_wall_contact, 4)
    );
    let percent = |q: &Quantity| g(100.0 * q.si / a.radius.si, 4);
    let _ = writeln!(
        o,
        "  peak overlap at v: {} against a wall ({} % of s), {} between two particles ({} %)",
        si(&a.peak_overlap_wall),
        percent(&a.peak_overlap_wall),
        si(&a.peak_overlap_pair),
        percent(&a.peak_overlap_pair),
    );
    if let Some(c) = &a.column {
        let _ = writeln!(
            o,
            "  at rest at the pile's bottom: {} ({} % of s); a fall over H reaches √(2gH) = {}",
            si(&c.overlap),
            percent(&c.overlap),
            si(&c.free_fall_speed),
        );
    }
    let u = &a.units;
    let _ = writeln!(
        o,
        "\nUnits: pkdgrav's are the AU, the solar mass and the time in which G = 1\n  1 AU = {} m (IAU 2012); 1 M_sun = {} kg (IAU 2015 GM_sun / G)\n  1 yr/2pi = √(AU³/(G·M_sun)) = {} s, with G = {} m^3/(kg s^2) (CODATA 2014)\n  k_n: 1 M_sun/(yr/2pi)^2 = {} kg/s^2; dt: 1 yr/2pi = {} s\n  a walls file in SI units: lengthunit {}  massunit {}  timeunit {}",
        g(u.length, 10),
        g(u.mass, 6),
        g(u.time, 6),
        g(walls_sim::advise::G_SI, 6),
        g(u.factor(Dimension::Stiffness), 6),
        g(u.time, 6),
        g(1.0 / u.length, 6),
        g(1.0 / u.mass, 6),
        g(1.0 / u.time, 6),
    );
    let _ = writeln!(o, "\n# pkdgrav parameters: paste into the .par file");
    for line in a.par_lines(args.walls.as_deref()) {
        let _ = writeln!(o, "{line}");
    }
    o
}

/// The advice as JSON: every quantity as {si, pkdgrav, si_unit, pkdgrav_unit}.
fn advice_json(a: &walls_sim::advise::Advice, args: &AdviseArgs) -> String {
    use serde_json::{Value, json};
    use walls_sim::advise::{Contact, Criterion, Quantity};
    let q = |q: &Quantity| {
        json!({
            "si": q.si,
            "pkdgrav": q.pkdgrav,
            "si_unit": q.dimension.si_unit(),
            "pkdgrav_unit": q.dimension.pkdgrav_unit(),
        })
    };
    let column = a.column.as_ref();
    let u = &a.units;
    let mut par = json!({
        "dKn": a.k_n.pkdgrav,
        "dKt": a.k_t.pkdgrav,
        "dDelta": a.dt.pkdgrav,
    });
    if let (Some(file), Value::Object(map)) = (&args.walls, &mut par) {
        map.insert("achWallsFile".into(), json!(file));
    }
    let value = json!({
        "inputs": {
            "units": match args.units { UnitsArg::Si => "si", UnitsArg::Pkdgrav => "pkdgrav" },
            "mass": q(&a.mass),
            "radius": q(&a.radius),
            "density": q(&a.density),
            "speed": q(&a.speed),
            "overlap": a.overlap_fraction,
            "max_overlap": q(&a.max_overlap),
            "gravity": column.map(|c| q(&c.gravity)),
            "height": column.map(|c| q(&c.height)),
            "packing": column.map(|c| c.packing),
            "steps_per_contact": a.steps_per_contact,
            "contact": match a.contact { Contact::Pair => "pair", Contact::Wall => "wall" },
        },
        "k_n_kinetic": q(&a.k_n_kinetic),
        "k_n_static": column.map(|c| q(&c.k_n)),
        "governs": match a.governs { Criterion::Kinetic => "kinetic", Criterion::Static => "static" },
        "k_n": q(&a.k_n),
        "k_t": q(&a.k_t),
        "contact_time": {"pair": q(&a.contact_time_pair), "wall": q(&a.contact_time_wall)},
        "dt": q(&a.dt),
        "steps_per_wall_contact": a.steps_per_wall_contact,
        "peak_overlap": {
            "wall": q(&a.peak_overlap_wall),
            "pair": q(&a.peak_overlap_pair),
            "pile": column.map(|c| q(&c.overlap)),
        },
        "free_fall_speed": column.map(|c| q(&c.free_fall_speed)),
        "units": {
            "length_m": u.length,
            "mass_kg": u.mass,
            "time_s": u.time,
            "g_si": walls_sim::advise::G_SI,
            "walls_file_in_si": {
                "lengthunit": 1.0 / u.length,
                "massunit": 1.0 / u.mass,
                "timeunit": 1.0 / u.time,
            },
        },
        "par": par,
        "par_lines": a.par_lines(args.walls.as_deref()),
        "warnings": a.warnings,
    });
    match serde_json::to_string_pretty(&value) {
        Ok(text) => text + "\n",
        Err(e) => unreachable!("JSON of numbers and strings: {e}"),
    }
}

fn simulate(args: &RunArgs) -> ExitCode {
    match simulate_inner(args) {
        Ok(code) => code,
        Err(e) => {
            eprintln!("walls-sim: error: {e}");
            ExitCode::from(2)
        }
    }
}

/// Reads and checks everything a run needs: the walls file (checked in the run's mode),
/// the particles, the `.par` file, and the settings from options, `.par` and defaults.
fn prepare(args: &RunArgs) -> Result<Prepared, String> {
    use walls_sim::input::read_par;
    use walls_sim::run::{Integrator, Planning};
    use walls_sim::run::{Method, ParticleMaterial, Settings, default_dt};
    use walls_sim::setup;
    let options = Options {
        mode: args.method.into(),
        ..Options::default()
    };
    let checked = check_bytes(input::read(&args.file).bytes?, &options);
    let errors = checked
        .diagnostics
        .iter()
        .filter(|d| d.severity == Severity::Error)
        .count();
    if errors > 0 {
        eprintln!(
            "walls-sim: {}: {errors} error(s); running what could be resolved (see walls-lint)",
            args.file
        );
    }
    let walls = walls_geometry::decode(&checked.scene);
    let scene = &walls[..];
    let par = match &args.par {
        Some(p) => Some(
            read_par(&std::fs::read_to_string(p).map_err(|e| format!("cannot read {p}: {e}"))?)
                .map_err(|e| format!("{p}: {e}"))?,
        ),
        None => None,
    };
    let particle_file = args.particles.clone().or_else(|| {
        let par_dir = std::path::Path::new(args.par.as_deref()?)
            .parent()?
            .to_path_buf();
        par.as_ref()?
            .in_file
            .as_ref()
            .map(|f| par_dir.join(f).to_string_lossy().into_owned())
    });
    let (particles, embedded) = match &particle_file {
        Some(f) => (read_particles(f)?, false),
        None => (setup::default_particles(scene), true),
    };
    if particles.is_empty() {
        return Err("no particles to run".into());
    }
    let gravity = match (&args.gravity, par.as_ref().and_then(|p| p.gravity)) {
        (Some(g), _) => nalgebra::Vector3::new(g[0], g[1], g[2]),
        (None, Some(g)) => g,
        (None, None) if embedded => nalgebra::Vector3::new(0.0, 0.0, -1.0),
        (None, None) => nalgebra::Vector3::zeros(),
    };
    let from_par = |f: fn(&walls_sim::input::Params) -> Option<f64>| par.as_ref().and_then(f);
    let method = match args.method {
        ModeArg::Ssdem => Method::Soft,
        ModeArg::Hsdem => Method::Hard,
    };
    let k_n = args
        .k_n
        .or(from_par(|p| p.k_n))
        .unwrap_or_else(|| setup::default_k_n(scene, &particles, &gravity));
    let default = setup::default_material(k_n);
    let material = ParticleMaterial {
        eps_n: args.epsn.or(from_par(|p| p.eps_n)).unwrap_or(default.eps_n),
        eps_t: args.epst.or(from_par(|p| p.eps_t)).unwrap_or(default.eps_t),
        k_n,
        k_t: args.k_t.or(from_par(|p| p.k_t)).unwrap_or(default.k_t),
        mu_s: args.mu_s.or(from_par(|p| p.mu_s)).unwrap_or(default.mu_s),
        mu_r: args.mu_r.or(from_par(|p| p.mu_r)).unwrap_or(default.mu_r),
        mu_t: args.mu_t.or(from_par(|p| p.mu_t)).unwrap_or(default.mu_t),
    };
    let t_end = args
        .t_end
        .or_else(|| par.as_ref().and_then(|p| Some(p.steps? as f64 * p.dt?)))
        .unwrap_or_else(|| setup::default_duration(scene, &particles, &gravity));
    let dt = args
        .dt
        .or(from_par(|p| p.dt))
        .unwrap_or_else(|| match method {
            Method::Soft => default_dt(&particles, k_n),
            Method::Hard => setup::default_hard_dt(&particles, &gravity, t_end),
        });
    let settings = Settings {
        method,
        gravity,
        particle_contacts: !args.no_particle_contacts,
        edges: !args.no_edges && par.as_ref().and_then(|p| p.edge_detect).unwrap_or(true),
        stepping: match args.oscillation {
            Oscillation::Exact => walls_sim::OscillationStepping::Exact,
            Oscillation::Pkdgrav => walls_sim::OscillationStepping::Pkdgrav,
        },
        integrator: match args.integrator {
            IntegratorArg::Leapfrog => Integrator::Leapfrog,
            IntegratorArg::Pkdgrav => Integrator::LeapfrogPredicted,
            IntegratorArg::Euler => Integrator::ExplicitEuler,
        },
        planning: if args.all_parts {
            Planning::Everything
        } else {
            Planning::Needed
        },
        ..Settings::new(dt, t_end, material)
    };
    Ok(Prepared {
        walls,
        particles,
        settings,
        errors,
    })
}

/// Particles from a CSV file (by its extension, in any case) or a pkdgrav `.ss` file.
fn read_particles(f: &str) -> Result<Vec<walls_sim::input::Particle>, String> {
    use walls_sim::input::{read_csv, read_ss};
    let bytes = std::fs::read(f).map_err(|e| format!("cannot read {f}: {e}"))?;
    let csv = std::path::Path::new(f)
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("csv"));
    if csv {
        read_csv(&String::from_utf8_lossy(&bytes))
    } else {
        read_ss(&bytes).map(|(_, ps)| ps)
    }
    .map_err(|e| format!("{f}: {e}"))
}

/// `walls-sim preview`: pictures of the walls at a time, or over a span.
#[derive(clap::Args)]
struct PreviewArgs {
    /// The walls file; `-` reads standard input.
    #[arg(value_name = "FILE")]
    file: String,
    /// Where the walls are: at this time (pkdgrav units).
    #[arg(long, value_name = "T", default_value_t = 0.0, allow_negative_numbers = true, value_parser = ruled(Rule::Any))]
    time: f64,
    /// The picture, by its extension: .svg (the default, on standard output without
    /// --out), .pov (POV-Ray, with walls.inc beside it), .vtp (VTK, for ParaView) or
    /// .html (an interactive page over [--time, --until]).
    #[arg(long, value_name = "FILE")]
    out: Option<std::path::PathBuf>,
    /// Particles to draw too: CSV or .ss.
    #[arg(long, value_name = "FILE")]
    particles: Option<String>,
    /// Draw reactive walls where a run left them: the WALLSREACTviz.out that
    /// `walls-sim run --out` (or pkdgrav) wrote; its last step.
    #[arg(long, value_name = "FILE")]
    reactive: Option<String>,
    /// HTML: particle trajectories to play, the particles.csv that `walls-sim run --out`
    /// writes.
    #[arg(long, value_name = "FILE")]
    trajectory: Option<String>,
    /// The direction to look from (towards the scene).
    #[arg(long, num_args = 3, value_names = ["X", "Y", "Z"], allow_negative_numbers = true, value_parser = ruled(Rule::Any))]
    view: Option<Vec<f64>>,
    /// Which way is up in the picture.
    #[arg(long, num_args = 3, value_names = ["X", "Y", "Z"], allow_negative_numbers = true, value_parser = ruled(Rule::Any))]
    up: Option<Vec<f64>>,
    /// The picture's size in pixels.
    #[arg(long, num_args = 2, value_names = ["W", "H"], value_parser = clap::value_parser!(u32).range(16..=16384))]
    size: Option<Vec<u32>>,
    /// Frames from --time to --until: numbered pictures FILE-000.svg… and FILE.svg
    /// animated.
    #[arg(long, value_name = "N", default_value_t = 1, value_parser = clap::value_parser!(u64).range(1..=10000))]
    frames: u64,
    /// The end of the span the frames cover.
    #[arg(long, value_name = "T", allow_negative_numbers = true, value_parser = ruled(Rule::Any))]
    until: Option<f64>,
    /// Seconds the animation takes to play once.
    #[arg(long, value_name = "S", default_value_t = 4.0, value_parser = ruled(Rule::Positive))]
    seconds: f64,
    /// Segments around round shapes.
    #[arg(long, value_name = "N", default_value_t = 48, value_parser = clap::value_parser!(u64).range(3..=4096))]
    segments: u64,
}

fn preview(args: &PreviewArgs) -> ExitCode {
    match preview_inner(args) {
        Ok(code) => code,
        Err(e) => {
            eprintln!("walls-sim: error: {e}");
            ExitCode::from(2)
        }
    }
}

fn preview_inner(args: &PreviewArgs) -> Result<ExitCode, String> {
    use nalgebra::Vector3;
    use walls_preview::svg::{Frame, View, write};
    let checked = check_bytes(input::read(&args.file).bytes?, &Options::default());
    let errors = checked
        .diagnostics
        .iter()
        .filter(|d| d.severity == Severity::Error)
        .count();
    if errors > 0 {
        eprintln!(
            "walls-sim: {}: {errors} error(s); drawing what could be resolved (see walls-lint)",
            args.file
        );
    }
    let scene = &checked.scene;
    let particles = match &args.particles {
        Some(f) => read_particles(f)?,
        None => Vec::new(),
    };
    let v3 = |v: &Option<Vec<f64>>, default: Vector3<f64>| {
        v.as_ref()
            .map_or(default, |v| Vector3::new(v[0], v[1], v[2]))
    };
    let default = View::default();
    let view = View {
        from: v3(&args.view, default.from),
        up: v3(&args.up, default.up),
        width: args.size.as_ref().map_or(default.width, |s| s[0]),
        height: args.size.as_ref().map_or(default.height, |s| s[1]),
    };
    let segments = args.segments as usize;
    let n = args.frames as usize;
    let until = args.until.unwrap_or(args.time);
    let times: Vec<f64> = (0..n)
        .map(|k| {
            if n == 1 {
                args.time
            } else {
                args.time + (until - args.time) * k as f64 / (n - 1) as f64
            }
        })
        .collect();
    let mut meshes: Vec<_> = times
        .iter()
        .map(|t| walls_preview::wall_meshes(scene, *t, segments))
        .collect();
    if let Some(f) = &args.reactive {
        // Reactive walls where a run moved them: the last step of WALLSREACTviz.out.
        let placed = read_reactive_viz(f)?;
        for frame in &mut meshes {
            walls_preview::mesh::place(frame, scene, &placed);
        }
    }
    let frames: Vec<Frame> = times
        .iter()
        .zip(&meshes)
        .map(|(t, walls)| Frame {
            t: *t,
            walls,
            particles: &particles,
        })
        .collect();
    let bounds = walls_geometry::scene_bounds(&walls_geometry::decode(scene));
    let kind = args
        .out
        .as_ref()
        .and_then(|p| p.extension())
        .map(|e| e.to_string_lossy().to_ascii_lowercase());
    if args.reactive.is_some() && !matches!(kind.as_deref(), None | Some("svg") | Some("vtp")) {
        return Err("--reactive is drawn in .svg and .vtp pictures only".into());
    }
    match kind.as_deref() {
        None => {
            let mut out = std::io::BufWriter::new(std::io::stdout().lock());
            write(&mut out, &frames, &view, bounds, args.seconds)
                .and_then(|()| out.flush())
                .map_err(|e| format!("cannot write the picture: {e}"))?;
        }
        Some("svg") => {
            let path = args.out.as_ref().expect("an extension comes from a path");
            let save = |path: &std::path::Path, frames: &[Frame]| {
                let mut out = std::io::BufWriter::new(
                    std::fs::File::create(path)
                        .map_err(|e| format!("cannot write {}: {e}", path.display()))?,
                );
                write(&mut out, frames, &view, bounds, args.seconds)
                    .and_then(|()| out.flush())
                    .map_err(|e| format!("cannot write {}: {e}", path.display()))
            };
            save(path, &frames)?;
            if n > 1 {
                let stem = path.with_extension("");
                for (k, frame) in frames.iter().enumerate() {
                    let numbered = format!("{}-{k:03}.svg", stem.display());
                    save(std::path::Path::new(&numbered), std::slice::from_ref(frame))?;
                }
            }
        }
        Some("pov") => {
            let path = args.out.as_ref().expect("an extension comes from a path");
            let pov_view = walls_preview::pov::View {
                from: view.from,
                aspect: f64::from(view.width) / f64::from(view.height),
                ..walls_preview::pov::View::default()
            };
            walls_preview::pov::write_file(path, scene, args.time, &particles, &pov_view)
                .map_err(|e| format!("cannot write {}: {e}", path.display()))?;
        }
        Some("vtp") => {
            let path = args.out.as_ref().expect("an extension comes from a path");
            let mut out = std::io::BufWriter::new(
                std::fs::File::create(path)
                    .map_err(|e| format!("cannot write {}: {e}", path.display()))?,
            );
            walls_preview::vtk::write(&mut out, &meshes[0], &particles)
                .and_then(|()| out.flush())
                .map_err(|e| format!("cannot write {}: {e}", path.display()))?;
        }
        Some("html") => {
            let path = args.out.as_ref().expect("an extension comes from a path");
            let moving = match &args.trajectory {
                Some(f) => Some(read_trajectory(f)?),
                None if !particles.is_empty() => Some(walls_preview::html::Particles {
                    radii: particles.iter().map(|p| p.radius).collect(),
                    colors: particles.iter().map(|p| i64::from(p.color)).collect(),
                    times: vec![args.time],
                    frames: vec![particles.iter().map(|p| p.pos).collect()],
                }),
                None => None,
            };
            let mut out = std::io::BufWriter::new(
                std::fs::File::create(path)
                    .map_err(|e| format!("cannot write {}: {e}", path.display()))?,
            );
            walls_preview::html::write(&mut out, scene, moving.as_ref(), until, n.max(101))
                .and_then(|()| out.flush())
                .map_err(|e| format!("cannot write {}: {e}", path.display()))?;
        }
        Some(other) => {
            return Err(format!(
                "cannot draw .{other} files: use .svg, .pov, .vtp or .html (or no --out for SVG on standard output)"
            ));
        }
    }
    Ok(if errors > 0 {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    })
}

/// The walls' placements on the last line of a `WALLSREACTviz.out`: for each wall id,
/// its origin and either (vertex1, vertex2) or orient.
fn read_reactive_viz(f: &str) -> Result<Vec<walls_preview::mesh::Placement>, String> {
    use walls_preview::mesh::Placement;
    let text = std::fs::read_to_string(f).map_err(|e| format!("cannot read {f}: {e}"))?;
    let (n, line) = text
        .lines()
        .enumerate()
        .filter(|(_, l)| !l.trim().is_empty())
        .last()
        .ok_or_else(|| format!("{f}: no steps"))?;
    let bad = || format!("{f}: line {}: not a WALLSREACTviz.out line", n + 1);
    let fields: Vec<f64> = line
        .split_whitespace()
        .map(|x| x.parse::<f64>().map_err(|_| bad()))
        .collect::<Result<_, _>>()?;
    let mut out = Vec::new();
    let mut k = 1; // after the step
    let v3 = |k: usize| -> Result<nalgebra::Vector3<f64>, String> {
        (k + 3 <= fields.len())
            .then(|| nalgebra::Vector3::new(fields[k], fields[k + 1], fields[k + 2]))
            .ok_or_else(bad)
    };
    while k < fields.len() {
        let (kind, id) = (fields[k], fields.get(k + 1).copied().ok_or_else(bad)?);
        let origin = v3(k + 2)?;
        if kind == 0.0 {
            out.push(Placement::Polygon {
                wall: id as usize,
                origin,
                vertex1: v3(k + 5)?,
                vertex2: v3(k + 8)?,
            });
            k += 11;
        } else {
            out.push(Placement::Round {
                wall: id as usize,
                origin,
                orient: v3(k + 5)?,
            });
            k += 8;
        }
    }
    Ok(out)
}

/// Particle trajectories from the `particles.csv` of `walls-sim run --out`
/// (`step,t,particle,alive,mass,radius,x,y,z,…`): one frame per output step.
fn read_trajectory(f: &str) -> Result<walls_preview::html::Particles, String> {
    let text = std::fs::read_to_string(f).map_err(|e| format!("cannot read {f}: {e}"))?;
    let mut lines = text.lines().enumerate();
    match lines.next() {
        Some((_, header)) if header.starts_with("step,t,particle,alive,mass,radius,x,y,z") => {}
        _ => {
            return Err(format!(
                "{f}: not a trajectory (the particles.csv of walls-sim run --out)"
            ));
        }
    }
    let mut out = walls_preview::html::Particles::default();
    for (n, line) in lines {
        let cells: Vec<&str> = line.split(',').collect();
        let number = |k: usize| -> Result<f64, String> {
            cells
                .get(k)
                .and_then(|c| c.parse::<f64>().ok())
                .filter(|x| x.is_finite())
                .ok_or_else(|| format!("{f}: line {}: column {} is not a number", n + 1, k + 1))
        };
        let (t, i) = (number(1)?, number(2)? as usize);
        if out.times.last() != Some(&t) {
            out.times.push(t);
            out.frames.push(Vec::new());
        }
        let frame = out.frames.last_mut().expect("pushed above");
        if i != frame.len() {
            return Err(format!("{f}: line {}: particles out of order", n + 1));
        }
        frame.push(nalgebra::Vector3::new(number(6)?, number(7)?, number(8)?));
        if out.frames.len() == 1 {
            out.radii.push(number(5)?);
            out.colors.push(3);
        }
    }
    Ok(out)
}

/// One output step of pkdgrav's reactive-wall files: each assembly's state, and every
/// finite wall of an assembly where it now is.
fn record_reactive(
    out: &mut walls_sim::reactive_output::ReactiveOutput,
    step: u64,
    scene: &[walls_geometry::Wall],
    assemblies: &[walls_sim::reactive::Assembly],
) -> std::io::Result<()> {
    use walls_geometry::Shape;
    use walls_sim::reactive_output::{AssemblyState, VizWall};
    let states: Vec<AssemblyState> = assemblies
        .iter()
        .map(|a| AssemblyState {
            cog: a.cog,
            velocity: a.velocity,
            rot_vec: a.rotation.omega,
            axes: a.rotation.axes,
        })
        .collect();
    let mut walls: Vec<(usize, VizWall)> = Vec::new();
    for a in assemblies {
        let turn = a.turn();
        for (k, &w) in a.walls.iter().enumerate() {
            let shape = &scene[w].shape;
            // pkdgrav's viz file holds finite walls only.
            if matches!(shape, Shape::Plane { .. } | Shape::InfiniteCylinder { .. }) {
                continue;
            }
            let origin = a.origin(k);
            walls.push((
                w,
                match (shape.edges(), shape.axis()) {
                    (Some((e1, e2)), _) => VizWall::Polygon {
                        id: w,
                        origin,
                        vertex1: turn * e1,
                        vertex2: turn * e2,
                    },
                    (None, axis) => VizWall::Round {
                        id: w,
                        origin,
                        orient: turn * axis.unwrap_or_default(),
                    },
                },
            ));
        }
    }
    walls.sort_by_key(|(w, _)| *w);
    let walls: Vec<VizWall> = walls.into_iter().map(|(_, v)| v).collect();
    out.record(step, &states, &walls)
}

/// What a run needs, read and checked.
struct Prepared {
    walls: Vec<walls_geometry::Wall>,
    particles: Vec<walls_sim::input::Particle>,
    settings: walls_sim::run::Settings,
    errors: usize,
}

fn simulate_inner(args: &RunArgs) -> Result<ExitCode, String> {
    use walls_sim::run::run_observed;
    let Prepared {
        walls,
        particles,
        settings,
        errors,
    } = prepare(args)?;
    let scene = &walls[..];
    let (t_end, dt) = (settings.t_end, settings.dt);
    let mut trajectory = match &args.out {
        Some(dir) => Some(
            walls_sim::trajectory::Trajectory::create(dir)
                .map_err(|e| format!("cannot write to {}: {e}", dir.display()))?,
        ),
        None => None,
    };
    let progress = progress_bar((t_end / dt).ceil() as u64);
    let mut written: std::io::Result<()> = Ok(());
    if let Some(out) = &mut trajectory {
        let start: Vec<_> = particles.iter().map(walls_sim::run::State::new).collect();
        written = out.record(0, 0.0, &start, scene, &[]);
    }
    // pkdgrav's reactive-wall files, beside the trajectory, when the run has assemblies:
    // appended to as pkdgrav does, unless --fresh.
    let reactive = settings.method == walls_sim::run::Method::Soft
        && !walls_sim::reactive::assemblies(scene).is_empty();
    let mut reactive_files = match (&args.out, reactive) {
        (Some(dir), true) => Some(
            walls_sim::reactive_output::ReactiveOutput::open(dir, args.fresh)
                .map_err(|e| format!("cannot write to {}: {e}", dir.display()))?,
        ),
        _ => None,
    };
    let outcome = run_observed(
        scene,
        particles.clone(),
        &settings,
        &mut |step, t, states, assemblies| {
            if let Some(bar) = &progress {
                bar.set_position(step);
            }
            if let Some(out) = &mut reactive_files
                && step % args.every == 0
                && written.is_ok()
            {
                written = record_reactive(out, step, scene, assemblies);
            }
            if let Some(out) = &mut trajectory
                && step % args.every == 0
                && written.is_ok()
            {
                written = out.record(step, t, states, scene, assemblies);
            }
        },
    );
    if let Some(bar) = progress {
        bar.finish_and_clear();
    }
    if let Some(out) = trajectory {
        written = written.and_then(|()| out.finish());
    }
    if let Some(out) = reactive_files {
        written = written.and_then(|()| out.finish());
    }
    if let (Err(e), Some(dir)) = (written, &args.out) {
        return Err(format!(
            "cannot write the trajectory to {}: {e}",
            dir.display()
        ));
    }
    report(args, scene, &particles, &settings, &outcome)?;
    Ok(if errors > 0 {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    })
}

/// A progress bar over `steps` steps, when standard error is a terminal.
fn progress_bar(steps: u64) -> Option<indicatif::ProgressBar> {
    if !std::io::stderr().is_terminal() {
        return None;
    }
    let bar = indicatif::ProgressBar::new(steps);
    if let Ok(style) =
        indicatif::ProgressStyle::with_template("walls-sim {bar:40} {pos}/{len} steps, {eta} left")
    {
        bar.set_style(style);
    }
    Some(bar)
}

/// The parts of the model a run used, for the JSON `model` field: the plan's (as the
/// run saw it), plus sticky and death walls when a particle met one.
fn model(
    scene: &[walls_geometry::Wall],
    particles: &[walls_sim::input::Particle],
    settings: &walls_sim::run::Settings,
) -> Vec<&'static str> {
    let (_, parts) = walls_sim::plan::parts(scene, particles, settings);
    let everything = settings.planning == walls_sim::run::Planning::Everything;
    let mut model = vec![match settings.method {
        walls_sim::run::Method::Soft => "ssdem: spring-dashpot",
        walls_sim::run::Method::Hard => "hsdem: exact collision prediction",
    }];
    model.extend(
        parts
            .iter()
            .filter(|p| p.used || (everything && p.name != "reactive walls"))
            .map(|p| p.name),
    );
    model
}

/// Prints the outcome: JSON on standard output, or a summary on standard error.
fn report(
    args: &RunArgs,
    scene: &[walls_geometry::Wall],
    particles: &[walls_sim::input::Particle],
    settings: &walls_sim::run::Settings,
    out: &walls_sim::run::Outcome,
) -> Result<(), String> {
    use walls_sim::run::EventKind;
    let kind = |k: EventKind| match k {
        EventKind::Bounce => "bounce",
        EventKind::Stick => "stick",
        EventKind::Remove => "remove",
    };
    if args.json {
        let v3 = |v: &nalgebra::Vector3<f64>| serde_json::json!([v.x, v.y, v.z]);
        let report = serde_json::json!({
            "t": out.t,
            "steps": out.steps,
            "particles": out.particles.iter().map(|s| serde_json::json!({
                "pos": v3(&s.particle.pos),
                "vel": v3(&s.particle.vel),
                "spin": v3(&s.particle.spin),
                "alive": s.alive,
                "stuck_to": s.stuck_to.map(|(w, _)| w),
            })).collect::<Vec<_>>(),
            "events": out.events.iter().map(|e| serde_json::json!({
                "t": e.t, "particle": e.particle, "wall": e.wall, "kind": kind(e.kind),
                "vn_in": e.vn_in, "vn_out": e.vn_out,
            })).collect::<Vec<_>>(),
            "pair_contacts": out.pair_contacts,
            "energy": {"initial": out.energy.0, "final": out.energy.1},
            "model": model(scene, particles, settings),
            "warnings": out.warnings,
        });
        println!(
            "{}",
            serde_json::to_string_pretty(&report).map_err(|e| e.to_string())?
        );
    } else {
        eprintln!(
            "walls-sim: t = {:.6} after {} steps of {:.3e}: {} particles ({} alive), {} wall events, {} particle contacts, energy {:.6e} → {:.6e}",
            out.t,
            out.steps,
            settings.dt,
            out.particles.len(),
            out.particles.iter().filter(|s| s.alive).count(),
            out.events.len(),
            out.pair_contacts,
            out.energy.0,
            out.energy.1
        );
        for w in &out.warnings {
            eprintln!("walls-sim: warning: {w}");
        }
    }
    Ok(())
}

/// A value parser for a number that must obey `rule`, as the `.par` file's values must.
fn ruled(rule: Rule) -> impl Fn(&str) -> Result<f64, String> + Clone {
    move |s| {
        let x = s
            .parse::<f64>()
            .map_err(|_| format!("`{s}` is not a number"))?;
        rule.check(x).map_err(|says| format!("it must be {says}"))
    }
}

fn scene(path: &str, time: Option<f64>, mode: ModeArg) -> ExitCode {
    let read = input::read(path);
    let bytes = match read.bytes {
        Ok(bytes) => bytes,
        Err(e) => {
            eprintln!("walls-sim: error: {e}");
            return ExitCode::from(2);
        }
    };
    let options = Options {
        mode: mode.into(),
        ..Options::default()
    };
    let checked = check_bytes(bytes, &options);
    let mut out = std::io::BufWriter::new(std::io::stdout().lock());
    let written = walls_geometry::json::write_scene(&mut out, &checked.scene, &checked.text, time)
        .and_then(|()| out.flush());
    if let Err(e) = written {
        if e.kind() != std::io::ErrorKind::BrokenPipe {
            eprintln!("walls-sim: error: cannot write output: {e}");
        }
        return ExitCode::from(2);
    }
    let report = FileReport {
        path: &read.name,
        source: &checked.text,
        diagnostics: &checked.diagnostics,
    };
    let color = std::io::stderr().is_terminal() && std::env::var_os("NO_COLOR").is_none();
    let mut err = std::io::BufWriter::new(std::io::stderr().lock());
    // Standard error is only for people here; if it is gone there is nobody to tell.
    let _ = render::human(&mut err, &report, color).and_then(|()| err.flush());
    if checked
        .diagnostics
        .iter()
        .any(|d| d.severity == Severity::Error)
    {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    }
}
