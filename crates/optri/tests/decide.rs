//! Area decisions through the request layer, against independent optima:
//! optri-oracle's Klincsek program on convex polygons and its enumeration of
//! every triangulation on small point sets. Yes at the optimum (with a
//! witness whose bottleneck meets the threshold exactly), no just past it
//! (the next double, and an exact decimal one digit past), on convex lenses,
//! convex polygons with collinear sides, simple polygons, general sets
//! where the approximation decides, and decimal input.

use optri::io::{read, triangulation_from_json, Input, ReadInput, ReadOptions, Source, Threshold};
use optri::request::{Request, Task};
use optri::Error;
use optri_oracle::inputs::{convex_lens, uniform_in_square};
use optri_oracle::klincsek::{klincsek, MaxMinArea, MinMaxArea};
use optri_oracle::{all_triangulations, twice_area, BigInt, BigRational};
use rand::rngs::StdRng;
use rand::SeedableRng;
use serde_json::Value;
use std::cmp::Reverse;

type Point = [f64; 2];

const SEED_LENSES: u64 = 0x1e75;
const SEED_GENERAL: u64 = 0x9e7e;

/// The decision document for `criterion` at the threshold `text`.
fn decide(input: ReadInput, criterion: &str, text: &str) -> Value {
    let threshold = Threshold::parse("threshold", text).unwrap();
    let task = if criterion == "maxmin-area" {
        Task::decide(criterion, Some(threshold), None)
    } else {
        Task::decide(criterion, None, Some(threshold))
    }
    .unwrap();
    Request::new(input, task).run().unwrap().to_json()
}

fn points(p: &[Point]) -> ReadInput {
    ReadInput::from_doubles(Input::Points(p.to_vec()))
}

/// `v` as an exact rational.
fn rational(text: &str) -> BigRational {
    let (m, e) = Threshold::parse("t", text).unwrap().value();
    let ten = BigRational::from_integer(BigInt::from(10).pow(e.unsigned_abs() as u32));
    let m = BigRational::from_integer(BigInt::from(m));
    if e >= 0 {
        m * ten
    } else {
        m / ten
    }
}

/// The exact decimal text of a half-integer `doubled / 2` (integer input).
fn half(doubled: &BigRational) -> String {
    let twice = doubled.to_integer();
    let two = BigInt::from(2);
    let (q, r): (BigInt, BigInt) = (&twice / &two, &twice % &two);
    if r == BigInt::from(0) {
        q.to_string()
    } else {
        format!("{q}.5")
    }
}

/// The witness of a yes: a valid triangulation of the input whose every
/// triangle meets the threshold, checked with exact rational areas.
fn check_witness(doc: &Value, maxmin: bool, threshold: &str) {
    assert_eq!(doc["answer"], true, "{doc}");
    let witness = triangulation_from_json(&doc["witness"]).unwrap();
    witness.validate().unwrap();
    let p = witness.points();
    let twice = rational(threshold) * BigRational::from_integer(BigInt::from(2));
    // The document's coordinates are the user's; the triangulation's
    // points are those coordinates as read back.
    for t in witness.triangles() {
        let area = twice_area(p[t[0] as usize], p[t[1] as usize], p[t[2] as usize]);
        if maxmin {
            assert!(area >= twice, "{t:?} below {threshold}");
        } else {
            assert!(area <= twice, "{t:?} above {threshold}");
        }
    }
}

