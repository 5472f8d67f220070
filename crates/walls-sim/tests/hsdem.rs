//! The hard-sphere bounce and collision prediction against analytic answers, exact to
//! 1e−12 relative.

use nalgebra::Vector3;
use walls_sim::hsdem::{bounce, plane_hit};

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

#[test]
fn predicting_a_hit_on_a_moving_plane() {
    // Falling at 2 from height 1 (radius 0.1) onto a plane rising at 0.5: contact after
    // (1 − 0.1)/2.5 = 0.36.
    let t = plane_hit(
        &Vec3::new(0.0, 0.0, 1.0),
        &Vec3::new(0.0, 0.0, -2.0),
        0.1,
        &Vec3::zeros(),
        &Vec3::z(),
        &Vec3::new(0.0, 0.0, 0.5),
        1.0,
    );
    assert!((t.unwrap() - 0.36).abs() <= 1e-12 * 0.36);
    // Not within a shorter step, nor when moving away, and from below as well.
    assert_eq!(
        plane_hit(
            &Vec3::new(0.0, 0.0, 1.0),
            &Vec3::new(0.0, 0.0, -2.0),
            0.1,
            &Vec3::zeros(),
            &Vec3::z(),
            &Vec3::zeros(),
            0.1
        ),
        None
    );
    assert_eq!(
        plane_hit(
            &Vec3::new(0.0, 0.0, 1.0),
            &Vec3::new(0.0, 0.0, 2.0),
            0.1,
            &Vec3::zeros(),
            &Vec3::z(),
            &Vec3::zeros(),
            1.0
        ),
        None
    );
    let below = plane_hit(
        &Vec3::new(0.0, 0.0, -1.0),
        &Vec3::new(0.0, 0.0, 3.0),
        0.1,
        &Vec3::zeros(),
        &Vec3::z(),
        &Vec3::zeros(),
        1.0,
    );
    assert!((below.unwrap() - 0.3).abs() <= 1e-12 * 0.3);
}
