//! Minmax edge-length triangulation against independent references:
//! an exhaustive search over all triangulations (n ≤ 9), Delaunay, the
//! paper's examples, and (for the fast polygon algorithm) the cubic DP.

use optri::internals::minmax_length_cubic;
use optri::kernel::{compare_lengths, orient_sign, Point};
use optri::{Criterion, Diagnostics, PointSet, Triangulation};
use optri_oracle::inputs::{
    circle_r5_ccw, grid, lattice_points, perturbed_circle, uniform_in_square, uniform_unit_square,
};
use rand::{rngs::StdRng, Rng, SeedableRng};
use std::cmp::Ordering;
use std::collections::HashMap;

const SEED_RANDOM_SMALL_SETS: u64 = 1;
const SEED_DEGENERATE_SMALL_SETS: u64 = 2;
const SEED_RANDOM_VS_CUBIC: u64 = 3;
const SEED_INTEGER_GRIDS_VS_CUBIC: u64 = 4;
const SEED_CONVEX_VS_CUBIC: u64 = 5;
const SEED_ORACLE_EXHAUSTIVE: u64 = 7;
const SEED_ORACLE_CUBIC: u64 = 8;

/// The longest edge of `t` as a pair of points.
fn longest(t: &Triangulation) -> [Point; 2] {
    let e = t.longest_edge();
    let p = t.point_set().input_points();
    [p[e[0] as usize], p[e[1] as usize]]
}

fn cmp_seg(a: [Point; 2], b: [Point; 2]) -> Ordering {
    compare_lengths(a[0], a[1], b[0], b[1])
}

/// Exhaustive minmax oracle: enumerates every triangulation of the distinct
/// points (branch and bound on the longest edge) by repeatedly choosing the
/// apex of the triangle left of the first open directed edge.
struct Exhaustive<'a> {
    p: &'a [Point],
    edges: Vec<[usize; 2]>,
    /// Directed edges whose left side is still untriangulated / already done.
    open: Vec<[usize; 2]>,
    closed: Vec<[usize; 2]>,
    best: Option<[Point; 2]>,
}

impl Exhaustive<'_> {
    fn crosses(&self, a: usize, b: usize) -> bool {
        let (pa, pb) = (self.p[a], self.p[b]);
        self.edges.iter().any(|&[u, w]| {
            if u == a || u == b || w == a || w == b {
                return false;
            }
            let (pu, pw) = (self.p[u], self.p[w]);
            orient_sign(pa, pb, pu) * orient_sign(pa, pb, pw) < 0
                && orient_sign(pu, pw, pa) * orient_sign(pu, pw, pb) < 0
        })
    }
    fn has_edge(&self, a: usize, b: usize) -> bool {
        self.edges
            .iter()
            .any(|&[u, w]| (u == a && w == b) || (u == b && w == a))
    }
    fn search(&mut self, current: Option<[Point; 2]>) {
        if let (Some(c), Some(b)) = (current, self.best) {
            if cmp_seg(c, b) != Ordering::Less {
                return;
            }
        }
        let Some(&[a, b]) = self.open.last() else {
            self.best = current;
            return;
        };
        let n = self.p.len();
        for c in 0..n {
            if c == a || c == b || orient_sign(self.p[a], self.p[b], self.p[c]) <= 0 {
                continue;
            }
            // Empty closed triangle (other than its corners).
            let (pa, pb, pc) = (self.p[a], self.p[b], self.p[c]);
            let blocked = (0..n).any(|x| {
                x != a
                    && x != b
                    && x != c
                    && orient_sign(pa, pb, self.p[x]) >= 0
                    && orient_sign(pb, pc, self.p[x]) >= 0
                    && orient_sign(pc, pa, self.p[x]) >= 0
            });
            if blocked {
                continue;
            }
            let new_edges = [[b, c], [c, a]];
            if new_edges.iter().any(|&[u, w]| {
                self.closed.contains(&[u, w]) || (!self.has_edge(u, w) && self.crosses(u, w))
            }) {
                continue;
            }
            // Apply.
            let saved = (self.edges.len(), self.open.clone(), self.closed.len());
            self.open.retain(|&e| e != [a, b]);
            self.closed.push([a, b]);
            let mut cur = current;
            for &[u, w] in &new_edges {
                self.closed.push([u, w]);
                if let Some(i) = self.open.iter().position(|&e| e == [u, w]) {
                    self.open.remove(i);
                } else if !self.closed.contains(&[w, u]) {
                    self.open.push([w, u]);
                }
                if !self.has_edge(u, w) {
                    self.edges.push([u, w]);
                }
                let s = [self.p[u], self.p[w]];
                cur = Some(match cur {
                    Some(m) if cmp_seg(m, s) != Ordering::Less => m,
                    _ => s,
                });
            }
            self.search(cur);
            self.edges.truncate(saved.0);
            self.open = saved.1;
            self.closed.truncate(saved.2);
        }
    }
}

