//! Delaunay triangulation of a convex polygon in expected O(k) time:
//! Chew's randomised algorithm (L. P. Chew, *Building Voronoi diagrams for
//! convex polygons in linear expected time*, Dartmouth TR PCS-TR90-147,
//! 1990). The polygon may have
//! straight-angle vertices (points in weakly convex position: all on the hull
//! boundary, some on the interior of hull edges); its Delaunay triangulation
//! is then the Delaunay triangulation of its vertex set, which has no flat
//! triangles.
//!
//! 1. Delete the `k` vertices in random order from the cyclic vertex list
//!    until three remain. Each deleted vertex keeps its `prev`/`next` links
//!    (dancing links), i.e. its two neighbours at deletion time.
//! 2. Start from the triangle of the three survivors and re-insert the
//!    deleted vertices in reverse order. When `p` returns, its remembered
//!    neighbours `a`, `b` are consecutive on the current polygon, so `p` lies
//!    outside it, beyond the hull edge `ab`: add the triangle `a p b`. If
//!    `p` is a straight-angle vertex of the current polygon it lies *on*
//!    the side `ab` (the polygon is weakly convex, so `a, p, b` collinear
//!    means `p` between them): split the triangle `a b c` on that side into
//!    `a p c` and `p b c` instead, the usual insertion of a point on an edge.
//! 3. Restore the Delaunay property by Lawson flips of the edges opposite `p`
//!    (exact [`incircle_sign`]). Only the triangles containing `p` changed,
//!    so only the edges of `p`'s link can be illegal; a flip replaces one by
//!    an edge incident to `p` and queues the two new link edges.
//!
//! # Degeneracies
//! Any subset of a weakly convex polygon's vertices, in cyclic order, is a
//! weakly convex polygon, so step 2 only needs three survivors that are not
//! collinear; if the random ones are, one of them is exchanged with the last
//! deleted vertex off their line (there is one: the polygon is not flat).
//! A flip never makes a flat triangle: if `c` is strictly inside the
//! circumcircle of `p x y` across `xy`, the quadrilateral `p x c y` is strictly
//! convex. The point `p` on an edge `ab` lies strictly inside the
//! circumcircle of `a b c`, so the argument below for the edges at `p`
//! applies to the edge split too.
//!
//! An edge is flipped only when the opposite vertex is *strictly* inside the
//! circumcircle. Edges incident to `p` are never flipped, so each insertion
//! does at most `k` flips and the algorithm terminates. The result is a
//! Delaunay triangulation for cocircular input too: an edge `pc` created by a
//! flip has a circle through `p` and `c` whose closed disc holds no other
//! vertex (shrink the empty circumcircle of the old triangle at `c` towards
//! `p`, which lies strictly inside it), and such an edge is strictly locally
//! Delaunay in every triangulation containing it. Every other edge is checked
//! (link edges) or kept its two triangles, so every edge is locally Delaunay
//! (opposite vertex not strictly inside), which makes the triangulation
//! Delaunay. For cocircular vertices it is one of the Delaunay completions.
//!
//! # Cost
//! Backward analysis: the vertex inserted at step `r` is a uniformly random
//! one of the `r` current vertices, and the flips it causes are its degree in
//! the triangulation after the step minus 2. The `r` degrees of a
//! triangulation of a convex `r`-gon sum to `2(2r - 3)`, so the expected number
//! of flips per insertion is below 2 (for vertices in general position, where
//! the triangulation after each step is the unique Delaunay one). Everything
//! else is O(1) per vertex, so the expected time is O(k), and the memory is
//! O(k) in buffers that are reused across calls.
//!
//! The random order comes from a splitmix64 generator with a fixed seed whose
//! state carries over between calls, so every run is reproducible.

use crate::kernel::{incircle_sign, orient_sign, Point};

/// No triangle: marks a side on the current polygon boundary.
const NONE: u32 = u32::MAX;

/// Reusable state for Delaunay triangulations of convex polygons.
///
/// After [`ConvexDelaunay::triangulate`], vertices are *positions* `0..k` in
/// the polygon passed in.
pub(super) struct ConvexDelaunay {
    /// splitmix64 state.
    rng: u64,
    /// Random permutation of `0..k`: deletion order of the first `k - 3`.
    order: Vec<u32>,
    /// Cyclic vertex list; a deleted vertex keeps its links.
    prev: Vec<u32>,
    next: Vec<u32>,
    /// Per vertex `v` on the current polygon: the triangle with side `v → next[v]`.
    boundary: Vec<u32>,
    /// Counter-clockwise triangles; side `j` runs from corner `j` to `j + 1`.
    triangles: Vec<[u32; 3]>,
    /// The triangle across each side, [`NONE`] on the boundary.
    neighbours: Vec<[u32; 3]>,
    /// Triangles `[p, x, y]` whose side `x → y` (opposite `p`) is to be checked.
    pending: Vec<u32>,
}

