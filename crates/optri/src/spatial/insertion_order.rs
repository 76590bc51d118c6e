//! A biased randomized insertion order (BRIO: N. Amenta, S. Choi and
//! G. Rote, *Incremental constructions con BRIO*, SoCG 2003, §2): the points
//! fall into rounds, a point into round `k` with probability `2^-(k+1)`, the
//! sparsest round comes first, and each round is in Z-order. Rounds keep the
//! expected structural change of randomized incremental Delaunay
//! construction (O(n) in total, for every input: the Clarkson–Shor bound
//! holds within a constant factor for the rounds' random samples), and the
//! Z-order within a round keeps the point location walks short and the
//! memory local.
//!
//! Why not a sweep: a sweep's structural change depends on the input, and
//! points in convex position (a parabola) or on two crossing lines make
//! every new point flip edges to a constant fraction of the points before
//! it — quadratic time. The order only schedules work; it never decides
//! anything, and the round of a point is a hash of its index, so the order
//! is a function of the points and their numbering alone.

use super::morton_order;
use crate::kernel::Point;

/// The rounds: `ROUNDS - 1` geometric ones and the rest in the first.
const ROUNDS: usize = 24;

/// A fixed seed, so that every run inserts in the same order.
const SEED: u64 = 0x0DE1_A0A7_B210_5EED;

/// The splitmix64 finalizer (S. Vigna): a bijection of `u64` whose output
/// bits are independent enough for the trailing zeros to be geometric.
fn mix(mut z: u64) -> u64 {
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

/// Indices of `points` in a biased randomized insertion order: rounds of
/// expected sizes `…, n/8, n/4, n/2` (a point's round is the number of
/// trailing zeros of a hash of its index, capped), the smallest first, each
/// in the Z-order of [`morton_order`].
pub(crate) fn brio_order(points: &[Point]) -> Vec<u32> {
    let round = |v: u32| {
        let zeros = mix(SEED.wrapping_add(u64::from(v))).trailing_zeros() as usize;
        // Round 0 (half of the points) goes last.
        ROUNDS - 1 - zeros.min(ROUNDS - 1)
    };
    let z_order = morton_order(points);
    // A stable counting sort of the Z-order by round.
    let mut start = [0usize; ROUNDS + 1];
    for &v in &z_order {
        start[round(v) + 1] += 1;
    }
    for r in 0..ROUNDS {
        start[r + 1] += start[r];
    }
    let mut order = vec![0u32; points.len()];
    for &v in &z_order {
        let r = round(v);
        order[start[r]] = v;
        start[r] += 1;
    }
    order
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every index comes once; the rounds halve (within a loose margin) and
    /// each is in Z-order.
    #[test]
    fn rounds_halve_and_keep_the_z_order() {
        let n = 1 << 14;
        let points: Vec<Point> = (0..n)
            .map(|i| [(i % 128) as f64, (i / 128) as f64])
            .collect();
        let order = brio_order(&points);
        let mut sorted = order.clone();
        sorted.sort_unstable();
        assert_eq!(sorted, (0..n as u32).collect::<Vec<_>>());
        let last_round = |v: u32| mix(SEED.wrapping_add(u64::from(v))).trailing_zeros() == 0;
        let tail = order.iter().rev().take_while(|&&v| last_round(v)).count();
        assert!(
            (n * 2 / 5..n * 3 / 5).contains(&tail),
            "{tail} of {n} in the last round"
        );
        assert!(order[..n - tail].iter().all(|&v| !last_round(v)));
        // The last round is a subsequence of the Z-order.
        let rank = crate::spatial::inverse_permutation(&morton_order(&points));
        let ranks: Vec<u32> = order[n - tail..]
            .iter()
            .map(|&v| rank[v as usize])
            .collect();
        assert!(ranks.windows(2).all(|w| w[0] < w[1]));
    }
}
