//! Proof by oracle: optri's hull, RNG, Gabriel graph, MST and Delaunay
//! triangulation against the brute-force definitions in `optri-oracle`, on
//! random and degenerate inputs (grids, collinear runs, cocircular sets,
//! duplicates, huge/tiny/negative coordinates, TSPLIB files).

use optri::{
    convex_hull, delaunay, gabriel_graph, minimum_spanning_tree, relative_neighborhood_graph,
    PointSet,
};
use optri_oracle as oracle;
use optri_oracle::inputs::{
    grid, integer_circle_points as circle_points, lattice_points, uniform_unit_square,
};
use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};

type Point = [f64; 2];

const SEED_RANDOM_POINT_SETS: u64 = 20261122;
const SEED_COLLINEAR_RUNS: u64 = 7;
const SEED_COCIRCULAR: u64 = 11;
const SEED_NEARLY_COCIRCULAR: u64 = 23;
const SEED_DUPLICATES: u64 = 13;
const SEED_HUGE_TINY_NEGATIVE: u64 = 17;
const SEED_PLANAR_GRAPH_FACES: u64 = 31;
const SEED_DELAUNAY_CRITERION: u64 = 3;
const SEED_RANGE_LIMITS: u64 = 19;

/// Which checks to run (the Delaunay check is O(n²) in-circle tests).
#[derive(Clone, Copy)]
struct Checks {
    delaunay: bool,
    mst: bool,
}
const ALL: Checks = Checks {
    delaunay: true,
    mst: true,
};

/// Input-index edges → sorted `[min, max]` distinct-index edges. Every index
/// must be the kept copy of its point.
fn to_distinct(ps: &PointSet, edges: &[[u32; 2]]) -> Vec<[u32; 2]> {
    let mut out: Vec<[u32; 2]> = edges
        .iter()
        .map(|e| {
            e.map(|i| {
                let d = ps.distinct_index(i);
                assert_eq!(ps.input_index(d), i, "output uses a dropped duplicate {i}");
                d
            })
        })
        .map(|[a, b]| [a.min(b), a.max(b)])
        .collect();
    out.sort_unstable();
    out
}

/// Runs every comparison on `input`; returns the number of distinct points.
fn check(input: &[Point], checks: Checks, label: &str) -> usize {
    let ps = PointSet::new(input).unwrap_or_else(|e| panic!("{label}: {e}"));
    let pts = ps.points();

    let hull = to_distinct(&ps, &cycle_edges(&convex_hull(&ps)));
    assert_eq!(hull, oracle::convex_hull_edges(pts), "{label}: hull");

    let rng = to_distinct(&ps, &relative_neighborhood_graph(&ps).unwrap());
    assert_eq!(rng, oracle::rng_edges(pts), "{label}: RNG");

    let gabriel = to_distinct(&ps, &gabriel_graph(&ps).unwrap());
    assert_eq!(gabriel, oracle::gabriel_edges(pts), "{label}: Gabriel");

    if checks.mst {
        let mst = to_distinct(&ps, &minimum_spanning_tree(&ps).unwrap());
        oracle::is_minimum_spanning_tree(pts, &mst).unwrap_or_else(|e| panic!("{label}: MST: {e}"));
    }
    if checks.delaunay {
        let t = delaunay(&ps).unwrap();
        t.validate()
            .unwrap_or_else(|e| panic!("{label}: Delaunay invalid: {e}"));
        let tris: Vec<[u32; 3]> = t
            .triangles()
            .iter()
            .map(|tri| tri.map(|i| ps.distinct_index(i)))
            .collect();
        // Independent shape check: 2n − h − 2 ccw triangles covering the hull's area.
        assert_eq!(tris.len(), 2 * pts.len() - hull.len() - 2, "{label}");
        for tri in &tris {
            let [a, b, c] = tri.map(|v| pts[v as usize]);
            assert_eq!(oracle::orient(a, b, c), 1, "{label}: {tri:?} not ccw");
        }
        oracle::delaunay_check(pts, &tris).unwrap_or_else(|e| panic!("{label}: Delaunay: {e}"));
    }
    pts.len()
}

/// `n` integer points drawn from `[0, side)²` (64-bit draws).
fn integers(rng: &mut StdRng, n: usize, side: i64) -> Vec<Point> {
    lattice_points(rng, n, 0..side, 0..side)
}

