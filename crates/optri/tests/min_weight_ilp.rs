//! Minimum-weight triangulation of general sets of 40–60 points against the
//! oracle's integer program over empty triangles
//! ([`optri_oracle::min_weight_ilp`]: Kyoda et al. 1997's triangle
//! formulation, solved by branch and bound and re-checked exactly), on
//! random uniform (also huge and negative coordinates), clustered, integer
//! lattice (ties), cocircular (with and without the centre), collinear-run
//! and duplicated sets, and on the odd wheels (regular (2k+1)-gons with
//! their centre, k = 3…10) and nested wheels, which defeat the LMT-skeleton.
//!
//! The program is solved in floating point, so weights are compared with a
//! relative tolerance of 10⁻⁹; both are sums of `f64` edge lengths of a
//! triangulation ([`optri_oracle::total_length`]). When the edge sets differ
//! the weights must still agree: a tie, counted and printed.
//!
//! The default tier runs one or two sets per family; the `#[ignore]`d sweep
//! runs many (`cargo test --release -p optri --test min_weight_ilp --
//! --ignored --nocapture`).

use optri::internals::min_weight_pipeline;
use optri::kernel::Point;
use optri::{triangulate, Criterion, PointSet};
use optri_oracle::inputs::{
    clustered, collinear_runs, grid, grid_subset, integer_circle_points, lattice_points,
    uniform_in_box, uniform_in_square,
};
use optri_oracle::{canonical_triangulation, min_weight_ilp, total_length};
use rand::rngs::StdRng;
use rand::seq::SliceRandom;
use rand::{Rng, SeedableRng};
use std::time::{Duration, Instant};

const TOLERANCE: f64 = 1e-9;
const SEED_DEFAULT: u64 = 1204;
const SEED_SWEEP: u64 = 1205;
const SEED_COCIRCULAR: u64 = 1206;

/// The input families; each draws a set of about 40–60 points.
#[derive(Clone, Copy, Debug)]
enum Family {
    Uniform,
    /// Uniform in a small box far from the origin, at negative coordinates.
    FarNegative,
    Clustered,
    /// Integer points of a small square, drawn with repeats (ties, collinear
    /// triples and duplicates).
    Lattice,
    /// A full or thinned integer grid.
    Grid,
    /// A random subset of the integer points of a circle.
    Cocircular,
    /// The same with the centre: beyond optri's face-search budget (see
    /// `cocircular_sets_with_their_centre_equal_the_integer_program`).
    CocircularCentre,
    CollinearRuns,
    /// A uniform set with some points repeated, shuffled.
    Duplicates,
}

const FAMILIES: [Family; 8] = [
    Family::Uniform,
    Family::FarNegative,
    Family::Clustered,
    Family::Lattice,
    Family::Grid,
    Family::Cocircular,
    Family::CollinearRuns,
    Family::Duplicates,
];

fn draw(family: Family, rng: &mut StdRng) -> Vec<Point> {
    let n = rng.gen_range(40..=60);
    match family {
        Family::Uniform => uniform_in_square(rng, n, 1000.0),
        Family::FarNegative => {
            uniform_in_box(rng, n, [-3.0e9, -7.5e8], [-3.0e9 + 1e4, -7.5e8 + 1e4])
        }
        Family::Clustered => {
            let clusters = rng.gen_range(2..=5);
            clustered(rng, n, clusters)
        }
        Family::Lattice => lattice_points(rng, n + n / 4, 0..9, 0..9),
        Family::Grid => {
            if rng.gen_bool(0.3) {
                let w = rng.gen_range(6..=8);
                grid(w, 7, 1.0)
            } else {
                let p = rng.gen_range(0.5..0.75);
                grid_subset(rng, 9, 9, p)
            }
        }
        Family::Cocircular | Family::CocircularCentre => {
            // x² + y² = 325²: 60 integer points in strictly convex position.
            let mut c = integer_circle_points(325);
            c.shuffle(rng);
            c.truncate(n.min(c.len()));
            if matches!(family, Family::CocircularCentre) {
                c.push([0.0, 0.0]);
            }
            c
        }
        Family::CollinearRuns => collinear_runs(rng, 4..7, 6..10, 10..25),
        Family::Duplicates => {
            let mut p = uniform_in_square(rng, n - n / 5, 100.0);
            for _ in 0..n / 5 {
                let q = p[rng.gen_range(0..p.len())];
                p.push(q);
            }
            p.shuffle(rng);
            p
        }
    }
}

