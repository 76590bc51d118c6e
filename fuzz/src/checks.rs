//! The properties the fuzz targets check, shared with the normal test suite
//! (`crates/optri/tests/fuzz_regressions.rs` replays the committed corpus
//! and every crash found through the same functions).
//!
//! * [`check_readers`]: every input format (`optri::io::read`, as points
//!   and with polygons allowed), and the format picked by content, on
//!   arbitrary bytes returns `Ok` or an error and never panics; an error
//!   message holds no control character; an `Ok` result whose working
//!   points (the decimals scaled to integers when exact) validate as a point
//!   set or polygon triangulates (Delaunay, or the polygon's constrained
//!   Delaunay) to something `validate()` accepts, and its JSON document (in
//!   the user's values) reads back to the same triangles.
//! * [`check_criteria`]: up to 12 points decoded from the bytes (small
//!   integers, or arbitrary `f64` bit patterns): every criterion and graph
//!   returns `Ok` or an error, every `Ok` triangulation validates, and for
//!   at most 7 distinct points each exact criterion's answer is optimal
//!   against `optri-oracle`'s exhaustive enumeration.

use optri::io::{
    read, triangulation_from_json, Input, InputFormat, ReadInput, ReadOptions, Source,
    TriangulationReport,
};
use optri::{graph, triangulate, Criterion, GraphKind, Options, PointSet, SimplePolygon};
use optri_oracle as oracle;
use std::cmp::Reverse;

/// Points with more than this many vertices are only read, not solved (keeps
/// each fuzz execution short).
const SOLVE_AT_MOST: usize = 64;

/// Largest distinct-point count checked against the exhaustive oracle.
pub const ORACLE_AT_MOST: usize = 7;

pub fn check_readers(data: &[u8]) {
    let formats = InputFormat::ALL.iter().map(|&f| Some(f)).chain([None]);
    for format in formats {
        let options = ReadOptions::default().with_format(format);
        // As points, every input is points; with polygons, only a `.poly`
        // or a GeoJSON polygon may be one.
        let points = read(Source::Bytes(data), &options);
        if let Ok(got) = &points {
            assert!(
                matches!(got.input, Input::Points(_)),
                "{format:?}: a polygon read as points"
            );
        }
        let polygons = read(Source::Bytes(data), &options.with_polygons(true));
        if let Ok(got) = &polygons {
            if matches!(got.input, Input::Polygon(_)) {
                assert!(
                    matches!(got.format, Some(InputFormat::Poly | InputFormat::GeoJson)),
                    "{format:?}: a polygon from {:?}",
                    got.format
                );
            }
        }
        // Messages quote tokens escaped: no control character of the input
        // reaches a terminal.
        for e in [points.as_ref().err(), polygons.as_ref().err()]
            .into_iter()
            .flatten()
        {
            let message = e.to_string();
            assert!(
                !message.chars().any(char::is_control),
                "{format:?}: a control character in {message:?}"
            );
        }
        let Ok(got) = polygons else {
            continue;
        };
        let format = got.format.expect("a reader names its format");
        let points = got.working_points();
        assert!(!points.is_empty(), "{format:?}: Ok with no points");
        if points.len() > SOLVE_AT_MOST {
            continue;
        }
        let solved = match &got.input {
            // Elevations that conflict on duplicates are refused before any
            // run (`PointSet::with_elevations`), so there is no document.
            Input::Points(_) => PointSet::new(points)
                .ok()
                .and_then(|set| match &got.elevations {
                    Some(z) => set.with_elevations(z).ok(),
                    None => Some(set),
                })
                .map(|set| triangulate(&set, Criterion::Delaunay)),
            Input::Polygon(_) => SimplePolygon::new(points)
                .ok()
                .map(|polygon| triangulate(&polygon, Criterion::Delaunay)),
        };
        if let Some(solved) = solved {
            let s = solved.unwrap_or_else(|e| panic!("{format:?}: Delaunay failed: {e}"));
            s.triangulation
                .validate()
                .unwrap_or_else(|e| panic!("{format:?}: invalid Delaunay of {points:?}: {e}"));
            check_document_reads_back(&got, &s, format);
        }
    }
}

/// The document of `s` in the user's values reads back (validated where
/// the reader decided: on the decimals when they were exact) to the same
/// triangles.
fn check_document_reads_back(read: &ReadInput, s: &optri::Solution, format: InputFormat) {
    let document = TriangulationReport::of_solution(s)
        .with_input(read)
        .to_json();
    // Documents of user values that do not survive JSON (e.g. beyond f64's
    // range after unscaling) are not what this checks.
    if !read.input.points().iter().flatten().all(|v| v.is_finite()) {
        return;
    }
    match triangulation_from_json(&document) {
        Ok(back) => assert_eq!(
            back.triangles(),
            s.triangulation.triangles(),
            "{format:?}: the document reads back to other triangles"
        ),
        Err(e) => panic!(
            "{format:?}: the document of {:?} does not read back: {e}",
            read.input.points()
        ),
    }
}

