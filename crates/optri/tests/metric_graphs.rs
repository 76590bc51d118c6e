//! RNG and MST under normed metrics against their brute-force definitions
//! (every pair, every third point, the kernel's exact tie-broken lune), and
//! the kernel's norm comparison against independent rational arithmetic.

use optri::kernel::{Metric, Point};
use optri::{graph, GraphKind, Options, PointSet};
use optri_oracle::exact::to_rational;
use optri_oracle::inputs::{
    collinear_runs, grid, grid_subset, integer_circle_points, lattice_points, uniform_unit_square,
};
use rand::{rngs::StdRng, Rng, SeedableRng};
use std::cmp::Ordering;

const SEED_GRAPHS: u64 = 1101;
const SEED_NORMS: u64 = 1102;

pub fn metrics() -> Vec<Metric> {
    vec![
        Metric::l1(),
        Metric::linf(),
        Metric::lp(3).unwrap(),
        Metric::lp(7).unwrap(),
        // A regular-ish hexagon and an irregular octagon.
        Metric::parse("polygon:2,0,1,2,-1,2,-2,0,-1,-2,1,-2").unwrap(),
        Metric::parse("polygon:3,0,2,1,0.5,2,-1,1.5,-3,0,-2,-1,-0.5,-2,1,-1.5").unwrap(),
    ]
}

fn brute_rng(pts: &[Point], m: &Metric) -> Vec<[u32; 2]> {
    let n = pts.len() as u32;
    let mut out = Vec::new();
    for p in 0..n {
        for q in p + 1..n {
            if (0..n).all(|x| x == p || x == q || !m.in_lune_symbolic(pts, p, q, x)) {
                out.push([p, q]);
            }
        }
    }
    out
}

fn brute_mst(pts: &[Point], m: &Metric) -> Vec<[u32; 2]> {
    let n = pts.len() as u32;
    let mut all: Vec<[u32; 2]> = (0..n)
        .flat_map(|p| (p + 1..n).map(move |q| [p, q]))
        .collect();
    all.sort_by(|a, b| m.compare_lengths_symbolic(pts, *a, *b));
    let mut comp: Vec<u32> = (0..n).collect();
    let mut out = Vec::new();
    for [a, b] in all {
        let (ca, cb) = (comp[a as usize], comp[b as usize]);
        if ca != cb {
            for c in comp.iter_mut() {
                if *c == cb {
                    *c = ca;
                }
            }
            out.push([a, b]);
        }
    }
    out.sort_unstable();
    out
}

fn inputs(rng: &mut StdRng) -> Vec<(String, Vec<Point>)> {
    let mut v = Vec::new();
    for n in [5, 12, 40, 90] {
        v.push((format!("uniform {n}"), uniform_unit_square(rng, n)));
    }
    v.push(("grid 6x5".into(), grid(6, 5, 1.0)));
    v.push(("grid 9x9 spacing 0.5".into(), grid(9, 9, 0.5)));
    v.push(("grid subset".into(), grid_subset(rng, 10, 10, 0.5)));
    v.push(("lattice".into(), lattice_points(rng, 60, 0..8, 0..8)));
    v.push((
        "collinear runs".into(),
        collinear_runs(rng, 2..5, 3..8, 0..3),
    ));
    v.push(("integer circle r=5".into(), integer_circle_points(5)));
    v.push((
        "huge negative".into(),
        uniform_unit_square(rng, 30)
            .iter()
            .map(|p| [p[0] * -1e40 - 3e40, p[1] * 1e40])
            .collect(),
    ));
    v
}

#[test]
fn rng_and_mst_equal_their_definitions_under_every_metric() {
    let mut rng = StdRng::seed_from_u64(SEED_GRAPHS);
    let sets = inputs(&mut rng);
    let mut cases = 0;
    for m in metrics() {
        for (name, pts) in &sets {
            let ps = PointSet::new(pts).unwrap();
            let d = ps.points().to_vec();
            let options = Options::default().with_metric(m.clone());
            let got = graph(ps.input_points(), GraphKind::Rng, &options)
                .unwrap()
                .edges;
            let want: Vec<[u32; 2]> = ps_to_input(&ps, brute_rng(&d, &m));
            assert_eq!(got, want, "RNG under {m} on {name}");
            let mut got = graph(ps.input_points(), GraphKind::Mst, &options)
                .unwrap()
                .edges;
            got.sort_unstable();
            let want = ps_to_input(&ps, brute_mst(&d, &m));
            assert_eq!(got, want, "MST under {m} on {name}");
            cases += 1;
        }
    }
    assert_eq!(cases, 6 * 11);
}

fn ps_to_input(ps: &PointSet, edges: Vec<[u32; 2]>) -> Vec<[u32; 2]> {
    let mut out: Vec<[u32; 2]> = edges
        .into_iter()
        .map(|[a, b]| {
            let (a, b) = (ps.input_index(a), ps.input_index(b));
            [a.min(b), a.max(b)]
        })
        .collect();
    out.sort_unstable();
    out
}

/// The norm's value, exactly, computed here from its definition.
fn exact_norm(m: &Metric, a: Point, b: Point) -> num_rational::BigRational {
    use num_traits::Signed;
    let dx = to_rational(b[0]) - to_rational(a[0]);
    let dy = to_rational(b[1]) - to_rational(a[1]);
    let name = m.name();
    if name == "l1" {
        dx.abs() + dy.abs()
    } else if name == "linf" {
        dx.abs().max(dy.abs())
    } else if let Some(p) = name.strip_prefix("lp:") {
        let p: usize = p.parse().unwrap();
        num_traits::pow(dx.abs(), p) + num_traits::pow(dy.abs(), p)
    } else {
        // Gauge of the polygon: the smallest t with v/t inside, via facets.
        let vs = m.unit_polygon().unwrap();
        let k = vs.len();
        (0..k)
            .map(|i| {
                let (u, w) = (vs[i], vs[(i + 1) % k]);
                let (ux, uy, wx, wy) = (
                    to_rational(u[0]),
                    to_rational(u[1]),
                    to_rational(w[0]),
                    to_rational(w[1]),
                );
                ((&wy - &uy) * &dx - (&wx - &ux) * &dy) / (&ux * &wy - &uy * &wx)
            })
            .max()
            .unwrap()
    }
}

#[test]
fn norm_comparisons_are_exact() {
    let mut rng = StdRng::seed_from_u64(SEED_NORMS);
    let mut ties = 0;
    for m in metrics() {
        for round in 0..4000 {
            let pick = |rng: &mut StdRng| -> Point {
                if round % 2 == 0 {
                    [rng.gen_range(-4..5) as f64, rng.gen_range(-4..5) as f64]
                } else {
                    let s = 10f64.powi(rng.gen_range(-30..30));
                    [rng.gen::<f64>() * s, rng.gen::<f64>() * s + 1.0]
                }
            };
            let (a, b, c) = (pick(&mut rng), pick(&mut rng), pick(&mut rng));
            // d close to a shifted copy of b so near-ties occur.
            let d = if round % 3 == 0 {
                [c[0] + (b[0] - a[0]), c[1] + (b[1] - a[1])]
            } else {
                pick(&mut rng)
            };
            let want = exact_norm(&m, a, b).cmp(&exact_norm(&m, c, d));
            assert_eq!(
                m.compare_norm(a, b, c, d),
                want,
                "{m} {a:?}{b:?} vs {c:?}{d:?}"
            );
            if want == Ordering::Equal {
                ties += 1;
            }
        }
    }
    assert!(ties > 1000, "{ties} ties");
}
