//! The general area approximation against exhaustive enumeration (n ≤ 9)
//! and its own definitions: every candidate validates and is never worse
//! than Delaunay, the bound is a true bound and exact results attain it,
//! the `RNG ∪ hull` candidate is optimal among the triangulations
//! containing `RNG ∪ hull`, and Theorem 74 with Algorithm 75.

use super::*;
use crate::structures::Triangulation;
use optri_oracle as oracle;
use oracle::{to_rational, BigRational};
use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};

/// [`super::area_general`], never stopped.
fn area_general(points: &PointSet, objective: AreaBottleneck) -> Result<GeneralAreaResult> {
    super::area_general(points, objective, Settings::default(), &Stop::default())
}

/// [`super::candidates`], never stopped.
fn candidates(points: &PointSet, objective: AreaBottleneck) -> Result<Candidates<'static>> {
    super::candidates(points, objective, Settings::default(), &Stop::default())
}

/// [`super::candidates_with_cap`], never stopped.
fn candidates_with_cap(
    points: &PointSet,
    objective: AreaBottleneck,
    max_face: usize,
) -> Result<Candidates<'static>> {
    super::candidates_with_cap(
        points,
        objective,
        Settings::default(),
        max_face,
        &Stop::default(),
    )
}

const OBJECTIVES: [AreaBottleneck; 2] = [AreaBottleneck::MaxMin, AreaBottleneck::MinMax];

/// The candidates in their tie-breaking order.
const CANDIDATE_NAMES: [&str; 4] = [DELAUNAY, ALGORITHM_75, RNG_HULL_OPTIMUM, ALGORITHM_76];

/// The point-set families of the tests, by name.
const FAMILIES: [&str; 5] = ["uniform", "real", "clustered", "grid", "collinear runs"];

/// `n` points of `family` (duplicates possible: `PointSet` merges them).
fn sample(rng: &mut StdRng, family: &str, n: usize) -> Vec<Point> {
    let int = |rng: &mut StdRng, lo: i32, hi: i32| rng.gen_range(lo..hi) as f64;
    match family {
        "uniform" => (0..n)
            .map(|_| [int(rng, 0, 100), int(rng, 0, 100)])
            .collect(),
        "real" => (0..n)
            .map(|_| [rng.gen_range(0.0..1.0), rng.gen_range(0.0..1.0)])
            .collect(),
        "clustered" => {
            let centres: Vec<Point> = (0..3)
                .map(|_| [int(rng, 0, 1000), int(rng, 0, 1000)])
                .collect();
            (0..n)
                .map(|i| {
                    let c = centres[i % 3];
                    [c[0] + int(rng, -20, 21), c[1] + int(rng, -20, 21)]
                })
                .collect()
        }
        "grid" => {
            let side = ((n as f64).sqrt().ceil() as i32 + 1).max(3);
            (0..n)
                .map(|_| [int(rng, 0, side), int(rng, 0, side)])
                .collect()
        }
        "collinear runs" => {
            // Points on three lines with integer steps, plus a few others.
            let lines: Vec<(Point, Point)> = (0..3)
                .map(|_| {
                    (
                        [int(rng, 0, 50), int(rng, 0, 50)],
                        [int(rng, -3, 4), int(rng, -3, 4)],
                    )
                })
                .collect();
            (0..n)
                .map(|i| {
                    if i % 5 == 4 {
                        return [int(rng, 0, 60), int(rng, 0, 60)];
                    }
                    let (a, d) = lines[i % 3];
                    let t = int(rng, 0, 12);
                    [a[0] + t * d[0], a[1] + t * d[1]]
                })
                .collect()
        }
        _ => unreachable!(),
    }
}

/// The exact doubled bottleneck area of `triangles` (oracle).
fn value(pts: &[Point], triangles: &[[u32; 3]], objective: AreaBottleneck) -> BigRational {
    match objective {
        AreaBottleneck::MaxMin => oracle::min_twice_area(pts, triangles),
        AreaBottleneck::MinMax => oracle::max_twice_area(pts, triangles),
    }
}

fn twice_area(pts: &[Point], t: [u32; 3]) -> BigRational {
    let p = |v: u32| pts[v as usize];
    oracle::twice_area(p(t[0]), p(t[1]), p(t[2]))
}

/// The best exact bottleneck value over `triangulations` (oracle).
fn best_value<'a>(
    pts: &[Point],
    triangulations: impl Iterator<Item = &'a Vec<[u32; 3]>>,
    objective: AreaBottleneck,
) -> BigRational {
    triangulations
        .map(|t| value(pts, t, objective))
        .reduce(|a, b| {
            if at_least_as_good(objective, &a, &b) {
                a
            } else {
                b
            }
        })
        .expect("at least one triangulation")
}

