//! A movie: the frames of a run, each the walls and particles at one time, as
//! `walls-sim preview` reads them from a run's outputs (docs/spec.md §2) and every
//! picture format draws them.

use crate::WallMesh;
use walls_geometry::Particle;

/// One frame: the walls and the particles at one time.
#[derive(Debug, Clone, PartialEq)]
pub struct MovieFrame {
    /// The time (pkdgrav units).
    pub t: f64,
    /// pkdgrav's step number, when the frame's file says it (`ss.00100`).
    pub step: Option<u64>,
    /// Every wall where it was then (moving walls from their motion, reactive walls
    /// from the run's `WALLSREACTviz.out`).
    pub walls: Vec<WallMesh>,
    /// The particles then; [`Particle::index`] is a particle's identity across frames
    /// (pkdgrav's original index), and a particle missing from a frame was not there.
    pub particles: Vec<Particle>,
}
