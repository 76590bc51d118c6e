//! Times the δ-triangulations (threshold sweep of the polygon program) on
//! strictly convex polygons against one run of Klincsek's program for
//! MinMax area on the same input, alternating, and reports how many
//! programs each sweep ran.
//!
//! ```sh
//! cargo build --release -p optri-bench --bin delta_timing
//! target/release/delta_timing 50 100 200
//! ```

use optri::{triangulate, Criterion, PointSet};
use optri_oracle::inputs::ellipse_polygon;
use rand::{rngs::StdRng, SeedableRng};
use std::time::Instant;

const SEED: u64 = 0xDE17A;

fn secs<T>(f: impl FnOnce() -> T) -> (T, f64) {
    let start = Instant::now();
    let out = f();
    (out, start.elapsed().as_secs_f64())
}

fn main() {
    let sizes: Vec<usize> = std::env::args()
        .skip(1)
        .map(|a| a.parse().expect("sizes are integers"))
        .collect();
    let mut rng = StdRng::seed_from_u64(SEED);
    println!("| n | Klincsek minmax-area | δ-area (programs) | δ-angle (programs) | δ-length (programs) |");
    println!("|---|---|---|---|---|");
    for n in sizes {
        let points = ellipse_polygon(&mut rng, n, 1e6, 1.5);
        let set = PointSet::new(&points).expect("valid points");
        let (_, klincsek) = secs(|| {
            optri::internals::area_by_polygon_program(&set, Criterion::MinMaxArea)
                .expect("the program runs")
        });
        let mut cells = Vec::new();
        for criterion in [
            Criterion::MinMaxDeltaArea,
            Criterion::MinMaxDeltaAngle,
            Criterion::MinMaxDeltaLength,
        ] {
            let (solution, t) = secs(|| triangulate(&set, criterion).expect("a δ-triangulation"));
            solution.triangulation.validate().expect("valid");
            assert!(solution.exact);
            let programs = solution.diagnostics.get("polygon programs").unwrap_or(0);
            cells.push(format!(
                "{t:.3} s ×{:.1} ({programs})",
                t / klincsek.max(1e-9)
            ));
        }
        println!(
            "| {} | {klincsek:.3} s | {} |",
            points.len(),
            cells.join(" | ")
        );
    }
}
