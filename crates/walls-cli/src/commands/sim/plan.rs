//! `walls-sim plan`: lists the parts of the model a run would use, with the reason for
//! each ([`walls_sim::run::plan`]); it takes the same options as `run`.

use super::run::{RunArgs, prepare};
use super::{error, exit_status};
use std::process::ExitCode;

/// Prints the plan of the run `args` describe; the exit status.
pub fn run(args: &RunArgs) -> ExitCode {
    let prepared = match prepare(args) {
        Ok(p) => p,
        Err(e) => return error(e),
    };
    let (_, parts) =
        walls_sim::run::plan::parts(&prepared.walls, &prepared.particles, &prepared.settings);
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
    exit_status(prepared.errors)
}
