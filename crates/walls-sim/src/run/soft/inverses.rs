//! Each particle's 1/m and 1/I for the soft-sphere run's kicks ([`Inverses`]): one pair
//! for all when every particle has the same mass and radius.

use super::{CHUNK, State, inertia};
use rayon::prelude::*;

/// Each particle's 1/m and 1/I (a solid sphere's I = 0.4·m·r²), worked out once: a
/// division costs as much as the rest of a free particle's step. Kept beside the states,
/// which the drift writes back every step (it only reads these), and handed to the
/// passes chunk by chunk, beside the states' chunks. When every particle has the same
/// mass and radius (to the bit), one chunk's worth of their one pair stands for every
/// chunk: a monodisperse run keeps 8 KB rather than 16 bytes a particle (16 MB at 10⁶),
/// and the drift reads it from the processor's first cache rather than from memory.
pub(super) struct Inverses {
    /// Particle i's at i (its place); or, when `shared`, the one pair [`CHUNK`] times.
    values: Vec<(f64, f64)>,
    /// Whether every particle's is the one pair in `values`.
    shared: bool,
    /// How many particles.
    len: usize,
}

impl Inverses {
    /// The 1/m and 1/I of the particles `states`.
    pub(super) fn new(states: &[State]) -> Inverses {
        let of = |s: &State| {
            let p = &s.particle;
            (1.0 / p.mass, 1.0 / inertia(p.mass, p.radius))
        };
        let bits = |s: &State| (s.particle.mass.to_bits(), s.particle.radius.to_bits());
        let (values, shared) = match states.split_first() {
            Some((first, rest)) if rest.iter().all(|s| bits(s) == bits(first)) => {
                (vec![of(first); CHUNK.min(states.len())], true)
            }
            _ => (states.iter().map(of).collect(), false),
        };
        Inverses {
            values,
            shared,
            len: states.len(),
        }
    }

    /// Chunk `c` of [`CHUNK`] particles (the last one shorter).
    #[inline]
    fn chunk(&self, c: usize) -> &[(f64, f64)] {
        let (start, end) = (c * CHUNK, ((c + 1) * CHUNK).min(self.len));
        if self.shared {
            &self.values[..end - start]
        } else {
            &self.values[start..end]
        }
    }

    /// The particles' in chunks of [`CHUNK`], as `states.chunks(CHUNK)` cuts the states.
    ///
    /// # Panics
    /// If `size` is not [`CHUNK`].
    pub(super) fn chunks(&self, size: usize) -> impl Iterator<Item = &[(f64, f64)]> {
        assert_eq!(size, CHUNK, "the inverses come in the passes' chunks");
        (0..self.len.div_ceil(CHUNK)).map(|c| self.chunk(c))
    }

    /// [`Inverses::chunks`] on rayon's threads.
    ///
    /// # Panics
    /// If `size` is not [`CHUNK`].
    pub(super) fn par_chunks(
        &self,
        size: usize,
    ) -> impl IndexedParallelIterator<Item = &[(f64, f64)]> {
        assert_eq!(size, CHUNK, "the inverses come in the passes' chunks");
        (0..self.len.div_ceil(CHUNK))
            .into_par_iter()
            .map(|c| self.chunk(c))
    }

    /// Each particle's, in order.
    pub(super) fn iter(&self) -> impl Iterator<Item = &(f64, f64)> {
        self.chunks(CHUNK).flatten()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use walls_geometry::Particle;

    /// Particles at rest of unit density and radii `radii`, in a row along x.
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
        let n = CHUNK + 3;
        let alike = Inverses::new(&states(&vec![0.5; n]));
        let mut radii = vec![0.5; n];
        radii[n - 1] = 0.25;
        let each = Inverses::new(&states(&radii));
        // One chunk's worth for all, or one a particle.
        assert_eq!(alike.values.len(), CHUNK);
        assert_eq!(each.values.len(), n);
        // The same numbers as each particle's own, to the bit, in chunks as the states'.
        let m = Particle::at_rest(0.5, nalgebra::Vector3::zeros(), 0).mass;
        let own = (1.0 / m, 1.0 / inertia(m, 0.5));
        let lengths = |i: &Inverses| i.chunks(CHUNK).map(<[_]>::len).collect::<Vec<_>>();
        assert_eq!(lengths(&alike), [CHUNK, 3]);
        assert_eq!(lengths(&each), [CHUNK, 3]);
        let par: Vec<_> = alike.par_chunks(CHUNK).map(<[_]>::len).collect();
        assert_eq!(par, [CHUNK, 3]);
        assert!(alike.iter().all(|&i| i == own));
        assert_eq!(alike.iter().count(), n);
        assert!(each.iter().take(n - 1).all(|&i| i == own));
        assert_ne!(each.iter().last(), Some(&own));
        assert_eq!(Inverses::new(&[]).iter().count(), 0);
    }
}
