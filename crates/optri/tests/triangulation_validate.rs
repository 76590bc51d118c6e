//! Proof by oracle: `Triangulation::validate` accepts every triangulation the
//! oracle enumerates and rejects corrupted ones, on random and degenerate
//! small sets.

use optri::{PointSet, Triangulation};
use optri_oracle as oracle;
use optri_oracle::inputs::{
    cocircular_seven_with_centre, grid, lattice_points, parabola, square_with_centre,
};
use rand::rngs::StdRng;
use rand::SeedableRng;

type Point = [f64; 2];

const SEED_POINT_SETS: u64 = 99;

/// Small test sets: random, grids, collinear runs, cocircular, duplicates.
fn point_sets() -> Vec<(String, Vec<Point>)> {
    let mut rng = StdRng::seed_from_u64(SEED_POINT_SETS);
    let mut sets = Vec::new();
    for n in 4..=9 {
        for rep in 0..4 {
            let side = if rep % 2 == 0 { 4 } else { 1000 };
            let pts = lattice_points(&mut rng, n, 0..side, 0..side);
            sets.push((format!("random n={n} rep={rep}"), pts));
        }
    }
    sets.push(("grid 3x3".into(), grid(3, 3, 1.0)));
    sets.push(("grid 4x2".into(), grid(4, 2, 1.0)));
    sets.push(("grid 3x3 step 0.1".into(), grid(3, 3, 0.1)));
    sets.push(("grid 3x3 huge".into(), grid(3, 3, 2f64.powi(150))));
    sets.push((
        "grid 3x3 tiny negative".into(),
        grid(3, 3, -(2f64.powi(-100))),
    ));
    sets.push((
        "collinear run + apexes".into(),
        vec![
            [0.0, 0.0],
            [1.0, 0.0],
            [2.0, 0.0],
            [3.0, 0.0],
            [1.0, 2.0],
            [2.0, -1.0],
            [1.5, 0.5],
        ],
    ));
    sets.push((
        "cocircular octagon-ish".into(),
        cocircular_seven_with_centre(),
    ));
    sets.push(("convex 9-gon".into(), parabola(9)));
    sets.push(("square with centre".into(), square_with_centre(2.0)));
    sets.push((
        "duplicates".into(),
        vec![
            [0.0, 0.0],
            [3.0, 0.0],
            [0.0, 0.0],
            [1.0, 1.0],
            [3.0, 3.0],
            [1.0, 1.0],
            [0.0, 3.0],
            [2.0, 1.0],
        ],
    ));
    sets.retain(|(_, p)| PointSet::new(p).is_ok() && PointSet::new(p).unwrap().len() <= 9);
    sets
}

/// Distinct-index triangles → input-index triangles.
fn to_input(ps: &PointSet, tris: &[[u32; 3]]) -> Vec<[u32; 3]> {
    tris.iter().map(|t| t.map(|d| ps.input_index(d))).collect()
}

fn rejected(ps: &PointSet, tris: Vec<[u32; 3]>, what: &str, label: &str) -> bool {
    match Triangulation::from_triangles(ps, tris.clone()) {
        Ok(_) => panic!("{label}: {what} accepted: {tris:?}"),
        Err(optri::Error::InvalidTriangulation(_)) => true,
        Err(e) => panic!("{label}: {what}: wrong error kind {e}"),
    }
}

