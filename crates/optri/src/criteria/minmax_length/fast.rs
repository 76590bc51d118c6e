//! The O(k²) polygon algorithm of §5.1, §5.3 and §6 (000_5891e11f36dd26ad.txt),
//! run on the kernel's symbolic perturbation `S′` (no equal lengths, no
//! three collinear points), as §5.3 prescribes.
//!
//! | function | paper |
//! |---|---|
//! | [`crate::kernel::height_sign`] | distance of a lune vertex from `pq` (§5.1 step 1) |
//! | [`FastRegion::incomplete`] | §5.1, incomplete rng-polygons (1-Edge Lemma) |
//! | [`FastRegion::visible`] | diagonals at a vertex in angular order (§6 step 1) |
//! | [`FastRegion::shortest_expandable_2_edge`] | §6 steps 1–3 (stack scan, `p′ p″ q′ q″`, Crossing Lemma) |
//! | [`FastRegion::triangulate_side`] | §5.3 step 2 and §6 Cases 1–2 (Expandability Lemma) |
//! | [`FastRegion::hull_fan`] | §6 Case 2 step 2 (Claim 1) |
//! | [`FastRegion::pocket`] | §6 Case 2 steps 3.1–3.3 (Claims 2–5) |
//! | [`FastRegion::fan_out`] | §5.2 fan-out triangulation (Fan-Out Lemma) |
//!
//! Visibility uses the Delaunay triangles inside the region as a polygon
//! triangulation: they are non-degenerate in `S`, so they keep their
//! orientation in `S′` and still tile the perturbed region; the visible
//! vertices of a corner are found by walking the (tree-shaped) dual from the
//! corner's fan, narrowing a wedge — O(k) per corner.

use super::polygon::Region;
use crate::kernel::height_sign;
use crate::kernel::{in_half_lune_symbolic, in_lune_symbolic, Point};
use crate::parallel::prelude::*;
use crate::structures::DelaunayGraph;
use std::cmp::Ordering;
use std::collections::HashMap;

const NONE: u32 = u32::MAX;

/// Delaunay triangles addressed by directed edge, with the region
/// boundaries (`ch(S) ∪ rng(S′)`) marked.
pub(crate) struct Mesh<'a> {
    g: &'a DelaunayGraph,
    /// Per Delaunay edge (indexed like `g.edges`): is it in `rng(S′)`?
    rng: &'a [bool],
    /// One triangle at each vertex, where turning around it starts.
    vertex_triangle: Vec<u32>,
}

impl<'a> Mesh<'a> {
    /// `g` must come from [`DelaunayGraph::with_topology`].
    pub fn new(g: &'a DelaunayGraph, rng: &'a [bool]) -> Self {
        let mut vertex_triangle = vec![NONE; g.offsets.len() - 1];
        for (t, tri) in g.triangles.iter().enumerate() {
            for &c in tri {
                vertex_triangle[c as usize] = t as u32;
            }
        }
        Self {
            g,
            rng,
            vertex_triangle,
        }
    }

    /// The triangle to the left of `u → v` and the side index of `u → v` in
    /// it: turn around `u` one way, then, if the hull stops the turn, the
    /// other way. O(degree of `u`).
    fn side(&self, u: u32, v: u32) -> Option<(u32, usize)> {
        let start = self.vertex_triangle[u as usize];
        let corner = |t: u32| {
            self.g.triangles[t as usize]
                .iter()
                .position(|&c| c == u)
                .expect("the turn stays at the vertex")
        };
        let nb = &self.g.topology.neighbours;
        let (mut t, mut i) = (start, corner(start));
        // Counter-clockwise: across the side entering `u`.
        loop {
            if self.g.triangles[t as usize][(i + 1) % 3] == v {
                return Some((t, i));
            }
            t = nb[t as usize][(i + 2) % 3];
            if t == NONE || t == start {
                break;
            }
            i = corner(t);
        }
        if t == start {
            return None;
        }
        // Clockwise from the start: across the side leaving `u`.
        let (mut t, mut i) = (start, corner(start));
        loop {
            t = nb[t as usize][i];
            if t == NONE {
                return None;
            }
            i = corner(t);
            if self.g.triangles[t as usize][(i + 1) % 3] == v {
                return Some((t, i));
            }
        }
    }

