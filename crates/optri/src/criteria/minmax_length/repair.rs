//! §5.4: from a triangulation of the perturbed points `S′` back to one of
//! the input points `S`, by the Δ-Lemma.

use super::counters::Counters;
use crate::kernel::{orient_sign, Point};
use std::collections::HashMap;

/// §5.4: turns a triangulation of the perturbed points into one of the
/// input points. A triangle whose corners are collinear in `S` is *flat*.
/// The flat triangles, joined across shared edges, form components, each on
/// one line; every input point on the open segment `uw` of a non-flat
/// triangle `uwy` lies in the flat component across `uw` (it cannot be inside
/// the empty perturbed triangle). Replacing each such triangle by the fan
/// from `y` over the points of `uw` in order along the line, and dropping the
/// flat triangles, gives a triangulation of `S`; by the Δ-Lemma the new edges
/// are shorter than `max(|uy|, |wy|)`, so the longest edge does not grow.
pub(super) fn repair_flat_triangles(
    points: &[Point],
    triangles: Vec<[u32; 3]>,
    counters: &Counters,
) -> Vec<[u32; 3]> {
    let p = |m: u32| points[m as usize];
    let is_flat = |t: &[u32; 3]| orient_sign(p(t[0]), p(t[1]), p(t[2])) == 0;
    if !triangles.iter().any(is_flat) {
        return triangles;
    }
    counters
        .flat_triangles
        .add(triangles.iter().filter(|t| is_flat(t)).count());
    let key = |u: u32, w: u32| (u.min(w), u.max(w));
    // Flat triangles by edge, and their components (union-find).
    let flat: Vec<[u32; 3]> = triangles.iter().copied().filter(is_flat).collect();
    let mut parent: Vec<usize> = (0..flat.len()).collect();
    fn find(parent: &mut [usize], mut i: usize) -> usize {
        while parent[i] != i {
            parent[i] = parent[parent[i]];
            i = parent[i];
        }
        i
    }
    let mut by_edge: HashMap<(u32, u32), usize> = HashMap::new();
    for (i, t) in flat.iter().enumerate() {
        for j in 0..3 {
            let e = key(t[j], t[(j + 1) % 3]);
            if let Some(&other) = by_edge.get(&e) {
                let (a, b) = (find(&mut parent, i), find(&mut parent, other));
                parent[a] = b;
            } else {
                by_edge.insert(e, i);
            }
        }
    }
    // Points of each component, sorted along its line (lexicographic order
    // is an order along any line).
    let root: Vec<usize> = (0..flat.len()).map(|i| find(&mut parent, i)).collect();
    let mut members: HashMap<usize, Vec<u32>> = HashMap::new();
    for (i, t) in flat.iter().enumerate() {
        members.entry(root[i]).or_default().extend_from_slice(t);
    }
    let lex = |a: &u32, b: &u32| {
        let (pa, pb) = (p(*a), p(*b));
        pa[0].total_cmp(&pb[0]).then(pa[1].total_cmp(&pb[1]))
    };
    for list in members.values_mut() {
        list.sort_by(lex);
        list.dedup();
    }
    let mut out = Vec::with_capacity(triangles.len());
    let mut work: Vec<[u32; 3]> = triangles.into_iter().filter(|t| !is_flat(t)).collect();
    while let Some(t) = work.pop() {
        let split = (0..3).find_map(|j| {
            let (u, w, y) = (t[j], t[(j + 1) % 3], t[(j + 2) % 3]);
            let &f = by_edge.get(&key(u, w))?;
            let line = &members[&root[f]];
            let iu = line.iter().position(|&m| m == u)?;
            let iw = line.iter().position(|&m| m == w)?;
            (iu.abs_diff(iw) > 1).then(|| {
                let inner: Vec<u32> = if iu < iw {
                    line[iu..=iw].to_vec()
                } else {
                    line[iw..=iu].iter().rev().copied().collect()
                };
                (inner, y)
            })
        });
        match split {
            None => out.push(t),
            Some((chain, y)) => {
                for w in chain.windows(2) {
                    work.push([w[0], w[1], y]);
                }
            }
        }
    }
    out
}
