//! Gabriel graph (K. R. Gabriel & R. R. Sokal, *A new statistical approach
//! to geographic variation analysis*, Systematic Zoology 18, 1969): `pq` is
//! an edge iff no other point lies in *or on* the circle with diameter `pq`
//! (the closed disc; equivalently, no `r` sees `pq` at an angle of 90° or
//! more). With the closed disc the graph is planar and a subgraph of *every*
//! Delaunay triangulation, however cocircular points are completed.
//!
//! A Delaunay edge `pq` with apexes `a`, `b` is a Gabriel edge iff both
//! angles `paq` and `pbq` are strictly acute. If they are, the closed half of
//! the diametral disc on `a`'s side, less `p` and `q`, lies strictly inside
//! the circumcircle of `pqa` (its centre is on `a`'s side, so the two
//! circles meet only at `p` and `q`), which is empty, and likewise for `b`;
//! a hull edge has no points on its outer side. Conversely a point with a
//! right or obtuse angle is in the closed disc. A Gabriel edge has an empty
//! circle through its endpoints with no other point on it, so it is in every
//! Delaunay completion: testing the edges of the one spade returns suffices.
//! Exact: one dot-product sign per apex.

use crate::error::Result;
use crate::kernel::{dot_sign, Point};
use crate::structures::DelaunayGraph;
use crate::structures::PointSet;

/// Gabriel edges as distinct-index pairs.
pub(crate) fn gabriel_from_delaunay(points: &[Point], g: &DelaunayGraph) -> Vec<[u32; 2]> {
    let p = |i: u32| points[i as usize];
    g.edges
        .iter()
        .filter(|&&([u, v], apexes)| {
            apexes
                .iter()
                .flatten()
                .all(|&a| dot_sign(p(a), p(u), p(v)) > 0)
        })
        .map(|&(e, _)| e)
        .collect()
}

/// The Gabriel graph: edges as sorted `[min, max]` input-index pairs.
pub fn gabriel_graph(points: &PointSet) -> Result<Vec<[u32; 2]>> {
    let g = DelaunayGraph::new(points.points())?;
    let e = gabriel_from_delaunay(points.points(), &g);
    Ok(points.to_input_edges(e.into_iter()))
}
