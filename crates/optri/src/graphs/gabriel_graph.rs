//! Gabriel graph: `pq` is an edge iff no point lies strictly inside the circle
//! with diameter `pq` (equivalently, no `r` sees `pq` at an obtuse angle).
//!
//! Every Gabriel edge has an empty (open) circle through its endpoints, so it
//! is an edge of the Delaunay *graph*. For a Delaunay edge with apexes `a`, `b`
//! it suffices to test `a` and `b`: if the angle at `a` is at most 90°, the
//! half of the diametral disc on `a`'s side lies inside the empty circumcircle
//! of `pqa`. The one subtlety is cocircular input: the chosen Delaunay
//! completion contains only one diagonal of a cocircular cell, but *every*
//! diameter of the cell's circle is a Gabriel edge (all cell vertices are on
//! the diametral circle, none inside). Those are added explicitly.

use crate::error::Result;
use crate::kernel::{dot_sign, incircle_sign, Point};
use crate::structures::DelaunayGraph;
use crate::structures::PointSet;
use std::collections::{HashMap, HashSet};

/// Gabriel edges as distinct-index pairs.
pub(crate) fn gabriel_from_delaunay(points: &[Point], g: &DelaunayGraph) -> Vec<[u32; 2]> {
    let p = |i: u32| points[i as usize];
    let mut out: Vec<[u32; 2]> = g
        .edges
        .iter()
        .filter(|&&([u, v], apexes)| {
            apexes
                .iter()
                .flatten()
                .all(|&a| dot_sign(p(a), p(u), p(v)) >= 0)
        })
        .map(|&(e, _)| e)
        .collect();
    out.extend(cocircular_diameters(points, g));
    out
}

/// Diameters of cocircular Delaunay cells (≥ 4 points on an empty circle)
/// that the chosen completion does not contain.
fn cocircular_diameters(points: &[Point], g: &DelaunayGraph) -> Vec<[u32; 2]> {
    let p = |i: u32| points[i as usize];
    // Edges whose two apexes are cocircular with them join one Delaunay cell.
    let cocircular: Vec<[[u32; 3]; 2]> = g
        .edges
        .iter()
        .filter_map(|&([u, v], apexes)| match apexes {
            [Some(l), Some(r)] if incircle_sign(p(u), p(v), p(l), p(r)) == 0 => {
                Some([[u, v, l], [v, u, r]])
            }
            _ => None,
        })
        .collect();
    if cocircular.is_empty() {
        return Vec::new();
    }
    let tri_of: HashMap<[u32; 3], usize> = g
        .triangles
        .iter()
        .enumerate()
        .map(|(i, t)| (canonical(*t), i))
        .collect();
    let mut parent: Vec<usize> = (0..g.triangles.len()).collect();
    fn find(parent: &mut [usize], mut x: usize) -> usize {
        while parent[x] != x {
            parent[x] = parent[parent[x]];
            x = parent[x];
        }
        x
    }
    for [t1, t2] in cocircular {
        let (a, b) = (tri_of[&canonical(t1)], tri_of[&canonical(t2)]);
        let (ra, rb) = (find(&mut parent, a), find(&mut parent, b));
        parent[ra] = rb;
    }
    let mut cells: HashMap<usize, HashSet<u32>> = HashMap::new();
    for (i, t) in g.triangles.iter().enumerate() {
        let root = find(&mut parent, i);
        cells.entry(root).or_default().extend(t.iter().copied());
    }
    let present: HashSet<[u32; 2]> = g
        .edges
        .iter()
        .map(|&([u, v], _)| [u.min(v), u.max(v)])
        .collect();
    let mut out = Vec::new();
    for verts in cells.values().filter(|c| c.len() >= 4) {
        let mut vs: Vec<u32> = verts.iter().copied().collect();
        vs.sort_unstable();
        // O(k²) per cell of k cocircular points; k = 4 on grids.
        for (i, &a) in vs.iter().enumerate() {
            for &b in &vs[i + 1..] {
                if present.contains(&[a, b]) {
                    continue;
                }
                let witness = vs.iter().copied().find(|&c| c != a && c != b).unwrap();
                if dot_sign(p(witness), p(a), p(b)) == 0 {
                    out.push([a, b]);
                }
            }
        }
    }
    out
}

fn canonical(mut t: [u32; 3]) -> [u32; 3] {
    t.sort_unstable();
    t
}

/// The Gabriel graph: edges as sorted `[min, max]` input-index pairs.
pub fn gabriel_graph(points: &PointSet) -> Result<Vec<[u32; 2]>> {
    let g = DelaunayGraph::new(points.points())?;
    let e = gabriel_from_delaunay(points.points(), &g);
    Ok(points.to_input_edges(e.into_iter()))
}
