//! The greedy triangulation against the independent oracle
//! [`optri_oracle::greedy_edges`] (the definition, with its own exact
//! arithmetic and its own simulation-of-simplicity order), edge for edge:
//! the dispatching entry points (`greedy_triangulation`, `greedy`) and every
//! algorithm that applies (`General` always, `Convex` on strictly convex
//! position, `Semicircular` on semicircular polygons). Every triangulation
//! must pass `validate()`. Each test counts what it checked and asserts a
//! minimum, so that nothing can be skipped silently.
//!
//! optri's own `greedy_naive_edges` shares the sorting and predicates with
//! the algorithms; it is only cross-checked against the oracle here.

use optri::internals::{
    greedy_edges_by, greedy_naive_edges, greedy_triangulation, is_convex_position, is_semicircular,
    GreedyAlgorithm,
};
use optri::kernel::Point;
use optri::{triangulate, Criterion, PointSet};
use optri_oracle::inputs::{
    circle_at_random_angles, clustered, collinear_runs, convex_lens, fan, grid, grid_subset,
    integer_circle_points as circle, jittered_arc, lattice_points, perturbed_circle,
    random_parabola, rounded_circle, run_with_apex, sampled_circle, uniform_in_square,
};
use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};

const SEED_RANDOM_SMALL_SETS: u64 = 3;
const SEED_LARGER_RANDOM_SETS: u64 = 5;
const SEED_GRIDS_AND_COLLINEAR_RUNS: u64 = 4;
const SEED_COCIRCULAR_HUGE_DUPLICATES: u64 = 6;
const SEED_SMALL_CONVEX_INPUTS: u64 = 7;
const SEED_CONVEX_AT_SCALE: u64 = 8;
const SEED_CONVEX_3000: u64 = 10;
const SEED_RANDOM_5000: u64 = 15;
const SEED_NAIVE_REFERENCE: u64 = 16;
const SEED_REGISTRY: u64 = 9;
const SEED_CONVEX_10000: u64 = 12;
const SEED_CLIFF_FAMILIES: u64 = 17;
const SEED_DEGENERATE_FAMILIES: u64 = 18;
const SEED_CLUSTER_SCALES: u64 = 19;
const SEED_WEAKLY_CONVEX: u64 = 20;

/// Distinct-index `[min, max]` edges of a triangulation, sorted.
fn distinct_edges(ps: &PointSet, t: &optri::Triangulation) -> Vec<[u32; 2]> {
    let mut e: Vec<[u32; 2]> = t
        .edges()
        .into_iter()
        .map(|[a, b]| {
            let (a, b) = (ps.distinct_index(a), ps.distinct_index(b));
            [a.min(b), a.max(b)]
        })
        .collect();
    e.sort_unstable();
    e
}

/// What a test checked.
#[derive(Debug, Default)]
struct Tally {
    /// Point sets compared with the oracle.
    sets: usize,
    /// Algorithm runs compared, by algorithm.
    general: usize,
    convex: usize,
    semicircular: usize,
    /// Which algorithm the dispatcher chose, by algorithm.
    dispatched: [usize; 4],
}

fn slot(a: GreedyAlgorithm) -> usize {
    match a {
        GreedyAlgorithm::General => 0,
        GreedyAlgorithm::Convex => 1,
        GreedyAlgorithm::Semicircular => 2,
        GreedyAlgorithm::Fan => 3,
    }
}

/// Points for a failure message (all of them if few).
fn show(points: &[Point]) -> String {
    if points.len() <= 60 {
        format!("{points:?}")
    } else {
        format!("({} points)", points.len())
    }
}

/// The first disagreement of the product with the oracle on `points`, if any
/// (`None` also for inputs `PointSet` rejects).
fn mismatch(points: &[Point]) -> Option<String> {
    let ps = PointSet::new(points).ok()?;
    let reference = optri_oracle::greedy_edges(ps.points());
    let (t, algorithm) = greedy_triangulation(&ps).unwrap();
    if let Err(e) = t.validate() {
        return Some(format!("greedy_triangulation ({algorithm:?}) invalid: {e}"));
    }
    if distinct_edges(&ps, &t) != reference {
        return Some(format!("greedy_triangulation ({algorithm:?}) != oracle"));
    }
    for a in [
        GreedyAlgorithm::General,
        GreedyAlgorithm::Convex,
        GreedyAlgorithm::Semicircular,
        GreedyAlgorithm::Fan,
    ] {
        if let Some(e) = greedy_edges_by(&ps, a) {
            if e != reference {
                return Some(format!("{a:?} != oracle"));
            }
        }
    }
    None
}

/// Deletes points while the product still disagrees with the oracle, to
/// report a small reproducer (only runs after a failure).
fn shrink(points: &[Point]) -> Vec<Point> {
    let mut pts = points.to_vec();
    let mut budget = 3000;
    let mut changed = true;
    while changed && budget > 0 {
        changed = false;
        let mut i = 0;
        while i < pts.len() && budget > 0 {
            budget -= 1;
            let mut fewer = pts.clone();
            fewer.remove(i);
            if mismatch(&fewer).is_some() {
                pts = fewer;
                changed = true;
            } else {
                i += 1;
            }
        }
    }
    pts
}

fn fail(points: &[Point], what: &str, message: String) -> ! {
    let small = if points.len() <= 2500 {
        shrink(points)
    } else {
        points.to_vec()
    };
    panic!(
        "{what}: {message} on {}; reduced to {} points ({}): {:?}",
        show(points),
        small.len(),
        mismatch(&small).unwrap_or_default(),
        small
    );
}

