//! §5.3: complete rng-polygons. §6 steps 1–3 find the shortest expandable
//! 2-edge, and both sides of it are triangulated by §6 Case 1 (here) or
//! Case 2 (`case2.rs`).

use super::{map_corners, Inconsistent, RngPolygon};
use crate::kernel::in_half_lune_symbolic;
use std::cmp::Ordering;

/// Regions of up to this many corners keep the visibility lists of §6 step 1
/// for the later scans (O(k²) memory: at most 2048² list entries, 32 MiB);
/// larger ones recompute them (O(k) each).
const MAX_CACHED_VISIBILITY: usize = 2048;

impl RngPolygon<'_> {
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
    pub(super) fn shortest_expandable_2_edge(&self) -> Result<[usize; 6], Inconsistent> {
        let k = self.k;
        let cached: Vec<Vec<usize>> = if k <= MAX_CACHED_VISIBILITY {
            map_corners(k, |a| self.visible(a))
        } else {
            Vec::new()
        };
        let visible = |a: usize| -> std::borrow::Cow<'_, [usize]> {
            match cached.get(a) {
                Some(v) => std::borrow::Cow::Borrowed(v.as_slice()),
                None => std::borrow::Cow::Owned(self.visible(a)),
            }
        };
        // Step 1: per corner, the stack scan over its diagonals in angular
        // order; what remains on the stack has an empty half-lune.
        let ccw_of: Vec<Vec<u32>> = map_corners::<_, Vec<_>>(k, |a| -> Vec<u32> {
            let vis = visible(a);
            let o = self.v[a];
            let mut stack: Vec<usize> = Vec::new();
            for &b in vis.iter() {
                let x = self.v[b];
                while let Some(&top) = stack.last() {
                    if x != self.v[top] && in_half_lune_symbolic(self.points, o, self.v[top], x) {
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
        let candidates: Vec<[usize; 6]> =
            map_corners::<_, Vec<_>>(k, |a| -> Result<Option<[usize; 6]>, Inconsistent> {
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
                        self.geo
                            .compare_lengths([self.v[a], self.v[b]], [self.v[c[0]], self.v[c[1]]])
                            == Ordering::Less
                    });
                    if shorter {
                        best = Some([a, b, p1, q2, q1, p2]);
                    }
                }
                Ok(best)
            })
            .into_iter()
            .collect::<Result<Vec<_>, Inconsistent>>()?
            .into_iter()
            .flatten()
            .collect();
        candidates
            .into_iter()
            .min_by(|c, d| {
                self.geo
                    .compare_lengths([self.v[c[0]], self.v[c[1]]], [self.v[d[0]], self.v[d[1]]])
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
