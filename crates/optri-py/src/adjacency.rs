//! The companions of `simplices` that `scipy.spatial.Delaunay` gives
//! (Virtanen et al., 2020, *SciPy 1.0: fundamental algorithms for
//! scientific computing in Python*, Nature Methods 17, `scipy.spatial`):
//! the triangle across each side (`neighbors`), a triangle at each input
//! point (`vertex_to_simplex`) and the boundary of the triangulated domain
//! (`convex_hull`). Combinatorial only: every triangle is counter-clockwise
//! and two triangles share at most one side, which the library's
//! `Triangulation::validate` guarantees.

use std::collections::HashMap;

/// The triangle opposite corner `j` of triangle `i` is across the side from
/// corner `j + 1` to corner `j + 2` (counter-clockwise, so the triangle is on
/// its left).
fn side(t: [u32; 3], j: usize) -> [u32; 2] {
    [t[(j + 1) % 3], t[(j + 2) % 3]]
}

/// `neighbors[i][j]`: the triangle that shares with triangle `i` the side
/// opposite its corner `j`, or `-1` where that side is on the boundary
/// (scipy's meaning). Sides are matched by sorting their vertex pairs, so
/// the two triangles of an inner side are adjacent in the order.
pub(crate) fn neighbors(triangles: &[[u32; 3]]) -> Vec<[i64; 3]> {
    let mut sides: Vec<(u64, usize)> = Vec::with_capacity(3 * triangles.len());
    for (i, &t) in triangles.iter().enumerate() {
        for j in 0..3 {
            let [a, b] = side(t, j);
            let key = (u64::from(a.min(b)) << 32) | u64::from(a.max(b));
            sides.push((key, 3 * i + j));
        }
    }
    sides.sort_unstable();
    let mut out = vec![[-1i64; 3]; triangles.len()];
    for pair in sides.windows(2) {
        let [(k0, s0), (k1, s1)] = [pair[0], pair[1]];
        if k0 == k1 {
            out[s0 / 3][s0 % 3] = (s1 / 3) as i64;
            out[s1 / 3][s1 % 3] = (s0 / 3) as i64;
        }
    }
    out
}

/// For each of the `n` input points, the smallest index of a triangle with
/// it as a corner, `-1` for a point that is no corner; a merged duplicate
/// (`[dropped, kept]` in `duplicates`) maps as its kept twin, so the
/// triangle contains it too.
pub(crate) fn vertex_to_simplex(
    triangles: &[[u32; 3]],
    n: usize,
    duplicates: &[[u32; 2]],
) -> Vec<i64> {
    let mut out = vec![-1i64; n];
    // Backwards, so that the smallest index is written last.
    for (i, t) in triangles.iter().enumerate().rev() {
        for &v in t {
            out[v as usize] = i as i64;
        }
    }
    for &[dropped, kept] in duplicates {
        out[dropped as usize] = out[kept as usize];
    }
    out
}

/// The boundary sides of the triangulated domain, each `[a, b]` with the
/// domain on its left, in counter-clockwise order from the side that leaves
/// the smallest vertex index. The domain (a convex hull or a simple
/// polygon's interior) is a disk whose boundary passes each of its vertices
/// once; were it not so, the sides are given sorted instead.
pub(crate) fn boundary(triangles: &[[u32; 3]], neighbors: &[[i64; 3]]) -> Vec<[u32; 2]> {
    let mut sides: Vec<[u32; 2]> = Vec::new();
    for (&t, across) in triangles.iter().zip(neighbors) {
        for (j, &neighbor) in across.iter().enumerate() {
            if neighbor < 0 {
                sides.push(side(t, j));
            }
        }
    }
    sides.sort_unstable();
    let next: HashMap<u32, u32> = sides.iter().map(|&[a, b]| (a, b)).collect();
    let Some(&[start, _]) = sides.first() else {
        return sides;
    };
    if next.len() != sides.len() {
        return sides;
    }
    let mut cycle = Vec::with_capacity(sides.len());
    let mut a = start;
    while let Some(&b) = next.get(&a) {
        cycle.push([a, b]);
        a = b;
        if a == start || cycle.len() > sides.len() {
            break;
        }
    }
    if a == start && cycle.len() == sides.len() {
        cycle
    } else {
        sides
    }
}
