//! Every reported length, area and angle is the exact value correctly
//! rounded (`kernel::metrics`, `Stats`), checked against the oracle's
//! rational arithmetic (`optri_oracle::measures`): random triangles at every
//! scale of the kernel's range, needles, values on and next to rounding
//! boundaries, decimal input, and the agreement of certified bounds with
//! the measures they bound.

use optri::internals::kernel::{area_scaled, length_scaled, total_length_scaled, Rounding};
use optri::io::{read, InputFormat, ReadOptions, Source, TriangulationReport};
use optri::kernel::metrics::{angle_deg, area, length, total_length};
use optri::kernel::Point;
use optri::{triangulate, Criterion, Measure, PointSet, Triangulation};
use optri_oracle::measures as oracle;
use rand::{rngs::StdRng, Rng, SeedableRng};
use std::cmp::Ordering;

/// A coordinate of magnitude about `2^e` (random sign and mantissa).
fn coordinate(rng: &mut StdRng, e: i32) -> f64 {
    let sign = if rng.gen_bool(0.5) { 1.0 } else { -1.0 };
    sign * rng.gen_range(0.5..1.0) * 2f64.powi(e)
}

/// A random triangle at scale `2^e` around a random centre at scale
/// `2^(e + shift)` (so differences lose bits to the centre's magnitude).
fn triangle(rng: &mut StdRng, e: i32, shift: i32) -> [Point; 3] {
    let centre = [coordinate(rng, e + shift), coordinate(rng, e + shift)];
    [0; 3].map(|_| {
        [
            centre[0] + coordinate(rng, e),
            centre[1] + coordinate(rng, e),
        ]
    })
}

/// Checks the three measures of one triangle (and its scaled lengths and
/// areas for `k`) against the oracle.
fn check_triangle(t: [Point; 3], k: i32) {
    let [a, b, c] = t;
    assert_eq!(length(a, b), oracle::length(a, b, 0), "{t:?}");
    assert_eq!(area(a, b, c), oracle::area(a, b, c, 0), "{t:?}");
    assert_eq!(
        length_scaled(b, c, k),
        oracle::length(b, c, k),
        "{t:?} k {k}"
    );
    assert_eq!(
        area_scaled(a, b, c, k),
        oracle::area(a, b, c, k),
        "{t:?} k {k}"
    );
    assert_eq!(angle_deg(a, b, c), oracle::angle_degrees(a, b, c), "{t:?}");
}

#[test]
fn random_triangles_at_every_scale_match_the_oracle() {
    let mut rng = StdRng::seed_from_u64(2030);
    let mut cases = 0;
    // Scales from near the kernel's smallest coordinate 2^-142 to near its
    // largest 2^201, with centres up to 2^40 times farther out.
    for e in [-140, -120, -60, -20, 0, 1, 30, 100, 150, 160] {
        for shift in [0, 10, 40] {
            if e + shift > 200 {
                continue;
            }
            for _ in 0..12 {
                let t = triangle(&mut rng, e, shift);
                check_triangle(t, rng.gen_range(-15..=15));
                cases += 1;
            }
        }
    }
    assert!(cases >= 300, "{cases}");
}

