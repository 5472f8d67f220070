//! Nearest points and features of every wall type and degenerate form, against points
//! whose answers are known by construction.

use nalgebra::Vector3;
use walls_geometry::{Feature, Nearest, OscillationStepping, Shape, Wall};
use walls_model::{Options, analyze};

type Vec3 = Vector3<f64>;

fn shape(text: &str) -> Shape {
    walls_test_support::scene(text).swap_remove(0).shape
}

fn near(s: &Shape, p: [f64; 3]) -> Nearest {
    s.nearest(&Vec3::from(p))
}

fn close(a: Vec3, b: [f64; 3]) -> bool {
    (a - Vec3::from(b)).norm() < 1e-12
}

#[test]
fn plane() {
    let s = shape("wall type plane\n  origin 0 0 1\n  orient 0 0 2\n");
    let n = near(&s, [3.0, 4.0, -1.0]);
    assert!(close(n.point, [3.0, 4.0, 1.0]) && close(n.normal, [0.0, 0.0, -1.0]));
    assert_eq!((n.distance, n.feature), (2.0, Feature::Face));
}

#[test]
fn triangle_face_edges_vertices() {
    let s = shape("wall type triangle\n  vertex1 2 0 0\n  vertex2 0 2 0\n");
    let face = near(&s, [0.5, 0.5, 1.0]);
    assert_eq!(face.feature, Feature::Face);
    assert!(close(face.point, [0.5, 0.5, 0.0]) && close(face.normal, [0.0, 0.0, 1.0]));
    assert_eq!(near(&s, [1.0, -1.0, 0.0]).feature, Feature::Edge(0));
    assert_eq!(near(&s, [2.0, 2.0, 0.0]).feature, Feature::Edge(1));
    assert_eq!(near(&s, [-1.0, 1.0, 0.0]).feature, Feature::Edge(2));
    // Beyond a vertex the contact normal runs from the vertex to the point.
    let v = near(&s, [3.0, -1.0, 0.0]);
    assert_eq!(v.feature, Feature::Vertex(1));
    assert!(close(v.point, [2.0, 0.0, 0.0]));
    assert!(close(
        v.normal,
        [1.0 / 2f64.sqrt(), -1.0 / 2f64.sqrt(), 0.0]
    ));
    assert_eq!(near(&s, [-1.0, -1.0, 0.5]).feature, Feature::Vertex(0));
}

#[test]
fn rectangle_face_edges_vertices() {
    let s = shape("wall type rectangle\n  vertex1 2 0 0\n  vertex2 0 1 0\n");
    assert_eq!(near(&s, [1.0, 0.5, -3.0]).feature, Feature::Face);
    assert_eq!(near(&s, [1.0, -1.0, 0.0]).feature, Feature::Edge(0));
    assert_eq!(near(&s, [3.0, 0.5, 0.0]).feature, Feature::Edge(1));
    assert_eq!(near(&s, [1.0, 2.0, 0.0]).feature, Feature::Edge(2));
    assert_eq!(near(&s, [-1.0, 0.5, 0.0]).feature, Feature::Edge(3));
    let corner = near(&s, [3.0, 2.0, 0.0]);
    assert_eq!(corner.feature, Feature::Vertex(3));
    assert!(close(corner.point, [2.0, 1.0, 0.0]));
}

#[test]
fn disk_face_rim_hole_and_point() {
    let s = shape("wall type disk\n  radius 2\n  hole-radius 1\n");
    assert_eq!(near(&s, [1.5, 0.0, 1.0]).feature, Feature::Face);
    let rim = near(&s, [3.0, 0.0, 1.0]);
    assert_eq!(rim.feature, Feature::Rim(0));
    assert!(close(rim.point, [2.0, 0.0, 0.0]));
    let hole = near(&s, [0.0, 0.5, 0.0]);
    assert_eq!(hole.feature, Feature::HoleRim);
    assert!(close(hole.point, [0.0, 1.0, 0.0]));
    // A particle on the axis, in the hole: the hole rim is a whole circle away.
    assert!((near(&s, [0.0, 0.0, 0.0]).distance - 1.0).abs() < 1e-12);
    let point = shape("wall type disk\n  radius 0\n");
    let n = near(&point, [0.0, 3.0, 4.0]);
    assert_eq!((n.feature, n.distance), (Feature::Point, 5.0));
}

#[test]
fn cylinders_inside_outside_and_degenerate() {
    let tube = shape("wall type cylinder-infinite\n  radius 1\n");
    let outside = near(&tube, [3.0, 0.0, 7.0]);
    assert!(close(outside.point, [1.0, 0.0, 7.0]) && close(outside.normal, [1.0, 0.0, 0.0]));
    let inside = near(&tube, [0.25, 0.0, -2.0]);
    assert!(close(inside.point, [1.0, 0.0, -2.0]) && close(inside.normal, [-1.0, 0.0, 0.0]));
    let line = shape("wall type cylinder-infinite\n  radius 0\n");
    assert!((near(&line, [3.0, 4.0, 9.0]).distance - 5.0).abs() < 1e-12);

    let finite = shape("wall type cylinder-finite\n  radius 1\n  length 2\n");
    assert_eq!(near(&finite, [2.0, 0.0, 0.5]).feature, Feature::Side);
    let top = near(&finite, [2.0, 0.0, 3.0]);
    assert_eq!(top.feature, Feature::Rim(1));
    assert!(close(top.point, [1.0, 0.0, 1.0]));
    assert_eq!(near(&finite, [0.5, 0.0, -2.0]).feature, Feature::Rim(0));
    let ring = shape("wall type cylinder-finite\n  radius 1\n  length 0\n");
    let r = near(&ring, [0.0, 0.0, 1.0]);
    assert_eq!(r.feature, Feature::Rim(0));
    assert!((r.distance - 2f64.sqrt()).abs() < 1e-12);
    let segment = shape("wall type cylinder-finite\n  radius 0\n  length 2\n");
    assert!((near(&segment, [0.0, 3.0, 2.0]).distance - 10f64.sqrt()).abs() < 1e-12);
}

