//! Where each particle is kept in the soft-sphere run ([`Numbering`]): in the pair grid's
//! order, not the file's, so that the two spheres of a candidate pair are near each
//! other in memory as they are in space.
//!
//! The particles come numbered as their file lists them (a lattice is written x
//! fastest), and the pair grid orders cells x slowest: at 10⁶ particles three quarters
//! of the pairs' first test was the load of a pair's second sphere, a cache miss
//! (docs/performance-history.md, issue 42). Set-up therefore keeps each particle at its
//! *place* in the grid's order ([`Numbering::along`]). Nothing else changes: the pair
//! grid ranks each particle by its number in the file ([`CellGrid::refill_ranked`]), so
//! the pairs come in the same order and each pair the same way round, and each load sums
//! its forces as before; what the run reports (events, warnings, the first particle not
//! finite) names the file's numbers, in the file's order; and whoever looks at the
//! particles sees them in the file's order ([`crate::run::Snapshot`]). The outputs are
//! those of a run kept in the file's order, bit for bit.
//!
//! [`CellGrid::refill_ranked`]: crate::broad::grid::CellGrid::refill_ranked

use crate::permute;

/// Each place's particle by its number in the file: empty when the places are the
/// file's order.
#[derive(Default)]
pub(super) struct Numbering {
    file_of: Vec<u32>,
}

impl Numbering {
    /// The places `order` gives (the particle at each place, every one once), the
    /// file's order if it is that.
    pub(super) fn along(order: Vec<u32>) -> Numbering {
        let same = order.iter().zip(0..).all(|(&i, n)| i == n);
        Numbering {
            file_of: if same { Vec::new() } else { order },
        }
    }

    /// Whether the places are the file's order.
    pub(super) fn in_file_order(&self) -> bool {
        self.file_of.is_empty()
    }

    /// The file's number of the particle at `place`.
    #[inline]
    pub(super) fn file(&self, place: usize) -> usize {
        self.file_of.get(place).map_or(place, |&i| i as usize)
    }

    /// `items`, one per particle in the file's order, moved to the particles' places
    /// (in place: no second copy).
    pub(super) fn to_places<T>(&self, items: &mut [T]) {
        if !self.in_file_order() {
            permute::gather(items, |place| self.file_of[place] as usize);
        }
    }

    /// `items`, one per place, put back in the file's order (the inverse of
    /// [`Numbering::to_places`]).
    pub(super) fn to_file<T>(&self, items: &mut [T]) {
        if !self.in_file_order() {
            permute::scatter(items, |place| self.file_of[place] as usize);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        #[test]
        fn places_and_back(order in (0..200u32).prop_flat_map(|n| Just((0..n).collect::<Vec<_>>()).prop_shuffle())) {
            let numbering = Numbering::along(order.clone());
            let file: Vec<u32> = (0..order.len() as u32).collect();
            let mut items = file.clone();
            numbering.to_places(&mut items);
            prop_assert_eq!(&items, &order);
            let numbers: Vec<u32> = (0..order.len()).map(|p| numbering.file(p) as u32).collect();
            prop_assert_eq!(&numbers, &order);
            numbering.to_file(&mut items);
            prop_assert_eq!(items, file);
        }
    }

    #[test]
    fn the_files_order_is_kept_as_it_is() {
        let numbering = Numbering::along(vec![0, 1, 2]);
        assert!(numbering.in_file_order());
        assert_eq!(numbering.file(2), 2);
    }
}