/// Full check of one point set: the oracle's edges from the dispatcher, from
/// `greedy`, and from every algorithm that accepts the input; valid
/// triangulations. Inputs `PointSet` rejects are not counted.
fn check(points: &[Point], what: &str, tally: &mut Tally) -> Option<GreedyAlgorithm> {
    let ps = PointSet::new(points).ok()?;
    let reference = optri_oracle::greedy_edges(ps.points());
    let (t, algorithm) = greedy_triangulation(&ps).unwrap();
    if let Err(e) = t.validate() {
        fail(points, what, format!("invalid ({algorithm:?}): {e}"));
    }
    if distinct_edges(&ps, &t) != reference {
        fail(
            points,
            what,
            format!("greedy_triangulation ({algorithm:?}) != oracle"),
        );
    }
    tally.dispatched[slot(algorithm)] += 1;
    let general = greedy_edges_by(&ps, GreedyAlgorithm::General).unwrap();
    if general != reference {
        fail(points, what, "General != oracle".into());
    }
    tally.general += 1;
    if let Some(e) = greedy_edges_by(&ps, GreedyAlgorithm::Convex) {
        if e != reference {
            fail(points, what, "Convex != oracle".into());
        }
        tally.convex += 1;
    }
    if let Some(e) = greedy_edges_by(&ps, GreedyAlgorithm::Semicircular) {
        if e != reference {
            fail(points, what, "Semicircular != oracle".into());
        }
        tally.semicircular += 1;
    }
    if let Some(e) = greedy_edges_by(&ps, GreedyAlgorithm::Fan) {
        if e != reference {
            fail(points, what, "Fan != oracle".into());
        }
    }
    if ps.len() <= 500 {
        // `greedy` is `greedy_triangulation` without the algorithm name.
        let t = triangulate(&ps, Criterion::Greedy).unwrap().triangulation;
        t.validate().unwrap();
        assert_eq!(
            distinct_edges(&ps, &t),
            reference,
            "triangulate(greedy) on {what}"
        );
    }
    tally.sets += 1;
    Some(algorithm)
}

#[test]
fn random_small_sets_match_the_oracle() {
    let mut rng = StdRng::seed_from_u64(SEED_RANDOM_SMALL_SETS);
    let mut tally = Tally::default();
    for case in 0..3000 {
        let n = rng.gen_range(3..=40);
        let pts = match case % 3 {
            0 => uniform_in_square(&mut rng, n, 100.0),
            1 => uniform_in_square(&mut rng, n, 1.0),
            _ => {
                let k = rng.gen_range(1..4);
                clustered(&mut rng, k * n.div_ceil(3), k)
            }
        };
        check(&pts, &format!("random case {case}"), &mut tally);
    }
    assert!(tally.sets >= 2900, "{tally:?}");
}

#[test]
fn larger_random_sets_match_the_oracle() {
    let mut rng = StdRng::seed_from_u64(SEED_LARGER_RANDOM_SETS);
    let mut tally = Tally::default();
    for &n in &[100, 200, 500, 1000, 2000] {
        for rep in 0..4 {
            let scale = [1e3, 1.0, 1e-3, 2f64.powi(100)][rep];
            let pts = uniform_in_square(&mut rng, n, scale);
            check(&pts, &format!("uniform n={n} rep {rep}"), &mut tally);
        }
    }
    for case in 0..4 {
        let k = 4 + 2 * case;
        let pts = clustered(&mut rng, 60 * k, k);
        check(&pts, &format!("clusters case {case}"), &mut tally);
    }
    assert_eq!(tally.sets, 24, "{tally:?}");
}

#[test]
fn integer_grids_and_collinear_runs_match_the_oracle() {
    let mut rng = StdRng::seed_from_u64(SEED_GRIDS_AND_COLLINEAR_RUNS);
    let mut tally = Tally::default();
    // Full grids, including thin 2 × k and 3 × k strips.
    for w in 2..=12 {
        for h in 1..=12 {
            check(&grid(w, h, 1.0), &format!("grid {w}x{h}"), &mut tally);
        }
    }
    for k in [20, 50, 100, 200] {
        check(&grid(2, k, 1.0), &format!("grid 2x{k}"), &mut tally);
        check(&grid(k, 2, 1.0), &format!("grid {k}x2"), &mut tally);
        check(&grid(3, k, 1.0), &format!("grid 3x{k}"), &mut tally);
    }
    check(&grid(30, 30, 1.0), "grid 30x30", &mut tally);
    // Random subsets of grids.
    for case in 0..600 {
        let (w, h) = (rng.gen_range(2..9), rng.gen_range(2..9));
        let p = rng.gen_range(0.3..0.9);
        let pts = grid_subset(&mut rng, w, h, p);
        check(&pts, &format!("grid subset case {case}"), &mut tally);
    }
    for (w, h, p) in [(40, 40, 0.5), (60, 20, 0.3), (2, 300, 0.8), (100, 3, 0.6)] {
        let pts = grid_subset(&mut rng, w, h, p);
        check(&pts, &format!("grid subset {w}x{h} p={p}"), &mut tally);
    }
    // Small integer sets with duplicates.
    for case in 0..600 {
        let n = rng.gen_range(3..30i32) as usize;
        let m = rng.gen_range(2..7);
        let pts = lattice_points(&mut rng, n, 0..m, 0..m);
        check(&pts, &format!("small integer case {case}"), &mut tally);
    }
    // Points on a few lines (many points on open segments), plus noise.
    for case in 0..300 {
        let pts = collinear_runs(&mut rng, 1..4, 2..12, 0..6);
        check(&pts, &format!("collinear runs case {case}"), &mut tally);
    }
    // A long collinear run with one point off the line.
    for k in [10, 100, 300] {
        check(
            &run_with_apex(k),
            &format!("run of {k} plus apex"),
            &mut tally,
        );
    }
    assert!(tally.sets >= 1500, "{tally:?}");
}