    /// The triangle to the left of `u → v`.
    fn left_of(&self, u: u32, v: u32) -> Option<u32> {
        self.side(u, v).map(|(t, _)| t)
    }

    /// Is `u v` a region boundary (or no interior Delaunay edge at all)?
    fn is_constraint(&self, u: u32, v: u32) -> bool {
        self.side(u, v).map_or(true, |(t, j)| {
            super::regions::is_boundary(self.g, self.rng, t as usize, j)
        })
    }

    /// Is `u v` a hull edge that is not in `rng(S′)`?
    pub fn is_hull_only(&self, u: u32, v: u32) -> bool {
        let on_hull = |(t, j): (u32, usize)| {
            let edge = self.g.topology.sides[t as usize][j] as usize;
            (self.g.topology.neighbours[t as usize][j] == NONE).then_some(edge)
        };
        self.side(u, v)
            .and_then(on_hull)
            .or_else(|| self.side(v, u).and_then(on_hull))
            .is_some_and(|edge| !self.rng[edge])
    }
}

/// Failure of an invariant the paper guarantees: the caller falls back to the
/// exact cubic program for the region (counted, and asserted zero in tests).
#[derive(Debug)]
pub(crate) struct Inconsistent(pub &'static str);

type Res<T> = std::result::Result<T, Inconsistent>;

/// `f` over all corners `0..k`, in parallel for large regions only (rayon's
/// task overhead dominates on the many small regions of typical inputs).
fn map_corners<T: Send, R: FromIterator<T> + crate::parallel::prelude::FromParallelIterator<T>>(
    k: usize,
    f: impl Fn(usize) -> T + Sync + Send,
) -> R {
    if k >= 256 {
        (0..k).into_par_iter().map(f).collect()
    } else {
        (0..k).map(f).collect()
    }
}

/// One region, prepared for the §6 scans: its Delaunay triangles with local
/// adjacency (no hashing during the walks).
pub(crate) struct FastRegion<'a> {
    points: &'a [Point],
    v: &'a [u32],
    k: usize,
    mesh: &'a Mesh<'a>,
    /// Corners (vertex indices, counter-clockwise) of the local triangles.
    corners: Vec<[u32; 3]>,
    /// Neighbour across edge `j` (corner `j` → `j+1`), `NONE` at the boundary.
    neighbours: Vec<[u32; 3]>,
    /// Region position of each corner.
    positions: Vec<[u32; 3]>,
    /// Per position: the first triangle of its fan and the corner index.
    fan_start: Vec<(u32, u8)>,
    geo: Region<'a>,
}