/// Is `s` at least as good as `t` (exact, oracle)?
fn at_least_as_good(objective: AreaBottleneck, s: &BigRational, t: &BigRational) -> bool {
    match objective {
        AreaBottleneck::MaxMin => s >= t,
        AreaBottleneck::MinMax => s <= t,
    }
}

/// The angle at `o` is at least 30°, by the definition in rationals:
/// `u·v ≤ 0` or `4(u·v)² ≤ 3|u|²|v|²` (independent of the kernel).
fn at_least_30_rational(o: Point, a: Point, b: Point) -> bool {
    let d = |p: Point, k: usize| to_rational(p[k]) - to_rational(o[k]);
    let (ux, uy, vx, vy) = (d(a, 0), d(a, 1), d(b, 0), d(b, 1));
    let dot = ux.clone() * vx.clone() + uy.clone() * vy.clone();
    let uu = ux.clone() * ux + uy.clone() * uy;
    let vv = vx.clone() * vx + vy.clone() * vy;
    let int = |k: i64| BigRational::from_integer(k.into());
    dot <= int(0) || int(4) * dot.clone() * dot <= int(3) * uu * vv
}

fn is_thirty_degree(pts: &[Point], triangles: &[[u32; 3]]) -> bool {
    triangles.iter().all(|t| {
        let [a, b, c] = t.map(|v| pts[v as usize]);
        at_least_30_rational(a, b, c)
            && at_least_30_rational(b, c, a)
            && at_least_30_rational(c, a, b)
    })
}

fn edges_of(triangles: &[[u32; 3]]) -> std::collections::HashSet<[u32; 2]> {
    oracle::triangle_edges(triangles).into_iter().collect()
}

/// Every candidate validates and is never worse than Delaunay; the
/// `RNG ∪ hull` optimum is never worse than Algorithm 75; Algorithm 75 is
/// a 30°-triangulation when it runs; Algorithm 76 stays within `C(n, 2)`
/// flips and keeps every angle at least `DT`'s smallest; the returned
/// result is the best candidate.
#[test]
fn candidates_are_valid_and_never_worse_than_delaunay() {
    const SEED: u64 = 0xA4EA_0001;
    let mut rng = StdRng::seed_from_u64(SEED);
    let sizes = [3, 4, 5, 7, 10, 16, 30, 60, 120];
    let (mut cases, mut flipped, mut thirty) = (0, 0, 0);
    for family in FAMILIES {
        for &n in &sizes {
            for _ in 0..6 {
                let input = sample(&mut rng, family, n);
                let Ok(ps) = PointSet::new(&input) else {
                    continue;
                };
                let pts = ps.points();
                for objective in OBJECTIVES {
                    let c = candidates(&ps, objective).unwrap();
                    assert_eq!(c.list.len(), 4);
                    for (cand, name) in c.list.iter().zip(CANDIDATE_NAMES) {
                        assert_eq!(cand.name, name);
                        Triangulation::from_distinct(&ps, cand.triangles.clone())
                            .validate()
                            .unwrap_or_else(|e| panic!("{family} n={n} {name}: {e}"));
                        assert_eq!(
                            value(pts, &cand.triangles, objective),
                            twice_area(pts, cand.bottleneck)
                        );
                    }
                    let v: Vec<BigRational> = c
                        .list
                        .iter()
                        .map(|cand| value(pts, &cand.triangles, objective))
                        .collect();
                    for (k, vk) in v.iter().enumerate() {
                        assert!(
                            at_least_as_good(objective, vk, &v[0]),
                            "{family} n={n} {objective:?}: {} worse than Delaunay",
                            CANDIDATE_NAMES[k]
                        );
                    }
                    assert!(at_least_as_good(objective, &v[2], &v[1]));
                    if c.thirty_degrees {
                        assert!(is_thirty_degree(pts, &c.list[1].triangles));
                        thirty += 1;
                    } else {
                        assert_eq!(c.list[1].triangles, c.list[0].triangles);
                    }
                    let n_distinct = pts.len();
                    assert!(c.flips <= n_distinct * (n_distinct - 1) / 2);
                    flipped += (c.flips > 0) as usize;
                    let alpha = c.smallest_angle.map(|v| pts[v as usize]);
                    for t in &c.list[3].triangles {
                        for k in 0..3 {
                            let corner =
                                [t[k], t[(k + 1) % 3], t[(k + 2) % 3]].map(|v| pts[v as usize]);
                            assert_ne!(
                                compare_corner_angles(corner, alpha),
                                Ordering::Less,
                                "Algorithm 76 went below the Delaunay angle"
                            );
                        }
                    }
                    let result = area_general(&ps, objective).unwrap();
                    let best = v.iter().skip(1).fold(&v[0], |b, x| {
                        if at_least_as_good(objective, b, x) {
                            b
                        } else {
                            x
                        }
                    });
                    assert_eq!(&value(pts, &result.triangles, objective), best);
                    cases += 1;
                }
            }
        }
    }
    assert!(cases >= 500, "{cases} cases");
    assert!(flipped > 50, "Algorithm 76 flipped in only {flipped} cases");
    eprintln!(
        "{cases} cases, Algorithm 76 flipped in {flipped}, step 3 of Algorithm 75 ran in {thirty}"
    );
}

