//! The regions the skeleton's certain edges leave (module docs of
//! `faces`): traced directly when the certain edges connect every point,
//! else joined from the constrained Delaunay triangles across the sides
//! that are not certain edges.

use super::super::skeleton::Skeleton;
use super::Region;
use crate::kernel::{compare_angles, Point};
use crate::parallel::prelude::*;
use crate::structures::{ConstrainedDelaunay, Csr};
use std::cmp::Ordering;
use std::collections::{BTreeSet, HashMap, HashSet};

/// The skeleton's certain edges.
fn certain_edges(sk: &Skeleton) -> Vec<[u32; 2]> {
    sk.edges
        .iter()
        .zip(&sk.certain)
        .filter(|(_, &c)| c)
        .map(|(&e, _)| e)
        .collect()
}

/// The faces of the plane graph of the certain edges (the hull among them)
/// when it connects every point, as boundary walks (the face on the left,
/// each starting at its least half-edge `(from, to)`, as [`regions`] starts
/// them), the outer face left out; `None` when some point is on no certain
/// edge or the graph is not connected. A connected plane graph has faces
/// bounded by one closed walk each (Euler), and a point inside a face would
/// be a vertex of the graph, hence on its walk: every face is a simple
/// region (weakly simple where an edge dangles), found without the
/// constrained Delaunay triangulation by following, at each vertex, the
/// next certain edge clockwise (exact angular order).
pub(super) fn traced_faces(pts: &[Point], sk: &Skeleton) -> Option<Vec<Vec<u32>>> {
    let n = pts.len();
    let certain = certain_edges(sk);
    if certain.len() + 1 < n {
        return None; // a spanning connected graph has at least n − 1 edges
    }
    let mut parent: Vec<u32> = (0..n as u32).collect();
    fn root(parent: &mut [u32], mut v: u32) -> u32 {
        while parent[v as usize] != v {
            let up = parent[parent[v as usize] as usize];
            parent[v as usize] = up;
            v = up;
        }
        v
    }
    let mut components = n;
    for &[u, v] in &certain {
        let (a, b) = (root(&mut parent, u), root(&mut parent, v));
        if a != b {
            parent[a.max(b) as usize] = a.min(b);
            components -= 1;
        }
    }
    drop(parent);
    if components != 1 {
        return None;
    }
    // Half-edges `v → w` grouped by `v`, counter-clockwise from east.
    let mut around = Csr::from_pairs(n, certain.iter().flat_map(|&[u, v]| [(u, v), (v, u)]));
    drop(certain);
    // Two certain edges in one direction would overlap: not a plane graph
    // (never expected; the general way then decides).
    let plane = around
        .rows_mut()
        .collect::<Vec<_>>()
        .into_par_iter()
        .enumerate()
        .all(|(v, list)| {
            let a = pts[v];
            list.sort_unstable_by(|&x, &y| compare_angles(a, pts[x as usize], pts[y as usize]));
            list.windows(2).all(|w| {
                compare_angles(a, pts[w[0] as usize], pts[w[1] as usize]) == Ordering::Less
            })
        });
    if !plane {
        return None;
    }
    // next(u → v) = v → w, w the neighbour of v just clockwise of u: the
    // face left of u → v continues along it.
    let to = around.items();
    let source = around.key_of_each_item();
    let next: Vec<u32> = (0..to.len())
        .into_par_iter()
        .map(|h| {
            let (u, v) = (source[h], to[h]);
            let range = around.range(v);
            let list = around.row(v);
            let b = pts[v as usize];
            let i = list.partition_point(|&x| {
                compare_angles(b, pts[x as usize], pts[u as usize]) == Ordering::Less
            });
            debug_assert_eq!(list[i], u);
            (range.start + (i + list.len() - 1) % list.len()) as u32
        })
        .collect();
    // The outer face holds the hull's edges reversed: `hull[1] → hull[0]`.
    let hull = crate::spatial::convex_hull_cycle(pts);
    let outer = around
        .range(hull[1])
        .find(|&h| to[h] == hull[0])
        .expect("hull edges are certain");
    let mut seen = vec![false; to.len()];
    let mut faces = Vec::with_capacity(to.len() / 3);
    for start in 0..to.len() {
        if seen[start] {
            continue;
        }
        let mut cycle = Vec::new();
        let mut is_outer = false;
        let mut h = start;
        while !seen[h] {
            seen[h] = true;
            is_outer |= h == outer;
            cycle.push(source[h]);
            h = next[h] as usize;
        }
        if is_outer {
            continue;
        }
        let k = cycle.len();
        let first = (0..k)
            .min_by_key(|&i| (cycle[i], cycle[(i + 1) % k]))
            .expect("a face has a boundary");
        cycle.rotate_left(first);
        faces.push(cycle);
    }
    Some(faces)
}