#[test]
fn cocircular_huge_negative_and_duplicate_points_match_the_oracle() {
    let mut rng = StdRng::seed_from_u64(SEED_COCIRCULAR_HUGE_DUPLICATES);
    let mut tally = Tally::default();
    // Single exactly cocircular circles: strictly convex, not semicircular,
    // so the dispatcher runs the convex algorithm.
    let radii = [5i64, 25, 65, 5 * 5 * 13 * 13];
    let sizes = [12, 20, 36, 100];
    for (&r, &size) in radii.iter().zip(&sizes) {
        let c = circle(r);
        assert_eq!(c.len(), size, "points on x² + y² = {r}²");
        for (s, shift) in [(1.0, 0.0), (2f64.powi(150), 0.0), (-1.0, -1e6)] {
            let pts: Vec<Point> = c.iter().map(|p| [p[0] * s + shift, p[1] * s]).collect();
            let what = format!("circle r={r} scale {s} shift {shift}");
            assert_eq!(
                check(&pts, &what, &mut tally),
                Some(GreedyAlgorithm::Convex),
                "{what}"
            );
        }
    }
    // Concentric circles, with and without the centre (general algorithm).
    let mut rings: Vec<Point> = [5i64, 25, 65].iter().flat_map(|&r| circle(r)).collect();
    check(&rings, "circles 5, 25, 65", &mut tally);
    rings.push([0.0, 0.0]);
    check(&rings, "circles 5, 25, 65 with centre", &mut tally);
    let mut one = circle(65);
    one.push([0.0, 0.0]);
    check(&one, "circle 65 with centre", &mut tally);
    // Duplicates, huge, tiny and negative coordinates: exactness across scales.
    for case in 0..400 {
        let n = rng.gen_range(3..30i32) as usize;
        let scale = [2f64.powi(150), -(2f64.powi(-120)), 1e-3, 7.0][case % 4];
        let offset = [0.0, -3.0][case / 4 % 2];
        let mut pts: Vec<Point> = lattice_points(&mut rng, n, -6..6, -6..6)
            .into_iter()
            .map(|p| [(p[0] + offset) * scale, (p[1] + offset) * scale])
            .collect();
        pts.push(pts[0]);
        check(&pts, &format!("scaled integer case {case}"), &mut tally);
    }
    for case in 0..100 {
        let n = rng.gen_range(3..40);
        let mut pts: Vec<Point> = uniform_in_square(&mut rng, n, 1.0)
            .into_iter()
            .map(|p| {
                [
                    p[0] * 2f64.powi(150) - 2f64.powi(151),
                    p[1] * 2f64.powi(150),
                ]
            })
            .collect();
        for _ in 0..3 {
            pts.push(pts[rng.gen_range(0..pts.len())]);
        }
        check(&pts, &format!("huge random case {case}"), &mut tally);
    }
    assert!(tally.sets >= 480, "{tally:?}");
    assert!(tally.dispatched[1] >= 12, "{tally:?}");
}

fn tsplib_files() -> Vec<std::path::PathBuf> {
    let dir = optri_oracle::data_dir().join("tsplib");
    let mut files: Vec<_> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "tsp"))
        .collect();
    files.sort();
    assert_eq!(files.len(), 14, "expected the 14 TSPLIB files");
    files
}

/// Checks the TSPLIB files with at most (`small`) or more than 1100 points;
/// returns how many.
fn check_tsplib(small: bool) -> usize {
    let mut tally = Tally::default();
    let mut files = 0;
    for path in tsplib_files() {
        let options = optri::io::ReadOptions::default().with_format(optri::io::InputFormat::Tsplib);
        let read = optri::io::read(optri::io::Source::Path(&path), &options)
            .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        let pts = read.input.points();
        assert!(pts.len() >= 52, "{}", path.display());
        if (pts.len() <= 1100) != small {
            continue;
        }
        let start = std::time::Instant::now();
        check(pts, &path.display().to_string(), &mut tally)
            .unwrap_or_else(|| panic!("{} rejected", path.display()));
        files += 1;
        eprintln!(
            "{}: {} points, {:?}",
            path.display(),
            pts.len(),
            start.elapsed()
        );
    }
    assert_eq!(tally.sets, files);
    files
}

#[test]
fn tsplib_files_match_the_oracle() {
    assert_eq!(check_tsplib(true), 11);
}

/// The three TSPLIB files above 1100 points (fl1577, pcb3038, fnl4461):
/// about 12 s in the test profile, mostly the oracle on fnl4461 (8 s).
#[test]
fn large_tsplib_files_match_the_oracle() {
    assert_eq!(check_tsplib(false), 3);
}

#[test]
fn convex_and_semicircular_algorithms_match_on_small_convex_inputs() {
    let mut rng = StdRng::seed_from_u64(SEED_SMALL_CONVEX_INPUTS);
    let mut tally = Tally::default();
    for case in 0..1200 {
        let n = rng.gen_range(3..=40);
        let (pts, kind) = match case % 5 {
            0 => (convex_lens(&mut rng, n.max(4)), "lens"),
            1 => (random_parabola(&mut rng, n, 3 * n), "parabola"),
            2 => (rounded_circle(&mut rng, n, 1e3), "rounded circle"),
            3 => (rounded_circle(&mut rng, n, 1e9), "rounded big circle"),
            _ => (jittered_arc(&mut rng, n), "jittered arc"),
        };
        let ps = PointSet::new(&pts).unwrap();
        match kind {
            "lens" => {
                assert!(
                    is_convex_position(&ps) && !is_semicircular(&ps),
                    "case {case}"
                )
            }
            "parabola" if ps.len() >= 3 => assert!(is_semicircular(&ps), "case {case}"),
            _ => {}
        }
        check(&pts, &format!("{kind} case {case}"), &mut tally)
            .unwrap_or_else(|| panic!("case {case} rejected"));
    }
    assert_eq!(tally.sets, 1200, "{tally:?}");
    assert!(
        tally.convex > 700 && tally.semicircular > 400 && tally.dispatched[1] > 300,
        "{tally:?}"
    );
}

