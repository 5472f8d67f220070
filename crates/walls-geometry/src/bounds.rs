//! The scene's box: the size every preview frames, planes are cut to and the embedded
//! particles are scaled by. It is the box around what has an extent, the finite walls
//! (where they are at the times asked) and the particles, with no minimum size, so that
//! a 5 cm tube in AU (`lengthunit 6.68e-14`) gives a box 3.7e-13 across. A plane within
//! the box's size of its centre (a floor) stretches it to reach the plane; an infinite
//! cylinder widens it to its cross-section there (it is usually the container). Planes
//! and infinite cylinders are then cut to the box. Only a scene with nothing finite falls back on the
//! box around its infinite walls' origins, one of the file's length units across.

use crate::shape::rim_bounds;
use crate::{Particle, Wall};
use nalgebra::Vector3;

type Vec3 = Vector3<f64>;

/// A box that grows to hold what is added.
#[derive(Debug, Clone, Copy)]
struct Grow {
    lo: Vec3,
    hi: Vec3,
}

impl Grow {
    fn empty() -> Grow {
        Grow {
            lo: Vec3::repeat(f64::INFINITY),
            hi: Vec3::repeat(f64::NEG_INFINITY),
        }
    }

    fn add(&mut self, lo: Vec3, hi: Vec3) {
        if lo.iter().chain(hi.iter()).all(|x| x.is_finite()) {
            self.lo = self.lo.inf(&lo);
            self.hi = self.hi.sup(&hi);
        }
    }

    fn is_empty(&self) -> bool {
        !self.lo.iter().all(|x| x.is_finite())
    }
}

/// The box around `walls` at t = 0 and `particles` (see the module documentation).
pub fn scene_bounds(walls: &[Wall], particles: &[Particle]) -> (Vec3, Vec3) {
    scene_bounds_at(walls, particles, &[0.0])
}

/// The box around `walls` where they are at each of `times` and `particles`: a moving
/// scene's box over a span (see the module documentation). The particles may be those
/// of many frames, read in place.
pub fn scene_bounds_at<'a>(
    walls: &[Wall],
    particles: impl IntoIterator<Item = &'a Particle>,
    times: &[f64],
) -> (Vec3, Vec3) {
    let mut b = Grow::empty();
    for w in walls.iter().filter(|w| !w.shape.is_infinite()) {
        // A wall that does not translate is where it is at every time: once is enough
        // (a hull of 10⁵ triangles in a movie of 10³ frames).
        let times = if w.motion.translates() {
            times
        } else {
            &times[..times.len().min(1)]
        };
        for &t in times {
            let shape = w.shape.at(w.motion.position_or_origin(t));
            let (lo, hi) = shape.bounds().unwrap_or_else(|| shape.extent());
            b.add(lo, hi);
        }
    }
    for p in particles {
        let r = Vec3::repeat(p.radius.abs());
        b.add(p.pos - r, p.pos + r);
    }
    // The file's length unit, the scale it speaks in: the largest in force for a wall.
    let unit = walls
        .iter()
        .map(|w| w.units.length)
        .fold(None, |m: Option<f64>, u| Some(m.map_or(u, |m| m.max(u))))
        .unwrap_or(1.0);
    if b.is_empty() {
        for w in walls {
            let o = w.origin_at_start();
            b.add(o, o);
        }
        if b.is_empty() {
            b.add(Vec3::zeros(), Vec3::zeros());
        }
        let centre = (b.lo + b.hi) / 2.0;
        let half = ((b.hi - b.lo) / 2.0).sup(&Vec3::repeat(unit / 2.0));
        return (centre - half, centre + half);
    }
    // A plane near the scene (the floor the particles rest on, within the box's size of
    // its centre) reaches into the box: the box grows to the point of the plane under
    // its centre. A distant plane (a catch-all death plane far below) does not.
    let centre = (b.lo + b.hi) / 2.0;
    let size = (b.hi - b.lo).max();
    for w in walls {
        if let crate::Shape::Plane(p) = w.shape.at(w.origin_at_start()) {
            let height = p.normal.dot(&(centre - p.origin));
            if height.abs() <= size {
                let q = centre - p.normal * height;
                b.add(q, q);
            }
        }
    }
    // An infinite cylinder around the scene (a container) widens the box to its cross
    // section where its axis passes the box's centre; along its axis it is cut.
    let centre = (b.lo + b.hi) / 2.0;
    for w in walls {
        if let crate::Shape::InfiniteCylinder(c) = w.shape.at(w.origin_at_start()) {
            let along = (centre - c.origin).dot(&c.axis);
            let (lo, hi) = rim_bounds(&(c.origin + along * c.axis), &c.axis, c.radius.abs());
            b.add(lo, hi);
        }
    }
    // A box flat along some axis (a floor of rectangles, one particle of radius 0) gets
    // a hundredth of its size there, so that the planes cut through it cleanly.
    let size = (b.hi - b.lo).max();
    let size = if size > 0.0 { size } else { unit };
    let centre = (b.lo + b.hi) / 2.0;
    let half = ((b.hi - b.lo) / 2.0).sup(&Vec3::repeat(size / 200.0));
    (centre - half, centre + half)
}
