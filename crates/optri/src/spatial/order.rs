//! Orders below the graphs and criteria that share them: segments sorted by
//! a length order, the runs of a sort by a coarse key re-sorted in parallel,
//! and the inverse of a permutation. Every comparison that decides
//! something is the kernel's ([`crate::kernel::LengthOrder`], the rounded
//! keys of its squared-length module, whose docs prove the run splitting);
//! this module only arranges them.

use crate::kernel::{in_one_key_run, rounded_squared_length, LengthOrder, Point};
use crate::parallel::prelude::*;

/// Runs per parallel task in [`sort_runs`]. A tuning choice: most runs
/// hold a few segments, so a task takes many; the result does not depend
/// on it.
const RUNS_PER_TASK: usize = 1024;

/// Sorts segments (indices into `points`) by `order`.
///
/// The Euclidean order goes by rounded squared lengths first and re-sorts
/// only the runs of close keys with the exact comparison
/// ([`sort_keyed_runs`]); any other order is a comparison sort.
pub(crate) fn sort_by_length<O: LengthOrder>(
    points: &[Point],
    order: O,
    segments: &mut Vec<[u32; 2]>,
) {
    if O::EUCLIDEAN {
        let mut keyed = keyed_by_length(points, segments, |_, s| s);
        sort_keyed_runs(&mut keyed, |s| s, |x, y| order.compare(points, *x, *y));
        segments.clear();
        segments.extend(keyed.into_iter().map(|(_, s)| s));
    } else {
        segments.par_sort_unstable_by(|a, b| order.compare(points, *a, *b));
    }
}

/// `(rounded squared length, item(i, segment))` for every segment, in order:
/// the input of [`sort_keyed_runs`].
pub(crate) fn keyed_by_length<T: Send>(
    points: &[Point],
    segments: &[[u32; 2]],
    item: impl Fn(usize, [u32; 2]) -> T + Sync + Send,
) -> Vec<(f64, T)> {
    segments
        .par_iter()
        .enumerate()
        .map(|(i, &[a, b])| {
            let key = rounded_squared_length(points[a as usize], points[b as usize]);
            (key, item(i, [a, b]))
        })
        .collect()
}

/// Sorts `(rounded squared length, item)` pairs into the exact order
/// `exact`: by the rounded key first, then the runs of keys that may be out
/// of exact order ([`in_one_key_run`]) by `exact`, which compares what
/// `gather` takes from each item of the run.
///
/// Why the gathering and the parallel runs: on integer coordinates (a file
/// of six-decimal points, scaled) equal squared lengths are common, most
/// keys sit in runs, and the exact comparisons are most of the sort's work.
/// A run's items lie anywhere in the input, so `gather` reads each one's
/// data once (one scattered read per item, not two per comparison) into a
/// buffer that the comparisons then share.
pub(crate) fn sort_keyed_runs<T: Send + Copy, G: Send>(
    keyed: &mut [(f64, T)],
    gather: impl Fn(T) -> G + Sync,
    exact: impl Fn(&G, &G) -> std::cmp::Ordering + Sync,
) {
    keyed.par_sort_unstable_by(|x, y| x.0.total_cmp(&y.0));
    sort_runs(
        keyed,
        |x, y| in_one_key_run(x.0, y.0),
        |buffer: &mut Vec<(f64, T, G)>, run| {
            buffer.clear();
            buffer.extend(run.iter().map(|&(key, item)| (key, item, gather(item))));
            buffer.sort_unstable_by(|x, y| exact(&x.2, &y.2));
            for (slot, &(key, item, _)) in run.iter_mut().zip(&*buffer) {
                *slot = (key, item);
            }
        },
    );
}

/// Calls `sort` on every run of two or more consecutive items of `items`
/// that `same_run` joins (each item with the next), in parallel,
/// [`RUNS_PER_TASK`] runs a task, each task with its own scratch `S`: the
/// second step of a sort by a coarse key, which leaves the order within
/// a run of equal coarse keys to `sort`.
pub(crate) fn sort_runs<T: Send, S: Default>(
    items: &mut [T],
    same_run: impl Fn(&T, &T) -> bool,
    sort: impl Fn(&mut S, &mut [T]) + Sync,
) {
    let mut runs: Vec<&mut [T]> = Vec::new();
    let mut rest = items;
    while !rest.is_empty() {
        let mut end = 1;
        while end < rest.len() && same_run(&rest[end - 1], &rest[end]) {
            end += 1;
        }
        let (run, tail) = rest.split_at_mut(end);
        if end > 1 {
            runs.push(run);
        }
        rest = tail;
    }
    runs.par_chunks_mut(RUNS_PER_TASK).for_each(|chunk| {
        let mut scratch = S::default();
        for run in chunk.iter_mut() {
            sort(&mut scratch, run);
        }
    });
}