#[test]
fn convex_and_semicircular_algorithms_match_the_oracle_at_scale() {
    let mut rng = StdRng::seed_from_u64(SEED_CONVEX_AT_SCALE);
    let mut tally = Tally::default();
    for &n in &[300, 1000] {
        let pts = convex_lens(&mut rng, n);
        assert_eq!(
            check(&pts, &format!("lens n={n}"), &mut tally),
            Some(GreedyAlgorithm::Convex)
        );
        let pts = random_parabola(&mut rng, n, 4 * n);
        assert_eq!(
            check(&pts, &format!("parabola n={n}"), &mut tally),
            Some(GreedyAlgorithm::Semicircular)
        );
    }
    assert_eq!(
        (tally.sets, tally.convex, tally.semicircular),
        (4, 4, 2),
        "{tally:?}"
    );
}

/// Larger convex inputs (about 4 s in the test profile).
#[test]
fn convex_inputs_of_three_thousand_points() {
    let mut rng = StdRng::seed_from_u64(SEED_CONVEX_3000);
    let mut tally = Tally::default();
    check(
        &random_parabola(&mut rng, 3000, 12_000),
        "parabola n=3000",
        &mut tally,
    );
    check(&convex_lens(&mut rng, 3000), "lens n=3000", &mut tally);
    check(&circle(5525), "circle r=5525", &mut tally);
    assert_eq!((tally.sets, tally.convex), (3, 3), "{tally:?}");
}

/// Random point sets of 5000 points, slow:
/// `cargo test -p optri --test greedy -- --ignored five_thousand`
/// takes 29 s in the test profile (opt-level 2), nearly all of it in the
/// oracle (6 s uniform, 6 s clusters, 15 s grid subset). (Before the general
/// algorithm's density guard it took 111 s: 46 s per run on the clusters.)
#[test]
#[ignore]
fn random_sets_of_five_thousand_points() {
    let mut rng = StdRng::seed_from_u64(SEED_RANDOM_5000);
    let mut tally = Tally::default();
    check(
        &uniform_in_square(&mut rng, 5000, 1e3),
        "uniform n=5000",
        &mut tally,
    );
    check(
        &clustered(&mut rng, 5000, 20),
        "clusters n=5000",
        &mut tally,
    );
    check(
        &grid_subset(&mut rng, 100, 100, 0.5),
        "grid subset 100x100",
        &mut tally,
    );
    assert_eq!(tally.sets, 3);
}

/// The product's own naive reference agrees with the oracle (a cross-check
/// of the two references, not a test of the algorithms).
#[test]
fn product_naive_reference_agrees_with_the_oracle() {
    let mut rng = StdRng::seed_from_u64(SEED_NAIVE_REFERENCE);
    let mut checked = 0;
    for case in 0..300 {
        let n = rng.gen_range(3..40);
        let pts: Vec<Point> = if case % 2 == 0 {
            uniform_in_square(&mut rng, n, 10.0)
        } else {
            lattice_points(&mut rng, n, 0..5, 0..5)
        };
        let Ok(ps) = PointSet::new(&pts) else {
            continue;
        };
        assert_eq!(
            greedy_naive_edges(&ps),
            optri_oracle::greedy_edges(ps.points()),
            "case {case}: {pts:?}"
        );
        checked += 1;
    }
    assert!(checked >= 250, "{checked}");
}

#[test]
fn criterion_registry_reports_the_algorithm_and_total_length() {
    let mut rng = StdRng::seed_from_u64(SEED_REGISTRY);
    let cases = [
        (uniform_in_square(&mut rng, 300, 10.0), "general"),
        (convex_lens(&mut rng, 300), "convex"),
        (random_parabola(&mut rng, 300, 900), "semicircular"),
    ];
    for (pts, name) in cases {
        let ps = PointSet::new(&pts).unwrap();
        let s = triangulate(&ps, Criterion::Greedy).unwrap();
        assert!(s.algorithm.starts_with(name), "{} vs {name}", s.algorithm);
        assert!(s.exact);
        s.triangulation.validate().unwrap();
        let d = ps.points();
        let reference = optri_oracle::greedy_edges(d);
        assert_eq!(distinct_edges(&ps, &s.triangulation), reference, "{name}");
        let expected: f64 = reference
            .iter()
            .map(|&[a, b]| optri_oracle::edge_length(d[a as usize], d[b as usize]))
            .sum();
        let total = s.triangulation.stats().total_edge_length;
        assert!(
            (total - expected).abs() <= 1e-9 * expected,
            "{total} vs {expected}"
        );
    }
    assert_eq!(Criterion::from_name("greedy").unwrap(), Criterion::Greedy);
    assert_eq!(
        Criterion::from_name("min-weight").unwrap(),
        Criterion::MinWeight
    );
}

/// The convex-position algorithms at scale: at n = 10⁴ the
/// convex and semicircular algorithms equal the general one edge for edge
/// (no oracle here: it would dominate the run).
#[test]
fn convex_and_semicircular_equal_general_at_ten_thousand_points() {
    let mut rng = StdRng::seed_from_u64(SEED_CONVEX_10000);
    let n = 10_000;
    let inputs = [
        (random_parabola(&mut rng, n, 4 * n), "parabola", true),
        (convex_lens(&mut rng, n), "lens", false),
    ];
    for (pts, what, semicircular) in inputs {
        let ps = PointSet::new(&pts).unwrap();
        let general = greedy_edges_by(&ps, GreedyAlgorithm::General).unwrap();
        assert_eq!(
            general.len(),
            2 * n - 3,
            "{what}: a triangulation of a convex polygon"
        );
        let convex = greedy_edges_by(&ps, GreedyAlgorithm::Convex).expect("convex position");
        assert_eq!(convex, general, "{what}: convex != general");
        let semi = greedy_edges_by(&ps, GreedyAlgorithm::Semicircular);
        assert_eq!(semi.is_some(), semicircular, "{what}");
        if let Some(semi) = semi {
            assert_eq!(semi, general, "{what}: semicircular != general");
        }
        let (t, algorithm) = greedy_triangulation(&ps).unwrap();
        t.validate().unwrap();
        assert_eq!(distinct_edges(&ps, &t), general);
        let expected = if semicircular {
            GreedyAlgorithm::Semicircular
        } else {
            GreedyAlgorithm::Convex
        };
        assert_eq!(algorithm, expected, "{what}");
    }
}

