//! The hard-sphere bounce and collision prediction against analytic answers, exact to
//! 1e−12 relative.

use nalgebra::Vector3;
use walls_geometry::{Feature, Hit, Shape};
use walls_sim::contact::hsdem::bounce;

type Vec3 = Vector3<f64>;

fn close(a: &Vec3, b: &Vec3) -> bool {
    (a - b).norm() <= 1e-12 * b.norm().max(1.0)
}

#[test]
fn normal_rebound_at_eps_n_times_the_speed() {
    for eps in [1.0, 0.8, 0.3, 0.0] {
        let b = bounce(
            0.1,
            &Vec3::new(0.0, 0.0, -2.0),
            &Vec3::zeros(),
            &Vec3::zeros(),
            &Vec3::z(),
            eps,
            1.0,
        );
        assert!(
            close(&b.velocity, &Vec3::new(0.0, 0.0, 2.0 * eps)),
            "{eps}: {:?}",
            b.velocity
        );
    }
}

#[test]
fn elastic_kick_off_a_moving_wall() {
    // v′ = 2u − v along the normal for a wall moving at u.
    let (v, u) = (-3.0, 1.5);
    let b = bounce(
        0.1,
        &Vec3::new(0.0, 0.0, v),
        &Vec3::zeros(),
        &Vec3::new(0.0, 0.0, u),
        &Vec3::z(),
        1.0,
        1.0,
    );
    assert!(close(&b.velocity, &Vec3::new(0.0, 0.0, 2.0 * u - v)));
}

#[test]
fn tangential_restitution_and_spin() {
    // ε_t = −1 reverses the contact point's tangential velocity; ε_t = 1 leaves it.
    let (r, v) = (0.5, Vec3::new(1.0, 0.0, -1.0));
    let kept = bounce(r, &v, &Vec3::zeros(), &Vec3::zeros(), &Vec3::z(), 1.0, 1.0);
    assert!(close(&kept.velocity, &Vec3::new(1.0, 0.0, 1.0)) && close(&kept.spin, &Vec3::zeros()));
    let b = bounce(r, &v, &Vec3::zeros(), &Vec3::zeros(), &Vec3::z(), 1.0, -1.0);
    let contact_after = b.velocity + b.spin.cross(&(-Vec3::z() * r));
    assert!(
        close(
            &Vec3::new(contact_after.x, contact_after.y, 0.0),
            &Vec3::new(-1.0, 0.0, 0.0)
        ),
        "{contact_after:?}"
    );
    // Angular momentum about the contact point is conserved (no torque there).
    let l = |vel: &Vec3, w: &Vec3| (-Vec3::z() * r).cross(vel) * -1.0 + w * 0.4 * r * r;
    let before = l(&Vec3::new(1.0, 0.0, 0.0), &Vec3::zeros());
    let after = l(&Vec3::new(b.velocity.x, 0.0, 0.0), &b.spin);
    assert!(close(&after, &before), "{before:?} {after:?}");
}

fn shape(text: &str) -> Shape {
    walls_test_support::scene(text).swap_remove(0).shape
}

fn exact(t: Option<Hit>, expected: f64, feature: Feature) {
    let hit = t.unwrap_or_else(|| panic!("no hit; expected {expected}"));
    assert!(
        (hit.t - expected).abs() <= 1e-12 * expected.abs().max(1e-300),
        "{} vs {expected}",
        hit.t
    );
    assert_eq!(hit.feature, feature);
}

