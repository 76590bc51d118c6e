//! Triangulates a point file by one criterion and prints the result's
//! quality measures.
//!
//! ```sh
//! cargo run --release -p optri --example triangulate_file -- points.txt minmax-length
//! ```
//! The file may be plain `x y` text, Triangle `.node`, TSPLIB `.tsp` or
//! GeoJSON; the criterion is any name of `optri::Criterion::ALL`.

use optri::io::{self, ReadOptions, Source};
use optri::{triangulate, Criterion, PointSet};
use std::path::Path;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut args = std::env::args().skip(1);
    let (Some(path), criterion) = (args.next(), args.next()) else {
        let names: Vec<&str> = Criterion::ALL.iter().map(|c| c.name()).collect();
        eprintln!(
            "usage: triangulate_file POINTS [CRITERION]   criteria: {}",
            names.join(", ")
        );
        std::process::exit(2);
    };
    let criterion = Criterion::from_name(criterion.as_deref().unwrap_or("delaunay"))?;
    // The format by extension, else by content; a .poly gives its vertices.
    let read = io::read(Source::Path(Path::new(&path)), &ReadOptions::default())?;
    let raw = read.input.points();
    let points = PointSet::new(raw)?;
    let solution = triangulate(&points, criterion)?;
    solution.triangulation.validate()?;
    let stats = solution.triangulation.stats();
    println!(
        "{}: {} points ({} distinct), {} triangles",
        criterion.name(),
        raw.len(),
        points.len(),
        stats.triangles
    );
    println!("  optimality: {}", solution.optimality.name());
    println!("  algorithm:  {}", solution.algorithm);
    println!(
        "  longest edge {:.6}, total length {:.6}",
        stats.max_edge_length, stats.total_edge_length
    );
    println!(
        "  areas {:.6e} .. {:.6e}, angles {:.3}° .. {:.3}°",
        stats.min_area, stats.max_area, stats.min_angle_deg, stats.max_angle_deg
    );
    for phase in &solution.phases {
        println!("  {:>16}: {:9.3} ms", phase.name, phase.ms);
    }
    Ok(())
}