/// A cluster far below the resolution of any grid over the bounding box
/// (spacing 10⁻¹² in a box of 10⁶): the density guard must stop shrinking.
#[test]
fn a_cluster_below_the_grid_resolution() {
    let mut pts: Vec<Point> = (0..100)
        .map(|i| {
            [
                1e-12 * (i % 10) as f64,
                1e-12 * (i / 10) as f64 + 1e-13 * (i % 3) as f64,
            ]
        })
        .collect();
    pts.extend([[1e6, 1e6], [1e6, -3e5], [-2e5, 7e5]]);
    let mut tally = Tally::default();
    assert_eq!(
        check(&pts, "cluster below the grid resolution", &mut tally),
        Some(GreedyAlgorithm::General)
    );
    assert_eq!(tally.sets, 1);
}

/// A map of the plane (for moving a test input around).
type PointMap = fn(Point) -> Point;

/// The inputs that once made the greedy triangulation quadratic, small,
/// edge for edge against the oracle:
/// fans (every orientation, apex anywhere, duplicates), collinear runs with
/// several apexes, circles sampled with cos/sin (regular polygons, with and
/// without the centre, at several radii and offsets), perturbed circles and
/// random angles on a circle.
#[test]
fn cliff_families_match_the_oracle() {
    let mut rng = StdRng::seed_from_u64(SEED_CLIFF_FAMILIES);
    let mut tally = Tally::default();
    // Fans: the line along x, along y, diagonal, reversed; apex above,
    // below, over an end point or beyond the run; then with duplicates.
    for n in [3, 4, 5, 6, 7, 10, 17, 40, 200] {
        let base = fan(n);
        let maps: [(&str, PointMap); 4] = [
            ("x", |p| p),
            ("y", |p| [-p[1], p[0]]),
            ("diagonal", |p| [p[0] + 3.0 * p[1], 2.0 * p[0] - p[1]]),
            ("reversed", |p| [-p[0], -p[1]]),
        ];
        for (what, map) in maps {
            let pts: Vec<Point> = base.iter().map(|&p| map(p)).collect();
            check(&pts, &format!("fan {n} {what}"), &mut tally);
        }
        for apex in [[0.0, 1.0], [0.0, -2.5], [-1.0, 0.5], [n as f64 + 3.0, 7.0]] {
            let mut pts: Vec<Point> = (0..n).map(|i| [i as f64, 0.0]).collect();
            pts.push(apex);
            check(&pts, &format!("fan {n} apex {apex:?}"), &mut tally);
        }
        let mut pts = fan(n);
        for _ in 0..3 {
            pts.push(pts[rng.gen_range(0..pts.len())]);
        }
        check(&pts, &format!("fan {n} with duplicates"), &mut tally);
    }
    // Collinear runs with several apexes on both sides (the general
    // algorithm, not the fan shortcut).
    for case in 0..200 {
        let k = rng.gen_range(3..40);
        let step = [1.0, 0.5, 3.0][case % 3];
        let mut pts: Vec<Point> = (0..k).map(|i| [i as f64 * step, 0.0]).collect();
        for _ in 0..rng.gen_range(2..6) {
            let x = rng.gen_range(-3..k + 3) as f64 * step;
            let y = [1.0, -1.0, 2.0, -0.5, 10.0][rng.gen_range(0..5)];
            pts.push([x, y]);
        }
        check(
            &pts,
            &format!("run of {k} with apexes, case {case}"),
            &mut tally,
        );
    }
    for k in [100, 300] {
        let mut pts: Vec<Point> = (0..k).map(|i| [i as f64, 0.0]).collect();
        pts.extend([[k as f64 / 3.0, 1.0], [2.0 * k as f64 / 3.0, -1.0]]);
        check(&pts, &format!("run of {k} with two apexes"), &mut tally);
    }
    // Sampled circles: regular polygons, with and without the centre.
    for n in (3..40).chain([50, 64, 100, 128, 300]) {
        for (r, shift) in [(1.0, 0.0), (1000.0, 0.0), (1e-3, 5.0), (7.0, -1e6)] {
            let mut pts: Vec<Point> = sampled_circle(n, r)
                .into_iter()
                .map(|p| [p[0] + shift, p[1]])
                .collect();
            check(
                &pts,
                &format!("sampled circle n={n} r={r} shift {shift}"),
                &mut tally,
            );
            if n <= 64 {
                pts.push([shift, 0.0]);
                check(
                    &pts,
                    &format!("sampled circle n={n} r={r} with centre"),
                    &mut tally,
                );
            }
        }
    }
    // Nearly cocircular, convex or not as rounding decides.
    for case in 0..200 {
        let n = rng.gen_range(4..60);
        let pts = match case % 3 {
            0 => perturbed_circle(&mut rng, n, 1e-9),
            1 => perturbed_circle(&mut rng, n, 1e-3),
            _ => circle_at_random_angles(&mut rng, n, 1e3),
        };
        check(&pts, &format!("near circle case {case}"), &mut tally);
    }
    for pts in [
        sampled_circle(1000, 1000.0),
        perturbed_circle(&mut rng, 1000, 1e-6),
    ] {
        check(&pts, "near circle n=1000", &mut tally);
    }
    assert!(tally.sets >= 800, "{tally:?}");
    assert!(tally.dispatched[1] >= 100, "{tally:?}");
    // The fans (all orientations, apexes, with duplicates) take the shortcut.
    assert!(tally.dispatched[3] >= 70, "{tally:?}");
}

/// The boundary of the square `[0, k]²` with `k` integer points a side
/// (corners once): convex but not strictly (the convex algorithm).
fn square_boundary(k: usize) -> Vec<Point> {
    let side = k as f64;
    (0..k)
        .flat_map(|i| {
            let t = i as f64;
            [[t, 0.0], [side, t], [side - t, side], [0.0, side - t]]
        })
        .collect()
}