/// With the face programs capped away, the candidates are Delaunay,
/// Algorithm 75 (= Delaunay when its step 3 does not run) and
/// Algorithm 76, and the result is still valid and no worse than
/// Delaunay.
#[test]
fn face_cap_skips_the_face_programs() {
    const SEED: u64 = 0xA4EA_0005;
    let mut rng = StdRng::seed_from_u64(SEED);
    let mut capped = 0;
    for _ in 0..40 {
        let ps = PointSet::new(&sample(&mut rng, "real", 30)).unwrap();
        let pts = ps.points();
        for objective in OBJECTIVES {
            let c = candidates_with_cap(&ps, objective, 5).unwrap();
            if c.largest_face <= 5 {
                assert_eq!(c.list.len(), 4);
                continue;
            }
            let names: Vec<&str> = c.list.iter().map(|k| k.name).collect();
            if c.thirty_degrees {
                assert_eq!(names, [DELAUNAY, ALGORITHM_76]);
            } else {
                assert_eq!(names, [DELAUNAY, ALGORITHM_75, ALGORITHM_76]);
            }
            let dt = value(pts, &c.list[0].triangles, objective);
            for k in &c.list {
                Triangulation::from_distinct(&ps, k.triangles.clone())
                    .validate()
                    .unwrap();
                assert!(at_least_as_good(
                    objective,
                    &value(pts, &k.triangles, objective),
                    &dt
                ));
            }
            capped += 1;
        }
    }
    assert!(capped >= 60, "{capped}");
}

/// The bound never contradicts the exhaustive optimum, the result never
/// beats it, and `exact` results attain it (n ≤ 9).
#[test]
fn bound_is_a_true_bound_and_exact_results_are_optimal() {
    const SEED: u64 = 0xA4EA_0002;
    let mut rng = StdRng::seed_from_u64(SEED);
    let (mut cases, mut exact, mut fixtures) = (0, 0, 0);
    let mut inputs: Vec<Vec<Point>> = FIXTURES.iter().map(|f| f.to_vec()).collect();
    for i in 0..400 {
        let family = FAMILIES[i % FAMILIES.len()];
        let n = rng.gen_range(3..=9);
        inputs.push(sample(&mut rng, family, n));
    }
    for input in &inputs {
        let Ok(ps) = PointSet::new(input) else {
            continue;
        };
        let pts = ps.points();
        if pts.len() > 9 {
            continue;
        }
        let all = oracle::all_triangulations(pts);
        for objective in OBJECTIVES {
            let optimum = best_value(pts, all.iter(), objective);
            let r = area_general(&ps, objective).unwrap();
            let got = value(pts, &r.triangles, objective);
            assert!(at_least_as_good(objective, &optimum, &got));
            let bound = twice_area(pts, r.bound.expect("a hull edge"));
            assert_eq!(
                bound,
                brute_force_bound(pts, objective),
                "{objective:?} {pts:?}"
            );
            assert!(
                at_least_as_good(objective, &bound, &optimum),
                "{objective:?} bound {bound} beats the optimum {optimum} on {pts:?}"
            );
            if r.exact {
                assert_eq!(got, optimum, "exact but not optimal on {pts:?}");
                assert_eq!(got, bound);
                exact += 1;
            }
            cases += 1;
        }
        fixtures += (inputs.iter().position(|x| x == input).unwrap() < FIXTURES.len()) as usize;
    }
    assert_eq!(fixtures, FIXTURES.len());
    assert!(cases >= 600, "{cases} cases");
    assert!(exact >= 50, "only {exact} of {cases} certified");
    eprintln!("{cases} cases, {exact} certified exact");
}