#[test]
fn needles_have_positive_areas_and_proper_angles() {
    // With the far corner at (−2^40, −2^40) the naive float evaluation
    // rounds the products and cancels the doubled area to 0 (and the
    // smallest angle to 0°); exactly it is 1/2048.
    let m = 2f64.powi(40);
    let needle = [
        [-m, -m],
        [1.0 / 128.0, 3.0 / 128.0],
        [5.0 / 128.0, 7.0 / 128.0],
    ];
    let [a, b, c] = needle;
    let naive = 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])).abs();
    assert_eq!(naive, 0.0);
    assert_eq!(area(a, b, c), 1.0 / 4096.0);
    check_triangle(needle, 3);
    let ps = PointSet::new(&needle).unwrap();
    let t = Triangulation::from_triangles(&ps, vec![[0, 2, 1]]).unwrap();
    let s = t.stats();
    assert_eq!(s.min_area, 1.0 / 4096.0);
    assert!(s.min_angle_deg > 0.0, "{s:?}");
    assert!(s.max_angle_deg < 180.0, "{s:?}");
    assert_eq!(
        s.min_angle_deg,
        oracle::angle_degrees(a, c, b).min(oracle::angle_degrees(c, b, a))
    );
    // A needle with a unit height over 2^41, and one so thin (2^-340 rad
    // at 2^200) that its widest angle is within half an ulp of 180°: it
    // reports 180 honestly, while the smallest stays positive.
    let big = 2f64.powi(40);
    check_triangle([[0.0, 0.0], [big, 1.0], [2.0 * big, 1.0]], -2);
    let huge = 2f64.powi(200);
    let thin = [[0.0, 0.0], [huge, 0.0], [2.0 * huge, 2f64.powi(-140)]];
    check_triangle(thin, 0);
    let ps = PointSet::new(&thin).unwrap();
    let s = Triangulation::from_triangles(&ps, vec![[0, 1, 2]])
        .unwrap()
        .stats();
    assert!(s.min_area > 0.0 && s.min_angle_deg > 0.0, "{s:?}");
    assert_eq!(
        s.max_angle_deg,
        oracle::angle_degrees(thin[1], thin[2], thin[0])
    );
    assert_eq!(s.max_angle_deg, 180.0);
}

#[test]
fn values_on_and_next_to_rounding_boundaries() {
    let two53 = 2f64.powi(53);
    for scale in [1.0, 2f64.powi(-80), 2f64.powi(140)] {
        let p = |x: f64, y: f64| [x * scale, y * scale];
        // Length 2^53 + 1, a midpoint: ties to the even 2^53; a hair above
        // (a tiny y) rounds up, a hair below (the start moved right by an
        // ulp of 1) rounds down.
        let cases = [
            (p(-1.0, 0.0), p(two53, 0.0)),
            (p(-1.0, 0.0), p(two53, 2f64.powi(-10))),
            (p(-1.0 + 2f64.powi(-53), 0.0), p(two53, 0.0)),
            (p(-3.0, 0.0), p(two53, 0.0)),
        ];
        let expected = [two53, two53 + 2.0, two53, two53 + 4.0];
        for ((a, b), want) in cases.into_iter().zip(expected) {
            assert_eq!(length(a, b), want * scale, "{a:?} {b:?}");
            assert_eq!(length(a, b), oracle::length(a, b, 0));
        }
        // A squared length just above and below a perfect square: the
        // correctly rounded root is the same double either way, and the
        // oracle agrees.
        for y in [1e-9, 3.0] {
            let (a, b) = (p(0.0, 0.0), p(two53 - 1.0, y));
            assert_eq!(length(a, b), oracle::length(a, b, 0), "{y}");
        }
    }
    // Doubled area 2(2^53 + 1) + 2^-40: the area has a half-ulp tail plus a
    // little, so it rounds up to 2^53 + 2, where rounding the products first
    // gives 2^53.
    let y_int: u64 = 6_004_799_503_160_662; // (2^54 + 2)/3, below 2^53
    assert_eq!(3 * y_int, (1 << 54) + 2);
    let y = y_int as f64;
    let tail = 2f64.powi(-20);
    let (a, b, c) = ([0.0, 0.0], [3.0, tail], [-tail, y]);
    let naive = 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])).abs();
    assert_eq!(naive, two53);
    assert_eq!(area(a, b, c), two53 + 2.0);
    assert_eq!(area(a, b, c), oracle::area(a, b, c, 0));
    // Exactly on the midpoint: ties to even.
    assert_eq!(area(a, [3.0, 0.0], [0.0, y]), two53);
}