impl<'a> FastRegion<'a> {
    pub fn new(points: &'a [Point], v: &'a [u32], mesh: &'a Mesh<'a>) -> Res<Self> {
        let k = v.len();
        // The region's Delaunay triangles: flood fill inside the boundary.
        let first = mesh
            .left_of(v[0], v[1])
            .ok_or(Inconsistent("no triangle"))?;
        let mut local: HashMap<u32, u32> = HashMap::with_capacity(2 * k);
        let mut globals = vec![first];
        local.insert(first, 0);
        let mut i = 0;
        while i < globals.len() {
            let tri = mesh.g.triangles[globals[i] as usize];
            for j in 0..3 {
                let (x, y) = (tri[j], tri[(j + 1) % 3]);
                if mesh.is_constraint(x, y) {
                    continue;
                }
                let t = mesh.left_of(y, x).ok_or(Inconsistent("open edge"))?;
                if let std::collections::hash_map::Entry::Vacant(e) = local.entry(t) {
                    e.insert(globals.len() as u32);
                    globals.push(t);
                }
            }
            i += 1;
            if globals.len() > 2 * k {
                return Err(Inconsistent("region leaks"));
            }
        }
        let corners: Vec<[u32; 3]> = globals
            .iter()
            .map(|&t| mesh.g.triangles[t as usize])
            .collect();
        let mut neighbours = vec![[NONE; 3]; corners.len()];
        for (t, c) in corners.iter().enumerate() {
            for j in 0..3 {
                let (x, y) = (c[j], c[(j + 1) % 3]);
                if !mesh.is_constraint(x, y) {
                    neighbours[t][j] = local[&mesh.left_of(y, x).ok_or(Inconsistent("open"))?];
                }
            }
        }
        let mut positions = vec![[NONE; 3]; corners.len()];
        let mut fan_start = Vec::with_capacity(k);
        let index_of = |c: &[u32; 3], o: u32| c.iter().position(|&w| w == o).map(|i| i as u8);
        for a in 0..k {
            let o = v[a];
            let g = mesh.left_of(o, v[(a + 1) % k]).ok_or(Inconsistent("fan"))?;
            let mut t = *local.get(&g).ok_or(Inconsistent("fan outside"))?;
            let mut i = index_of(&corners[t as usize], o).ok_or(Inconsistent("corner"))?;
            fan_start.push((t, i));
            let mut steps = 0;
            loop {
                positions[t as usize][i as usize] = a as u32;
                let next = neighbours[t as usize][(i as usize + 2) % 3];
                if next == NONE {
                    break;
                }
                t = next;
                i = index_of(&corners[t as usize], o).ok_or(Inconsistent("corner"))?;
                steps += 1;
                if steps > 2 * k {
                    return Err(Inconsistent("fan loops"));
                }
            }
        }
        if positions.iter().flatten().any(|&p| p == NONE) {
            return Err(Inconsistent("corner without position"));
        }
        Ok(Self {
            points,
            v,
            k,
            mesh,
            corners,
            neighbours,
            positions,
            fan_start,
            geo: Region {
                points,
                vertices: v,
                symbolic: true,
            },
        })
    }

    #[inline]
    fn off(&self, a: usize, b: usize) -> usize {
        (b + self.k - a) % self.k
    }

    #[inline]
    fn at(&self, a: usize, offset: usize) -> usize {
        (a + offset) % self.k
    }

    /// Positions visible from corner `a` (diagonals and the two boundary
    /// edges), in counter-clockwise angular order, which for a (weakly)
    /// simple polygon is boundary order from `a + 1` to `a − 1`.
    pub fn visible(&self, a: usize) -> Vec<usize> {
        let o = self.v[a];
        let mut out = Vec::new();
        // (triangle, edge j, r, l): edge j of the triangle, seen from o
        // through the wedge from ray o→r (clockwise side) to ray o→l.
        let mut stack: Vec<(u32, u8, u32, u32)> = Vec::new();
        let (mut t, mut i) = self.fan_start[a];
        loop {
            let (c, pos) = (&self.corners[t as usize], &self.positions[t as usize]);
            let (i1, i2) = ((i as usize + 1) % 3, (i as usize + 2) % 3);
            out.push(pos[i1] as usize);
            out.push(pos[i2] as usize);
            if self.neighbours[t as usize][i1] != NONE {
                stack.push((t, i1 as u8, c[i1], c[i2]));
            }
            let next = self.neighbours[t as usize][i2];
            if next == NONE {
                break;
            }
            t = next;
            i = self.corners[t as usize]
                .iter()
                .position(|&w| w == o)
                .unwrap_or(0) as u8;
        }
        while let Some((t, j, r, l)) = stack.pop() {
            let c = &self.corners[t as usize];
            let x = c[j as usize];
            let t2 = self.neighbours[t as usize][j as usize];
            let c2 = &self.corners[t2 as usize];
            // In t2 the shared edge runs x → ... reversed: y = c2[iy], x = c2[iy+1], z = c2[iy+2].
            let ix = c2.iter().position(|&w| w == x).unwrap_or(0);
            let (iy, iz) = ((ix + 2) % 3, (ix + 1) % 3);
            let z = c2[iz];
            if z == o {
                continue; // a crack copy of o: nothing beyond is visible
            }
            let right_of_l = self.geo.orient(o, z, l) > 0;
            let left_of_r = self.geo.orient(o, r, z) > 0;
            if left_of_r && right_of_l {
                out.push(self.positions[t2 as usize][iz] as usize);
            }
            let n2 = &self.neighbours[t2 as usize];
            if left_of_r && n2[ix] != NONE {
                stack.push((t2, ix as u8, r, if right_of_l { z } else { l }));
            }
            if right_of_l && n2[iz] != NONE {
                stack.push((t2, iz as u8, if left_of_r { z } else { r }, l));
            }
            let _ = iy;
        }
        // Boundary order by marking: O(k), no sort.
        let mut mark = vec![false; self.k];
        for &b in &out {
            mark[b] = true;
        }
        (1..self.k)
            .map(|o| self.at(a, o))
            .filter(|&b| mark[b])
            .collect()
    }