#[test]
fn predicting_a_hit_on_a_moving_plane() {
    // Falling at 2 from height 1 (radius 0.1) onto a plane rising at 0.5: in the plane's
    // frame it falls at 2.5, so contact after (1 − 0.1)/2.5 = 0.36.
    let plane = shape("wall type plane\n");
    let (p, d) = (Vec3::new(0.0, 0.0, 1.0), Vec3::new(0.0, 0.0, -2.5));
    exact(plane.first_hit(&p, &d, 0.1, 1.0, true), 0.36, Feature::Face);
    // Not within a shorter step, nor when moving away; from below as well.
    assert_eq!(plane.first_hit(&p, &d, 0.1, 0.3, true), None);
    assert_eq!(plane.first_hit(&p, &-d, 0.1, 1.0, true), None);
    let below = plane.first_hit(&-p, &Vec3::new(0.0, 0.0, 3.0), 0.1, 1.0, true);
    exact(below, 0.3, Feature::Face);
}

#[test]
fn predicting_hits_on_every_feature_hsdem_supports() {
    let r = 0.1;
    let rect = shape("wall type rectangle\n  vertex1 2 0 0\n  vertex2 0 1 0\n");
    let down = Vec3::new(0.0, 0.0, -1.0);
    // The face: from height 1 at speed 1, 0.9.
    exact(
        rect.first_hit(&Vec3::new(1.0, 0.5, 1.0), &down, r, 2.0, true),
        0.9,
        Feature::Face,
    );
    // Edge 1 (along e2 at x = 2) from beside it, centre in the plane: 1 − r away.
    let p = Vec3::new(3.0, 0.5, 0.0);
    let left = Vec3::new(-1.0, 0.0, 0.0);
    exact(
        rect.first_hit(&p, &left, r, 2.0, true),
        1.0 - r,
        Feature::Edge(1),
    );
    // With edge detection off, the edge is not seen.
    assert_eq!(rect.first_hit(&p, &left, r, 2.0, false), None);
    // Vertex 3 (origin + e1 + e2 = (2, 1, 0)) along the diagonal: |(1,1,1)|·(1 − r/√3)/√3.
    let dir = Vec3::new(1.0, 1.0, 1.0).normalize();
    let corner = Vec3::new(2.0, 1.0, 0.0);
    exact(
        rect.first_hit(&(corner + dir * 2.0), &-dir, r, 5.0, true),
        2.0 - r,
        Feature::Vertex(3),
    );
    // A disk's face, its rim (a quartic) and its hole's rim.
    let disk = shape("wall type disk\n  radius 1\n  hole-radius 0.3\n");
    exact(
        disk.first_hit(&Vec3::new(0.6, 0.0, 1.0), &down, r, 2.0, true),
        0.9,
        Feature::Face,
    );
    // In the disk's plane towards the rim from outside: it meets the rim at distance r.
    exact(
        disk.first_hit(&Vec3::new(3.0, 0.0, 0.0), &left, r, 5.0, true),
        2.0 - r,
        Feature::Rim(0),
    );
    // Down the axis, a particle wider than the hole rests on the hole's rim: it touches
    // when its centre is √(r² − h²) above the plane (h the hole's radius).
    let big = 0.5;
    let touch_height = (big * big - 0.09f64).sqrt();
    exact(
        disk.first_hit(&Vec3::new(0.0, 0.0, 1.0), &down, big, 2.0, true),
        1.0 - touch_height,
        Feature::HoleRim,
    );
    // Cylinders: from outside by the earlier root, from inside by the later.
    let tube = shape("wall type cylinder-infinite\n  radius 1\n");
    exact(
        tube.first_hit(&Vec3::new(3.0, 0.0, 0.0), &left, r, 5.0, true),
        2.0 - r,
        Feature::Side,
    );
    exact(
        tube.first_hit(&Vec3::zeros(), &left, r, 5.0, true),
        1.0 - r,
        Feature::Side,
    );
    let can = shape("wall type cylinder-finite\n  radius 1\n  length 2\n");
    exact(
        can.first_hit(&Vec3::new(0.5, 0.0, 0.0), &-left, r, 5.0, true),
        0.5 - r,
        Feature::Side,
    );
    // Its upper end's rim, met from above just outside the radius.
    let rim = can
        .first_hit(&Vec3::new(1.05, 0.0, 3.0), &down, r, 5.0, true)
        .expect("rim");
    let height = (r * r - 0.05f64 * 0.05).sqrt();
    assert!((rim.t - (2.0 - height)).abs() < 1e-12, "{rim:?}");
    assert_eq!(rim.feature, Feature::Rim(1));
    // A zero-radius disk is a point.
    let point = shape("wall type disk\n  radius 0\n");
    exact(
        point.first_hit(&Vec3::new(0.0, 0.0, 1.0), &down, r, 2.0, true),
        0.9,
        Feature::Point,
    );
    // Triangles, shells and tapers are not pkdgrav HSDEM shapes.
    for text in [
        "wall type triangle\n",
        "wall type shell\n",
        "wall type cylinder-finite\n  taper 0.5\n",
    ] {
        assert!(!shape(text).hard_sphere_supported(), "{text}");
    }
}

