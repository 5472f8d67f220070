//! A slice put in another order in place, without a second copy of it: along each cycle
//! of the permutation, with a byte an item to mark those done. The soft-sphere run moves
//! its particles to and from their places so.

/// `items` gathered: the item at j becomes the one that was at `source(j)` (a
/// permutation of `0..items.len()`).
pub(crate) fn gather<T>(items: &mut [T], source: impl Fn(usize) -> usize) {
    along_cycles(items.len(), source, |_, j, k| items.swap(j, k));
}

/// `items` scattered: the item at j goes to `dest(j)` (a permutation of
/// `0..items.len()`); the inverse of [`gather`] with the same function.
pub(crate) fn scatter<T>(items: &mut [T], dest: impl Fn(usize) -> usize) {
    along_cycles(items.len(), dest, |start, _, k| items.swap(start, k));
}

/// Calls `step(start, j, k)` for each place j of each cycle of `next` over `0..len`,
/// from the cycle's start, with k = `next(j)` (but the cycle's last place, which leads
/// back to its start). Gathering, each place takes the item of the next (which holds
/// it until then); scattering, the item held at the start is sent on to the next, and
/// the one found there takes its turn.
fn along_cycles(
    len: usize,
    next: impl Fn(usize) -> usize,
    mut step: impl FnMut(usize, usize, usize),
) {
    let mut done = vec![false; len];
    for start in 0..len {
        if done[start] {
            continue;
        }
        done[start] = true;
        let (mut j, mut k) = (start, next(start));
        while k != start {
            step(start, j, k);
            done[k] = true;
            (j, k) = (k, next(k));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        #[test]
        fn gathered_and_scattered_back(order in (0..200usize).prop_flat_map(|n| Just((0..n).collect::<Vec<_>>()).prop_shuffle())) {
            let start: Vec<usize> = (0..order.len()).collect();
            let mut items = start.clone();
            gather(&mut items, |j| order[j]);
            prop_assert_eq!(&items, &order);
            scatter(&mut items, |j| order[j]);
            prop_assert_eq!(items, start);
        }
    }
}
