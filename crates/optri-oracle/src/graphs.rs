//! Brute-force proximity graphs and checks, straight from the definitions.
//!
//! All point coordinates are first scaled by one common power of two to exact
//! integers (`i128` when small enough, else `BigInt`), so every test below is
//! an exact integer comparison. Edge lists are sorted `[min, max]` pairs.

use crate::exact::{cross, dist2, dot, incircle, orient, scale, Point, Ring, Scaled};
use num_bigint::BigInt;
use rand::rngs::StdRng;
use rand::seq::SliceRandom;
use rand::SeedableRng;
use std::cmp::Ordering;
use std::collections::{HashMap, HashSet};

/// Points as exact scaled integers.
struct Exact<T> {
    c: Vec<T>,
}

impl<T: Ring> Exact<T> {
    fn coords<const N: usize, const M: usize>(&self, idx: [usize; N]) -> [T; M] {
        std::array::from_fn(|k| self.c[2 * idx[k / 2] + k % 2].clone())
    }
    fn orient(&self, p: usize, q: usize, r: usize) -> Ordering {
        cross(&self.coords::<3, 6>([p, q, r])).cmp(&T::zero())
    }
    fn dot(&self, p: usize, q: usize, r: usize) -> Ordering {
        dot(&self.coords::<3, 6>([p, q, r])).cmp(&T::zero())
    }
    fn dist2(&self, p: usize, q: usize) -> T {
        dist2(&self.coords::<2, 4>([p, q]))
    }
}

/// Runs `$body` with `$g` bound to the exact integer image of `$points`.
macro_rules! with_exact {
    ($points:expr, |$g:ident| $body:expr) => {{
        let flat: Vec<f64> = $points.iter().flat_map(|p| [p[0], p[1]]).collect();
        // 61-bit coordinates: squared distances and their sums stay below 2^127.
        match scale(&flat, 61).0 {
            Scaled::Small(c) => {
                let $g = Exact::<i128> { c };
                $body
            }
            Scaled::Big(c) => {
                let $g = Exact::<BigInt> { c };
                $body
            }
        }
    }};
}

fn assert_distinct(points: &[Point]) {
    let mut sorted: Vec<(u64, u64, usize)> = points
        .iter()
        .enumerate()
        .map(|(i, p)| ((p[0] + 0.0).to_bits(), (p[1] + 0.0).to_bits(), i))
        .collect();
    sorted.sort_unstable();
    for w in sorted.windows(2) {
        assert!(
            (w[0].0, w[0].1) != (w[1].0, w[1].1),
            "optri-oracle: points {} and {} coincide",
            w[0].2,
            w[1].2
        );
    }
}

/// The seed of [`shuffled`]'s permutation.
const SCAN_ORDER_SEED: u64 = 0x9E37_79B9_7F4A_7C15;

/// A fixed pseudo-random permutation of `0..n` (the same for every call with
/// the same `n`). It only orders the scan: results do not depend on it.
fn shuffled(n: usize) -> Vec<usize> {
    let mut v: Vec<usize> = (0..n).collect();
    v.shuffle(&mut StdRng::seed_from_u64(SCAN_ORDER_SEED));
    v
}

/// Convex hull edges by definition: `pq` is an edge iff every point lies in
/// one closed half-plane of line `pq` and no point lies on the open segment
/// `pq`. Collinear boundary points are thus hull vertices. O(n³); the third
/// points are visited in a shuffled order so that spatially sorted inputs
/// find a witness on each side quickly.
pub fn convex_hull_edges(points: &[Point]) -> Vec<[u32; 2]> {
    assert_distinct(points);
    fn run<T: Ring>(g: &Exact<T>, n: usize) -> Vec<[u32; 2]> {
        let order = shuffled(n);
        let mut out = Vec::new();
        for p in 0..n {
            for q in p + 1..n {
                let (mut left, mut right, mut between) = (false, false, false);
                for &r in &order {
                    match g.orient(p, q, r) {
                        Ordering::Greater => left = true,
                        Ordering::Less => right = true,
                        Ordering::Equal => {
                            if r != p && r != q && g.dot(r, p, q) == Ordering::Less {
                                between = true;
                            }
                        }
                    }
                    if (left && right) || between {
                        break;
                    }
                }
                if !(between || left && right) {
                    out.push([p as u32, q as u32]);
                }
            }
        }
        out
    }
    with_exact!(points, |g| run(&g, points.len()))
}

