//! The O(k²) rng-polygon algorithm of Edelsbrunner & Tan (*A quadratic time
//! algorithm for the minmax length triangulation*, FOCS 1991 / SIAM J.
//! Comput. 1993), §5.1, §5.3 and §6, run on the kernel's symbolic
//! perturbation `S′` (no equal lengths, no three collinear points), as §5.3
//! prescribes.
//!
//! Every length comparison, lune and half-lune test, and §5.1's vertex
//! choice goes through the region's [`LengthOrder`]: Euclidean in the
//! product's Euclidean path ([`RngPolygon::new`], monomorphised to the
//! Euclidean predicates), or a normed metric's simulated strictly convex
//! norm under §7 ([`RngPolygon::with_order`], from `under_metric.rs`, where
//! the module docs say what is proven and what only tested). Orientations,
//! visibility and the triangles that tile the region do not depend on it.
//!
//! | function | file | paper |
//! |---|---|---|
//! | [`LengthOrder::nearer_to_edge`] | the kernel's length orders | §5.1 step 1: distance of a lune vertex from `pq` ([`crate::kernel::height_sign`]), or under a metric the remark's `max(|xp|, |xq|)` |
//! | [`RngPolygon::triangulate`] | here | §5.1 for an incomplete rng-polygon, else §5.3 |
//! | [`RngPolygon::incomplete`] | `incomplete.rs` | §5.1, incomplete rng-polygons (1-Edge Lemma) |
//! | [`RngPolygon::visible_offsets`] | `visibility.rs` | diagonals at a vertex in angular order (§6 step 1) |
//! | `BitRows` | `bits.rs` | the per-pair tables of §6 steps 1–3, one bit a pair |
//! | [`RngPolygon::complete`] | `complete.rs` | §5.3, complete rng-polygons |
//! | [`RngPolygon::shortest_expandable_2_edge`] | `complete.rs` | §6 steps 1–3 (stack scan, `p′ p″ q′ q″`, Crossing Lemma) |
//! | [`RngPolygon::triangulate_side`] | `complete.rs` | §5.3 step 2 and §6 Case 1 (Expandability Lemma) |
//! | [`RngPolygon::case_2`] | `case2.rs` | §6 Case 2 step 1 |
//! | [`RngPolygon::hull_fan`] | `case2.rs` | §6 Case 2 step 2 (Claim 1) |
//! | [`RngPolygon::pocket`] | `case2.rs` | §6 Case 2 steps 3.1–3.3 (Claims 2–5) |
//! | [`RngPolygon::fan_out`] | `case2.rs` | §5.2 fan-out triangulation (Fan-Out Lemma) |
//!
//! The region's Delaunay triangles come from a [`Mesh`] (`mesh.rs`), the
//! Delaunay triangulation addressed by directed edge with the region
//! boundaries marked. Visibility uses them as a polygon triangulation: they
//! are non-degenerate in `S`, so they keep their orientation in `S′` and
//! still tile the perturbed region; the visible vertices of a corner are
//! found by walking the (tree-shaped) dual from the corner's fan, narrowing a
//! wedge — O(k) per corner.
//!
//! Where an invariant that the paper guarantees fails ([`Inconsistent`]),
//! the polygon, or the part of it concerned, goes to the cubic program
//! ([`super::fallback`]); the run's counters report it, and the tests assert
//! that it never happens.

mod bits;
mod case2;
mod complete;
mod incomplete;
mod mesh;
mod visibility;

pub(crate) use mesh::Mesh;

use super::counters::Counters;
use super::fallback::{cubic_fallback, Fallback};
use super::polygon::Region;
use super::regions::is_boundary;
#[cfg(test)]
use super::{regions, rng_perturbed, rng_perturbed_flags};
use crate::kernel::{EuclideanOrder, LengthOrder, Point};
use crate::parallel::prelude::*;
use std::collections::HashMap;
use std::fmt;

/// Marks a missing local triangle (across the region's boundary) or position.
const NONE: u32 = u32::MAX;

/// Regions with at least this many corners run the per-corner scans in
/// parallel. Below it rayon's task overhead outweighs the O(k) work per
/// corner, and nearly all regions of typical inputs are far smaller.
const PARALLEL_CORNERS: usize = 256;

/// Failure of an invariant the paper guarantees: the caller falls back to the
/// exact cubic program (counted, and asserted zero in tests).
#[derive(Debug)]
pub(crate) struct Inconsistent(pub &'static str);

impl fmt::Display for Inconsistent {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "rng-polygon invariant failed: {}", self.0)
    }
}