#[test]
fn random_point_sets() {
    let mut rng = StdRng::seed_from_u64(SEED_RANDOM_POINT_SETS);
    let mut cases = 0;
    for n in (4..=60).chain((70..=300).step_by(23)) {
        let reps = if n <= 60 { 4 } else { 2 };
        for rep in 0..reps {
            let input = match rep % 4 {
                0 => uniform_unit_square(&mut rng, n),
                1 => integers(&mut rng, n, 1 << 20),
                // Small integer ranges: many collinear and cocircular tuples.
                2 => integers(&mut rng, n, 3 + n as i64 / 4),
                _ => integers(&mut rng, n, 1000),
            };
            if PointSet::new(&input).is_err() {
                continue; // all collinear or too few distinct: nothing to compare
            }
            check(&input, ALL, &format!("random n={n} rep={rep}"));
            cases += 1;
        }
    }
    assert!(cases > 200, "{cases}");
}

#[test]
fn integer_grids_with_exact_and_inexact_spacing() {
    for w in 3..=12 {
        for h in 3..=9 {
            check(&grid(w, h, 1.0), ALL, &format!("grid {w}x{h}"));
            // 0.1 is not a binary fraction: i·0.1 are not equally spaced exactly.
            check(&grid(w, h, 0.1), ALL, &format!("grid {w}x{h} step 0.1"));
        }
    }
}

#[test]
fn collinear_runs_inside_random_sets() {
    let mut rng = StdRng::seed_from_u64(SEED_COLLINEAR_RUNS);
    for case in 0..40 {
        let mut input = integers(&mut rng, 10 + case, 200);
        let (dx, dy) = [(1, 0), (0, 1), (1, 1), (2, -1), (3, 5)][case % 5];
        let (x0, y0) = (rng.gen_range(0..50), rng.gen_range(50..150));
        for k in 0..(4 + case % 9) as i64 {
            input.push([(x0 + k * dx) as f64, (y0 + k * dy) as f64]);
        }
        // A run through existing points, in f64 steps that are exact.
        let a = input[0];
        for k in 1..5 {
            input.push([a[0] + 0.5 * k as f64, a[1] + 0.25 * k as f64]);
        }
        check(&input, ALL, &format!("collinear run {case}"));
    }
}

#[test]
fn cocircular_pythagorean_sets() {
    let mut rng = StdRng::seed_from_u64(SEED_COCIRCULAR);
    for r in [5, 25, 65, 325, 1105] {
        let circle = circle_points(r);
        assert!(circle.len() >= 12, "radius {r}: {}", circle.len());
        check(&circle, ALL, &format!("circle r={r}"));
        // With the centre, shifted, and with a few interior points.
        let mut with_centre = circle.clone();
        with_centre.push([0.0, 0.0]);
        check(&with_centre, ALL, &format!("circle r={r} + centre"));
        let shifted: Vec<Point> = circle.iter().map(|p| [p[0] + 3.0, p[1] - 7.0]).collect();
        check(&shifted, ALL, &format!("circle r={r} shifted"));
        let mut mixed = circle.clone();
        for _ in 0..10 {
            let h = r / 2;
            mixed.push([rng.gen_range(-h..=h) as f64, rng.gen_range(-h..=h) as f64]);
        }
        check(&mixed, ALL, &format!("circle r={r} + interior"));
        // Two concentric circles sharing the lattice directions.
        let mut two = circle.clone();
        two.extend(circle.iter().map(|p| [p[0] * 2.0, p[1] * 2.0]));
        check(&two, ALL, &format!("circles r={r}, {}", 2 * r));
    }
}

/// Points on a circle computed in floating point: nearly (not exactly)
/// cocircular, so every in-circle and lune decision is a near tie.
#[test]
fn nearly_cocircular_float_sets() {
    let mut rng = StdRng::seed_from_u64(SEED_NEARLY_COCIRCULAR);
    for case in 0..12 {
        let n = 8 + 6 * case;
        let (cx, cy, r) = (
            rng.gen_range(-1e3..1e3),
            rng.gen_range(-1e3..1e3),
            10f64.powi(case % 5 - 2),
        );
        let mut input: Vec<Point> = (0..n)
            .map(|k| {
                let th = std::f64::consts::TAU * k as f64 / n as f64;
                [cx + r * th.cos(), cy + r * th.sin()]
            })
            .collect();
        if case % 2 == 1 {
            input.push([cx, cy]);
        }
        check(&input, ALL, &format!("near-cocircular {case}"));
    }
}