/// [`certified_bound`] without settling edges by a triangulation: every hull
/// edge searched, in hull order.
fn bound_searching_every_edge(
    pts: &[Point],
    hull: &[u32],
    objective: AreaBottleneck,
) -> Option<[u32; 3]> {
    let h = hull.len();
    let mut bound: Option<[u32; 3]> = None;
    let mut inner = Vec::new();
    for e in 0..h {
        let Some(value) = edge_bound(pts, hull[e], hull[(e + 1) % h], objective, &mut inner) else {
            continue;
        };
        if tightens(pts, objective, value, bound) {
            bound = Some(value);
        }
    }
    bound
}

/// Settling hull edges by the empty triangles of a triangulation changes
/// nothing: the same bound triangle as searching every edge, with every
/// candidate triangulation, on the test families, lattices (every empty
/// triangle ties) and points near a circle (long hulls).
#[test]
fn settled_edges_leave_the_bound_unchanged() {
    const SEED: u64 = 0xA4EA_0003;
    let mut rng = StdRng::seed_from_u64(SEED);
    let mut inputs: Vec<Vec<Point>> = Vec::new();
    for i in 0..150 {
        let n = rng.gen_range(10..=120);
        inputs.push(sample(&mut rng, FAMILIES[i % FAMILIES.len()], n));
    }
    for side in [3, 4, 7, 12] {
        inputs.push(oracle::inputs::shuffled_grid(&mut rng, side, side + 2, 1.0));
    }
    for n in [20, 60, 150] {
        let mut near_circle = oracle::inputs::rounded_circle(&mut rng, n, 1000.0);
        near_circle.extend(oracle::inputs::uniform_in_box(
            &mut rng,
            n / 10,
            [-300.0, -300.0],
            [300.0, 300.0],
        ));
        inputs.push(near_circle);
    }
    let mut compared = 0;
    for input in &inputs {
        let Ok(ps) = PointSet::new(input) else {
            continue;
        };
        let pts = ps.points();
        let hull = convex_hull_cycle(pts);
        if hull.len() == pts.len() {
            continue;
        }
        for objective in OBJECTIVES {
            let expected = bound_searching_every_edge(pts, &hull, objective);
            for candidate in candidates(&ps, objective).unwrap().list {
                assert_eq!(
                    certified_bound(
                        pts,
                        &hull,
                        &candidate.triangles,
                        objective,
                        &Stop::default()
                    )
                    .unwrap(),
                    expected,
                    "{objective:?}, {} on {pts:?}",
                    candidate.name
                );
                compared += 1;
            }
        }
    }
    assert!(compared >= 900, "{compared}");
}

/// The bound of the module docs by its definition (oracle predicates):
/// over hull edges `ab` (counter-clockwise), the largest empty triangle
/// `abr` (MaxMin), of which the smallest; or the smallest triangle `abr`
/// (MinMax), of which the largest. O(h n²).
fn brute_force_bound(pts: &[Point], objective: AreaBottleneck) -> BigRational {
    let n = pts.len() as u32;
    let p = |v: u32| pts[v as usize];
    let hull = oracle::convex_hull_edges(pts);
    let per_edge = hull.iter().map(|&[a, b]| {
        // The oracle's hull edges are sorted pairs: orient them
        // counter-clockwise (every point on the left or on the line).
        let (a, b) = if (0..n).any(|r| oracle::orient(p(a), p(b), p(r)) < 0) {
            (b, a)
        } else {
            (a, b)
        };
        let inner = (0..n).filter(|&r| oracle::orient(p(a), p(b), p(r)) > 0);
        let areas = inner
            .filter(|&r| {
                objective == AreaBottleneck::MinMax
                    || (0..n).all(|q| {
                        q == a
                            || q == b
                            || q == r
                            || oracle::orient(p(a), p(b), p(q)) < 0
                            || oracle::orient(p(b), p(r), p(q)) < 0
                            || oracle::orient(p(r), p(a), p(q)) < 0
                    })
            })
            .map(|r| twice_area(pts, [a, b, r]));
        match objective {
            AreaBottleneck::MaxMin => areas.max().unwrap(),
            AreaBottleneck::MinMax => areas.min().unwrap(),
        }
    });
    match objective {
        AreaBottleneck::MaxMin => per_edge.min().unwrap(),
        AreaBottleneck::MinMax => per_edge.max().unwrap(),
    }
}

