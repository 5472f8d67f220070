//! Walls from walls-file text that must parse cleanly, as the back end reads them
//! (typed, decoded once) or as the model resolves them.

use walls_geometry::{Wall, decode};
use walls_keywords::ContactModel;
use walls_model::{Options, Scene, analyze};

/// The scene of `text` resolved with `options`; the text must parse without syntax
/// diagnostics.
fn resolved(text: &str, options: &Options) -> Scene {
    let parsed = walls_syntax::parse(text);
    assert!(parsed.diagnostics.is_empty(), "{:?}", parsed.diagnostics);
    analyze(&parsed.tree, options).scene
}

/// The model's scene of `text` with the default options (soft-sphere mode); the text
/// must parse without syntax diagnostics.
pub fn model_scene(text: &str) -> Scene {
    resolved(text, &Options::default())
}

/// The walls of `text` in the soft-sphere mode; the text must parse without syntax
/// diagnostics.
pub fn scene(text: &str) -> Vec<Wall> {
    scene_in(text, ContactModel::Ssdem)
}

/// The walls of `text` checked in `mode`; the text must parse without syntax
/// diagnostics.
pub fn scene_in(text: &str, mode: ContactModel) -> Vec<Wall> {
    let options = Options {
        mode,
        ..Options::default()
    };
    decode(&resolved(text, &options))
}

/// The walls of `text` in the soft-sphere mode, all of them: without pkdgrav's cap on
/// their number (`max_walls`), for hulls of thousands of triangles. The text must parse
/// without syntax diagnostics.
pub fn scene_uncapped(text: &str) -> Vec<Wall> {
    let options = Options {
        max_walls: usize::MAX,
        ..Options::default()
    };
    decode(&resolved(text, &options))
}
