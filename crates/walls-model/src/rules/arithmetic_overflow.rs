//! C121 `arithmetic-overflow`: a length or speed so large that pkdgrav's arithmetic with
//! it overflows a double.
//!
//! Checked per wall on the values in pkdgrav units (after C120, which leaves out a value
//! that is already infinite): each length and speed token the wall's type uses, and the
//! speeds its motion makes of two tokens (the oscillation's A·ω, a round wall's rim
//! ang-speed·radius).
//!
//! The bound, [`LIMIT`] = 1e150, comes from what the geometry computes. A contact test
//! squares lengths: the distance from a particle to a point of the wall, |r − q|² summed
//! over three components, the radial distance ρ² against R², a point's |r − O|² against
//! (R + r)²; the points q are sums of a few tokens (a rectangle's corner is origin +
//! vertex1 + vertex2, a cylinder's rim origin ± ½·length·orient + radius). The speeds
//! are squared alike (the relative velocity of particle and wall, v − V, in the dashpot
//! and the hard-sphere bounce). A square overflows past √(1.8e308) ≈ 1.3e154; a sum of
//! n terms each below L squares below 3·(nL)². At 1e150 the squares stay below 1e301 with
//! room for sums of up to about a thousand such terms, and no length pkdgrav is meant for
//! (its unit is the AU) comes near.

use crate::check::Checker;
use crate::scene::{Value, Wall};
use std::ops::Range;
use walls_diagnostics::{Code, Diagnostic};
use walls_keywords::{Dimension, Keyword, WallType};

/// A length or speed so large that pkdgrav's arithmetic with it overflows a double.
pub static ARITHMETIC_OVERFLOW: Code = Code {
    id: "C121",
    name: "arithmetic-overflow",
    summary: "a length or speed so large that pkdgrav's arithmetic with it overflows",
    explanation: "pkdgrav's contact tests square lengths and speeds: the distance from a \
particle to the wall (|r − q|², over three components), a radius against the distance from \
the axis, the particles' speed relative to the wall. A length or speed above 1e150 in \
pkdgrav units (after the units are applied) has a square near the largest double (about \
1.8e308), and the sums pkdgrav squares overflow: a plane at `origin 1e308 1e308 1e308` is \
read, and every distance to it is infinite or NaN. The speeds a wall's motion makes of two \
tokens are checked too: the oscillation's osc-ampl·osc-freq and a round wall's rim, \
ang-speed·radius.

Bad:
```walls
wall type plane
  origin 1e308 1e308 1e308
```

Good:
```walls
wall type plane
  origin 1 1 1
```
",
};

/// The largest length or speed (pkdgrav units) whose squares, and the squares of the sums
/// pkdgrav forms of them, stay within a double.
pub const LIMIT: f64 = 1e150;

/// Reports each length and speed of `wall` (of type `t`) beyond [`LIMIT`].
pub(crate) fn check(cx: &mut Checker, wall: &Wall, t: WallType) {
    // One pass over what the wall sets; most values are small and end the look there.
    let mut rates = false;
    for (k, setting) in wall.settings.iter() {
        rates |= matches!(k, Keyword::OscFreq | Keyword::AngSpeed);
        let size = match setting.value {
            Value::Number(x) => x.abs(),
            Value::Vector(v) => v.x.abs().max(v.y.abs()).max(v.z.abs()),
            _ => continue,
        };
        if size <= LIMIT {
            continue;
        }
        let what = match k.dimension() {
            Dimension::Length => "length",
            Dimension::Velocity => "speed",
            _ => continue,
        };
        // A token the type ignores is C201's.
        if k.applies_to().contains(t)
            && let Some(span) = setting.source.span()
        {
            let message = format!(
                "`{}` is a {what} of {size:e} in pkdgrav units: pkdgrav's contact tests square it, beyond what a double holds",
                k.name()
            );
            report(cx, span, message, what);
        }
    }
    if !rates {
        return;
    }
    motion(cx, wall, t, Keyword::OscAmpl, Keyword::OscFreq);
    if matches!(
        t,
        WallType::Disk | WallType::CylinderInfinite | WallType::CylinderFinite | WallType::Shell
    ) {
        motion(cx, wall, t, Keyword::Radius, Keyword::AngSpeed);
    }
}

/// Reports the speed `length`·`rate` of `wall`'s motion beyond [`LIMIT`] (each factor
/// within it), at the rate's token.
fn motion(cx: &mut Checker, wall: &Wall, t: WallType, length: Keyword, rate: Keyword) {
    let Some(setting) = wall.settings.get(rate) else {
        return;
    };
    let (l, w) = (wall.number(length).abs(), wall.number(rate).abs());
    let speed = l * w;
    if l <= LIMIT
        && speed > LIMIT
        && rate.applies_to().contains(t)
        && let Some(span) = setting.source.span()
    {
        let message = format!(
            "wall {} moves at {}·{} = {speed:e} in pkdgrav units: pkdgrav squares its speed, beyond what a double holds",
            wall.index,
            length.name(),
            rate.name()
        );
        report(cx, span, message, "speed");
    }
}

/// Reports a `what` ("length", "speed") beyond the limit at `span`.
fn report(cx: &mut Checker, span: Range<usize>, message: String, what: &str) {
    let help =
        format!("keep every {what} below 1e150 in pkdgrav units: check the value, or its unit");
    cx.push(Diagnostic::error(&ARITHMETIC_OVERFLOW, span, message).with_help(help));
}
