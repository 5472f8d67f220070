//! `walls-sim advise`: suggests the spring constants and timestep (dKn, dKt, dDelta) for
//! the real pkdgrav run from the particles' size, mass and speed, and prints the .par
//! lines. The advice, its text and its JSON are [`walls_sim::advise`]'s.

use walls_sim::advise::{Contact, UnitSystem};
use walls_sim::cli::ruled;
use walls_sim::io::par::Rule;

/// `walls-sim advise`: physical inputs in, pkdgrav parameters out (docs/evaluator.md,
/// "Advice for the real run").
#[derive(clap::Args)]
#[command(
    group(clap::ArgGroup::new("amount").required(true).args(["mass", "density"])),
    after_help = "k_n is the larger of m·(v/x)² (the fastest impact stops within the overlap x) and φ·ρ·g·H·s²/x (the pile's bottom bears its weight within x); k_t = 2/7·k_n; dDelta = π·√(m/(2k_n))/N. Values are SI unless --units pkdgrav; the output gives both."
)]
pub struct AdviseArgs {
    /// The typical (most energetic) particle's mass: kg, or M_sun with --units pkdgrav.
    #[arg(long, value_name = "M", value_parser = ruled(Rule::Positive))]
    pub mass: Option<f64>,
    /// Or its density: kg/m^3, or M_sun/AU^3.
    #[arg(long, value_name = "RHO", value_parser = ruled(Rule::Positive))]
    pub density: Option<f64>,
    /// The typical particle's radius: m, or AU.
    #[arg(long, value_name = "S", value_parser = ruled(Rule::Positive))]
    pub radius: f64,
    /// The maximum expected speed, of a particle at a wall or of two particles towards
    /// each other: m/s, or AU/(yr/2pi).
    #[arg(long, value_name = "V", value_parser = ruled(Rule::Positive))]
    pub speed: f64,
    /// The allowed overlap, as a fraction of the radius (pkdgrav warns at 0.03 and 0.15).
    #[arg(long, value_name = "FRACTION", default_value_t = walls_sim::advise::DEFAULT_OVERLAP, value_parser = ruled(Rule::Overlap))]
    pub overlap: f64,
    /// Gravity (uniform, or at the surface), for the static criterion with --height:
    /// m/s^2, or AU/(yr/2pi)^2.
    #[arg(long, value_name = "G", requires = "height", value_parser = ruled(Rule::Positive))]
    pub gravity: Option<f64>,
    /// The pile's height (or the body's radius), for the static criterion: m, or AU.
    #[arg(long, value_name = "H", requires = "gravity", value_parser = ruled(Rule::Positive))]
    pub height: Option<f64>,
    /// The pile's packing fraction (static criterion).
    #[arg(long, value_name = "PHI", default_value_t = walls_sim::advise::DEFAULT_PACKING, value_parser = ruled(Rule::Fraction))]
    pub packing: f64,
    /// Steps per contact (pkdgrav's demparams uses 30; 50 for a closer restitution).
    #[arg(long, value_name = "N", default_value_t = walls_sim::advise::DEFAULT_STEPS_PER_CONTACT, value_parser = ruled(Rule::Positive))]
    pub steps_per_contact: f64,
    /// The shortest contact the timestep must resolve: between particles (reduced mass
    /// m/2), or only against walls (m, √2 longer).
    #[arg(long, value_enum, default_value_t = Contact::Pair)]
    pub contact: Contact,
    /// The walls file, for an achWallsFile line.
    #[arg(long, value_name = "FILE", value_parser = par_name)]
    pub walls: Option<String>,
    /// The units of the inputs.
    #[arg(long, value_enum, default_value_t = UnitSystem::Si)]
    pub units: UnitSystem,
    /// Print the advice as JSON on standard output.
    #[arg(long)]
    pub json: bool,
}

/// A file name pkdgrav's parameter reader reads back as written.
fn par_name(s: &str) -> Result<String, String> {
    walls_sim::advise::par_string(s)
        .map(str::to_string)
        .map_err(|why| format!("pkdgrav cannot read that name: {why}"))
}

/// Prints the advice `args` ask for; the exit status.
pub fn run(args: &AdviseArgs) -> i32 {
    use walls_sim::advise::{self, Amount, Column, Inputs};
    let inputs = Inputs {
        units: args.units,
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
        contact: args.contact,
    };
    let advice = match advise::advise(&inputs) {
        Ok(a) => a,
        Err(e) if e.derived => {
            crate::errln!("walls-sim: error: {e}");
            return 2;
        }
        Err(e) => {
            crate::errln!("walls-sim: error: --{e}");
            return 2;
        }
    };
    let walls = args.walls.as_deref();
    if args.json {
        let json = advise::json(&advice, &inputs, walls);
        crate::console::out_data(|w| w.write_all(json.as_bytes()));
    } else {
        crate::out!("{}", advise::text(&advice, &inputs, walls));
        for w in &advice.warnings {
            crate::errln!("walls-sim: warning: {w}");
        }
    }
    0
}
