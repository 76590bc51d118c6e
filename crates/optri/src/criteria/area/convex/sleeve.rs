//! Steps i–iii of Algorithm 44 (Vassilev 2005, §2.3.1, L1807-1864; Lemma 45):
//! the geometry of sub-polygons (zonality, `Top`, `MaxCW`/`MaxCCW`, strips)
//! and the O(n²) sleeve dynamic program over the pieces of zonality ≤ 2;
//! and step v, reconstruction from the stored sleeve choices.
//!
//! Conventions: positions `0..n` along the counter-clockwise
//! cycle, read modulo `n`; the piece `P_ij` is stored as `(i, len)` with
//! `j = i + len`, `1 ≤ len ≤ n − 1`, and `i < k < i + n` for positions
//! inside a range are kept unreduced. Offsets `r = k − i` measure a vertex
//! of `P_ij` from `i`.

use super::super::AreaBottleneck;
use crate::error::Result;
use crate::interrupt::Stop;
use crate::kernel::cross_sign;
use crate::kernel::{compare_areas, dot_sign, orient_sign, Point, MAX_COORDINATE, MIN_COORDINATE};
use std::cmp::Ordering;

/// Marks a piece that the sleeve program does not solve: a boundary edge
/// (`len = 1`: never a sub-problem in step iv, repair T2 of the module docs
/// of `convex`) or a
/// piece of zonality ≥ 3.
pub(super) const UNSOLVED: u32 = u32::MAX;

/// First index in `lo..=hi` where the monotone predicate (false…false,
/// true…true) holds, or `hi + 1` if it never does.
pub(super) fn first_true(lo: usize, hi: usize, pred: impl FnMut(usize) -> bool) -> usize {
    first_true_before(lo, hi + 1, pred)
}

/// [`first_true`] on the half-open range `lo..end`: `end` if it never holds.
fn first_true_before(mut lo: usize, mut end: usize, mut pred: impl FnMut(usize) -> bool) -> usize {
    while lo < end {
        let mid = lo + (end - lo) / 2;
        if pred(mid) {
            end = mid;
        } else {
            lo = mid + 1;
        }
    }
    lo
}

/// [`first_true`] by a galloping search from `guess`: the same answer, in
/// O(log d) evaluations where `d` is its distance from `guess`. Step iv
/// searches neighbouring pairs one after the other, and their answers
/// (strip ends, switch points) lie close together, so this replaces
/// O(log n) evaluations by a few.
pub(super) fn first_true_near(
    lo: usize,
    hi: usize,
    guess: usize,
    mut pred: impl FnMut(usize) -> bool,
) -> usize {
    if lo > hi {
        return lo;
    }
    let guess = guess.clamp(lo, hi);
    let mut step = 1;
    if pred(guess) {
        // The answer is in [lo, upper]; widen downwards until pred fails.
        let mut upper = guess;
        loop {
            if upper - lo < step {
                return first_true_before(lo, upper, pred);
            }
            let probe = upper - step;
            if !pred(probe) {
                return first_true_before(probe + 1, upper, pred);
            }
            upper = probe;
            step *= 2;
        }
    } else {
        // The answer is in (lower, hi + 1]; widen upwards until pred holds.
        let mut lower = guess;
        loop {
            if hi - lower < step {
                return first_true_before(lower + 1, hi + 1, pred);
            }
            let probe = lower + step;
            if pred(probe) {
                return first_true_before(lower + 1, probe, pred);
            }
            lower = probe;
            step *= 2;
        }
    }
}

/// A strictly convex polygon, counter-clockwise, as positions into `points`.
pub(super) struct ConvexPolygon<'a> {
    polygon: &'a [u32],
    /// The points of the cycle twice over, `cycle[pos]` for `pos < 2n`: every
    /// position of step iv is below `2n`, so no position needs a division.
    cycle: Vec<Point>,
    pub(super) n: usize,
}

