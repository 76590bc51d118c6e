//! Minmax-length under normed metrics (Edelsbrunner & Tan 1991, §7) against
//! independent references: exhaustive enumeration of all triangulations with
//! the oracle's own exact norm lengths (n ≤ 9), and §3's cubic program on
//! every region (larger n), on random and degenerate sets. Also the Euclidean
//! path is unchanged, and the registry refuses metrics where they mean nothing.

use optri::internals::minmax_length_under_with;
use optri::kernel::{Metric, Point};
use optri::{triangulate_with, Criterion, Error, Options, PointSet, UnsupportedReason};
use optri_oracle::inputs::{
    circle_r5_ccw, collinear_runs, convex_lens, grid, grid_subset, integer_circle_points,
    jittered_arc, lattice_points, parabola, uniform_unit_square,
};
#[path = "common/metrics.rs"]
mod metrics;
use metrics::{longest_edge_key, metrics_with_oracle_norms};
use rand::{rngs::StdRng, Rng, SeedableRng};

const SEED_EXHAUSTIVE: u64 = 1111;
const SEED_CUBIC: u64 = 1112;
const SEED_CONVEX: u64 = 1113;
const SEED_CERTIFICATE: u64 = 1114;

fn solve(pts: &[Point], metric: &Metric) -> optri::Triangulation {
    solution(&PointSet::new(pts).unwrap(), metric).triangulation
}

/// The product's minmax-length solution under `metric`, validated.
fn solution(ps: &PointSet, metric: &Metric) -> optri::Solution {
    let s = triangulate_with(
        ps,
        Criterion::MinMaxLength,
        &Options::default().with_metric(metric.clone()),
    )
    .unwrap();
    s.triangulation.validate().unwrap();
    s
}

fn small_sets(rng: &mut StdRng) -> Vec<(String, Vec<Point>)> {
    let mut v = Vec::new();
    for i in 0..14 {
        let n = rng.gen_range(4..=9);
        v.push((format!("uniform {i}"), uniform_unit_square(rng, n)));
    }
    for i in 0..14 {
        let n = rng.gen_range(5..=9);
        v.push((format!("lattice {i}"), lattice_points(rng, n, 0..4, 0..4)));
    }
    v.push(("grid 3x3".into(), grid(3, 3, 1.0)));
    v.push(("grid 4x2".into(), grid(4, 2, 1.0)));
    v.push((
        "circle r5".into(),
        circle_r5_ccw().into_iter().take(9).collect(),
    ));
    v.push(("collinear runs".into(), {
        let mut p = collinear_runs(rng, 2..3, 3..4, 1..2);
        p.truncate(9);
        p
    }));
    v.push((
        "square with diagonal points".into(),
        vec![
            [0.0, 0.0],
            [2.0, 0.0],
            [2.0, 2.0],
            [0.0, 2.0],
            [1.0, 1.0],
            [1.0, 0.0],
            [3.0, 1.0],
        ],
    ));
    v
}

#[test]
fn equals_exhaustive_enumeration_under_every_metric() {
    let mut rng = StdRng::seed_from_u64(SEED_EXHAUSTIVE);
    let sets = small_sets(&mut rng);
    let mut cases = 0;
    for (metric, norm) in metrics_with_oracle_norms() {
        for (name, pts) in &sets {
            let ps = PointSet::new(pts).unwrap();
            let d = ps.points().to_vec();
            if optri::kernel::orient_sign(d[0], d[1], d[2]) == 0
                && d.iter()
                    .all(|&p| optri::kernel::orient_sign(d[0], d[1], p) == 0)
            {
                continue;
            }
            let want = norm.exhaustive_minmax(&d);
            let got = longest_edge_key(&norm, &solve(pts, &metric));
            assert_eq!(got, want, "{metric} on {name}: {pts:?}");
            // The cubic program on every region, and §5.1 on every convex
            // incomplete region, reach it too.
            for from in [None, Some(0)] {
                let (t, _) = minmax_length_under_with(&ps, &metric, from).unwrap();
                t.validate().unwrap();
                assert_eq!(
                    longest_edge_key(&norm, &t),
                    want,
                    "{metric} {from:?} on {name}"
                );
            }
            cases += 1;
        }
    }
    assert!(cases >= 5 * 30, "{cases}");
}

