//! Times the polygon program on simple polygons ([`optri::triangulate`]
//! with `minmax-area`, `minmax-length` and `min-weight`): a random star
//! (few diagonals) and a circle with one dent (vertex 0 pulled in to a
//! reflex corner: almost every chord is a diagonal, the program's worst
//! case), at 200, 500 and 1000 vertices, with the phases of each run.
//!
//! ```text
//! cargo run --release -p optri-bench --bin polygon_timing
//! ```

use optri::{triangulate, Criterion, SimplePolygon};
use optri_oracle::polygon::star_polygon;
use rand::{rngs::StdRng, SeedableRng};

const SEED_STARS: u64 = 0x5eed_71e5;

fn main() {
    let mut rng = StdRng::seed_from_u64(SEED_STARS);
    for n in [200, 500, 1000] {
        let star = star_polygon(&mut rng, n, 1e6);
        let mut dented: Vec<[f64; 2]> = (0..n)
            .map(|k| {
                let a = k as f64 * std::f64::consts::TAU / n as f64;
                [(1e6 * a.cos()).round(), (1e6 * a.sin()).round()]
            })
            .collect();
        dented[0] = [9e5, 0.0];
        for (shape, ring) in [("star", star), ("dented circle", dented)] {
            let polygon = SimplePolygon::new(&ring).expect("a simple polygon");
            for c in [
                Criterion::MinMaxArea,
                Criterion::MinMaxLength,
                Criterion::MinWeight,
            ] {
                let start = std::time::Instant::now();
                let s = triangulate(&polygon, c).expect("the polygon program runs");
                let ms = start.elapsed().as_secs_f64() * 1e3;
                s.triangulation.validate().expect("a triangulation");
                let phases: Vec<String> = s
                    .phases
                    .iter()
                    .map(|p| format!("{} {:.0} ms", p.name, p.ms))
                    .collect();
                println!(
                    "n = {n:5} {shape:14} {:14} {ms:9.0} ms ({})",
                    c.name(),
                    phases.join(", ")
                );
            }
        }
    }
}
