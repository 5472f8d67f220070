//! C209 `too-many-walls`: more walls than pkdgrav's compile-time limit.
//!
//! Checked once per file, against `--max-walls`.

use crate::check::Checker;
use crate::scene::Scene;
use walls_diagnostics::{Code, Diagnostic};

/// More walls than pkdgrav's compile-time limit.
pub static TOO_MANY_WALLS: Code = Code {
    id: "C209",
    name: "too-many-walls",
    summary: "more walls than pkdgrav's compile-time limit",
    explanation:
        "pkdgrav holds at most MAX_NUM_WALLS walls, 20 unless it was compiled with more. Set the
limit of your build with `--max-walls N`.

Bad (with `--max-walls 1`):
```walls
wall type plane
wall type disk
```

Good:
```walls
wall type plane
```
",
};

/// Reports the first wall past pkdgrav's limit.
pub(crate) fn check(cx: &mut Checker, scene: &Scene) {
    let max = cx.options.max_walls;
    if let Some(wall) = scene.walls.get(max) {
        cx.push(
            Diagnostic::warning(
                &TOO_MANY_WALLS,
                wall.span.clone(),
                format!(
                    "{} walls, more than the {max} pkdgrav holds (MAX_NUM_WALLS); this is wall {}",
                    scene.walls.len(),
                    wall.index
                ),
            )
            .with_help(
                "if your pkdgrav was compiled with a larger MAX_NUM_WALLS, pass it as --max-walls",
            ),
        );
    }
}
