//! Exact symmetries change nothing: scaling every
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
//!
//! Simple polygons too: every polygon criterion gives the same triangles
//! (as ring positions) under exact scalings and translations, and the
//! constrained Delaunay triangulation also wherever the ring starts (its
//! cocircular faces are fanned from a vertex chosen by coordinates), on
//! cocircular polygons (the integer points of a circle, with and without
//! the centre), rectangles, lattice histograms full of cocircular unit
//! squares and random star polygons.

use optri::{graph, triangulate, Criterion, Error, GraphKind, Options, PointSet, SimplePolygon};
use optri_oracle::polygon as op;
use optri_oracle::{constrained_delaunay_check, inputs};
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

/// Triangles as a set: each sorted, then the list.
fn sorted_triangles(triangles: &[[u32; 3]]) -> Vec<[u32; 3]> {
    let mut t: Vec<[u32; 3]> = triangles
        .iter()
        .map(|t| {
            let mut t = *t;
            t.sort_unstable();
            t
        })
        .collect();
    t.sort_unstable();
    t
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
            Ok(Outcome::Triangles(sorted_triangles(
                solution.triangulation.triangles(),
            )))
        }
        Err(e) => Ok(Outcome::Failed(std::mem::discriminant(&e))),
    }
}

fn graph_outcome(points: &[Point], kind: GraphKind) -> Option<Vec<[u32; 2]>> {
    let set = PointSet::new(points).ok()?;
    graph(set.input_points(), kind, &Options::default())
        .ok()
        .map(|g| {
            let mut edges = g.edges;
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
        Criterion::MinMaxLength,
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

/// A polygon family, drawn from a seed: cocircular (an arc of the integer
/// points of `x² + y² = 25` in order, sometimes closed through the centre),
/// a rectangle, a lattice histogram, or a random star.
fn polygon_family(kind: u8, seed: u64, size: usize) -> Vec<Point> {
    let mut rng = StdRng::seed_from_u64(seed);
    match kind % 4 {
        0 => {
            let circle = inputs::circle_r5_ccw();
            let start = rng.gen_range(0..circle.len());
            let keep = 3 + size % 10;
            let mut ring: Vec<Point> = (0..keep)
                .map(|k| circle[(start + k) % circle.len()])
                .collect();
            if keep < circle.len() && rng.gen_bool(0.5) {
                ring.push([0.0, 0.0]);
            }
            ring
        }
        1 => {
            let (w, h) = (rng.gen_range(1..20) as f64, rng.gen_range(1..20) as f64);
            vec![[0.0, 0.0], [w, 0.0], [w, h], [0.0, h]]
        }
        2 => {
            let lattice = rng.gen_bool(0.7);
            op::histogram(&mut rng, 2 + size % 6, 4, lattice)
        }
        _ => op::star_polygon(&mut rng, 5 + size % 12, 100.0),
    }
}

/// The sorted triangles (each sorted) of a polygon criterion's answer, or
/// the error's variant; the constrained Delaunay triangulation is checked
/// against the oracle (every interior edge locally Delaunay).
fn polygon_outcome(ring: &[Point], criterion: Criterion) -> Result<Outcome, TestCaseError> {
    let polygon = match SimplePolygon::new(ring) {
        Ok(polygon) => polygon,
        Err(e) => return Ok(Outcome::Failed(std::mem::discriminant(&e))),
    };
    let solution = match triangulate(&polygon, criterion) {
        Ok(solution) => solution,
        Err(e) => return Ok(Outcome::Failed(std::mem::discriminant(&e))),
    };
    solution
        .triangulation
        .validate()
        .map_err(|e| TestCaseError::fail(format!("{criterion:?}: invalid: {e}")))?;
    let triangles = solution.triangulation.triangles();
    if criterion == Criterion::Delaunay {
        let n = ring.len() as u32;
        let boundary: Vec<[u32; 2]> = (0..n).map(|i| [i, (i + 1) % n]).collect();
        let checked = constrained_delaunay_check(ring, triangles, &boundary)
            .map_err(|e| TestCaseError::fail(format!("{ring:?}: {e}")))?;
        prop_assert_eq!(checked, ring.len() - 3);
    }
    Ok(Outcome::Triangles(sorted_triangles(triangles)))
}

fn polygon_answers(ring: &[Point]) -> Result<Vec<(Criterion, Outcome)>, TestCaseError> {
    Criterion::ALL
        .iter()
        .filter(|c| c.accepts(optri::InputKind::SimplePolygon))
        .map(|&c| Ok((c, polygon_outcome(ring, c)?)))
        .collect()
}

/// The polygon answers of `ring` equal those of its power-of-two scalings
/// and the given exact translations, and its constrained Delaunay
/// triangulation is the same, mapped back, for every start of the ring.
/// Returns how many transformed copies were compared.
fn check_polygon_symmetries(ring: &[Point], offsets: &[Point]) -> Result<usize, TestCaseError> {
    let base = polygon_answers(ring)?;
    let mut compared = 0;
    for &k in SCALES {
        let got = polygon_answers(&scaled(ring, k))?;
        prop_assert_eq!(&got, &base, "scale 2^{} of {:?}", k, ring);
        compared += 1;
    }
    for &offset in offsets {
        let q = translated(ring, offset).expect("the test's offsets are exact");
        let got = polygon_answers(&q)?;
        prop_assert_eq!(&got, &base, "offset {:?} of {:?}", offset, ring);
        compared += 1;
    }
    let delaunay = polygon_outcome(ring, Criterion::Delaunay)?;
    let n = ring.len();
    for start in 1..n {
        let rotated: Vec<Point> = (0..n).map(|i| ring[(i + start) % n]).collect();
        let Outcome::Triangles(t) = polygon_outcome(&rotated, Criterion::Delaunay)? else {
            return Err(TestCaseError::fail(format!("{rotated:?} failed")));
        };
        let back: Vec<[u32; 3]> = t
            .iter()
            .map(|t| t.map(|i| ((i as usize + start) % n) as u32))
            .collect();
        prop_assert_eq!(
            &Outcome::Triangles(sorted_triangles(&back)),
            &delaunay,
            "ring {:?} started at {}",
            ring,
            start
        );
        compared += 1;
    }
    Ok(compared)
}

fn polygon_symmetry_case(kind: u8, seed: u64, size: usize) -> Result<(), TestCaseError> {
    let ring = polygon_family(kind, seed, size);
    let compared = check_polygon_symmetries(&ring, &offsets(seed))?;
    prop_assert!(compared >= SCALES.len() + 2 + ring.len() - 1);
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(CASES))]

    #[test]
    fn cocircular_polygons(seed in any::<u64>(), size in 0usize..12) {
        polygon_symmetry_case(0, seed, size)?;
    }

    #[test]
    fn rectangles(seed in any::<u64>(), size in 0usize..4) {
        polygon_symmetry_case(1, seed, size)?;
    }

    #[test]
    fn lattice_histograms(seed in any::<u64>(), size in 0usize..12) {
        polygon_symmetry_case(2, seed, size)?;
    }

    #[test]
    fn star_polygons(seed in any::<u64>(), size in 0usize..12) {
        polygon_symmetry_case(3, seed, size)?;
    }
}

/// The twelve integer points `(±5, 0)`, `(0, ±5)`, `(±3, ±4)`, `(±4, ±3)`
/// of a circle as a polygon, an octagon of eight of them, and a rectangle:
/// all cocircular, so every triangulation is Delaunay and only the fan rule
/// decides; the answer is the fan from the lexicographically smallest
/// vertex, wherever the ring starts.
#[test]
fn cocircular_polygons_are_fanned_from_their_lowest_vertex() {
    let circle = inputs::circle_r5_ccw();
    let octagon: Vec<Point> = circle
        .iter()
        .step_by(3)
        .chain(circle.iter().skip(1).step_by(3))
        .copied()
        .collect();
    let mut octagon_sorted: Vec<Point> = octagon.clone();
    // The octagon's corners in counter-clockwise order.
    octagon_sorted.sort_by(|a, b| a[1].atan2(a[0]).total_cmp(&b[1].atan2(b[0])));
    for ring in [
        circle.clone(),
        octagon_sorted,
        vec![[0.0, 0.0], [7.0, 0.0], [7.0, 3.0], [0.0, 3.0]],
    ] {
        let n = ring.len();
        let lowest = (0..n)
            .min_by(|&a, &b| {
                (ring[a][0], ring[a][1])
                    .partial_cmp(&(ring[b][0], ring[b][1]))
                    .unwrap()
            })
            .unwrap() as u32;
        for start in 0..n {
            let rotated: Vec<Point> = (0..n).map(|i| ring[(i + start) % n]).collect();
            let polygon = SimplePolygon::new(&rotated).unwrap();
            let s = triangulate(&polygon, Criterion::Delaunay).unwrap();
            s.triangulation.validate().unwrap();
            let apex = ((lowest as usize + n - start) % n) as u32;
            assert_eq!(s.triangulation.triangles().len(), n - 2);
            assert!(
                s.triangulation
                    .triangles()
                    .iter()
                    .all(|t| t.contains(&apex)),
                "{ring:?} from {start}: not the fan from its lowest vertex"
            );
        }
    }
}
