//! What every picture refuses (docs/preview.md, "Numbers a picture cannot draw"): a
//! frame with a number that is not finite, or so large that drawing it would overflow.
//!
//! Every writer projects the walls' meshes and the particles it is given (SVG onto the
//! screen, POV-Ray and the HTML page about the scene's centre in units of its size, VTK
//! into the units asked for), and those projections take differences, products and
//! squares of lengths. [`check`] is the one test of a movie's frames before any of that:
//! every number of every frame finite, and every length, time, mass, velocity and spin
//! within ±[`LIMIT`] (pkdgrav units), where every product and square the drawing takes,
//! and every conversion to cgs or SI units, stays finite. Every writer calls it (or
//! [`check_frame`] for its one frame) before it writes a byte, so that a refused
//! picture leaves nothing half written; `walls-sim preview` calls it before it opens a
//! file, and names the wall's line in the walls file.

use crate::{MovieFrame, WallMesh};
use nalgebra::Vector3;
use std::fmt;
use walls_geometry::Particle;
use walls_keywords::WallType;

type Vec3 = Vector3<f64>;

/// The largest magnitude of a number a picture draws (pkdgrav units): its square,
/// 1e300, and its product with any unit's factor (cgs grams per solar mass, 2e33) are
/// still doubles.
pub const LIMIT: f64 = 1e150;

/// What holds the number a picture cannot draw.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Subject {
    /// A wall, by its index in the scene.
    Wall {
        /// Its index (pkdgrav's wall id, from 0).
        index: usize,
        /// Its type.
        wall_type: WallType,
    },
    /// A particle, by its index (pkdgrav's original index).
    Particle {
        /// Its index.
        index: i32,
    },
    /// The frame itself (its time).
    Frame,
    /// The box the picture frames.
    Box,
    /// The view (POV-Ray's camera from an ssdraw.par).
    View,
}

/// A frame a picture refuses: what holds the number, which of its numbers, the value,
/// and when.
#[derive(Debug, Clone, PartialEq)]
pub struct NotDrawable {
    /// The wall, particle or frame.
    pub subject: Subject,
    /// Which of its numbers: "a vertex of its mesh", "its position", …
    pub part: &'static str,
    /// The value (NaN, an infinity, or beyond ±[`LIMIT`]).
    pub value: f64,
    /// The frame's time (pkdgrav units).
    pub t: f64,
    /// The frame's step, when it has one.
    pub step: Option<u64>,
    /// The frame's number (from 1) and the number of frames, for a movie.
    pub frame: Option<(usize, usize)>,
}

impl fmt::Display for NotDrawable {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.subject {
            Subject::Wall { index, wall_type } => write!(f, "wall {index} ({})", wall_type.name())?,
            Subject::Particle { index } => write!(f, "particle {index}")?,
            Subject::Frame => write!(f, "the frame")?,
            Subject::Box => write!(f, "the picture's box")?,
            Subject::View => write!(f, "the view")?,
        }
        // The time as written, or in exponent form when that is long (1e200).
        let t = format!("{}", self.t);
        if t.len() <= 20 {
            write!(f, " at t = {t}")?;
        } else {
            write!(f, " at t = {:e}", self.t)?;
        }
        match (self.frame, self.step) {
            (Some((k, n)), Some(step)) => write!(f, " (frame {k} of {n}, step {step})")?,
            (Some((k, n)), None) => write!(f, " (frame {k} of {n})")?,
            (None, Some(step)) => write!(f, " (step {step})")?,
            (None, None) => {}
        }
        write!(f, ": {} is ", self.part)?;
        if self.value.is_nan() {
            write!(f, "NaN")
        } else if self.value.is_infinite() {
            write!(f, "{}infinite", if self.value < 0.0 { "-" } else { "" })
        } else {
            write!(
                f,
                "{:e}, beyond the ±{LIMIT:e} a picture can draw",
                self.value
            )
        }
    }
}

impl std::error::Error for NotDrawable {}

impl From<NotDrawable> for std::io::Error {
    fn from(e: NotDrawable) -> Self {
        std::io::Error::new(std::io::ErrorKind::InvalidData, e)
    }
}

/// Every frame of a movie (see the module documentation), in order: the first number
/// that cannot be drawn, with its frame's number when there are several.
pub fn check(frames: &[MovieFrame]) -> Result<(), NotDrawable> {
    let n = frames.len();
    frames.iter().enumerate().try_for_each(|(k, f)| {
        check_frame(f.t, &f.walls, &f.particles).map_err(|e| NotDrawable {
            step: f.step,
            frame: (n > 1).then_some((k + 1, n)),
            ..e
        })
    })
}

