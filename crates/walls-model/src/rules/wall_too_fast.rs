//! C210 `wall-too-fast`: in SSDEM, a wall moves too far in one step against the smallest particle.
//!
//! Checked per wall in SSDEM when `--min-radius` is given.

use crate::ContactModel;
use crate::check::Checker;
use crate::fix;
use crate::scene::Wall;
use walls_diagnostics::{Code, Diagnostic};
use walls_keywords::{Keyword, WallType};

/// In SSDEM, a wall moves too far in one step against the smallest particle.
pub static WALL_TOO_FAST: Code = Code {
    id: "C210",
    name: "wall-too-fast",
    summary: "in SSDEM, a wall moves too far in one step against the smallest particle",
    explanation:
        "In SSDEM the wall's top speed (|velocity| + |osc-ampl·osc-freq| + |ang-speed|·radius)
times its update step (`step`, or the timestep `--dt` when step is 0) should be small
against the smallest particle radius, or overlaps grow large. Checked when
`--min-radius R` is given; the limit is 3 % of R, the first overlap pkdgrav warns about.
Spinning planes are not checked (their rim is at infinity).

Bad (with `--min-radius 0.01`):
```walls
wall type plane
  velocity 0 0 1
  step 0.01
```

Good:
```walls
wall type plane
  velocity 0 0 1
  step 0.0001
```
",
};

/// A wall may move this fraction of the smallest particle radius in one step.
pub const STEP_TRAVEL_FRACTION: f64 = 0.03;

/// Reports a wall whose top speed times its update step is large against the smallest
/// particle radius.
pub(crate) fn check(cx: &mut Checker, wall: &Wall, t: WallType) {
    let Some(min_radius) = cx.options.min_radius else {
        return;
    };
    if cx.options.mode != ContactModel::Ssdem {
        return;
    }
    let step = match wall.number(Keyword::Step) {
        s if s > 0.0 => s,
        _ => match cx.options.dt {
            Some(dt) => dt,
            None => return,
        },
    };
    let rim = match t {
        WallType::Disk
        | WallType::CylinderInfinite
        | WallType::CylinderFinite
        | WallType::Shell => wall.number(Keyword::AngSpeed).abs() * wall.number(Keyword::Radius),
        _ => 0.0,
    };
    let linear = wall.vector(Keyword::Velocity).norm();
    let osc = (wall.number(Keyword::OscAmpl) * wall.number(Keyword::OscFreq)).abs();
    let speed = linear + osc + rim;
    let travel = speed * step;
    if travel > STEP_TRAVEL_FRACTION * min_radius {
        cx.push(
            Diagnostic::warning(
                &WALL_TOO_FAST,
                wall.span.clone(),
                format!(
                    "wall {} moves up to {} per step ({} × step {}), more than {}% of the smallest particle radius {}",
                    wall.index,
                    fix::rounded(travel),
                    fix::rounded(speed),
                    fix::rounded(step),
                    STEP_TRAVEL_FRACTION * 100.0,
                    fix::rounded(min_radius)
                ),
            )
            .with_help(format!(
                "speed = |velocity| {} + |osc-ampl·osc-freq| {} + |ang-speed|·radius {}; use a smaller step",
                fix::rounded(linear),
                fix::rounded(osc),
                fix::rounded(rim)
            )),
        );
    }
}