/// The corruptions of one valid triangulation (distinct indices); returns
/// how many were tried, and how many of them were flat-triangle ones.
fn corrupt_and_check(ps: &PointSet, t: &[[u32; 3]], label: &str) -> (usize, usize) {
    let pts = ps.points();
    let p = |i: u32| pts[i as usize];
    let mut tried = 0;
    let mut flat = 0;
    // 1. Drop a triangle.
    for i in 0..t.len() {
        let mut c = t.to_vec();
        c.remove(i);
        tried += rejected(ps, to_input(ps, &c), "dropped triangle", label) as usize;
    }
    // 2. A clockwise triangle.
    for i in 0..t.len() {
        let mut c = t.to_vec();
        c[i] = [c[i][0], c[i][2], c[i][1]];
        tried += rejected(ps, to_input(ps, &c), "clockwise triangle", label) as usize;
    }
    // 3. Two adjacent triangles replaced by an overlapping pair: keep one,
    //    and put the flipped quadrilateral's triangle on the same side.
    for x in 0..t.len() {
        for y in 0..t.len() {
            if x == y {
                continue;
            }
            let shared: Vec<u32> = t[x].iter().copied().filter(|v| t[y].contains(v)).collect();
            if shared.len() != 2 {
                continue;
            }
            let c_apex = *t[x].iter().find(|v| !shared.contains(v)).unwrap();
            let d_apex = *t[y].iter().find(|v| !shared.contains(v)).unwrap();
            for &s in &shared {
                let mut tri = [c_apex, d_apex, s];
                match oracle::orient(p(tri[0]), p(tri[1]), p(tri[2])) {
                    0 => continue,
                    o if o < 0 => tri.swap(1, 2),
                    _ => {}
                }
                let mut c = t.to_vec();
                c[y] = tri;
                tried += rejected(ps, to_input(ps, &c), "overlapping pair", label) as usize;
            }
            // 5. Flat triangle: apexes collinear with a shared vertex m between
            //    them; replace (a, m, x), (m, b, x) by (a, b, x) and flat (a, m, b).
            for (k, &m) in shared.iter().enumerate() {
                let xv = shared[1 - k];
                let (a, b) = (c_apex, d_apex);
                if oracle::on_open_segment(p(a), p(b), p(m)) {
                    let mut big = [a, b, xv];
                    if oracle::orient(p(a), p(b), p(xv)) < 0 {
                        big.swap(0, 1);
                    }
                    let mut c = t.to_vec();
                    c[x] = big;
                    c[y] = [a, m, b];
                    tried += rejected(ps, to_input(ps, &c), "flat triangle", label) as usize;
                    c[y] = [b, m, a];
                    tried += rejected(ps, to_input(ps, &c), "flat triangle (cw)", label) as usize;
                    flat += 2;
                }
            }
        }
    }
    // 4. A triangle covering a point: remove the star of an interior
    //    degree-3 vertex and put the covering triangle back.
    for v in 0..pts.len() as u32 {
        let star: Vec<usize> = (0..t.len()).filter(|&i| t[i].contains(&v)).collect();
        if star.len() != 3 {
            continue;
        }
        let mut ring: Vec<u32> = star
            .iter()
            .flat_map(|&i| t[i])
            .filter(|&u| u != v)
            .collect();
        ring.sort_unstable();
        ring.dedup();
        if ring.len() != 3 {
            continue; // a hull vertex's fan
        }
        let mut cover = [ring[0], ring[1], ring[2]];
        if oracle::orient(p(cover[0]), p(cover[1]), p(cover[2])) < 0 {
            cover.swap(1, 2);
        }
        let mut c: Vec<[u32; 3]> = (0..t.len())
            .filter(|i| !star.contains(i))
            .map(|i| t[i])
            .collect();
        c.push(cover);
        tried += rejected(ps, to_input(ps, &c), "triangle covering a point", label) as usize;
        // Same count: add a copy of another triangle as well.
        c.push(c[0]);
        c.push(c[1]);
        tried += rejected(ps, to_input(ps, &c), "covering + repeated", label) as usize;
    }
    // 6. A triangle repeated in place of another.
    if t.len() >= 2 {
        let mut c = t.to_vec();
        c[1] = c[0];
        tried += rejected(ps, to_input(ps, &c), "repeated triangle", label) as usize;
    }
    (tried, flat)
}

#[test]
fn every_enumerated_triangulation_is_accepted() {
    let mut total = 0;
    for (label, input) in point_sets() {
        let ps = PointSet::new(&input).unwrap();
        for t in oracle::all_triangulations(ps.points()) {
            let input_tris = to_input(&ps, &t);
            Triangulation::from_triangles(&ps, input_tris.clone())
                .unwrap_or_else(|e| panic!("{label}: valid triangulation rejected: {e}: {t:?}"));
            // Any rotation of a ccw triangle and any triangle order is fine too.
            let mut rotated: Vec<[u32; 3]> =
                input_tris.iter().map(|t| [t[1], t[2], t[0]]).collect();
            rotated.reverse();
            Triangulation::from_triangles(&ps, rotated).unwrap();
            total += 1;
        }
    }
    assert!(total > 1000, "{total}");
}

#[test]
fn corrupted_triangulations_are_rejected() {
    let mut tried = 0;
    let mut flat = 0;
    for (label, input) in point_sets() {
        let ps = PointSet::new(&input).unwrap();
        let all = oracle::all_triangulations(ps.points());
        let step = (all.len() / 25).max(1);
        for t in all.iter().step_by(step) {
            let (n, f) = corrupt_and_check(&ps, t, &label);
            tried += n;
            flat += f;
        }
    }
    assert!(tried > 2000, "{tried}");
    assert!(flat > 20, "{flat}");
}

