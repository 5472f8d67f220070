//! Wall meshes: each shape's triangles lie on the wall (every vertex at distance 0 from
//! the shape the evaluator uses), cover it (area against the analytic area) and follow
//! the wall's motion; colours follow ssdraw.

use walls_geometry::{Wall, decode, scene_bounds};
use walls_preview::{palette, wall_meshes};
use walls_test_support::model_scene as scene;

fn area(m: &walls_preview::Mesh) -> f64 {
    m.triangles
        .iter()
        .map(|[a, b, c]| {
            let (a, b, c) = (
                m.positions[*a as usize],
                m.positions[*b as usize],
                m.positions[*c as usize],
            );
            (b - a).cross(&(c - a)).norm() / 2.0
        })
        .sum()
}

#[test]
fn every_vertex_lies_on_its_wall_and_the_area_is_right() {
    use std::f64::consts::PI;
    let cases = [
        (
            "wall type triangle\n  vertex1 2 0 0\n  vertex2 0 1 0\n",
            1.0,
        ),
        (
            "wall type rectangle\n  vertex1 2 0 0\n  vertex2 0 3 0\n",
            6.0,
        ),
        ("wall type disk\n  radius 1\n  hole-radius 0.5\n", PI * 0.75),
        ("wall type disk\n  radius 1\n", PI),
        (
            "wall type cylinder-finite\n  radius 1\n  length 2\n",
            2.0 * PI * 2.0,
        ),
        ("wall type shell\n  radius 1\n", 4.0 * PI),
        ("wall type shell\n  radius 1\n  open-angle 90\n", 2.0 * PI),
        (
            "wall type cylinder-finite\n  radius 1\n  length 1\n  taper 1\n",
            PI * 2f64.sqrt(),
        ),
    ];
    for (text, expected) in cases {
        let s = scene(text);
        let wall = &s.walls[0];
        let shape = Wall::decode(wall).shape;
        let meshes = wall_meshes(&s, 0.0, 256);
        let m = &meshes[0].mesh;
        for p in &m.positions {
            assert!(
                shape.nearest(p).distance < 1e-9,
                "{text}: {p:?} is off the wall"
            );
        }
        let a = area(m);
        assert!(
            (a / expected - 1.0).abs() < 1e-3,
            "{text}: area {a} vs {expected}"
        );
    }
    // Shapes with no area have no triangles.
    for text in [
        "wall type disk\n  radius 0\n",
        "wall type shell\n  radius 1\n  open-angle 180\n",
    ] {
        assert!(
            wall_meshes(&scene(text), 0.0, 32)[0]
                .mesh
                .triangles
                .is_empty(),
            "{text}"
        );
    }
}

#[test]
fn meshes_move_with_their_walls_and_take_ssdraw_colours() {
    let s = scene("wall type disk\n  radius 1\n  velocity 0 0 2\n  color 2\n  transparency 25\n");
    let at = |t| wall_meshes(&s, t, 16).remove(0);
    let (a, b) = (at(0.0), at(1.5));
    for (p, q) in a.mesh.positions.iter().zip(&b.mesh.positions) {
        assert!((q - p - nalgebra::Vector3::new(0.0, 0.0, 3.0)).norm() < 1e-12);
    }
    assert_eq!(a.rgb, Some([1.0, 0.0, 0.0]));
    assert!((a.opacity - 0.75).abs() < 1e-12);
    // A wall of colour 0 is not drawn.
    let hidden = scene("wall type disk\n  radius 1\n  color 0\n");
    assert_eq!(wall_meshes(&hidden, 0.0, 16)[0].rgb, None);
}

#[test]
fn the_palette_is_ssdraws() {
    // docs/pkdgrav-physics.md §16: the same for particles and walls.
    for (index, bytes) in [
        (0, [0, 0, 0]),
        (1, [255, 255, 255]),
        (2, [255, 0, 0]),
        (3, [0, 255, 0]),
        (4, [0, 0, 255]),
        (5, [255, 255, 0]),
        (6, [255, 0, 255]),
        (7, [0, 255, 255]),
        (8, [255, 215, 0]),
        (9, [255, 192, 203]),
        (10, [255, 165, 0]),
        (11, [240, 230, 140]),
        (12, [238, 130, 238]),
        (13, [176, 48, 96]),
        (14, [127, 255, 212]),
        (15, [0, 0, 128]),
        // Greys of level ⌊255·(c − 16)/239⌋.
        (16, [0, 0, 0]),
        (17, [1, 1, 1]),
        (135, [126, 126, 126]),
        (223, [220, 220, 220]),
        (254, [253, 253, 253]),
        (255, [255, 255, 255]),
    ] {
        assert_eq!(palette::bytes(index), Some(bytes), "colour {index}");
        let [r, g, b] = bytes;
        let hex = format!("#{r:02x}{g:02x}{b:02x}");
        assert_eq!(palette::hex(index).as_deref(), Some(hex.as_str()));
        let rgb = palette::rgb(index).unwrap();
        assert_eq!(rgb, bytes.map(|x| f64::from(x) / 255.0));
        assert_eq!(palette::css(rgb), hex);
    }
    // Particles of colour 0 are drawn (black); walls of colour 0 are not.
    assert_eq!(palette::rgb(0), Some([0.0; 3]));
    assert_eq!(palette::wall(0), None);
    assert_eq!(palette::wall(8), palette::rgb(8));
    for outside in [-1, 256, i64::MIN, i64::MAX] {
        assert_eq!(palette::bytes(outside), None);
        assert_eq!(palette::wall(outside), None);
    }
}

