//! R006 `token-needs-build`: a walls-file token whose physics needs a compile option the
//! `--pkdgrav-build` build lacks: cohesion tokens without `DEM_COHESION` (docs/
//! pkdgrav-physics.md §7), two-layer tokens without `DEM_TWOLAYERS` (§8), a wall's mass
//! and assembly without `DEM_WALLS_REACT` (§10). The evaluator warns of the same as
//! W501, W502 and W402; here each token is reported where it is set.

use crate::precheck::{Context, Findings};
use walls_diagnostics::Diagnostic;

pub use walls_par::run_codes::build_lacks::BUILD_LACKS;

/// Reports each token of the walls file whose compile option the build lacks.
pub(crate) fn check(cx: &Context, out: &mut Findings) {
    if cx.run.walls.is_none() {
        return;
    }
    let build = cx.run.par.build;
    for (w, wall) in cx.walls.iter().enumerate() {
        let mut lacking: Vec<(&'static str, &'static str)> = Vec::new();
        if !build.has("DEM_COHESION") {
            lacking.extend(
                wall.optional
                    .cohesion_tokens()
                    .into_iter()
                    .map(|t| (t, "DEM_COHESION")),
            );
        }
        if !build.has("DEM_TWOLAYERS") {
            lacking.extend(
                wall.optional
                    .two_layer_tokens()
                    .into_iter()
                    .map(|t| (t, "DEM_TWOLAYERS")),
            );
        }
        if !build.has("DEM_WALLS_REACT") && wall.reactive.is_heavy() {
            lacking.push(("mass", "DEM_WALLS_REACT"));
        }
        for (token, option) in lacking {
            let span = cx.token_span(w, token).unwrap_or_else(|| cx.wall_span(w));
            let what = match option {
                "DEM_COHESION" => "cohesion",
                "DEM_TWOLAYERS" => "two-layer contacts",
                _ => "walls that react to the particles",
            };
            out.walls.push(
                Diagnostic::warning(
                    &BUILD_LACKS,
                    span,
                    format!(
                        "`{token}` of {} needs {option} ({what}), which the build ({}) lacks: pkdgrav runs as if it were not there",
                        cx.wall_name(w),
                        build.names()
                    ),
                )
                .with_help(format!(
                    "run a pkdgrav built with {option} (and check with --pkdgrav-build naming it), or take the token out"
                )),
            );
        }
    }
}
