//! Exact symmetries change nothing (issue 14, item 3): scaling every
//! coordinate by a power of two, translating by an amount that keeps every
//! coordinate exact, and the number of rayon threads give the *same*
//! triangles (as sets of input-index triples) for every criterion of
//! `Criterion::ALL`, and the same edges for every `GraphKind`, ties
//! included. Every decision in optri is an exact predicate or the documented
//! symbolic tie-break on a numbering that these maps preserve, so any
//! difference is a float decision that depends on magnitude (it was one:
//! spade's bulk load, see `structures/delaunay_graph.rs`).
//!
//! Property tests (proptest) over random small sets, grids, collinear runs
//! and cocircular sets from `optri_oracle::inputs`, drawn from a proptest
//! seed. The default case counts keep CI fast; `heavy_symmetry_sweep`
//! (`#[ignore]`) runs many more, larger sets.

use optri::{graph, triangulate, Criterion, Error, GraphKind, PointSet};
use optri_oracle::inputs;
use proptest::prelude::*;
use proptest::test_runner::TestCaseError;
use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};

type Point = [f64; 2];

/// Power-of-two scale exponents: small, and near both ends of the accepted
/// coordinate range 2⁻¹⁴²..2²⁰¹ for inputs with integer coordinates of
/// magnitude below 2⁸ (so every scaled non-zero coordinate stays in range).
const SCALES: &[i32] = &[-130, -60, -30, -1, 1, 40, 120, 190];

/// Cases per input family in the default run, and in the ignored sweep.
const CASES: u32 = 12;
const HEAVY_CASES: u32 = 2000;

/// What a run of one criterion gives: sorted triangles (each sorted), or
/// the error's variant.
#[derive(Debug, PartialEq)]
enum Outcome {
    Triangles(Vec<[u32; 3]>),
    Failed(std::mem::Discriminant<Error>),
}

fn criterion_outcome(points: &[Point], criterion: Criterion) -> Result<Outcome, TestCaseError> {
    let set = match PointSet::new(points) {
        Ok(set) => set,
        Err(e) => return Ok(Outcome::Failed(std::mem::discriminant(&e))),
    };
    match triangulate(&set, criterion) {
        Ok(solution) => {
            solution
                .triangulation
                .validate()
                .map_err(|e| TestCaseError::fail(format!("{criterion:?}: invalid: {e}")))?;
            let mut t: Vec<[u32; 3]> = solution
                .triangulation
                .triangles()
                .iter()
                .map(|t| {
                    let mut t = *t;
                    t.sort_unstable();
                    t
                })
                .collect();
            t.sort_unstable();
            Ok(Outcome::Triangles(t))
        }
        Err(e) => Ok(Outcome::Failed(std::mem::discriminant(&e))),
    }
}

fn graph_outcome(points: &[Point], kind: GraphKind) -> Option<Vec<[u32; 2]>> {
    let set = PointSet::new(points).ok()?;
    graph(&set, kind).ok().map(|(mut edges, _)| {
        if kind == GraphKind::Hull {
            // The hull is a cycle; its starting vertex is not a symmetry.
            edges.sort_unstable();
        }
        edges
    })
}

/// Everything the library computes for `points`, per criterion and graph.
#[derive(Debug, PartialEq)]
struct Answers {
    criteria: Vec<(Criterion, Outcome)>,
    graphs: Vec<(GraphKind, Option<Vec<[u32; 2]>>)>,
}

fn answers(points: &[Point]) -> Result<Answers, TestCaseError> {
    let mut criteria = Vec::new();
    for &c in Criterion::ALL {
        criteria.push((c, criterion_outcome(points, c)?));
    }
    let graphs = GraphKind::ALL
        .iter()
        .map(|&k| (k, graph_outcome(points, k)))
        .collect();
    Ok(Answers { criteria, graphs })
}

fn in_pool<T: Send>(threads: usize, f: impl FnOnce() -> T + Send) -> T {
    rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .expect("a rayon pool")
        .install(f)
}

/// `a + b` if it is exact (Knuth's TwoSum error term is zero), else `None`.
fn exact_sum(a: f64, b: f64) -> Option<f64> {
    let s = a + b;
    let bv = s - a;
    let av = s - bv;
    ((a - av) + (b - bv) == 0.0).then_some(s)
}

fn scaled(points: &[Point], k: i32) -> Vec<Point> {
    let s = 2f64.powi(k);
    points
        .iter()
        .map(|p| {
            let q = [p[0] * s, p[1] * s];
            // Exact: dividing back gives the original bits.
            assert_eq!([q[0] / s, q[1] / s], *p, "scaling by 2^{k} is not exact");
            q
        })
        .collect()
}

/// `points + offset`, or `None` if some coordinate would be rounded.
fn translated(points: &[Point], offset: Point) -> Option<Vec<Point>> {
    points
        .iter()
        .map(|p| Some([exact_sum(p[0], offset[0])?, exact_sum(p[1], offset[1])?]))
        .collect()
}

