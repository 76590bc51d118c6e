//! Minimum-weight triangulation of a general point set by integer
//! programming over its empty triangles — the reference for sets far beyond
//! exhaustive enumeration (tens of points), independent of optri.
//!
//! The model is the triangle formulation of the minimum-weight triangulation
//! (Kyoda, Imai, Takeuchi and Tajima 1997, "A branch-and-cut approach for
//! minimum weight triangulation", ISAAC '97, §2; the polytope is studied by
//! De Loera, Hoşten, Santos and Sturmfels 1996, "The polytope of all
//! triangulations of a point configuration"): one 0/1 variable `x_t` per
//! *empty* triangle `t` (three points, not collinear, no other point inside
//! or on a side), and one equation per *empty segment* `e` (no third point on
//! the closed segment):
//!
//! - `e` on the convex hull: `Σ_{t ∋ e} x_t = 1`;
//! - otherwise: `Σ_{t ∋ e, t left of e} x_t = Σ_{t ∋ e, t right of e} x_t`.
//!
//! **Why the integer points are exactly the triangulations.** Let `f(p)` be
//! the number of chosen triangles covering a point `p` of the plane. Two
//! distinct empty segments never overlap (a partial overlap of collinear
//! segments puts an endpoint of one inside the other), and no empty triangle
//! has a point of the set inside a side, so on a path crossing the relative
//! interior of a segment `e` at a generic point, `f` changes only by the
//! triangles with side `e`: by `Σ_right − Σ_left`, which the equations make
//! zero for every segment off the hull. `f` is `0` outside the hull and, by
//! the hull equations, `1` just inside each hull edge; the hull's interior
//! minus finitely many points is connected, so `f = 1` almost everywhere in
//! it: the chosen triangles are interior-disjoint and cover the hull. Every
//! point of the set lies in some chosen closed triangle, which, being empty,
//! has it as a vertex; and no vertex lies inside another's side. So the
//! chosen triangles triangulate the set; conversely every triangulation
//! meets the equations (each inner edge has one triangle on each side).
//!
//! **Objective.** A triangle's weight is the length of its hull sides plus
//! half the length of its other sides: every inner edge of a triangulation
//! lies in two triangles, every hull edge in one, so the sum over the chosen
//! triangles is the total edge length. The program is solved by `microlp`
//! (branch and bound on a floating-point simplex); its answer is then
//! *re-checked here*, exactly: the rounded 0/1 solution must meet every
//! equation in integers, have `2n − h − 2` triangles (`h` points on the hull
//! boundary) and their exact areas must add up to the hull's. The returned
//! weight is the sum of the `f64` edge lengths of that triangulation
//! ([`total_length`]), so it compares with other weights computed the same
//! way; its optimality holds up to the solver's floating-point tolerances
//! (relative `1e-12` pruning here), not exactly.

use crate::enumerate::total_length;
use crate::exact::{dot_sign, orient, twice_area, Point};
use num_rational::BigRational;
use num_traits::Zero;
use std::collections::HashMap;

/// The result of [`min_weight_ilp`].
#[derive(Clone, Debug)]
pub struct IlpTriangulation {
    /// Total edge length of [`Self::triangles`] (sum of `f64` lengths).
    pub weight: f64,
    /// The triangles, counter-clockwise with the smallest index first, sorted.
    pub triangles: Vec<[u32; 3]>,
    /// Number of empty triangles (variables of the program).
    pub empty_triangles: usize,
    /// Number of empty segments carrying an equation.
    pub equations: usize,
    /// Branch-and-bound nodes the solver explored (0: the relaxation was integral).
    pub nodes: u64,
}

/// Exact orientations of all triples, `o[(i·n + j)·n + k] = orient(pᵢ, pⱼ, pₖ)`.
fn orientation_table(points: &[Point]) -> Vec<i8> {
    let n = points.len();
    let mut o = vec![0i8; n * n * n];
    for i in 0..n {
        for j in i + 1..n {
            for k in j + 1..n {
                let s = orient(points[i], points[j], points[k]) as i8;
                // Even permutations keep the sign, odd ones flip it.
                for (a, b, c, v) in [
                    (i, j, k, s),
                    (j, k, i, s),
                    (k, i, j, s),
                    (j, i, k, -s),
                    (i, k, j, -s),
                    (k, j, i, -s),
                ] {
                    o[(a * n + b) * n + c] = v;
                }
            }
        }
    }
    o
}