/// `f` over `0..n`, in parallel if `parallel` (large regions only).
fn map_range<T: Send, R: FromIterator<T> + FromParallelIterator<T>>(
    parallel: bool,
    n: usize,
    f: impl Fn(usize) -> T + Sync + Send,
) -> R {
    if parallel {
        (0..n).into_par_iter().map(f).collect()
    } else {
        (0..n).map(f).collect()
    }
}

/// The triangles that tile a region, with their local adjacency (the
/// fields of [`RngPolygon`] of the same names).
struct Tiling {
    corners: Vec<[u32; 3]>,
    neighbours: Vec<[u32; 3]>,
    positions: Vec<[u32; 3]>,
    fan_start: Vec<(u32, u8)>,
}

/// One region of `ch(S) ∪ rng(S′)` (an rng-polygon), prepared for the §6
/// scans: its Delaunay triangles with local adjacency (no hashing during the
/// walks). Lengths are compared by `L` (Euclidean unless a metric is given,
/// [`RngPolygon::with_order`]).
pub(crate) struct RngPolygon<'a, L: LengthOrder = EuclideanOrder> {
    points: &'a [Point],
    order: L,
    /// Is the region strictly convex? Computed only where the §5.1 choice of
    /// `L` needs a visibility check ([`LengthOrder::CHOICE_IS_VISIBLE`]);
    /// `true` otherwise (no check).
    convex: bool,
    v: &'a [u32],
    k: usize,
    /// The Delaunay triangles it was read from (`None`: a fan, see
    /// [`RngPolygon::convex_fan`]).
    mesh: Option<&'a Mesh<'a>>,
    counters: &'a Counters,
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

impl<'a> RngPolygon<'a> {
    /// The region with corners `v` (counter-clockwise positions; the
    /// Delaunay triangles inside it are read from `mesh`), Euclidean lengths.
    pub fn new(
        points: &'a [Point],
        v: &'a [u32],
        mesh: &'a Mesh<'a>,
        counters: &'a Counters,
    ) -> Result<Self, Inconsistent> {
        Self::with_order(points, v, mesh, counters, EuclideanOrder)
    }
}

impl<'a, L: LengthOrder> RngPolygon<'a, L> {
    /// [`RngPolygon::new`] with lengths compared by `order`. Every boundary
    /// edge of the region must be a Delaunay edge marked in `mesh` (or a
    /// hull edge); the triangles only tile the region, so they need not be
    /// Delaunay for `order`.
    pub fn with_order(
        points: &'a [Point],
        v: &'a [u32],
        mesh: &'a Mesh<'a>,
        counters: &'a Counters,
        order: L,
    ) -> Result<Self, Inconsistent> {
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
        let tiling = Tiling {
            corners,
            neighbours,
            positions,
            fan_start,
        };
        Ok(Self::assemble(
            points,
            v,
            counters,
            order,
            Some(mesh),
            None,
            tiling,
        ))
    }

    /// A complete, strictly convex region (every corner a strict left turn
    /// in `S′`, no repeated vertex) tiled by the fan from position 0:
    /// triangle `t` has the positions `0, t+1, t+2`. For regions whose
    /// boundary is not made of Delaunay edges (under a metric, RNG chords
    /// need not be), where a [`Mesh`] cannot supply the triangles; the
    /// visibility walk only needs some triangulation of the region.
    pub fn convex_fan(
        points: &'a [Point],
        v: &'a [u32],
        counters: &'a Counters,
        order: L,
    ) -> Result<Self, Inconsistent> {
        let k = v.len();
        let geo = Region {
            points,
            vertices: v,
            symbolic: true,
        };
        if k < 3 || !geo.is_strictly_convex() {
            return Err(Inconsistent("fan of a region that is not strictly convex"));
        }
        let fan: Vec<[u32; 3]> = (0..k as u32 - 2).map(|t| [0, t + 1, t + 2]).collect();
        Self::from_tiling(points, v, counters, order, fan, Some(true))
    }

