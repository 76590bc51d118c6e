//! Compares every registered criterion on one point set: how the longest
//! edge, the total length and the extreme areas and angles trade off.
//!
//! ```sh
//! cargo run --release -p optri --example compare_criteria            # a built-in set
//! cargo run --release -p optri --example compare_criteria -- pts.tsp # a file
//! ```

use optri::io::{self, ReadOptions, Source};
use optri::{triangulate, Criterion, Error, PointSet};
use std::path::Path;

/// A fixed scattered set (a lattice walk modulo two primes: no randomness,
/// the same set everywhere) plus a collinear run along the bottom.
fn built_in() -> Vec<[f64; 2]> {
    let mut points: Vec<[f64; 2]> = (0..40)
        .map(|i| [((i * 37) % 101) as f64, ((i * 61) % 103) as f64 + 5.0])
        .collect();
    points.extend((0..6).map(|x| [x as f64 * 20.0, 0.0]));
    points
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let raw = match std::env::args().nth(1) {
        Some(path) => io::read(Source::Path(Path::new(&path)), &ReadOptions::default())?
            .input
            .points()
            .to_vec(),
        None => built_in(),
    };
    let points = PointSet::new(&raw)?;
    println!("{} points ({} distinct)\n", raw.len(), points.len());
    println!(
        "{:<14} {:>12} {:>14} {:>12} {:>12} {:>9} {:>9}  optimality",
        "criterion", "longest", "total length", "min area", "max area", "min °", "max °"
    );
    for &criterion in Criterion::ALL {
        match triangulate(&points, criterion) {
            Ok(solution) => {
                let s = solution.triangulation.stats();
                println!(
                    "{:<14} {:>12.5} {:>14.5} {:>12.5} {:>12.5} {:>9.3} {:>9.3}  {}",
                    criterion.name(),
                    s.max_edge_length,
                    s.total_edge_length,
                    s.min_area,
                    s.max_area,
                    s.min_angle_deg,
                    s.max_angle_deg,
                    solution.optimality.name()
                );
            }
            // A criterion that refuses this input says why.
            Err(e @ Error::Unsupported { .. }) => {
                println!("{:<14} skipped: {e}", criterion.name());
            }
            Err(e) => return Err(e.into()),
        }
    }
    Ok(())
}
