//! Which walls a particle could touch, without asking every wall: a bounding-volume
//! hierarchy (BVH) over the walls' axis-aligned boxes ([`walls_geometry::Shape::bounds`]).
//!
//! A query — every wall that could be within `reach` of a point — costs about the
//! logarithm of the wall count plus the walls returned, instead of one nearest-point
//! query per wall: near a hull of 10⁵ triangles a particle's walls are found in
//! 1.5 µs instead of 3.4 ms (`docs/charts/wall_scaling.png`).
//!
//! # Moving walls
//!
//! Walls only translate (docs/spec.md §1 "Motion": the spin never moves the drawn shape),
//! and a wall's displacement from its place at t = 0 depends on its motion values alone:
//! `velocity`, `osc-ampl`, `osc-freq`, `osc-phase`, `osc-vec` and `step`. So the walls
//! are grouped by motion — walls whose motion values are equal move together; every
//! static wall is in one group — and each group has its own hierarchy, built once over
//! the walls' shapes at t = 0. A group is queried with the point shifted back by the
//! group's displacement, read off one of its walls (its *representative*, the lowest
//! index): the origins passed to a query minus the origins at t = 0. Nothing is rebuilt
//! as the walls move, and a query costs one tree walk per group (a file of 10⁵ walls
//! each moving its own way would still cost 10⁵ box tests: every group is then a single
//! wall).
//!
//! Walls with no box — planes, infinite cylinders, degenerate polygons — and walls
//! whose box is not finite are candidates of every query.
//!
//! # The hierarchy
//!
//! Built top-down: each node's walls are split at the median of their boxes' centres
//! along the axis where those centres spread widest, down to leaves of at most
//! [`LEAF_SIZE`] walls. Median splits keep the tree balanced (depth ⌈log₂(N/4)⌉ + 1
//! whatever the walls' layout) and the build O(N log N); the nodes are stored flat,
//! each inner node followed by its left child.
//!
//! # Rounding
//!
//! Each wall's origin is computed on its own (and pkdgrav's stepping adds a step's
//! travel to it every step), so the walls of a group can drift apart from the
//! representative's displacement by rounding. Every query reaches further by
//! [`SLACK`] times the size of the coordinates involved (10⁻⁸ of them, some 10⁷ steps
//! of rounding at one unit in the last place each): candidates are a superset of the
//! walls within reach, never fewer.

use nalgebra::Vector3;
use std::collections::HashMap;
use walls_geometry::{Motion, Wall};

type Vec3 = Vector3<f64>;

/// The most walls a leaf of the hierarchy holds.
pub const LEAF_SIZE: usize = 4;

/// How much further than asked a query reaches, relative to the size of the
/// coordinates (see the module's "Rounding").
pub const SLACK: f64 = 1e-8;

/// One node of a hierarchy: its box, and either a leaf's walls or the index of its
/// right child (the left child is the next node).
#[derive(Debug, Clone)]
struct Node {
    lo: Vec3,
    hi: Vec3,
    /// A leaf's first wall in the group's `walls`; an inner node's right child.
    start: u32,
    /// A leaf's wall count; 0 for an inner node.
    count: u32,
}

/// Walls that move together, with their hierarchy at t = 0.
#[derive(Debug, Clone)]
struct Group {
    /// The lowest wall index of the group, whose origin gives the group's displacement.
    representative: usize,
    /// The representative's origin at t = 0.
    origin: Vec3,
    /// The walls, in leaf order.
    walls: Vec<u32>,
    nodes: Vec<Node>,
}

/// A wall's box and centre while the hierarchy is built.
#[derive(Debug, Clone, Copy)]
struct Item {
    wall: u32,
    lo: Vec3,
    hi: Vec3,
    centre: Vec3,
}

/// The walls of a scene in hierarchies, one for each group of walls that move together.
#[derive(Debug, Clone)]
pub struct WallIndex {
    /// Walls without a (finite) box, ascending: candidates of every query.
    always: Vec<usize>,
    groups: Vec<Group>,
    /// The walls' number.
    len: usize,
    /// The largest coordinate of any box at t = 0 or origin, for the slack.
    scale: f64,
}

/// Deepest a hierarchy can be: median splits of fewer than 2⁶⁰ walls stay far above.
const MAX_DEPTH: usize = 64;