#[test]
fn total_lengths_are_rounded_once() {
    let mut rng = StdRng::seed_from_u64(77);
    let mut cases = 0;
    for e in [-140, -30, 0, 40, 180] {
        for n in [2, 5, 40] {
            let points: Vec<Point> = (0..n)
                .map(|_| [coordinate(&mut rng, e), coordinate(&mut rng, e)])
                .collect();
            let edges: Vec<[u32; 2]> = (0..n as u32)
                .flat_map(|i| (i + 1..n as u32).map(move |j| [i, j]))
                .collect();
            let segments: Vec<[Point; 2]> = edges
                .iter()
                .map(|&[a, b]| [points[a as usize], points[b as usize]])
                .collect();
            assert_eq!(
                total_length(&points, &edges),
                oracle::total_length(&segments, 0, false)
            );
            let k = rng.gen_range(-15..=15);
            for (mode, down) in [(Rounding::Nearest, false), (Rounding::Down, true)] {
                assert_eq!(
                    total_length_scaled(&points, &edges, k, mode),
                    oracle::total_length(&segments, k, down),
                    "k {k} {mode:?}"
                );
            }
            cases += 1;
        }
    }
    assert_eq!(cases, 15);
    // Lengths 2^52 + 1 and 2^52 (both exact) sum to the midpoint 2^53 + 1:
    // ties to even; the naive sum of the rounded lengths agrees here, but
    // adding √2 · 2^-60 must round up.
    let two52 = 2f64.powi(52);
    let points = [[-1.0, 0.0], [two52, 0.0], [0.0, 1.0], [two52, 1.0]];
    assert_eq!(total_length(&points, &[[0, 1], [2, 3]]), 2f64.powi(53));
    let tiny = 2f64.powi(-60);
    let points = [
        [-1.0, 0.0],
        [two52, 0.0],
        [0.0, 1.0],
        [two52, 1.0],
        [0.0, 0.0],
        [tiny, tiny],
    ];
    assert_eq!(
        total_length(&points, &[[0, 1], [2, 3], [4, 5]]),
        2f64.powi(53) + 2.0
    );
}

/// The stats of `t` against the oracle: measures from the exact extremes.
fn check_stats(t: &Triangulation, k: i32, what: &str) {
    let pts = t.points();
    let p = |i: u32| pts[i as usize];
    let s = if k == 0 {
        t.stats()
    } else {
        t.stats_over_power_of_ten(k)
    };
    let [a, b] = s.longest_edge;
    assert_eq!(s.max_edge_length, oracle::length(p(a), p(b), k), "{what}");
    let segments: Vec<[Point; 2]> = t.edges().iter().map(|&[a, b]| [p(a), p(b)]).collect();
    assert_eq!(
        s.total_edge_length,
        oracle::total_length(&segments, k, false),
        "{what}"
    );
    let areas: Vec<f64> = t
        .triangles()
        .iter()
        .map(|&[a, b, c]| oracle::area(p(a), p(b), p(c), k))
        .collect();
    let min = areas.iter().copied().fold(f64::INFINITY, f64::min);
    let max = areas.iter().copied().fold(0.0, f64::max);
    assert!(s.min_area > 0.0, "{what}: {s:?}");
    assert_eq!((s.min_area, s.max_area), (min, max), "{what}");
    let mut angles = Vec::new();
    for &[a, b, c] in t.triangles() {
        for (o, u, v) in [(a, b, c), (b, c, a), (c, a, b)] {
            angles.push(oracle::angle_degrees(p(o), p(u), p(v)));
        }
    }
    let min = angles.iter().copied().fold(f64::INFINITY, f64::min);
    let max = angles.iter().copied().fold(0.0, f64::max);
    assert!(s.min_angle_deg > 0.0, "{what}");
    assert_eq!((s.min_angle_deg, s.max_angle_deg), (min, max), "{what}");
    check_bottleneck_stats(t, &s, k, what);
}