/// Small fixtures (distinct points): the square with its centre (one
/// triangulation), three convex hexagons (MaxMin / MinMax
/// doubled areas 4 / 8, 9 / 18, 94 / 309) and a lattice with an interior
/// point.
const FIXTURES: [&[Point]; 5] = [
    &[[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0], [1.0, 1.0]],
    &[
        [0.0, 0.0],
        [-1.0, 2.0],
        [0.0, 4.0],
        [2.0, 4.0],
        [3.0, 2.0],
        [2.0, 0.0],
    ],
    &[
        [0.0, 0.0],
        [0.0, 3.0],
        [2.0, 5.0],
        [5.0, 5.0],
        [7.0, 2.0],
        [6.0, 0.0],
    ],
    &[
        [-6.0, 10.0],
        [12.0, 11.0],
        [10.0, 3.0],
        [-5.0, -10.0],
        [-9.0, -8.0],
        [-12.0, 8.0],
    ],
    &[
        [0.0, 0.0],
        [3.0, 0.0],
        [0.0, 3.0],
        [3.0, 3.0],
        [1.0, 2.0],
        [2.0, 1.0],
    ],
];

#[test]
fn fixtures_have_their_known_optima() {
    let want = [(2, 2), (4, 8), (9, 18), (94, 309)];
    for (f, (maxmin, minmax)) in FIXTURES.iter().zip(want) {
        let ps = PointSet::new(f).unwrap();
        let pts = ps.points();
        let all = oracle::all_triangulations(pts);
        let best = |o: AreaBottleneck| best_value(pts, all.iter(), o);
        let int = |k: i64| BigRational::from_integer(k.into());
        assert_eq!(best(AreaBottleneck::MaxMin), int(maxmin), "{f:?}");
        assert_eq!(best(AreaBottleneck::MinMax), int(minmax), "{f:?}");
    }
    // The square with its centre has one triangulation, and the bound
    // proves it optimal for both objectives.
    let ps = PointSet::new(FIXTURES[0]).unwrap();
    for objective in OBJECTIVES {
        let r = area_general(&ps, objective).unwrap();
        assert!(r.exact, "{objective:?}");
        assert_eq!(
            twice_area(ps.points(), r.bound.unwrap()),
            BigRational::from_integer(2.into())
        );
    }
}

/// Candidate 3 is the optimum over all triangulations containing
/// `RNG ∪ hull` (exhaustive, n ≤ 9, RNG by the oracle's definition).
#[test]
fn rng_hull_candidate_is_optimal_among_triangulations_containing_rng_and_hull() {
    const SEED: u64 = 0xA4EA_0003;
    let mut rng = StdRng::seed_from_u64(SEED);
    let mut cases = 0;
    for i in 0..240 {
        let n = rng.gen_range(4..=9);
        let input = sample(&mut rng, FAMILIES[i % FAMILIES.len()], n);
        let Ok(ps) = PointSet::new(&input) else {
            continue;
        };
        let pts = ps.points();
        let mut fixed = oracle::rng_edges(pts);
        fixed.extend(
            oracle::convex_hull_edges(pts)
                .into_iter()
                .map(|[a, b]| [a.min(b), a.max(b)]),
        );
        let containing: Vec<Vec<[u32; 3]>> = oracle::all_triangulations(pts)
            .into_iter()
            .filter(|t| {
                let e = edges_of(t);
                fixed.iter().all(|f| e.contains(f))
            })
            .collect();
        assert!(!containing.is_empty(), "DT contains RNG ∪ hull");
        for objective in OBJECTIVES {
            let best = best_value(pts, containing.iter(), objective);
            let c = candidates(&ps, objective).unwrap();
            assert_eq!(value(pts, &c.list[2].triangles, objective), best, "{pts:?}");
            let e = edges_of(&c.list[2].triangles);
            assert!(fixed.iter().all(|f| e.contains(f)));
            cases += 1;
        }
    }
    assert!(cases >= 400, "{cases} cases");
}

/// Near-equilateral sets: a patch of the triangular lattice with spacing
/// 100, each point moved by up to ±`jitter` (integers, so exact).
fn lattice_patch(rng: &mut StdRng, n: usize, jitter: i32) -> Vec<Point> {
    let mut sites: Vec<Point> = Vec::new();
    for j in 0..4 {
        for i in 0..4 {
            let x = 100.0 * i as f64 + 50.0 * j as f64;
            let y = (100.0 * 3f64.sqrt() / 2.0 * j as f64).round();
            sites.push([x, y]);
        }
    }
    // n sites near a random centre site, so the patch is compact.
    let centre = sites[rng.gen_range(0..sites.len())];
    sites.sort_by(|a, b| {
        let d = |p: &Point| (p[0] - centre[0]).powi(2) + (p[1] - centre[1]).powi(2);
        d(a).total_cmp(&d(b))
    });
    sites
        .into_iter()
        .take(n)
        .map(|p| {
            [
                p[0] + rng.gen_range(-jitter..=jitter) as f64,
                p[1] + rng.gen_range(-jitter..=jitter) as f64,
            ]
        })
        .collect()
}

