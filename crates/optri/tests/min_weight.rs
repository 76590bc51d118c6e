//! Minimum-weight triangulation of convex inputs against the exhaustive
//! oracle (n ≤ 9) and the oracle's Klincsek DP; the greedy triangulation
//! against the oracle's independent greedy; the approximation ratio.
//!
//! Inputs are in convex position *by construction*
//! ([`optri_oracle::inputs::convex_by_construction`]: integer points on a
//! parabola, on a lens of two parabolas, with or without integer midpoints
//! of hull edges as collinear boundary points), or rounded circle points that
//! are regenerated until the oracle's exact hull contains them all; every
//! generated input is checked, none skipped.
//!
//! **Weights** are sums of square roots; optri and the oracle both add
//! rounded `f64` lengths (relative error below `(E + 1)·2^-52`, under 10⁻¹³
//! here), so weights are compared with the relative tolerance
//! [`TOLERANCE`] = 10⁻¹², and only weights. **Triangles** are compared
//! exactly whenever the oracle certifies the optimum unique beyond that
//! tolerance ([`optri_oracle::klincsek_unique`], or for n ≤ 9 a single
//! triangulation within the tolerance in the exhaustive enumeration).

use optri::kernel::Point;
use optri::{triangulate, Criterion, PointSet};
use optri_oracle::inputs::{
    convex_by_construction, lattice_points, rounded_circle,
    ConvexShape::{Lens, Parabola},
};
use optri_oracle::{
    all_triangulations, canonical_triangulation, convex_hull_edges, klincsek, klincsek_unique,
    optimum_by, orient, total_length, MinWeight, TotalF64,
};
use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};

/// Relative tolerance on weights (see the module docs).
const TOLERANCE: f64 = 1e-12;

const SEED_EXHAUSTIVE_SMALL_CONVEX: u64 = 11;
const SEED_ORACLE_DP: u64 = 12;
const SEED_KLINCSEK_PLAIN_FORM: u64 = 14;
const SEED_GREEDY_SMALL_SETS: u64 = 13;

/// Triangles of a triangulation as distinct indices.
fn distinct_triangles(ps: &PointSet, t: &optri::Triangulation) -> Vec<[u32; 3]> {
    t.triangles()
        .iter()
        .map(|tri| tri.map(|i| ps.distinct_index(i)))
        .collect()
}

fn relative_eq(a: f64, b: f64) -> bool {
    (a - b).abs() <= TOLERANCE * a.abs().max(b.abs())
}

/// Integer-rounded points on a circle, regenerated until all of them are on
/// the oracle's exact convex hull (collinear boundary points allowed).
fn rounded_circle_in_convex_position(rng: &mut StdRng, n: usize) -> Vec<Point> {
    for _ in 0..1000 {
        // Rounding by ≤ 0.5 must not undo the curvature between close
        // neighbours (angle gaps down to about 1/n²): radius ~ n⁴.
        let r = rng.gen_range(0.05..1.0) * (n as f64).powi(4).max(200.0);
        let pts = rounded_circle(rng, n, r);
        let Ok(ps) = PointSet::new(&pts) else {
            continue;
        };
        if convex_hull_edges(ps.points()).len() == ps.len() {
            return pts;
        }
    }
    panic!("no rounded circle in convex position with {n} points");
}

/// The points as a counter-clockwise polygon, from the oracle's hull edges
/// (every point must be a hull vertex, collinear ones included).
fn oracle_polygon(points: &[Point]) -> Vec<u32> {
    let edges = convex_hull_edges(points);
    assert_eq!(edges.len(), points.len(), "not in convex position");
    let mut next = vec![Vec::new(); points.len()];
    for &[a, b] in &edges {
        next[a as usize].push(b);
        next[b as usize].push(a);
    }
    let mut cycle = vec![0u32];
    let mut prev = u32::MAX;
    loop {
        let cur = *cycle.last().unwrap();
        let nb = next[cur as usize]
            .iter()
            .copied()
            .find(|&v| v != prev)
            .unwrap();
        if nb == 0 {
            break;
        }
        prev = cur;
        cycle.push(nb);
    }
    assert_eq!(cycle.len(), points.len());
    let k = cycle.len();
    let p = |i: usize| points[cycle[i % k] as usize];
    let turn = (0..k)
        .map(|i| orient(p(i), p(i + 1), p(i + 2)))
        .find(|&o| o != 0)
        .unwrap();
    if turn < 0 {
        cycle.reverse();
    }
    cycle
}