#[test]
fn a_stuck_particle_takes_its_walls_colour() {
    // Colour −1 − w: wall w's colour (0 too, drawn black); any other colour outside
    // 0–255, or a wall there is not, has none.
    let walls = [0, 8, 300];
    let wall_colour = |w: usize| walls.get(w).copied();
    let particle = |c| palette::particle(c, wall_colour);
    assert_eq!(particle(0), Some(0));
    assert_eq!(particle(255), Some(255));
    assert_eq!(particle(-1), Some(0));
    assert_eq!(particle(-2), Some(8));
    assert_eq!(particle(-3), None, "wall 2's colour is outside the palette");
    assert_eq!(particle(-4), None, "there is no wall 3");
    assert_eq!(particle(256), None);
    assert_eq!(particle(666), None);
    assert_eq!(particle(i64::MIN), None);
}

#[test]
fn a_plane_is_cut_to_the_scenes_box() {
    // A floor through an upright disk of radius 1 centred at height 0.5: the box is y in
    // [−1, 1], z in [−0.5, 1.5] and x a hundredth of that around 0; the floor is the
    // rectangle where it cuts it.
    let s =
        scene("wall type plane\nwall type disk\n  origin 0 0 0.5\n  orient 1 0 0\n  radius 1\n");
    let (lo, hi) = scene_bounds(&decode(&s), &[]);
    let floor = &wall_meshes(&s, 0.0, 32)[0].mesh;
    let a = area(floor);
    assert!((a - (hi.x - lo.x) * (hi.y - lo.y)).abs() < 1e-9, "area {a}");
    for p in &floor.positions {
        assert!(
            p.z.abs() < 1e-12 && p.x >= lo.x - 1e-12 && p.x <= hi.x + 1e-12,
            "{p:?}"
        );
    }
    // A tilted plane through the box is cut to a polygon inside it, on the plane.
    let s = scene("wall type plane\n  orient 1 1 1\nwall type disk\n  radius 1\n");
    let (lo, hi) = scene_bounds(&decode(&s), &[]);
    let tilted = &wall_meshes(&s, 0.0, 32)[0].mesh;
    assert!(tilted.positions.len() >= 3 && !tilted.triangles.is_empty());
    for p in &tilted.positions {
        assert!((p.x + p.y + p.z).abs() < 1e-9, "{p:?} off the plane");
        assert!(
            (0..3).all(|k| p[k] >= lo[k] - 1e-9 && p[k] <= hi[k] + 1e-9),
            "{p:?} outside"
        );
    }
}

#[test]
fn reactive_walls_are_drawn_where_a_run_left_them() {
    use nalgebra::Vector3;
    use walls_preview::mesh::{Placement, place};
    // A 2 × 1 rectangle placed turned a quarter about z and moved to (5, 0, 1); a disk
    // turned to face x.
    let s = scene(
        "wall type rectangle\n  vertex1 2 0 0\n  vertex2 0 1 0\nwall type disk\n  radius 1\n",
    );
    let mut meshes = wall_meshes(&s, 0.0, 16);
    let placed = [
        Placement::Polygon {
            wall: 0,
            origin: Vector3::new(5.0, 0.0, 1.0),
            vertex1: Vector3::new(0.0, 2.0, 0.0),
            vertex2: Vector3::new(-1.0, 0.0, 0.0),
        },
        Placement::Round {
            wall: 1,
            origin: Vector3::new(0.0, 0.0, 3.0),
            orient: Vector3::x(),
        },
    ];
    place(&mut meshes, &decode(&s), &placed);
    let corners: Vec<_> = meshes[0].mesh.positions.clone();
    let expect = [
        Vector3::new(5.0, 0.0, 1.0),
        Vector3::new(5.0, 2.0, 1.0),
        Vector3::new(4.0, 2.0, 1.0),
        Vector3::new(4.0, 0.0, 1.0),
    ];
    for (c, e) in corners.iter().zip(&expect) {
        assert!((c - e).norm() < 1e-12, "{c:?} vs {e:?}");
    }
    for p in &meshes[1].mesh.positions {
        assert!(
            p.x.abs() < 1e-12 && (p - Vector3::new(0.0, 0.0, 3.0)).norm() <= 1.0 + 1e-12,
            "{p:?}"
        );
    }
}

#[test]
fn a_round_wall_turned_upside_down_is_drawn_so() {
    use nalgebra::Vector3;
    use walls_preview::mesh::{Placement, place};
    // A cone from radius 1 at z = −1 to a point at z = +1, placed with its axis down: the
    // wide end is then at z = +1.
    let cone = scene("wall type cylinder-finite\n  radius 1\n  length 2\n  taper 1\n");
    let wide = |m: &walls_preview::WallMesh| {
        let p = m
            .mesh
            .positions
            .iter()
            .find(|p| (p.x * p.x + p.y * p.y - 1.0).abs() < 1e-9)
            .expect("a rim vertex");
        p.z
    };
    let mut meshes = wall_meshes(&cone, 0.0, 16);
    assert!((wide(&meshes[0]) + 1.0).abs() < 1e-12);
    place(
        &mut meshes,
        &decode(&cone),
        &[Placement::Round {
            wall: 0,
            origin: Vector3::zeros(),
            orient: -Vector3::z(),
        }],
    );
    assert!((wide(&meshes[0]) - 1.0).abs() < 1e-12);
}