impl<'a> ConvexPolygon<'a> {
    /// Wraps the input after checking the contract of the public functions.
    ///
    /// # Panics
    /// If `polygon` has fewer than 3 or more than 65535 vertices, a
    /// coordinate is outside the kernel's exact range
    /// ([`crate::kernel::MAX_COORDINATE`]), or the polygon is not a strictly
    /// convex counter-clockwise cycle (every turn strictly left and the
    /// boundary winding once).
    pub(super) fn new(points: &'a [Point], polygon: &'a [u32]) -> Self {
        let n = polygon.len();
        assert!(n >= 3, "a polygon needs at least 3 vertices");
        assert!(n <= 65535, "polygon too large for the O(n²) tables");
        let in_range = |v: f64| v == 0.0 || (MIN_COORDINATE..=MAX_COORDINATE).contains(&v.abs());
        assert!(
            polygon
                .iter()
                .all(|&v| points[v as usize].iter().all(|&c| in_range(c))),
            "coordinates outside the kernel's exact range"
        );
        let cycle = (0..2 * n)
            .map(|pos| points[polygon[pos % n] as usize])
            .collect();
        let poly = ConvexPolygon { polygon, cycle, n };
        assert!(
            poly.is_strictly_convex_ccw(),
            "polygon is not strictly convex and counter-clockwise"
        );
        poly
    }

    /// Every turn is strictly left, and the edge directions pass from the
    /// lower to the upper half-plane exactly once (winding number 1).
    fn is_strictly_convex_ccw(&self) -> bool {
        let n = self.n;
        let upper = |a: Point, b: Point| b[1] > a[1] || (b[1] == a[1] && b[0] > a[0]);
        let mut wraps = 0;
        for t in 0..n {
            let (a, b, c) = (self.at(t), self.at(t + 1), self.at(t + 2));
            if orient_sign(a, b, c) <= 0 {
                return false;
            }
            if !upper(a, b) && upper(b, c) {
                wraps += 1;
            }
        }
        wraps == 1
    }

    /// The point at position `pos` (mod n), `pos < 2n`.
    #[inline]
    pub(super) fn at(&self, pos: usize) -> Point {
        self.cycle[pos]
    }

    /// The input vertex index at position `pos` (mod n).
    #[inline]
    pub(super) fn vertex(&self, pos: usize) -> u32 {
        self.polygon[pos % self.n]
    }

    /// The triangle with the given positions, as points.
    #[inline]
    pub(super) fn triangle(&self, t: [usize; 3]) -> [Point; 3] {
        [self.at(t[0]), self.at(t[1]), self.at(t[2])]
    }

    /// Exact comparison of the areas of two triangles given by positions.
    #[inline]
    pub(super) fn compare_triangles(&self, s: [usize; 3], t: [usize; 3]) -> Ordering {
        compare_areas(self.triangle(s), self.triangle(t))
    }

    /// z(P_{i,i+len}) ≤ 2, for `len ≥ 2` (Def. 27): the base
    /// angles sum to at most 180°, i.e. the two side edges at the base turn
    /// by at most a half-turn: `cross(v_{i+1} − v_i, v_{j−1} − v_j)` has the
    /// sign of `orient(v_i, v_j, v_{i+1})` or is zero.
    pub(super) fn at_most_two_zones(&self, i: usize, len: usize) -> bool {
        debug_assert!(len >= 2);
        let j = i + len;
        let (vi, vj) = (self.at(i), self.at(j));
        let side = orient_sign(vi, vj, self.at(i + 1));
        cross_sign(vi, self.at(i + 1), vj, self.at(j - 1)) * side >= 0
    }

    /// `mcw(i)` for every `i` (Def. 38, computed directly from the
    /// zonality test: repair T10): the largest `len ≤ n − 1` with z(P_{i,i+len}) ≤ 2.
    ///
    /// Zonality grows with the chain (its total turning does), so the end
    /// `i + mcw(i)` never moves backwards as `i` advances: a two-pointer scan,
    /// O(n) exact tests.
    pub(super) fn max_clockwise(&self) -> Vec<usize> {
        let n = self.n;
        let mut mcw = vec![0; n];
        let mut end: usize = 2;
        for (i, slot) in mcw.iter_mut().enumerate() {
            let mut len = end.saturating_sub(i).max(2);
            while len < n - 1 && self.at_most_two_zones(i, len + 1) {
                len += 1;
            }
            *slot = len;
            end = i + len;
        }
        mcw
    }