impl WallIndex {
    /// Groups `walls` by motion and builds each group's hierarchy over the shapes at
    /// t = 0 (each wall's origin as [`Wall::origin_at_start`] places it).
    pub fn new(walls: &[Wall]) -> WallIndex {
        let origins: Vec<Vec3> = walls.iter().map(Wall::origin_at_start).collect();
        let mut always = Vec::new();
        let mut members: Vec<Vec<Item>> = Vec::new();
        let mut group_of: HashMap<MotionKey, usize> = HashMap::new();
        let mut scale = 0.0f64;
        for (w, (wall, origin)) in walls.iter().zip(&origins).enumerate() {
            scale = scale.max(finite_amax(origin));
            let bounds = wall
                .shape
                .at(*origin)
                .bounds()
                .filter(|(lo, hi)| lo.iter().chain(hi.iter()).all(|x| x.is_finite()));
            let Some((lo, hi)) = bounds else {
                always.push(w);
                continue;
            };
            scale = scale.max(lo.amax()).max(hi.amax());
            let g = *group_of
                .entry(MotionKey::of(&wall.motion))
                .or_insert_with(|| {
                    members.push(Vec::new());
                    members.len() - 1
                });
            members[g].push(Item {
                wall: w as u32,
                lo,
                hi,
                centre: (lo + hi) / 2.0,
            });
        }
        let groups = members
            .into_iter()
            .map(|mut items| {
                let representative = items[0].wall as usize;
                let mut nodes = Vec::with_capacity(2 * items.len() / LEAF_SIZE + 1);
                build(&mut items, 0, 1, &mut nodes);
                Group {
                    representative,
                    origin: origins[representative],
                    walls: items.iter().map(|i| i.wall).collect(),
                    nodes,
                }
            })
            .collect();
        WallIndex {
            always,
            groups,
            len: walls.len(),
            scale,
        }
    }

    /// The number of walls indexed.
    pub fn len(&self) -> usize {
        self.len
    }

    /// Whether there are no walls.
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// The groups of walls that move together (and have boxes): one hierarchy each.
    pub fn group_count(&self) -> usize {
        self.groups.len()
    }

    /// Each group's representative: its lowest wall index, whose origin gives the
    /// group's displacement and which [`WallIndex::for_each_candidate_by_group`]'s query
    /// is asked about.
    pub fn representatives(&self) -> impl Iterator<Item = usize> + '_ {
        self.groups.iter().map(|g| g.representative)
    }

    /// The walls without a finite box (planes, infinite cylinders, degenerate polygons),
    /// ascending: candidates of every query.
    pub fn unbounded(&self) -> &[usize] {
        &self.always
    }

    /// Calls `f`, in ascending order, with every wall that could be within `reach` of
    /// `p` when the walls' origins are at `origins` (indexed by wall; the positions at
    /// the time of the query). A superset: every wall whose nearest point is within
    /// `reach` is among them, and some a little further may be. A point or reach that is
    /// not a number makes every wall a candidate.
    ///
    /// # Panics
    ///
    /// If `origins` has fewer entries than there are walls.
    pub fn for_each_candidate(&self, p: &Vec3, reach: f64, origins: &[Vec3], f: impl FnMut(usize)) {
        self.for_each_candidate_by_group(origins, |_| (*p, reach), f);
    }

    /// [`WallIndex::for_each_candidate`] with a point and reach of its own for each
    /// group: `query(representative)` answers them for the group whose lowest wall is
    /// `representative` (the same for every wall of the group, as their motions are
    /// the same). For the hard-sphere prediction, where the point is the particle in the
    /// frame of the walls' motion over the step and the reach grows with the speed
    /// relative to them. Walls without a box are candidates whatever the query.
    ///
    /// # Panics
    ///
    /// If `origins` has fewer entries than there are walls.
    pub fn for_each_candidate_by_group(
        &self,
        origins: &[Vec3],
        mut query: impl FnMut(usize) -> (Vec3, f64),
        mut f: impl FnMut(usize),
    ) {
        let mut found = Found::new();
        for &w in &self.always {
            found.push(w as u32);
        }
        for g in &self.groups {
            let shift = origins[g.representative] - g.origin;
            let (p, reach) = query(g.representative);
            let slack = SLACK * (self.scale + finite_amax(&shift) + finite_amax(&p));
            let r = reach + slack;
            g.visit(&(p - shift), r * r, &mut found);
        }
        found.sorted(&mut f);
    }
}

impl Group {
    /// Adds to `found` the walls whose box is within √`r2` of `p` (`p` in the frame of
    /// the walls at t = 0). A comparison that is not a number visits.
    fn visit(&self, p: &Vec3, r2: f64, found: &mut Found) {
        let mut stack = [0u32; MAX_DEPTH];
        let mut top = 1;
        while top > 0 {
            top -= 1;
            let node = &self.nodes[stack[top] as usize];
            // Distance² from p to the box (written so that NaN visits).
            let below = node.lo - p;
            let above = p - node.hi;
            let d2: f64 = (0..3)
                .map(|i| {
                    let d = below[i].max(above[i]).max(0.0);
                    d * d
                })
                .sum();
            if d2 > r2 {
                continue;
            }
            if node.count > 0 {
                let start = node.start as usize;
                for &w in &self.walls[start..start + node.count as usize] {
                    found.push(w);
                }
            } else {
                let here = stack[top] as usize;
                stack[top] = node.start;
                stack[top + 1] = (here + 1) as u32;
                top += 2;
            }
        }
    }
}

