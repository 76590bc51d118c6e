//! Simple polygons by definition, in exact rational arithmetic: simplicity,
//! orientation, diagonals, every triangulation, the greedy triangulation,
//! and seeded generators of test polygons.
//!
//! A *ring* is the caller's vertex list in boundary order (either
//! orientation, the closing vertex not repeated); indices are ring
//! positions. Every decision is exact, in `BigInt` arithmetic on the
//! coordinates scaled by one power of two (doubled, so that midpoints are
//! integer points),
//! with definitions chosen to differ from optri's: a chord is a diagonal iff
//! its open segment meets no closed boundary edge (solved parametrically)
//! and its midpoint is inside the polygon (ray crossing parity), not by a
//! wedge test at its endpoint.

use crate::enumerate::canonical_triangle;
use crate::exact::{orient, scale, squared_length, to_rational, Point, Scaled};
use crate::symbolic::compare_lengths_perturbed;
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{Signed, Zero};
use rand::rngs::StdRng;
use rand::Rng;
use std::cmp::Ordering;
use std::collections::HashSet;

/// Largest ring [`polygon_triangulations`] accepts.
pub const MAX_POLYGON_ENUMERATION: usize = 12;

/// Ring coordinates scaled by one common power of two to integers and then
/// doubled, so that midpoints of vertices are integer points too. Scaling
/// by a positive constant preserves every sign and comparison below.
type Z = BigInt;
type ZPoint = [Z; 2];

fn integer_ring(ring: &[Point]) -> Vec<ZPoint> {
    let flat: Vec<f64> = ring.iter().flat_map(|p| [p[0], p[1]]).collect();
    let ints: Vec<Z> = match scale(&flat, 0).0 {
        Scaled::Small(v) => v.into_iter().map(Z::from).collect(),
        Scaled::Big(v) => v,
    };
    ints.chunks(2).map(|c| [&c[0] * 2, &c[1] * 2]).collect()
}

fn sub(a: &ZPoint, b: &ZPoint) -> ZPoint {
    [&a[0] - &b[0], &a[1] - &b[1]]
}

fn cross(u: &ZPoint, v: &ZPoint) -> Z {
    &u[0] * &v[1] - &u[1] * &v[0]
}

fn dot(u: &ZPoint, v: &ZPoint) -> Z {
    &u[0] * &v[0] + &u[1] * &v[1]
}

/// Is `num / den` (with `den > 0`) in the open interval (0, 1), or with
/// `closed` in [0, 1]?
fn in_unit(num: &Z, den: &Z, closed: bool) -> bool {
    if closed {
        !num.is_negative() && num <= den
    } else {
        num.is_positive() && num < den
    }
}

/// Does the segment `ab` (open or closed) meet the closed segment `uw`?
/// Solved as `a + t (b − a) = u + s (w − u)` (`t`, `s` as fractions with a
/// common positive denominator); collinear segments by projecting onto
/// `b − a`.
fn segment_meets(a: &ZPoint, b: &ZPoint, open: bool, u: &ZPoint, w: &ZPoint) -> bool {
    let (d, e, f) = (sub(b, a), sub(w, u), sub(u, a));
    let mut denom = cross(&d, &e);
    if !denom.is_zero() {
        let (mut t, mut s) = (cross(&f, &e), cross(&f, &d));
        if denom.is_negative() {
            denom = -denom;
            t = -t;
            s = -s;
        }
        return in_unit(&t, &denom, !open) && in_unit(&s, &denom, true);
    }
    if !cross(&f, &d).is_zero() {
        return false; // parallel lines
    }
    let len = dot(&d, &d);
    let tu = dot(&f, &d);
    let tw = dot(&sub(w, a), &d);
    let (lo, hi) = if tu <= tw { (tu, tw) } else { (tw, tu) };
    if open {
        hi.is_positive() && lo < len
    } else {
        !hi.is_negative() && lo <= len
    }
}

