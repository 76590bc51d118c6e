//! The general minimum-weight pipeline's edge sets against brute-force
//! references written from their definitions:
//!
//! - **diamond candidates**: every pair `uv` for which at least one of the
//!   two isosceles triangles on `uv` with the exact test's base angle
//!   (`angle_below_diamond` at both ends, strict side by `orient_sign`) holds
//!   no other point, every point of the set tested (no grid, no search, no
//!   dead sectors);
//! - **LMT-skeleton**: the empty candidate triangles (closed triangle, all
//!   points tested), the loop repeated over all edges until nothing changes
//!   (the removal is monotone, so the fixed point is unique whatever the
//!   order), and the certain edges: left edges that meet no other left edge
//!   except at a shared endpoint, or convex-hull edges.
//!
//! Inputs: uniform random, clustered, integer lattices with duplicates,
//! full and partial grids, cocircular integer points (with and without their
//! centre), collinear runs, and huge, tiny and negative coordinates.

use optri::internals::kernel::angle_below_diamond;
use optri::internals::kernel::dot_sign;
use optri::internals::min_weight_skeleton_edges;
use optri::kernel::{compare_lengths, orient_sign, properly_cross, Point};
use optri::PointSet;
use optri_oracle::inputs::{
    clustered, collinear_runs, grid, grid_subset, integer_circle_points, lattice_points,
    uniform_in_square,
};
use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};
use std::cmp::Ordering;

/// The pairs `u < v` passing the exact diamond test, by brute force.
fn candidates_reference(pts: &[Point]) -> Vec<[u32; 2]> {
    let n = pts.len();
    let mut out = Vec::new();
    for u in 0..n {
        for v in u + 1..n {
            let (a, b) = (pts[u], pts[v]);
            let (mut left, mut right) = (false, false);
            for (r, &c) in pts.iter().enumerate() {
                if r == u || r == v {
                    continue;
                }
                let inside = angle_below_diamond(a, b, c) && angle_below_diamond(b, a, c);
                match orient_sign(a, b, c) {
                    1 => left |= inside,
                    -1 => right |= inside,
                    _ => {}
                }
            }
            if !(left && right) {
                out.push([u as u32, v as u32]);
            }
        }
    }
    out
}

fn in_closed_triangle(a: Point, b: Point, c: Point, d: Point) -> bool {
    orient_sign(a, b, d) >= 0 && orient_sign(b, c, d) >= 0 && orient_sign(c, a, d) >= 0
}

/// Closed segments `ab`, `cd` with disjoint endpoints share a point.
fn closed_segments_meet(a: Point, b: Point, c: Point, d: Point) -> bool {
    let (o1, o2, o3, o4) = (
        orient_sign(a, b, c),
        orient_sign(a, b, d),
        orient_sign(c, d, a),
        orient_sign(c, d, b),
    );
    if o1 * o2 < 0 && o3 * o4 < 0 {
        return true;
    }
    // A point on the other closed segment (collinear and between).
    let on = |p: Point, q: Point, z: Point| orient_sign(p, q, z) == 0 && dot_sign(z, p, q) <= 0;
    on(a, b, c) || on(a, b, d) || on(c, d, a) || on(c, d, b)
}

/// Do candidate edges `e` and `f` (distinct) meet other than in one shared
/// endpoint? Two edges from a common endpoint conflict when they overlap.
fn conflict(pts: &[Point], e: [u32; 2], f: [u32; 2]) -> bool {
    let p = |i: u32| pts[i as usize];
    match e.iter().find(|x| f.contains(x)) {
        None => closed_segments_meet(p(e[0]), p(e[1]), p(f[0]), p(f[1])),
        Some(&s) => {
            let u = if e[0] == s { e[1] } else { e[0] };
            let v = if f[0] == s { f[1] } else { f[0] };
            orient_sign(p(s), p(u), p(v)) == 0 && dot_sign(p(s), p(u), p(v)) > 0
        }
    }
}

