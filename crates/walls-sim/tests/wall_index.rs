//! The wall index never misses a wall: for random scenes of every wall type, size and
//! place, some walls moving together and some on their own (exactly or by pkdgrav's
//! steps), every wall whose nearest point is within reach of a query point is a
//! candidate, in ascending order. And it is selective: near a hull of 10,000 triangles
//! a particle gets a few dozen candidates.

use nalgebra::Vector3;
use proptest::prelude::*;
use std::f64::consts::PI;
use walls_geometry::shape::{
    Disk, FiniteCylinder, InfiniteCylinder, Plane, Rectangle, Shell, Triangle,
};
use walls_geometry::{OscillationStepping, Shape, Wall};
use walls_sim::WallIndex;
use walls_test_support::scene_uncapped as scene;
use walls_test_support::scenes::sphere_hull;

type Vec3 = Vector3<f64>;

fn v(p: &Vec3) -> String {
    format!("{} {} {}", p.x, p.y, p.z)
}

fn basis(n: &Vec3) -> (Vec3, Vec3) {
    let helper = if n.x.abs() < 0.9 {
        Vec3::x()
    } else {
        Vec3::y()
    };
    let u = n.cross(&helper).normalize();
    (u, n.cross(&u))
}

/// The candidates of a query, checked to be ascending without repeats.
fn candidates(index: &WallIndex, p: &Vec3, reach: f64, origins: &[Vec3]) -> Vec<usize> {
    let mut out = Vec::new();
    index.for_each_candidate(p, reach, origins, |w| out.push(w));
    assert!(out.windows(2).all(|w| w[0] < w[1]), "{out:?}");
    out
}

/// Every wall's origin at time `t`, exactly or moved step by step from t = 0.
fn origins_at(scene: &[Wall], t: f64, steps: u32, stepping: OscillationStepping) -> Vec<Vec3> {
    let dt = t / f64::from(steps);
    scene
        .iter()
        .map(|w| {
            let mut o = w.motion.position(0.0).unwrap();
            for k in 0..steps {
                o = w.motion.step(&o, f64::from(k) * dt, dt, stepping).unwrap();
            }
            o
        })
        .collect()
}

// Strategies.

fn vec3(s: f64) -> impl Strategy<Value = Vec3> {
    (-s..s, -s..s, -s..s).prop_map(|(x, y, z)| Vec3::new(x, y, z))
}

fn unit() -> impl Strategy<Value = Vec3> {
    vec3(1.0)
        .prop_filter("not too short", |u| u.norm_squared() > 0.05)
        .prop_map(|u| u.normalize())
}

/// A length from 0.003 to 3, log-uniform.
fn size() -> impl Strategy<Value = f64> {
    (-2.5..0.5f64).prop_map(|e| 10f64.powf(e))
}

/// One wall's type and geometry, as walls-file lines.
fn geometry() -> impl Strategy<Value = String> {
    let at = || vec3(5.0);
    prop_oneof![
        1 => (at(), unit()).prop_map(|(o, n)| format!(" type plane\n origin {}\n orient {}\n", v(&o), v(&n))),
        1 => (at(), unit(), size()).prop_map(|(o, n, r)| {
            format!(" type cylinder-infinite\n origin {}\n orient {}\n radius {r}\n", v(&o), v(&n))
        }),
        4 => (at(), unit(), size(), vec3(1.0), vec3(1.0))
            .prop_filter("area", |(_, _, _, a, b)| a.normalize().cross(&b.normalize()).norm() > 0.05)
            .prop_map(|(o, _, s, a, b)| {
                format!(" type triangle\n origin {}\n vertex1 {}\n vertex2 {}\n", v(&o), v(&(a * s)), v(&(b * s)))
            }),
        2 => (at(), unit(), size(), size()).prop_map(|(o, n, a, b)| {
            let (u, w) = basis(&n);
            format!(" type rectangle\n origin {}\n vertex1 {}\n vertex2 {}\n", v(&o), v(&(u * a)), v(&(w * b)))
        }),
        2 => (at(), unit(), size(), 0.0..0.9f64).prop_map(|(o, n, r, h)| {
            format!(" type disk\n origin {}\n orient {}\n radius {r}\n hole-radius {}\n", v(&o), v(&n), r * h)
        }),
        2 => (at(), unit(), size(), size(), 0.0..1.0f64).prop_map(|(o, n, r, l, taper)| {
            format!(
                " type cylinder-finite\n origin {}\n orient {}\n radius {r}\n length {l}\n taper {taper}\n",
                v(&o),
                v(&n)
            )
        }),
        2 => (at(), unit(), size(), 0.0..180.0f64).prop_map(|(o, n, r, open)| {
            format!(" type shell\n origin {}\n orient {}\n radius {r}\n open-angle {open}\n", v(&o), v(&n))
        }),
    ]
}