/// Is `ring` a simple polygon: at least three distinct points, consecutive
/// edges meeting only at their shared vertex, other edges not at all?
pub fn is_simple(ring: &[Point]) -> bool {
    let n = ring.len();
    if n < 3 {
        return false;
    }
    let r = integer_ring(ring);
    for i in 0..n {
        for j in i + 1..n {
            if r[i] == r[j] {
                return false;
            }
        }
    }
    for i in 0..n {
        let (a, b, c) = (&r[i], &r[(i + 1) % n], &r[(i + 2) % n]);
        // Consecutive edges ab, bc overlap iff they fold back along a line.
        let (u, v) = (sub(a, b), sub(c, b));
        if cross(&u, &v).is_zero() && dot(&u, &v).is_positive() {
            return false;
        }
    }
    for i in 0..n {
        for j in i + 1..n {
            if (i + 1) % n == j || (j + 1) % n == i {
                continue;
            }
            if segment_meets(&r[i], &r[(i + 1) % n], false, &r[j], &r[(j + 1) % n]) {
                return false;
            }
        }
    }
    true
}

/// Twice the signed area of the ring (shoelace), exact.
pub fn twice_signed_area(ring: &[Point]) -> BigRational {
    let n = ring.len();
    let r: Vec<[BigRational; 2]> = ring
        .iter()
        .map(|p| [to_rational(p[0]), to_rational(p[1])])
        .collect();
    (0..n).fold(BigRational::zero(), |acc, i| {
        let (p, q) = (&r[i], &r[(i + 1) % n]);
        acc + &p[0] * &q[1] - &p[1] * &q[0]
    })
}

/// The ring positions in counter-clockwise order, starting at 0.
pub fn counter_clockwise(ring: &[Point]) -> Vec<u32> {
    let n = ring.len() as u32;
    if twice_signed_area(ring).is_negative() {
        std::iter::once(0).chain((1..n).rev()).collect()
    } else {
        (0..n).collect()
    }
}

/// Is the point `m` strictly inside the ring (not on its boundary — the
/// caller guarantees that)? Crossing parity of the ray to `+x`, edges
/// counted half-open in `y`.
fn inside(r: &[ZPoint], m: &ZPoint) -> bool {
    let n = r.len();
    let mut odd = false;
    for i in 0..n {
        let (p, s) = (&r[i], &r[(i + 1) % n]);
        if (p[1] > m[1]) != (s[1] > m[1]) {
            // The crossing's x = p.x + (m.y − p.y)(s.x − p.x)/(s.y − p.y)
            // exceeds m.x iff num / den > 0.
            let den = &s[1] - &p[1];
            let num = (&p[0] - &m[0]) * &den + (&m[1] - &p[1]) * (&s[0] - &p[0]);
            if num.sign() == den.sign() && !num.is_zero() {
                odd = !odd;
            }
        }
    }
    odd
}

/// Is the chord between ring positions `a` and `b` a diagonal of the simple
/// polygon `ring`: is its open segment inside the open polygon? By
/// definition: it meets no closed boundary edge (so it is entirely inside or
/// entirely outside) and its midpoint is inside.
pub fn is_diagonal(ring: &[Point], a: usize, b: usize) -> bool {
    let n = ring.len();
    if a >= n || b >= n || a == b || (a + 1) % n == b || (b + 1) % n == a {
        return false;
    }
    let r = integer_ring(ring);
    diagonal_in(&r, a, b)
}

fn diagonal_in(r: &[ZPoint], a: usize, b: usize) -> bool {
    let n = r.len();
    if (0..n).any(|i| segment_meets(&r[a], &r[b], true, &r[i], &r[(i + 1) % n])) {
        return false;
    }
    // Coordinates are doubled, so the midpoint is an integer point.
    let mid = [(&r[a][0] + &r[b][0]) / 2, (&r[a][1] + &r[b][1]) / 2];
    inside(r, &mid)
}

/// Every diagonal `[a, b]`, `a < b`, of the simple polygon `ring`, sorted.
pub fn diagonals(ring: &[Point]) -> Vec<[u32; 2]> {
    let n = ring.len();
    let r = integer_ring(ring);
    let mut out = Vec::new();
    for a in 0..n {
        for b in a + 2..n {
            if !(a == 0 && b == n - 1) && diagonal_in(&r, a, b) {
                out.push([a as u32, b as u32]);
            }
        }
    }
    out
}