/// The regions of the skeleton from the constrained Delaunay triangulation
/// of the points with the certain edges as constraints: triangles joined
/// across sides that are neither constraints nor on the hull, with their
/// boundary walks (each from its least half-edge `(from, to)`), isolated
/// points and triangles.
pub(super) fn regions(pts: &[Point], sk: &Skeleton) -> crate::error::Result<Vec<Region>> {
    let constraints = certain_edges(sk);
    let cdt = ConstrainedDelaunay::new(pts, &constraints)?;
    drop(constraints);
    // Side `j` of triangle `t` is the half-edge `3t + j`.
    let ends = |d: usize| {
        let t = cdt.triangles[d / 3];
        (t[d % 3], t[(d % 3 + 1) % 3])
    };
    let is_boundary = |d: usize| cdt.is_barrier(d / 3, d % 3);
    // The half-edge after `d` in its triangle, and its twin across.
    let next_in_triangle = |d: usize| 3 * (d / 3) + (d % 3 + 1) % 3;
    let twin = |d: usize| {
        let u = cdt.neighbours[d / 3][d % 3];
        3 * u as usize + cdt.side_towards(u, (d / 3) as u32)
    };
    // Flood fill triangles across unconstrained sides.
    let mut region_of = vec![u32::MAX; cdt.triangles.len()];
    let mut out: Vec<Region> = Vec::new();
    for f in 0..cdt.triangles.len() {
        if region_of[f] != u32::MAX {
            continue;
        }
        let r = out.len() as u32;
        let mut stack = vec![f];
        region_of[f] = r;
        let mut members = Vec::new();
        let mut boundary: Vec<usize> = Vec::new();
        while let Some(g) = stack.pop() {
            members.push(g);
            for d in 3 * g..3 * g + 3 {
                if is_boundary(d) {
                    boundary.push(d);
                } else {
                    let h = cdt.neighbours[g][d % 3] as usize;
                    if region_of[h] == u32::MAX {
                        region_of[h] = r;
                        stack.push(h);
                    }
                }
            }
        }
        // Boundary walks: after u → v, turn around v through the region to
        // the next boundary half-edge leaving v.
        let mut next: HashMap<usize, usize> = HashMap::with_capacity(boundary.len());
        for &d in &boundary {
            let mut e = next_in_triangle(d);
            while !is_boundary(e) {
                e = next_in_triangle(twin(e));
            }
            next.insert(d, e);
        }
        let mut used: HashSet<usize> = HashSet::with_capacity(boundary.len());
        let mut cycles = Vec::new();
        boundary.sort_unstable_by_key(|&d| ends(d));
        for &d in &boundary {
            if used.contains(&d) {
                continue;
            }
            let mut cycle = Vec::new();
            let mut e = d;
            while used.insert(e) {
                cycle.push(ends(e).0);
                e = next[&e];
            }
            cycles.push(cycle);
        }
        let on_boundary: HashSet<u32> = cycles.iter().flatten().copied().collect();
        let mut cdt_triangles = Vec::with_capacity(members.len());
        let mut inner = BTreeSet::new();
        for g in members {
            let t = cdt.triangles[g];
            for v in t {
                if !on_boundary.contains(&v) {
                    inner.insert(v);
                }
            }
            cdt_triangles.push(t);
        }
        out.push(Region {
            cycles,
            inner: inner.into_iter().collect(),
            cdt_triangles,
        });
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use optri_oracle::inputs;
    use rand::{rngs::StdRng, SeedableRng};

    const SEED_REGIONS: u64 = 21;

    /// The faces traced from the certain edges are exactly the constrained
    /// Delaunay regions (same walks, same starts), and they are traced
    /// exactly when every region is simple: on random, clustered, grid,
    /// lattice (collinear runs, cocircular quadruples) and wheel sets, with
    /// both outcomes met.
    #[test]
    fn traced_faces_are_the_constrained_delaunay_regions() {
        let mut rng = StdRng::seed_from_u64(SEED_REGIONS);
        let mut sets: Vec<Vec<Point>> = vec![
            inputs::uniform_unit_square(&mut rng, 2000),
            inputs::clustered(&mut rng, 1500, 12),
            inputs::shuffled_grid(&mut rng, 30, 30, 1.0),
            inputs::grid_subset(&mut rng, 40, 40, 0.5),
            inputs::distinct_lattice_points(&mut rng, 600, -20i64..20, -20i64..20),
            inputs::uniform_in_square(&mut rng, 1000, 1e12),
        ];
        for k in [13, 15, 17] {
            sets.push(super::super::ring_with(k, [0.0, 0.0]));
        }
        let (mut traced, mut general) = (0, 0);
        for pts in &sets {
            let candidates = super::super::super::skeleton::diamond_candidates(pts);
            let sk = super::super::super::skeleton::lmt_skeleton(pts, candidates).unwrap();
            let regions = regions(pts, &sk).unwrap();
            let simple = regions
                .iter()
                .all(|r| r.cycles.len() == 1 && r.inner.is_empty());
            match traced_faces(pts, &sk) {
                Some(mut faces) => {
                    assert!(simple, "traced although a region has a hole or a point");
                    let mut expected: Vec<Vec<u32>> =
                        regions.into_iter().map(|r| r.cycles[0].clone()).collect();
                    faces.sort();
                    expected.sort();
                    assert_eq!(faces, expected);
                    traced += 1;
                }
                None => {
                    assert!(!simple, "every region is simple, yet not traced");
                    general += 1;
                }
            }
        }
        assert!(
            traced >= 4 && general >= 3,
            "traced {traced}, general {general}"
        );
    }
}