    /// `mccw(j)` for every `j`: the largest `len` with z(P_{j−len,j}) ≤ 2.
    /// Mirror of [`Self::max_clockwise`]: the start `j − mccw(j)` never moves
    /// forward as `j` decreases.
    pub(super) fn max_counter_clockwise(&self) -> Vec<usize> {
        let n = self.n;
        let mut mccw = vec![0; n];
        let mut previous: usize = 2;
        for j in (0..n).rev() {
            let end = j + n; // unreduced, so that end − len ≥ 0
            let mut len = previous.saturating_sub(1).max(2);
            while len < n - 1 && self.at_most_two_zones(end - len - 1, len + 1) {
                len += 1;
            }
            mccw[j] = len;
            previous = len;
        }
        mccw
    }

    /// Is `v_{i+r+1}` strictly farther from the line `v_i v_{i+len}` than
    /// `v_{i+r}`? Both are on the chain's side, so this is the sign of
    /// `cross(v_j − v_i, v_{t+1} − v_t)` relative to the chain's side.
    fn rises(&self, i: usize, len: usize, r: usize) -> bool {
        let (vi, vj) = (self.at(i), self.at(i + len));
        let side = orient_sign(vi, vj, self.at(i + 1));
        cross_sign(vi, vj, self.at(i + r), self.at(i + r + 1)) * side > 0
    }

    /// Offset of Top(v_i v_{i+len}) (Def. 26): the vertex strictly inside the
    /// chain farthest from the base line, the first of two on a tie.
    ///
    /// Heights along the chain rise strictly, then possibly two adjacent
    /// vertices tie, then fall strictly (Def. 26), so "the next vertex is
    /// strictly higher" is true…true, false…false: one binary search.
    pub(super) fn top_offset(&self, i: usize, len: usize) -> usize {
        debug_assert!(len >= 2);
        first_true(1, len - 2, |r| !self.rises(i, len, r)).min(len - 1)
    }

    /// Restricts the offsets `[lo, hi]` (inside `[1, len − 1]`) to
    /// strip(i, i+len): the vertices whose projection on the line
    /// `v_i v_j` falls on the segment (L2232). Each half-plane cuts the
    /// convex chain in a contiguous run that starts (resp. ends) the chain,
    /// so both ends are monotone searches. `None` if nothing remains.
    ///
    /// `guess` holds offsets `(start, beyond)` where the searches start (any
    /// values give the same answer); it is overwritten with this strip's
    /// first offset and the first offset past it, the guesses for the
    /// neighbouring pair.
    pub(super) fn clip_to_strip(
        &self,
        i: usize,
        len: usize,
        lo: usize,
        hi: usize,
        guess: &mut (usize, usize),
    ) -> Option<(usize, usize)> {
        let (vi, vj) = (self.at(i), self.at(i + len));
        let lo = first_true_near(lo, hi, guess.0, |r| dot_sign(vi, self.at(i + r), vj) >= 0);
        guess.0 = lo;
        if lo > hi {
            return None;
        }
        let beyond = first_true_near(lo, hi, guess.1, |r| dot_sign(vj, self.at(i + r), vi) < 0);
        guess.1 = beyond;
        (beyond > lo).then(|| (lo, beyond - 1))
    }
}

/// Top(v_i v_j) for a fixed `i` as `j` advances: the farthest vertex from a
/// chord rotating forward never moves backwards (rotating calipers,
/// L1104-1160), so a whole row costs O(n) height comparisons.
pub(super) struct TopFromStart<'p, 'a> {
    poly: &'p ConvexPolygon<'a>,
    i: usize,
    top: usize,
}

impl<'p, 'a> TopFromStart<'p, 'a> {
    pub(super) fn new(poly: &'p ConvexPolygon<'a>, i: usize) -> Self {
        TopFromStart { poly, i, top: 1 }
    }

    /// The offset of Top(v_i v_{i+len}); `len ≥ 2`, non-decreasing between calls.
    pub(super) fn offset(&mut self, len: usize) -> usize {
        let mut r = self.top;
        while r + 1 < len && self.poly.rises(self.i, len, r) {
            r += 1;
        }
        self.top = r;
        r
    }
}

/// Top(v_i v_j) for a fixed `j` as `i` moves backwards: the mirror image of
/// [`TopFromStart`], Top never moves forwards.
pub(super) struct TopFromEnd<'p, 'a> {
    poly: &'p ConvexPolygon<'a>,
    /// `j + n`, so that `end − len` is a non-negative position.
    end: usize,
    /// Unreduced position of the last Top.
    position: usize,
}