/// Do two diagonals conflict? Only by meeting away from a shared endpoint
/// (a diagonal's open segment holds no vertex, so sharing an endpoint is
/// fine).
fn conflict(r: &[ZPoint], s: [u32; 2], t: [u32; 2]) -> bool {
    if s[0] == t[0] || s[0] == t[1] || s[1] == t[0] || s[1] == t[1] {
        return false;
    }
    let p = |i: u32| &r[i as usize];
    segment_meets(p(s[0]), p(s[1]), true, p(t[0]), p(t[1]))
}

/// The triangles of a polygon triangulation given by its diagonals: every
/// 3-cycle of boundary edges and diagonals (a 3-cycle inside a polygon
/// without interior points bounds a face), canonical and sorted.
fn triangles_of(ring: &[Point], chosen: &[[u32; 2]]) -> Vec<[u32; 3]> {
    let n = ring.len() as u32;
    let mut edges: HashSet<[u32; 2]> = chosen.iter().copied().collect();
    for i in 0..n {
        let j = (i + 1) % n;
        edges.insert([i.min(j), i.max(j)]);
    }
    let has = |a: u32, b: u32| edges.contains(&[a.min(b), a.max(b)]);
    let mut tris = Vec::new();
    for a in 0..n {
        for b in a + 1..n {
            for c in b + 1..n {
                if has(a, b) && has(b, c) && has(a, c) {
                    tris.push(canonical_triangle(ring, [a, b, c]));
                }
            }
        }
    }
    tris.sort_unstable();
    assert_eq!(
        tris.len(),
        n as usize - 2,
        "optri-oracle: {} diagonals gave {} triangles in a {n}-gon",
        chosen.len(),
        tris.len()
    );
    tris
}

/// Every triangulation of the simple polygon `ring` (at most
/// [`MAX_POLYGON_ENUMERATION`] vertices): the maximal sets of pairwise
/// compatible diagonals (include/exclude search), each as canonical
/// triangles over ring positions (counter-clockwise, smallest first), sorted.
///
/// # Panics
/// On a ring that is not simple or too long.
pub fn polygon_triangulations(ring: &[Point]) -> Vec<Vec<[u32; 3]>> {
    assert!(
        ring.len() <= MAX_POLYGON_ENUMERATION,
        "optri-oracle: at most {MAX_POLYGON_ENUMERATION} vertices"
    );
    assert!(is_simple(ring), "optri-oracle: not a simple polygon");
    let r = integer_ring(ring);
    let diags = diagonals(ring);
    let m = diags.len();
    let crossers: Vec<Vec<usize>> = (0..m)
        .map(|s| {
            (0..m)
                .filter(|&t| conflict(&r, diags[s], diags[t]))
                .collect()
        })
        .collect();
    let mut all: Vec<Vec<[u32; 3]>> = crate::enumerate::maximal_compatible_sets(&crossers)
        .iter()
        .map(|set| {
            let chosen: Vec<[u32; 2]> = set.iter().map(|&s| diags[s]).collect();
            triangles_of(ring, &chosen)
        })
        .collect();
    all.sort();
    all
}

/// The greedy triangulation of the simple polygon `ring` by definition: its
/// diagonals shortest first (exact squared lengths, ties by the symbolic
/// perturbation of [`crate::symbolic`] with ring positions as ranks), each
/// kept unless it meets a kept one away from a shared endpoint. The kept
/// diagonals, `[min, max]`, sorted.
pub fn greedy_polygon_diagonals(ring: &[Point]) -> Vec<[u32; 2]> {
    let r = integer_ring(ring);
    let p = |i: u32| ring[i as usize];
    let mut diags: Vec<([u32; 2], BigRational)> = diagonals(ring)
        .into_iter()
        .map(|d| (d, squared_length(p(d[0]), p(d[1]))))
        .collect();
    diags.sort_by(|(s, ls), (t, lt)| {
        ls.cmp(lt)
            .then_with(|| match compare_lengths_perturbed(ring, *s, *t) {
                Ordering::Equal => s.cmp(t),
                o => o,
            })
    });
    let mut kept: Vec<[u32; 2]> = Vec::new();
    for (d, _) in diags {
        if kept.iter().all(|&e| !conflict(&r, d, e)) {
            kept.push(d);
        }
    }
    kept.sort_unstable();
    kept
}