#[test]
fn tapered_cylinder_and_cone_to_a_point() {
    // Radius 1 at z = −1 down to 0.5 at z = +1: the side leans in by 0.25 per unit.
    let frustum = shape("wall type cylinder-finite\n  radius 1\n  length 2\n  taper 0.5\n");
    let side = near(&frustum, [2.0, 0.0, 0.0]);
    assert_eq!(side.feature, Feature::Side);
    let slope = Vec3::new(-0.5, 0.0, 2.0).normalize(); // along the side, upwards
    assert!(((side.point - Vec3::new(0.75, 0.0, 0.0)).dot(&slope.cross(&Vec3::y()))).abs() < 1e-12);
    assert!(
        side.normal.dot(&slope).abs() < 1e-12,
        "normal perpendicular to the side"
    );
    let cone = shape("wall type cylinder-finite\n  radius 1\n  length 2\n  taper 1\n");
    let tip = near(&cone, [0.0, 0.0, 5.0]);
    assert_eq!(tip.feature, Feature::Point);
    assert!(close(tip.point, [0.0, 0.0, 1.0]));
}

#[test]
fn shells_with_openings() {
    let half = shape("wall type shell\n  radius 2\n  open-angle 90\n");
    let below = near(&half, [0.0, 0.0, -5.0]);
    assert_eq!(below.feature, Feature::Face);
    assert!(close(below.point, [0.0, 0.0, -2.0]));
    let inside = near(&half, [0.0, 0.0, -1.0]);
    assert!(close(inside.point, [0.0, 0.0, -2.0]) && close(inside.normal, [0.0, 0.0, 1.0]));
    // Above the opening, the nearest material is the rim.
    let above = near(&half, [0.5, 0.0, 3.0]);
    assert_eq!(above.feature, Feature::Rim(0));
    assert!(close(above.point, [2.0, 0.0, 0.0]));
    let gone = shape("wall type shell\n  radius 2\n  open-angle 180\n");
    let n = near(&gone, [0.0, 0.0, 1.0]);
    assert_eq!(n.feature, Feature::Point);
    assert!(close(n.point, [0.0, 0.0, -2.0]));
}

#[test]
fn point_velocity_adds_translation_oscillation_and_spin() {
    let tree = walls_syntax::parse(
        "wall type disk\n  radius 2\n  velocity 1 0 0\n  osc-ampl 0.5 osc-freq 2 osc-phase 0.25\n  ang-speed 3\n",
    )
    .tree;
    let scene = analyze(&tree, &Options::default()).scene;
    let motion = Wall::decode(&scene.walls[0]).motion;
    // At t = 0: cos(2π·0.25) = 0, so no oscillation velocity; spin 3 about z at (1, 0, 0)
    // relative to the origin gives (0, 3, 0).
    let origin = Vec3::new(0.0, 0.0, 0.5);
    let v = motion.point_velocity(&(origin + Vec3::x()), &origin, 0.0);
    assert!(close(v, [1.0, 3.0, 0.0]), "{v:?}");
    // A quarter period later (ω·t = π/2): cos(π/2 + π/2) = −1, so A·ω·(−1) along z.
    let t = std::f64::consts::FRAC_PI_4;
    assert!(close(motion.origin_velocity(t), [1.0, 0.0, -1.0]));
}

#[test]
fn pkdgrav_stepping_lags_half_a_step_and_does_not_drift() {
    let tree =
        walls_syntax::parse("wall type plane\n  osc-ampl 1 osc-freq 6.283185307179586\n").tree;
    let scene = analyze(&tree, &Options::default()).scene;
    let wall = &scene.walls[0];
    let motion = Wall::decode(wall).motion;
    for n in [20usize, 100] {
        let dt = 1.0 / n as f64;
        let mut origin = Vec3::zeros();
        let mut worst: f64 = 0.0;
        for k in 0..10 * n {
            origin = motion
                .step(&origin, k as f64 * dt, dt, OscillationStepping::Pkdgrav)
                .unwrap();
            let exact = motion.position((k + 1) as f64 * dt).unwrap();
            worst = worst.max((origin - exact).norm());
        }
        // The gap is half a step of lag plus an offset of half a step's travel: A·ω·dt.
        let expected = std::f64::consts::TAU / n as f64;
        assert!(
            (worst / expected - 1.0).abs() < 0.05,
            "N = {n}: {worst} vs 2πA/N = {expected}"
        );
        // After ten whole cycles it is back where the exact motion is.
        assert!(origin.norm() < 1e-9, "{origin:?}");
    }
}
