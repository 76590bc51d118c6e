//! §6 Case 2 (the partners `pp′` and `qq″` cross), in the paper's three
//! steps: §5.1 beyond `qq″` (or the mirror image), the convex hull `C` of the
//! vertices inside triangle `pqq″` together with `p, q″`, fanned from `q`,
//! and for each pocket `Y_uv` behind an edge `uv` of `C`: step 3.1 finds
//! `u_L`, 3.2 keeps the triangles of §5.1 beyond `uu_L` that lie in the
//! pocket, and 3.3 fans the rest out from `v` (§5.2). Each pocket's result
//! is checked against what Claims 1–5 promise; a pocket failing the check
//! goes to the cubic program on `S′`, and a hull chain failing its
//! boundary-order check sends the whole remainder there.

use super::{cubic_fallback, Fallback, Inconsistent, Region, RngPolygon};
use crate::kernel::LengthOrder;
use std::cmp::Ordering;

impl<L: LengthOrder> RngPolygon<'_, L> {
    /// §6 Case 2 on the side `s … e` of the 2-edge `e → s`, whose partners
    /// `s·ns` and `e·ne` cross. Step 1: with `|ne s| < |ne e|` (else the
    /// mirror image) §5.1 beyond the 1-edge `e·ne`; steps 2–3 on the rest:
    /// [`Self::hull_fan`]. Should the hull chain fail its check (not
    /// expected), the rest goes to the cubic program.
    pub(super) fn case_2(
        &self,
        s: usize,
        e: usize,
        ns: usize,
        ne: usize,
        out: &mut Vec<[u32; 3]>,
    ) -> Result<(), Inconsistent> {
        let (vs, ve, vne) = (self.v[s], self.v[e], self.v[ne]);
        self.counters.case_2.add(1);
        // Step 1 beyond the shorter-side 1-edge, then steps 2–3 on the rest:
        // (apex, from … to) is (q, p … q″), or the mirror image.
        let (apex, from, to, forward) =
            if self.order.compare(self.points, [vne, vs], [vne, ve]) == Ordering::Less {
                self.incomplete(ne, self.off(ne, e), out)?;
                (e, s, ne, true)
            } else {
                self.incomplete(s, self.off(s, ns), out)?;
                (s, ns, e, false)
            };
        let mark = out.len();
        if self.hull_fan(apex, from, to, forward, out).is_err() {
            let rest: Vec<u32> = (0..=self.off(from, to))
                .map(|i| self.v[self.at(from, i)])
                .chain([self.v[apex]])
                .collect();
            cubic_fallback(
                self.points,
                self.order,
                Fallback::Case2Remainder,
                &rest,
                self.counters,
                out,
                mark,
            );
        }
        Ok(())
    }

    /// §6 Case 2 steps 2–3 on the polygon `from … to` plus `apex`: the convex
    /// hull `C` of the chain vertices inside the triangle `(apex, from, to)`
    /// together with `from` and `to`; the side of `C` facing the apex is
    /// fanned from the apex (Claim 1: shorter than `|pq|`), and each pocket
    /// between an edge of `C` and the boundary is triangulated by step 3
    /// ([`Self::pocket`]). `forward` says whether the paper's `p` is `from`
    /// (the 2-edge is `from → apex`) or, in the mirror image, `to`.
    fn hull_fan(
        &self,
        apex: usize,
        from: usize,
        to: usize,
        forward: bool,
        out: &mut Vec<[u32; 3]>,
    ) -> Result<(), Inconsistent> {
        let (va, vf, vt) = (self.v[apex], self.v[from], self.v[to]);
        let side = self.geo.orient(vf, vt, va);
        if side == 0 {
            return Err(Inconsistent("flat Case 2 triangle"));
        }
        let pq = if forward { [vf, va] } else { [va, vt] };
        let span = self.off(from, to);
        let inside: Vec<usize> = (1..span)
            .map(|i| self.at(from, i))
            .filter(|&pos| {
                let x = self.v[pos];
                self.geo.orient(vf, vt, x) == side
                    && self.geo.orient(vt, va, x) == side
                    && self.geo.orient(va, vf, x) == side
            })
            .collect();
        // Gift wrapping from `from` to `to` along the side facing the apex.
        let mut chain = vec![from];
        let mut c = from;
        while c != to {
            let mut w = to;
            for &cand in &inside {
                if self.geo.orient(self.v[c], self.v[w], self.v[cand]) == side {
                    w = cand;
                }
            }
            if self.off(from, w) <= self.off(from, c) || chain.len() > inside.len() + 1 {
                return Err(Inconsistent("hull chain not in boundary order"));
            }
            chain.push(w);
            c = w;
        }
        let h = chain.len();
        for (i, pair) in chain.windows(2).enumerate() {
            let (a, b) = (pair[0], pair[1]);
            out.push([va, self.v[a], self.v[b]]);
            if self.off(a, b) < 2 {
                continue;
            }
            // The paper's `u` and its neighbours on the closed polygon `C`.
            let iu = if forward { i } else { i + 1 };
            let cone =
                (h > 2).then(|| [self.v[chain[(iu + h - 1) % h]], self.v[chain[(iu + 1) % h]]]);
            let mark = out.len();
            let done = self
                .pocket(a, b, apex, forward, pq, cone, out)
                .and_then(|()| self.check_pocket(a, b, pq, &out[mark..]));
            if done.is_err() {
                // Not expected (Claims 2–5): the pocket by the cubic program.
                let pocket: Vec<u32> = (0..=self.off(a, b))
                    .map(|i| self.v[self.at(a, i)])
                    .collect();
                cubic_fallback(
                    self.points,
                    self.order,
                    Fallback::Case2Pocket,
                    &pocket,
                    self.counters,
                    out,
                    mark,
                );
            }
        }
        Ok(())
    }

    /// Is no vertex of the region in the half-lune of the chord between
    /// positions `x` and `y` on the side away from the chain `x … y`?
    fn beneath_is_empty(&self, x: usize, y: usize) -> bool {
        let (vx, vy) = (self.v[x], self.v[y]);
        !self
            .v
            .iter()
            .any(|&w| w != vx && w != vy && self.order.in_half_lune(self.points, vx, vy, w))
    }

    /// §6 Case 2 step 3 for the pocket `Y_uv`: the chain `a … b` (positions)
    /// behind the edge `ab` of `C`. The paper's `u` is `a` if `forward`, else
    /// `b`; `v` is the other one. `cone` holds `u`'s two neighbours on `C`.
    ///
    /// 3.1: `u_L = v` if `uv` is a 1-edge with `pq` beneath (then §5.1 does
    /// the whole pocket); otherwise the vertex nearest to `u` past `v` (away
    /// from `u`, before the apex) with `|u u_L| < |pq|`, `u u_L` a diagonal
    /// and a 1-edge with `pq` beneath, not entering `C` (Claim 2 shows one
    /// exists). 3.2: §5.1 beyond `u u_L`, keeping the triangles whose corners
    /// all lie on the pocket's chain. 3.3: the rest `X_uv` (the pocket's part
    /// covered by the dropped triangles, which cross `uv`) is fanned out from
    /// `v` ([`Self::fan_out`]); Claims 3–5 and the Fan-Out Lemma bound its
    /// edges by `|pq|`.
    #[allow(clippy::too_many_arguments)]
    fn pocket(
        &self,
        a: usize,
        b: usize,
        apex: usize,
        forward: bool,
        pq: [u32; 2],
        cone: Option<[u32; 2]>,
        out: &mut Vec<[u32; 3]>,
    ) -> Result<(), Inconsistent> {
        let span = self.off(a, b);
        if self.beneath_is_empty(a, b) {
            self.counters.case_2_pockets_by_5_1.add(1);
            return self.incomplete(a, span, out);
        }
        let (u, v) = if forward { (a, b) } else { (b, a) };
        let vu = self.v[u];
        // Step 3.1: candidates past v, shortest first.
        let mut candidates: Vec<usize> = Vec::new();
        for i in 1..self.k {
            let j = if forward {
                self.at(v, i)
            } else {
                self.at(v, self.k - i)
            };
            if j == apex {
                break;
            }
            if self.v[j] != vu
                && self.order.compare(self.points, [vu, self.v[j]], pq) == Ordering::Less
            {
                candidates.push(j);
            }
        }
        candidates.sort_by(|&x, &y| {
            self.order
                .compare(self.points, [vu, self.v[x]], [vu, self.v[y]])
        });
        let enters_c = |x: u32| {
            cone.is_some_and(|[c1, c2]| {
                self.geo.orient(vu, c1, x) == self.geo.orient(vu, c1, c2)
                    && self.geo.orient(vu, c2, x) == self.geo.orient(vu, c2, c1)
            })
        };
        let ul = candidates
            .into_iter()
            .find(|&j| {
                let (x, y) = if forward { (u, j) } else { (j, u) };
                !enters_c(self.v[j]) && self.geo.is_diagonal(u, j) && self.beneath_is_empty(x, y)
            })
            .ok_or(Inconsistent("no u_L (Claim 2)"))?;
        self.counters.case_2_pockets_by_fan_out.add(1);
        // Step 3.2: §5.1 beyond u u_L, clipped to the pocket.
        let (x, y) = if forward { (u, ul) } else { (ul, u) };
        let in_pocket = |pos: usize| self.off(a, pos) <= span;
        let mut on_x = vec![false; span + 1];
        on_x[0] = true;
        on_x[span] = true;
        self.incomplete_positions(x, self.off(x, y), |p1, p2, p3| {
            if in_pocket(p1) && in_pocket(p2) && in_pocket(p3) {
                out.push([self.v[p1], self.v[p2], self.v[p3]]);
            } else {
                for pos in [p1, p2, p3] {
                    if in_pocket(pos) {
                        on_x[self.off(a, pos)] = true;
                    }
                }
            }
        })?;
        // Step 3.3: the fan-out of X_uv from v.
        let xs: Vec<u32> = (0..=span)
            .filter(|&i| on_x[i])
            .map(|i| self.v[self.at(a, i)])
            .collect();
        let center = if forward { xs.len() - 1 } else { 0 };
        self.fan_out(xs, center, out);
        Ok(())
    }

    /// §5.2's fan-out triangulation `f_c(X)` of the polygon `xs`
    /// (counter-clockwise vertex indices) with centre position `center`:
    /// connect the centre to every visible vertex, close each pair of
    /// angularly adjacent neighbours by a cut-off edge, and recurse in the
    /// pocket behind it, centred at the cut-off edge's endpoint whose other
    /// pocket edge is hidden from the centre. O(m²) diagonal tests per pocket.
    fn fan_out(&self, xs: Vec<u32>, center: usize, out: &mut Vec<[u32; 3]>) {
        let mut stack = vec![(xs, center)];
        while let Some((poly, c)) = stack.pop() {
            let m = poly.len();
            if m < 3 {
                continue;
            }
            let region = Region {
                points: self.points,
                vertices: &poly,
                symbolic: true,
            };
            // Visible vertices in counter-clockwise angular order, which is
            // boundary order for a polygonal region.
            let neighbours: Vec<usize> = (1..m)
                .filter(|&o| o == 1 || o == m - 1 || region.is_diagonal(c, (c + o) % m))
                .map(|o| (c + o) % m)
                .collect();
            for w in neighbours.windows(2) {
                let (x, y) = (w[0], w[1]);
                out.push([poly[c], poly[x], poly[y]]);
                let gap = (y + m - x) % m;
                if gap >= 2 {
                    let sub: Vec<u32> = (0..=gap).map(|i| poly[(x + i) % m]).collect();
                    // The edge x → x+1 is partly visible iff it turns
                    // counter-clockwise from the ray c → x; then y is the
                    // pocket's centre, else x.
                    let partly_visible = region.orient(poly[c], poly[x], poly[(x + 1) % m]) > 0;
                    stack.push((sub, if partly_visible { gap } else { 0 }));
                }
            }
        }
    }

    /// Safety net for step 3: the pocket `a … b` got `span − 1` triangles, and
    /// every new diagonal is shorter than `|pq|` (Claims 1–5).
    fn check_pocket(
        &self,
        a: usize,
        b: usize,
        pq: [u32; 2],
        tris: &[[u32; 3]],
    ) -> Result<(), Inconsistent> {
        let span = self.off(a, b);
        if tris.len() != span - 1 {
            return Err(Inconsistent("pocket triangle count"));
        }
        let is_chain_edge = |x: u32, y: u32| {
            (0..span).any(|i| {
                let (s, t) = (self.v[self.at(a, i)], self.v[self.at(a, i + 1)]);
                (s == x && t == y) || (s == y && t == x)
            })
        };
        for t in tris {
            if self.geo.orient(t[0], t[1], t[2]) <= 0 {
                return Err(Inconsistent("pocket triangle not counter-clockwise"));
            }
            for j in 0..3 {
                let (x, y) = (t[j], t[(j + 1) % 3]);
                if self.order.compare(self.points, [x, y], pq) != Ordering::Less
                    && !is_chain_edge(x, y)
                {
                    return Err(Inconsistent("pocket edge not shorter than pq"));
                }
            }
        }
        Ok(())
    }
}