/// A motion, as walls-file lines: linear, oscillating, both, stepped or not.
fn motion() -> impl Strategy<Value = String> {
    (
        vec3(1.0),
        prop_oneof![Just(0.0), -0.5..0.5f64],
        0.0..10.0f64,
        -2.0..2.0f64,
        unit(),
        prop_oneof![Just(0.0), 0.01..0.3f64],
    )
        .prop_map(|(vel, ampl, freq, phase, dir, step)| {
            format!(
                " velocity {}\n osc-ampl {ampl}\n osc-freq {freq}\n osc-phase {phase}\n osc-vec {}\n step {step}\n",
                v(&vel),
                v(&dir)
            )
        })
}

/// A scene of up to 60 walls: each is static or moves in one of three ways shared with
/// others, or in a way of its own.
fn scenes() -> impl Strategy<Value = String> {
    (
        proptest::collection::vec(motion(), 3),
        proptest::collection::vec((geometry(), 0..6usize, motion()), 0..60),
    )
        .prop_map(|(shared, walls)| {
            let mut text = String::new();
            for (geometry, how, own) in walls {
                text.push_str("wall\n");
                text.push_str(&geometry);
                match how {
                    0 | 1 => {}
                    2..=4 => text.push_str(&shared[how - 2]),
                    _ => text.push_str(&own),
                }
            }
            text
        })
}

/// Query points with reaches from 0 to 3.
fn queries() -> impl Strategy<Value = Vec<(Vec3, f64)>> {
    proptest::collection::vec(
        (
            vec3(8.0),
            prop_oneof![Just(0.0), (-3.0..0.5f64).prop_map(|e| 10f64.powf(e))],
        ),
        1..12,
    )
}