#[test]
fn duplicates_are_merged_and_outputs_use_kept_copies() {
    let mut rng = StdRng::seed_from_u64(SEED_DUPLICATES);
    for case in 0..30 {
        let base = integers(&mut rng, 6 + case, 12);
        let mut input = base.clone();
        for _ in 0..(3 + case) {
            let p = base[rng.gen_range(0..base.len())];
            let at = rng.gen_range(0..=input.len());
            input.insert(at, p);
        }
        if case % 3 == 0 {
            input.push([-0.0, 0.0]);
            input.push([0.0, -0.0]);
        }
        let ps = PointSet::new(&input).unwrap();
        assert!(ps.len() < input.len());
        check(&input, ALL, &format!("duplicates {case}"));
    }
}

#[test]
fn huge_tiny_and_negative_coordinates() {
    let mut rng = StdRng::seed_from_u64(SEED_HUGE_TINY_NEGATIVE);
    let scales = [
        2f64.powi(150),
        -(2f64.powi(150)),
        2f64.powi(-100),
        -(2f64.powi(-100)),
        -1.0,
        3.0 * 2f64.powi(-60),
    ];
    for (i, &s) in scales.iter().enumerate() {
        for case in 0..6 {
            let base = match case % 3 {
                0 => integers(&mut rng, 40, 16),
                1 => grid(5, 4, 1.0),
                _ => circle_points(25),
            };
            let input: Vec<Point> = base
                .iter()
                .map(|p| [p[0] * s, (p[1] - 8.0) * s.abs()])
                .collect();
            check(&input, ALL, &format!("scale #{i} case {case}"));
        }
    }
    // Mixed magnitudes in one set (exact expansions must carry both ends).
    let mut mixed = integers(&mut rng, 30, 100);
    mixed.push([2f64.powi(100), 1.0]);
    mixed.push([1.0 + 2f64.powi(-40), 2f64.powi(-40)]);
    mixed.push([-(2f64.powi(90)), -(2f64.powi(90))]);
    check(&mixed, ALL, "mixed magnitudes");
}

/// A counterexample to the 1-hop lune test: testing only Delaunay
/// neighbours of p and q misses the lune point r = (13, 12) of the hull edge pq.
#[test]
fn rng_one_hop_counterexample() {
    let input: Vec<Point> = [
        (21, 26),
        (26, 12),
        (30, 26),
        (23, 19),
        (19, 0),
        (20, 9),
        (13, 12),
        (6, 19),
        (8, 15),
    ]
    .iter()
    .map(|&(x, y)| [x as f64, y as f64])
    .collect();
    check(&input, ALL, "1-hop counterexample");
    let ps = PointSet::new(&input).unwrap();
    let rng = relative_neighborhood_graph(&ps).unwrap();
    assert!(
        !rng.contains(&[0, 7]),
        "p=(21,26), q=(6,19) is not an RNG edge"
    );
}

/// A counterexample to the 2-hop lune test: the only lune point of pq is 3
/// Delaunay hops away, so a 2-hop test also fails.
#[test]
fn rng_two_hop_counterexample() {
    let input: Vec<Point> = [
        (0, 0),
        (100, 0),
        (-54, 84),
        (-44, 34),
        (4, 29),
        (18, 62),
        (53, 107),
        (54, 116),
        (55, 78),
        (88, 57),
        (101, 15),
        (110, 85),
        (115, 67),
        (136, 95),
        (158, 33),
    ]
    .iter()
    .map(|&(x, y)| [x as f64, y as f64])
    .collect();
    check(&input, ALL, "2-hop counterexample");
    let ps = PointSet::new(&input).unwrap();
    assert!(!relative_neighborhood_graph(&ps).unwrap().contains(&[0, 1]));
    assert!(!oracle::rng_edges(&input).contains(&[0, 1]));
    // ... but it is a Delaunay edge, so the test case does exercise the lune search.
    assert!(optri::delaunay(&ps).unwrap().edges().contains(&[0, 1]));
}

