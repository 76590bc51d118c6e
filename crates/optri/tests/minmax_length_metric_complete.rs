//! Minmax-length under normed metrics on *complete* regions (Edelsbrunner &
//! Tan 1991, §5.3/§6 run under §7's metrics, so convex position stays
//! O(n²)): points in convex position, where the RNG of the hull is
//! one or a few complete rng-polygons. The quadratic algorithm (forced on
//! every region, and the product) against independent references:
//! exhaustive enumeration of all triangulations with the oracle's own exact
//! norm lengths (n ≤ 9), and §3's cubic program on every region (larger n).
//! §7 gives no proof that §5–§6 carry over, so the tests also assert that
//! the quadratic algorithm's safety nets never fire (`fallbacks`,
//! `case_2_hull_fallbacks` zero) and that §5.3/§6 actually ran
//! (`regions_by_5_3`, `case_1`, `case_2`).

use optri::internals::minmax_length_under_with;
use optri::kernel::Point;
use optri::{triangulate_with, Criterion, Diagnostics, Options, PointSet};
use optri_oracle::inputs::{
    circle_at_random_angles, convex_by_construction, integer_circle_points, perturbed_circle,
    sampled_circle, ConvexShape,
};
#[path = "common/metrics.rs"]
mod metrics;
use metrics::{longest_edge_key, metrics_with_oracle_norms};
use rand::{rngs::StdRng, Rng, SeedableRng};

const SEED_SMALL: u64 = 1121;
const SEED_LARGE: u64 = 1122;
const SEED_SWEEP: u64 = 1123;

/// A strictly convex lattice polygon with many edges: the primitive vectors
/// `(a, b)`, `|a|, |b| ≤ m`, sorted by angle and summed. Its edge vectors
/// come in symmetric families, so L1 and L∞ lengths tie in large classes.
fn lattice_polygon(m: i64) -> Vec<Point> {
    fn gcd(a: i64, b: i64) -> i64 {
        if b == 0 {
            a.abs()
        } else {
            gcd(b, a % b)
        }
    }
    let mut dirs: Vec<[i64; 2]> = Vec::new();
    for a in -m..=m {
        for b in -m..=m {
            if (a, b) != (0, 0) && gcd(a, b) == 1 {
                dirs.push([a, b]);
            }
        }
    }
    dirs.sort_by(|u, v| {
        let (tu, tv) = (
            (u[1] as f64).atan2(u[0] as f64),
            (v[1] as f64).atan2(v[0] as f64),
        );
        tu.total_cmp(&tv)
    });
    let mut p = [0i64, 0];
    dirs.iter()
        .map(|d| {
            p = [p[0] + d[0], p[1] + d[1]];
            [p[0] as f64, p[1] as f64]
        })
        .collect()
}

/// A regular `n`-gon turned by `turn`, scaled by `scale` and moved by
/// `shift` (huge and negative coordinates).
fn moved_polygon(n: usize, turn: f64, scale: f64, shift: Point) -> Vec<Point> {
    (0..n)
        .map(|i| {
            let a = turn + std::f64::consts::TAU * i as f64 / n as f64;
            [scale * a.cos() + shift[0], scale * a.sin() + shift[1]]
        })
        .collect()
}

/// Random points in convex position: sorted random angles on an ellipse.
fn random_ellipse(rng: &mut StdRng, n: usize) -> Vec<Point> {
    let (a, b) = (rng.gen_range(1.0..3.0), rng.gen_range(0.3..1.0));
    let mut t: Vec<f64> = (0..n)
        .map(|_| rng.gen_range(0.0..std::f64::consts::TAU))
        .collect();
    t.sort_by(f64::total_cmp);
    t.iter().map(|t| [a * t.cos(), b * t.sin()]).collect()
}

/// The safety nets stayed silent; returns the `regions_by_5_3` count.
fn assert_no_fallback(d: &Diagnostics, what: &str) -> u64 {
    assert_eq!(d.get("fallbacks"), Some(0), "{what}");
    assert_eq!(d.get("case_2_hull_fallbacks"), Some(0), "{what}");
    assert_eq!(d.get("case_2_pocket_fallbacks"), Some(0), "{what}");
    d.get("regions_by_5_3").unwrap()
}