/// The flat corruption must actually occur: on a collinear run with an apex
/// on each side there is a pair of triangles to merge.
#[test]
fn flat_triangle_on_collinear_points_is_rejected() {
    let input = [[0.0, 0.0], [1.0, 0.0], [2.0, 0.0], [1.0, 1.0], [1.0, -1.0]];
    let ps = PointSet::new(&input).unwrap();
    let t = vec![[0, 1, 3], [1, 2, 3], [0, 4, 1], [1, 4, 2]];
    Triangulation::from_triangles(&ps, t).unwrap();
    // (0, 3) - (2, 3) merged over the run and the flat (0, 1, 2) added.
    rejected(
        &ps,
        vec![[0, 2, 3], [0, 1, 2], [0, 4, 1], [1, 4, 2]],
        "flat",
        "run",
    );
    rejected(&ps, vec![[0, 2, 3], [0, 4, 1], [1, 4, 2]], "missing", "run");
    // Hull with a collinear point skipped: (0,4,2) is not a triangulation of all points.
    rejected(&ps, vec![[0, 2, 3], [0, 4, 2]], "skips point 1", "run");
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-12 * a.abs().max(b.abs())
}

/// `longest_edge` (exact, ties to the smallest pair) and the rounded `stats`
/// against the oracle's exact keys.
#[test]
fn stats_and_longest_edge_match_the_oracle() {
    use oracle::BigRational;
    let mut checked = 0;
    for (label, input) in point_sets() {
        let ps = PointSet::new(&input).unwrap();
        let pts = ps.points();
        let hull_points = oracle::convex_hull_edges(pts).len();
        let all = oracle::all_triangulations(pts);
        let step = (all.len() / 40).max(1);
        for t in all.iter().step_by(step) {
            let tri = Triangulation::from_triangles(&ps, to_input(&ps, t)).unwrap();
            let s = tri.stats();
            let p = |i: u32| pts[i as usize];
            let longest = oracle::max_edge_squared(pts, t);
            let first_longest = oracle::triangle_edges(t)
                .into_iter()
                .map(|e| e.map(|d| ps.input_index(d)))
                .map(|[a, b]| [a.min(b), a.max(b)])
                .filter(|e| {
                    let d = e.map(|i| ps.distinct_index(i));
                    oracle::squared_length(p(d[0]), p(d[1])) == longest
                })
                .min()
                .unwrap();
            assert_eq!(tri.longest_edge(), first_longest, "{label}");
            assert_eq!(s.longest_edge, first_longest, "{label}");
            assert!(
                close(s.max_edge_length, oracle::rational_to_f64(&longest).sqrt()),
                "{label}"
            );
            assert!(
                close(s.total_edge_length, oracle::total_length(pts, t)),
                "{label}"
            );
            let half = |r: BigRational| oracle::rational_to_f64(&r) / 2.0;
            assert!(
                close(s.min_area, half(oracle::min_twice_area(pts, t))),
                "{label}"
            );
            assert!(
                close(s.max_area, half(oracle::max_twice_area(pts, t))),
                "{label}"
            );
            assert_eq!(s.triangles, t.len());
            assert_eq!(s.edges, oracle::triangle_edges(t).len());
            assert_eq!(s.hull_points, hull_points, "{label}");
            assert!(s.min_angle_deg > 0.0 && s.max_angle_deg < 180.0);
            checked += 1;
        }
    }
    assert!(checked > 300, "{checked}");
}

/// Regression: a triangle naming a *dropped* duplicate (not the first
/// occurrence) used to be accepted, and then `edges()` / `stats().edges`
/// counted one geometric edge twice ([0, 2] and [2, 4] below).
#[test]
fn triangles_must_use_the_first_occurrence_of_a_duplicate() {
    let input = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0], [0.0, 0.0]];
    let ps = PointSet::new(&input).unwrap();
    let good = Triangulation::from_triangles(&ps, vec![[0, 1, 2], [0, 2, 3]]).unwrap();
    assert_eq!(good.edges().len(), 5);
    assert_eq!(good.stats().edges, 5);
    let err = Triangulation::from_triangles(&ps, vec![[0, 1, 2], [4, 2, 3]]).unwrap_err();
    assert!(
        matches!(err, optri::Error::InvalidTriangulation(_)),
        "{err}"
    );
    assert!(err.to_string().contains("duplicate"), "{err}");
}