/// Parses the `NODE_COORD_SECTION` of a TSPLIB file.
fn read_tsplib(path: &std::path::Path) -> Vec<Point> {
    let text = std::fs::read_to_string(path).unwrap();
    let mut in_section = false;
    let mut pts = Vec::new();
    for line in text.lines() {
        let line = line.trim();
        if line.starts_with("NODE_COORD_SECTION") {
            in_section = true;
            continue;
        }
        if !in_section || line.is_empty() {
            continue;
        }
        if line == "EOF" {
            break;
        }
        let f: Vec<&str> = line.split_whitespace().collect();
        assert_eq!(f.len(), 3, "{}: bad node line {line:?}", path.display());
        pts.push([f[1].parse().unwrap(), f[2].parse().unwrap()]);
    }
    pts
}

#[test]
fn tsplib_files_up_to_1100_points() {
    let dir = optri_oracle::data_dir().join("tsplib");
    // (file, distinct hull points incl. collinear, from the data README)
    let files = [
        ("berlin52", 8),
        ("kroA100", 12),
        ("ch150", 15),
        ("ts225", 96),
        ("a280", 44),
        ("lin318", 11),
        ("att532", 12),
        ("ali535", 10),
        ("pr1002", 31),
        ("u1060", 24),
        ("vm1084", 380),
    ];
    for (name, hull_points) in files {
        let input = read_tsplib(&dir.join(format!("{name}.tsp")));
        let checks = Checks {
            delaunay: input.len() <= 600,
            mst: true,
        };
        check(&input, checks, name);
        let ps = PointSet::new(&input).unwrap();
        assert_eq!(
            oracle::convex_hull_edges(ps.points()).len(),
            hull_points,
            "{name}"
        );
    }
}

/// Cycles up to rotation: the lexicographically smallest rotation.
fn normalized_cycles(cycles: Vec<Vec<u32>>) -> Vec<Vec<u32>> {
    let mut out: Vec<Vec<u32>> = cycles
        .into_iter()
        .map(|c| {
            (0..c.len())
                .map(|k| {
                    let mut r = c.clone();
                    r.rotate_left(k);
                    r
                })
                .min()
                .unwrap()
        })
        .collect();
    out.sort();
    out
}

/// `PlanarGraph::bounded_faces` (the regions Klincsek's DP runs on) against
/// the oracle's face walk, on hull ∪ RNG and on hull ∪ MST (many cracks).
#[test]
fn planar_graph_faces_of_hull_with_rng_or_mst() {
    let mut rng = StdRng::seed_from_u64(SEED_PLANAR_GRAPH_FACES);
    let mut inputs: Vec<Vec<Point>> = Vec::new();
    for n in [5, 8, 12, 20, 40, 80] {
        for side in [6, 30, 1 << 20] {
            inputs.push(integers(&mut rng, n, side));
        }
    }
    inputs.push(grid(5, 4, 1.0));
    inputs.push(grid(6, 6, 0.1));
    inputs.push(circle_points(65));
    let mut cracked = 0;
    for (i, input) in inputs.iter().enumerate() {
        let Ok(ps) = PointSet::new(input) else {
            continue;
        };
        let pts = ps.points();
        let hull = oracle::convex_hull_edges(pts);
        let rng_edges = oracle::rng_edges(pts);
        let mst = to_distinct(&ps, &minimum_spanning_tree(&ps).unwrap());
        for g in [rng_edges, mst] {
            let mut edges = g;
            edges.extend(&hull);
            edges.sort_unstable();
            edges.dedup();
            let expected = normalized_cycles(oracle::bounded_faces(pts, &edges));
            let graph = optri::internals::PlanarGraph::new(pts, &edges);
            let got = normalized_cycles(
                graph
                    .bounded_faces(pts)
                    .into_iter()
                    .map(|f| f.vertices)
                    .collect(),
            );
            assert_eq!(got, expected, "input {i}");
            cracked += expected.iter().filter(|f| oracle::is_cracked(f)).count();
        }
    }
    assert!(cracked > 20, "{cracked}");
}