/// The inverse of the permutation `order` of `0..order.len()`, in parallel
/// (each slot is written once; relaxed atomics only make the scattered
/// writes safe).
pub(crate) fn inverse_permutation(order: &[u32]) -> Vec<u32> {
    use std::sync::atomic::{AtomicU32, Ordering::Relaxed};
    let inverse: Vec<AtomicU32> = (0..order.len()).map(|_| AtomicU32::new(0)).collect();
    order
        .par_iter()
        .enumerate()
        .for_each(|(at, &v)| inverse[v as usize].store(at as u32, Relaxed));
    inverse.into_iter().map(AtomicU32::into_inner).collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::{compare_lengths_symbolic, EuclideanOrder, Metric};
    use rand::{rngs::StdRng, seq::SliceRandom, Rng, SeedableRng};

    /// Seed of the point sets below.
    const SEED: u64 = 77;

    /// Points with many exact and near ties: a small integer grid, the same
    /// grid scaled by 0.1 (lengths equal up to rounding), and a circle
    /// sampled with cos/sin.
    fn tied_points(rng: &mut StdRng, case: usize) -> Vec<Point> {
        let mut points: Vec<Point> = match case % 3 {
            0 => (0..36)
                .map(|i| [f64::from(i % 6), f64::from(i / 6)])
                .collect(),
            1 => (0..36)
                .map(|i| [0.1 * f64::from(i % 6), 0.1 * f64::from(i / 6)])
                .collect(),
            _ => (0..36)
                .map(|i| {
                    let t = std::f64::consts::TAU * f64::from(i) / 36.0;
                    [1e3 * t.cos(), 1e3 * t.sin()]
                })
                .collect(),
        };
        points.shuffle(rng);
        points.truncate(rng.gen_range(4..=36));
        points
    }

    /// Both branches of `sort_by_length` give the order of a plain
    /// comparison sort by the exact symbolic comparison, on inputs full of
    /// ties, and the keyed branch forms runs at all.
    #[test]
    fn sorted_segments_follow_the_exact_order() {
        let mut rng = StdRng::seed_from_u64(SEED);
        let mut tied_runs = 0;
        for case in 0..60 {
            let points = tied_points(&mut rng, case);
            let n = points.len() as u32;
            let mut segments: Vec<[u32; 2]> = Vec::new();
            for a in 0..n {
                for b in a + 1..n {
                    segments.push(if rng.gen_bool(0.5) { [a, b] } else { [b, a] });
                }
            }
            segments.shuffle(&mut rng);
            let mut want = segments.clone();
            want.sort_by(|s, t| compare_lengths_symbolic(&points, *s, *t));
            let mut keys: Vec<f64> = keyed_by_length(&points, &segments, |_, s| s)
                .into_iter()
                .map(|(key, _)| key)
                .collect();
            keys.sort_by(f64::total_cmp);
            tied_runs += keys
                .windows(2)
                .filter(|w| in_one_key_run(w[0], w[1]))
                .count();
            let mut by_keys = segments.clone();
            sort_by_length(&points, EuclideanOrder, &mut by_keys);
            assert_eq!(by_keys, want, "case {case}");
            let euclidean = Metric::euclidean();
            let mut by_comparison = segments.clone();
            sort_by_length(&points, &euclidean, &mut by_comparison);
            assert_eq!(by_comparison, want, "case {case}");
        }
        assert!(tied_runs > 100, "{tied_runs}");
    }

    #[test]
    fn inverse_permutation_inverts() {
        let mut rng = StdRng::seed_from_u64(SEED);
        let mut order: Vec<u32> = (0..1000).collect();
        order.shuffle(&mut rng);
        let inverse = inverse_permutation(&order);
        for (at, &v) in order.iter().enumerate() {
            assert_eq!(inverse[v as usize], at as u32);
        }
    }
}