fn stepping() -> impl Strategy<Value = (OscillationStepping, u32)> {
    prop_oneof![
        Just(OscillationStepping::Exact),
        Just(OscillationStepping::Pkdgrav)
    ]
    .prop_flat_map(|s| (Just(s), 1..60u32))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    #[test]
    fn every_wall_within_reach_is_a_candidate(
        text in scenes(),
        t in prop_oneof![Just(0.0), 0.0..5.0f64],
        (how, steps) in stepping(),
        queries in queries(),
    ) {
        let scene = scene(&text);
        let index = WallIndex::new(&scene);
        prop_assert_eq!(index.len(), scene.len());
        let origins = origins_at(&scene, t, steps, how);
        let shapes: Vec<Shape> = scene.iter().zip(&origins).map(|(w, o)| w.shape.at(*o)).collect();
        for (p, reach) in queries {
            let found = candidates(&index, &p, reach, &origins);
            for (w, shape) in shapes.iter().enumerate() {
                let d = shape.nearest(&p).distance;
                prop_assert!(
                    d > reach || found.binary_search(&w).is_ok(),
                    "wall {w} ({shape:?}) is {d} from {p:?}, within {reach}, but not a candidate of {found:?}"
                );
            }
            // Walls without a box are always there.
            for w in index.unbounded() {
                prop_assert!(found.contains(w));
            }
        }
    }

    /// The hard-sphere prediction's query: over a step from t to t + dt each wall moves
    /// along its chord; a particle at `p` moving at `vel`, `tau` into the step, can meet
    /// the walls whose nearest point in their own frame is within its radius plus its
    /// travel relative to them.
    #[test]
    fn every_wall_a_moving_particle_can_reach_is_a_candidate(
        text in scenes(),
        t in 0.0..5.0f64,
        dt in 0.001..0.5f64,
        frac in 0.0..1.0f64,
        particles in proptest::collection::vec((vec3(8.0), vec3(3.0), 0.001..0.5f64), 1..10),
    ) {
        let scene = scene(&text);
        let index = WallIndex::new(&scene);
        let start: Vec<Vec3> = scene.iter().map(|w| w.motion.position(t).unwrap()).collect();
        let chord: Vec<Vec3> = scene
            .iter()
            .zip(&start)
            .map(|(w, s)| (w.motion.position(t + dt).unwrap() - s) / dt)
            .collect();
        let shapes: Vec<Shape> = scene.iter().zip(&start).map(|(w, o)| w.shape.at(*o)).collect();
        let tau = frac * dt;
        let left = dt - tau;
        for (pos, vel, radius) in particles {
            let query = |w: usize| (pos - chord[w] * tau, radius + (vel - chord[w]).norm() * left);
            let mut found = Vec::new();
            index.for_each_candidate_by_group(&start, query, |w| found.push(w));
            prop_assert!(found.windows(2).all(|w| w[0] < w[1]));
            for (w, shape) in shapes.iter().enumerate() {
                let (here, reach) = query(w);
                let d = shape.nearest(&here).distance;
                prop_assert!(
                    d > reach || found.binary_search(&w).is_ok(),
                    "wall {w} ({shape:?}) is {d} from {here:?}, within {reach}, but not a candidate"
                );
            }
        }
    }

    /// A shape's box holds every nearest point it answers.
    #[test]
    fn nearest_points_lie_in_the_bounds(text in geometry(), p in vec3(10.0)) {
        let scene = scene(&format!("wall\n{text}"));
        let shape = scene[0].shape.at(scene[0].motion.position(0.0).unwrap());
        if let Some((lo, hi)) = shape.bounds() {
            let q = shape.nearest(&p).point;
            let tolerance = 1e-12 * (1.0 + q.amax());
            for i in 0..3 {
                prop_assert!(lo[i] <= hi[i]);
                prop_assert!(
                    q[i] >= lo[i] - tolerance && q[i] <= hi[i] + tolerance,
                    "{shape:?}: nearest {q:?} outside {lo:?}..{hi:?}"
                );
            }
        }
    }
}