/// Up to 12 points from the bytes: the first byte picks small integers
/// (one byte per coordinate, in -8..8) or raw `f64` bit patterns (eight
/// bytes per coordinate, anything including NaN and huge values).
pub fn decode_points(data: &[u8]) -> Vec<[f64; 2]> {
    let Some((&mode, rest)) = data.split_first() else {
        return Vec::new();
    };
    if mode % 2 == 0 {
        rest.chunks_exact(2)
            .take(12)
            .map(|c| [((c[0] % 16) as f64) - 8.0, ((c[1] % 16) as f64) - 8.0])
            .collect()
    } else {
        rest.chunks_exact(16)
            .take(12)
            .map(|c| {
                let f = |b: &[u8]| f64::from_bits(u64::from_le_bytes(b.try_into().unwrap()));
                [f(&c[..8]), f(&c[8..])]
            })
            .collect()
    }
}

pub fn check_criteria(data: &[u8]) {
    check_points(&decode_points(data));
}

/// Every criterion and graph on `points`: `Ok` or an error, every `Ok`
/// triangulation valid, and with at most [`ORACLE_AT_MOST`] distinct points
/// each result optimal by its [`optimality_check`]. Returns the criteria
/// whose optimality was checked.
pub fn check_points(points: &[[f64; 2]]) -> Vec<Criterion> {
    let mut checked = Vec::new();
    let Ok(set) = PointSet::new(points) else {
        return checked;
    };
    let set = set
        .clone()
        .with_elevations(&elevations(points))
        .unwrap_or(set);
    let distinct = set.points().to_vec();
    let small = distinct.len() <= ORACLE_AT_MOST;
    let all = if small {
        oracle::all_triangulations(&distinct)
    } else {
        Vec::new()
    };
    for &criterion in Criterion::ALL {
        let Ok(solution) = triangulate(&set, criterion) else {
            continue;
        };
        solution
            .triangulation
            .validate()
            .unwrap_or_else(|e| panic!("{criterion:?}: invalid on {points:?}: {e}"));
        if !small {
            continue;
        }
        let tris: Vec<[u32; 3]> = solution
            .triangulation
            .triangles()
            .iter()
            .map(|t| t.map(|i| set.distinct_index(i)))
            .collect();
        check_optimal(criterion, solution.exact, &distinct, &tris, &all);
        checked.push(criterion);
    }
    for &kind in GraphKind::ALL {
        let _ = graph(set.input_points(), kind, &Options::default());
    }
    checked
}

/// An elevation per point for the criteria that read one (`minmax-slope`):
/// a small integer from the coordinates' bits, so equal points agree and
/// the checks below recompute it from the distinct points.
pub fn elevations(points: &[[f64; 2]]) -> Vec<f64> {
    points
        .iter()
        .map(|p| {
            let bits = (p[0] + 0.0).to_bits() ^ (p[1] + 0.0).to_bits().rotate_left(17);
            (bits.wrapping_mul(0x9e37_79b9_7f4a_7c15) >> 62) as f64
        })
        .collect()
}

/// The bottleneck check of an edge-insertion criterion (elevations by
/// [`elevations`]).
fn bottleneck_check(
    b: oracle::bottleneck_measures::Bottleneck,
    points: &[[f64; 2]],
    tris: &[[u32; 3]],
    all: &[Vec<[u32; 3]>],
) -> Result<(), String> {
    use oracle::bottleneck_measures::bottleneck;
    let z = elevations(points);
    let best = all.iter().map(|t| bottleneck(b, points, &z, t)).min();
    (Some(bottleneck(b, points, &z, tris)) == best)
        .then_some(())
        .ok_or_else(|| format!("{b:?} bottleneck not optimal"))
}

/// An optimality check: `Err(why)` when `tris` (distinct indices) is not
/// optimal for its criterion among `all`, every triangulation of `points`;
/// `exact` says whether the criterion claimed an exact optimum.
pub type OptimalityCheck = fn(
    exact: bool,
    points: &[[f64; 2]],
    tris: &[[u32; 3]],
    all: &[Vec<[u32; 3]>],
) -> Result<(), String>;