/// Yes at the optimum `doubled / 2` (exact decimal and, when exact, the
/// double), no at the next double past it and at a decimal just past it.
fn check_at_and_past(input: &ReadInput, criterion: &str, doubled: &BigRational) -> usize {
    let maxmin = criterion == "maxmin-area";
    let at = half(doubled);
    let doc = decide(input.clone(), criterion, &at);
    check_witness(&doc, maxmin, &at);
    assert_eq!(doc["exact"], true);
    let past_decimal = if maxmin {
        format!(
            "{at}{}1",
            if at.contains('.') {
                "0000000000"
            } else {
                ".0000000000"
            }
        )
    } else {
        let below = rational(&at) - rational("0.00000000001");
        let text = format!("{}", optri_oracle::rational_to_f64(&below));
        assert!(rational(&text) < rational(&at));
        text
    };
    let no = decide(input.clone(), criterion, &past_decimal);
    assert_eq!(no["answer"], false, "{past_decimal}: {no}");
    assert!(no["witness"].is_null());
    let value: f64 = at.parse().unwrap();
    let mut checks = 2;
    if rational(&format!("{value}")) == rational(&at) {
        let next = if maxmin {
            f64::from_bits(value.to_bits() + 1)
        } else {
            f64::from_bits(value.to_bits() - 1)
        };
        let yes = decide(input.clone(), criterion, &format!("{value}"));
        assert_eq!(yes["answer"], true);
        let no = decide(input.clone(), criterion, &format!("{next}"));
        assert_eq!(no["answer"], false, "{next}");
        checks += 2;
    }
    checks
}

#[test]
fn convex_lenses_are_decided_at_and_just_past_their_optima() {
    let mut rng = StdRng::seed_from_u64(SEED_LENSES);
    let mut checks = 0;
    for n in [5, 8, 11, 14, 17] {
        let lens = convex_lens(&mut rng, n);
        // Klincsek needs the polygon order: sort around the centroid.
        let c = lens
            .iter()
            .fold([0.0, 0.0], |a, p| [a[0] + p[0], a[1] + p[1]]);
        let mut order: Vec<u32> = (0..n as u32).collect();
        order.sort_by(|&a, &b| {
            let angle = |i: u32| {
                let p = lens[i as usize];
                (p[1] * n as f64 - c[1]).atan2(p[0] * n as f64 - c[0])
            };
            angle(a).total_cmp(&angle(b))
        });
        let (Reverse(maxmin), _) = klincsek(&lens, &order, MaxMinArea).unwrap();
        let (minmax, _) = klincsek(&lens, &order, MinMaxArea).unwrap();
        checks += check_at_and_past(&points(&lens), "maxmin-area", &maxmin);
        checks += check_at_and_past(&points(&lens), "minmax-area", &minmax);
        // The same lens as a polygon.
        let ring: Vec<Point> = order.iter().map(|&i| lens[i as usize]).collect();
        let polygon = ReadInput::from_doubles(Input::Polygon(ring));
        checks += check_at_and_past(&polygon, "maxmin-area", &maxmin);
        let doc = decide(polygon, "maxmin-area", &half(&maxmin));
        assert!(doc["method"].as_str().unwrap().contains("Algorithm 49"));
    }
    assert!(checks >= 40, "{checks}");
}

/// The optimum over every triangulation (enumerated): the doubled MaxMin
/// and MinMax areas.
fn enumerated_optima(p: &[Point]) -> (BigRational, BigRational) {
    let mut best = None::<(BigRational, BigRational)>;
    for t in all_triangulations(p) {
        let areas: Vec<BigRational> = t
            .iter()
            .map(|t| twice_area(p[t[0] as usize], p[t[1] as usize], p[t[2] as usize]))
            .collect();
        let small = areas.iter().min().unwrap().clone();
        let large = areas.iter().max().unwrap().clone();
        best = Some(match best {
            None => (small, large),
            Some((s, l)) => (s.max(small), l.min(large)),
        });
    }
    best.unwrap()
}

