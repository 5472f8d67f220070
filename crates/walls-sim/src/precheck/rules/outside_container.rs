//! R003 `outside-container`: a particle outside a closed container that holds the
//! others.
//!
//! Kept to what can be told for sure: only walls that close a region whatever the
//! particles do (an infinite cylinder, a shell with no opening) are containers, one
//! holds the particles when at least nine in ten of them lie wholly inside it (and two
//! at least), and a particle is reported only when it lies wholly outside (not touching
//! it: a contact is R002's). A container that holds fewer is no finding at all: particles
//! on both sides of a wall may be meant.

use crate::precheck::{Context, Findings, capped};
use walls_diagnostics::{Diagnostic, Severity};
use walls_geometry::Shape;

pub use walls_par::run_codes::outside_container::OUTSIDE_CONTAINER;

/// Where a particle of radius `r` at `p` lies with respect to a closed wall: `Some(true)`
/// wholly inside, `Some(false)` wholly outside, `None` touching it or not closed.
fn side(shape: &Shape, p: &nalgebra::Vector3<f64>, r: f64) -> Option<bool> {
    let (distance, radius) = match shape {
        Shape::InfiniteCylinder(c) => {
            let axis = c.axis.try_normalize(0.0)?;
            let d = p - c.origin;
            ((d - axis * axis.dot(&d)).norm(), c.radius.abs())
        }
        Shape::Shell(s) if s.open == 0.0 => ((p - s.center).norm(), s.radius.abs()),
        _ => return None,
    };
    if !(distance.is_finite() && radius > 0.0) {
        return None;
    }
    if distance + r < radius {
        Some(true)
    } else if distance - r > radius {
        Some(false)
    } else {
        None
    }
}

/// Reports the particles outside a container that holds nine in ten of them.
pub(crate) fn check(cx: &Context, out: &mut Findings) {
    let Some(ss) = cx.particles() else { return };
    let n = ss.particles.len();
    let mut found = Vec::new();
    let mut reported = vec![false; 0];
    for (w, wall) in cx.walls.iter().enumerate() {
        let sides: Vec<Option<bool>> = (ss.particles.iter().enumerate())
            .map(|(k, p)| side(&wall.shape, &p.pos, cx.radii[k]))
            .collect();
        let inside = sides.iter().filter(|s| **s == Some(true)).count();
        if sides.iter().all(Option::is_none) || inside < 2 || 10 * inside < 9 * n {
            continue;
        }
        if reported.is_empty() {
            reported = vec![false; n];
        }
        for (k, s) in sides.iter().enumerate() {
            if *s != Some(false) || reported[k] {
                continue;
            }
            reported[k] = true;
            found.push(
                Diagnostic::new(
                    &OUTSIDE_CONTAINER,
                    Severity::Warning,
                    ss.span(k),
                    format!(
                        "particle {k} lies outside {}, which holds {inside} of the {n} particles: it never meets them",
                        cx.wall_name(w)
                    ),
                )
                .in_record("particle", k)
                .with_help("place it inside with the others, or leave it out of the initial conditions"),
            );
        }
    }
    found.sort_by_key(|d| d.span.start);
    let total = found.len();
    out.particles.extend(capped(
        found,
        total,
        &OUTSIDE_CONTAINER,
        "particles outside containers",
    ));
}