/// Degenerate families for the general algorithm, small, edge for
/// edge against the oracle: boundaries of squares and rectangles (sides
/// along the axes and the diagonals, huge and negative coordinates, with
/// interior points), collinear runs cut into several chains on one line and
/// on parallel lines with apexes on both sides (the line classes are joined
/// per line), two concentric sampled circles, a grid's rows with apexes,
/// heavy duplicates and a cluster far below the bounding box's resolution.
#[test]
fn degenerate_families_match_the_oracle() {
    let mut rng = StdRng::seed_from_u64(SEED_DEGENERATE_FAMILIES);
    let mut tally = Tally::default();
    let maps: [(&str, PointMap); 4] = [
        ("axes", |p| p),
        ("diagonal", |p| [p[0] + p[1], p[0] - p[1]]),
        ("huge", |p| [p[0] * 2f64.powi(100), p[1] * 2f64.powi(100)]),
        ("negative", |p| [-3.0 * p[1] - 1e6, -3.0 * p[0]]),
    ];
    for k in (2..=12).chain([25, 60, 150]) {
        for (what, map) in maps {
            let pts: Vec<Point> = square_boundary(k).into_iter().map(map).collect();
            check(&pts, &format!("square boundary {k} {what}"), &mut tally);
        }
        let mut pts = square_boundary(k);
        for _ in 0..3 {
            let side = k as f64;
            pts.push([
                rng.gen_range(0.1..side - 0.1),
                rng.gen_range(0.1..side - 0.1),
            ]);
        }
        check(
            &pts,
            &format!("square boundary {k} with inner points"),
            &mut tally,
        );
    }
    for case in 0..60 {
        let (w, h) = (rng.gen_range(1..30), rng.gen_range(1..30));
        let mut pts: Vec<Point> = (0..w).map(|i| [i as f64, 0.0]).collect();
        pts.extend((0..h).map(|j| [w as f64, j as f64]));
        pts.extend((0..w).map(|i| [(w - i) as f64, h as f64]));
        pts.extend((0..h).map(|j| [0.0, (h - j) as f64]));
        check(&pts, &format!("rectangle {w}x{h}, case {case}"), &mut tally);
    }
    // Runs with gaps on one line, or on two parallel lines, apexes on both
    // sides of each: several chains a line once the apexes' fans end.
    for case in 0..150 {
        let mut pts = Vec::new();
        let lines = [vec![0.0], vec![0.0, 3.0], vec![0.0, 1e-3]][case % 3].clone();
        for &y in &lines {
            let mut x = 0;
            for _ in 0..rng.gen_range(2..5) {
                let run = rng.gen_range(2..25);
                pts.extend((x..x + run).map(|i| [i as f64, y]));
                x += run + rng.gen_range(1..8);
            }
            for _ in 0..rng.gen_range(2..6) {
                let above = [1.0, -1.0, 0.5, -7.0][rng.gen_range(0..4)];
                pts.push([rng.gen_range(-2..x + 2) as f64, y + above]);
            }
        }
        check(
            &pts,
            &format!("runs on {} lines, case {case}", lines.len()),
            &mut tally,
        );
    }
    for k in [400, 1000] {
        let mut pts: Vec<Point> = (0..k).map(|i| [i as f64, 0.0]).collect();
        pts.extend([[(k / 3) as f64, 1.0], [(2 * k / 3) as f64, -1.0]]);
        check(&pts, &format!("run of {k} with two apexes"), &mut tally);
    }
    // A grid's rows (every row a line) with points above and below.
    for (w, h) in [(30, 4), (12, 12), (40, 2)] {
        let mut pts = grid(w, h, 1.0);
        pts.extend([[w as f64 / 3.0, -1.5], [w as f64 / 2.0, h as f64 + 0.5]]);
        check(&pts, &format!("grid {w}x{h} with apexes"), &mut tally);
    }
    // Two concentric sampled circles, aligned or rotated by half a step.
    for n in [6, 8, 13, 32, 60, 200] {
        for (inner, turn) in [(0.5, 0.0), (0.9, 0.5), (0.999, 0.0)] {
            let mut pts = sampled_circle(n, 1000.0);
            let step = std::f64::consts::TAU / n as f64;
            pts.extend((0..n).map(|i| {
                let a = (i as f64 + turn) * step;
                [1000.0 * inner * a.cos(), 1000.0 * inner * a.sin()]
            }));
            check(
                &pts,
                &format!("two circles n={n} inner {inner} turn {turn}"),
                &mut tally,
            );
        }
    }
    // Heavy duplicates: 3000 points, 20 distinct.
    let distinct = uniform_in_square(&mut rng, 20, 1.0);
    let pts: Vec<Point> = (0..3000).map(|i| distinct[(i * 7) % 20]).collect();
    check(&pts, "3000 points, 20 distinct", &mut tally);
    // A cluster in a 2·10⁻⁹ box (the former 2⁻³⁰ grids' finest cells) plus two far points.
    let mut pts = uniform_in_square(&mut rng, 300, 1e-9);
    pts.extend([[-0.5, -0.5], [0.5, -0.2]]);
    check(&pts, "300 points in a 1e-9 box plus two", &mut tally);
    assert!(tally.sets >= 300, "{tally:?}");
    // Squares and rectangles without inner points go to the convex algorithm.
    assert!(tally.dispatched[0] >= 180, "{tally:?}");
    assert!(tally.dispatched[1] >= 110, "{tally:?}");
}