/// Edge `uv` between consecutive points of the convex hull (points on hull
/// edges are hull points): every point on one closed side, none on the open
/// segment.
fn hull_edge(pts: &[Point], [u, v]: [u32; 2]) -> bool {
    let (a, b) = (pts[u as usize], pts[v as usize]);
    let (mut pos, mut neg) = (false, false);
    for (r, &c) in pts.iter().enumerate() {
        if r == u as usize || r == v as usize {
            continue;
        }
        match orient_sign(a, b, c) {
            1 => pos = true,
            -1 => neg = true,
            _ if dot_sign(c, a, b) < 0 => return false,
            _ => {}
        }
    }
    !(pos && neg)
}

/// The edges left by the LMT loop and the certain edges, by brute force
/// from the candidate edges.
fn skeleton_reference(pts: &[Point], edges: &[[u32; 2]]) -> (Vec<[u32; 2]>, Vec<[u32; 2]>) {
    let n = pts.len();
    let mut id = vec![vec![usize::MAX; n]; n];
    for (k, &[u, v]) in edges.iter().enumerate() {
        id[u as usize][v as usize] = k;
        id[v as usize][u as usize] = k;
    }
    // Empty candidate triangles (counter-clockwise corners, edge ids).
    let mut triangles: Vec<([u32; 3], [usize; 3])> = Vec::new();
    for u in 0..n {
        for v in u + 1..n {
            for w in v + 1..n {
                let ids = [id[u][v], id[v][w], id[u][w]];
                if ids.contains(&usize::MAX) {
                    continue;
                }
                let o = orient_sign(pts[u], pts[v], pts[w]);
                let c = match o {
                    1 => [u, v, w],
                    -1 => [u, w, v],
                    _ => continue,
                };
                let empty = (0..n).all(|r| {
                    c.contains(&r) || !in_closed_triangle(pts[c[0]], pts[c[1]], pts[c[2]], pts[r])
                });
                if empty {
                    triangles.push((c.map(|x| x as u32), ids));
                }
            }
        }
    }
    let hull: Vec<bool> = edges.iter().map(|&e| hull_edge(pts, e)).collect();
    let mut alive = vec![true; edges.len()];
    loop {
        let mut changed = false;
        for (k, &[u, v]) in edges.iter().enumerate() {
            if !alive[k] || hull[k] {
                continue;
            }
            let (a, b) = (pts[u as usize], pts[v as usize]);
            // Apexes of the live triangles on each side of u → v.
            let mut sides: [Vec<Point>; 2] = [Vec::new(), Vec::new()];
            for (c, ids) in &triangles {
                if !ids.contains(&k) || !ids.iter().all(|&f| alive[f]) {
                    continue;
                }
                let apex = *c.iter().find(|&&x| x != u && x != v).unwrap();
                let r = pts[apex as usize];
                sides[(orient_sign(a, b, r) < 0) as usize].push(r);
            }
            let minimal = sides[0].iter().any(|&r| {
                sides[1].iter().any(|&s| {
                    !properly_cross(a, b, r, s) || compare_lengths(a, b, r, s) != Ordering::Greater
                })
            });
            if !minimal {
                alive[k] = false;
                changed = true;
            }
        }
        if !changed {
            break;
        }
    }
    let left: Vec<usize> = (0..edges.len()).filter(|&k| alive[k]).collect();
    let certain = left
        .iter()
        .filter(|&&k| {
            hull[k]
                || left
                    .iter()
                    .all(|&f| f == k || !conflict(pts, edges[k], edges[f]))
        })
        .map(|&k| edges[k])
        .collect();
    (left.iter().map(|&k| edges[k]).collect(), certain)
}