/// A convex input of `n` (or a few more) points of one of five kinds.
fn convex_input(rng: &mut StdRng, n: usize, case: usize) -> Vec<Point> {
    match case % 5 {
        0 => convex_by_construction(rng, n, Parabola, false),
        1 => convex_by_construction(rng, n.max(4), Lens, false),
        2 => convex_by_construction(rng, n, Parabola, true),
        3 => convex_by_construction(rng, n.max(4), Lens, true),
        _ => rounded_circle_in_convex_position(rng, n),
    }
}

#[test]
fn min_weight_equals_the_exhaustive_optimum_on_small_convex_sets() {
    let mut rng = StdRng::seed_from_u64(SEED_EXHAUSTIVE_SMALL_CONVEX);
    let (mut checked, mut unique) = (0, 0);
    for case in 0..600 {
        let n = rng.gen_range(3..8);
        let pts = convex_input(&mut rng, n, case);
        let ps = PointSet::new(&pts).unwrap();
        if ps.len() > 9 {
            continue; // midpoints made it too large for the enumeration
        }
        assert_eq!(optri::convex_hull(&ps).len(), ps.len(), "case {case}");
        let d = ps.points();
        let t = triangulate(&ps, Criterion::MinWeight)
            .unwrap()
            .triangulation;
        t.validate().unwrap();
        let mine = distinct_triangles(&ps, &t);
        let (best, optimal) = optimum_by(d, |tris| TotalF64(total_length(d, tris)));
        let weight = total_length(d, &mine);
        assert!(
            relative_eq(weight, best.0),
            "case {case}: {weight} vs {} on {pts:?}",
            best.0
        );
        // Unless two optima tie within the tolerance, the triangulation is
        // the optimum.
        let near_optimal = all_triangulations(d)
            .iter()
            .filter(|tris| relative_eq(total_length(d, tris), best.0))
            .count();
        if near_optimal == 1 {
            assert_eq!(
                canonical_triangulation(d, &mine),
                optimal[0],
                "case {case}: {pts:?}"
            );
            unique += 1;
        }
        checked += 1;
    }
    assert!(checked >= 550 && unique >= 300, "{checked} {unique}");
}

#[test]
fn min_weight_equals_the_oracle_dp_and_bounds_the_greedy_triangulation() {
    let mut rng = StdRng::seed_from_u64(SEED_ORACLE_DP);
    let (mut checked, mut unique) = (0, 0);
    for case in 0..100 {
        let n = rng.gen_range(10..110);
        let pts = convex_input(&mut rng, n, case);
        let ps = PointSet::new(&pts).unwrap();
        let d = ps.points();
        if case % 5 < 2 {
            assert!(optri::internals::is_convex_position(&ps), "case {case}");
        }
        let polygon = oracle_polygon(d);
        let (oracle, tris, is_unique) =
            klincsek_unique(d, &polygon, MinWeight, |a, b| a.0 > b.0 * (1.0 + TOLERANCE))
                .expect("convex polygon");
        let t = triangulate(&ps, Criterion::MinWeight)
            .unwrap()
            .triangulation;
        t.validate().unwrap();
        let mine = distinct_triangles(&ps, &t);
        let weight = total_length(d, &mine);
        assert!(
            relative_eq(weight, oracle.0),
            "case {case}: {weight} vs {} on {pts:?}",
            oracle.0
        );
        if is_unique {
            assert_eq!(
                canonical_triangulation(d, &mine),
                tris,
                "case {case}: {pts:?}"
            );
            unique += 1;
        }
        // GT is a triangulation too, so it cannot be lighter than the MWT;
        // and the solutions report the total length in their stats.
        let gt = triangulate(&ps, Criterion::Greedy).unwrap().triangulation;
        gt.validate().unwrap();
        let gt_weight = total_length(d, &distinct_triangles(&ps, &gt));
        assert!(gt_weight >= oracle.0 * (1.0 - TOLERANCE), "case {case}");
        let s = triangulate(&ps, Criterion::MinWeight).unwrap();
        s.triangulation.validate().unwrap();
        assert!(s.exact, "sums of square roots are compared exactly");
        assert!(relative_eq(
            s.triangulation.stats().total_edge_length,
            oracle.0
        ));
        checked += 1;
    }
    assert_eq!(checked, 100);
    assert!(unique >= 50, "only {unique} of {checked} certified unique");
}