/// Convex sets of 4 to 9 points: regular polygons (all chords tie in
/// pairs), cocircular integer points, lattice polygons, random ellipse
/// points, near-cocircular and huge/negative ones.
fn small_sets(rng: &mut StdRng) -> Vec<(String, Vec<Point>)> {
    let mut v = Vec::new();
    for n in 4..=9 {
        v.push((format!("regular {n}"), sampled_circle(n, 1.0)));
        v.push((
            format!("huge negative {n}"),
            moved_polygon(n, 0.3, 1e12, [-3e12, -7e11]),
        ));
        v.push((format!("ellipse {n}"), random_ellipse(rng, n)));
        v.push((
            format!("near-cocircular {n}"),
            perturbed_circle(rng, n, 1e-9),
        ));
    }
    v.push(("integer circle r=5 (12 points, 9 taken)".into(), {
        let mut c = integer_circle_points(5);
        c.truncate(9);
        c
    }));
    v.push(("lattice polygon m=1".into(), lattice_polygon(1)));
    v.push((
        "square".into(),
        vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]],
    ));
    v.push((
        "octagon with unit sides".into(),
        vec![
            [1.0, 0.0],
            [2.0, 0.0],
            [3.0, 1.0],
            [3.0, 2.0],
            [2.0, 3.0],
            [1.0, 3.0],
            [0.0, 2.0],
            [0.0, 1.0],
        ],
    ));
    for i in 0..4 {
        let n = rng.gen_range(5..=9);
        let p = convex_by_construction(rng, n, ConvexShape::Lens, false);
        v.push((format!("lens {i}"), p));
    }
    v
}

#[test]
fn convex_sets_equal_exhaustive_enumeration_without_fallback() {
    let mut rng = StdRng::seed_from_u64(SEED_SMALL);
    let sets = small_sets(&mut rng);
    let (mut cases, mut by_5_3) = (0, 0);
    for (metric, norm) in metrics_with_oracle_norms() {
        for (name, pts) in &sets {
            let ps = PointSet::new(pts).unwrap();
            let want = norm.exhaustive_minmax(ps.points());
            let product = triangulate_with(
                &ps,
                Criterion::MinMaxLength,
                &Options::default().with_metric(metric.clone()),
            )
            .unwrap();
            product.triangulation.validate().unwrap();
            assert_eq!(
                longest_edge_key(&norm, &product.triangulation),
                want,
                "{metric} on {name}"
            );
            let (t, d) = minmax_length_under_with(&ps, &metric, Some(0)).unwrap();
            t.validate().unwrap();
            assert_eq!(
                longest_edge_key(&norm, &t),
                want,
                "{metric} quadratic on {name}: {pts:?}"
            );
            by_5_3 += assert_no_fallback(&d, &format!("{metric} on {name}"));
            cases += 1;
        }
    }
    assert!(cases >= 5 * 30, "{cases}");
    eprintln!("{cases} cases, {by_5_3} regions by §5.3");
    assert!(by_5_3 >= 4 * 20, "§5.3 ran on {by_5_3} regions");
}

/// Convex sets of 30 to 300 points.
fn large_sets(rng: &mut StdRng) -> Vec<(String, Vec<Point>)> {
    vec![
        ("regular 120".into(), sampled_circle(120, 1.0)),
        (
            "random angles 200".into(),
            circle_at_random_angles(rng, 200, 1e3),
        ),
        (
            "near-cocircular 300".into(),
            perturbed_circle(rng, 300, 1e-9),
        ),
        (
            "perturbed circle 150".into(),
            perturbed_circle(rng, 150, 1e-3),
        ),
        ("ellipse 250".into(), random_ellipse(rng, 250)),
        ("integer circle r=65".into(), integer_circle_points(65)),
        ("lattice polygon m=4".into(), lattice_polygon(4)),
        ("lattice polygon m=6".into(), lattice_polygon(6)),
        (
            "huge negative 160".into(),
            moved_polygon(160, 0.1, 1e12, [-3e12, -7e11]),
        ),
        (
            "lens 100".into(),
            convex_by_construction(rng, 100, ConvexShape::Lens, false),
        ),
        (
            "lens with collinear midpoints 60".into(),
            convex_by_construction(rng, 60, ConvexShape::Lens, true),
        ),
        ("dented circle 240".into(), dented_circle(rng, 240)),
    ]
}