#[test]
fn bounds_of_each_shape() {
    let o = Vec3::new(1.0, 2.0, 3.0);
    let plane = Shape::Plane(Plane {
        origin: o,
        normal: Vec3::z(),
    });
    assert_eq!(plane.bounds(), None);
    let tube = Shape::InfiniteCylinder(InfiniteCylinder {
        origin: o,
        axis: Vec3::z(),
        radius: 1.0,
    });
    assert_eq!(tube.bounds(), None);
    let flat = Shape::Triangle(Triangle {
        origin: o,
        e1: Vec3::x(),
        e2: Vec3::x() * 2.0,
    });
    assert_eq!(
        flat.bounds(),
        None,
        "a triangle with parallel edges has no normal"
    );
    let triangle = Shape::Triangle(Triangle {
        origin: o,
        e1: Vec3::new(1.0, -1.0, 0.0),
        e2: Vec3::new(0.0, 2.0, 0.5),
    });
    assert_eq!(
        triangle.bounds(),
        Some((Vec3::new(1.0, 1.0, 3.0), Vec3::new(2.0, 4.0, 3.5)))
    );
    let rectangle = Shape::Rectangle(Rectangle {
        origin: o,
        e1: Vec3::x(),
        e2: Vec3::y() * 2.0,
    });
    assert_eq!(rectangle.bounds(), Some((o, Vec3::new(2.0, 4.0, 3.0))));
    // A disk facing z is flat in z; tilted 45° about x, it reaches r·cos 45° in y and z.
    let disk = |normal: Vec3| {
        Shape::Disk(Disk {
            center: o,
            normal,
            radius: 2.0,
            hole: 1.0,
        })
    };
    assert_eq!(
        disk(Vec3::z()).bounds(),
        Some((Vec3::new(-1.0, 0.0, 3.0), Vec3::new(3.0, 4.0, 3.0)))
    );
    let (lo, hi) = disk(Vec3::new(0.0, 1.0, 1.0).normalize()).bounds().unwrap();
    let c = 2.0 * (PI / 4.0).cos();
    assert!(
        (lo - Vec3::new(-1.0, 2.0 - c, 3.0 - c)).amax() < 1e-12,
        "{lo}"
    );
    assert!(
        (hi - Vec3::new(3.0, 2.0 + c, 3.0 + c)).amax() < 1e-12,
        "{hi}"
    );
    // A cone along z from radius 2 at z = 2 to radius 1 at z = 4.
    let cone = Shape::FiniteCylinder(FiniteCylinder {
        center: o,
        axis: Vec3::z(),
        radius: 2.0,
        length: 2.0,
        taper: 0.5,
    });
    assert_eq!(
        cone.bounds(),
        Some((Vec3::new(-1.0, 0.0, 2.0), Vec3::new(3.0, 4.0, 4.0)))
    );
    let shell = Shape::Shell(Shell {
        center: o,
        axis: Vec3::z(),
        radius: 0.5,
        open: 1.0,
    });
    assert_eq!(
        shell.bounds(),
        Some((o - Vec3::repeat(0.5), o + Vec3::repeat(0.5)))
    );
}

#[test]
fn walls_moving_alike_share_a_hierarchy() {
    let triangle = " type triangle\n origin 0 0 0\n vertex1 1 0 0\n vertex2 0 1 0\n";
    let text = [
        // 0, 1: static (an oscillation of amplitude 0 does not move a wall).
        format!("wall\n{triangle}"),
        format!("wall\n{triangle} osc-freq 3\n step 0.1\n"),
        // 2, 4: the same velocity; 3: another; 5: a plane, moving or not.
        format!("wall\n{triangle} velocity 1 0 0\n"),
        format!("wall\n{triangle} velocity 0 1 0\n"),
        format!("wall\n{triangle} velocity 1 0 0\n"),
        "wall\n type plane\n velocity 1 0 0\n".to_string(),
        // 6, 7: the same oscillation, phases a whole cycle apart.
        format!("wall\n{triangle} osc-ampl 0.5\n osc-freq 2\n osc-phase 0.25\n"),
        format!("wall\n{triangle} osc-ampl 0.5\n osc-freq 2\n osc-phase 1.25\n"),
    ]
    .concat();
    let index = WallIndex::new(&scene(&text));
    assert_eq!(index.len(), 8);
    assert_eq!(index.group_count(), 4);
    assert_eq!(index.representatives().collect::<Vec<_>>(), [0, 2, 3, 6]);
    assert_eq!(index.unbounded(), [5]);
}