/// The optimal longest edge over all triangulations of the distinct points.
fn exhaustive_minmax(ps: &PointSet) -> [Point; 2] {
    let p = ps.points();
    let hull: Vec<usize> = optri::convex_hull(ps)
        .into_iter()
        .map(|i| ps.distinct_index(i) as usize)
        .collect();
    let h = hull.len();
    let mut ex = Exhaustive {
        p,
        edges: Vec::new(),
        open: Vec::new(),
        closed: Vec::new(),
        best: None,
    };
    let mut current: Option<[Point; 2]> = None;
    for i in 0..h {
        let (a, b) = (hull[i], hull[(i + 1) % h]);
        ex.edges.push([a, b]);
        ex.open.push([a, b]);
        ex.closed.push([b, a]);
        let s = [p[a], p[b]];
        current = Some(match current {
            Some(m) if cmp_seg(m, s) != Ordering::Less => m,
            _ => s,
        });
    }
    ex.search(current);
    ex.best.expect("every point set has a triangulation")
}

/// The §5.1/§6 algorithm on every region, however small (the product hands
/// regions below `SMALL_REGION` corners to the cubic program), with the
/// run's diagnostics.
fn quadratic_only(ps: &PointSet) -> (Triangulation, Diagnostics) {
    optri::internals::minmax_length_with(ps, 0).unwrap()
}

/// The product ([`minmax_length`], through the registry), with the run's
/// diagnostics.
fn product(ps: &PointSet) -> (Triangulation, Diagnostics) {
    let s = optri::triangulate(ps, Criterion::MinMaxLength).unwrap();
    (s.triangulation, s.diagnostics)
}

