//! §5.1: incomplete rng-polygons, triangulated from the 1-edge that closes
//! them (1-Edge Lemma).

use super::{Inconsistent, RngPolygon};
use crate::kernel::{height_sign, in_lune_symbolic};

impl RngPolygon<'_> {
    /// §5.1 on the chain of positions `s, s+1, …, s+m` whose closing edge
    /// `(s+m) → s` is a 1-edge with the chain beyond it. Each step draws the
    /// triangle to the lune vertex nearest to the closing edge; by the
    /// 1-Edge Lemma the two new edges are 1-edges (or region edges) with the
    /// rest beyond them, and all are shorter than the closing edge.
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
            let mut best: Option<(usize, u32)> = None;
            for i in 1..m {
                let x = self.v[self.at(s, i)];
                if !in_lune_symbolic(self.points, p, q, x) || self.geo.orient(p, q, x) > 0 {
                    continue;
                }
                let better = match best {
                    None => true,
                    Some((_, y)) if y == x => {
                        // The same vertex at two positions (a crack): take the
                        // copy whose corner opens towards p.
                        let pos = self.at(s, i);
                        self.geo.strictly_inside_wedge(
                            x,
                            self.v[self.at(pos, 1)],
                            self.v[self.at(pos, self.k - 1)],
                            p,
                        )
                    }
                    Some((_, y)) => height_sign(self.points, p, q, x, y) > 0,
                };
                if better {
                    best = Some((i, x));
                }
            }
            let (i, _) = best.ok_or(Inconsistent("site9"))?;
            emit(s, self.at(s, i), self.at(s, m));
            stack.push((s, i));
            stack.push((self.at(s, i), m - i));
        }
        Ok(())
    }
}