#[test]
fn a_group_is_found_where_it_has_moved() {
    let text = "wall\n type triangle\n origin 0 0 0\n vertex1 1 0 0\n vertex2 0 1 0\n velocity 10 0 0\n\
                wall\n type triangle\n origin 0 0 0.5\n vertex1 1 0 0\n vertex2 0 1 0\n velocity 10 0 0\n\
                wall\n type shell\n origin 0 0 2\n radius 0.5\n velocity 0 0 -5\n\
                wall\n type plane\n origin 0 0 -100\n";
    let scene = scene(text);
    let index = WallIndex::new(&scene);
    assert_eq!(index.group_count(), 2);
    let at = |t: f64| -> Vec<Vec3> {
        scene
            .iter()
            .map(|w| w.motion.position(t).unwrap())
            .collect()
    };
    // A leaf holds up to four walls: both triangles' box is one.
    let p = Vec3::new(0.2, 0.2, 0.05);
    assert_eq!(candidates(&index, &p, 0.1, &at(0.0)), [0, 1, 3]);
    assert_eq!(candidates(&index, &p, 0.1, &at(1.0)), [3]);
    assert_eq!(
        candidates(&index, &(p + Vec3::x() * 10.0), 0.1, &at(1.0)),
        [0, 1, 3]
    );
    assert_eq!(
        candidates(&index, &Vec3::new(0.0, 0.0, -2.4), 0.2, &at(1.0)),
        [2, 3]
    );
    assert_eq!(
        candidates(&index, &Vec3::new(0.0, 0.0, -2.4), 0.05, &at(1.0)),
        [3]
    );
    // A query that is not a number finds every wall.
    assert_eq!(candidates(&index, &p, f64::NAN, &at(1.0)), [0, 1, 2, 3]);
    assert_eq!(
        candidates(&index, &Vec3::repeat(f64::NAN), 0.1, &at(1.0)),
        [0, 1, 2, 3]
    );
    // No walls, no candidates.
    let none = WallIndex::new(&[]);
    assert!(none.is_empty());
    assert!(candidates(&none, &p, 1.0, &[]).is_empty());
}

#[test]
fn near_a_hull_of_10k_triangles_few_walls_are_candidates() {
    let scene = scene(&sphere_hull(50));
    assert_eq!(scene.len(), 10_000);
    let index = WallIndex::new(&scene);
    assert_eq!(index.group_count(), 1);
    let origins: Vec<Vec3> = scene
        .iter()
        .map(|w| w.motion.position(0.0).unwrap())
        .collect();
    let shapes: Vec<Shape> = scene
        .iter()
        .zip(&origins)
        .map(|(w, o)| w.shape.at(*o))
        .collect();
    let (mut total, mut most, mut touching) = (0, 0, 0);
    let queries = 500;
    for k in 0..queries {
        // Points spread over the sphere (a golden-angle spiral), 0 to 0.02 inside it.
        let z = 1.0 - 2.0 * (k as f64 + 0.5) / queries as f64;
        let phi = k as f64 * PI * (3.0 - 5f64.sqrt());
        let s = (1.0 - z * z).sqrt();
        let p = Vec3::new(s * phi.cos(), s * phi.sin(), z) * (1.0 - 0.02 * (k % 5) as f64 / 4.0);
        let reach = 0.01;
        let found = candidates(&index, &p, reach, &origins);
        let within: Vec<usize> = (0..shapes.len())
            .filter(|&w| shapes[w].nearest(&p).distance <= reach)
            .collect();
        assert!(
            within.iter().all(|w| found.contains(w)),
            "{p}: {within:?} ⊄ {found:?}"
        );
        touching += usize::from(!within.is_empty());
        total += found.len();
        most = most.max(found.len());
    }
    assert!(touching > queries / 10, "{touching} queries touch the hull");
    // A wide reach: hundreds of candidates, still ascending and complete.
    let p = Vec3::new(0.3, 0.4, 0.8);
    let found = candidates(&index, &p, 0.3, &origins);
    let within: Vec<usize> = (0..shapes.len())
        .filter(|&w| shapes[w].nearest(&p).distance <= 0.3)
        .collect();
    assert!(within.len() > 200, "{}", within.len());
    assert!(within.iter().all(|w| found.binary_search(w).is_ok()));
    let mean = total as f64 / queries as f64;
    assert!(mean < 30.0, "{mean} candidates on average of 10,000 walls");
    assert!(most < 100, "{most} candidates at most of 10,000 walls");
}