/// Builds the hierarchy of `items` (which start at `first` in the group's walls, at
/// `depth`) into `nodes`: a leaf for a few walls, else a split at the median centre on
/// the axis where the centres spread widest. Returns the node's index.
fn build(items: &mut [Item], first: usize, depth: usize, nodes: &mut Vec<Node>) -> u32 {
    let (lo, hi) = items
        .iter()
        .fold((items[0].lo, items[0].hi), |(lo, hi), i| {
            (lo.inf(&i.lo), hi.sup(&i.hi))
        });
    let me = nodes.len();
    nodes.push(Node {
        lo,
        hi,
        start: first as u32,
        count: items.len() as u32,
    });
    if items.len() <= LEAF_SIZE {
        items.sort_unstable_by_key(|i| i.wall);
        return me as u32;
    }
    assert!(depth < MAX_DEPTH, "wall hierarchy deeper than {MAX_DEPTH}");
    let (clo, chi) = items
        .iter()
        .fold((items[0].centre, items[0].centre), |(lo, hi), i| {
            (lo.inf(&i.centre), hi.sup(&i.centre))
        });
    let axis = (chi - clo).imax();
    let mid = items.len() / 2;
    // Ties by wall index: the halves are the same however the selection goes.
    items.select_nth_unstable_by(mid, |a, b| {
        a.centre[axis]
            .total_cmp(&b.centre[axis])
            .then(a.wall.cmp(&b.wall))
    });
    let (left, right) = items.split_at_mut(mid);
    build(left, first, depth + 1, nodes);
    let right = build(right, first + mid, depth + 1, nodes);
    nodes[me].start = right;
    nodes[me].count = 0;
    me as u32
}

/// The candidates of one query, gathered without allocating while they are few, then
/// sorted.
struct Found {
    inline: [u32; 64],
    len: usize,
    spill: Vec<u32>,
}

impl Found {
    fn new() -> Found {
        Found {
            inline: [0; 64],
            len: 0,
            spill: Vec::new(),
        }
    }

    fn push(&mut self, w: u32) {
        if self.len < self.inline.len() {
            self.inline[self.len] = w;
            self.len += 1;
        } else {
            if self.spill.is_empty() {
                self.spill.extend_from_slice(&self.inline);
            }
            self.spill.push(w);
        }
    }

    /// Calls `f` with every wall, ascending.
    fn sorted(mut self, f: &mut impl FnMut(usize)) {
        let walls: &mut [u32] = if self.spill.is_empty() {
            &mut self.inline[..self.len]
        } else {
            &mut self.spill
        };
        walls.sort_unstable();
        for &w in walls.iter() {
            f(w as usize);
        }
    }
}

/// The largest finite |coordinate| of `v` (0 if none is finite).
fn finite_amax(v: &Vec3) -> f64 {
    v.iter()
        .filter(|x| x.is_finite())
        .fold(0.0, |m, x| m.max(x.abs()))
}

/// What a wall's displacement from its place at t = 0 depends on, as bits: walls with
/// equal keys move together. Values that cannot matter are zeroed (the oscillation's
/// when its amplitude is 0, the step of a wall that does not move), −0 counts as 0, and
/// the phase is taken within its cycle, as the motion takes it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
struct MotionKey([u64; 10]);

impl MotionKey {
    fn of(motion: &Motion) -> MotionKey {
        let velocity = motion.velocity;
        let o = &motion.oscillation;
        let amplitude = o.amplitude;
        let (freq, phase, vector) = if amplitude != 0.0 {
            (o.frequency, o.cycle(), o.direction)
        } else {
            (0.0, 0.0, Vec3::zeros())
        };
        let moves = amplitude != 0.0 || velocity != Vec3::zeros();
        let step = match motion.step {
            s if moves && s > 0.0 => s,
            _ => 0.0,
        };
        // Adding 0 turns −0 into +0.
        let bits = |x: f64| (x + 0.0).to_bits();
        MotionKey([
            bits(velocity.x),
            bits(velocity.y),
            bits(velocity.z),
            bits(amplitude),
            bits(freq),
            bits(phase),
            bits(vector.x),
            bits(vector.y),
            bits(vector.z),
            bits(step),
        ])
    }
}
