//! Meshes to walls: the triangle of each face, orientation outward and inward from
//! scrambled windings, open, non-manifold, non-orientable and degenerate meshes refused
//! by name, and rectangles merged only where two triangles make one.

use walls_build::mesh::{Mesh, MeshOptions, Orientation, to_walls};
use walls_build::{DumpOptions, Value, Wall, dumps};

/// The unit cube's corners: index x + 2y + 4z.
fn corners() -> Vec<[f64; 3]> {
    (0..8)
        .map(|i| [(i & 1) as f64, (i >> 1 & 1) as f64, (i >> 2 & 1) as f64])
        .collect()
}

/// The cube's 12 triangles, each facing out.
const CUBE: [[usize; 3]; 12] = [
    [0, 2, 3],
    [0, 3, 1],
    [4, 5, 7],
    [4, 7, 6],
    [0, 1, 5],
    [0, 5, 4],
    [2, 6, 7],
    [2, 7, 3],
    [0, 4, 6],
    [0, 6, 2],
    [1, 3, 7],
    [1, 7, 5],
];

/// The cube with every third face wound the other way.
fn scrambled_cube() -> Mesh {
    let faces: Vec<[usize; 3]> = CUBE
        .iter()
        .enumerate()
        .map(|(i, &[a, b, c])| if i % 3 == 0 { [a, c, b] } else { [a, b, c] })
        .collect();
    Mesh::from_arrays(corners(), &faces).unwrap()
}

fn vector(wall: &Wall, name: &str) -> [f64; 3] {
    match wall.get(name) {
        Some(Value::Vector(v)) => v,
        other => panic!("{name}: {other:?}"),
    }
}

/// For each wall, the sign of its normal (vertex1 × vertex2) along the line from the
/// cube's centre to its origin.
fn facing(walls: &[Wall]) -> Vec<f64> {
    walls
        .iter()
        .map(|w| {
            let [o, a, b] = ["origin", "vertex1", "vertex2"].map(|n| vector(w, n));
            let n = [
                a[1] * b[2] - a[2] * b[1],
                a[2] * b[0] - a[0] * b[2],
                a[0] * b[1] - a[1] * b[0],
            ];
            let out: f64 = (0..3)
                .map(|k| n[k] * (o[k] + a[k] / 3.0 + b[k] / 3.0 - 0.5))
                .sum();
            out.signum()
        })
        .collect()
}

fn options(orientation: Orientation, merge_rectangles: bool) -> MeshOptions {
    MeshOptions {
        orientation,
        merge_rectangles,
    }
}

#[test]
fn each_face_becomes_its_triangle() {
    let mesh = Mesh::from_arrays(
        vec![[1.0, 2.0, 3.0], [1.5, 2.0, 3.0], [1.0, 2.25, 3.0]],
        &[[0, 1, 2]],
    )
    .unwrap();
    let walls = to_walls(&mesh, &MeshOptions::default()).unwrap();
    let dumped = dumps(&walls, &DumpOptions::default()).unwrap();
    assert_eq!(
        dumped.text,
        "wall type triangle\n  origin 1 2 3\n  vertex1 0.5 0 0\n  vertex2 0 0.25 0\n"
    );
}

#[test]
fn keep_leaves_the_windings_as_they_are() {
    let walls = to_walls(&scrambled_cube(), &options(Orientation::Keep, false)).unwrap();
    let expected: Vec<f64> = (0..12)
        .map(|i| if i % 3 == 0 { -1.0 } else { 1.0 })
        .collect();
    assert_eq!(facing(&walls), expected);
}

#[test]
fn outward_and_inward_turn_every_face() {
    let mesh = scrambled_cube();
    let out = to_walls(&mesh, &options(Orientation::Outward, false)).unwrap();
    assert_eq!(facing(&out), vec![1.0; 12]);
    let inward = to_walls(&mesh, &options(Orientation::Inward, false)).unwrap();
    assert_eq!(facing(&inward), vec![-1.0; 12]);
}

#[test]
fn two_pieces_are_turned_each_by_its_own_volume() {
    // A second cube, 3 along x, given inside out.
    let mut vertices = corners();
    vertices.extend(corners().iter().map(|&[x, y, z]| [x + 3.0, y, z]));
    let mut faces = CUBE.to_vec();
    faces.extend(CUBE.iter().map(|&[a, b, c]| [a + 8, c + 8, b + 8]));
    let mesh = Mesh::from_arrays(vertices, &faces).unwrap();
    let walls = to_walls(&mesh, &options(Orientation::Outward, false)).unwrap();
    assert!(walls[12..].iter().all(|w| vector(w, "origin")[0] >= 3.0));
    let mut shifted = facing(&walls[..12]);
    // The second cube's centre is at x = 3.5: shift its walls back to reuse `facing`.
    let back: Vec<Wall> = walls[12..]
        .iter()
        .map(|w| {
            let o = vector(w, "origin");
            w.clone().with("origin", [o[0] - 3.0, o[1], o[2]]).unwrap()
        })
        .collect();
    shifted.extend(facing(&back));
    assert_eq!(shifted, vec![1.0; 24]);
}