impl ConvexDelaunay {
    pub(super) fn new() -> Self {
        ConvexDelaunay {
            rng: 0x0DE1_A0A7_C4E3_5EED,
            order: Vec::new(),
            prev: Vec::new(),
            next: Vec::new(),
            boundary: Vec::new(),
            triangles: Vec::new(),
            neighbours: Vec::new(),
            pending: Vec::new(),
        }
    }

    fn next_u64(&mut self) -> u64 {
        self.rng = self.rng.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.rng;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in `0..n` (multiply-shift; the bias is at most `n / 2⁶⁴`).
    fn below(&mut self, n: usize) -> usize {
        ((u128::from(self.next_u64()) * n as u128) >> 64) as usize
    }

    /// Delaunay triangulation of the convex polygon `polygon`
    /// (counter-clockwise indices into `points`, at least 3 of them, not all
    /// collinear). With `straight_angles`, vertices with a straight angle
    /// are allowed (weakly convex position); without, the polygon must be
    /// strictly convex, and the collinearity tests are skipped. Expected O(k)
    /// time. Returns the number of flips.
    pub(super) fn triangulate(
        &mut self,
        points: &[Point],
        polygon: &[u32],
        straight_angles: bool,
    ) -> usize {
        let k = polygon.len();
        assert!(k >= 3, "a polygon has at least 3 vertices");
        assert!(k < NONE as usize, "too many vertices");
        let pt = |v: u32| points[polygon[v as usize] as usize];

        self.order.clear();
        self.order.extend(0..k as u32);
        for i in (1..k).rev() {
            let j = self.below(i + 1);
            self.order.swap(i, j);
        }
        self.prev.clear();
        self.prev.extend((0..k).map(|i| ((i + k - 1) % k) as u32));
        self.next.clear();
        self.next.extend((0..k).map(|i| ((i + 1) % k) as u32));
        let Self {
            order,
            prev,
            next,
            boundary,
            triangles,
            neighbours,
            pending,
            ..
        } = self;
        if straight_angles {
            let [s0, s1, s2] = [order[k - 3], order[k - 2], order[k - 1]];
            if orient_sign(pt(s0), pt(s1), pt(s2)) == 0 {
                let off = order[..k - 3]
                    .iter()
                    .rposition(|&v| orient_sign(pt(s1), pt(s2), pt(v)) != 0)
                    .expect("a polygon that is not flat");
                order.swap(off, k - 3);
            }
        }
        for &v in &order[..k - 3] {
            let (a, b) = (prev[v as usize], next[v as usize]);
            next[a as usize] = b;
            prev[b as usize] = a;
        }

        triangles.clear();
        neighbours.clear();
        boundary.clear();
        boundary.resize(k, NONE);
        let r0 = order[k - 1];
        let r1 = next[r0 as usize];
        let r2 = next[r1 as usize];
        triangles.push([r0, r1, r2]);
        neighbours.push([NONE; 3]);
        for r in [r0, r1, r2] {
            boundary[r as usize] = 0;
        }
        let mut flips = 0;

        for &p in order[..k - 3].iter().rev() {
            let (a, b) = (prev[p as usize], next[p as usize]);
            next[a as usize] = p;
            prev[b as usize] = p;
            let s = boundary[a as usize];
            let t = triangles.len() as u32;
            if straight_angles && orient_sign(pt(p), pt(b), pt(a)) == 0 {
                // `p` lies on the side a → b of `s` = [a, b, c]: `s` becomes
                // [p, b, c], the new `t` is [p, c, a].
                let j = corner(&triangles[s as usize], a);
                let c = triangles[s as usize][(j + 2) % 3];
                let n_bc = neighbours[s as usize][(j + 1) % 3];
                let n_ca = neighbours[s as usize][(j + 2) % 3];
                triangles[s as usize] = [p, b, c];
                neighbours[s as usize] = [NONE, n_bc, t];
                triangles.push([p, c, a]);
                neighbours.push([s, n_ca, NONE]);
                if n_ca == NONE {
                    boundary[c as usize] = t;
                } else {
                    let i = side_towards(&neighbours[n_ca as usize], s);
                    neighbours[n_ca as usize][i] = t;
                }
                boundary[a as usize] = t;
                boundary[p as usize] = s;
                pending.push(s);
                pending.push(t);
            } else {
                // `p` lies beyond the boundary edge a → b of triangle `s`.
                triangles.push([p, b, a]);
                neighbours.push([NONE, s, NONE]);
                let j = corner(&triangles[s as usize], a);
                debug_assert_eq!(triangles[s as usize][(j + 1) % 3], b);
                neighbours[s as usize][j] = t;
                boundary[a as usize] = t;
                boundary[p as usize] = t;
                pending.push(t);
            }
            while let Some(t) = pending.pop() {
                let [q, x, y] = triangles[t as usize];
                debug_assert_eq!(q, p);
                let u = neighbours[t as usize][1];
                if u == NONE {
                    continue; // x → y is on the polygon boundary
                }
                // In `u`: side j is y → x, and `c` is opposite it.
                let j = side_towards(&neighbours[u as usize], t);
                let c = triangles[u as usize][(j + 2) % 3];
                if incircle_sign(pt(p), pt(x), pt(y), pt(c)) <= 0 {
                    continue;
                }
                // Flip x y into p c: t = [p, x, c], u = [p, c, y].
                flips += 1;
                let [n_px, _, n_yp] = neighbours[t as usize];
                let n_xc = neighbours[u as usize][(j + 1) % 3];
                let n_cy = neighbours[u as usize][(j + 2) % 3];
                triangles[t as usize] = [p, x, c];
                neighbours[t as usize] = [n_px, n_xc, u];
                triangles[u as usize] = [p, c, y];
                neighbours[u as usize] = [t, n_cy, n_yp];
                if n_xc == NONE {
                    boundary[x as usize] = t;
                } else {
                    let i = side_towards(&neighbours[n_xc as usize], u);
                    neighbours[n_xc as usize][i] = t;
                }
                if n_yp == NONE {
                    boundary[y as usize] = u;
                } else {
                    let i = side_towards(&neighbours[n_yp as usize], t);
                    neighbours[n_yp as usize][i] = u;
                }
                pending.push(t);
                pending.push(u);
            }
        }
        debug_assert_eq!(triangles.len(), k - 2);
        flips
    }

    /// The `k - 2` counter-clockwise triangles of the last triangulation
    /// (polygon positions).
    #[cfg(test)]
    pub(super) fn triangles(&self) -> &[[u32; 3]] {
        &self.triangles
    }

    /// The `k - 3` diagonals of the last triangulation (polygon positions),
    /// each once.
    pub(super) fn diagonals(&self) -> impl Iterator<Item = [u32; 2]> + '_ {
        self.triangles
            .iter()
            .zip(&self.neighbours)
            .enumerate()
            .flat_map(|(t, (tri, nb))| {
                (0..3)
                    .filter(move |&j| nb[j] != NONE && nb[j] > t as u32)
                    .map(move |j| [tri[j], tri[(j + 1) % 3]])
            })
    }
}