/// One frame at time `t`: its walls (every one, drawn or not: VTK writes them all) and
/// its particles.
pub fn check_frame(t: f64, walls: &[WallMesh], particles: &[Particle]) -> Result<(), NotDrawable> {
    let refuse = |subject, part, value| NotDrawable {
        subject,
        part,
        value,
        t,
        step: None,
        frame: None,
    };
    if !within(t) {
        return Err(refuse(Subject::Frame, "its time", t));
    }
    for w in walls {
        let subject = Subject::Wall {
            index: w.wall,
            wall_type: w.wall_type,
        };
        let found = first_beyond(w.mesh.positions.iter().flat_map(|p| p.iter()))
            .map(|x| ("a vertex of its mesh", x))
            .or_else(|| first_beyond(w.origin.iter()).map(|x| ("its origin", x)))
            .or_else(|| first_beyond(w.turn.matrix().iter()).map(|x| ("its turn", x)))
            .or_else(|| first_beyond([w.opacity].iter()).map(|x| ("its opacity", x)));
        if let Some((part, value)) = found {
            return Err(refuse(subject, part, value));
        }
    }
    for p in particles {
        let subject = Subject::Particle { index: p.index };
        let vectors = [
            ("its position", &p.pos),
            ("its velocity", &p.vel),
            ("its spin", &p.spin),
        ];
        let found = vectors
            .iter()
            .find_map(|(part, v)| first_beyond(v.iter()).map(|x| (*part, x)))
            .or_else(|| first_beyond([p.radius].iter()).map(|x| ("its radius", x)))
            .or_else(|| first_beyond([p.mass].iter()).map(|x| ("its mass", x)));
        if let Some((part, value)) = found {
            return Err(refuse(subject, part, value));
        }
    }
    Ok(())
}

/// The box `lo`–`hi` a picture frames (the movie's), at the first frame's time `t`.
pub fn check_box(bounds: &(Vec3, Vec3), t: f64) -> Result<(), NotDrawable> {
    match first_beyond(bounds.0.iter().chain(bounds.1.iter())) {
        Some(value) => Err(NotDrawable {
            subject: Subject::Box,
            part: "a corner",
            value,
            t,
            step: None,
            frame: None,
        }),
        None => Ok(()),
    }
}

/// Whether `x` is a number a picture draws: finite and within ±[`LIMIT`].
fn within(x: f64) -> bool {
    x.abs() <= LIMIT
}

/// The first of `xs` that is not [`within`] the limit.
fn first_beyond<'a>(xs: impl IntoIterator<Item = &'a f64>) -> Option<f64> {
    xs.into_iter().copied().find(|x| !within(*x))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::wall_meshes;
    use walls_test_support::model_scene as scene;

    #[test]
    fn a_plane_far_out_is_refused_with_its_wall_and_time() {
        let s = scene("wall type plane\n  origin 1e308 1e308 1e308\n");
        let walls = wall_meshes(&s, 0.0, 8);
        let e = check_frame(0.0, &walls, &[]).unwrap_err();
        assert_eq!(
            e.subject,
            Subject::Wall {
                index: 0,
                wall_type: WallType::Plane
            }
        );
        assert_eq!(
            e.to_string(),
            "wall 0 (plane) at t = 0: a vertex of its mesh is NaN"
        );
    }

    #[test]
    fn a_particle_is_named_with_its_frame() {
        let ok = Particle::at_rest(0.1, Vec3::zeros(), 3);
        let mut far = ok.clone();
        far.index = 7;
        far.pos.x = 2e150;
        let frame = |t: f64, particles: Vec<Particle>| MovieFrame {
            t,
            step: Some(100),
            walls: Vec::new(),
            particles,
        };
        let frames = [frame(0.0, vec![ok.clone()]), frame(0.5, vec![ok, far])];
        assert_eq!(
            check(&frames).unwrap_err().to_string(),
            "particle 7 at t = 0.5 (frame 2 of 2, step 100): its position is 2e150, beyond \
             the ±1e150 a picture can draw"
        );
        let mut slow = Particle::at_rest(0.1, Vec3::zeros(), 0);
        slow.vel.y = f64::NEG_INFINITY;
        assert_eq!(
            check_frame(1.0, &[], &[slow]).unwrap_err().to_string(),
            "particle 0 at t = 1: its velocity is -infinite"
        );
    }

    #[test]
    fn ordinary_scenes_and_tiny_units_pass() {
        let s = scene(
            "lengthunit 6.68445e-14\nwall type shell\n  radius 1\nwall type plane\n  origin 0 0 -1\n",
        );
        assert_eq!(check_frame(0.0, &wall_meshes(&s, 0.0, 8), &[]), Ok(()));
        let e = check_box(&(Vec3::zeros(), Vec3::repeat(f64::INFINITY)), 0.0).unwrap_err();
        assert_eq!(
            e.to_string(),
            "the picture's box at t = 0: a corner is infinite"
        );
    }
}