/// `triangulate(_, Criterion::Delaunay)` returns an exact, valid Delaunay
/// triangulation (checked by the oracle), on random and cocircular input.
#[test]
fn delaunay_criterion_solution_is_delaunay() {
    let mut rng = StdRng::seed_from_u64(SEED_DELAUNAY_CRITERION);
    let mut inputs = vec![circle_points(325), grid(7, 5, 0.1)];
    for n in [10, 50, 200] {
        inputs.push(integers(&mut rng, n, 30));
        inputs.push(uniform_unit_square(&mut rng, n));
    }
    for input in inputs {
        let ps = PointSet::new(&input).unwrap();
        let s = optri::triangulate(&ps, optri::Criterion::Delaunay).unwrap();
        assert_eq!(s.criterion, optri::Criterion::Delaunay);
        assert!(s.exact);
        s.triangulation.validate().unwrap();
        let tris: Vec<[u32; 3]> = s
            .triangulation
            .triangles()
            .iter()
            .map(|t| t.map(|i| ps.distinct_index(i)))
            .collect();
        oracle::delaunay_check(ps.points(), &tris).unwrap();
    }
}

/// Coordinates at the ends of the accepted range, 2^201 and 2^-142, alone
/// and mixed in one set.
#[test]
fn coordinates_at_the_range_limits() {
    let mut rng = StdRng::seed_from_u64(SEED_RANGE_LIMITS);
    let (top, bottom) = (2f64.powi(201), 2f64.powi(-142));
    for case in 0..12 {
        let base = integers(&mut rng, 12 + case, 5);
        let scale = [top / 4.0, bottom, -top / 4.0, -bottom][case % 4];
        let mut input: Vec<Point> = base.iter().map(|p| [p[0] * scale, p[1] * scale]).collect();
        if case >= 4 {
            // Mixed: tiny points near the origin among huge ones.
            input.extend([[bottom, 0.0], [0.0, bottom], [bottom * 3.0, bottom * 5.0]]);
            input.extend([[top, top], [-top, top], [top, 0.0]]);
        }
        check(&input, ALL, &format!("range limits {case}"));
    }
}

/// The Gabriel graph uses the closed diametral disc: on a 3 × 3 grid each
/// unit square's diagonals have two square corners on their diametral
/// circle, so only the 12 grid edges remain, and no two edges cross on
/// grids or on a real data set with many cocircular quadruples.
#[test]
fn gabriel_graph_is_planar_and_uses_the_closed_disc() {
    let grid: Vec<Point> = (0..3)
        .flat_map(|y| (0..3).map(move |x| [x as f64, y as f64]))
        .collect();
    let ps = PointSet::new(&grid).unwrap();
    let edges = gabriel_graph(&ps).unwrap();
    assert_eq!(edges.len(), 12, "{edges:?}");
    let dir = optri_oracle::data_dir().join("tsplib");
    let mut checked = 0;
    for (label, pts) in [
        (
            "grid 7x5",
            (0..35).map(|i| [(i % 7) as f64, (i / 7) as f64]).collect(),
        ),
        (
            "a280",
            optri::io::read(
                optri::io::Source::Path(&dir.join("a280.tsp")),
                &optri::io::ReadOptions::default(),
            )
            .unwrap()
            .input
            .points()
            .to_vec(),
        ),
    ] {
        let ps = PointSet::new(&pts).unwrap();
        let p = ps.input_points();
        let edges = gabriel_graph(&ps).unwrap();
        for (i, a) in edges.iter().enumerate() {
            for b in &edges[i + 1..] {
                let (a0, a1, b0, b1) = (
                    p[a[0] as usize],
                    p[a[1] as usize],
                    p[b[0] as usize],
                    p[b[1] as usize],
                );
                assert!(
                    !optri::kernel::properly_cross(a0, a1, b0, b1),
                    "{label}: Gabriel edges {a:?} and {b:?} cross"
                );
            }
        }
        checked += 1;
    }
    assert_eq!(checked, 2);
}

/// The edges `[a, b]` of a cycle of indices, in its order.
fn cycle_edges(cycle: &[u32]) -> Vec<[u32; 2]> {
    (0..cycle.len())
        .map(|i| [cycle[i], cycle[(i + 1) % cycle.len()]])
        .collect()
}
