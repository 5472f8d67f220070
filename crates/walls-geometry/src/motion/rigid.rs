//! A wall's motion at one instant, as a rigid body's: where its origin is, how fast the
//! origin moves, and its spin (docs/spec.md §3 "Contact velocity"). The velocity of its
//! material at a point, and a point the wall holds (a particle stuck to a sticky wall,
//! docs/pkdgrav-physics.md §6) carried over a step, turned about the spin axis.

use nalgebra::{Rotation3, Unit, Vector3};

type Vec3 = Vector3<f64>;

/// A wall moving at one instant: its origin, the origin's velocity, and its angular
/// velocity about the origin.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Moving {
    /// Where its origin is.
    pub origin: Vec3,
    /// How fast its origin moves.
    pub velocity: Vec3,
    /// Its angular velocity.
    pub spin: Vec3,
}

impl Moving {
    /// The velocity of the wall's material at `q`: the origin's velocity plus the spin
    /// about the origin.
    #[inline]
    pub fn point_velocity(&self, q: &Vec3) -> Vec3 {
        self.velocity + self.spin.cross(&(q - self.origin))
    }

    /// Carries a point the wall holds, `offset` from its origin, over a step of `dt` that
    /// ends with the wall as it is now: the offset turned about the spin axis by the
    /// step's turn ([`turned`]). Returns where the point is and how fast it moves.
    #[inline]
    pub fn carry(&self, offset: &mut Vec3, dt: f64) -> (Vec3, Vec3) {
        *offset = turned(&self.spin, dt, *offset);
        let at = self.origin + *offset;
        (at, self.point_velocity(&at))
    }
}

/// `v` turned about the axis of `spin` by its rate times `time` (unchanged when there is
/// no spin).
pub fn turned(spin: &Vec3, time: f64, v: Vec3) -> Vec3 {
    match Unit::try_new(*spin, 0.0) {
        Some(axis) => Rotation3::from_axis_angle(&axis, spin.norm() * time) * v,
        None => v,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::FRAC_PI_2;

    fn close(a: Vec3, b: Vec3) -> bool {
        (a - b).norm() < 1e-12
    }

    #[test]
    fn turned_follows_the_right_hand_about_the_spin() {
        let spin = Vec3::new(0.0, 0.0, 2.0);
        // A quarter turn: 2 rad/s for π/4 s.
        let v = turned(&spin, FRAC_PI_2 / 2.0, Vec3::x());
        assert!(close(v, Vec3::y()), "{v}");
        // Backwards in time, the other way.
        assert!(close(
            turned(&spin, -FRAC_PI_2 / 2.0, Vec3::x()),
            -Vec3::y()
        ));
        // No spin, no turn (to the bit).
        let w = Vec3::new(0.1, -0.2, 0.3);
        assert_eq!(turned(&Vec3::zeros(), 5.0, w), w);
    }

    #[test]
    fn the_material_moves_with_the_origin_and_the_spin() {
        let wall = Moving {
            origin: Vec3::new(1.0, 0.0, 0.0),
            velocity: Vec3::new(0.0, 0.0, 3.0),
            spin: Vec3::new(0.0, 0.0, 2.0),
        };
        assert_eq!(wall.point_velocity(&wall.origin), wall.velocity);
        let v = wall.point_velocity(&Vec3::new(2.0, 0.0, 0.0));
        assert!(close(v, Vec3::new(0.0, 2.0, 3.0)), "{v}");
    }

    #[test]
    fn a_held_point_turns_with_the_wall_and_moves_with_its_material() {
        let wall = Moving {
            origin: Vec3::new(0.0, 0.0, 1.0),
            velocity: Vec3::new(0.5, 0.0, 0.0),
            spin: Vec3::new(0.0, 0.0, FRAC_PI_2),
        };
        let mut offset = Vec3::x();
        let (at, v) = wall.carry(&mut offset, 1.0);
        assert!(close(offset, Vec3::y()), "{offset}");
        assert!(close(at, Vec3::new(0.0, 1.0, 1.0)), "{at}");
        assert_eq!(v, wall.point_velocity(&at));
    }
}
