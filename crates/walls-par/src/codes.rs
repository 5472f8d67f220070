//! The `.par` diagnostic codes (`P…`): the registry. Each is defined beside its check
//! under `rules/`; [`ALL`] lists them in code order.

use walls_diagnostics::Code;

pub use crate::rules::duplicate_key::DUPLICATE_KEY;
pub use crate::rules::line_too_long::LINE_TOO_LONG;
pub use crate::rules::not_finite::NOT_FINITE;
pub use crate::rules::not_modelled::NOT_MODELLED;
pub use crate::rules::par_syntax::PAR_SYNTAX;
pub use crate::rules::read_as::READ_AS;
pub use crate::rules::startup::{PKDGRAV_CHANGES, PKDGRAV_STOPS, PKDGRAV_WARNS, RUN_DIFFERS};
pub use crate::rules::unknown_key::UNKNOWN_KEY;

/// Every `.par` code, in code order.
pub static ALL: &[&Code] = &[
    &PAR_SYNTAX,
    &LINE_TOO_LONG,
    &UNKNOWN_KEY,
    &READ_AS,
    &NOT_FINITE,
    &DUPLICATE_KEY,
    &NOT_MODELLED,
    &PKDGRAV_STOPS,
    &PKDGRAV_WARNS,
    &PKDGRAV_CHANGES,
    &RUN_DIFFERS,
];