/// Diagnostics summed over runs, by name.
#[derive(Default)]
struct Tally(HashMap<&'static str, u64>);

impl Tally {
    fn add(&mut self, d: &Diagnostics) {
        for (name, value) in d.iter() {
            *self.0.entry(name).or_default() += value;
        }
    }

    fn add_all(&mut self, other: Tally) {
        for (name, value) in other.0 {
            *self.0.entry(name).or_default() += value;
        }
    }

    fn get(&self, name: &str) -> u64 {
        *self
            .0
            .get(name)
            .unwrap_or_else(|| panic!("no diagnostic {name:?}"))
    }
}

/// Compares the product and the quadratic algorithm with the exhaustive
/// search; returns their diagnostics.
fn check_against_exhaustive(points: &[Point]) -> Tally {
    let mut tally = Tally::default();
    let Ok(ps) = PointSet::new(points) else {
        return tally;
    };
    let want = exhaustive_minmax(&ps);
    let d = optri::delaunay(&ps).unwrap();
    for (t, diagnostics) in [product(&ps), quadratic_only(&ps)] {
        t.validate()
            .unwrap_or_else(|e| panic!("{e} for {points:?}"));
        assert_eq!(
            cmp_seg(longest(&t), want),
            Ordering::Equal,
            "points {points:?}: got {:?}, optimum {:?}",
            longest(&t),
            want
        );
        assert_ne!(cmp_seg(longest(&t), longest(&d)), Ordering::Greater);
        tally.add(&diagnostics);
    }
    no_fallbacks(&tally, points);
    tally
}

/// The quadratic algorithm never had to fall back to the cubic program.
fn no_fallbacks(tally: &Tally, what: impl std::fmt::Debug) {
    let n = tally.get("fallbacks");
    assert_eq!(n, 0, "fallbacks to the cubic program ({what:?})");
}

#[test]
fn random_small_sets_match_the_exhaustive_search() {
    let mut rng = StdRng::seed_from_u64(SEED_RANDOM_SMALL_SETS);
    for _ in 0..1500 {
        let n = rng.gen_range(3..=9i32) as usize;
        let pts = uniform_in_square(&mut rng, n, 100.0);
        check_against_exhaustive(&pts);
    }
}

#[test]
fn degenerate_small_sets_match_the_exhaustive_search() {
    let mut rng = StdRng::seed_from_u64(SEED_DEGENERATE_SMALL_SETS);
    for round in 0..2500 {
        let n = rng.gen_range(3..=9);
        let pts: Vec<Point> = match round % 5 {
            // Small integer grid: many equal lengths, collinear runs, duplicates.
            0 | 1 => lattice_points(&mut rng, n as usize, 0..4, 0..4),
            // Collinear run plus a few points.
            2 => (0..n)
                .map(|i| {
                    if i < n / 2 + 1 {
                        [i as f64, 2.0 * i as f64]
                    } else {
                        [rng.gen_range(-3..8) as f64, rng.gen_range(-3..8) as f64]
                    }
                })
                .collect(),
            // Cocircular: integer points on the circle x² + y² = 25, plus the centre sometimes.
            3 => {
                let circle = circle_r5_ccw();
                let mut v: Vec<Point> = (0..n).map(|_| circle[rng.gen_range(0..12)]).collect();
                if rng.gen_bool(0.3) {
                    v.push([0.0, 0.0]);
                }
                v
            }
            // Triangular lattice-ish (equal lengths) with huge and negative scale.
            _ => {
                let s = if rng.gen_bool(0.5) { 1e30 } else { -3e-20 };
                (0..n)
                    .map(|_| {
                        let (a, b) = (rng.gen_range(0..3) as f64, rng.gen_range(0..3) as f64);
                        [s * (2.0 * a + b), s * (2.0 * b)]
                    })
                    .collect()
            }
        };
        check_against_exhaustive(&pts);
    }
}

#[test]
fn paper_section_2_example_beats_delaunay() {
    // §2: a = (−2, 0), b = (1, √3), c = (1, −√3), d = (2 − ε, 0). Delaunay uses
    // ad; the minmax triangulation uses bc. Rational stand-in: √3 ≈ 1.732.
    let pts = [[-2.0, 0.0], [1.0, 1.732], [1.0, -1.732], [1.9, 0.0]];
    let ps = PointSet::new(&pts).unwrap();
    let t = optri::triangulate(&ps, Criterion::MinMaxLength)
        .unwrap()
        .triangulation;
    t.validate().unwrap();
    let d = optri::delaunay(&ps).unwrap();
    assert_eq!(cmp_seg(longest(&t), longest(&d)), Ordering::Less);
    assert!(t.edges().contains(&[1, 2]), "the optimum draws bc");
    check_against_exhaustive(&pts);
}

#[test]
fn paper_section_5_3_remark_example() {
    // Two equilateral triangles abc, abd, with d moved slightly towards ab:
    // the unique optimum draws ab, which is not a 2-edge.
    let s = 1.7320508075688772;
    let pts = [[0.0, 0.0], [2.0, 0.0], [1.0, s], [1.0, -s + 0.05]];
    let ps = PointSet::new(&pts).unwrap();
    let t = optri::triangulate(&ps, Criterion::MinMaxLength)
        .unwrap()
        .triangulation;
    t.validate().unwrap();
    assert!(t.edges().contains(&[0, 1]));
    check_against_exhaustive(&pts);
    // And the §4 remark configuration: c, d close to b, ab crossing cd.
    check_against_exhaustive(&[[0.0, 0.0], [10.0, 0.0], [9.5, 1.0], [9.6, -1.2]]);
}

#[test]
fn duplicates_and_errors() {
    let pts = [
        [0.0, 0.0],
        [1.0, 0.0],
        [0.0, 0.0],
        [0.0, 1.0],
        [1.0, 1.0],
        [1.0, 1.0],
    ];
    let ps = PointSet::new(&pts).unwrap();
    let t = optri::triangulate(&ps, Criterion::MinMaxLength)
        .unwrap()
        .triangulation;
    t.validate().unwrap();
    assert_eq!(t.triangles().len(), 2);
    assert!(PointSet::new(&[[0.0, 0.0], [1.0, 1.0], [2.0, 2.0]]).is_err());
}

// ---- fast polygon algorithm vs the cubic reference ----

/// Compares the product and the quadratic algorithm with the cubic
/// reference; returns their diagnostics.
fn same_optimum(points: &[Point], what: &str) -> Tally {
    let ps = PointSet::new(points).unwrap();
    let r = minmax_length_cubic(&ps).unwrap();
    r.validate().unwrap();
    let d = optri::delaunay(&ps).unwrap();
    let mut tally = Tally::default();
    for (t, diagnostics) in [product(&ps), quadratic_only(&ps)] {
        t.validate().unwrap_or_else(|e| panic!("{what}: {e}"));
        assert_eq!(
            cmp_seg(longest(&t), longest(&r)),
            Ordering::Equal,
            "{what}: fast {:?} vs cubic {:?}",
            longest(&t),
            longest(&r)
        );
        assert_ne!(
            cmp_seg(longest(&t), longest(&d)),
            Ordering::Greater,
            "{what}"
        );
        tally.add(&diagnostics);
    }
    no_fallbacks(&tally, what);
    tally
}

#[test]
fn random_sets_match_the_cubic_reference() {
    let mut rng = StdRng::seed_from_u64(SEED_RANDOM_VS_CUBIC);
    for &n in &[10usize, 50, 200, 1000, 2000] {
        let pts = uniform_unit_square(&mut rng, n);
        same_optimum(&pts, &format!("uniform n={n}"));
    }
}

#[test]
fn integer_grids_match_the_cubic_reference() {
    let mut rng = StdRng::seed_from_u64(SEED_INTEGER_GRIDS_VS_CUBIC);
    for &(w, n) in &[(5, 20), (10, 80), (20, 300), (40, 1000), (6, 36)] {
        let pts = lattice_points(&mut rng, n, 0..w, 0..w);
        same_optimum(&pts, &format!("grid {w}x{w} n={n}"));
    }
    same_optimum(&grid(15, 15, 1.0), "full 15x15 grid");
}

#[test]
fn convex_position_matches_the_cubic_reference() {
    let mut rng = StdRng::seed_from_u64(SEED_CONVEX_VS_CUBIC);
    for &n in &[20usize, 100, 300] {
        let pts = perturbed_circle(&mut rng, n, 1e-3);
        same_optimum(&pts, &format!("perturbed circle n={n}"));
    }
}

/// Tiny TSPLIB reader: `NODE_COORD_SECTION`, then `id x y` lines until `EOF`.
fn read_tsp(path: &std::path::Path) -> Vec<Point> {
    let text = std::fs::read_to_string(path).unwrap();
    let mut pts = Vec::new();
    let mut inside = false;
    for line in text.lines() {
        let line = line.trim();
        if line.starts_with("NODE_COORD_SECTION") {
            inside = true;
            continue;
        }
        if !inside || line.is_empty() {
            continue;
        }
        if line.starts_with("EOF") {
            break;
        }
        let f: Vec<f64> = line
            .split_whitespace()
            .skip(1)
            .map(|x| x.parse().unwrap())
            .collect();
        pts.push([f[0], f[1]]);
    }
    pts
}

#[test]
fn tsplib_files_match_the_cubic_reference() {
    let dir = optri_oracle::data_dir().join("tsplib");
    let mut files: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "tsp"))
        .collect();
    files.sort();
    assert!(files.len() >= 14, "{dir:?}");
    for f in files {
        let pts = read_tsp(&f);
        same_optimum(&pts, &f.display().to_string());
    }
}

