//! Orienting a mesh (a consistent winding across shared edges, then each connected piece
//! turned by the sign of the volume it encloses) and finding the pairs of triangles that
//! make a rectangle.

use super::{Mesh, Problem, cross, dot, norm, sub};
use std::collections::HashMap;
use walls_model::RECTANGLE_COS_TOLERANCE;

/// How far (relative to the diagonal) two triangles may be from coplanar, and the
/// corner opposite a right angle from where a rectangle's fourth corner would be, to be
/// merged into one rectangle.
pub const MERGE_TOLERANCE: f64 = 1e-6;

/// The faces on each undirected edge (its two vertices, smaller first), in face order.
fn edge_faces(windings: &[[usize; 3]]) -> HashMap<(usize, usize), Vec<usize>> {
    let mut edges: HashMap<(usize, usize), Vec<usize>> = HashMap::new();
    for (f, w) in windings.iter().enumerate() {
        for (a, b) in directed(*w) {
            edges.entry(key(a, b)).or_default().push(f);
        }
    }
    edges
}

/// A triangle's three directed edges.
fn directed(w: [usize; 3]) -> [(usize, usize); 3] {
    [(w[0], w[1]), (w[1], w[2]), (w[2], w[0])]
}

fn key(a: usize, b: usize) -> (usize, usize) {
    (a.min(b), a.max(b))
}

/// Whether the winding `w` runs along the edge from `a` to `b`.
fn runs(w: [usize; 3], a: usize, b: usize) -> bool {
    directed(w).contains(&(a, b))
}

/// The windings of `mesh`'s faces, consistent across every shared edge and with each
/// connected piece facing out of (`outward`) or into the volume it encloses.
pub(super) fn orient(mesh: &Mesh, outward: bool) -> Result<Vec<[usize; 3]>, Problem> {
    let faces = &mesh.faces;
    let given: Vec<[usize; 3]> = faces.iter().map(|f| f.vertices).collect();
    let edges = edge_faces(&given);
    let edge_problem = |f: usize, (a, b): (usize, usize), what: String| {
        Problem::at(
            faces[f].origin,
            format!(
                "the edge between vertices {} and {} {what}",
                mesh.vertex_name(a),
                mesh.vertex_name(b)
            ),
        )
    };
    for (f, w) in given.iter().enumerate() {
        for (a, b) in directed(*w) {
            match edges[&key(a, b)].len() {
                1 => return Err(edge_problem(f, (a, b), "belongs to this face only: the mesh is open, so it has no inside to face; keep the orientation as it is, or close the mesh".into())),
                2 => {}
                n => return Err(edge_problem(f, (a, b), format!("belongs to {n} faces: the mesh has no single inside to face"))),
            }
        }
    }
    // Flip each face or not, spreading from a first face across shared edges: a
    // neighbour must run along the edge the other way.
    let mut flipped: Vec<Option<bool>> = vec![None; faces.len()];
    let mut windings = given.clone();
    for seed in 0..faces.len() {
        if flipped[seed].is_some() {
            continue;
        }
        flipped[seed] = Some(false);
        let mut piece = vec![seed];
        let mut next = 0;
        while let Some(&f) = piece.get(next) {
            next += 1;
            for (a, b) in directed(windings[f]) {
                for &g in &edges[&key(a, b)] {
                    if g == f {
                        continue;
                    }
                    let flip = runs(given[g], a, b);
                    match flipped[g] {
                        None => {
                            flipped[g] = Some(flip);
                            if flip {
                                windings[g].swap(1, 2);
                            }
                            piece.push(g);
                        }
                        Some(done) if done != flip => {
                            return Err(edge_problem(g, (a, b), "joins faces that cannot all be wound the same way: the mesh is not orientable (like a Möbius strip), so it has no inside to face".into()));
                        }
                        Some(_) => {}
                    }
                }
            }
        }
        // Six times the enclosed volume, from a point of the piece to keep it exact.
        let o = mesh.vertices[windings[seed][0]];
        let volume: f64 = piece
            .iter()
            .map(|&f| {
                let [a, b, c] = windings[f].map(|i| sub(mesh.vertices[i], o));
                dot(a, cross(b, c))
            })
            .sum();
        if volume == 0.0 {
            return Err(Problem::at(
                faces[seed].origin,
                "the closed piece of the mesh with this face encloses no volume, so it has no inside to face",
            ));
        }
        if (volume > 0.0) != outward {
            for &f in &piece {
                windings[f].swap(1, 2);
            }
        }
    }
    Ok(windings)
}

/// A face's part in a rectangle.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Pair {
    /// The first face of a pair (in face order), with its right-angled corner (0, 1 or 2
    /// in its winding): the rectangle's wall stands in its place.
    First {
        /// The right angle's position in the winding.
        corner: usize,
    },
    /// The second face of a pair: no wall of its own.
    Second,
}

/// The faces that pair up into rectangles: two faces on a shared edge that is, for both,
/// the side opposite a right angle (|cos| ≤ walls-lint's 0.001 for rectangles), wound
/// the same way, coplanar, and whose far corners make a parallelogram with the edge.
pub(super) fn rectangles(mesh: &Mesh, windings: &[[usize; 3]]) -> Vec<Option<Pair>> {
    let edges = edge_faces(windings);
    let p = |i: usize| mesh.vertices[i];
    let mut pairs = vec![None; windings.len()];
    for f in 0..windings.len() {
        if pairs[f].is_some() {
            continue;
        }
        let Some(corner) = right_corner(windings[f].map(p)) else {
            continue;
        };
        let w = windings[f];
        let (u, v) = (w[(corner + 1) % 3], w[(corner + 2) % 3]);
        let [g] = edges[&key(u, v)]
            .iter()
            .copied()
            .filter(|&g| g != f)
            .collect::<Vec<_>>()[..]
        else {
            continue;
        };
        let wg = windings[g];
        let Some(other) = right_corner(wg.map(p)) else {
            continue;
        };
        let fits = pairs[g].is_none() && wg[other] != u && wg[other] != v && runs(wg, v, u) && {
            let diagonal = norm(sub(p(u), p(v)));
            let fourth = sub(sub(p(u), p(w[corner])), sub(p(wg[other]), p(v)));
            let nf = unit_normal(w.map(p));
            let ng = unit_normal(wg.map(p));
            norm(fourth) <= MERGE_TOLERANCE * diagonal && norm(sub(nf, ng)) <= MERGE_TOLERANCE
        };
        if fits {
            pairs[f] = Some(Pair::First { corner });
            pairs[g] = Some(Pair::Second);
        }
    }
    pairs
}

/// The corner of a triangle whose angle is right, within walls-lint's tolerance for a
/// rectangle's sides.
fn right_corner(t: [[f64; 3]; 3]) -> Option<usize> {
    (0..3).find(|&i| {
        let (a, b) = (sub(t[(i + 1) % 3], t[i]), sub(t[(i + 2) % 3], t[i]));
        (dot(a, b) / (norm(a) * norm(b))).abs() <= RECTANGLE_COS_TOLERANCE
    })
}

fn unit_normal(t: [[f64; 3]; 3]) -> [f64; 3] {
    let n = cross(sub(t[1], t[0]), sub(t[2], t[0]));
    let len = norm(n);
    n.map(|x| x / len)
}
