//! The global segment order of a round's candidates (M. T. Dickerson,
//! R. L. S. Drysdale, S. A. McElfresh & E. Welzl, *Fast greedy triangulation
//! algorithms*, 1997: candidates in length order), exact and with the ties
//! of the kernel's perturbation decided on the caller's numbering while the
//! rounds work on a Z-order copy.

use crate::kernel::{compare_equal_lengths_symbolic, compare_lengths, exact_squared_length, Point};
use crate::parallel::prelude::*;
use crate::spatial::{inverse_permutation, keyed_by_length, sort_keyed_runs, sort_runs};

/// Local (memory-friendly) numbering versus the caller's, which decides ties.
pub(super) struct Renumbering<'a> {
    pub(super) to_original: &'a [u32],
}

/// Original indices below this fit [`Renumbering::tie_key`]'s 31 bits.
const TIE_KEY_INDEX_LIMIT: usize = 1 << 31;

impl Renumbering<'_> {
    /// The global segment order of local-index segments (exact), both ways.
    ///
    /// That order is [`crate::kernel::segment_order`] on the original
    /// indices; the local copy holds the same coordinates, so lengths are
    /// compared there and only ties look at the original indices
    /// ([`compare_equal_lengths_symbolic`]). When `f64` computes every
    /// squared length exactly (integer coordinates, as from a file of
    /// six-decimal points, where ties are common: [`exact_squared_length`]),
    /// the order is that of one integer key per segment
    /// ([`Self::order_by_key`]); otherwise [`Self::order_by_comparison`].
    pub(super) fn ranking(&self, points: &[Point], segments: &[[u32; 2]]) -> Ranking {
        let order = self
            .order_by_key(points, segments)
            .unwrap_or_else(|| self.order_by_comparison(points, segments));
        Ranking {
            rank: inverse_permutation(&order),
            order,
        }
    }

    /// [`Self::ranking`]'s order by sorting one `u128` per segment — its
    /// exact squared length (64 bits), [`Self::tie_key`] (32 bits) and its
    /// own index (32 bits) — then, in the rare runs that agree on the first
    /// 96 bits, by the other endpoint's `(y, x)` (descending); `None` if a
    /// squared length is not exact in `f64` (or there are too many points
    /// for the key). Each key is computed from the segment's own endpoints,
    /// in the candidates' spatial order; the comparison sort it replaces read
    /// every tied segment's endpoints at random (a fifth of greedy's time on
    /// a 10⁶-point CLI run), and a key holding the `(y, x)` position too
    /// needed a sort of the points and twice the bytes a segment.
    fn order_by_key(&self, points: &[Point], segments: &[[u32; 2]]) -> Option<Vec<u32>> {
        if points.len() > TIE_KEY_INDEX_LIMIT || segments.len() > u32::MAX as usize {
            return None;
        }
        let lengths: Option<Vec<f64>> = segments
            .par_iter()
            .map(|&[a, b]| exact_squared_length(points[a as usize], points[b as usize]))
            .collect();
        let lengths = lengths?;
        let mut keys: Vec<u128> = segments
            .par_iter()
            .zip(lengths)
            .enumerate()
            .map(|(i, (&s, length))| {
                // Non-negative doubles order as their bit patterns.
                (u128::from(length.to_bits()) << 64)
                    | (u128::from(self.tie_key(points, s)) << 32)
                    | i as u128
            })
            .collect();
        keys.par_sort_unstable();
        // Runs of one length and one tie key: segments sharing the endpoint
        // of lower original index, with the same length and the same kind.
        let far = |key: u128| {
            let [a, b] = segments[key as u32 as usize];
            let u = if self.to_original[a as usize] < self.to_original[b as usize] {
                b
            } else {
                a
            };
            let p = points[u as usize];
            (p[1], p[0])
        };
        sort_runs(
            &mut keys,
            |x, y| x >> 32 == y >> 32,
            |_: &mut (), run| {
                // Descending `(y, x)` of the far endpoint: distinct points.
                run.sort_unstable_by(|&x, &y| {
                    far(y).partial_cmp(&far(x)).expect("finite coordinates")
                });
            },
        );
        Some(keys.into_par_iter().map(|k| k as u32).collect())
    }

    /// The order of [`compare_equal_lengths_symbolic`] among segments of
    /// one exact length, but for the last criterion: with `m` a segment's
    /// lower original index and `u` its other endpoint, a segment whose `m`
    /// lies strictly below `u` is shorter than every segment of larger `m`,
    /// one whose `m` does not is longer, and at equal `m` the segment with
    /// the higher `u` in `(y, x)` order is shorter. So the shorter come
    /// first as: the first kind by ascending `m`, then the second by
    /// descending `m`; within one `m`, by descending `u` (left to
    /// [`Self::order_by_key`]'s runs). Key: the kind (1 bit), then `m` or
    /// its complement (31 bits).
    fn tie_key(&self, points: &[Point], [a, b]: [u32; 2]) -> u32 {
        let (oa, ob) = (self.to_original[a as usize], self.to_original[b as usize]);
        let ((m, pm), u) = if oa < ob {
            ((oa, points[a as usize]), b)
        } else {
            ((ob, points[b as usize]), a)
        };
        let holder_longer = pm[1] >= points[u as usize][1];
        if holder_longer {
            (1u32 << 31) | (TIE_KEY_INDEX_LIMIT as u32 - 1 - m)
        } else {
            m
        }
    }

    /// [`Self::ranking`]'s order by the exact comparison (see
    /// [`sort_keyed_runs`]): squared lengths that `f64` computes
    /// exactly are compared as numbers, the others by [`compare_lengths`].
    fn order_by_comparison(&self, points: &[Point], segments: &[[u32; 2]]) -> Vec<u32> {
        let mut keyed = keyed_by_length(points, segments, |i, _| i as u32);
        let gather = |i: u32| {
            let ends =
                segments[i as usize].map(|v| (self.to_original[v as usize], points[v as usize]));
            (ends, exact_squared_length(ends[0].1, ends[1].1))
        };
        type Gathered = ([(u32, Point); 2], Option<f64>);
        let exact = |x: &Gathered, y: &Gathered| {
            let ([a, b], [c, d]) = (x.0, y.0);
            match (x.1, y.1) {
                (Some(s), Some(t)) => s.total_cmp(&t),
                _ => compare_lengths(a.1, b.1, c.1, d.1),
            }
            .then_with(|| compare_equal_lengths_symbolic(x.0, y.0))
        };
        sort_keyed_runs(&mut keyed, gather, exact);
        keyed.into_par_iter().map(|(_, i)| i).collect()
    }
}