/// Height, eccentricity and (with elevations) slope against the oracle's
/// independent forms (`bottleneck_measures`): the reported triangle is the
/// first of the worst, and the value is the exact one rounded once (lengths
/// over `10^k`, slopes times `10^k`).
fn check_bottleneck_stats(t: &Triangulation, s: &optri::Stats, k: i32, what: &str) {
    use optri_oracle::bottleneck_measures::{badness, Bottleneck};
    use optri_oracle::BigRational;
    let pts = t.points();
    let ps = t.point_set();
    let z: Vec<f64> = match ps.elevations() {
        Some(z) => (0..pts.len() as u32)
            .map(|i| z[ps.distinct_index(i) as usize])
            .collect(),
        None => vec![0.0; pts.len()],
    };
    let worst = |b: Bottleneck| {
        let keys: Vec<BigRational> = t
            .triangles()
            .iter()
            .map(|&tri| badness(b, pts, &z, tri))
            .collect();
        let max = keys.iter().max().unwrap().clone();
        let first = keys.iter().position(|key| *key == max).unwrap();
        (t.triangles()[first], max)
    };
    let ten = oracle::power_of_ten(2 * k);
    let (triangle, key) = worst(Bottleneck::MaxMinHeight);
    assert_eq!(s.min_height_triangle, triangle, "{what}");
    assert_eq!(s.min_height, oracle::nearest_sqrt(&(-key / &ten)), "{what}");
    let (triangle, key) = worst(Bottleneck::MinMaxEccentricity);
    assert_eq!(s.max_eccentricity_triangle, triangle, "{what}");
    let expected = if num_traits::Zero::is_zero(&key) {
        0.0
    } else {
        oracle::nearest_sqrt(&(key / &ten))
    };
    assert_eq!(s.max_eccentricity, expected, "{what}");
    match ps.elevations() {
        Some(_) => {
            let (triangle, key) = worst(Bottleneck::MinMaxSlope);
            assert_eq!(s.max_slope_triangle, Some(triangle), "{what}");
            let expected = if num_traits::Zero::is_zero(&key) {
                0.0
            } else {
                oracle::nearest_sqrt(&(key * &ten))
            };
            assert_eq!(s.max_slope, Some(expected), "{what}");
        }
        None => assert_eq!((s.max_slope, s.max_slope_triangle), (None, None), "{what}"),
    }
}

#[test]
fn stats_of_triangulations_match_the_oracle() {
    let mut rng = StdRng::seed_from_u64(5);
    let mut cases = 0;
    for (scale, shift) in [
        (1.0, 0.0),
        (2f64.powi(-130), 0.0),
        (2f64.powi(180), 0.0),
        (1.0, 2f64.powi(30)),
        (1e-3, 1e3),
    ] {
        for criterion in [
            Criterion::Delaunay,
            Criterion::Greedy,
            Criterion::MaxMinArea,
        ] {
            let pts: Vec<Point> = (0..14)
                .map(|_| {
                    [
                        shift + scale * rng.gen_range(-1.0..1.0),
                        shift + scale * rng.gen_range(-1.0..1.0),
                    ]
                })
                .collect();
            let ps = PointSet::new(&pts).unwrap();
            let s = triangulate(&ps, criterion).unwrap();
            check_stats(&s.triangulation, 0, &format!("{criterion:?} at {scale}"));
            cases += 1;
        }
    }
    // Lattice points: equal lengths, areas and angles everywhere (ties).
    let lattice = optri_oracle::inputs::grid(4, 3, 1.0);
    let ps = PointSet::new(&lattice).unwrap();
    check_stats(
        &triangulate(&ps, Criterion::Delaunay).unwrap().triangulation,
        0,
        "grid",
    );
    // Elevations: the slope is reported and chosen exactly; a tilted plane
    // gives every triangle the same slope (all tie: the first is reported).
    for (name, z) in [
        (
            "random z",
            (0..12)
                .map(|_| rng.gen_range(-5.0..5.0))
                .collect::<Vec<f64>>(),
        ),
        (
            "plane",
            lattice.iter().map(|p| 3.0 * p[0] - 2.0 * p[1]).collect(),
        ),
    ] {
        let ps = PointSet::new(&lattice)
            .unwrap()
            .with_elevations(&z)
            .unwrap();
        for criterion in [Criterion::Delaunay, Criterion::MinMaxSlope] {
            let t = triangulate(&ps, criterion).unwrap().triangulation;
            check_stats(&t, 0, &format!("{name} {criterion:?}"));
            cases += 1;
        }
    }
    assert_eq!(cases, 19);
}