// ---------------------------------------------------------------------------
// Generators: integer coordinates (exact in f64), each loop bounded.

/// Rejection sampling with a bound: `make` until it returns a simple ring.
fn simple_by_rejection(mut make: impl FnMut() -> Vec<Point>, what: &str) -> Vec<Point> {
    for _ in 0..1000 {
        let ring = make();
        if is_simple(&ring) {
            return ring;
        }
    }
    panic!("optri-oracle: no simple {what} in 1000 tries");
}

/// A random star-shaped polygon with `n ≥ 3` integer vertices, counter-
/// clockwise: one vertex per angular sector of `2π/n` around the origin, at
/// a random angle inside it and a random radius in `[radius/5, radius]`.
pub fn star_polygon(rng: &mut StdRng, n: usize, radius: f64) -> Vec<Point> {
    simple_by_rejection(
        || {
            (0..n)
                .map(|k| {
                    let a =
                        (k as f64 + rng.gen_range(0.15..0.85)) * std::f64::consts::TAU / n as f64;
                    let r = rng.gen_range(radius / 5.0..=radius);
                    [(r * a.cos()).round(), (r * a.sin()).round()]
                })
                .collect()
        },
        "star polygon",
    )
}

/// A random simple polygon on `n` distinct random integer points of
/// `[0, range)²` by 2-opt untangling: while two non-adjacent edges meet,
/// reverse the chain between them (strictly shortening the tour for a proper
/// crossing). Orientation is whatever the untangling gives.
pub fn two_opt_polygon(rng: &mut StdRng, n: usize, range: i64) -> Vec<Point> {
    simple_by_rejection(
        || {
            let mut seen = HashSet::new();
            let mut ring: Vec<Point> = Vec::with_capacity(n);
            while ring.len() < n {
                let p = [rng.gen_range(0..range), rng.gen_range(0..range)];
                if seen.insert(p) {
                    ring.push([p[0] as f64, p[1] as f64]);
                }
            }
            untangle(&mut ring, 20 * n * n);
            ring
        },
        "2-opt polygon",
    )
}

/// Do the closed segments `ab` and `cd` meet? Exact orientations; collinear
/// segments by their coordinate intervals.
fn closed_segments_meet(a: Point, b: Point, c: Point, d: Point) -> bool {
    let (o1, o2) = (orient(a, b, c), orient(a, b, d));
    let (o3, o4) = (orient(c, d, a), orient(c, d, b));
    if o1 * o2 > 0 || o3 * o4 > 0 {
        return false;
    }
    if o1 != 0 || o2 != 0 || o3 != 0 || o4 != 0 {
        return true;
    }
    (0..2).all(|k| a[k].min(b[k]) <= c[k].max(d[k]) && c[k].min(d[k]) <= a[k].max(b[k]))
}

/// 2-opt moves until no two non-adjacent edges meet, or `budget` moves.
fn untangle(ring: &mut [Point], budget: usize) {
    let n = ring.len();
    for _ in 0..budget {
        let mut found = None;
        'search: for i in 0..n {
            for j in i + 2..n {
                if i == 0 && j == n - 1 {
                    continue;
                }
                if closed_segments_meet(ring[i], ring[i + 1], ring[j], ring[(j + 1) % n]) {
                    found = Some((i, j));
                    break 'search;
                }
            }
        }
        match found {
            Some((i, j)) => ring[i + 1..=j].reverse(),
            None => return,
        }
    }
}

/// A comb with `teeth ≥ 1` teeth of random heights in `1..=max_height`
/// (counter-clockwise): a bar under teeth of width 1 with gaps of width 1.
pub fn comb(rng: &mut StdRng, teeth: usize, max_height: i64) -> Vec<Point> {
    let t = teeth as i64;
    let mut ring = vec![[0.0, -1.0], [(2 * t - 1) as f64, -1.0]];
    for i in (0..t).rev() {
        let h = rng.gen_range(1..=max_height) as f64;
        ring.push([(2 * i + 1) as f64, h]);
        ring.push([(2 * i) as f64, h]);
        if i > 0 {
            ring.push([(2 * i) as f64, 0.0]);
            ring.push([(2 * i - 1) as f64, 0.0]);
        }
    }
    assert!(is_simple(&ring));
    ring
}