    /// A complete region with distinct corners that is simple in `S′`, tiled
    /// by ear clipping (the Two Ears Theorem: a simple polygon of more than
    /// three corners has two non-overlapping ears). For the regions that are
    /// neither strictly convex nor tiled by the Delaunay mesh (a metric's RNG
    /// chord that is not a Delaunay edge bounds a region with reflex
    /// corners). Only reflex corners can lie in a candidate ear (a corner
    /// inside an ear's triangle implies a reflex one inside it), so with the
    /// ear status of the clipped corner's two neighbours recomputed, the
    /// tiling costs O(k·r) orientation tests for `r` reflex corners: within
    /// §6's O(k²). A non-simple boundary leaves no ear and is reported
    /// [`Inconsistent`] (the caller's cubic program takes it).
    pub fn ear_clipped(
        points: &'a [Point],
        v: &'a [u32],
        counters: &'a Counters,
        order: L,
    ) -> Result<Self, Inconsistent> {
        let k = v.len();
        if k < 3 {
            return Err(Inconsistent("region of fewer than three corners"));
        }
        let mut seen = std::collections::HashSet::with_capacity(k);
        if !v.iter().all(|&w| seen.insert(w)) {
            return Err(Inconsistent("repeated corner"));
        }
        let geo = Region {
            points,
            vertices: v,
            symbolic: true,
        };
        let orient = |a: usize, b: usize, c: usize| geo.orient(v[a], v[b], v[c]);
        let mut prev: Vec<usize> = (0..k).map(|a| (a + k - 1) % k).collect();
        let mut next: Vec<usize> = (0..k).map(|a| (a + 1) % k).collect();
        let mut removed = vec![false; k];
        let mut reflex: Vec<bool> = (0..k).map(|a| orient(prev[a], a, next[a]) < 0).collect();
        let mut reflex_list: Vec<usize> = (0..k).filter(|&a| reflex[a]).collect();
        let is_ear = |a: usize, prev: &[usize], next: &[usize], reflex: &[bool], list: &[usize]| {
            let (p, n) = (prev[a], next[a]);
            !reflex[a]
                && list.iter().all(|&r| {
                    !reflex[r]
                        || r == p
                        || r == n
                        || r == a
                        || !(orient(p, a, r) > 0 && orient(a, n, r) > 0 && orient(n, p, r) > 0)
                })
        };
        let mut tiles = Vec::with_capacity(k - 2);
        let mut left = k;
        let mut stack: Vec<usize> = (0..k).rev().collect();
        let mut rescans = 0;
        while left > 3 {
            let Some(a) = stack.pop() else {
                // A corner that became an ear because a blocking reflex
                // corner turned convex was not queued: scan all again.
                rescans += 1;
                if rescans > 2 * k {
                    return Err(Inconsistent("ear clipping stalls"));
                }
                let before = stack.len();
                stack.extend((0..k).filter(|&a| !removed[a] && !reflex[a]));
                if stack.len() == before {
                    return Err(Inconsistent("no ear: region not simple"));
                }
                reflex_list.retain(|&r| !removed[r] && reflex[r]);
                continue;
            };
            if removed[a] || !is_ear(a, &prev, &next, &reflex, &reflex_list) {
                continue;
            }
            let (p, n) = (prev[a], next[a]);
            tiles.push([p as u32, a as u32, n as u32]);
            removed[a] = true;
            next[p] = n;
            prev[n] = p;
            left -= 1;
            for w in [p, n] {
                reflex[w] = orient(prev[w], w, next[w]) < 0;
                stack.push(w);
            }
        }
        let a = (0..k).find(|&a| !removed[a]).ok_or(Inconsistent("ears"))?;
        let (p, n) = (prev[a], next[a]);
        if orient(p, a, n) <= 0 {
            return Err(Inconsistent("last ear not a left turn"));
        }
        tiles.push([p as u32, a as u32, n as u32]);
        Self::from_tiling(points, v, counters, order, tiles, None)
    }

    /// The local adjacency of a tiling of the region given by position
    /// triples (counter-clockwise): neighbours across shared sides, and each
    /// corner's fan starting at the triangle left of its boundary edge
    /// `a → a+1`. `convex` as in [`Self::assemble`].
    fn from_tiling(
        points: &'a [Point],
        v: &'a [u32],
        counters: &'a Counters,
        order: L,
        positions: Vec<[u32; 3]>,
        convex: Option<bool>,
    ) -> Result<Self, Inconsistent> {
        let k = v.len();
        let mut side_of: HashMap<(u32, u32), (u32, u8)> =
            HashMap::with_capacity(3 * positions.len());
        for (t, c) in positions.iter().enumerate() {
            for j in 0..3 {
                if side_of
                    .insert((c[j], c[(j + 1) % 3]), (t as u32, j as u8))
                    .is_some()
                {
                    return Err(Inconsistent("side used twice"));
                }
            }
        }
        let neighbours: Vec<[u32; 3]> = positions
            .iter()
            .map(|c| {
                std::array::from_fn(|j| {
                    side_of
                        .get(&(c[(j + 1) % 3], c[j]))
                        .map_or(NONE, |&(t, _)| t)
                })
            })
            .collect();
        let fan_start: Vec<(u32, u8)> = (0..k)
            .map(|a| {
                side_of
                    .get(&(a as u32, ((a + 1) % k) as u32))
                    .copied()
                    .ok_or(Inconsistent("boundary edge outside the tiling"))
            })
            .collect::<Result<_, _>>()?;
        let tiling = Tiling {
            corners: positions.iter().map(|c| c.map(|a| v[a as usize])).collect(),
            neighbours,
            positions,
            fan_start,
        };
        Ok(Self::assemble(
            points, v, counters, order, None, convex, tiling,
        ))
    }