/// Theorem 74 by enumeration: every RNG edge (oracle definition) is in
/// every triangulation whose angles are all at least 30° (rational test);
/// and Algorithm 75, when it runs its step 3, attains the best area over
/// the enumerated 30°-triangulations.
#[test]
fn theorem_74_and_algorithm_75_by_enumeration() {
    const SEED: u64 = 0xA4EA_0074;
    let mut rng = StdRng::seed_from_u64(SEED);
    let (mut sets, mut thirty_triangulations, mut step_3) = (0, 0, 0);
    for i in 0..600 {
        let n = 6 + i % 3;
        let jitter = [1, 4, 8][(i / 3) % 3];
        let ps = PointSet::new(&lattice_patch(&mut rng, n, jitter)).unwrap();
        let pts = ps.points();
        let rng_edges = oracle::rng_edges(pts);
        let fat: Vec<Vec<[u32; 3]>> = oracle::all_triangulations(pts)
            .into_iter()
            .filter(|t| is_thirty_degree(pts, t))
            .collect();
        for t in &fat {
            let e = edges_of(t);
            for f in &rng_edges {
                assert!(
                    e.contains(f),
                    "RNG edge {f:?} missing from a 30°-triangulation of {pts:?}"
                );
            }
        }
        thirty_triangulations += fat.len();
        for objective in OBJECTIVES {
            let c = candidates(&ps, objective).unwrap();
            assert_eq!(
                c.thirty_degrees,
                !fat.is_empty(),
                "DT maximises the smallest angle"
            );
            if !c.thirty_degrees {
                continue;
            }
            let best = best_value(pts, fat.iter(), objective);
            assert_eq!(value(pts, &c.list[1].triangles, objective), best);
            step_3 += 1;
        }
        sets += 1;
    }
    assert_eq!(sets, 600);
    assert!(
        thirty_triangulations >= 150 && step_3 >= 200,
        "{thirty_triangulations} {step_3}"
    );
    eprintln!("{sets} sets, {thirty_triangulations} 30°-triangulations, Algorithm 75 step 3 in {step_3} runs");
}

/// [`super::area_general`] with an angle floor of `degrees` and an
/// approximation, never stopped.
fn with_alpha(
    points: &PointSet,
    objective: AreaBottleneck,
    degrees: Option<f64>,
    approximation: AreaApproximation,
) -> Result<GeneralAreaResult> {
    let floor = degrees.map(|d| AngleFloor::new(d).expect("a valid floor"));
    let settings = Settings {
        alpha: floor.as_ref(),
        approximation,
    };
    super::area_general(points, objective, settings, &Stop::default())
}

/// The angle at `o` against `degrees`, by the oracle's rationals and the
/// platform's tangent, independent of the kernel: `Some(true)` if at least,
/// `Some(false)` if below, `None` within 10⁻⁹ relative of `tan α` (too close
/// for this reference to decide).
fn at_least_degrees_rational(o: Point, a: Point, b: Point, degrees: f64) -> Option<bool> {
    let d = |p: Point, k: usize| to_rational(p[k]) - to_rational(o[k]);
    let (ux, uy, vx, vy) = (d(a, 0), d(a, 1), d(b, 0), d(b, 1));
    let dot = ux.clone() * vx.clone() + uy.clone() * vy.clone();
    let cross = ux * vy - uy * vx;
    let cross = if cross < BigRational::from_integer(0.into()) {
        -cross
    } else {
        cross
    };
    if dot <= BigRational::from_integer(0.into()) || degrees == 0.0 {
        return Some(true);
    }
    let tan = degrees.to_radians().tan();
    let lo = to_rational(tan * (1.0 - 1e-9));
    let hi = to_rational(tan * (1.0 + 1e-9));
    if cross >= hi * dot.clone() {
        Some(true)
    } else if cross < lo * dot {
        Some(false)
    } else {
        None
    }
}

/// Is every angle of `triangles` at least `degrees` (rationals)? `None`
/// when some corner is too close to decide.
fn is_alpha_triangulation(pts: &[Point], triangles: &[[u32; 3]], degrees: f64) -> Option<bool> {
    let mut all = true;
    for t in triangles {
        let [a, b, c] = t.map(|v| pts[v as usize]);
        for [o, p, q] in [[a, b, c], [b, c, a], [c, a, b]] {
            all &= at_least_degrees_rational(o, p, q, degrees)?;
        }
    }
    Some(all)
}

