//! `walls-sim plan`: lists the parts of the model a run would use, with the reason for
//! each ([`walls_sim::run::plan`]), and the pkdgrav build it follows with where that
//! came from; it takes the same options as `run`.

use super::run::{Prepared, RunArgs, prepare_as};
use super::{error, exit_status};
use walls_geometry::Particle;

/// Prints the plan of the run `args` describe; the exit status.
pub fn run(args: &RunArgs) -> i32 {
    let prepared: Prepared<Particle> = match prepare_as(args, Some("running")) {
        Ok(p) => p,
        Err(e) => return error(e),
    };
    for w in &prepared.numbers {
        crate::errln!("walls-sim: warning: {w}");
    }
    let (_, mut parts) =
        walls_sim::run::plan::parts(&prepared.walls, &prepared.particles, &prepared.settings);
    let origin = prepared.flags.build_origin();
    for p in parts.iter_mut().filter(|p| p.name == "pkdgrav build") {
        p.reason = match p.reason.split_once(';') {
            Some((names, rest)) => format!("{names} ({origin});{rest}"),
            None => format!("{} ({origin})", p.reason),
        };
    }
    if args.json {
        let list: Vec<_> = parts
            .iter()
            .map(|p| serde_json::json!({"part": p.name, "used": p.used, "reason": p.reason}))
            .collect();
        let plan = serde_json::json!({ "plan": list });
        crate::console::out_data(|w| writeln!(w, "{plan}"));
    } else {
        for p in &parts {
            let mark = if p.used { "uses" } else { "skips" };
            crate::outln!("{mark:5} {}: {}", p.name, p.reason);
        }
    }
    exit_status(prepared.errors)
}