fn larger_sets(rng: &mut StdRng) -> Vec<(String, Vec<Point>)> {
    let mut v = Vec::new();
    for n in [30, 100, 300] {
        v.push((format!("uniform {n}"), uniform_unit_square(rng, n)));
    }
    v.push(("grid 12x12".into(), grid(12, 12, 1.0)));
    v.push(("grid subset 15".into(), grid_subset(rng, 15, 15, 0.6)));
    v.push(("lattice 150".into(), lattice_points(rng, 150, 0..20, 0..20)));
    v.push((
        "collinear runs".into(),
        collinear_runs(rng, 3..6, 5..15, 0..5),
    ));
    v.push(("integer circle r=25".into(), integer_circle_points(25)));
    v.push(("jittered arc".into(), jittered_arc(rng, 120)));
    v.push(("parabola".into(), parabola(60)));
    v.push(("convex lens".into(), convex_lens(rng, 80)));
    v
}

#[test]
fn equals_the_cubic_program_under_every_metric() {
    let mut rng = StdRng::seed_from_u64(SEED_CUBIC);
    let sets = larger_sets(&mut rng);
    let mut by_5_1 = 0;
    for (metric, norm) in metrics_with_oracle_norms() {
        for (name, pts) in &sets {
            let ps = PointSet::new(pts).unwrap();
            let (cubic, _) = minmax_length_under_with(&ps, &metric, None).unwrap();
            cubic.validate().unwrap();
            let want = longest_edge_key(&norm, &cubic);
            assert_eq!(
                longest_edge_key(&norm, &solve(pts, &metric)),
                want,
                "{metric} on {name}"
            );
            let (quad, d) = minmax_length_under_with(&ps, &metric, Some(0)).unwrap();
            quad.validate().unwrap();
            assert_eq!(
                longest_edge_key(&norm, &quad),
                want,
                "{metric} §5.1 on {name}"
            );
            assert_eq!(d.get("fallbacks"), Some(0), "{metric} on {name}");
            by_5_1 += d.get("regions_by_5_1").unwrap();
        }
    }
    assert!(by_5_1 >= 15, "§5.1 ran on {by_5_1} regions");
}

/// The hull certificate (the Euclidean Delaunay triangulation when no edge of
/// it is longer in the metric than the longest hull segment) against the
/// exhaustive oracle (n ≤ 9) and the cubic program on every region (larger
/// sets), on random, lattice, grid and huge/negative-coordinate sets; both
/// outcomes of the certificate must occur under every metric.
#[test]
fn hull_certificate_is_exact_and_both_ways_occur() {
    let mut rng = StdRng::seed_from_u64(SEED_CERTIFICATE);
    let mut small = small_sets(&mut rng);
    for i in 0..12 {
        let n = rng.gen_range(5..=9);
        small.push((
            format!("lattice 0..6 {i}"),
            lattice_points(&mut rng, n, 0..6, 0..3),
        ));
    }
    // In a disk the hull segments are short, so the certificate mostly fails.
    let disk = |rng: &mut StdRng, n: usize| -> Vec<Point> {
        let mut v = Vec::new();
        while v.len() < n {
            let [x, y] = uniform_unit_square(rng, 1)[0];
            if (x - 0.5).powi(2) + (y - 0.5).powi(2) < 0.25 {
                v.push([x, y]);
            }
        }
        v
    };
    for i in 0..10 {
        let n = rng.gen_range(6..=9);
        small.push((format!("disk {i}"), disk(&mut rng, n)));
    }
    let mut large = Vec::new();
    for n in [60, 250] {
        large.push((format!("disk {n}"), disk(&mut rng, n)));
    }
    for n in [40, 120, 400] {
        large.push((format!("uniform {n}"), uniform_unit_square(&mut rng, n)));
    }
    large.push(("grid 9x6".to_string(), grid(9, 6, 1.0)));
    large.push((
        "huge negative uniform".to_string(),
        uniform_unit_square(&mut rng, 150)
            .into_iter()
            .map(|[x, y]| [x * 1e12 - 3e12, -y * 7e11])
            .collect(),
    ));
    large.push((
        "lattice 200".to_string(),
        lattice_points(&mut rng, 200, 0..30, 0..9),
    ));
    for (metric, norm) in metrics_with_oracle_norms()
        .into_iter()
        .filter(|(m, _)| !m.is_euclidean())
    {
        let (mut certified, mut solved) = (0, 0);
        for (exhaustive, (name, pts)) in small
            .iter()
            .map(|s| (true, s))
            .chain(large.iter().map(|s| (false, s)))
        {
            let ps = PointSet::new(pts).unwrap();
            let d = ps.points().to_vec();
            if d.iter()
                .all(|&p| optri::kernel::orient_sign(d[0], d[1], p) == 0)
            {
                continue;
            }
            let want = if exhaustive {
                norm.exhaustive_minmax(&d)
            } else {
                let (cubic, _) = minmax_length_under_with(&ps, &metric, None).unwrap();
                longest_edge_key(&norm, &cubic)
            };
            let s = solution(&ps, &metric);
            assert_eq!(
                longest_edge_key(&norm, &s.triangulation),
                want,
                "{metric} on {name}"
            );
            if s.diagnostics.get("regions_certified_by_bound") == Some(1) {
                certified += 1;
                assert!(s.algorithm_detail.contains("hull lower bound"), "{metric}");
            } else {
                solved += 1;
            }
        }
        assert!(
            certified >= 3 && solved >= 3,
            "{metric}: certified {certified}, solved {solved}"
        );
    }
}