    /// The region with corners `v` and its tiling; `convex` is the known
    /// answer of the §5.1 visibility check's convexity test, or `None` to
    /// compute it where `L` needs it ([`LengthOrder::CHOICE_IS_VISIBLE`]).
    fn assemble(
        points: &'a [Point],
        v: &'a [u32],
        counters: &'a Counters,
        order: L,
        mesh: Option<&'a Mesh<'a>>,
        convex: Option<bool>,
        tiling: Tiling,
    ) -> Self {
        let geo = Region {
            points,
            vertices: v,
            symbolic: true,
        };
        let Tiling {
            corners,
            neighbours,
            positions,
            fan_start,
        } = tiling;
        Self {
            points,
            order,
            convex: convex.unwrap_or_else(|| L::CHOICE_IS_VISIBLE || geo.is_strictly_convex()),
            v,
            k: v.len(),
            mesh,
            counters,
            corners,
            neighbours,
            positions,
            fan_start,
            geo,
        }
    }

    #[inline]
    fn off(&self, a: usize, b: usize) -> usize {
        (b + self.k - a) % self.k
    }

    #[inline]
    fn at(&self, a: usize, offset: usize) -> usize {
        (a + offset) % self.k
    }

    /// The whole region: §5.1 if one edge is a hull edge outside `rng(S′)`
    /// (an incomplete rng-polygon, beyond that edge), else §5.3.
    pub fn triangulate(&self) -> Result<Vec<[u32; 3]>, Inconsistent> {
        let k = self.k;
        let hull_only = |a: usize| {
            self.mesh
                .is_some_and(|m| m.is_hull_only(self.v[a], self.v[(a + 1) % k]))
        };
        if let Some(a) = (0..k).find(|&a| hull_only(a)) {
            let mut out = Vec::with_capacity(k - 2);
            self.incomplete((a + 1) % k, k - 1, &mut out)?;
            return Ok(out);
        }
        self.complete()
    }
}

#[cfg(test)]
mod consistency_tests {
    use super::*;
    use crate::spatial::convex_hull_cycle;
    use crate::structures::DelaunayGraph;
    use rand::{rngs::StdRng, Rng, SeedableRng};

    /// Seed of the random 8-point sets.
    const SMALL_SETS_SEED: u64 = 7;

    #[test]
    fn random_regions_never_hit_an_inconsistency() {
        let pts: Vec<Point> = vec![[0.0, 0.0], [4.0, 0.1], [4.2, 3.0], [0.3, 2.9], [2.0, 1.4]];
        let mut rng = StdRng::seed_from_u64(SMALL_SETS_SEED);
        let counters = Counters::default();
        for trial in 0..200 {
            let pts: Vec<Point> = if trial == 0 {
                pts.clone()
            } else {
                (0..8)
                    .map(|_| [rng.gen_range(0.0..100.0), rng.gen_range(0.0..100.0)])
                    .collect()
            };
            let g = DelaunayGraph::with_topology(&pts).unwrap();
            let rng_edges = rng_perturbed(&pts, &g);
            let flags = rng_perturbed_flags(&pts, &g);
            let hull = convex_hull_cycle(&pts);
            let mesh = Mesh::new(&g, &flags);
            for r in regions(&pts, &rng_edges, &hull) {
                if r.len() == 3 {
                    continue;
                }
                let f = RngPolygon::new(&pts, &r, &mesh, &counters).unwrap();
                if let Err(e) = f.triangulate() {
                    let hull_only: Vec<bool> = (0..r.len())
                        .map(|a| mesh.is_hull_only(r[a], r[(a + 1) % r.len()]))
                        .collect();
                    let sel = f.shortest_expandable_2_edge();
                    panic!("{e} pts {pts:?} region {r:?} hull_only {hull_only:?} sel {sel:?}");
                }
            }
        }
    }
}