#[test]
fn klincsek_reference_agrees_with_its_plain_form() {
    // klincsek_unique is klincsek plus a certificate.
    let mut rng = StdRng::seed_from_u64(SEED_KLINCSEK_PLAIN_FORM);
    for case in 0..20 {
        let pts = convex_input(&mut rng, 12, case);
        let ps = PointSet::new(&pts).unwrap();
        let d = ps.points();
        let polygon = oracle_polygon(d);
        let (v, t) = klincsek(d, &polygon, MinWeight).unwrap();
        let (w, u, _) = klincsek_unique(d, &polygon, MinWeight, |a, b| a > b).unwrap();
        assert_eq!((v, t), (w, u));
    }
}

#[test]
fn greedy_matches_the_oracle_greedy_on_small_sets() {
    let mut rng = StdRng::seed_from_u64(SEED_GREEDY_SMALL_SETS);
    let mut checked = 0;
    for case in 0..300 {
        let n = rng.gen_range(3..11i32) as usize;
        let m = if case % 2 == 0 { 5 } else { 1000 };
        let pts = lattice_points(&mut rng, n, 0..m, 0..m);
        let Ok(ps) = PointSet::new(&pts) else {
            continue;
        };
        let d = ps.points();
        let t = triangulate(&ps, Criterion::Greedy).unwrap().triangulation;
        t.validate().unwrap();
        assert_eq!(
            canonical_triangulation(d, &distinct_triangles(&ps, &t)),
            optri_oracle::greedy_triangulation(d),
            "case {case}: {pts:?}"
        );
        checked += 1;
    }
    assert!(checked >= 250, "{checked}");
}

#[test]
fn min_weight_takes_non_convex_input() {
    // A triangle with a point inside has exactly one triangulation.
    let ps = PointSet::new(&[[0.0, 0.0], [4.0, 0.0], [0.0, 4.0], [1.0, 1.0]]).unwrap();
    let t = triangulate(&ps, Criterion::MinWeight)
        .unwrap()
        .triangulation;
    t.validate().unwrap();
    assert_eq!(t.triangles().len(), 3);
    let s = triangulate(&ps, Criterion::MinWeight).unwrap();
    assert!(s.exact);
}

#[test]
fn convex_sets_beyond_the_program_limit_are_answered_with_a_certified_bound() {
    // Integer points on the parabola y = x² and on a circle (cocircular as
    // doubles only nearly): convex position, past the cubic program's
    // limit. Not proven optimal: the lighter of greedy and Delaunay, with a
    // lower bound between the perimeter and the result's weight.
    let limit = optri::internals::MIN_WEIGHT_MAX_POINTS;
    let parabola: Vec<[f64; 2]> = (0..=limit as i64)
        .map(|x| [x as f64, (x * x) as f64])
        .collect();
    let k = limit + 300;
    let circle: Vec<[f64; 2]> = (0..k)
        .map(|i| {
            let t = std::f64::consts::TAU * i as f64 / k as f64;
            [1e3 * t.cos(), 1e3 * t.sin()]
        })
        .collect();
    for (what, pts) in [("parabola", parabola), ("circle", circle)] {
        let ps = optri::PointSet::new(&pts).unwrap();
        let s = triangulate(&ps, Criterion::MinWeight).unwrap();
        s.triangulation.validate().unwrap();
        assert_eq!(s.triangulation.triangles().len(), pts.len() - 2, "{what}");
        assert!(!s.exact, "{what}");
        assert_eq!(s.diagnostics.get("exact"), Some(0), "{what}");
        let weight = s.triangulation.stats().total_edge_length;
        for other in [Criterion::Greedy, Criterion::Delaunay] {
            let o = triangulate(&ps, other).unwrap();
            assert!(
                weight <= o.triangulation.stats().total_edge_length * (1.0 + TOLERANCE),
                "{what}: heavier than {other:?}"
            );
        }
        let bound = s.bound.expect("a certified lower bound").value;
        let hull = optri::graph(
            ps.input_points(),
            optri::GraphKind::Hull,
            &optri::Options::default(),
        )
        .unwrap()
        .edges;
        let perimeter: f64 = hull
            .iter()
            .map(|&[a, b]| {
                let (p, q) = (pts[a as usize], pts[b as usize]);
                (p[0] - q[0]).hypot(p[1] - q[1])
            })
            .sum();
        assert!(
            perimeter < bound && bound <= weight,
            "{what}: perimeter {perimeter}, bound {bound}, weight {weight}"
        );
    }
}