/// For each point, the other points sorted by exact distance from it, with
/// the full exact distance matrix.
fn by_distance<T: Ring>(g: &Exact<T>, n: usize) -> (Vec<T>, Vec<Vec<usize>>) {
    let mut d = Vec::with_capacity(n * n);
    for p in 0..n {
        for q in 0..n {
            d.push(g.dist2(p, q));
        }
    }
    let order = (0..n)
        .map(|p| {
            let mut o: Vec<usize> = (0..n).filter(|&q| q != p).collect();
            o.sort_by(|&a, &b| d[p * n + a].cmp(&d[p * n + b]));
            o
        })
        .collect();
    (d, order)
}

/// Keeps pair `pq` iff no third point `r` satisfies `blocks(d_pr, d_qr, d_pq)`,
/// a condition that implies `d_pr < d_pq`: so only the points nearer to `p`
/// than `q` need testing. This is the O(n³) definition, merely ordered.
fn pairs_without_blocker<T: Ring>(
    g: &Exact<T>,
    n: usize,
    blocks: impl Fn(&T, &T, &T) -> bool,
) -> Vec<[u32; 2]> {
    let (d, order) = by_distance(g, n);
    let mut out = Vec::new();
    for p in 0..n {
        for &q in &order[p] {
            if q < p {
                continue;
            }
            let dpq = &d[p * n + q];
            let blocked = order[p]
                .iter()
                .take_while(|&&r| d[p * n + r] < *dpq)
                .any(|&r| r != q && blocks(&d[p * n + r], &d[q * n + r], dpq));
            if !blocked {
                out.push([p as u32, q as u32]);
            }
        }
    }
    out.sort_unstable();
    out
}

/// Relative neighbourhood graph by definition: `pq` is an edge iff no third
/// point `r` has `|pr| < |pq|` and `|qr| < |pq|` (strict; a point on the open
/// segment `pq` blocks it).
pub fn rng_edges(points: &[Point]) -> Vec<[u32; 2]> {
    assert_distinct(points);
    with_exact!(points, |g| pairs_without_blocker(
        &g,
        points.len(),
        |pr, qr, pq| pr < pq && qr < pq
    ))
}

/// Gabriel graph by definition: `pq` is an edge iff no other point lies in
/// or on the circle with diameter `pq` (the closed disc), i.e. no `r` with
/// angle `prq ≥ 90°`, i.e. (law of cosines, exact) `|pr|² + |qr|² ≤ |pq|²`.
pub fn gabriel_edges(points: &[Point]) -> Vec<[u32; 2]> {
    assert_distinct(points);
    fn in_diameter_circle<T: Ring>(pr: &T, qr: &T, pq: &T) -> bool {
        pr.clone() + qr.clone() <= *pq
    }
    with_exact!(points, |g| pairs_without_blocker(
        &g,
        points.len(),
        in_diameter_circle
    ))
}