impl<'p, 'a> TopFromEnd<'p, 'a> {
    pub(super) fn new(poly: &'p ConvexPolygon<'a>, j: usize) -> Self {
        let end = j % poly.n + poly.n;
        TopFromEnd {
            poly,
            end,
            position: end - 1,
        }
    }

    /// The offset from `i = j − len` of Top(v_i v_j); `len ≥ 2`,
    /// non-decreasing between calls. Top is the last offset `r` whose vertex
    /// is strictly higher than its predecessor (offset 1 always is).
    pub(super) fn offset(&mut self, len: usize) -> usize {
        let i = self.end - len;
        let mut r = self.position - i;
        while r > 1 && !self.poly.rises(i, len, r - 1) {
            r -= 1;
        }
        self.position = i + r;
        r
    }
}

/// An area value in step iv: a table value (by rank) or the area of a
/// triangle given by positions.
#[derive(Clone, Copy, Debug)]
pub(super) enum Bottleneck {
    /// The area behind a rank of the table.
    Ranked(u32),
    /// The area of this triangle (positions).
    Triangle([usize; 3]),
}

/// What step iv found; step v turns it into triangles (L2351-2358).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Witness {
    /// The whole polygon as the solved piece `P_{i,i+n−1}` (used for n = 3).
    Whole { i: usize },
    /// A 2-2 diagonal `(i, i+len)`: both pieces solved.
    Diagonal { i: usize, len: usize },
    /// An internal 2-2-2 triangle `(i, i+r, i+len)`: all three pieces solved.
    Triangle { i: usize, r: usize, len: usize },
}

/// The sleeve table of steps ii–iii (Lemma 45): for every piece of
/// zonality ≤ 2 the optimum μ* (or λ*) and which base-adjacent triangle the
/// optimal sleeve uses.
///
/// Values are stored as *ranks*: after the program, the distinct bottleneck
/// triangles are sorted once, exactly, and equal areas share a rank, so that
/// step iv compares `u32`s. Ranks start at 1; a larger rank is a larger area.
pub(super) struct SleeveTable<'a> {
    pub(super) poly: ConvexPolygon<'a>,
    /// `mcw[i]`: P_{i,i+len} is solved iff `2 ≤ len ≤ mcw[i]`.
    pub(super) mcw: Vec<usize>,
    /// `mccw[j]`: P_{j−len,j} is solved iff `2 ≤ len ≤ mccw[j]`.
    pub(super) mccw: Vec<usize>,
    /// `rank[i * n + len]`, or [`UNSOLVED`].
    rank: Vec<u32>,
    /// The same values column-major, `rank_by_end[j * n + len]` for
    /// P_{j−len,j}: step iv walks columns as often as rows, and a strided
    /// walk through an n² table misses the cache on every step.
    rank_by_end: Vec<u32>,
    /// `uses_first_ear[i * n + len]`: the optimal sleeve of P_{i,j} contains
    /// (i, i+1, j) and continues with P_{i+1,j}; otherwise (i, j−1, j) and
    /// P_{i,j−1}.
    uses_first_ear: Vec<bool>,
    /// The triangle (positions) behind each rank; index 0 unused.
    /// Positions fit in `u16` (n ≤ 65535); the compact form keeps more of
    /// this array, read at random ranks in step iv, in the cache.
    representative: Vec<[u16; 3]>,
}