/// A polygonal spiral band (counter-clockwise): the outer arm
/// `r = 1 + θ/2π` for `θ ∈ [0, 2π·turns]`, `steps` points per turn, back
/// along the inner arm `r − 0.5`, scaled by `scale` and rounded.
pub fn spiral(turns: f64, steps: usize, scale: f64) -> Vec<Point> {
    let total = (turns * steps as f64).round() as usize;
    let at = |k: usize, offset: f64| {
        let a = k as f64 * std::f64::consts::TAU / steps as f64;
        let r = (1.0 + a / std::f64::consts::TAU - offset) * scale;
        [(r * a.cos()).round(), (r * a.sin()).round()]
    };
    let mut ring: Vec<Point> = (0..=total).map(|k| at(k, 0.0)).collect();
    ring.extend((0..=total).rev().map(|k| at(k, 0.5)));
    ring.dedup();
    assert!(
        is_simple(&ring),
        "optri-oracle: spiral not simple; use a larger scale"
    );
    ring
}

/// The ring scaled by 6 with, on each edge with probability `p`, 1, 2 or 5
/// extra vertices at the halves, thirds or sixths: straight (180°) vertices,
/// exactly on the edge.
pub fn with_straight_vertices(rng: &mut StdRng, ring: &[Point], p: f64) -> Vec<Point> {
    let n = ring.len();
    let mut out = Vec::new();
    for i in 0..n {
        let (a, b) = (ring[i], ring[(i + 1) % n]);
        let (a, b) = ([6.0 * a[0], 6.0 * a[1]], [6.0 * b[0], 6.0 * b[1]]);
        out.push(a);
        if rng.gen_bool(p) {
            let parts = [2, 3, 6][rng.gen_range(0..3)];
            for k in 1..parts {
                let t = k as f64 / parts as f64;
                out.push([a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t]);
            }
        }
    }
    assert!(is_simple(&out));
    out
}

/// A histogram polygon (counter-clockwise): every lattice point of the
/// bottom edge `[0, columns] × {0}`, then columns of width 1 and random
/// heights in `1..=max_height`; with `lattice`, every lattice point of the
/// top and side edges too. Many straight vertices and equal lengths and areas.
pub fn histogram(rng: &mut StdRng, columns: usize, max_height: i64, lattice: bool) -> Vec<Point> {
    let w = columns as i64;
    let h: Vec<i64> = (0..w).map(|_| rng.gen_range(1..=max_height)).collect();
    let mut corners: Vec<[i64; 2]> = (0..=w).map(|x| [x, 0]).collect();
    for x in (1..=w).rev() {
        corners.push([x, h[x as usize - 1]]);
        corners.push([x - 1, h[x as usize - 1]]);
    }
    corners.dedup();
    let mut ring: Vec<[i64; 2]> = Vec::new();
    let m = corners.len();
    for i in 0..m {
        let (a, b) = (corners[i], corners[(i + 1) % m]);
        ring.push(a);
        if lattice && i >= w as usize {
            // axis-parallel edges: add the lattice points strictly between
            let steps = (b[0] - a[0]).abs().max((b[1] - a[1]).abs());
            for s in 1..steps {
                ring.push([
                    a[0] + (b[0] - a[0]) / steps * s,
                    a[1] + (b[1] - a[1]) / steps * s,
                ]);
            }
        }
    }
    let ring: Vec<Point> = ring.iter().map(|p| [p[0] as f64, p[1] as f64]).collect();
    assert!(is_simple(&ring), "optri-oracle: histogram not simple");
    ring
}