/// The convex polygon with integer corners `corners` (ccw, strictly convex),
/// scaled by `m + 1` so that `per_side[i]` points on side `i` (`0 ≤
/// per_side[i] ≤ m`, evenly spaced) have exact integer coordinates.
fn subdivided_polygon(corners: &[Point], per_side: &[usize], m: usize) -> Vec<Point> {
    let s = (m + 1) as f64;
    let k = corners.len();
    let mut pts = Vec::new();
    for i in 0..k {
        let (a, b) = (corners[i], corners[(i + 1) % k]);
        pts.push([a[0] * s, a[1] * s]);
        let c = per_side[i];
        for t in 1..=c {
            // At integer multiples u < m + 1 of (b - a): exact, strictly
            // between the scaled corners.
            let step = ((m + 1) / (c + 1)) as f64;
            let u = t as f64 * step;
            pts.push([a[0] * s + u * (b[0] - a[0]), a[1] * s + u * (b[1] - a[1])]);
        }
    }
    pts
}

/// Weakly convex inputs (all points on the hull boundary, some on
/// hull edges), edge for edge against the oracle, asserting that the
/// dispatcher ran the convex algorithm: triangles, squares, rectangles and
/// random lattice polygons with 1–50 points per side, regular integer
/// polygons and integer circles with their edge midpoints, huge, tiny and
/// negative coordinates, shuffled, with duplicates. Sampled circles with
/// rounded midpoints are checked too (convex or not as rounding decides).
#[test]
fn weakly_convex_inputs_run_the_convex_algorithm() {
    let mut rng = StdRng::seed_from_u64(SEED_WEAKLY_CONVEX);
    let mut tally = Tally::default();
    let maps: [(&str, PointMap); 4] = [
        ("plain", |p| p),
        ("huge", |p| {
            [
                p[0] * 2f64.powi(150) - 2f64.powi(160),
                -p[1] * 2f64.powi(150),
            ]
        }),
        ("tiny", |p| [p[1] * 2f64.powi(-100), p[0] * 2f64.powi(-100)]),
        ("negative", |p| [-3.0 * p[0] - 1e6, -5.0 * p[1] - 7.0]),
    ];
    let shapes: [(&str, Vec<Point>); 5] = [
        ("triangle", vec![[0.0, 0.0], [7.0, 0.0], [2.0, 5.0]]),
        ("thin triangle", vec![[0.0, 0.0], [40.0, 1.0], [1.0, 1.0]]),
        (
            "square",
            vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]],
        ),
        (
            "rectangle",
            vec![[0.0, 0.0], [9.0, 0.0], [9.0, 2.0], [0.0, 2.0]],
        ),
        (
            "octagon",
            vec![
                [2.0, 0.0],
                [4.0, 0.0],
                [6.0, 2.0],
                [6.0, 4.0],
                [4.0, 6.0],
                [2.0, 6.0],
                [0.0, 4.0],
                [0.0, 2.0],
            ],
        ),
    ];
    // A triangle with one side subdivided is a fan: the dispatcher takes
    // the shortcut, and `check` still runs the convex algorithm on it.
    let convex_run = |pts: &[Point], what: &str, fan: bool, tally: &mut Tally| {
        let expected = if fan {
            GreedyAlgorithm::Fan
        } else {
            GreedyAlgorithm::Convex
        };
        assert_eq!(check(pts, what, tally), Some(expected), "{what}");
    };
    for (name, corners) in &shapes {
        let k = corners.len();
        for case in 0..12 {
            let m = [1, 2, 3, 5, 50][case % 5];
            let per_side: Vec<usize> = (0..k)
                .map(|i| match case {
                    0..=4 => m,
                    5 => usize::from(i == 0),
                    _ => rng.gen_range(0..=m.min(20 + case)),
                })
                .collect();
            if per_side.iter().all(|&c| c == 0) {
                continue;
            }
            let base = subdivided_polygon(corners, &per_side, m);
            let fan = k == 3 && per_side.iter().filter(|&&c| c > 0).count() == 1;
            for (how, map) in maps {
                let mut pts: Vec<Point> = base.iter().map(|&p| map(p)).collect();
                let what = format!("{name} {per_side:?} {how}");
                convex_run(&pts, &what, fan, &mut tally);
                // Shuffled, with duplicates: the same distinct set.
                for i in (1..pts.len()).rev() {
                    pts.swap(i, rng.gen_range(0..=i));
                }
                for _ in 0..3 {
                    pts.push(pts[rng.gen_range(0..pts.len())]);
                }
                convex_run(&pts, &format!("{what} shuffled"), fan, &mut tally);
            }
        }
    }
    // Random lattice polygons: the strict corners of the hull of random
    // integer points, every side subdivided.
    for case in 0..120 {
        let n = rng.gen_range(3..25);
        let pts = lattice_points(&mut rng, n, -20..20, -20..20);
        let ps = PointSet::new(&pts).unwrap();
        let corners = strict_hull_corners(ps.points());
        if corners.len() < 3 {
            continue;
        }
        let m = [1, 4, 10][case % 3];
        let per_side: Vec<usize> = (0..corners.len()).map(|_| rng.gen_range(0..=m)).collect();
        let pts = subdivided_polygon(&corners, &per_side, m);
        let (how, map) = maps[case % 4];
        let pts: Vec<Point> = pts.into_iter().map(map).collect();
        let what = format!("lattice polygon case {case} {how}");
        if per_side.iter().all(|&c| c == 0) {
            check(&pts, &what, &mut tally);
        } else {
            let fan = corners.len() == 3 && per_side.iter().filter(|&&c| c > 0).count() == 1;
            convex_run(&pts, &what, fan, &mut tally);
        }
    }
    // Integer circles with the midpoints of (some of) their sides: exactly
    // cocircular corners, straight angles at the midpoints.
    for r in [5i64, 25, 65, 325] {
        let c = strict_hull_corners(&circle(r));
        let k = c.len();
        for every in [1, 2, 3] {
            let mut pts = Vec::new();
            for i in 0..k {
                let (a, b) = (c[i], c[(i + 1) % k]);
                pts.push([2.0 * a[0], 2.0 * a[1]]);
                if i % every == 0 {
                    pts.push([a[0] + b[0], a[1] + b[1]]);
                }
            }
            convex_run(
                &pts,
                &format!("circle r={r} midpoints every {every}"),
                false,
                &mut tally,
            );
        }
    }
    // Sampled regular polygons with rounded midpoints: the dispatcher may
    // pick any algorithm; the edges must still be the oracle's.
    for n in [3, 4, 5, 6, 8, 12, 30, 100] {
        let c = sampled_circle(n, 1000.0);
        let mut pts = Vec::new();
        for i in 0..n {
            let (a, b) = (c[i], c[(i + 1) % n]);
            pts.push(a);
            pts.push([(a[0] + b[0]) / 2.0, (a[1] + b[1]) / 2.0]);
        }
        check(&pts, &format!("sampled {n}-gon with midpoints"), &mut tally);
    }
    // Larger: a square with 100 points a side, a triangle with 300 on one.
    convex_run(
        &square_boundary(100),
        "square boundary 100",
        false,
        &mut tally,
    );
    let mut pts: Vec<Point> = (0..300).map(|i| [i as f64, 0.0]).collect();
    pts.push([150.0, 1.0]);
    convex_run(&pts, "run of 300 with one apex", true, &mut tally);
    assert!(tally.sets >= 500, "{tally:?}");
    assert!(tally.dispatched[1] >= 480, "{tally:?}");
}