#[test]
fn decimal_input_is_divided_exactly_and_rounded_once() {
    let mut rng = StdRng::seed_from_u64(15);
    let mut cases = 0;
    for places in [1u32, 3, 7, 11, 15] {
        for _ in 0..3 {
            // Integers below 10^places written with `places` decimals (so
            // below 1 and exact after scaling by 10^places).
            let limit = 10i64.pow(places.min(15)).min(1 << 52);
            let text: String = (0..9)
                .map(|_| {
                    let v = |rng: &mut StdRng| {
                        let n = rng.gen_range(-limit..limit);
                        let sign = if n < 0 { "-" } else { "" };
                        let n = n.unsigned_abs();
                        let p = 10u64.pow(places);
                        format!("{sign}{}.{:0w$}", n / p, n % p, w = places as usize)
                    };
                    format!("{} {}\n", v(&mut rng), v(&mut rng))
                })
                .collect();
            let read = read(
                Source::Text(&text),
                &ReadOptions::default().with_format(InputFormat::Text),
            )
            .unwrap();
            let k = read.scale_exponent();
            assert!(k > 0 && k <= places as i32, "{text}");
            let ps = PointSet::new(read.working_points()).unwrap();
            for criterion in [
                Criterion::Delaunay,
                Criterion::MaxMinArea,
                Criterion::MinWeight,
            ] {
                let s = triangulate(&ps, criterion).unwrap();
                let report = TriangulationReport::of_solution(&s).with_input(&read);
                let stats = report.stats();
                assert_eq!(stats, s.triangulation.stats_over_power_of_ten(k));
                check_stats(&s.triangulation, k, &format!("{criterion:?} k {k}"));
                // The document's bound agrees with the stats where it is the
                // same triangle's area.
                if criterion == Criterion::MaxMinArea && s.exact && s.bound.is_some() {
                    assert_eq!(report.bound_value(), Some(stats.min_area));
                }
                cases += 1;
            }
        }
    }
    assert_eq!(cases, 45);
}

#[test]
fn certified_bounds_equal_the_measures_they_bound() {
    let mut rng = StdRng::seed_from_u64(44);
    let (mut exact_maxmin, mut exact_minmax) = (0, 0);
    for _ in 0..60 {
        let n = rng.gen_range(6..11);
        let pts = optri_oracle::inputs::lattice_points(&mut rng, n, -40i64..40, -40i64..40);
        let Ok(ps) = PointSet::new(&pts) else {
            continue;
        };
        for criterion in [Criterion::MaxMinArea, Criterion::MinMaxArea] {
            let Ok(s) = triangulate(&ps, criterion) else {
                continue;
            };
            let (Some(bound), true) = (&s.bound, s.exact) else {
                continue;
            };
            let stats = s.triangulation.stats();
            if criterion == Criterion::MaxMinArea {
                assert_eq!(stats.min_area, bound.value, "{pts:?}");
                exact_maxmin += 1;
            } else {
                assert_eq!(stats.max_area, bound.value, "{pts:?}");
                exact_minmax += 1;
            }
        }
    }
    assert!(
        exact_maxmin >= 10 && exact_minmax >= 10,
        "{exact_maxmin} {exact_minmax}"
    );
    // Min-weight: an exact result's certified lower bound is its weight
    // rounded down, the stats its weight rounded to nearest.
    let mut exact_weights = 0;
    for _ in 0..20 {
        let pts = optri_oracle::inputs::uniform_in_square(&mut rng, 12, 100.0);
        let ps = PointSet::new(&pts).unwrap();
        let optri::internals::MinWeightRun {
            triangulation: t,
            exact,
            lower_bound: lower,
            ..
        } = optri::internals::min_weight_pipeline(&ps).unwrap();
        if !exact {
            continue;
        }
        let p = |i: u32| t.points()[i as usize];
        let segments: Vec<[Point; 2]> = t.edges().iter().map(|&[a, b]| [p(a), p(b)]).collect();
        let total = t.stats().total_edge_length;
        assert_eq!(lower, oracle::total_length(&segments, 0, true));
        assert_eq!(total, oracle::total_length(&segments, 0, false));
        assert!(lower == total || lower == total.next_down());
        exact_weights += 1;
    }
    assert!(exact_weights >= 15, "{exact_weights}");
}