impl<'a> SleeveTable<'a> {
    /// Steps i–iii: O(n²) time and space, plus one exact sort of the
    /// distinct bottleneck triangles (O(n² log n) comparisons).
    ///
    /// # Errors
    /// [`Error::Interrupted`](crate::Error::Interrupted) when `stop` says
    /// so (checked once per piece length).
    pub(super) fn new(
        points: &'a [Point],
        polygon: &'a [u32],
        objective: AreaBottleneck,
        stop: &Stop,
    ) -> Result<Self> {
        let poly = ConvexPolygon::new(points, polygon);
        let n = poly.n;
        let mcw = poly.max_clockwise();
        let mccw = poly.max_counter_clockwise();

        // During the program a value is an *ear*: the triangle (t, t+1, c),
        // encoded t * n + c. Every sleeve triangle has a boundary edge, so
        // every bottleneck is an ear.
        let ear = |t: usize, c: usize| ((t % n) * n + c % n) as u32;
        let ear_positions = |id: u32| {
            let (t, c) = (id as usize / n, id as usize % n);
            [t, (t + 1) % n, c]
        };
        let compare_ears = |a: u32, b: u32| {
            if a == b {
                Ordering::Equal
            } else {
                poly.compare_triangles(ear_positions(a), ear_positions(b))
            }
        };
        // The better of two candidates under the objective.
        let better = |a: u32, b: u32| match (objective, compare_ears(a, b)) {
            (AreaBottleneck::MaxMin, Ordering::Less)
            | (AreaBottleneck::MinMax, Ordering::Greater) => b,
            _ => a,
        };
        // The worse of two candidates: the bottleneck of their union.
        let worse = |a: u32, b: u32| if better(a, b) == a { b } else { a };

        let mut value = vec![UNSOLVED; n * n];
        let mut uses_first_ear = vec![false; n * n];
        // Corollary 36 (L1433): a piece of zonality ≤ 2 has an optimal
        // triangulation that is a sleeve (Lemmas 31/32), so its optimum comes
        // from one of the two triangles at the base. Both sub-pieces are
        // ≤2-zone again (zonality grows with the chain), hence already solved.
        for len in 2..n {
            stop.check()?;
            for i in 0..n {
                if len > mcw[i] {
                    continue;
                }
                let entry = i * n + len;
                if len == 2 {
                    value[entry] = ear(i, i + 2);
                    uses_first_ear[entry] = true;
                    continue;
                }
                let j = i + len;
                let first = value[((i + 1) % n) * n + len - 1];
                let second = value[i * n + len - 1];
                debug_assert!(first != UNSOLVED && second != UNSOLVED);
                let via_first = worse(ear(i, j), first);
                let via_second = worse(ear(j - 1, i), second);
                let best = better(via_first, via_second);
                value[entry] = best;
                uses_first_ear[entry] = best == via_first;
            }
        }

        // One exact sort of the distinct bottleneck triangles; equal areas
        // get equal ranks.
        stop.check()?;
        let mut ears: Vec<u32> = value.iter().copied().filter(|&v| v != UNSOLVED).collect();
        ears.sort_unstable();
        ears.dedup();
        ears.sort_unstable_by(|&a, &b| compare_ears(a, b));
        let mut rank_of_ear = vec![0u32; n * n];
        let mut representative = vec![[0u16; 3]];
        for (index, &id) in ears.iter().enumerate() {
            if index == 0 || compare_ears(ears[index - 1], id) != Ordering::Equal {
                representative.push(ear_positions(id).map(|p| p as u16));
            }
            rank_of_ear[id as usize] = (representative.len() - 1) as u32;
        }
        for v in value.iter_mut().filter(|v| **v != UNSOLVED) {
            *v = rank_of_ear[*v as usize];
        }
        stop.check()?;
        Ok(SleeveTable {
            poly,
            mcw,
            mccw,
            rank_by_end: (0..n * n)
                .map(|at| {
                    let (j, len) = (at / n, at % n);
                    value[((j + n - len) % n) * n + len]
                })
                .collect(),
            rank: value,
            uses_first_ear,
            representative,
        })
    }

    /// Number of vertices.
    #[inline]
    pub(super) fn n(&self) -> usize {
        self.poly.n
    }

    /// Largest rank in use (the number of distinct table values).
    pub(super) fn max_rank(&self) -> u32 {
        (self.representative.len() - 1) as u32
    }

    /// Is P_{i,i+len} solved (zonality ≤ 2, `len ≥ 2`)?
    #[inline]
    pub(super) fn solved(&self, i: usize, len: usize) -> bool {
        len >= 2 && len <= self.mcw[self.reduce(i)]
    }

    /// `pos` mod n for `pos < 2n`, without a division (hot in step iv). A
    /// position `≥ 2n` stays `≥ n` and makes the caller's index panic.
    #[inline]
    pub(super) fn reduce(&self, pos: usize) -> usize {
        if pos >= self.n() {
            pos - self.n()
        } else {
            pos
        }
    }

    /// Rank of μ*/λ* of P_{i,i+len}, or [`UNSOLVED`]; `i < 2n`.
    #[inline]
    pub(super) fn rank(&self, i: usize, len: usize) -> u32 {
        self.rank[self.reduce(i) * self.n() + len]
    }

