//! Each particle's 1/m and 1/I for the soft-sphere run's kicks ([`Inverses`]): one pair
//! for all when every particle has the same mass and radius.

use super::{State, inertia};

/// Each particle's 1/m and 1/I (a solid sphere's I = 0.4·m·r²), worked out once: a
/// division costs as much as the rest of a free particle's step. Kept beside the states,
/// which the drift writes back every step (it only reads these, and only for the
/// particles it kicks with a load). When every particle has the same mass and radius (to
/// the bit), the one pair they share: a monodisperse run keeps 16 bytes rather than 16 a
/// particle (16 MB at 10⁶).
pub(super) enum Inverses {
    /// Particle i's at i (its place).
    Each(Vec<(f64, f64)>),
    /// Every particle's.
    All((f64, f64)),
}

impl Inverses {
    /// The 1/m and 1/I of the particles `states`.
    pub(super) fn new(states: &[State]) -> Inverses {
        let of = |s: &State| {
            let p = &s.particle;
            (1.0 / p.mass, 1.0 / inertia(p.mass, p.radius))
        };
        let bits = |s: &State| (s.particle.mass.to_bits(), s.particle.radius.to_bits());
        match states.split_first() {
            Some((first, rest)) if rest.iter().all(|s| bits(s) == bits(first)) => {
                Inverses::All(of(first))
            }
            _ => Inverses::Each(states.iter().map(of).collect()),
        }
    }

    /// Particle `i`'s (at place `i`).
    #[inline]
    pub(super) fn of(&self, i: usize) -> (f64, f64) {
        match self {
            Inverses::Each(each) => each[i],
            Inverses::All(all) => *all,
        }
    }

    /// The largest 1/m or 1/I, by `largest`, from 0.
    pub(super) fn largest(&self, largest: impl Fn(f64, f64) -> f64) -> f64 {
        let each = |i: &(f64, f64)| largest(i.0, i.1);
        match self {
            Inverses::Each(v) => v.iter().map(each).fold(0.0, &largest),
            Inverses::All(all) => largest(0.0, each(all)),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use walls_geometry::Particle;

    fn states(radii: &[f64]) -> Vec<State> {
        let at = |(i, &r): (usize, &f64)| {
            State::new(&Particle::at_rest(
                r,
                nalgebra::Vector3::new(i as f64, 0.0, 0.0),
                i,
            ))
        };
        radii.iter().enumerate().map(at).collect()
    }

    #[test]
    fn one_pair_for_particles_alike_each_its_own_otherwise() {
        let alike = Inverses::new(&states(&[0.5, 0.5, 0.5]));
        let each = Inverses::new(&states(&[0.5, 0.5, 0.25]));
        assert!(matches!(alike, Inverses::All(_)));
        assert!(matches!(each, Inverses::Each(_)));
        // The same numbers as each particle's own, to the bit.
        let m = Particle::at_rest(0.5, nalgebra::Vector3::zeros(), 0).mass;
        let own = (1.0 / m, 1.0 / inertia(m, 0.5));
        assert_eq!(alike.of(2), own);
        assert_eq!(each.of(0), own);
        assert_ne!(each.of(2), own);
        let largest = |a: f64, b: f64| a.max(b);
        assert_eq!(alike.largest(largest), own.0.max(own.1));
        assert_eq!(Inverses::new(&[]).largest(largest), 0.0);
    }
}
