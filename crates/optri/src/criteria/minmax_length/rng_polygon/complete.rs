//! §5.3: complete rng-polygons. §6 steps 1–3 find the shortest expandable
//! 2-edge, and both sides of it are triangulated by §6 Case 1 (here) or
//! Case 2 (`case2.rs`).

use super::bits::{in_range, set, BitRows, WORD};
use super::{map_range, Inconsistent, RngPolygon, NONE, PARALLEL_CORNERS};
use crate::kernel::LengthOrder;
use std::cmp::Ordering;
use std::sync::atomic::{AtomicBool, Ordering::Relaxed};

/// Blocks of corners swept independently in §6 step 3 (in parallel): each
/// costs one summary query per corner to start, so a few per thread.
const SWEEP_BLOCKS: usize = 16;

impl<L: LengthOrder> RngPolygon<'_, L> {
    /// §5.3: a complete region.
    pub(super) fn complete(&self) -> Result<Vec<[u32; 3]>, Inconsistent> {
        let [a, b, p1, q2, q1, p2] = self.shortest_expandable_2_edge()?;
        let mut out = Vec::with_capacity(self.k - 2);
        self.triangulate_side(a, b, p1, q2, &mut out)?;
        self.triangulate_side(b, a, q1, p2, &mut out)?;
        Ok(out)
    }

    /// §6 steps 1–3. Returns the shortest 2-edge `pq` (positions `a < b`)
    /// satisfying step 3, with `p′, q″` (right of `p → q`) and `q′, p″` (left).
    ///
    /// The per-pair tables are bit matrices by offset ([`BitRows`], k² bits
    /// each, three of them, freed on return): which corners `a` sees, which
    /// of its diagonals have an empty counter-clockwise half-lune (`ccw`) and
    /// which an empty clockwise one (`cw`, the skewed transpose of `ccw`).
    /// Every row is written and read in boundary order; the partners at the
    /// far end of a 2-edge are swept (step 3 below), so no pair reads a row
    /// of its own.
    pub(super) fn shortest_expandable_2_edge(&self) -> Result<[usize; 6], Inconsistent> {
        let k = self.k;
        let parallel = k >= PARALLEL_CORNERS;
        // Step 1a: the diagonals (and the two boundary edges) at each corner.
        let mut visible = BitRows::new(k, k, false);
        visible.fill(parallel, |a, row| self.visible_offsets(a, row));
        // Step 1b: per corner, the stack scan over its diagonals in angular
        // order; what remains on the stack has an empty half-lune. Bit
        // `off(a, b)` of `ccw` row `a`: `η_{ab}` (the beneath side
        // counter-clockwise, towards later diagonals) is empty; the
        // boundary edge a → a+1 starts the scan whatever its type (§6 step 2).
        let mut ccw = BitRows::new(k, k, true);
        ccw.fill(parallel, |a, row| {
            let o = self.v[a];
            let mut stack: Vec<usize> = Vec::new();
            for b in visible.row(a).ones().map(|off| self.at(a, off)) {
                let x = self.v[b];
                while let Some(&top) = stack.last() {
                    if x != self.v[top] && self.order.in_half_lune(self.points, o, self.v[top], x) {
                        stack.pop();
                    } else {
                        break;
                    }
                }
                stack.push(b);
            }
            set(row, 1);
            for b in stack {
                set(row, self.off(a, b));
            }
        });
        // Step 2 (the clockwise half): at b, the diagonals bc whose clockwise
        // side is empty, i.e. η_{cb} empty — the transpose of `ccw`. Every
        // `cw` row holds offset k − 1 (the transpose of the boundary edge
        // that starts every `ccw` row).
        let cw = ccw.transposed(parallel, true);
        // Step 3: the shortest 2-edge whose four partners meet or cross.
        // `η_{ab}` is empty iff bit `off(a, b)` of `ccw` row a is set, and
        // `η_{ba}` iff bit `off(b, a)` of `ccw` row b, which is bit
        // `off(a, b)` of `cw` row a; so the 2-edges `ab` with `b > a` are the
        // bits of `visible & !ccw & !cw` in row `a`. Their partners `p′`
        // (below `b` in `ccw` row a) and `q″` (above `a` in `cw` row b) meet
        // or cross iff `q″ ≤ p′`; `q′` (below `a` in `ccw` row b) and `p″`
        // (above `b` in `cw` row a) iff `off(b, p″) ≤ off(b, q′)`. The
        // partners at `a` are queries on row a; those at `b` would read a
        // different row for every pair, so they are swept instead, one
        // array entry per `b`: `q″ = min{c ∈ (a, b) : η_{cb} empty}` by
        // decreasing `a` (pass 1, which also replaces each `visible` row by
        // its 2-edges passing the first test), `q′`, the last `c` before `a`
        // in the boundary order from `b` with `η_{bc}` empty, by increasing
        // `a` (pass 2). The corners are cut into blocks swept independently,
        // each starting from one summary query per `b`.
        let broken = AtomicBool::new(false);
        let partner = |found: Option<usize>| {
            found.unwrap_or_else(|| {
                broken.store(true, Relaxed);
                0
            })
        };
        let block = if parallel {
            k.div_ceil(SWEEP_BLOCKS).max(WORD)
        } else {
            k
        };
        let stride = visible.stride();
        visible.blocks_mut(block, parallel, |a0, rows| {
            let a1 = a0 + rows.len() / stride;
            // q2[b]: the smallest c in (a, b) with η_{cb} empty, for the
            // current a; from rows ≥ a1 by one query, then swept.
            let mut q2 = vec![NONE; k];
            for (b, q) in q2.iter_mut().enumerate().skip(a1 + 1) {
                *q = self.at(b, partner(cw.row(b).succ(self.off(b, a1 - 1)))) as u32;
            }
            for a in (a0..a1).rev() {
                let row = &mut rows[(a - a0) * stride..(a - a0 + 1) * stride];
                let (ccw_a, cw_a) = (ccw.row(a), cw.row(a));
                let (ccw_0, cw_0) = (ccw_a.level_0(), cw_a.level_0());
                // ob ≤ k − 2 (a diagonal) and a + ob < k (b > a).
                let (lo, hi) = (2, (k - 2).min(k - 1 - a));
                for (w, word) in row.iter_mut().enumerate() {
                    let mut m = *word & !ccw_0[w] & !cw_0[w] & in_range(w, lo, hi);
                    let mut kept = 0;
                    while m != 0 {
                        let j = m.trailing_zeros() as usize;
                        m &= m - 1;
                        let ob = w * WORD + j;
                        let p1 = a + partner(ccw_a.pred(ob));
                        let q2 = partner((q2[a + ob] != NONE).then_some(q2[a + ob] as usize));
                        if q2 <= p1 {
                            kept |= 1 << j;
                        }
                    }
                    *word = kept;
                }
                // Row a joins: η_{ab} empty for b = a + o > a.
                for o in ccw_a.ones_in(1, k - 1 - a) {
                    q2[a + o] = a as u32;
                }
            }
        });
        let blocks = k.div_ceil(block);
        let per_block = |i: usize| -> Option<[usize; 6]> {
            let (a0, a1) = (i * block, ((i + 1) * block).min(k));
            // q1[b]: the last c before a in the boundary order from b with
            // η_{bc} empty; from the corners before a0 by one query, then
            // swept.
            let mut q1 = vec![NONE; k];
            // (For a0 = 0 and b = k − 1 there is no corner before a0 yet.)
            for (b, q) in q1.iter_mut().enumerate().skip(a0 + 1) {
                if self.off(b, a0) >= 2 {
                    *q = self.at(b, partner(ccw.row(b).pred(self.off(b, a0)))) as u32;
                }
            }
            let mut best: Option<[usize; 6]> = None;
            for a in a0..a1 {
                let (ccw_a, cw_a) = (ccw.row(a), cw.row(a));
                for ob in visible.row(a).ones() {
                    let b = a + ob;
                    let p2 = self.at(a, partner(cw_a.succ(ob)));
                    let q1 = q1[b] as usize;
                    if self.off(b, p2) > self.off(b, q1) {
                        continue;
                    }
                    let shorter = best.is_none_or(|c| {
                        self.order.compare(
                            self.points,
                            [self.v[a], self.v[b]],
                            [self.v[c[0]], self.v[c[1]]],
                        ) == Ordering::Less
                    });
                    if shorter {
                        let p1 = a + partner(ccw_a.pred(ob));
                        let q2 = self.at(b, partner(cw.row(b).succ(self.off(b, a))));
                        best = Some([a, b, p1, q2, q1, p2]);
                    }
                }
                // Corner a joins: η_{ba} empty for b = a + o > a.
                for o in cw_a.ones_in(1, k - 1 - a) {
                    q1[a + o] = a as u32;
                }
            }
            best
        };
        let candidates: Vec<[usize; 6]> = map_range::<_, Vec<_>>(parallel, blocks, per_block)
            .into_iter()
            .flatten()
            .collect();
        if broken.load(Relaxed) {
            return Err(Inconsistent("no partner"));
        }
        self.shortest_candidate(candidates)
    }

    /// The candidate `[a, b, …]` whose 2-edge `ab` is shortest (the first
    /// of equals, in the exact segment order of `order`).
    fn shortest_candidate(&self, candidates: Vec<[usize; 6]>) -> Result<[usize; 6], Inconsistent> {
        candidates
            .into_iter()
            .min_by(|c, d| {
                self.order.compare(
                    self.points,
                    [self.v[c[0]], self.v[c[1]]],
                    [self.v[d[0]], self.v[d[1]]],
                )
            })
            .ok_or(Inconsistent("site10"))
    }

    /// Triangulates the part of the region on the chain `s, s+1, …, e`
    /// closed by the 2-edge `e → s`, given the partners `ns` (at `s`) and
    /// `ne` (at `e`) of §6 step 2, all diagonals shorter than `|se|`.
    ///
    /// Case 1 (`ns = ne = r`): triangle `s r e` and §5.1 beyond `sr` and `re`.
    /// Case 2 (`s·ns` crosses `e·ne`): [`Self::case_2`].
    pub(super) fn triangulate_side(
        &self,
        s: usize,
        e: usize,
        ns: usize,
        ne: usize,
        out: &mut Vec<[u32; 3]>,
    ) -> Result<(), Inconsistent> {
        if ns == ne {
            self.counters.case_1.add(1);
            out.push([self.v[s], self.v[ns], self.v[e]]);
            self.incomplete(s, self.off(s, ns), out)?;
            return self.incomplete(ns, self.off(ns, e), out);
        }
        self.case_2(s, e, ns, ne, out)
    }
}