    /// Rank of P_{j−len,j} (column view), or [`UNSOLVED`]; `j < 2n`.
    #[inline]
    pub(super) fn rank_to(&self, j: usize, len: usize) -> u32 {
        self.rank_by_end[self.reduce(j) * self.n() + len]
    }

    /// The triangle (positions) whose area rank `r` stands for.
    #[inline]
    pub(super) fn representative(&self, r: u32) -> [usize; 3] {
        self.representative[r as usize].map(usize::from)
    }

    /// The triangle (positions) behind a bottleneck value.
    #[inline]
    pub(super) fn triangle_of(&self, b: Bottleneck) -> [usize; 3] {
        match b {
            Bottleneck::Ranked(r) => self.representative(r),
            Bottleneck::Triangle(t) => t,
        }
    }

    /// Exact comparison of two bottleneck values (ranks compare as integers).
    pub(super) fn compare(&self, a: Bottleneck, b: Bottleneck) -> Ordering {
        match (a, b) {
            (Bottleneck::Ranked(x), Bottleneck::Ranked(y)) => x.cmp(&y),
            _ => self
                .poly
                .compare_triangles(self.triangle_of(a), self.triangle_of(b)),
        }
    }

    /// The larger of two bottleneck values.
    pub(super) fn max(&self, a: Bottleneck, b: Bottleneck) -> Bottleneck {
        if self.compare(a, b) == Ordering::Less {
            b
        } else {
            a
        }
    }

    /// Step v (L2351-2358): the n − 2 triangles of the triangulation that
    /// `witness` describes, O(n).
    pub(super) fn triangulation(&self, witness: Witness) -> Vec<[u32; 3]> {
        sleeve_triangulation(&self.poly, &self.uses_first_ear, witness)
    }

    /// The optimal sleeve of one solved piece (step v).
    #[cfg(test)]
    pub(super) fn push_sleeve(&self, i: usize, len: usize, out: &mut Vec<[u32; 3]>) {
        debug_assert!(self.solved(i, len));
        push_sleeve(&self.poly, &self.uses_first_ear, i, len, out);
    }
}

/// Step v (L2351-2358): the n − 2 triangles (input vertex indices) of the
/// triangulation that `witness` describes, following the sleeve choices
/// `uses_first_ear[i * n + len]` of every solved piece it names (the
/// optimal sleeves of [`SleeveTable`], or the admissible ones of a threshold
/// program), O(n).
pub(super) fn sleeve_triangulation(
    poly: &ConvexPolygon,
    uses_first_ear: &[bool],
    witness: Witness,
) -> Vec<[u32; 3]> {
    let n = poly.n;
    let v = |p: usize| poly.vertex(p);
    let push_sleeve = |i: usize, len: usize, out: &mut Vec<[u32; 3]>| {
        push_sleeve(poly, uses_first_ear, i, len, out)
    };
    let mut out = Vec::with_capacity(n - 2);
    match witness {
        Witness::Whole { i } => push_sleeve(i, n - 1, &mut out),
        Witness::Diagonal { i, len } => {
            push_sleeve(i, len, &mut out);
            push_sleeve(i + len, n - len, &mut out);
        }
        Witness::Triangle { i, r, len } => {
            out.push([v(i), v(i + r), v(i + len)]);
            push_sleeve(i, r, &mut out);
            push_sleeve(i + r, len - r, &mut out);
            push_sleeve(i + len, n - len, &mut out);
        }
    }
    debug_assert_eq!(out.len(), n - 2);
    out
}

/// Step v for one solved piece P_{i,i+len}: appends the triangles (input
/// vertex indices) of its sleeve by following the stored choices, O(len).
pub(super) fn push_sleeve(
    poly: &ConvexPolygon,
    uses_first_ear: &[bool],
    mut i: usize,
    mut len: usize,
    out: &mut Vec<[u32; 3]>,
) {
    let n = poly.n;
    let v = |p: usize| poly.vertex(p);
    while len >= 2 {
        let j = i + len;
        if uses_first_ear[(i % n) * n + len] {
            out.push([v(i), v(i + 1), v(j)]);
            i += 1;
        } else {
            out.push([v(i), v(j - 1), v(j)]);
        }
        len -= 1;
    }
}
