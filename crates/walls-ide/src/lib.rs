//! One analysis of a walls file for every tool, and the editor features as plain data.
//!
//! [`check_text`] and [`check_bytes`] are the one place that parses, resolves, checks
//! and sorts the diagnostics of a file, honouring its suppression comments ([`suppress`]):
//! `walls-lint`, `walls-sim`, the language server and the charts all start from the
//! [`Checked`] they return. [`all_codes`],
//! [`find_code`] and [`explain`] are the registry of diagnostic codes, the `.par` files'
//! (`P…`, [`walls_par`]) among them; [`par`] is the one check of a `.par` file.
//!
//! The editor features are functions of an [`Analysis`] (a [`Checked`] file and its
//! [`Lines`]) and a byte offset or byte range, returning plain data whose positions are
//! byte ranges: [`hover`], [`completion`], [`inlay_hints`], [`semantic_tokens`],
//! [`definition`], [`symbols`], [`folding`], [`code_actions`], [`format`] and
//! [`format_range`]. Nothing here knows an editor protocol: converting byte offsets to
//! an editor's lines and columns (UTF-16 for LSP) is the client's business.
//!
//! "Which wall is at this offset" is a binary search over the walls' block ranges, the
//! source map the resolver records ([`walls_model::Wall::block`]).

mod actions;
mod check;
mod codes;
mod completion;
mod definition;
mod fix;
mod format;
mod hints;
mod hover;
mod lines;
mod locate;
mod outline;
pub mod par;
pub mod suppress;
mod tokens;

pub use actions::{Action, ActionKind, code_actions};
pub use check::{Analysis, Checked, check_bytes, check_text};
pub use codes::{all_codes, explain, explain_code, find_code};
pub use completion::{CompletionItem, CompletionKind, completion};
pub use definition::definition;
pub use fix::{Fixable, MAX_ROUNDS as MAX_FIX_ROUNDS, fix_rounds};
pub use format::{format, format_range};
pub use hints::{InlayHint, inlay_hints};
pub use hover::{Hover, hover};
pub use lines::Lines;
pub use outline::{MAX_DETAIL, Symbol, SymbolKind, folding, symbols};
pub use tokens::{Highlight, HighlightKind, semantic_tokens};