/// A regular k-gon of radius `r` rotated by `phase` (radians) around the origin.
fn ring(k: usize, r: f64, phase: f64) -> Vec<Point> {
    (0..k)
        .map(|i| {
            let a = phase + std::f64::consts::TAU * i as f64 / k as f64;
            [r * a.cos(), r * a.sin()]
        })
        .collect()
}

/// What a run of comparisons saw.
#[derive(Default)]
struct Tally {
    sets: usize,
    /// Sets whose optimal edge sets differ (equal weights: ties).
    ties: usize,
    /// Sets on which the program's relaxation was fractional.
    branched: usize,
    empty_triangles: usize,
    /// Sets on which optri (registry and pipeline) proved the optimum.
    equal: usize,
    /// Results optri did not prove optimal (`exact: false`), described.
    unproven: Vec<String>,
    ilp_time: Duration,
    optri_time: Duration,
    /// Faces decided by the triangle program, and its branch-and-bound
    /// nodes (pipeline diagnostics).
    programs: u64,
    nodes: u64,
}

/// Solves `pts` by optri (registry and the general pipeline) and by the
/// oracle's program; both must be valid, exact and of the same weight.
fn check(pts: &[Point], what: &str, tally: &mut Tally) {
    let ps = PointSet::new(pts).unwrap_or_else(|e| panic!("{what}: {e}"));
    let clock = Instant::now();
    let ilp = min_weight_ilp(ps.points()).expect("spans the plane");
    tally.ilp_time += clock.elapsed();
    tally.sets += 1;
    tally.branched += usize::from(ilp.nodes > 0);
    tally.empty_triangles += ilp.empty_triangles;
    let clock = Instant::now();
    let distinct = |t: &optri::Triangulation| -> Vec<[u32; 3]> {
        let tris: Vec<[u32; 3]> = t
            .triangles()
            .iter()
            .map(|tri| tri.map(|i| ps.distinct_index(i)))
            .collect();
        canonical_triangulation(ps.points(), &tris)
    };
    let close = |w: f64| (w - ilp.weight).abs() <= TOLERANCE * ilp.weight;

    let s = triangulate(&ps, Criterion::MinWeight).unwrap();
    s.triangulation.validate().unwrap();
    let tris = distinct(&s.triangulation);
    let w = total_length(ps.points(), &tris);
    let optri::internals::MinWeightRun {
        triangulation: t,
        exact,
        diagnostics,
        lower_bound: lower,
        ..
    } = min_weight_pipeline(&ps).unwrap();
    t.validate().unwrap();
    let wp = total_length(ps.points(), &distinct(&t));
    tally.optri_time += clock.elapsed();
    tally.programs += diagnostics.get("faces by triangle program").unwrap_or(0);
    tally.nodes += diagnostics.get("program branch nodes").unwrap_or(0);
    // Never lighter than the optimum, whatever optri proved.
    for (who, weight) in [("optri", w), ("pipeline", wp)] {
        assert!(
            weight >= ilp.weight * (1.0 - TOLERANCE),
            "{what}: {who} {weight} lighter than the integer program's {} (points {:?})",
            ilp.weight,
            ps.points()
        );
    }
    assert!(
        lower <= ilp.weight * (1.0 + TOLERANCE),
        "{what}: lower bound {lower} above the optimum {}",
        ilp.weight
    );
    for (who, proven, weight) in [("optri", s.exact, w), ("pipeline", exact, wp)] {
        if proven {
            assert!(
                close(weight),
                "{what}: {who} {weight}, integer program {} (points {:?})",
                ilp.weight,
                ps.points()
            );
        } else {
            // The face search ran out of budget: optri says so (`exact: false`).
            tally.unproven.push(format!(
                "{what}: {who} {weight} (lower bound {lower}), optimum {} ({diagnostics:?})",
                ilp.weight
            ));
        }
    }
    if !(s.exact && exact) {
        return;
    }
    tally.equal += 1;
    tally.ties += usize::from(tris != ilp.triangles);
}

fn families(seed: u64, families: &[Family], per_family: usize) -> Tally {
    let mut rng = StdRng::seed_from_u64(seed);
    let mut tally = Tally::default();
    for &family in families {
        for i in 0..per_family {
            let pts = draw(family, &mut rng);
            check(
                &pts,
                &format!("{family:?} #{i} ({} points)", pts.len()),
                &mut tally,
            );
        }
    }
    tally
}