/// Compares the pipeline's three edge sets with the references; returns
/// the number of candidates (so callers can see the inputs are not trivial).
fn check(input: &[Point], what: &str) -> usize {
    let Ok(ps) = PointSet::new(input) else {
        return 0; // all collinear: not a min-weight input
    };
    let pts = ps.points();
    // One edge per task of the parallel LMT loop: the threads interleave
    // the most.
    let [candidates, left, certain] = min_weight_skeleton_edges(&ps, 1);
    let expected = candidates_reference(pts);
    assert_eq!(candidates, expected, "{what}: diamond candidates differ");
    let (expected_left, expected_certain) = skeleton_reference(pts, &expected);
    assert_eq!(
        left, expected_left,
        "{what}: edges left by the LMT loop differ"
    );
    assert_eq!(certain, expected_certain, "{what}: certain edges differ");
    candidates.len()
}

fn scaled(pts: &[Point], scale: f64, shift: Point) -> Vec<Point> {
    pts.iter()
        .map(|p| [p[0] * scale + shift[0], p[1] * scale + shift[1]])
        .collect()
}

#[test]
fn random_sets_match_the_brute_force_sets() {
    let mut rng = StdRng::seed_from_u64(120);
    let mut total = 0;
    for round in 0..60 {
        let n = rng.gen_range(4..48);
        let pts = match round % 3 {
            0 => uniform_in_square(&mut rng, n, 1.0),
            1 => clustered(&mut rng, n, 3),
            _ => lattice_points(&mut rng, n, -6..6, -6..6),
        };
        total += check(&pts, &format!("round {round}"));
        // The same set far from the origin, huge and tiny.
        for (scale, shift) in [(1e12, [-3e15, 7e14]), (1e-9, [-1.0, 0.5])] {
            total += check(
                &scaled(&pts, scale, shift),
                &format!("round {round} scaled"),
            );
        }
    }
    assert!(total > 3000, "only {total} candidates in all");
}

#[test]
fn degenerate_sets_match_the_brute_force_sets() {
    let mut rng = StdRng::seed_from_u64(121);
    for (w, h) in [(2, 2), (3, 3), (4, 5), (7, 3), (6, 6)] {
        check(&grid(w, h, 1.0), &format!("grid {w}x{h}"));
        check(&grid_subset(&mut rng, w + 1, h + 1, 0.7), "grid subset");
    }
    for r in [5, 25, 65] {
        let mut circle = integer_circle_points(r);
        check(&circle, &format!("circle {r}"));
        circle.push([0.0, 0.0]);
        check(&circle, &format!("circle {r} with centre"));
        check(&scaled(&circle, -1e10, [1e16, -1e16]), "circle scaled");
    }
    for round in 0..30 {
        let pts = collinear_runs(&mut rng, 1..4, 2..9, 0..6);
        check(&pts, &format!("collinear runs {round}"));
    }
}

/// The parallel LMT loop (tasks of 1 and 64 edges, threads sharing the
/// triangle states) leaves exactly the sequential loop's edges, on sets far
/// beyond the brute force's reach, where many removals cascade across tasks.
#[test]
fn the_parallel_loop_leaves_the_sequential_loops_edges() {
    let mut rng = StdRng::seed_from_u64(122);
    let mut circle = integer_circle_points(325);
    circle.push([0.0, 0.0]);
    let sets: Vec<(&str, Vec<Point>)> = vec![
        ("uniform", uniform_in_square(&mut rng, 4000, 1.0)),
        ("clustered", clustered(&mut rng, 4000, 12)),
        ("grid subset", grid_subset(&mut rng, 60, 60, 0.8)),
        ("lattice", lattice_points(&mut rng, 3000, -40..40, -40..40)),
        ("circle with centre", circle),
    ];
    for (what, pts) in sets {
        let ps = PointSet::new(&pts).unwrap();
        let sequential = min_weight_skeleton_edges(&ps, usize::MAX);
        let [candidates, left, _] = &sequential;
        assert!(
            candidates.len() > left.len() + 500,
            "{what}: only {} candidates removed",
            candidates.len() - left.len()
        );
        for chunk in [1, 1, 64] {
            let parallel = min_weight_skeleton_edges(&ps, chunk);
            assert_eq!(parallel, sequential, "{what}: chunk {chunk}");
        }
    }
}