#[test]
fn meshes_without_an_inside_are_refused_naming_the_edge() {
    let open = Mesh::from_arrays(corners(), &CUBE[..10]).unwrap();
    let error = to_walls(&open, &options(Orientation::Outward, false)).unwrap_err();
    assert_eq!(
        error.to_string(),
        "face 1: the edge between vertices 3 and 1 belongs to this face only: the mesh is open, so it has no inside to face; keep the orientation as it is, or close the mesh"
    );
    // Keeping the windings needs no inside.
    assert_eq!(
        to_walls(&open, &options(Orientation::Keep, false))
            .unwrap()
            .len(),
        10
    );

    let mut fin = CUBE.to_vec();
    let mut vertices = corners();
    vertices.push([-1.0, -1.0, 0.0]);
    fin.push([0, 8, 1]);
    let fin = Mesh::from_arrays(vertices, &fin).unwrap();
    assert_eq!(
        to_walls(&fin, &options(Orientation::Inward, false))
            .unwrap_err()
            .to_string(),
        "face 1: the edge between vertices 1 and 0 belongs to 3 faces: the mesh has no single inside to face"
    );

    // The projective plane in six points: closed, every edge on two faces, one side.
    let projective = Mesh::from_arrays(
        vec![
            [0.0, 0.0, 1.0],
            [1.0, 0.0, 0.0],
            [0.3, 1.0, 0.1],
            [-1.0, 0.4, 0.2],
            [-0.3, -1.0, 0.3],
            [0.8, -0.7, -0.5],
        ],
        &[
            [0, 1, 2],
            [0, 2, 3],
            [0, 3, 4],
            [0, 4, 5],
            [0, 5, 1],
            [1, 2, 4],
            [2, 3, 5],
            [3, 4, 1],
            [4, 5, 2],
            [5, 1, 3],
        ],
    )
    .unwrap();
    assert_eq!(
        to_walls(&projective, &options(Orientation::Outward, false))
            .unwrap_err()
            .to_string(),
        "face 8: the edge between vertices 4 and 5 joins faces that cannot all be wound the same way: the mesh is not orientable (like a Möbius strip), so it has no inside to face"
    );
}

#[test]
fn a_face_without_area_is_refused_by_name() {
    let mesh = Mesh::from_arrays(
        vec![[0.0; 3], [1.0, 1.0, 1.0], [2.0, 2.0, 2.0]],
        &[[0, 1, 2], [0, 0, 1]],
    )
    .unwrap();
    assert_eq!(
        to_walls(&mesh, &MeshOptions::default())
            .unwrap_err()
            .to_string(),
        "face 0: the face with vertices 0, 1 and 2 has no area"
    );
    assert_eq!(
        Mesh::from_arrays(vec![[0.0; 3]], &[[0, 1, 0]])
            .unwrap_err()
            .to_string(),
        "face 0: vertex 1 does not exist: the mesh has 1 vertex"
    );
    // Far points: a face whose edges overflow says so (it "had no area"), and one whose
    // edges are finite has its area (the file then fails C121 for the far point).
    let far = |b: [f64; 3]| {
        Mesh::from_arrays(vec![[1e308, 0.0, 0.0], b, [0.0; 3]], &[[0, 1, 2]]).unwrap()
    };
    assert_eq!(
        to_walls(&far([-1e308, 1.0, 0.0]), &MeshOptions::default())
            .unwrap_err()
            .to_string(),
        "face 0: the face with vertices 0, 1 and 2 spans more than a double holds"
    );
    let walls = to_walls(&far([1e308, 1e308, 0.0]), &MeshOptions::default()).unwrap();
    let error = dumps(&walls, &DumpOptions::default()).unwrap_err();
    assert_eq!(error.diagnostics[0].code.id, "C121");
}

#[test]
fn pairs_of_triangles_that_make_a_rectangle_merge() {
    let mesh = scrambled_cube();
    let walls = to_walls(&mesh, &options(Orientation::Outward, true)).unwrap();
    assert_eq!(walls.len(), 6);
    assert!(walls.iter().all(|w| w.wall_type() == Some("rectangle")));
    assert_eq!(facing(&walls), vec![1.0; 6]);
    let dumped = dumps(&walls, &DumpOptions::default()).unwrap();
    assert!(dumped.warnings.is_empty(), "{:?}", dumped.warnings);
    assert!(
        dumped.text.starts_with(
            "wall type rectangle\n  origin 0 1 0\n  vertex1 1 0 0\n  vertex2 0 -1 0\n"
        ),
        "{}",
        dumped.text
    );

    // A kite: two right angles on the same diagonal, but not a rectangle.
    let kite = Mesh::from_arrays(
        vec![
            [0.0, 0.0, 0.0],
            [2.0, 0.0, 0.0],
            [1.0, 1.0, 0.0],
            [0.4, -0.8, 0.0],
        ],
        &[[0, 1, 2], [0, 3, 1]],
    )
    .unwrap();
    let walls = to_walls(&kite, &options(Orientation::Keep, true)).unwrap();
    assert_eq!(walls.len(), 2);
    // A square folded along its diagonal.
    let folded = Mesh::from_arrays(
        vec![
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [1.0, 1.0, 0.0],
            [0.0, 0.0, 1.0],
        ],
        &[[0, 1, 2], [0, 2, 3]],
    )
    .unwrap();
    let walls = to_walls(&folded, &options(Orientation::Keep, true)).unwrap();
    assert_eq!(walls.len(), 2);
}