/// The boundary lattice points of the square `[0, side]²`, counter-clockwise:
/// convex with `4 (side − 1)` straight vertices.
pub fn lattice_square(side: i64) -> Vec<Point> {
    let mut ring = Vec::new();
    for x in 0..side {
        ring.push([x, 0]);
    }
    for y in 0..side {
        ring.push([side, y]);
    }
    for x in (1..=side).rev() {
        ring.push([x, side]);
    }
    for y in (1..=side).rev() {
        ring.push([0, y]);
    }
    ring.iter().map(|p| [p[0] as f64, p[1] as f64]).collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::klincsek::{klincsek, MinMaxArea};
    use rand::SeedableRng;

    const SEED: u64 = 0x9017_60a1;

    #[test]
    fn convex_polygons_have_catalan_many_triangulations() {
        let catalan = [1usize, 1, 2, 5, 14, 42, 132, 429, 1430, 4862, 16796];
        for n in 3..=10 {
            let ring: Vec<Point> = (0..n)
                .map(|k| {
                    let a = k as f64 * std::f64::consts::TAU / n as f64;
                    [(1000.0 * a.cos()).round(), (1000.0 * a.sin()).round()]
                })
                .collect();
            assert_eq!(diagonals(&ring).len(), n * (n - 3) / 2);
            assert_eq!(
                polygon_triangulations(&ring).len(),
                catalan[n - 2],
                "n = {n}"
            );
        }
    }

    #[test]
    fn an_l_shape_and_a_straight_vertex() {
        // L-shape: the reflex corner 3 sees everything, 1-3 goes outside.
        let l = [
            [0.0, 0.0],
            [2.0, 0.0],
            [2.0, 1.0],
            [1.0, 1.0],
            [1.0, 2.0],
            [0.0, 2.0],
        ];
        assert!(is_simple(&l));
        assert_eq!(diagonals(&l), vec![[0, 2], [0, 3], [0, 4], [1, 3], [3, 5]]);
        assert!(!is_diagonal(&l, 2, 4));
        assert_eq!(polygon_triangulations(&l).len(), 4);
        // A straight vertex: 0-2 runs along the boundary through 1.
        let t = [[0.0, 0.0], [1.0, 0.0], [2.0, 0.0], [1.0, 1.0]];
        assert_eq!(diagonals(&t), vec![[1, 3]]);
        let r: Vec<Point> = t.iter().rev().copied().collect();
        assert!(twice_signed_area(&r).is_negative());
        assert_eq!(counter_clockwise(&r), vec![0, 3, 2, 1]);
    }

    #[test]
    fn not_simple_rings_are_recognised() {
        assert!(!is_simple(&[
            [0.0, 0.0],
            [1.0, 1.0],
            [1.0, 0.0],
            [0.0, 1.0]
        ]));
        assert!(!is_simple(&[
            [0.0, 0.0],
            [2.0, 0.0],
            [1.0, 0.0],
            [1.0, 1.0]
        ]));
        assert!(!is_simple(&[
            [0.0, 0.0],
            [4.0, 0.0],
            [4.0, 4.0],
            [2.0, 0.0],
            [0.0, 4.0]
        ]));
        assert!(!is_simple(&[[0.0, 0.0], [1.0, 0.0], [2.0, 0.0]]));
    }

    #[test]
    fn generators_give_simple_polygons_and_enumeration_agrees_with_klincsek() {
        let mut rng = StdRng::seed_from_u64(SEED);
        let mut cases = 0;
        for n in 4..=9 {
            for ring in [
                star_polygon(&mut rng, n, 50.0),
                two_opt_polygon(&mut rng, n, 20),
                histogram(&mut rng, n / 3, 4, false),
            ] {
                let ccw = counter_clockwise(&ring);
                let all = polygon_triangulations(&ring);
                let best = all
                    .iter()
                    .map(|t| crate::enumerate::max_twice_area(&ring, t))
                    .min()
                    .unwrap();
                let (value, _) = klincsek(&ring, &ccw, MinMaxArea).unwrap();
                assert_eq!(value, best, "{ring:?}");
                cases += 1;
            }
        }
        assert_eq!(cases, 18);
        assert!(is_simple(&comb(&mut rng, 4, 5)));
        assert!(is_simple(&spiral(2.5, 12, 40.0)));
        assert!(is_simple(&lattice_square(3)));
    }
}
