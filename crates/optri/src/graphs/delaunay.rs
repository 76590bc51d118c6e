//! Delaunay triangulation, through the `spade` crate (exact predicates,
//! O(n log n) bulk loading; chosen over delaunator, whose in-circle test is
//! not exact — see BENCHMARKS.md).
//!
//! For cocircular points the completion is canonical: each cocircular face
//! is fanned from its smallest distinct index (see `structures::delaunay_graph`), so
//! the answer does not depend on how spade built it; every consumer in optri
//! is correct for *any* completion (see the lemmas cited in the RNG and
//! Gabriel modules).

use crate::error::Result;
use crate::structures::{DelaunayGraph, PointSet, Triangulation};

/// The Delaunay triangulation of `points`.
///
/// For cocircular points, each cocircular face is fanned from its smallest
/// distinct index (first occurrence in the input).
/// Runs in O(n log n) expected time.
pub fn delaunay(points: &PointSet) -> Result<Triangulation> {
    let g = DelaunayGraph::new(points.points())?;
    Ok(Triangulation::from_distinct(points, g.triangles))
}

/// The Delaunay edges of `points` as `[min, max]` input-index pairs, sorted.
pub fn delaunay_edges(points: &PointSet) -> Result<Vec<[u32; 2]>> {
    let g = DelaunayGraph::new(points.points())?;
    Ok(points.to_input_edges(g.edges.iter().map(|&(e, _)| e)))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::incircle_sign;

    #[test]
    fn delaunay_is_valid_and_locally_delaunay_on_a_grid() {
        let mut pts = Vec::new();
        for x in 0..7 {
            for y in 0..5 {
                pts.push([x as f64 * 0.1, y as f64 * 0.1]);
            }
        }
        let ps = PointSet::new(&pts).unwrap();
        let t = delaunay(&ps).unwrap();
        t.validate().unwrap();
        let g = DelaunayGraph::new(ps.points()).unwrap();
        for &([u, v], [l, r]) in &g.edges {
            if let (Some(l), Some(r)) = (l, r) {
                let p = |i: u32| ps.points()[i as usize];
                assert!(incircle_sign(p(u), p(v), p(l), p(r)) <= 0);
            }
        }
    }
}