/// The large tier (n up to 2000): run with `--ignored --release`.
#[test]
#[ignore]
fn equals_the_cubic_program_up_to_2000_points() {
    let mut rng = StdRng::seed_from_u64(SEED_CONVEX);
    for (metric, norm) in metrics_with_oracle_norms() {
        for pts in [
            uniform_unit_square(&mut rng, 2000),
            jittered_arc(&mut rng, 1000),
            grid(40, 40, 1.0),
        ] {
            let ps = PointSet::new(&pts).unwrap();
            let (cubic, _) = minmax_length_under_with(&ps, &metric, None).unwrap();
            let want = longest_edge_key(&norm, &cubic);
            assert_eq!(
                longest_edge_key(&norm, &solve(&pts, &metric)),
                want,
                "{metric}"
            );
        }
    }
}

#[test]
fn euclidean_metric_is_the_euclidean_product() {
    let mut rng = StdRng::seed_from_u64(SEED_CONVEX);
    for _ in 0..5 {
        let pts = uniform_unit_square(&mut rng, 200);
        let ps = PointSet::new(&pts).unwrap();
        let a = optri::triangulate(&ps, optri::Criterion::MinMaxLength)
            .unwrap()
            .triangulation;
        let b = solve(&pts, &Metric::euclidean());
        assert_eq!(a.triangles(), b.triangles());
    }
}

#[test]
fn metrics_are_refused_where_they_mean_nothing() {
    let ps = PointSet::new(&grid(3, 3, 1.0)).unwrap();
    let opts = Options::default().with_metric(Metric::l1());
    for c in [
        Criterion::Delaunay,
        Criterion::MaxMinArea,
        Criterion::MinMaxArea,
        Criterion::MinWeight,
        Criterion::Greedy,
    ] {
        match triangulate_with(&ps, c, &opts) {
            Err(Error::Unsupported {
                reason: UnsupportedReason::MetricNotSupported { metric, taken_by },
                ..
            }) => {
                assert_eq!(metric, "l1");
                assert_eq!(taken_by, ["minmax-length", "hull", "rng", "mst"]);
            }
            other => panic!("{c:?}: {other:?}"),
        }
    }
    // The hull is the same under every norm.
    for metric in [Metric::l1(), Metric::linf()] {
        let opts = Options::default().with_metric(metric);
        let under = optri::graph(ps.input_points(), optri::GraphKind::Hull, &opts).unwrap();
        let euclidean = optri::graph(
            ps.input_points(),
            optri::GraphKind::Hull,
            &Options::default(),
        )
        .unwrap();
        assert_eq!(under.edges, euclidean.edges);
        assert_eq!(under.edges.len(), 8);
    }
    let e = Metric::parse("polygon:1,0,0,1,-1,0,0,-2").unwrap_err();
    assert!(e.to_string().contains("centrally symmetric"), "{e}");
    let e = Metric::parse("polygon:1,0,1,1,1,2,-1,0,-1,-1,-1,-2").unwrap_err();
    assert!(e.to_string().contains("convex"), "{e}");
}