/// The minimum-weight triangulation of the distinct points `points` by the
/// integer program of the module documentation, re-checked; `None` when the
/// points do not span the plane (fewer than three, or all collinear).
///
/// Practical up to about a hundred points in general position (the number of
/// empty triangles of a uniform random set grows like `2n²`); lattice sets
/// have many more empty triangles.
///
/// # Panics
/// On coincident points, when the solver fails or does not prove optimality,
/// or when its answer fails the exact re-check.
pub fn min_weight_ilp(points: &[Point]) -> Option<IlpTriangulation> {
    let n = points.len();
    for i in 0..n {
        for j in i + 1..n {
            assert!(
                points[i] != points[j],
                "optri-oracle: points {i} and {j} coincide"
            );
        }
    }
    if n < 3 {
        return None;
    }
    let o = orientation_table(points);
    let or = |a: usize, b: usize, c: usize| o[(a * n + b) * n + c];
    // Empty segments: no third point on the closed segment (collinear with
    // it and strictly between its ends). Hull segments: no point strictly
    // on one of their sides.
    let mut segment: HashMap<(usize, usize), usize> = HashMap::new();
    let mut on_hull: Vec<bool> = Vec::new();
    let mut ends: Vec<(usize, usize)> = Vec::new();
    for i in 0..n {
        for j in i + 1..n {
            // k strictly between i and j on their line: (pᵢ − pₖ)·(pⱼ − pₖ) < 0.
            let between = (0..n).any(|k| {
                k != i
                    && k != j
                    && or(i, j, k) == 0
                    && dot_sign(points[k], points[i], points[j]) < 0
            });
            if between {
                continue;
            }
            let left = (0..n).any(|k| or(i, j, k) > 0);
            let right = (0..n).any(|k| or(i, j, k) < 0);
            segment.insert((i, j), ends.len());
            ends.push((i, j));
            on_hull.push(!(left && right));
        }
    }
    if (0..n).all(|k| or(0, 1, k) == 0) {
        return None; // all collinear
    }
    let seg = |a: usize, b: usize| segment.get(&(a.min(b), a.max(b))).copied();
    let length = |a: usize, b: usize| {
        let (p, q) = (points[a], points[b]);
        (p[0] - q[0]).hypot(p[1] - q[1])
    };
    // Empty triangles, counter-clockwise: i < j < k or the reverse turn.
    let mut triangles: Vec<[u32; 3]> = Vec::new();
    for i in 0..n {
        for j in i + 1..n {
            let Some(_) = seg(i, j) else { continue };
            for k in j + 1..n {
                let s = or(i, j, k);
                if s == 0 || seg(j, k).is_none() || seg(i, k).is_none() {
                    continue;
                }
                // The sides are empty segments; no point strictly inside.
                let inside =
                    (0..n).any(|m| or(i, j, m) == s && or(j, k, m) == s && or(k, i, m) == s);
                if !inside {
                    let t = if s > 0 { [i, j, k] } else { [i, k, j] };
                    triangles.push(t.map(|v| v as u32));
                }
            }
        }
    }
    // Objective scaled to the longest segment (keeps the solver's numbers
    // near 1; the reported weight is recomputed from the edges).
    let scale = ends
        .iter()
        .map(|&(a, b)| length(a, b))
        .fold(0.0f64, f64::max);
    let mut problem = microlp::Problem::new(microlp::OptimizationDirection::Minimize);
    // rows[e]: (variable, +1 if the triangle is left of e = (min, max), else −1).
    let mut rows: Vec<Vec<(microlp::Variable, f64)>> = vec![Vec::new(); ends.len()];
    let mut vars = Vec::with_capacity(triangles.len());
    for t in &triangles {
        let t = t.map(|v| v as usize);
        let sides = [(t[0], t[1]), (t[1], t[2]), (t[2], t[0])];
        let w: f64 = sides
            .iter()
            .map(|&(a, b)| {
                let e = seg(a, b).unwrap();
                length(a, b) * if on_hull[e] { 1.0 } else { 0.5 }
            })
            .sum();
        let v = problem.add_binary_var(w / scale);
        vars.push(v);
        for (a, b) in sides {
            // Counter-clockwise: the triangle is left of (a, b).
            let e = seg(a, b).unwrap();
            rows[e].push((v, if a < b { 1.0 } else { -1.0 }));
        }
    }
    let mut equations = 0;
    for (e, row) in rows.iter().enumerate() {
        if on_hull[e] {
            let ones: Vec<(microlp::Variable, f64)> = row.iter().map(|&(v, _)| (v, 1.0)).collect();
            problem.add_constraint(ones, microlp::ComparisonOp::Eq, 1.0);
        } else if !row.is_empty() {
            problem.add_constraint(row.clone(), microlp::ComparisonOp::Eq, 0.0);
        } else {
            continue;
        }
        equations += 1;
    }
    let mut options = microlp::SolveOptions::default();
    // Prune only nodes that cannot beat the incumbent by more than 1e-12
    // (relative), so that the optimum is met to well within 1e-9.
    options.tolerances.prune_epsilon = 1e-12;
    let outcome = problem
        .solve_with(options)
        .unwrap_or_else(|e| panic!("optri-oracle: the MWT program failed: {e}"));
    assert!(
        outcome.is_optimal(),
        "optri-oracle: the MWT program stopped without proving optimality"
    );
    let nodes = outcome.stats().nodes_solved;
    let solution = outcome.into_solution().unwrap();
    let mut chosen: Vec<[u32; 3]> = Vec::new();
    let mut count = vec![0i64; ends.len()];
    for (t, &v) in triangles.iter().zip(&vars) {
        let x = solution.var_value(v);
        let r = x.round();
        assert!(
            (x - r).abs() < 1e-6 && (r == 0.0 || r == 1.0),
            "optri-oracle: non-binary value {x}"
        );
        if r == 1.0 {
            chosen.push(*t);
            let t = t.map(|v| v as usize);
            for (a, b) in [(t[0], t[1]), (t[1], t[2]), (t[2], t[0])] {
                count[seg(a, b).unwrap()] += if a < b { 1 } else { -1 };
            }
        }
    }
    // Exact re-check of the equations on the rounded solution: hull edges
    // once (a counter-clockwise triangle on the inner side), inner segments
    // balanced.
    for (e, &(a, b)) in ends.iter().enumerate() {
        if on_hull[e] {
            let inner = if (0..n).any(|k| or(a, b, k) > 0) {
                1
            } else {
                -1
            };
            assert_eq!(
                count[e], inner,
                "optri-oracle: hull edge {a}-{b} not covered once"
            );
        } else {
            assert_eq!(count[e], 0, "optri-oracle: segment {a}-{b} unbalanced");
        }
    }
    let hull_points = (0..n)
        .filter(|&p| {
            ends.iter()
                .enumerate()
                .any(|(e, &(a, b))| on_hull[e] && (a == p || b == p))
        })
        .count();
    assert_eq!(
        chosen.len(),
        2 * n - hull_points - 2,
        "optri-oracle: wrong number of triangles"
    );
    // Areas: the triangles add up to the hull (fan of its boundary points
    // around the lowest-index hull point).
    let area = |t: &[u32; 3]| {
        twice_area(
            points[t[0] as usize],
            points[t[1] as usize],
            points[t[2] as usize],
        )
    };
    let total: BigRational = chosen
        .iter()
        .map(area)
        .fold(BigRational::zero(), |s, a| s + a);
    let hull_area = hull_twice_area(points, &ends, &on_hull);
    assert_eq!(
        total, hull_area,
        "optri-oracle: the triangles do not tile the hull"
    );
    chosen.sort_unstable();
    Some(IlpTriangulation {
        weight: total_length(points, &chosen),
        triangles: chosen,
        empty_triangles: triangles.len(),
        equations,
        nodes,
    })
}

/// Twice the hull's area, exactly: the hull edges form one cycle; the
/// shoelace sum of its consecutive vertices from the first.
fn hull_twice_area(points: &[Point], ends: &[(usize, usize)], on_hull: &[bool]) -> BigRational {
    let mut next: HashMap<usize, Vec<usize>> = HashMap::new();
    for (e, &(a, b)) in ends.iter().enumerate() {
        if on_hull[e] {
            next.entry(a).or_default().push(b);
            next.entry(b).or_default().push(a);
        }
    }
    let start = *next.keys().min().unwrap();
    let mut cycle = vec![start];
    let mut prev = usize::MAX;
    loop {
        let cur = *cycle.last().unwrap();
        let nb = next[&cur].iter().copied().find(|&v| v != prev).unwrap();
        if nb == start {
            break;
        }
        prev = cur;
        cycle.push(nb);
    }
    assert_eq!(
        cycle.len(),
        next.len(),
        "optri-oracle: hull is not one cycle"
    );
    let p0 = points[cycle[0]];
    (1..cycle.len() - 1)
        .map(|i| twice_area(p0, points[cycle[i]], points[cycle[i + 1]]))
        .fold(BigRational::zero(), |s, a| s + a)
}
