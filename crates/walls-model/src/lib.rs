//! What a parsed walls file means to pkdgrav.
//!
//! [`analyze`] reads the syntax tree front to back as pkdgrav does ([`resolve`]) into a
//! [`Scene`] of walls with effective values in pkdgrav units, each remembering where it
//! came from, and checks every rule of docs/spec.md §1: single values as they are read,
//! then blocks, walls and the file as a whole. Each rule, with its diagnostic code and
//! the code's documentation, is one file of the private `rules` module; [`codes`] lists
//! them. The back end decodes each wall into typed parts once (the walls-geometry crate).

mod check;
pub mod codes;
mod fix;
mod resolve;
mod rules;
pub mod scene;

pub use resolve::resolve;
pub use rules::axes_not_orthogonal::AXES_COS_TOLERANCE;
pub use rules::axis_not_unit::AXIS_LENGTH_TOLERANCE;
pub use rules::rectangle_not_rectangular::RECTANGLE_COS_TOLERANCE;
pub use rules::wall_too_fast::STEP_TRAVEL_FRACTION;
pub use scene::{
    Place, Scene, Setting, Settings, Source, Span, Units, Value, Vec3, Wall, WallSettings,
    direction,
};
use walls_diagnostics::Diagnostic;
pub use walls_keywords::ContactModel;
use walls_syntax::SyntaxTree;

/// What the checker is told about the run the file is for.
#[derive(Debug, Clone, PartialEq)]
pub struct Options {
    /// The contact model.
    pub mode: ContactModel,
    /// pkdgrav's MAX_NUM_WALLS (20 unless compiled otherwise).
    pub max_walls: usize,
    /// The smallest particle radius, for the SSDEM wall-speed check.
    pub min_radius: Option<f64>,
    /// The simulation timestep, the update step of walls with `step 0`.
    pub dt: Option<f64>,
}

impl Default for Options {
    fn default() -> Self {
        Options {
            mode: ContactModel::Ssdem,
            max_walls: 20,
            min_radius: None,
            dt: None,
        }
    }
}

/// The scene and every model diagnostic, sorted by position.
#[derive(Debug, Clone)]
pub struct Analysis {
    /// The walls as pkdgrav builds them.
    pub scene: Scene,
    /// The findings, sorted by position.
    pub diagnostics: Vec<Diagnostic>,
}

/// Resolves and checks a parsed file. Works on files with syntax errors too: statements
/// whose values did not parse are skipped.
pub fn analyze(tree: &SyntaxTree, options: &Options) -> Analysis {
    let (scene, mut diagnostics, unread) = resolve::resolve_noting_unread(tree, options.mode);
    diagnostics.extend(check::check(tree, &scene, &unread, options));
    if options.mode == ContactModel::Hsdem {
        diagnostics.extend(rules::ignored_in_hsdem::check(tree));
    }
    diagnostics.sort_by_key(|d| (d.span.start, d.span.end));
    Analysis { scene, diagnostics }
}