/// Checks that `edges` is a minimum spanning tree of the complete Euclidean
/// graph on `points`: `n − 1` distinct valid edges forming a connected graph,
/// and the cycle property — for every pair `uv`, no edge on the tree path
/// from `u` to `v` is strictly longer than `uv` (exact). Orientation and order
/// of the edge list do not matter.
pub fn is_minimum_spanning_tree(points: &[Point], edges: &[[u32; 2]]) -> Result<(), String> {
    assert_distinct(points);
    let n = points.len();
    if edges.len() + 1 != n {
        return Err(format!("{} edges for {n} points", edges.len()));
    }
    let mut adj = vec![Vec::new(); n];
    for &[a, b] in edges {
        if a as usize >= n || b as usize >= n || a == b {
            return Err(format!("bad edge [{a}, {b}]"));
        }
        adj[a as usize].push(b as usize);
        adj[b as usize].push(a as usize);
    }
    fn run<T: Ring>(g: &Exact<T>, adj: &[Vec<usize>]) -> Result<(), String> {
        let n = adj.len();
        for s in 0..n {
            // Longest edge (squared) on the tree path from s to every vertex.
            let mut longest: Vec<Option<(T, [usize; 2])>> = vec![None; n];
            let mut seen = vec![false; n];
            seen[s] = true;
            let mut stack = vec![s];
            let mut reached = 1;
            while let Some(u) = stack.pop() {
                for &w in &adj[u] {
                    if seen[w] {
                        continue;
                    }
                    seen[w] = true;
                    reached += 1;
                    let e = g.dist2(u, w);
                    longest[w] = Some(match &longest[u] {
                        Some((l, le)) if *l >= e => (l.clone(), *le),
                        _ => (e, [u, w]),
                    });
                    stack.push(w);
                }
            }
            if reached != n {
                return Err(format!(
                    "not spanning: {reached} of {n} points reached from {s}"
                ));
            }
            for (v, path_max) in longest.iter().enumerate().skip(s + 1) {
                let (l, le) = path_max.as_ref().unwrap();
                if g.dist2(s, v) < *l {
                    return Err(format!(
                        "cycle property fails: [{s}, {v}] is shorter than tree edge {le:?} on its tree path"
                    ));
                }
            }
        }
        Ok(())
    }
    with_exact!(points, |g| run(&g, &adj))
}

/// Checks that `tris` are non-flat triangles (any orientation) none of whose
/// open circumcircles contains a point of `points`. Exact. Does not check
/// that they form a triangulation.
pub fn delaunay_check(points: &[Point], tris: &[[u32; 3]]) -> Result<(), String> {
    let n = points.len();
    for t in tris {
        if t.iter().any(|&v| v as usize >= n) {
            return Err(format!("triangle {t:?} has an index out of range"));
        }
        let [a, b, c] = t.map(|v| points[v as usize]);
        if orient(a, b, c) == 0 {
            return Err(format!("flat triangle {t:?}"));
        }
        for (r, &d) in points.iter().enumerate() {
            if incircle(a, b, c, d) > 0 {
                return Err(format!(
                    "point {r} is strictly inside the circumcircle of {t:?}"
                ));
            }
        }
    }
    Ok(())
}

/// Checks that every edge shared by two of the triangles `tris` is a
/// constraint (an unordered pair of `constraints`) or *locally constrained
/// Delaunay*: the apex of either triangle is not strictly inside the other's
/// circumcircle (a triangulation of a polygon with this property is its
/// constrained Delaunay triangulation; Lee & Lin 1986, Chew 1989). Exact.
/// Returns the number of shared edges that are not constraints (each
/// checked). Does not check that the triangles form a triangulation.
pub fn constrained_delaunay_check(
    points: &[Point],
    tris: &[[u32; 3]],
    constraints: &[[u32; 2]],
) -> Result<usize, String> {
    let n = points.len();
    let constraint: HashSet<[u32; 2]> = constraints
        .iter()
        .map(|&[u, v]| [u.min(v), u.max(v)])
        .collect();
    // The apex of the triangle left of each directed side.
    let mut apex: HashMap<(u32, u32), u32> = HashMap::new();
    for t in tris {
        if t.iter().any(|&v| v as usize >= n) {
            return Err(format!("triangle {t:?} has an index out of range"));
        }
        let [a, b, c] = if orient(
            points[t[0] as usize],
            points[t[1] as usize],
            points[t[2] as usize],
        ) < 0
        {
            [t[0], t[2], t[1]]
        } else {
            *t
        };
        if orient(points[a as usize], points[b as usize], points[c as usize]) == 0 {
            return Err(format!("flat triangle {t:?}"));
        }
        for (u, v, w) in [(a, b, c), (b, c, a), (c, a, b)] {
            if apex.insert((u, v), w).is_some() {
                return Err(format!("directed side ({u}, {v}) is in two triangles"));
            }
        }
    }
    let p = |i: u32| points[i as usize];
    let mut checked = 0;
    for (&(u, v), &w) in &apex {
        let Some(&x) = apex.get(&(v, u)) else {
            continue;
        };
        if u > v || constraint.contains(&[u, v]) {
            continue; // each shared side once; constraints need not be Delaunay
        }
        if incircle(p(u), p(v), p(w), p(x)) > 0 || incircle(p(v), p(u), p(x), p(w)) > 0 {
            return Err(format!(
                "edge ({u}, {v}) is neither a constraint nor locally Delaunay"
            ));
        }
        checked += 1;
    }
    Ok(checked)
}

