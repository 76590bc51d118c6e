//! Times the Delaunay crates and optri's proximity graphs in one process, so
//! the figures in BENCHMARKS.md are ratios measured under the same load.
//!
//! ```text
//! cargo run --release -p optri --example proximity_timing [-- N]
//! ```
//! N defaults to 1 000 000 uniform points. A second part builds 100 000
//! near-cocircular points and counts non-Delaunay edges (exact in-circle)
//! in the output of spade and of delaunator.

use optri::kernel::incircle_sign;
use optri::PointSet;
use optri_oracle::inputs::{circle_at_random_angles, uniform_unit_square};
use rand::{rngs::StdRng, SeedableRng};
use std::collections::HashMap;
use std::time::Instant;

const SEED_UNIFORM: u64 = 2026;
const SEED_CIRCLE: u64 = 7;

fn secs<T>(f: impl FnOnce() -> T) -> (T, f64) {
    let t = Instant::now();
    let out = f();
    (out, t.elapsed().as_secs_f64())
}

/// Counts interior edges whose opposite apex lies strictly inside the circumcircle.
fn non_delaunay_edges(points: &[[f64; 2]], triangles: &[[usize; 3]]) -> usize {
    let mut apex: HashMap<(usize, usize), usize> = HashMap::new();
    for t in triangles {
        // Orient counter-clockwise: incircle_sign expects it.
        let t = if optri::kernel::orient_sign(points[t[0]], points[t[1]], points[t[2]]) < 0 {
            [t[0], t[2], t[1]]
        } else {
            *t
        };
        for k in 0..3 {
            apex.insert((t[k], t[(k + 1) % 3]), t[(k + 2) % 3]);
        }
    }
    let mut bad = 0;
    for (&(u, v), &w) in &apex {
        if u < v {
            if let Some(&x) = apex.get(&(v, u)) {
                if incircle_sign(points[u], points[v], points[w], points[x]) > 0 {
                    bad += 1;
                }
            }
        }
    }
    bad
}

fn delaunator_triangles(points: &[[f64; 2]]) -> Vec<[usize; 3]> {
    let pts: Vec<delaunator::Point> = points
        .iter()
        .map(|p| delaunator::Point { x: p[0], y: p[1] })
        .collect();
    let t = delaunator::triangulate(&pts);
    // delaunator's triangles are clockwise in a y-up frame; orientation is irrelevant here.
    t.triangles.chunks(3).map(|c| [c[0], c[1], c[2]]).collect()
}

fn main() {
    let n: usize = std::env::args()
        .nth(1)
        .and_then(|s| s.parse().ok())
        .unwrap_or(1_000_000);
    let points = uniform_unit_square(&mut StdRng::seed_from_u64(SEED_UNIFORM), n);
    let ps = PointSet::new(&points).expect("valid points");
    println!("uniform random points: n = {n}");
    let (dt, t_spade) = secs(|| optri::delaunay(&ps).unwrap());
    let (dtor, t_delaunator) = secs(|| delaunator_triangles(&points));
    let (_, t_dt_edges) = secs(|| optri::delaunay(&ps).unwrap().edges());
    let (rng_edges, t_rng) = secs(|| optri::relative_neighborhood_graph(&ps).unwrap());
    let (gabriel, t_gabriel) = secs(|| optri::gabriel_graph(&ps).unwrap());
    let (mst, t_mst) = secs(|| optri::minimum_spanning_tree(&ps).unwrap());
    println!(
        "  spade Delaunay (optri::delaunay)   {:8.3} s  ({} triangles)",
        t_spade,
        dt.triangles().len()
    );
    println!(
        "  delaunator                         {:8.3} s  ({} triangles)",
        t_delaunator,
        dtor.len()
    );
    println!("  Delaunay graph (edges + adjacency) {:8.3} s", t_dt_edges);
    println!(
        "  RNG (Delaunay graph + lune search) {:8.3} s  ({} edges); RNG alone ≈ {:.3} s = {:.2}× the Delaunay graph",
        t_rng,
        rng_edges.len(),
        t_rng - t_dt_edges,
        (t_rng - t_dt_edges) / t_dt_edges
    );
    println!(
        "  Gabriel graph                      {:8.3} s  ({} edges)",
        t_gabriel,
        gabriel.len()
    );
    println!(
        "  minimum spanning tree              {:8.3} s  ({} edges)",
        t_mst,
        mst.len()
    );

    let m = 100_000;
    // Points on a circle, rounded to f64: nearly cocircular, a stress test for in-circle.
    let circle = circle_at_random_angles(&mut StdRng::seed_from_u64(SEED_CIRCLE), m, 1e3);
    let cps = PointSet::new(&circle).unwrap();
    println!("near-cocircular points: n = {} distinct", cps.len());
    let (sdt, t_s) = secs(|| optri::delaunay(&cps).unwrap());
    let stris: Vec<[usize; 3]> = sdt
        .triangles()
        .iter()
        .map(|t| t.map(|i| cps.distinct_index(i) as usize))
        .collect();
    let (dtris, t_d) = secs(|| delaunator_triangles(cps.points()));
    println!(
        "  spade      {:8.3} s, non-Delaunay edges (exact in-circle): {}",
        t_s,
        non_delaunay_edges(cps.points(), &stris)
    );
    println!(
        "  delaunator {:8.3} s, non-Delaunay edges (exact in-circle): {}",
        t_d,
        non_delaunay_edges(cps.points(), &dtris)
    );
}