    /// §5.1 on the chain of positions `s, s+1, …, s+m` whose closing edge
    /// `(s+m) → s` is a 1-edge with the chain beyond it. Each step draws the
    /// triangle to the lune vertex nearest to the closing edge; by the
    /// 1-Edge Lemma the two new edges are 1-edges (or region edges) with the
    /// rest beyond them, and all are shorter than the closing edge.
    pub fn incomplete(&self, s: usize, m: usize, out: &mut Vec<[u32; 3]>) -> Res<()> {
        self.incomplete_positions(s, m, |a, b, c| out.push([self.v[a], self.v[b], self.v[c]]))
    }

    /// [`Self::incomplete`], reporting each triangle as three positions.
    fn incomplete_positions(
        &self,
        s: usize,
        m: usize,
        mut emit: impl FnMut(usize, usize, usize),
    ) -> Res<()> {
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

    /// §6 steps 1–3. Returns the shortest 2-edge `pq` (positions `a < b`)
    /// satisfying step 3, with `p′, q″` (right of `p → q`) and `q′, p″` (left).
    pub fn shortest_expandable_2_edge(&self) -> Res<[usize; 6]> {
        let k = self.k;
        // Small and medium regions keep the visibility lists of step 1 for the
        // later scans (O(k²) memory); large ones recompute them (O(k) each).
        let cached: Vec<Vec<usize>> = if k <= 2048 {
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
            map_corners::<_, Vec<_>>(k, |a| -> Res<Option<[usize; 6]>> {
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
                    let shorter = best.map_or(true, |c| {
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
            .collect::<Res<Vec<_>>>()?
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
    /// Case 2 (`s·ns` crosses `e·ne`): with `|ne s| < |ne e|` (else the mirror
    /// image) §5.1 beyond `e·ne`, then [`Self::hull_fan`] on the rest.
    pub fn triangulate_side(
        &self,
        s: usize,
        e: usize,
        ns: usize,
        ne: usize,
        out: &mut Vec<[u32; 3]>,
    ) -> Res<()> {
        if ns == ne {
            super::count(super::CASE_1, 1);
            out.push([self.v[s], self.v[ns], self.v[e]]);
            self.incomplete(s, self.off(s, ns), out)?;
            return self.incomplete(ns, self.off(ns, e), out);
        }
        let (vs, ve, vne) = (self.v[s], self.v[e], self.v[ne]);
        super::count(super::CASE_2, 1);
        // §6 Case 2 step 1 beyond the shorter-side 1-edge, then steps 2–3 on
        // the rest: (apex, from … to) is (q, p … q″), or the mirror image.
        let (apex, from, to, forward) =
            if self.geo.compare_lengths([vne, vs], [vne, ve]) == Ordering::Less {
                self.incomplete(ne, self.off(ne, e), out)?;
                (e, s, ne, true)
            } else {
                self.incomplete(s, self.off(s, ns), out)?;
                (s, ns, e, false)
            };
        let mark = out.len();
        if self.hull_fan(apex, from, to, forward, out).is_err() {
            // Not expected; the whole remainder by the cubic program instead.
            super::count(super::CASE_2_HULL_FALLBACKS, 1);
            out.truncate(mark);
            let rest: Vec<u32> = (0..=self.off(from, to))
                .map(|i| self.v[self.at(from, i)])
                .chain([self.v[apex]])
                .collect();
            super::count(super::CASE_2_REMAINDER_VERTICES, rest.len());
            let region = Region {
                points: self.points,
                vertices: &rest,
                symbolic: true,
            };
            out.extend(region.minmax_triangulation_cubic());
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
    ) -> Res<()> {
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
            if let Err(e) = done {
                if std::env::var_os("OPTRI_DEBUG").is_some() {
                    eprintln!("pocket fallback ({}) at {a}..{b} of {:?}", e.0, self.v);
                }
                // Not expected (Claims 2–5): the pocket by the cubic program.
                super::FALLBACKS.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                super::count(super::CASE_2_POCKET_FALLBACKS, 1);
                out.truncate(mark);
                let pocket: Vec<u32> = (0..=self.off(a, b))
                    .map(|i| self.v[self.at(a, i)])
                    .collect();
                super::count(super::CASE_2_REMAINDER_VERTICES, pocket.len());
                let region = Region {
                    points: self.points,
                    vertices: &pocket,
                    symbolic: true,
                };
                out.extend(region.minmax_triangulation_cubic());
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
            .any(|&w| w != vx && w != vy && in_half_lune_symbolic(self.points, vx, vy, w))
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
    ) -> Res<()> {
        let span = self.off(a, b);
        if self.beneath_is_empty(a, b) {
            super::count(super::CASE_2_POCKETS_BY_5_1, 1);
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
            if self.v[j] != vu && self.geo.compare_lengths([vu, self.v[j]], pq) == Ordering::Less {
                candidates.push(j);
            }
        }
        candidates.sort_by(|&x, &y| self.geo.compare_lengths([vu, self.v[x]], [vu, self.v[y]]));
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
        super::count(super::CASE_2_POCKETS_BY_FAN_OUT, 1);
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
    fn check_pocket(&self, a: usize, b: usize, pq: [u32; 2], tris: &[[u32; 3]]) -> Res<()> {
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
                if self.geo.compare_lengths([x, y], pq) != Ordering::Less && !is_chain_edge(x, y) {
                    return Err(Inconsistent("pocket edge not shorter than pq"));
                }
            }
        }
        Ok(())
    }

    /// The whole region: §5.1 if one edge is a hull edge outside `rng(S′)`
    /// (an incomplete rng-polygon, beyond that edge), else §5.3.
    pub fn triangulate(&self) -> Res<Vec<[u32; 3]>> {
        let k = self.k;
        if let Some(a) = (0..k).find(|&a| self.mesh.is_hull_only(self.v[a], self.v[(a + 1) % k])) {
            let mut out = Vec::with_capacity(k - 2);
            self.incomplete((a + 1) % k, k - 1, &mut out)?;
            return Ok(out);
        }
        self.complete()
    }

    /// §5.3: a complete region.
    pub fn complete(&self) -> Res<Vec<[u32; 3]>> {
        let [a, b, p1, q2, q1, p2] = self.shortest_expandable_2_edge()?;
        let mut out = Vec::with_capacity(self.k - 2);
        self.triangulate_side(a, b, p1, q2, &mut out)?;
        self.triangulate_side(b, a, q1, p2, &mut out)?;
        Ok(out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::criteria::minmax_length::{regions, rng_perturbed, rng_perturbed_flags};
    use crate::spatial::convex_hull_cycle;
    use crate::structures::DelaunayGraph;

    fn lcg_points(n: usize, seed: u64, grid: Option<u64>) -> Vec<Point> {
        let mut s = seed;
        let mut next = || {
            s = s
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            s >> 11
        };
        let mut pts: Vec<Point> = (0..n)
            .map(|_| match grid {
                Some(g) => [(next() % g) as f64, (next() % g) as f64],
                None => [
                    (next() % 1_000_000) as f64 * 1e-3,
                    (next() % 1_000_000) as f64 * 1e-3,
                ],
            })
            .collect();
        pts.sort_by(|a, b| a[0].total_cmp(&b[0]).then(a[1].total_cmp(&b[1])));
        pts.dedup();
        pts
    }

    #[test]
    fn visibility_walk_matches_the_diagonal_test() {
        for (seed, grid) in [(1, None), (2, Some(6)), (3, None), (4, Some(10))] {
            let pts = lcg_points(60, seed, grid);
            let g = DelaunayGraph::with_topology(&pts).unwrap();
            let rng = rng_perturbed(&pts, &g);
            let flags = rng_perturbed_flags(&pts, &g);
            let hull = convex_hull_cycle(&pts);
            let mesh = Mesh::new(&g, &flags);
            for r in regions(&pts, &rng, &hull) {
                let f = FastRegion::new(&pts, &r, &mesh).unwrap();
                let k = r.len();
                for a in 0..k {
                    let vis = f.visible(a);
                    let want: Vec<usize> = (1..k)
                        .map(|o| (a + o) % k)
                        .filter(|&b| {
                            f.off(a, b) == 1 || f.off(a, b) == k - 1 || f.geo.is_diagonal(a, b)
                        })
                        .collect();
                    assert_eq!(vis, want, "region {r:?} corner {a}");
                }
            }
        }
    }
}

#[cfg(test)]
mod consistency_tests {
    use super::*;
    use crate::criteria::minmax_length::{regions, rng_perturbed, rng_perturbed_flags};
    use crate::spatial::convex_hull_cycle;
    use crate::structures::DelaunayGraph;

    #[test]
    fn random_regions_never_hit_an_inconsistency() {
        let pts: Vec<Point> = vec![[0.0, 0.0], [4.0, 0.1], [4.2, 3.0], [0.3, 2.9], [2.0, 1.4]];
        let mut s = 7u64;
        let mut next = || {
            s = s
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (s >> 11) as f64 / (1u64 << 53) as f64
        };
        for trial in 0..200 {
            let pts: Vec<Point> = if trial == 0 {
                pts.clone()
            } else {
                (0..8).map(|_| [next() * 100.0, next() * 100.0]).collect()
            };
            let g = DelaunayGraph::with_topology(&pts).unwrap();
            let rng = rng_perturbed(&pts, &g);
            let flags = rng_perturbed_flags(&pts, &g);
            let hull = convex_hull_cycle(&pts);
            let mesh = Mesh::new(&g, &flags);
            for r in regions(&pts, &rng, &hull) {
                if r.len() == 3 {
                    continue;
                }
                let f = FastRegion::new(&pts, &r, &mesh).unwrap();
                if let Err(e) = f.triangulate() {
                    let hull_only: Vec<bool> = (0..r.len())
                        .map(|a| mesh.is_hull_only(r[a], r[(a + 1) % r.len()]))
                        .collect();
                    let sel = f.shortest_expandable_2_edge();
                    panic!("{e:?} pts {pts:?} region {r:?} hull_only {hull_only:?} sel {sel:?}");
                }
            }
        }
    }
}
