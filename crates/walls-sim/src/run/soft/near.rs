//! The walls near each particle of the soft-sphere run (a Verlet list of walls,
//! [`NearWalls`]), found with the candidate pairs ([`PairList`]) and found again with
//! them: through the wall index among many bounded walls (a mesh), else by looking at
//! every wall.

use super::numbering::Numbering;
use super::{State, WallNow};
use crate::broad::pairs::PairList;
use crate::broad::wall_index::WallIndex;
use nalgebra::Vector3;

type Vec3 = Vector3<f64>;

/// The walls within reach of each particle, found when the candidate pairs are (a
/// Verlet list of walls): a particle moves at most half the skin before they are found
/// again, and so does a wall that translates (the lists are found again when one has),
/// so a fixed wall farther than the particle's radius and half the skin when they were,
/// or a translating one farther than its radius and the skin, cannot touch it. The
/// walls of reactive assemblies, which turn as well, are visited by every particle. With
/// a wall index (the plan's, among many bounded walls), each particle's are found among
/// the index's candidates within its widest reach, so that a list costs a query of the
/// index per particle at each rebuild rather than one at every step.
pub(super) struct NearWalls {
    /// Whether each wall is kept in the lists: every wall but those of reactive
    /// assemblies.
    listed: Vec<bool>,
    /// Whether each wall translates.
    translating: Vec<bool>,
    /// The walls of reactive assemblies.
    pub(super) moving: Vec<usize>,
    /// The listed walls that translate, whose moves the lists must follow.
    sliding: Vec<usize>,
    /// Each wall's origin when the lists were found.
    built_origins: Vec<Vec3>,
    /// Where each particle's walls start in `walls` (one more entry than particles).
    starts: Vec<u32>,
    walls: Vec<usize>,
    /// The wall index the lists are found through, when the plan uses one.
    index: Option<WallIndex>,
}

impl NearWalls {
    pub(super) fn new(
        listed: Vec<bool>,
        translating: Vec<bool>,
        index: Option<WallIndex>,
    ) -> NearWalls {
        let moving = (0..listed.len()).filter(|&w| !listed[w]).collect();
        let sliding = (0..listed.len())
            .filter(|&w| listed[w] && translating[w])
            .collect();
        NearWalls {
            listed,
            translating,
            moving,
            sliding,
            built_origins: Vec::new(),
            starts: Vec::new(),
            walls: Vec::new(),
            index,
        }
    }

    /// The listed walls within reach of each particle in the run, `half` (half the
    /// skin) beyond its radius for a fixed wall and twice that for a translating one,
    /// in ascending order.
    pub(super) fn build(&mut self, states: &[State], walls: &[WallNow], half: f64) {
        let NearWalls {
            listed,
            translating,
            built_origins,
            starts,
            walls: near,
            index,
            ..
        } = self;
        built_origins.clear();
        built_origins.extend(walls.iter().map(|w| w.origin));
        starts.clear();
        near.clear();
        starts.push(0);
        for s in states {
            if s.alive {
                let (pos, r) = (&s.particle.pos, s.particle.radius);
                let particle = (pos, r, half);
                match index {
                    // The index's candidates come ascending, each once.
                    Some(index) => {
                        let test = |w| {
                            if within_reach(w, particle, listed, translating, walls) {
                                near.push(w);
                            }
                        };
                        index.for_each_candidate(pos, r + 2.0 * half, built_origins, test)
                    }
                    // A plain loop, the test inlined always (as a closure, the
                    // compiler at times made it a call for each wall and particle).
                    None => {
                        for w in 0..walls.len() {
                            if within_reach(w, particle, listed, translating, walls) {
                                near.push(w);
                            }
                        }
                    }
                }
            }
            starts.push(near.len() as u32);
        }
    }

    /// Whether a listed wall has translated more than `half` since the lists were
    /// found.
    pub(super) fn moved(&self, walls: &[WallNow], half: f64) -> bool {
        self.sliding.iter().any(|&w| {
            let d2 = (walls[w].origin - self.built_origins[w]).norm_squared();
            d2 > half * half || d2.is_nan()
        })
    }

    /// The listed walls near particle `i`.
    #[inline]
    pub(super) fn listed_of(&self, i: usize) -> &[usize] {
        &self.walls[self.starts[i] as usize..self.starts[i + 1] as usize]
    }
}

/// Whether wall `w` is listed and within reach of a particle at `pos` of radius `r`:
/// `half` (half the skin) beyond its radius for a fixed wall, twice that for a
/// translating one ([`NearWalls::build`]).
#[inline(always)]
fn within_reach(
    w: usize,
    (pos, r, half): (&Vec3, f64, f64),
    listed: &[bool],
    translating: &[bool],
    walls: &[WallNow],
) -> bool {
    let reach = if translating[w] {
        r + 2.0 * half
    } else {
        r + half
    };
    listed[w] && !walls[w].cull.clear_of(pos, reach)
}

/// The candidate pairs (when wanted) and the walls near each particle (when kept) found
/// where the particles are now, against the walls as they stand.
pub(super) fn build_lists(
    candidates: &mut PairList,
    near: &mut Option<NearWalls>,
    (states, numbering): (&[State], &Numbering),
    walls: &[WallNow],
) {
    if let Some(near) = near {
        near.build(states, walls, candidates.skin / 2.0);
    }
    // Each particle ranked by its number in the file: the pairs come in the file's order.
    candidates.build(states, |place| numbering.file(place) as u32);
}

/// Finds the lists again ([`build_lists`]) if some particle (free, or carried by its
/// wall) has moved more than half the skin, or a listed wall has translated that far
/// ([`PairList::stale`]).
pub(super) fn update_lists(
    candidates: &mut PairList,
    near: &mut Option<NearWalls>,
    (states, numbering): (&[State], &Numbering),
    walls: &[WallNow],
) {
    if !candidates.wanted && near.is_none() {
        return;
    }
    let walls_moved = (near.as_ref()).is_some_and(|n| n.moved(walls, candidates.skin / 2.0));
    if candidates.stale(states, walls_moved) {
        build_lists(candidates, near, (states, numbering), walls);
    }
}