/// The odd wheels k = 3…10 (radius 1000, centre at the origin or off it),
/// and nested odd wheels of two and three rings around a centre.
fn wheels() -> Tally {
    let mut tally = Tally::default();
    for k in 3..=10 {
        for centre in [[0.0, 0.0], [3.0, -7.0]] {
            let mut pts = ring(2 * k + 1, 1000.0, 0.0);
            pts.push(centre);
            check(
                &pts,
                &format!("wheel {}, centre {centre:?}", 2 * k + 1),
                &mut tally,
            );
        }
    }
    for rings in [
        &[(21, 1000.0), (19, 700.0)][..],
        &[(21, 1000.0), (15, 500.0)],
        &[(19, 1000.0), (13, 600.0), (7, 250.0)],
        &[(21, 1000.0), (17, 800.0), (11, 450.0), (5, 150.0)],
    ] {
        let mut pts: Vec<Point> = Vec::new();
        for (i, &(k, r)) in rings.iter().enumerate() {
            pts.extend(ring(k, r, 0.3 * i as f64));
        }
        pts.push([0.0, 0.0]);
        check(&pts, &format!("nested wheels {rings:?}"), &mut tally);
    }
    tally
}

impl Tally {
    fn report(&self, what: &str) {
        eprintln!(
            "{what}: {} sets, {} equal the integer program ({} ties in edges), {} results not \
             proven exact by optri; {} branched, {} empty triangles; integer programs {:.2?}, optri \
             {:.2?}; {} faces by optri's triangle program, {} branch-and-bound nodes",
            self.sets,
            self.equal,
            self.ties,
            self.unproven.len(),
            self.branched,
            self.empty_triangles,
            self.ilp_time,
            self.optri_time,
            self.programs,
            self.nodes
        );
        for u in &self.unproven {
            eprintln!("  unproven: {u}");
        }
    }
}

#[test]
fn equals_the_integer_program_on_every_family() {
    let tally = families(SEED_DEFAULT, &FAMILIES, 1);
    tally.report("families");
    assert_eq!(tally.sets, FAMILIES.len());
    assert!(tally.unproven.is_empty());
}

#[test]
fn odd_and_nested_wheels_equal_the_integer_program() {
    let tally = wheels();
    tally.report("wheels");
    assert_eq!(tally.sets, 20);
    assert!(tally.unproven.is_empty());
    // The odd wheels' relaxation is fractional: the program's branch and
    // bound (not its root LP) decides some of them.
    assert!(tally.branched > 0, "no wheel needed branching");
}

#[test]
#[ignore = "slow: 25 sets per family of 40–60 points (200 integer programs), about a minute in release"]
fn equals_the_integer_program_on_many_sets() {
    let tally = families(SEED_SWEEP, &FAMILIES, 25);
    tally.report("sweep");
    assert_eq!(tally.sets, 25 * FAMILIES.len());
    assert!(tally.unproven.is_empty());
}

/// 23 integer points of x² + y² = 65² and the origin (see below).
#[rustfmt::skip]
const SMALLEST_COCIRCULAR_WITH_CENTRE: [[i32; 2]; 24] = [
    [-63, 16], [-52, -39], [-33, 56], [-56, 33], [60, 25], [0, -65], [-39, 52], [39, -52],
    [60, -25], [52, 39], [16, -63], [-39, -52], [25, 60], [-25, 60], [39, 52], [-63, -16],
    [-16, 63], [-33, -56], [56, -33], [-52, 39], [-56, -33], [56, 33], [-65, 0], [0, 0],
];

/// With the centre added, a cocircular set of 24 or more points
/// stays one face with an inner point after the LMT-skeleton; the plain
/// front search runs out of its budget on it. The triangle program's
/// certificate (reduced-cost pricing of the search) decides the smallest
/// seen: the 23 integer points of x² + y² = 65² and the origin, optimum
/// 1464.705033468207 (before: `exact: false`, 1473.1138808050746).
#[test]
fn smallest_cocircular_set_with_its_centre_equals_the_integer_program() {
    let smallest: Vec<Point> = SMALLEST_COCIRCULAR_WITH_CENTRE
        .iter()
        .map(|&[x, y]| [f64::from(x), f64::from(y)])
        .collect();
    let mut tally = Tally::default();
    check(
        &smallest,
        "23 points of x² + y² = 65² and the origin",
        &mut tally,
    );
    tally.report("smallest cocircular set with centre");
    assert_eq!(tally.equal, 1);
    assert!(tally.unproven.is_empty());
}