#[test]
fn measures_compare_exactly_where_the_rounded_values_tie() {
    // Two triangulations of a square whose fourth corner is raised by
    // 2^-40: the diagonals differ by about 2^-41, far below what the tables
    // show, and the comparison sees it.
    let raised = 1.0 + 2f64.powi(-40);
    let pts = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, raised]];
    let ps = PointSet::new(&pts).unwrap();
    let short = Triangulation::from_triangles(&ps, vec![[0, 1, 2], [0, 2, 3]]).unwrap();
    let long = Triangulation::from_triangles(&ps, vec![[0, 1, 3], [1, 2, 3]]).unwrap();
    for (measure, expected) in [
        (Measure::MaxEdgeLength, Ordering::Less),
        (Measure::TotalEdgeLength, Ordering::Less),
        (Measure::MinArea, Ordering::Equal),
        (Measure::MaxArea, Ordering::Equal),
    ] {
        assert_eq!(
            short.compare_measure(&long, measure),
            expected,
            "{measure:?}"
        );
        assert_eq!(
            long.compare_measure(&short, measure),
            expected.reverse(),
            "{measure:?}"
        );
        assert_eq!(short.compare_measure(&short, measure), Ordering::Equal);
    }
    // Heights and eccentricities against the oracle's exact worst values
    // (its badness of a height is −h², so the order of values reverses).
    use optri_oracle::bottleneck_measures::{bottleneck, Bottleneck};
    for (measure, b) in [
        (Measure::MinHeight, Bottleneck::MaxMinHeight),
        (Measure::MaxEccentricity, Bottleneck::MinMaxEccentricity),
    ] {
        let worst = |t: &Triangulation| bottleneck(b, t.points(), &[0.0; 4], t.triangles());
        let mut expected = worst(&short).cmp(&worst(&long));
        if measure == Measure::MinHeight {
            expected = expected.reverse();
        }
        assert_eq!(
            short.compare_measure(&long, measure),
            expected,
            "{measure:?}"
        );
        assert_eq!(long.compare_measure(&short, measure), expected.reverse());
    }
    // The angles against the oracle's correctly rounded ones where they
    // differ as doubles.
    let (a, b) = (short.stats(), long.stats());
    for (measure, x, y) in [
        (Measure::MinAngle, a.min_angle_deg, b.min_angle_deg),
        (Measure::MaxAngle, a.max_angle_deg, b.max_angle_deg),
    ] {
        if x != y {
            assert_eq!(short.compare_measure(&long, measure), x.total_cmp(&y));
        }
    }
}

#[test]
fn a_weight_lower_bound_in_decimal_units_stays_a_lower_bound() {
    // Wheels whose centre face the exact search may not finish with a
    // budget of one front: the certified lower bound, a double, is divided
    // by 10^k rounding down.
    let mut checked = 0;
    for spokes in [13, 15, 17, 19, 21] {
        let text: String = (0..spokes)
            .map(|i| {
                let a = std::f64::consts::TAU * i as f64 / spokes as f64;
                format!("{:.3} {:.3}\n", 1000.0 * a.cos(), 1000.0 * a.sin())
            })
            .chain(std::iter::once("0.5 -0.25\n".to_string()))
            .collect();
        let read = read(
            Source::Text(&text),
            &ReadOptions::default().with_format(InputFormat::Text),
        )
        .unwrap();
        let k = read.scale_exponent();
        assert!(k > 0);
        let ps = PointSet::new(read.working_points()).unwrap();
        let s = optri::internals::min_weight_solution_with_budget(&ps, 1).unwrap();
        let Some(bound) = s.bound.clone() else {
            continue;
        };
        let report = TriangulationReport::of_solution(&s).with_input(&read);
        let value = report.bound_value().unwrap();
        let exact = optri_oracle::to_rational(bound.value) * oracle::power_of_ten(-k);
        assert_eq!(value, oracle::below(&exact), "{spokes} spokes");
        assert!(value <= report.stats().total_edge_length);
        checked += 1;
    }
    assert!(checked >= 3, "{checked}");
}