#[cfg(test)]
mod tests {
    use super::super::{regions, rng_perturbed, rng_perturbed_flags, Counters, Mesh, RngPolygon};
    use super::*;
    use crate::kernel::lune::in_half_lune_symbolic;
    use crate::kernel::Point;
    use crate::spatial::convex_hull_cycle;
    use crate::structures::DelaunayGraph;
    use rand::{rngs::StdRng, Rng, SeedableRng};

    /// Seed of the random point sets.
    const SETS_SEED: u64 = 15;

    impl RngPolygon<'_> {
        /// The reference for the bit tables: §6 steps 1–3 with sorted offset
        /// lists per corner and binary searches (the layout before the bit
        /// tables).
        fn shortest_expandable_2_edge_by_lists(&self) -> Result<[usize; 6], Inconsistent> {
            let k = self.k;
            let cached: Vec<Vec<usize>> = map_range(k >= PARALLEL_CORNERS, k, |a| self.visible(a));
            let visible = |a: usize| cached[a].as_slice();
            // Step 1: per corner, the stack scan over its diagonals in angular
            // order; what remains on the stack has an empty half-lune.
            let ccw_of: Vec<Vec<u32>> =
                map_range::<_, Vec<_>>(k >= PARALLEL_CORNERS, k, |a| -> Vec<u32> {
                    let vis = visible(a);
                    let o = self.v[a];
                    let mut stack: Vec<usize> = Vec::new();
                    for &b in vis.iter() {
                        let x = self.v[b];
                        while let Some(&top) = stack.last() {
                            if x != self.v[top]
                                && in_half_lune_symbolic(self.points, o, self.v[top], x)
                            {
                                stack.pop();
                            } else {
                                break;
                            }
                        }
                        stack.push(b);
                    }
                    // Edges and 1-edges with their beneath side counter-clockwise
                    // (towards later diagonals), as offsets in increasing order; the
                    // boundary edge a → a+1 starts the scan whatever its type (§6 step 2).
                    let mut ccw: Vec<u32> = stack.iter().map(|&b| self.off(a, b) as u32).collect();
                    if ccw.first() != Some(&1) {
                        ccw.insert(0, 1);
                    }
                    ccw
                });
            // `η_{ab}` is empty iff `off(a, b)` is in `ccw_of[a]`.
            let left_empty =
                |a: usize, b: usize| ccw_of[a].binary_search(&(self.off(a, b) as u32)).is_ok();
            // Step 2 (the clockwise half): at b, the diagonals bc whose clockwise
            // side is empty, i.e. η_{cb} empty — the transpose of the lists above.
            let mut cw_of: Vec<Vec<u32>> = vec![Vec::new(); k];
            for (a, list) in ccw_of.iter().enumerate() {
                for &o in list {
                    let b = self.at(a, o as usize);
                    cw_of[b].push(self.off(b, a) as u32);
                }
            }
            for cw in &mut cw_of {
                cw.sort_unstable();
                cw.dedup();
                if cw.last() != Some(&(k as u32 - 1)) {
                    cw.push(k as u32 - 1);
                }
            }
            // Predecessor / successor offsets in a sorted list.
            let below = |list: &[u32], x: usize| -> usize {
                let i = list.partition_point(|&o| (o as usize) < x);
                list[i - 1] as usize
            };
            let above = |list: &[u32], x: usize| -> usize {
                let i = list.partition_point(|&o| (o as usize) <= x);
                list[i] as usize
            };
            // Step 3: the shortest 2-edge whose four partners meet or cross.
            let candidates: Vec<[usize; 6]> = map_range::<_, Vec<_>>(
                k >= PARALLEL_CORNERS,
                k,
                |a| -> Result<Option<[usize; 6]>, Inconsistent> {
                    let mut best: Option<[usize; 6]> = None;
                    for &b in visible(a).iter() {
                        let ob = self.off(a, b);
                        if b < a || ob < 2 || ob > k - 2 || left_empty(a, b) || left_empty(b, a) {
                            continue;
                        }
                        let oa = self.off(b, a);
                        let p1 = self.at(a, below(&ccw_of[a], ob));
                        let q2 = self.at(b, above(&cw_of[b], oa));
                        if self.off(a, q2) > self.off(a, p1) {
                            continue;
                        }
                        let p2 = self.at(a, above(&cw_of[a], ob));
                        let q1 = self.at(b, below(&ccw_of[b], oa));
                        if self.off(b, p2) > self.off(b, q1) {
                            continue;
                        }
                        let shorter = best.is_none_or(|c| {
                            self.geo.compare_lengths(
                                [self.v[a], self.v[b]],
                                [self.v[c[0]], self.v[c[1]]],
                            ) == Ordering::Less
                        });
                        if shorter {
                            best = Some([a, b, p1, q2, q1, p2]);
                        }
                    }
                    Ok(best)
                },
            )
            .into_iter()
            .collect::<Result<Vec<_>, Inconsistent>>()?
            .into_iter()
            .flatten()
            .collect();
            self.shortest_candidate(candidates)
        }
    }

    /// Every complete region of `pts` with at least 4 corners: the bit
    /// tables pick the same 2-edge and the same four partners as the lists.
    /// Returns how many regions were compared and their largest size.
    fn compare_on(pts: &[Point]) -> (usize, usize) {
        let counters = Counters::default();
        let g = DelaunayGraph::with_topology(pts).unwrap();
        let rng_edges = rng_perturbed(pts, &g);
        let flags = rng_perturbed_flags(pts, &g);
        let hull = convex_hull_cycle(pts);
        let mesh = Mesh::new(&g, &flags);
        let (mut compared, mut largest) = (0, 0);
        for r in regions(pts, &rng_edges, &hull) {
            let k = r.len();
            if k < 4 || (0..k).any(|a| mesh.is_hull_only(r[a], r[(a + 1) % k])) {
                continue; // incomplete: §5.1, no tables
            }
            let f = RngPolygon::new(pts, &r, &mesh, &counters).unwrap();
            let by_bits = f.shortest_expandable_2_edge().map_err(|e| e.0);
            let by_lists = f.shortest_expandable_2_edge_by_lists().map_err(|e| e.0);
            assert_eq!(by_bits, by_lists, "region {r:?}");
            compared += 1;
            largest = largest.max(k);
        }
        (compared, largest)
    }

    /// Convex position (one complete region of all points, the O(k²) case):
    /// regular polygons (cocircular: every length repeated, ties broken by
    /// the perturbation), near-cocircular and random convex sets, with
    /// sizes across the word and summary boundaries of the bit rows and the
    /// parallel threshold; and random and grid sets with many regions.
    #[test]
    fn bit_tables_choose_what_the_lists_choose() {
        let mut rng = StdRng::seed_from_u64(SETS_SEED);
        let mut sets: Vec<Vec<Point>> = Vec::new();
        for n in [4usize, 5, 6, 12, 63, 64, 65, 129, 300] {
            // Regular n-gon on an integer-free circle and its near-cocircular
            // jitter.
            let regular: Vec<Point> = (0..n)
                .map(|i| {
                    let t = std::f64::consts::TAU * i as f64 / n as f64;
                    [1e3 * t.cos(), 1e3 * t.sin()]
                })
                .collect();
            let jittered: Vec<Point> = regular
                .iter()
                .map(|p| {
                    let s = 1.0 + rng.gen_range(-1e-3..1e-3);
                    [p[0] * s, p[1] * s]
                })
                .collect();
            // Random convex: sorted random angles on an ellipse.
            let mut angles: Vec<f64> = (0..n)
                .map(|_| rng.gen_range(0.0..std::f64::consts::TAU))
                .collect();
            angles.sort_by(f64::total_cmp);
            let ellipse: Vec<Point> = angles.iter().map(|t| [3.0 * t.cos(), t.sin()]).collect();
            sets.extend([regular, jittered, ellipse]);
        }
        // The integer points of x² + y² = 5², 25² and 65² (exactly cocircular).
        for r in [5i64, 25, 65] {
            let mut c: Vec<Point> = (-r..=r)
                .flat_map(|x| (-r..=r).map(move |y| (x, y)))
                .filter(|&(x, y)| x * x + y * y == r * r)
                .map(|(x, y)| [x as f64, y as f64])
                .collect();
            c.sort_by(|p, q| p[1].atan2(p[0]).total_cmp(&q[1].atan2(q[0])));
            sets.push(c);
        }
        for (n, w) in [(60, 6u32), (200, 12), (300, 1 << 20)] {
            let mut p: Vec<Point> = (0..n)
                .map(|_| [rng.gen_range(0..w) as f64, rng.gen_range(0..w) as f64])
                .collect();
            p.sort_by(|a, b| a[0].total_cmp(&b[0]).then(a[1].total_cmp(&b[1])));
            p.dedup();
            sets.push(p);
        }
        let (mut compared, mut largest) = (0, 0);
        for pts in &sets {
            let (c, l) = compare_on(pts);
            compared += c;
            largest = largest.max(l);
        }
        assert!(compared >= 30, "{compared} complete regions compared");
        assert!(largest >= 300, "largest complete region {largest}");
    }

    /// The same at k = 5000 (three summary levels, k > 4096): slow in a
    /// debug build.
    #[test]
    #[ignore]
    fn bit_tables_choose_what_the_lists_choose_beyond_4096_corners() {
        let mut rng = StdRng::seed_from_u64(SETS_SEED + 1);
        let pts: Vec<Point> = (0..5000)
            .map(|i| {
                let t = std::f64::consts::TAU * i as f64 / 5000.0;
                let s = 1.0 + rng.gen_range(-1e-3..1e-3);
                [s * t.cos(), s * t.sin()]
            })
            .collect();
        assert_eq!(compare_on(&pts), (1, 5000));
    }
}