/// Drawn sets of 40–60 points of x² + y² = 325² with the origin
/// (one face with an inner point after the LMT-skeleton). Before the branch
/// and bound over the face program, the sets of 54 and 57 points stayed
/// `exact: false` (root gap W − L about 6). The oracle's relaxation is
/// fractional on three of them; optri's face program (root certificate and
/// priced search) decides all five without a branch node, so the branch and bound itself
/// is exercised by the odd wheels of `min_weight_general`.
#[test]
#[ignore = "slow in debug: five sets of 41–58 points, a few seconds in release"]
fn cocircular_sets_with_their_centre_equal_the_integer_program() {
    let tally = families(SEED_COCIRCULAR, &[Family::CocircularCentre], 5);
    tally.report("cocircular with centre");
    assert_eq!(tally.sets, 5);
    assert!(tally.unproven.is_empty());
    assert!(tally.branched > 0, "no set had a fractional relaxation");
    assert_eq!(
        tally.programs, 5,
        "each set leaves one face for the program"
    );
}

/// The integer points of x² + y² = 325² (60, convex position), the first
/// `k` of a seeded shuffle, with the origin.
fn cocircular_with_centre(k: usize, rng: &mut StdRng) -> Vec<Point> {
    let mut c = integer_circle_points(325);
    c.shuffle(rng);
    c.truncate(k);
    c.push([0.0, 0.0]);
    c
}

/// Cocircular sets with their centre from 30 to 60 rim points (all 60
/// integer points of x² + y² = 325², 61 points with the centre).
#[test]
#[ignore = "slow: cocircular sets of 30–60 points with the centre, 14 integer programs"]
fn cocircular_sets_up_to_60_points_with_their_centre_equal_the_integer_program() {
    let mut rng = StdRng::seed_from_u64(SEED_COCIRCULAR + 1);
    let mut tally = Tally::default();
    for k in [30, 34, 38, 42, 45, 48, 50, 52, 54, 56, 57, 58, 59, 60] {
        let pts = cocircular_with_centre(k, &mut rng);
        check(
            &pts,
            &format!("{k} points of x² + y² = 325² and the origin"),
            &mut tally,
        );
    }
    tally.report("cocircular with centre, 30–60");
    assert_eq!(tally.sets, 14);
    assert!(tally.unproven.is_empty());
}

/// Two nested cocircular rings of integer points (a subset of x² + y² =
/// 325² around one of x² + y² = 65², the second rotated by a shuffle's
/// choice), with and without the common centre.
fn nested_cocircular(outer: usize, inner: usize, centre: bool, rng: &mut StdRng) -> Vec<Point> {
    let mut o = integer_circle_points(325);
    o.shuffle(rng);
    o.truncate(outer);
    let mut i = integer_circle_points(65);
    i.shuffle(rng);
    i.truncate(inner);
    o.extend(i);
    if centre {
        o.push([0.0, 0.0]);
    }
    o
}

#[test]
fn two_nested_cocircular_rings_equal_the_integer_program() {
    let mut rng = StdRng::seed_from_u64(SEED_COCIRCULAR + 2);
    let mut tally = Tally::default();
    for (outer, inner, centre) in [(24, 8, true), (30, 6, false)] {
        let pts = nested_cocircular(outer, inner, centre, &mut rng);
        check(
            &pts,
            &format!("nested cocircular {outer} + {inner}, centre {centre}"),
            &mut tally,
        );
    }
    tally.report("nested cocircular rings");
    assert!(tally.unproven.is_empty());
}

#[test]
#[ignore = "slow: 12 sets of two nested cocircular rings of 40–60 points"]
fn many_nested_cocircular_rings_equal_the_integer_program() {
    let mut rng = StdRng::seed_from_u64(SEED_COCIRCULAR + 3);
    let mut tally = Tally::default();
    for (outer, inner) in [(30, 10), (36, 12), (40, 16), (44, 12), (48, 8), (50, 10)] {
        for centre in [false, true] {
            let pts = nested_cocircular(outer, inner, centre, &mut rng);
            check(
                &pts,
                &format!("nested cocircular {outer} + {inner}, centre {centre}"),
                &mut tally,
            );
        }
    }
    tally.report("nested cocircular rings, 40–61 points");
    assert_eq!(tally.sets, 12);
    assert!(tally.unproven.is_empty());
}