#[test]
fn convex_polygons_with_collinear_sides_go_through_the_polygon_program() {
    // A 3×3 grid's hull: a square with a midpoint on each side, plus an
    // octagon-like ring with collinear runs.
    let square = vec![
        [0.0, 0.0],
        [1.0, 0.0],
        [2.0, 0.0],
        [2.0, 1.0],
        [2.0, 2.0],
        [1.0, 2.0],
        [0.0, 2.0],
        [0.0, 1.0],
    ];
    let run = vec![
        [0.0, 0.0],
        [3.0, 0.0],
        [6.0, 0.0],
        [8.0, 2.0],
        [8.0, 5.0],
        [5.0, 7.0],
        [2.0, 7.0],
        [0.0, 4.0],
    ];
    for ring in [square, run] {
        let (maxmin, minmax) = enumerated_optima(&ring);
        check_at_and_past(&points(&ring), "maxmin-area", &maxmin);
        check_at_and_past(&points(&ring), "minmax-area", &minmax);
        let polygon = ReadInput::from_doubles(Input::Polygon(ring.clone()));
        check_at_and_past(&polygon, "maxmin-area", &maxmin);
        check_at_and_past(&polygon, "minmax-area", &minmax);
    }
}

#[test]
fn simple_polygons_are_decided_by_their_exact_optimum() {
    let l_shape = vec![
        [0.0, 0.0],
        [4.0, 0.0],
        [4.0, 1.0],
        [1.0, 1.0],
        [1.0, 3.0],
        [0.0, 3.0],
    ];
    let comb = vec![
        [0.0, 0.0],
        [6.0, 0.0],
        [6.0, 4.0],
        [5.0, 4.0],
        [4.0, 1.0],
        [3.0, 4.0],
        [2.0, 1.0],
        [1.0, 4.0],
        [0.0, 4.0],
    ];
    for ring in [l_shape, comb] {
        let input = ReadInput::from_doubles(Input::Polygon(ring));
        for criterion in ["maxmin-area", "minmax-area"] {
            let optimum = Request::new(input.clone(), Task::triangulate(criterion).unwrap())
                .run()
                .unwrap()
                .to_json();
            assert_eq!(optimum["exact"], true);
            let witness = triangulation_from_json(&optimum).unwrap();
            let p = witness.points();
            let areas = witness
                .triangles()
                .iter()
                .map(|t| twice_area(p[t[0] as usize], p[t[1] as usize], p[t[2] as usize]));
            let doubled = if criterion == "maxmin-area" {
                areas.min().unwrap()
            } else {
                areas.max().unwrap()
            };
            check_at_and_past(&input, criterion, &doubled);
            let doc = decide(input.clone(), criterion, &half(&doubled));
            // The document's threshold is the reported measure.
            let measure = if criterion == "maxmin-area" {
                "min_area"
            } else {
                "max_area"
            };
            assert_eq!(doc["threshold"], optimum["stats"][measure]);
        }
    }
}

#[test]
fn general_sets_are_decided_where_the_approximation_settles_the_threshold() {
    let mut rng = StdRng::seed_from_u64(SEED_GENERAL);
    let (mut decided, mut unknown, mut sets) = (0, 0, 0);
    for _ in 0..12 {
        let p: Vec<Point> = uniform_in_square(&mut rng, 8, 1.0)
            .into_iter()
            .map(|q| [(q[0] * 64.0).round(), (q[1] * 64.0).round()])
            .collect();
        let set = optri::PointSet::new(&p).unwrap();
        if set.len() < 8 || optri_oracle::convex_hull_edges(&p).len() == p.len() {
            continue;
        }
        sets += 1;
        let (maxmin, minmax) = enumerated_optima(&p);
        for (criterion, optimum) in [("maxmin-area", &maxmin), ("minmax-area", &minmax)] {
            let maxmin = criterion == "maxmin-area";
            let halves = BigRational::new(BigInt::from(1), BigInt::from(2));
            // At the optimum, and a half unit past it on either side.
            for (text, truth) in [
                (half(optimum), true),
                (
                    half(&if maxmin {
                        optimum + &halves + &halves
                    } else {
                        optimum - &halves - &halves
                    }),
                    false,
                ),
                (
                    half(&if maxmin {
                        optimum - &halves - &halves
                    } else {
                        optimum + &halves + &halves
                    }),
                    true,
                ),
            ] {
                let doc = decide(points(&p), criterion, &text);
                match doc["answer"].as_bool() {
                    Some(answer) => {
                        assert_eq!(answer, truth, "{criterion} {text}: {doc}");
                        if answer {
                            check_witness(&doc, maxmin, &text);
                        }
                        decided += 1;
                    }
                    None => {
                        assert_eq!(doc["exact"], false);
                        unknown += 1;
                    }
                }
            }
        }
    }
    assert!(sets >= 6, "{sets}");
    assert!(decided > unknown, "{decided} decided, {unknown} unknown");
}