/// Random angles on a circle of radius 1000, every eighth point pulled in
/// by a random fraction of the sagitta of its gap: complete regions with
/// reflex corners whose RNG chords are not all Delaunay edges (the
/// ear-clipped tiling of `RngPolygon::ear_clipped`).
fn dented_circle(rng: &mut StdRng, n: usize) -> Vec<Point> {
    let mut angles: Vec<f64> = (0..n)
        .map(|_| rng.gen_range(0.0..std::f64::consts::TAU))
        .collect();
    angles.sort_by(f64::total_cmp);
    (0..n)
        .map(|i| {
            let a = angles[i];
            let r = if i % 8 == 3 {
                let gap = angles[(i + 1) % n] - angles[(i + n - 1) % n];
                1000.0 * (1.0 - rng.gen_range(0.0..3.0) * (1.0 - (gap.abs() / 2.0).cos()))
            } else {
                1000.0
            };
            [r * a.cos(), r * a.sin()]
        })
        .collect()
}

#[test]
fn convex_sets_equal_the_cubic_program_without_fallback() {
    let mut rng = StdRng::seed_from_u64(SEED_LARGE);
    let sets = large_sets(&mut rng);
    let (mut by_5_3, mut case_1, mut case_2, mut ear_clipped) = (0, 0, 0, 0);
    for (metric, norm) in metrics_with_oracle_norms() {
        for (name, pts) in &sets {
            let ps = PointSet::new(pts).unwrap();
            let (cubic, _) = minmax_length_under_with(&ps, &metric, None).unwrap();
            cubic.validate().unwrap();
            let want = longest_edge_key(&norm, &cubic);
            for from in [0, 16] {
                let (t, d) = minmax_length_under_with(&ps, &metric, Some(from)).unwrap();
                t.validate().unwrap();
                assert_eq!(
                    longest_edge_key(&norm, &t),
                    want,
                    "{metric} from {from} on {name}"
                );
                by_5_3 += assert_no_fallback(&d, &format!("{metric} on {name}"));
                case_1 += d.get("case_1").unwrap();
                case_2 += d.get("case_2").unwrap();
                ear_clipped += d.get("complete_regions_outside_mesh").unwrap_or(0);
            }
        }
    }
    eprintln!(
        "{by_5_3} regions by §5.3, case 1: {case_1}, case 2: {case_2}, ear-clipped: {ear_clipped}"
    );
    assert!(by_5_3 >= 2 * 4 * 8, "§5.3 ran on {by_5_3} regions");
    assert!(ear_clipped > 0, "no region was ear-clipped");
    assert!(
        case_1 > 0 && case_2 > 0,
        "case 1: {case_1}, case 2: {case_2}"
    );
}

/// The large tier: convex sets up to 2000 points under every metric, the
/// quadratic product against the cubic program. Run with `--ignored
/// --release`.
#[test]
#[ignore]
fn convex_sets_equal_the_cubic_program_up_to_2000_points() {
    let mut rng = StdRng::seed_from_u64(SEED_SWEEP);
    let sets: Vec<(String, Vec<Point>)> = vec![
        (
            "perturbed circle 2000".into(),
            perturbed_circle(&mut rng, 2000, 1e-3),
        ),
        (
            "random angles 1000".into(),
            circle_at_random_angles(&mut rng, 1000, 1e3),
        ),
        ("regular 1000".into(), sampled_circle(1000, 1.0)),
        ("lattice polygon m=14".into(), lattice_polygon(14)),
        ("ellipse 1500".into(), random_ellipse(&mut rng, 1500)),
    ];
    for (metric, norm) in metrics_with_oracle_norms() {
        for (name, pts) in &sets {
            let ps = PointSet::new(pts).unwrap();
            let (cubic, _) = minmax_length_under_with(&ps, &metric, None).unwrap();
            let want = longest_edge_key(&norm, &cubic);
            let (t, d) = minmax_length_under_with(&ps, &metric, Some(16)).unwrap();
            t.validate().unwrap();
            assert_eq!(longest_edge_key(&norm, &t), want, "{metric} on {name}");
            let by_5_3 = assert_no_fallback(&d, &format!("{metric} on {name}"));
            eprintln!(
                "{metric} on {name} ({} points): {by_5_3} regions by §5.3",
                pts.len()
            );
        }
    }
}