/// The bounded faces of the plane graph `(points, edges)` (straight, pairwise
/// non-crossing edges), each as a counter-clockwise cycle of point indices
/// with the face on the left, in the form [`crate::klincsek()`] takes. A
/// dangling edge or tree inside a face is walked on both sides, so vertices
/// may repeat. A face with holes (a disconnected graph) yields one cycle per
/// boundary component; only the outer component has positive area, and only
/// cycles of positive area are returned.
pub fn bounded_faces(points: &[Point], edges: &[[u32; 2]]) -> Vec<Vec<u32>> {
    let n = points.len();
    let mut around: Vec<Vec<u32>> = vec![Vec::new(); n];
    for &[a, b] in edges {
        around[a as usize].push(b);
        around[b as usize].push(a);
    }
    // Counter-clockwise angular order from the +x direction, exactly: the
    // upper half-plane (and the +x ray) first, then by orientation.
    for (v, nb) in around.iter_mut().enumerate() {
        let o = points[v];
        let half = |p: Point| -> u8 {
            if p[1] > o[1] || (p[1] == o[1] && p[0] > o[0]) {
                0
            } else {
                1
            }
        };
        nb.sort_by(|&a, &b| {
            let (pa, pb) = (points[a as usize], points[b as usize]);
            half(pa)
                .cmp(&half(pb))
                .then_with(|| 0.cmp(&orient(o, pa, pb)))
        });
        nb.dedup();
    }
    let mut used: std::collections::HashSet<(u32, u32)> = std::collections::HashSet::new();
    let mut faces = Vec::new();
    for u in 0..n as u32 {
        for &v in &around[u as usize] {
            if used.contains(&(u, v)) {
                continue;
            }
            // Walk: after u → v, leave v along the edge just clockwise of v → u.
            let mut cycle = Vec::new();
            let (mut a, mut b) = (u, v);
            while used.insert((a, b)) {
                cycle.push(a);
                let nb = &around[b as usize];
                let at = nb.iter().position(|&x| x == a).unwrap();
                let w = nb[(at + nb.len() - 1) % nb.len()];
                (a, b) = (b, w);
            }
            let area: crate::BigRational = (1..cycle.len().saturating_sub(1))
                .map(|i| {
                    let p = |k: usize| points[cycle[k] as usize];
                    let s = orient(p(0), p(i), p(i + 1));
                    let a = crate::exact::twice_area(p(0), p(i), p(i + 1));
                    if s < 0 {
                        -a
                    } else {
                        a
                    }
                })
                .sum();
            if area > crate::BigRational::from_integer(0.into()) {
                faces.push(cycle);
            }
        }
    }
    faces
}

/// Whether a face cycle from [`bounded_faces`] visits some vertex more than
/// once: a crack (a dangling edge or tree walked on both sides) or a pinch.
pub fn is_cracked(face: &[u32]) -> bool {
    let mut sorted = face.to_vec();
    sorted.sort_unstable();
    sorted.dedup();
    sorted.len() < face.len()
}