/// The corner of `tri` holding vertex `v`.
#[inline]
fn corner(tri: &[u32; 3], v: u32) -> usize {
    if tri[0] == v {
        0
    } else if tri[1] == v {
        1
    } else {
        debug_assert_eq!(tri[2], v);
        2
    }
}

/// The side of a triangle (given by its neighbours) facing triangle `t`.
#[inline]
fn side_towards(nb: &[u32; 3], t: u32) -> usize {
    corner(nb, t)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::orient_sign;
    use crate::spatial::convex_hull_cycle;
    use crate::structures::DelaunayGraph;
    use rand::rngs::StdRng;
    use rand::{Rng, SeedableRng};
    use std::collections::HashMap;

    #[test]
    fn incircle_sign_is_positive_inside_a_ccw_circle() {
        let (a, b, c) = ([1.0, 0.0], [0.0, 1.0], [-1.0, 0.0]);
        assert_eq!(orient_sign(a, b, c), 1);
        assert_eq!(incircle_sign(a, b, c, [0.0, 0.0]), 1);
        assert_eq!(incircle_sign(a, b, c, [0.0, -1.0]), 0);
        assert_eq!(incircle_sign(a, b, c, [0.0, -2.0]), -1);
    }

    /// The strict corners of the hull of `pts` (collinear boundary points and
    /// duplicates dropped), counter-clockwise.
    fn strictly_convex(mut pts: Vec<Point>) -> Vec<Point> {
        pts.sort_unstable_by(|p, q| p[0].total_cmp(&q[0]).then(p[1].total_cmp(&q[1])));
        pts.dedup();
        let h = convex_hull_cycle(&pts);
        let k = h.len();
        let p = |i: usize| pts[h[i % k] as usize];
        (0..k)
            .filter(|&i| orient_sign(p(i + k - 1), p(i), p(i + 1)) > 0)
            .map(p)
            .collect()
    }

    /// Checks that `dt` holds a triangulation of the convex polygon `pts`
    /// (positions) in which every diagonal is locally Delaunay; with
    /// `empty_circles`, also that no vertex lies strictly inside any
    /// triangle's circumcircle (O(k²)). Returns the sorted diagonals.
    fn check(pts: &[Point], dt: &ConvexDelaunay, empty_circles: bool) -> Vec<[u32; 2]> {
        let k = pts.len();
        let p = |v: u32| pts[v as usize];
        let tris = dt.triangles();
        assert_eq!(tris.len(), k - 2);
        // Directed sides: each at most once; polygon edges once; diagonals
        // once in each direction.
        let mut sides: HashMap<[u32; 2], [u32; 3]> = HashMap::new();
        for &tri in tris {
            let [a, b, c] = tri;
            assert!(a != b && b != c && a != c && (a.max(b).max(c) as usize) < k);
            assert_eq!(orient_sign(p(a), p(b), p(c)), 1, "{tri:?} not ccw");
            for j in 0..3 {
                let side = [tri[j], tri[(j + 1) % 3]];
                assert!(sides.insert(side, tri).is_none(), "side {side:?} twice");
            }
        }
        let mut diagonals = Vec::new();
        for (&[a, b], &tri) in &sides {
            if (a as usize + 1) % k == b as usize {
                continue;
            }
            let other = sides
                .get(&[b, a])
                .unwrap_or_else(|| panic!("diagonal {a}-{b} has one triangle"));
            if a < b {
                diagonals.push([a, b]);
            }
            let apex = other.iter().copied().find(|&v| v != a && v != b).unwrap();
            assert!(
                incircle_sign(p(tri[0]), p(tri[1]), p(tri[2]), p(apex)) <= 0,
                "diagonal {a}-{b} is not locally Delaunay"
            );
        }
        for [a, b] in (0..k as u32).map(|i| [i, (i + 1) % k as u32]) {
            assert!(sides.contains_key(&[a, b]), "polygon edge {a}-{b} missing");
        }
        diagonals.sort_unstable();
        let mut listed: Vec<[u32; 2]> = dt.diagonals().map(|[a, b]| [a.min(b), a.max(b)]).collect();
        listed.sort_unstable();
        assert_eq!(listed, diagonals);
        assert_eq!(diagonals.len(), k - 3);
        if empty_circles {
            for &[a, b, c] in tris {
                for v in 0..k as u32 {
                    assert!(incircle_sign(p(a), p(b), p(c), p(v)) <= 0);
                }
            }
        }
        diagonals
    }

    /// [`check`], then compare the diagonals with spade's Delaunay
    /// triangulation (unique for vertices in general position).
    fn check_against_spade(pts: &[Point], dt: &mut ConvexDelaunay, what: &str) {
        let polygon: Vec<u32> = (0..pts.len() as u32).collect();
        dt.triangulate(pts, &polygon, false);
        let ours = check(pts, dt, pts.len() <= 300);
        let k = pts.len() as u32;
        let mut spade: Vec<[u32; 2]> = DelaunayGraph::new(pts)
            .unwrap()
            .edges
            .iter()
            .map(|&([a, b], _)| [a.min(b), a.max(b)])
            .filter(|&[a, b]| b - a != 1 && b - a != k - 1)
            .collect();
        spade.sort_unstable();
        assert_eq!(ours, spade, "{what}: k = {k}");
    }

    fn ellipse(rng: &mut StdRng, k: usize, axes: [f64; 2], jitter: f64) -> Vec<Point> {
        (0..k)
            .map(|_| {
                let t = rng.gen_range(0.0..std::f64::consts::TAU);
                let r = 1.0 + rng.gen_range(-jitter..=jitter);
                [axes[0] * r * t.cos(), axes[1] * r * t.sin()]
            })
            .collect()
    }

    fn moved(pts: Vec<Point>, scale: f64, centre: [f64; 2]) -> Vec<Point> {
        pts.into_iter()
            .map(|[x, y]| [centre[0] + scale * x, centre[1] + scale * y])
            .collect()
    }

    #[test]
    fn matches_spade_on_random_convex_polygons() {
        let mut rng = StdRng::seed_from_u64(1);
        let mut dt = ConvexDelaunay::new();
        let mut sizes: Vec<usize> = (3..=60).collect();
        sizes.extend([100, 257, 500, 1000, 2000]);
        for &k in &sizes {
            for (axes, jitter) in [([1.0, 1.0], 0.0), ([1.0, 1.0], 0.01), ([3.0, 1.0], 0.001)] {
                let pts = strictly_convex(ellipse(&mut rng, k, axes, jitter));
                if pts.len() >= 3 {
                    check_against_spade(&pts, &mut dt, &format!("{axes:?} {jitter}"));
                }
            }
        }
    }

    #[test]
    fn triangle_and_small_polygons() {
        let mut dt = ConvexDelaunay::new();
        let tri = [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]];
        dt.triangulate(&tri, &[0, 1, 2], false);
        assert_eq!(dt.triangles(), &[[0, 1, 2]]);
        assert_eq!(dt.diagonals().count(), 0);
        // Indices into a larger array, not starting at 0.
        let pts = [[9.0, 9.0], [0.0, 0.0], [4.0, 0.0], [5.0, 2.0], [0.0, 3.0]];
        dt.triangulate(&pts, &[1, 2, 3, 4], false);
        let local = [pts[1], pts[2], pts[3], pts[4]];
        check(&local, &dt, true);
    }

    #[test]
    fn thin_ellipses_match_spade() {
        let mut rng = StdRng::seed_from_u64(2);
        let mut dt = ConvexDelaunay::new();
        for (k, ratio) in [(50, 1e-3), (200, 1e-6), (1000, 1e-9), (2000, 1e-12)] {
            for jitter in [0.0, 1e-3] {
                let pts = strictly_convex(ellipse(&mut rng, k, [1.0, ratio], jitter));
                check_against_spade(&pts, &mut dt, &format!("thin {ratio}"));
            }
        }
    }

    /// The extremes of the accepted coordinate range
    /// ([`crate::kernel::MAX_COORDINATE`] = 2²⁰¹,
    /// [`crate::kernel::MIN_COORDINATE`] = 2⁻¹⁴²; beyond it the degree-4
    /// in-circle expansions over- or underflow).
    #[test]
    fn huge_and_tiny_scales_match_spade() {
        let mut rng = StdRng::seed_from_u64(3);
        let mut dt = ConvexDelaunay::new();
        for (scale, centre) in [(1e60, [2e60, 2e60]), (1e-40, [3e-40, -3e-40])] {
            for k in [10, 100, 1000] {
                let pts = ellipse(&mut rng, k, [1.0, 0.5], 0.01);
                let pts = strictly_convex(moved(pts, scale, centre));
                for v in pts.iter().flatten() {
                    assert!(
                        (crate::kernel::MIN_COORDINATE..=crate::kernel::MAX_COORDINATE)
                            .contains(&v.abs())
                    );
                }
                check_against_spade(&pts, &mut dt, &format!("scale {scale}"));
            }
        }
    }

    /// Integer points with `x² + m y² = n`, counter-clockwise.
    fn integer_conic(m: i64, n: i64) -> Vec<Point> {
        let mut pts = Vec::new();
        let mut y = 0;
        while m * y * y <= n {
            let rest = n - m * y * y;
            let x = (rest as f64).sqrt().round() as i64;
            if x * x == rest {
                for (sx, sy) in [(1, 1), (-1, 1), (1, -1), (-1, -1)] {
                    pts.push([(sx * x) as f64, (sy * y) as f64]);
                }
            }
            y += 1;
        }
        strictly_convex(pts)
    }

    #[test]
    fn exactly_cocircular_points_give_a_delaunay_triangulation() {
        let mut dt = ConvexDelaunay::new();
        let mut rng = StdRng::seed_from_u64(4);
        for r in [5i64, 25, 65, 325, 1105, 5525] {
            let pts = integer_conic(1, r * r);
            assert!(pts.len() >= 12, "r = {r}: {} points", pts.len());
            let polygon: Vec<u32> = (0..pts.len() as u32).collect();
            for _ in 0..5 {
                dt.triangulate(&pts, &polygon, false);
                check(&pts, &dt, true);
            }
            // Random subsets, in a larger array with unused points.
            for _ in 0..10 {
                let sub: Vec<u32> = polygon
                    .iter()
                    .copied()
                    .filter(|_| rng.gen_bool(0.5))
                    .collect();
                if sub.len() >= 3 {
                    dt.triangulate(&pts, &sub, false);
                    let local: Vec<Point> = sub.iter().map(|&v| pts[v as usize]).collect();
                    check(&local, &dt, true);
                }
            }
        }
    }

    /// On `x² + m y² = n`, the points `(±x, ±y)` form rectangles: many
    /// cocircular quadruples, but not all points on one circle.
    #[test]
    fn partly_cocircular_points_give_a_delaunay_triangulation() {
        let mut dt = ConvexDelaunay::new();
        for (m, n) in [
            (2, 3 * 11 * 17 * 19 * 41),
            (2, 9 * 11 * 17 * 19 * 43),
            (3, 7 * 13 * 19 * 31 * 37),
        ] {
            let pts = integer_conic(m, n);
            assert!(pts.len() >= 12, "{m} {n}: {} points", pts.len());
            let polygon: Vec<u32> = (0..pts.len() as u32).collect();
            for _ in 0..5 {
                dt.triangulate(&pts, &polygon, false);
                check(&pts, &dt, true);
            }
        }
    }

    /// Weakly convex polygons (points on the sides of an integer polygon,
    /// exactly collinear, many cocircular quadruples): a triangulation
    /// with every circumcircle empty, no flat triangle (`check` asserts
    /// ccw triangles), for every seed of the deletion order; also one
    /// strict corner with every other vertex on one side.
    #[test]
    fn straight_angles_give_a_delaunay_triangulation() {
        let mut rng = StdRng::seed_from_u64(6);
        let mut dt = ConvexDelaunay::new();
        let shapes: [&[Point]; 3] = [
            &[[0.0, 0.0], [12.0, 0.0], [3.0, 12.0]],
            &[[0.0, 0.0], [12.0, 0.0], [12.0, 12.0], [0.0, 12.0]],
            &[
                [0.0, 0.0],
                [60.0, 0.0],
                [60.0, 24.0],
                [36.0, 48.0],
                [0.0, 12.0],
            ],
        ];
        for corners in shapes {
            let k = corners.len();
            for _ in 0..200 {
                let mut pts = Vec::new();
                for i in 0..k {
                    let (a, b) = (corners[i], corners[(i + 1) % k]);
                    // Scaled by 12: the side points are exact integers.
                    pts.push([12.0 * a[0], 12.0 * a[1]]);
                    for t in 1..12 {
                        if rng.gen_bool(0.5) {
                            let t = t as f64;
                            pts.push([
                                12.0 * a[0] + t * (b[0] - a[0]),
                                12.0 * a[1] + t * (b[1] - a[1]),
                            ]);
                        }
                    }
                }
                let polygon: Vec<u32> = (0..pts.len() as u32).collect();
                dt.triangulate(&pts, &polygon, true);
                check(&pts, &dt, true);
            }
        }
        let mut pts: Vec<Point> = (0..500).map(|i| [i as f64, 0.0]).collect();
        pts.push([7.0, 3.0]);
        let polygon: Vec<u32> = (0..pts.len() as u32).collect();
        for _ in 0..5 {
            dt.triangulate(&pts, &polygon, true);
            check(&pts, &dt, true);
        }
    }

    #[test]
    fn flips_are_expected_linear() {
        // Backward analysis: the expected number of flips per insertion is
        // below 2 (and tends to 2); allow 5% for randomness.
        let mut rng = StdRng::seed_from_u64(5);
        let mut dt = ConvexDelaunay::new();
        for (k, axes) in [(200_000, [1.0, 1.0]), (100_000, [1.0, 1e-3])] {
            let pts = strictly_convex(ellipse(&mut rng, k, axes, 0.0));
            let k = pts.len();
            let polygon: Vec<u32> = (0..k as u32).collect();
            let mut total = 0;
            for _ in 0..3 {
                let flips = dt.triangulate(&pts, &polygon, false);
                assert_eq!(dt.triangles().len(), k - 2);
                assert_eq!(dt.diagonals().count(), k - 3);
                total += flips;
            }
            assert!(
                20 * total < 3 * 2 * 21 * k,
                "{total} flips for 3 x {k} insertions"
            );
        }
    }
}