#[test]
fn decimal_input_is_decided_on_its_decimal_areas() {
    // Coordinates in tenths: areas are decimals no double equals.
    let text = "0.1 0.1\n0.7 0.1\n0.9 0.4\n0.6 0.9\n0.2 0.7\n";
    let input = read(Source::Text(text), &ReadOptions::default()).unwrap();
    let optimum = Request::new(input.clone(), Task::triangulate("maxmin-area").unwrap())
        .run()
        .unwrap()
        .to_json();
    assert_eq!(optimum["coordinate_arithmetic"], "decimal-exact");
    let reported = optimum["stats"]["min_area"].as_f64().unwrap();
    let at = format!("{reported}");
    let yes = decide(input.clone(), "maxmin-area", &at);
    assert_eq!(yes["answer"], true, "{yes}");
    assert_eq!(yes["threshold_decimal"], at.as_str());
    assert_eq!(
        yes["witness"]["stats"]["min_area"],
        optimum["stats"]["min_area"]
    );
    let past = format!("{at}00000000000000000001");
    assert_eq!(decide(input.clone(), "maxmin-area", &past)["answer"], false);
    let next = f64::from_bits(reported.to_bits() + 1);
    assert_eq!(
        decide(input, "maxmin-area", &format!("{next}"))["answer"],
        false
    );
}

#[test]
fn bad_thresholds_and_bounds_are_refused() {
    for text in ["nan", "inf", "-1", "0x10", "", "1.2.3", "1e"] {
        let e = Threshold::parse("at_least", text).unwrap_err();
        assert!(
            matches!(
                e,
                Error::InvalidOption {
                    option: "at_least",
                    ..
                }
            ),
            "{e}"
        );
    }
    for value in [f64::NAN, f64::INFINITY, -0.5] {
        assert!(Threshold::from_f64("at_most", value).is_err());
    }
    assert_eq!(Threshold::from_f64("t", 0.1).unwrap().value(), (1, -1));
    assert_eq!(Threshold::from_f64("t", -0.0).unwrap().value(), (0, 0));
    let t = || Some(Threshold::parse("t", "1").unwrap());
    assert!(Task::decide("maxmin-area", t(), None).is_ok());
    assert!(Task::decide("minmax-area", None, t()).is_ok());
    for (criterion, at_least, at_most) in [
        ("maxmin-area", None, t()),
        ("minmax-area", t(), None),
        ("maxmin-area", t(), t()),
        ("maxmin-area", None, None),
        ("delaunay", t(), None),
    ] {
        let e = Task::decide(criterion, at_least, at_most).unwrap_err();
        assert!(matches!(e, Error::InvalidOption { .. }), "{e}");
    }
    assert!(matches!(
        Task::decide("nope", t(), None),
        Err(Error::UnknownName { .. })
    ));
    // Zero admits every triangulation; a threshold beyond every area none.
    let square = [[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]];
    assert_eq!(decide(points(&square), "maxmin-area", "0")["answer"], true);
    assert_eq!(
        decide(points(&square), "maxmin-area", "1e400")["answer"],
        false
    );
    assert_eq!(
        decide(points(&square), "minmax-area", "1e-400")["answer"],
        false
    );
    assert_eq!(decide(points(&square), "minmax-area", "2")["answer"], true);
}