#[test]
fn registered_as_an_exact_criterion() {
    let c = optri::Criterion::from_name("minmax-length").unwrap();
    let ps = PointSet::new(&[[0.0, 0.0], [4.0, 0.0], [0.0, 3.0], [4.0, 3.0], [2.0, 1.0]]).unwrap();
    let s = optri::triangulate(&ps, c).unwrap();
    assert!(s.exact);
    assert!(s.algorithm.contains("Edelsbrunner"));
    // This Delaunay triangulation meets the hull's bound: no region work.
    assert!(s.phases.iter().any(|p| p.name == "lower bound"));
    assert!(!s.phases.iter().any(|p| p.name == "polygons"));
    assert_eq!(s.diagnostics.get("regions_certified_by_bound"), Some(1));
    assert_eq!(s.diagnostics.get("case_1"), Some(0));
    s.triangulation.validate().unwrap();
    assert_eq!(
        cmp_seg(
            longest(&s.triangulation),
            longest(&minmax_length_cubic(&ps).unwrap())
        ),
        Ordering::Equal
    );
}

#[test]
fn the_tests_exercise_every_branch() {
    // The diagnostics of every run below, summed.
    let mut tally = Tally::default();
    // Degenerate grids hit §6 Case 1 and Case 2 and the §5.4 repair.
    let mut rng = StdRng::seed_from_u64(6);
    for _ in 0..200 {
        let pts: Vec<Point> = (0..30)
            .map(|_| [rng.gen_range(0..6) as f64, rng.gen_range(0..6) as f64])
            .collect();
        tally.add_all(same_optimum(&pts, "6x6 grid"));
    }
    // Sparser 10×10 grids hit the §5.4 repair of flat triangles under the
    // Z-order numbering's perturbation (about one set in 40).
    for _ in 0..400 {
        let n = rng.gen_range(5..40);
        let pts: Vec<Point> = (0..n)
            .map(|_| [rng.gen_range(0..10) as f64, rng.gen_range(0..10) as f64])
            .collect();
        tally.add_all(same_optimum(&pts, "10x10 grid"));
    }
    // Uniform sets hit the §6 Case 2 step-3 pockets (u_L ≠ v, fan-out).
    for seed in 0..4 {
        let mut rng = StdRng::seed_from_u64(100 + seed);
        let pts: Vec<Point> = (0..3000)
            .map(|_| [rng.gen::<f64>(), rng.gen::<f64>()])
            .collect();
        tally.add_all(same_optimum(&pts, "uniform 3000 for Case 2 pockets"));
    }
    let c = |name: &str| tally.get(name);
    assert!(c("case_1") > 0 && c("case_2") > 0 && c("flat_triangles") > 0);
    assert!(
        c("case_2_pockets_by_5_1") > 0,
        "no pocket closed by a 1-edge"
    );
    assert!(
        c("case_2_pockets_by_fan_out") > 0,
        "no pocket needed the u_L search and the fan-out"
    );
    assert!(
        c("small_regions_certified") > 0 && c("small_regions_by_dp") > 0,
        "small regions should take both the certified-Delaunay and the cubic path"
    );
    assert!(
        c("regions_certified_by_bound") > 0,
        "the Length-Lemma certificate should keep some Delaunay regions"
    );
    assert_eq!(c("case_2_hull_fallbacks"), 0);
    assert_eq!(c("case_2_pocket_fallbacks"), 0);
}

