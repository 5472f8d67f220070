//! For any point, no point of the shape's material is nearer than the one `nearest`
//! returns: checked against thousands of points sampled over each shape, with the
//! returned point itself on the material and the normal a unit vector. The cheap test
//! before the query ([`Cull`]) never calls clear a point the query finds within reach.

use nalgebra::Vector3;
use proptest::prelude::*;
use std::f64::consts::{PI, TAU};
use walls_geometry::Shape;
use walls_geometry::shape::{
    Cull, Disk, FiniteCylinder, InfiniteCylinder, Plane, Rectangle, Shell, Triangle,
};

type Vec3 = Vector3<f64>;

/// Points of the material, on a grid of the shape's own parameters.
fn samples(s: &Shape) -> Vec<Vec3> {
    let grid = |n: usize| (0..=n).map(move |i| i as f64 / n as f64);
    let mut out = Vec::new();
    match s {
        Shape::Plane { .. } | Shape::InfiniteCylinder { .. } => {}
        Shape::Triangle(Triangle { origin, e1, e2 }) => {
            for a in grid(40) {
                for b in grid(40) {
                    if a + b <= 1.0 {
                        out.push(origin + e1 * a + e2 * b);
                    }
                }
            }
        }
        Shape::Rectangle(Rectangle { origin, e1, e2 }) => {
            for a in grid(40) {
                for b in grid(40) {
                    out.push(origin + e1 * a + e2 * b);
                }
            }
        }
        Shape::Disk(Disk {
            center,
            normal,
            radius,
            hole,
        }) => {
            let (u, v) = basis(normal);
            for r in grid(30) {
                for a in grid(90) {
                    let rho = hole + (radius - hole) * r;
                    out.push(center + (u * (a * TAU).cos() + v * (a * TAU).sin()) * rho);
                }
            }
        }
        Shape::FiniteCylinder(FiniteCylinder {
            center,
            axis,
            radius,
            length,
            taper,
        }) => {
            let (u, v) = basis(axis);
            for x in grid(40) {
                for a in grid(90) {
                    let rho = radius * (1.0 - taper * x);
                    let along = (x - 0.5) * length;
                    out.push(
                        center + axis * along + (u * (a * TAU).cos() + v * (a * TAU).sin()) * rho,
                    );
                }
            }
        }
        Shape::Shell(Shell {
            center,
            axis,
            radius,
            open,
        }) => {
            let (u, v) = basis(axis);
            for t in grid(60) {
                let theta = open + (PI - open) * t;
                for a in grid(90) {
                    let dir = axis * theta.cos()
                        + (u * (a * TAU).cos() + v * (a * TAU).sin()) * theta.sin();
                    out.push(center + dir * *radius);
                }
            }
        }
    }
    out
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

fn unit() -> impl Strategy<Value = Vec3> {
    (-1.0..1.0f64, -1.0..1.0f64, -1.0..1.0f64)
        .prop_filter("not too short", |(x, y, z)| x * x + y * y + z * z > 0.05)
        .prop_map(|(x, y, z)| Vec3::new(x, y, z).normalize())
}

fn shapes() -> impl Strategy<Value = Shape> {
    let c = || (-1.0..1.0f64, -1.0..1.0f64, -1.0..1.0f64).prop_map(|(x, y, z)| Vec3::new(x, y, z));
    prop_oneof![
        (c(), c(), c())
            .prop_filter("area", |(_, a, b)| a.cross(b).norm() > 0.1)
            .prop_map(|(origin, e1, e2)| Shape::Triangle(Triangle { origin, e1, e2 })),
        (c(), unit(), 0.2..2.0f64, 0.2..2.0f64).prop_map(|(origin, n, a, b)| {
            let (u, v) = basis(&n);
            Shape::Rectangle(Rectangle {
                origin,
                e1: u * a,
                e2: v * b,
            })
        }),
        (c(), unit(), 0.0..2.0f64, 0.0..1.0f64).prop_map(|(center, normal, radius, h)| {
            Shape::Disk(Disk {
                center,
                normal,
                radius,
                hole: radius * h * 0.9,
            })
        }),
        (c(), unit(), 0.0..2.0f64, 0.0..3.0f64, 0.0..1.0f64).prop_map(
            |(center, axis, radius, length, taper)| {
                Shape::FiniteCylinder(FiniteCylinder {
                    center,
                    axis,
                    radius,
                    length,
                    taper,
                })
            }
        ),
        (c(), unit(), 0.1..2.0f64, 0.0..PI).prop_map(|(center, axis, radius, open)| Shape::Shell(
            Shell {
                center,
                axis,
                radius,
                open
            }
        )),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    #[test]
    fn no_sampled_point_is_nearer(s in shapes(), p in (-3.0..3.0f64, -3.0..3.0f64, -3.0..3.0f64)) {
        let p = Vec3::new(p.0, p.1, p.2);
        let n = s.nearest(&p);
        prop_assert!((n.normal.norm() - 1.0).abs() < 1e-9, "{n:?}");
        prop_assert!(((p - n.point).norm() - n.distance).abs() < 1e-9);
        let points = samples(&s);
        let best = points.iter().map(|q| (p - q).norm()).fold(f64::INFINITY, f64::min);
        // The sampling grid is coarse: allow its spacing, never more.
        prop_assert!(n.distance <= best + 1e-9, "{s:?} at {p:?}: {n:?} but a sample is {best} away");
        let on_material = points.iter().map(|q| (n.point - q).norm()).fold(f64::INFINITY, f64::min);
        prop_assert!(on_material < 0.15, "{s:?}: nearest point {:?} is {on_material} from the material", n.point);
    }

    #[test]
    fn the_cheap_test_never_hides_a_reachable_point(
        s in every_shape(),
        p in (-3.0..3.0f64, -3.0..3.0f64, -3.0..3.0f64),
        reach in 0.0..2.0f64,
    ) {
        let p = Vec3::new(p.0, p.1, p.2);
        if Cull::of(&s).clear_of(&p, reach) {
            let n = s.nearest(&p);
            prop_assert!(n.distance > reach, "{s:?} at {p:?}: called clear at {reach}, {n:?}");
        }
    }
}

/// The finite shapes, and planes and infinite cylinders.
fn every_shape() -> impl Strategy<Value = Shape> {
    let c = || (-1.0..1.0f64, -1.0..1.0f64, -1.0..1.0f64).prop_map(|(x, y, z)| Vec3::new(x, y, z));
    prop_oneof![
        shapes(),
        (c(), unit()).prop_map(|(origin, normal)| Shape::Plane(Plane { origin, normal })),
        (c(), unit(), 0.0..2.0f64).prop_map(|(origin, axis, radius)| {
            Shape::InfiniteCylinder(InfiniteCylinder {
                origin,
                axis,
                radius,
            })
        }),
    ]
}

/// The cheap test answers clear far from each kind of shape, and not at its surface.
#[test]
fn the_cheap_test_clears_far_points() {
    let plane = Shape::Plane(Plane {
        origin: Vec3::zeros(),
        normal: Vec3::z(),
    });
    let tube = Shape::InfiniteCylinder(InfiniteCylinder {
        origin: Vec3::zeros(),
        axis: Vec3::z(),
        radius: 1.0,
    });
    let square = Shape::Rectangle(Rectangle {
        origin: Vec3::zeros(),
        e1: Vec3::x(),
        e2: Vec3::y(),
    });
    for (shape, far, near) in [
        (&plane, Vec3::new(5.0, 5.0, 0.2), Vec3::new(5.0, 5.0, 0.09)),
        (&tube, Vec3::new(0.0, 0.5, 7.0), Vec3::new(0.0, 0.95, 7.0)),
        (&tube, Vec3::new(0.0, 1.2, 7.0), Vec3::new(0.0, 1.05, 7.0)),
        (&square, Vec3::new(0.5, 1.2, 0.0), Vec3::new(0.5, 0.5, 0.05)),
    ] {
        let cull = Cull::of(shape);
        assert!(cull.clear_of(&far, 0.1), "{shape:?} at {far:?}");
        assert!(!cull.clear_of(&near, 0.1), "{shape:?} at {near:?}");
    }
}