/// The strict corners of the convex hull of distinct points, ccw.
fn strict_hull_corners(points: &[Point]) -> Vec<Point> {
    let mut pts = points.to_vec();
    pts.sort_unstable_by(|p, q| p[0].total_cmp(&q[0]).then(p[1].total_cmp(&q[1])));
    pts.dedup();
    let cross = |o: Point, a: Point, b: Point| {
        (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])
    };
    let mut hull: Vec<Point> = Vec::new();
    for pass in 0..2 {
        let start = hull.len();
        let iter: Box<dyn Iterator<Item = &Point>> = if pass == 0 {
            Box::new(pts.iter())
        } else {
            Box::new(pts.iter().rev())
        };
        for &p in iter {
            // Small integers: the cross product is exact.
            while hull.len() >= start + 2
                && cross(hull[hull.len() - 2], hull[hull.len() - 1], p) <= 0.0
            {
                hull.pop();
            }
            hull.push(p);
        }
        hull.pop();
    }
    hull
}

/// Clusters far below the bounding box's resolution, small, edge
/// for edge against the oracle: a tiny cluster plus two far points at
/// several scales (below the grids' former 2⁻³⁰ cells, near and below their
/// 2⁻⁶² cells, next to the origin), nested clusters at three scales,
/// clusters at a 10¹⁵ offset (a lattice of the doubles' spacing there) and
/// heavy duplicates of three points plus a few others.
#[test]
fn clusters_far_below_the_box_resolution_match_the_oracle() {
    let mut rng = StdRng::seed_from_u64(SEED_CLUSTER_SCALES);
    let mut tally = Tally::default();
    fn in_box(rng: &mut StdRng, n: usize, centre: Point, side: f64) -> Vec<Point> {
        (0..n)
            .map(|_| {
                [
                    centre[0] + side * rng.gen_range(-0.5..0.5),
                    centre[1] + side * rng.gen_range(-0.5..0.5),
                ]
            })
            .collect()
    }
    for (case, side) in [1e-6, 1e-9, 1e-12, 1e-15, 1e-18].into_iter().enumerate() {
        for n in [30, 120, 298] {
            let mut pts = in_box(&mut rng, n, [0.5, 0.5], side);
            pts.extend([[0.0, 0.0], [1.0, 0.3]]);
            check(&pts, &format!("{n} in a {side:e} box plus two"), &mut tally);
            // The same next to the origin (doubles far finer than the cells).
            let mut pts = in_box(&mut rng, n, [side, -side], side);
            pts.extend([[-1.0, -1.0], [1.0, 0.3]]);
            check(
                &pts,
                &format!("{n} in a {side:e} box at 0, case {case}"),
                &mut tally,
            );
        }
    }
    // Nested: a cluster inside a cluster inside a big box.
    for case in 0..6 {
        let centre = [0.3, 0.7];
        let mut pts = in_box(&mut rng, 60, centre, 1.0);
        pts.extend(in_box(&mut rng, 100, centre, [1e-4, 1e-6][case % 2]));
        pts.extend(in_box(
            &mut rng,
            100,
            centre,
            [1e-9, 1e-12, 1e-14][case % 3],
        ));
        check(&pts, &format!("nested clusters, case {case}"), &mut tally);
    }
    // At a 10¹⁵ offset: doubles there are 1/8 apart; a lattice of 1/8 (and
    // ties of every kind) in a box 10¹¹ wide, and a coarser cluster.
    for case in 0..6 {
        let o = 1e15;
        let mut pts: Vec<Point> = (0..200)
            .map(|_| {
                [
                    o + 0.125 * rng.gen_range(0..40) as f64,
                    o + 0.125 * rng.gen_range(0..40) as f64,
                ]
            })
            .collect();
        if case % 2 == 1 {
            pts.extend(in_box(&mut rng, 60, [o + 1e6, o - 1e6], 1e4));
        }
        pts.extend([[o - 1e11, o - 3e10], [o + 1e11, o + 2e10], [o, o + 1e11]]);
        check(&pts, &format!("cluster at 1e15, case {case}"), &mut tally);
    }
    // Heavy duplicates of three points plus a few others.
    for case in 0..4 {
        let three = in_box(&mut rng, 3, [0.0, 0.0], 1.0);
        let copies = [300, 3000, 30_000, 100_000][case];
        let mut pts: Vec<Point> = (0..copies).map(|i| three[i % 3]).collect();
        pts.extend(in_box(&mut rng, 2 + case, [0.0, 0.0], 2.0));
        check(
            &pts,
            &format!("{copies} copies of 3 points, case {case}"),
            &mut tally,
        );
    }
    assert!(tally.sets >= 40, "{tally:?}");
    assert!(tally.general >= 40, "{tally:?}");
}