#[test]
fn a_near_miss_is_missed_and_a_clip_is_a_corner() {
    // Passing the rectangle's corner (0, 1, 0) in its plane just beyond r, then just within.
    let rect = shape("wall type rectangle\n  vertex1 1 0 0\n  vertex2 0 1 0\n");
    let r = 0.1;
    let miss = rect.first_hit(
        &Vec3::new(-1.0, 1.0 + 1.01 * r, 0.0),
        &Vec3::x(),
        r,
        5.0,
        true,
    );
    assert_eq!(miss, None);
    let y = 0.99 * r;
    let clip = rect.first_hit(&Vec3::new(-1.0, 1.0 + y, 0.0), &Vec3::x(), r, 5.0, true);
    let expected = 1.0 - (r * r - y * y).sqrt();
    let clip = clip.expect("it clips the corner");
    assert_eq!(clip.feature, Feature::Vertex(2));
    assert!(
        (clip.t - expected).abs() < 1e-12,
        "{} vs {expected}",
        clip.t
    );
}

#[test]
fn a_hole_smaller_than_the_particle_stops_it_on_and_near_the_axis() {
    // Radius 0.1 down onto a hole of radius 0.05, on the axis and off it by up to 1e−7:
    // near the axis the ring quartic's roots are nearly double, and rounding must not
    // let the particle through. It meets the rim when its centre is √(r² − h²) above.
    let disk = shape("wall type disk\n  radius 1\n  hole-radius 0.05\n");
    let r: f64 = 0.1;
    for offset in [0.0, 1e-13, 1e-11, 1e-9, 1e-7] {
        // The nearest rim point is on the particle's side, 0.05 − offset across.
        let expected = 0.5 - (r * r - (0.05 - offset) * (0.05 - offset)).sqrt();
        let hit = disk.first_hit(
            &Vec3::new(offset, 0.0, 0.5),
            &Vec3::new(0.0, 0.0, -1.0),
            r,
            1.0,
            true,
        );
        let hit = hit.unwrap_or_else(|| panic!("offset {offset}: it fell through"));
        assert_eq!(hit.feature, Feature::HoleRim);
        assert!(
            (hit.t - expected).abs() < 1e-12,
            "offset {offset}: {} vs {expected}",
            hit.t
        );
    }
    // A finite cylinder's end narrower than the particle, approached along its axis.
    let can = shape("wall type cylinder-finite\n  radius 0.05\n  length 2\n");
    for tilt in [0.0, 1e-11, 1e-9] {
        let d = Vec3::new(tilt, 0.0, -1.0).normalize();
        let hit = can.first_hit(&Vec3::new(0.0, 0.0, 3.0), &d, r, 5.0, true);
        let hit = hit.unwrap_or_else(|| panic!("tilt {tilt}: missed the end"));
        assert_eq!(hit.feature, Feature::Rim(1));
        assert!(
            (hit.t - (2.0 - (r * r - 0.0025f64).sqrt())).abs() < 1e-8,
            "tilt {tilt}: {}",
            hit.t
        );
    }
}
