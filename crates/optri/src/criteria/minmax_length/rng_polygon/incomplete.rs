//! §5.1: incomplete rng-polygons, triangulated from the 1-edge that closes
//! them (1-Edge Lemma).

use super::{Inconsistent, RngPolygon};
use crate::kernel::LengthOrder;

impl<L: LengthOrder> RngPolygon<'_, L> {
    /// §5.1 on the chain of positions `s, s+1, …, s+m` whose closing edge
    /// `(s+m) → s` is a 1-edge with the chain beyond it. Each step draws the
    /// triangle to the lune vertex nearest to the closing edge (under a
    /// metric: minimising `max(|xp|, |xq|)` among the visible ones, the
    /// remark after §5.1); by the 1-Edge Lemma the two new edges are
    /// 1-edges (or region edges) with the rest beyond them, and all are
    /// shorter than the closing edge.
    pub(super) fn incomplete(
        &self,
        s: usize,
        m: usize,
        out: &mut Vec<[u32; 3]>,
    ) -> Result<(), Inconsistent> {
        self.incomplete_positions(s, m, |a, b, c| out.push([self.v[a], self.v[b], self.v[c]]))
    }

    /// [`Self::incomplete`], reporting each triangle as three positions.
    pub(super) fn incomplete_positions(
        &self,
        s: usize,
        m: usize,
        mut emit: impl FnMut(usize, usize, usize),
    ) -> Result<(), Inconsistent> {
        let mut stack = vec![(s, m)];
        while let Some((s, m)) = stack.pop() {
            if m < 2 {
                continue;
            }
            let (p, q) = (self.v[s], self.v[self.at(s, m)]);
            // The lune vertex on the chain's side that `L` prefers (the
            // nearest to `pq`, or the remark's choice under a metric),
            // among those visible from `p` and `q` if `visible_only`.
            let choose = |visible_only: bool| -> Option<usize> {
                let mut best: Option<(usize, u32)> = None;
                for i in 1..m {
                    let x = self.v[self.at(s, i)];
                    if !self.order.in_lune(self.points, p, q, x) || self.geo.orient(p, q, x) > 0 {
                        continue;
                    }
                    if visible_only && !self.visible_from_chord(s, m, i) {
                        continue;
                    }
                    let better = match best {
                        None => true,
                        Some((_, y)) if y == x => {
                            // The same vertex at two positions (a crack): take
                            // the copy whose corner opens towards p.
                            let pos = self.at(s, i);
                            self.geo.strictly_inside_wedge(
                                x,
                                self.v[self.at(pos, 1)],
                                self.v[self.at(pos, self.k - 1)],
                                p,
                            )
                        }
                        Some((_, y)) => self.order.nearer_to_edge(self.points, p, q, x, y),
                    };
                    if better {
                        best = Some((i, x));
                    }
                }
                best.map(|(i, _)| i)
            };
            let mut i = choose(false).ok_or(Inconsistent("site9"))?;
            // The nearest vertex is visible (§5.1); the remark's choice is
            // only allowed if it is, which a convex region guarantees.
            if !L::CHOICE_IS_VISIBLE && !self.convex && !self.visible_from_chord(s, m, i) {
                i = choose(true).ok_or(Inconsistent("no visible lune vertex"))?;
            }
            emit(s, self.at(s, i), self.at(s, m));
            stack.push((s, i));
            stack.push((self.at(s, i), m - i));
        }
        Ok(())
    }

    /// Are both sides `p x` and `x q` of the §5.1 triangle on the chain
    /// `s … s+m` (chord `pq`, `x` at `s+i`) boundary edges or diagonals of
    /// the region? A diagonal of the region from an endpoint of the chord to
    /// a chain vertex stays inside the sub-polygon. O(k).
    fn visible_from_chord(&self, s: usize, m: usize, i: usize) -> bool {
        let sees = |a: usize, b: usize| {
            let o = self.off(a, b);
            o == 1 || o == self.k - 1 || self.geo.is_diagonal(a, b)
        };
        let x = self.at(s, i);
        sees(s, x) && sees(x, self.at(s, m))
    }
}