/// The answers for `points` equal those for every power-of-two scaling
/// (from `scales`), the given exact translations, and 1- and 2-thread
/// pools. Returns how many transformed copies were compared.
fn check_symmetries(points: &[Point], offsets: &[Point]) -> Result<usize, TestCaseError> {
    let base = in_pool(1, || answers(points))?;
    let mut compared = 0;
    let two = in_pool(2, || answers(points))?;
    prop_assert_eq!(&two, &base, "2 threads vs 1 on {:?}", points);
    compared += 1;
    for &k in SCALES {
        let q = scaled(points, k);
        let got = in_pool(2, || answers(&q))?;
        prop_assert_eq!(&got, &base, "scale 2^{} of {:?}", k, points);
        compared += 1;
    }
    for &offset in offsets {
        let q = translated(points, offset).expect("the test's offsets are exact");
        let got = in_pool(2, || answers(&q))?;
        prop_assert_eq!(&got, &base, "offset {:?} of {:?}", offset, points);
        compared += 1;
        // Dyadic coordinates: scale first, then translate by a dyadic amount
        // that keeps every coordinate exact.
        let fine = scaled(points, -20);
        let shift = [offset[0] * 2f64.powi(-7), offset[1] * 2f64.powi(-7)];
        if let Some(q) = translated(&fine, shift) {
            let got = in_pool(1, || answers(&q))?;
            prop_assert_eq!(&got, &base, "2^-20 then offset {:?} of {:?}", shift, points);
            compared += 1;
        }
    }
    Ok(compared)
}

/// An input family, drawn from a seed: the points and a label.
fn family(kind: u8, seed: u64, size: usize) -> Vec<Point> {
    let mut rng = StdRng::seed_from_u64(seed);
    match kind % 5 {
        0 => inputs::lattice_points(&mut rng, 4 + size, -60i32..60, -60i32..60),
        1 => {
            let w = 2 + size % 5;
            let h = 2 + (size / 5) % 4;
            let spacing = [1.0, 2.0, 3.0][size % 3];
            if rng.gen_bool(0.5) {
                inputs::shuffled_grid(&mut rng, w, h, spacing)
            } else {
                inputs::grid_subset(&mut rng, w + 1, h + 1, 0.7)
            }
        }
        2 => inputs::collinear_runs(&mut rng, 1..4, 2..7, 0..4),
        3 => {
            let r = [5, 25, 65][size % 3];
            let mut pts = inputs::integer_circle_points(r);
            if rng.gen_bool(0.5) {
                pts.push([0.0, 0.0]);
            }
            if pts.len() > 14 {
                // Keep the area and weight programs quick: a random arc subset.
                let keep = 6 + size % 8;
                let start = rng.gen_range(0..pts.len());
                pts.rotate_left(start);
                pts.truncate(keep);
            }
            pts
        }
        _ => inputs::lattice_points(&mut rng, 3 + size % 6, -3i32..4, -3i32..4),
    }
}

fn offsets(seed: u64) -> Vec<Point> {
    let mut rng = StdRng::seed_from_u64(seed ^ 0x5eed);
    vec![
        [
            rng.gen_range(-1000..1000) as f64,
            rng.gen_range(-1000..1000) as f64,
        ],
        [(1u64 << 40) as f64, -((1u64 << 33) as f64) + 5.0],
    ]
}

fn symmetry_case(kind: u8, seed: u64, size: usize) -> Result<(), TestCaseError> {
    let points = family(kind, seed, size);
    let compared = check_symmetries(&points, &offsets(seed))?;
    prop_assert!(compared >= 1 + SCALES.len() + 2);
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(CASES))]

    #[test]
    fn random_lattice_sets(seed in any::<u64>(), size in 0usize..14) {
        symmetry_case(0, seed, size)?;
    }

    #[test]
    fn grids(seed in any::<u64>(), size in 0usize..20) {
        symmetry_case(1, seed, size)?;
    }

    #[test]
    fn collinear_runs(seed in any::<u64>(), size in 0usize..8) {
        symmetry_case(2, seed, size)?;
    }

    #[test]
    fn cocircular_sets(seed in any::<u64>(), size in 0usize..12) {
        symmetry_case(3, seed, size)?;
    }

    #[test]
    fn tiny_crowded_sets(seed in any::<u64>(), size in 0usize..12) {
        symmetry_case(4, seed, size)?;
    }
}

/// The reported failure: minmax-length on a 30×30 integer grid picked a
/// different optimal triangulation at scales 2⁻³⁰ and 2⁻⁶⁰ (and the
/// criteria that stay fast at 900 points, and every graph).
#[test]
fn grid_30_by_30_is_the_same_at_every_scale() {
    let grid = inputs::grid(30, 30, 1.0);
    let criteria = [
        Criterion::Delaunay,
        Criterion::MinmaxLength,
        Criterion::Greedy,
    ];
    let outcomes = |pts: &[Point]| {
        let c: Vec<Outcome> = criteria
            .iter()
            .map(|&c| criterion_outcome(pts, c).unwrap())
            .collect();
        let g: Vec<_> = GraphKind::ALL
            .iter()
            .map(|&k| graph_outcome(pts, k))
            .collect();
        (c, g)
    };
    let base = in_pool(1, || outcomes(&grid));
    for k in [-130, -60, -30, -1, 1, 40, 150, 190] {
        let q = scaled(&grid, k);
        assert!(in_pool(2, || outcomes(&q)) == base, "scale 2^{k}");
    }
    let q = translated(&grid, [-12345.0, 1048576.0]).unwrap();
    assert!(in_pool(2, || outcomes(&q)) == base, "translated");
}

/// Many more and larger cases; run by hand:
/// `cargo test --release -p optri --test symmetries -- --ignored`.
#[test]
#[ignore]
fn heavy_symmetry_sweep() {
    let mut runner =
        proptest::test_runner::TestRunner::new(ProptestConfig::with_cases(HEAVY_CASES));
    runner
        .run(&(0u8..5, any::<u64>(), 0usize..40), |(kind, seed, size)| {
            symmetry_case(kind, seed, size)
        })
        .unwrap();
}