/// The optimality check of every registered criterion, by registry name. A
/// criterion missing here fails `optimality_check` (and the test suite's
/// `every_registered_criterion_has_an_oracle_check`), so no criterion runs
/// unchecked.
pub const OPTIMALITY_CHECKS: &[(&str, OptimalityCheck)] = &[
    ("delaunay", |_, points, tris, _| {
        oracle::delaunay_check(points, tris)
    }),
    ("minmax-length", |_, points, tris, all| {
        let best = all
            .iter()
            .map(|t| oracle::max_edge_squared(points, t))
            .min();
        (Some(oracle::max_edge_squared(points, tris)) == best)
            .then_some(())
            .ok_or_else(|| "longest edge not minimal".to_string())
    }),
    ("greedy", |_, points, tris, _| {
        let want = oracle::canonical_triangulation(points, &oracle::greedy_triangulation(points));
        (oracle::canonical_triangulation(points, tris) == want)
            .then_some(())
            .ok_or_else(|| "not the greedy triangulation".to_string())
    }),
    ("min-weight", |_, points, tris, all| {
        // The oracle sums rounded lengths: a relative 1e-12 separates the
        // distinct sums of these small integer sets, and the exact sums are
        // checked against the integer program in tests/min_weight*.rs.
        let best = all
            .iter()
            .map(|t| oracle::total_length(points, t))
            .fold(f64::INFINITY, f64::min);
        (oracle::total_length(points, tris) <= best * (1.0 + 1e-12))
            .then_some(())
            .ok_or_else(|| "total length not minimal".to_string())
    }),
    ("maxmin-area", |exact, points, tris, all| {
        // An approximation (general sets) is checked for validity only.
        let best = all
            .iter()
            .map(|t| Reverse(oracle::min_twice_area(points, t)))
            .min();
        (!exact || Some(Reverse(oracle::min_twice_area(points, tris))) == best)
            .then_some(())
            .ok_or_else(|| "smallest area not maximal".to_string())
    }),
    ("minmax-area", |exact, points, tris, all| {
        let best = all.iter().map(|t| oracle::max_twice_area(points, t)).min();
        (!exact || Some(oracle::max_twice_area(points, tris)) == best)
            .then_some(())
            .ok_or_else(|| "largest area not minimal".to_string())
    }),
    ("minmax-angle", |_, points, tris, all| {
        bottleneck_check(
            oracle::bottleneck_measures::Bottleneck::MinMaxAngle,
            points,
            tris,
            all,
        )
    }),
    ("maxmin-height", |_, points, tris, all| {
        bottleneck_check(
            oracle::bottleneck_measures::Bottleneck::MaxMinHeight,
            points,
            tris,
            all,
        )
    }),
    ("minmax-eccentricity", |_, points, tris, all| {
        bottleneck_check(
            oracle::bottleneck_measures::Bottleneck::MinMaxEccentricity,
            points,
            tris,
            all,
        )
    }),
    ("minmax-slope", |_, points, tris, all| {
        bottleneck_check(
            oracle::bottleneck_measures::Bottleneck::MinMaxSlope,
            points,
            tris,
            all,
        )
    }),
    ("minmax-delta-area", |exact, points, tris, all| {
        delta_check(oracle::DeltaMeasure::Area, exact, points, tris, all)
    }),
    ("minmax-delta-angle", |exact, points, tris, all| {
        delta_check(oracle::DeltaMeasure::Angle, exact, points, tris, all)
    }),
    ("minmax-delta-length", |exact, points, tris, all| {
        delta_check(oracle::DeltaMeasure::Length, exact, points, tris, all)
    }),
];

/// A δ-triangulation is never better than the optimum over `all`, and equal
/// to it when it claims to be exact.
fn delta_check(
    measure: oracle::DeltaMeasure,
    exact: bool,
    points: &[[f64; 2]],
    tris: &[[u32; 3]],
    all: &[Vec<[u32; 3]>],
) -> Result<(), String> {
    let Some(best) = measure.optimum(points, all) else {
        return Ok(());
    };
    match measure.compare(points, tris, best) {
        std::cmp::Ordering::Less => Err("delta below the optimum".to_string()),
        std::cmp::Ordering::Greater if exact => Err("delta not minimal".to_string()),
        _ => Ok(()),
    }
}

/// The optimality check of `criterion`.
///
/// # Panics
/// When the criterion has none in [`OPTIMALITY_CHECKS`].
pub fn optimality_check(criterion: Criterion) -> OptimalityCheck {
    OPTIMALITY_CHECKS
        .iter()
        .find(|(name, _)| *name == criterion.name())
        .map(|&(_, check)| check)
        .unwrap_or_else(|| {
            panic!(
                "criterion {} has no optimality check in fuzz/src/checks.rs",
                criterion.name()
            )
        })
}

fn check_optimal(
    criterion: Criterion,
    exact: bool,
    points: &[[f64; 2]],
    tris: &[[u32; 3]],
    all: &[Vec<[u32; 3]>],
) {
    if let Err(why) = optimality_check(criterion)(exact, points, tris, all) {
        panic!("{criterion:?} on {points:?}: {why}: {tris:?}");
    }
}