/// The global segment order of a round's candidates (indices into the
/// candidate list): `order[r]` is the candidate of rank `r`, `rank[i]` the
/// rank of candidate `i`.
pub(super) struct Ranking {
    pub(super) order: Vec<u32>,
    pub(super) rank: Vec<u32>,
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{rngs::StdRng, seq::SliceRandom, Rng, SeedableRng};

    /// The integer keys give the comparison sort's order, with many ties
    /// (points of a 7×7 grid, halved: exact dyadic lengths), under a random
    /// renumbering; non-exact squared lengths fall back.
    #[test]
    fn integer_keys_order_segments_as_the_exact_comparison() {
        let mut rng = StdRng::seed_from_u64(12);
        for case in 0..200 {
            let mut points: Vec<Point> = (0..49)
                .map(|i| [f64::from(i % 7) * 0.5, f64::from(i / 7) * 0.5 - 1.0])
                .collect();
            points.shuffle(&mut rng);
            points.truncate(rng.gen_range(3..=49));
            let mut to_original: Vec<u32> = (0..points.len() as u32).collect();
            to_original.shuffle(&mut rng);
            let renumbering = Renumbering {
                to_original: &to_original,
            };
            let n = points.len() as u32;
            let mut segments: Vec<[u32; 2]> = Vec::new();
            for a in 0..n {
                for b in a + 1..n {
                    if rng.gen_bool(0.5) {
                        segments.push(if rng.gen_bool(0.5) { [a, b] } else { [b, a] });
                    }
                }
            }
            let by_key = renumbering.order_by_key(&points, &segments).expect("exact");
            assert_eq!(
                by_key,
                renumbering.order_by_comparison(&points, &segments),
                "case {case}"
            );
            if case % 10 == 0 && !segments.is_empty() {
                points[0][0] += 0.1; // 0.1 is not dyadic: not exact
                let touched = segments.iter().any(|s| s.contains(&0));
                assert_eq!(
                    renumbering.order_by_key(&points, &segments).is_none(),
                    touched
                );
            }
        }
    }
}