// ---- against the independent oracle crate (exact rationals) ----

use optri_oracle::{
    all_triangulations, bounded_faces, convex_hull_edges, klincsek, max_edge_squared, rng_edges,
    MinMaxLength,
};

/// Squared longest edge of `t`, exactly, by the oracle's rational arithmetic.
fn oracle_max_edge(t: &Triangulation) -> optri_oracle::BigRational {
    max_edge_squared(t.point_set().input_points(), t.triangles())
}

#[test]
fn oracle_exhaustive_enumeration_agrees() {
    let mut rng = StdRng::seed_from_u64(SEED_ORACLE_EXHAUSTIVE);
    for round in 0..400 {
        let n = rng.gen_range(3..=8i32) as usize;
        let pts = if round % 2 == 0 {
            lattice_points(&mut rng, n, 0..4, 0..3)
        } else {
            uniform_in_square(&mut rng, n, 50.0)
        };
        let Ok(ps) = PointSet::new(&pts) else {
            continue;
        };
        let best = all_triangulations(ps.points())
            .iter()
            .map(|t| max_edge_squared(ps.points(), t))
            .min()
            .unwrap();
        let mut tally = Tally::default();
        for (t, diagnostics) in [product(&ps), quadratic_only(&ps)] {
            t.validate().unwrap();
            assert_eq!(oracle_max_edge(&t), best, "{pts:?}");
            tally.add(&diagnostics);
        }
        no_fallbacks(&tally, &pts);
    }
}

/// The oracle's Klincsek program on the faces of its own hull ∪ RNG(S)
/// (the unperturbed, strict-lune RNG, which some minmax triangulation
/// contains: Edelsbrunner & Tan 1991, §4, Subgraph Theorem): an independent
/// cubic reference.
fn oracle_cubic(points: &[Point]) -> optri_oracle::BigRational {
    let ps = PointSet::new(points).unwrap();
    let p = ps.points();
    let mut edges = convex_hull_edges(p);
    edges.extend(rng_edges(p));
    edges.sort_unstable();
    edges.dedup();
    bounded_faces(p, &edges)
        .iter()
        .map(|f| klincsek(p, f, MinMaxLength).expect("face triangulable").0)
        .max()
        .unwrap()
}