/// `DT`'s smallest angle in degrees, rounded down to a thousandth: a floor
/// that every Delaunay angle meets.
fn delaunay_floor(ps: &PointSet) -> f64 {
    let pts = ps.points();
    let g = DelaunayGraph::with_topology(pts).unwrap();
    let [o, a, b] = smallest_angle(pts, &g.triangles).map(|v| pts[v as usize]);
    (angle_deg(o, a, b) * 1000.0).floor() / 1000.0 - 0.001
}

/// With a floor α ≤ α*, every approximation's result is an
/// α-triangulation (checked in rationals), never worse than Delaunay
/// (which is one), and reports the floor; Algorithm 76 with α = α* keeps
/// today's candidate.
#[test]
fn alpha_results_keep_every_angle_at_least_alpha() {
    const SEED: u64 = 0xA4EA_00A1;
    let mut rng = StdRng::seed_from_u64(SEED);
    let mut cases = 0;
    for i in 0..60 {
        let family = FAMILIES[i % FAMILIES.len()];
        let Ok(ps) = PointSet::new(&sample(&mut rng, family, 8 + i % 30)) else {
            continue;
        };
        let pts = ps.points();
        let top = delaunay_floor(&ps);
        if top <= 0.0 {
            continue;
        }
        for fraction in [0.0, 0.4, 0.8, 1.0] {
            let alpha = (top * fraction * 1000.0).floor() / 1000.0;
            for objective in OBJECTIVES {
                let dt = value(
                    pts,
                    &candidates(&ps, objective).unwrap().list[0].triangles,
                    objective,
                );
                for &approximation in AreaApproximation::ALL {
                    let r = with_alpha(&ps, objective, Some(alpha), approximation).unwrap();
                    Triangulation::from_distinct(&ps, r.triangles.clone())
                        .validate()
                        .unwrap();
                    assert_ne!(
                        is_alpha_triangulation(pts, &r.triangles, alpha),
                        Some(false),
                        "{family} α={alpha} {approximation:?}"
                    );
                    assert!(at_least_as_good(
                        objective,
                        &value(pts, &r.triangles, objective),
                        &dt
                    ));
                    assert_eq!(r.report.alpha_degrees, Some(alpha));
                    assert!(r.report.guarantee.smallest_angle_degrees >= alpha);
                    cases += 1;
                }
            }
        }
    }
    assert!(cases >= 1500, "{cases} cases");
}

/// Theorem 74 with the floor: for α ≥ 30° the result is optimal among the
/// α-triangulations (exhaustive enumeration, angles in rationals), and says
/// so; α above α* is refused with α* in the message.
#[test]
fn alpha_from_30_degrees_is_optimal_among_alpha_triangulations() {
    const SEED: u64 = 0xA4EA_00A2;
    let mut rng = StdRng::seed_from_u64(SEED);
    let (mut checked, mut refused, mut undecided) = (0, 0, 0);
    for i in 0..300 {
        let n = 6 + i % 3;
        let ps = PointSet::new(&lattice_patch(&mut rng, n, [1, 4, 8][i % 3])).unwrap();
        let pts = ps.points();
        let top = delaunay_floor(&ps);
        let all = oracle::all_triangulations(pts);
        for alpha in [30.0, 31.5, 33.25, top] {
            if alpha < 30.0 {
                continue;
            }
            if alpha > top + 0.002 {
                for objective in OBJECTIVES {
                    let Err(Error::InvalidOption { option, message }) =
                        with_alpha(&ps, objective, Some(alpha), AreaApproximation::Best)
                    else {
                        panic!("α = {alpha} above α* ≈ {top} accepted");
                    };
                    assert_eq!(option, "alpha");
                    assert!(message.contains("α*"), "{message}");
                    refused += 1;
                }
                continue;
            }
            let fat: Option<Vec<&Vec<[u32; 3]>>> = all
                .iter()
                .filter_map(|t| match is_alpha_triangulation(pts, t, alpha) {
                    Some(true) => Some(Some(t)),
                    Some(false) => None,
                    None => Some(None),
                })
                .collect();
            let Some(fat) = fat else {
                undecided += 1;
                continue;
            };
            assert!(!fat.is_empty(), "Delaunay is an α-triangulation");
            for objective in OBJECTIVES {
                let best = best_value(pts, fat.iter().copied(), objective);
                for approximation in [
                    AreaApproximation::Best,
                    AreaApproximation::RngHull,
                    AreaApproximation::Thesis75,
                ] {
                    let r = with_alpha(&ps, objective, Some(alpha), approximation).unwrap();
                    assert_eq!(
                        value(pts, &r.triangles, objective),
                        best,
                        "{pts:?} α={alpha}"
                    );
                    let kind = r.report.guarantee.kind;
                    assert!(
                        kind == "optimal" || kind == "optimal-among-alpha-triangulations",
                        "{kind}"
                    );
                    checked += 1;
                }
            }
        }
    }
    assert!(checked >= 600 && refused >= 100, "{checked} {refused}");
    assert!(undecided <= 5, "{undecided}");
}

/// A sweep of the floor on a lattice (α* = 45° exactly: right isosceles
/// triangles): every α from 0° to 45° gives an α-triangulation, 45° itself
/// included (an exact tie), and anything above is refused naming α*.
#[test]
fn alpha_sweep_on_a_lattice() {
    let grid: Vec<Point> = (0..36)
        .map(|k| [f64::from(k % 6), f64::from(k / 6)])
        .collect();
    let ps = PointSet::new(&grid).unwrap();
    let pts = ps.points();
    let mut alpha = 0.0;
    while alpha <= 45.0 {
        for objective in OBJECTIVES {
            for &approximation in AreaApproximation::ALL {
                let r = with_alpha(&ps, objective, Some(alpha), approximation).unwrap();
                Triangulation::from_distinct(&ps, r.triangles.clone())
                    .validate()
                    .unwrap();
                let floor = AngleFloor::new(alpha).unwrap();
                for t in &r.triangles {
                    let [a, b, c] = t.map(|v| pts[v as usize]);
                    assert!(floor.admits_triangle(a, b, c));
                }
                assert_ne!(
                    is_alpha_triangulation(pts, &r.triangles, alpha.min(44.9)),
                    Some(false)
                );
                assert_eq!(r.report.delaunay_smallest_angle_degrees, 45.0);
            }
        }
        alpha += 7.5;
    }
    for alpha in [45.000001, 50.0, 89.0] {
        let Err(Error::InvalidOption { message, .. }) = with_alpha(
            &ps,
            AreaBottleneck::MaxMin,
            Some(alpha),
            AreaApproximation::Best,
        ) else {
            panic!("α = {alpha} accepted");
        };
        assert!(message.contains("α* = 45°"), "{message}");
    }
}

/// Each approximation computes its own candidates; `best` without a floor
/// is today's result; the guarantee of a result that is not optimal
/// carries Theorem 81's factors.
#[test]
fn approximations_choose_their_candidates() {
    const SEED: u64 = 0xA4EA_00A3;
    let mut rng = StdRng::seed_from_u64(SEED);
    let mut approximations = 0;
    for _ in 0..20 {
        let ps = PointSet::new(&sample(&mut rng, "uniform", 40)).unwrap();
        for objective in OBJECTIVES {
            let default = area_general(&ps, objective).unwrap();
            let best = with_alpha(&ps, objective, None, AreaApproximation::Best).unwrap();
            assert_eq!(default.triangles, best.triangles);
            assert_eq!(best.report.candidates, CANDIDATE_NAMES);
            let expect = [
                (AreaApproximation::Thesis75, ALGORITHM_75),
                (AreaApproximation::Thesis76, ALGORITHM_76),
                (AreaApproximation::RngHull, RNG_HULL_OPTIMUM),
            ];
            for (approximation, name) in expect {
                let r = with_alpha(&ps, objective, None, approximation).unwrap();
                assert_eq!(r.report.candidates, [name]);
                assert_eq!(r.report.candidate, name);
                assert_eq!(r.report.choice, approximation);
                if r.report.guarantee.kind == "approximation" {
                    assert!(!r.report.guarantee.theorem_81.is_empty());
                    assert!(r.report.guarantee.statement.contains("Theorem 81"));
                    approximations += 1;
                }
            }
            if best.exact {
                assert_eq!(best.report.guarantee.kind, "optimal");
                assert!(best.report.guarantee.theorem_81.is_empty());
            }
        }
    }
    assert!(approximations >= 20, "{approximations}");
}

/// Faces beyond the cap are reported, not skipped silently.
#[test]
fn skipped_candidates_are_reported() {
    let mut rng = StdRng::seed_from_u64(0xA4EA_00A4);
    let ps = PointSet::new(&sample(&mut rng, "real", 30)).unwrap();
    let settings = Settings::default();
    let c = super::candidates_with_cap(&ps, AreaBottleneck::MaxMin, settings, 3, &Stop::default())
        .unwrap();
    assert!(c.largest_face > 3);
    let names: Vec<&str> = c.skipped.iter().map(|s| s.0).collect();
    assert!(names.contains(&RNG_HULL_OPTIMUM), "{names:?}");
    assert!(c.skipped.iter().all(|s| s.1.contains("cap of 3")));
    let r = best_of(&ps, AreaBottleneck::MaxMin, settings, &c, &Stop::default()).unwrap();
    assert_eq!(r.report.skipped, c.skipped);
}