#[test]
fn oracle_cubic_reference_agrees_on_random_sets_and_grids() {
    let mut rng = StdRng::seed_from_u64(SEED_ORACLE_CUBIC);
    for round in 0..30 {
        let n = rng.gen_range(10..=60i32) as usize;
        let pts = if round % 2 == 0 {
            lattice_points(&mut rng, n, 0..7, 0..7)
        } else {
            uniform_unit_square(&mut rng, n)
        };
        let ps = PointSet::new(&pts).unwrap();
        let want = oracle_cubic(&pts);
        let mut tally = Tally::default();
        for (t, diagnostics) in [product(&ps), quadratic_only(&ps)] {
            assert_eq!(oracle_max_edge(&t), want, "{pts:?}");
            tally.add(&diagnostics);
        }
        no_fallbacks(&tally, &pts);
    }
}

#[test]
fn oracle_cubic_reference_agrees_on_small_tsplib_files() {
    let dir = optri_oracle::data_dir().join("tsplib");
    for name in ["berlin52", "kroA100", "ch150", "ts225"] {
        let pts = read_tsp(&dir.join(format!("{name}.tsp")));
        let ps = PointSet::new(&pts).unwrap();
        let want = oracle_cubic(&pts);
        let mut tally = Tally::default();
        for (t, diagnostics) in [product(&ps), quadratic_only(&ps)] {
            assert_eq!(oracle_max_edge(&t), want, "{name}");
            tally.add(&diagnostics);
        }
        no_fallbacks(&tally, name);
    }
}

/// Convex position, where one complete rng-polygon holds (nearly) all points
/// and §6 runs on per-pair bit tables: regular polygons
/// (cocircular, every length repeated), near-cocircular and random convex
/// sets, with duplicated points and collinear points on hull edges, against
/// the oracle's exhaustive enumeration (n ≤ 9) and its cubic program.
#[test]
fn oracle_agrees_in_convex_position() {
    let mut rng = StdRng::seed_from_u64(SEED_ORACLE_CUBIC + 1);
    let regular = |n: usize| -> Vec<Point> {
        (0..n)
            .map(|i| {
                let t = std::f64::consts::TAU * i as f64 / n as f64;
                [64.0 * t.cos(), 64.0 * t.sin()]
            })
            .collect()
    };
    let mut sets: Vec<Vec<Point>> = Vec::new();
    for n in [4usize, 5, 6, 7, 8, 9, 12, 20, 40, 60] {
        sets.push(regular(n));
        sets.push(perturbed_circle(&mut rng, n, 1e-3));
        let mut angles: Vec<f64> = (0..n)
            .map(|_| rng.gen_range(0.0..std::f64::consts::TAU))
            .collect();
        angles.sort_by(f64::total_cmp);
        sets.push(angles.iter().map(|t| [3.0 * t.cos(), t.sin()]).collect());
    }
    // The 12 integer points of x² + y² = 25 (exactly cocircular), with
    // duplicates; an integer square with collinear points on its edges.
    let mut with_duplicates = circle_r5_ccw().to_vec();
    with_duplicates.extend([[5.0, 0.0], [0.0, -5.0]]);
    sets.push(with_duplicates);
    sets.push(
        (0..4)
            .flat_map(|i| {
                [
                    [i as f64, 0.0],
                    [4.0, i as f64],
                    [4.0 - i as f64, 4.0],
                    [0.0, 4.0 - i as f64],
                ]
            })
            .collect(),
    );
    for pts in &sets {
        let ps = PointSet::new(pts).unwrap();
        let want = oracle_cubic(pts);
        if ps.len() <= 9 {
            let best = all_triangulations(ps.points())
                .iter()
                .map(|t| max_edge_squared(ps.points(), t))
                .min()
                .unwrap();
            assert_eq!(best, want, "the oracle's references disagree: {pts:?}");
        }
        let mut tally = Tally::default();
        for (t, diagnostics) in [product(&ps), quadratic_only(&ps)] {
            t.validate().unwrap();
            assert_eq!(oracle_max_edge(&t), want, "{pts:?}");
            tally.add(&diagnostics);
        }
        no_fallbacks(&tally, pts);
    }
}
