//! Line classes: open vertices of the greedy triangulation's length rounds
//! (M. T. Dickerson, R. L. S. Drysdale, S. A. McElfresh & E. Welzl, *Fast
//! greedy triangulation algorithms*, 1997) whose open gaps all lie on one
//! line, so that no candidate joins two of them. Only the running time
//! depends on them.

use super::guard::NO_LINE;
use super::partial::OpenGaps;
use crate::kernel::{orient_sign, Point};
use crate::parallel::prelude::*;

/// Line classes of the open vertices (indices into `open`), for the guard
/// and the candidate listing: a vertex `v` whose open gaps are all straight
/// angles (each bounded by two neighbours collinear with `v`, so all of them
/// lie on one line `L` through `v`) can only be left strictly off `L`, so no
/// candidate joins it to another point of `L`. Chains of such vertices along
/// one line (each the other's gap neighbour) share a class, the smallest
/// open index in the chain; any other vertex gets [`NO_LINE`]. Pairs within
/// a class are skipped unlisted: a run of collinear points waiting for a
/// far apex would otherwise fill the guard's cells with hopeless pairs and
/// hold the threshold down for thousands of rounds (a run of 1000
/// points with two apexes took 8.8 s). Only the running time depends on the
/// classes: the skipped pairs fail `leaves_through` anyway.
pub(super) fn line_classes(points: &[Point], open: &[u32], gaps: &OpenGaps) -> Vec<u32> {
    let p = |v: u32| points[v as usize];
    // A gap neighbour of each straight-angle vertex (`NO_LINE` if none).
    let line_neighbour: Vec<u32> = open
        .par_iter()
        .enumerate()
        .map(|(i, &v)| match gaps.get(i) {
            Some(list)
                if !list.is_empty()
                    && list
                        .iter()
                        .all(|&[u, w]| orient_sign(p(v), p(u), p(w)) == 0) =>
            {
                list[0][0]
            }
            _ => NO_LINE,
        })
        .collect();
    if line_neighbour.iter().all(|&u| u == NO_LINE) {
        return line_neighbour;
    }
    let mut index = vec![NO_LINE; points.len()];
    for (i, &v) in open.iter().enumerate() {
        index[v as usize] = i as u32;
    }
    // Union-find over open indices: `v` joins the gap neighbours of its own
    // gaps that are straight-angle vertices of the same line.
    let mut parent: Vec<u32> = (0..open.len() as u32).collect();
    fn root(parent: &mut [u32], mut x: u32) -> u32 {
        while parent[x as usize] != x {
            let up = parent[parent[x as usize] as usize];
            parent[x as usize] = up;
            x = up;
        }
        x
    }
    for (i, &v) in open.iter().enumerate() {
        if line_neighbour[i] == NO_LINE {
            continue;
        }
        for &[u, w] in gaps.get(i).unwrap_or_default() {
            for x in [u, w] {
                let j = index[x as usize];
                // `x` is on `v`'s line; it shares the line if its own line
                // passes through `v`.
                if j != NO_LINE
                    && line_neighbour[j as usize] != NO_LINE
                    && orient_sign(p(x), p(line_neighbour[j as usize]), p(v)) == 0
                {
                    let (a, b) = (root(&mut parent, i as u32), root(&mut parent, j));
                    parent[a.max(b) as usize] = a.min(b);
                }
            }
        }
    }
    let chain: Vec<u32> = (0..open.len())
        .map(|i| {
            if line_neighbour[i] == NO_LINE {
                NO_LINE
            } else {
                root(&mut parent, i as u32)
            }
        })
        .collect();
    merge_chains_on_one_line(points, open, &line_neighbour, chain)
}

/// Joins the chains of [`line_classes`] that lie on one line into one class.
///
/// A closed vertex or a vertex with a non-straight open gap (the end of an
/// apex's fan) cuts a run into several chains, and the pairs between them
/// would fill the guard's cells (a run of 1000 points with two
/// apexes crawled through 3000 rounds). They are as hopeless as pairs within
/// a chain: a straight-angle vertex of a line `L` can only be left strictly
/// off `L`, whichever chain holds the other point of `L`. Chains are sorted
/// by a rounded key of their line (direction angle, then offset) and a
/// chain joins the previous one when both of its defining points lie on the
/// previous chain's line — an exact test, so only the running time depends
/// on the rounding (a missed join leaves two classes).
fn merge_chains_on_one_line(
    points: &[Point],
    open: &[u32],
    line_neighbour: &[u32],
    mut class: Vec<u32>,
) -> Vec<u32> {
    let p = |v: u32| points[v as usize];
    // The chains' roots (each is its own class), by the rounded line key.
    let mut roots: Vec<(f64, f64, u32)> = (0..open.len() as u32)
        .filter(|&i| class[i as usize] == i)
        .map(|i| {
            let (a, b) = (p(open[i as usize]), p(line_neighbour[i as usize]));
            let (mut dx, mut dy) = (b[0] - a[0], b[1] - a[1]);
            if dx < 0.0 || (dx == 0.0 && dy < 0.0) {
                (dx, dy) = (-dx, -dy);
            }
            let angle = dy.atan2(dx);
            let offset = (dx * a[1] - dy * a[0]) / dx.hypot(dy);
            (angle, offset, i)
        })
        .collect();
    if roots.len() < 2 {
        return class;
    }
    roots.sort_unstable_by(|x, y| x.0.total_cmp(&y.0).then(x.1.total_cmp(&y.1)));
    let mut joined_to = vec![NO_LINE; open.len()];
    let mut leader = roots[0].2;
    for &(_, _, r) in &roots[1..] {
        let (la, lb) = (p(open[leader as usize]), p(line_neighbour[leader as usize]));
        let (ra, rb) = (p(open[r as usize]), p(line_neighbour[r as usize]));
        if orient_sign(la, lb, ra) == 0 && orient_sign(la, lb, rb) == 0 {
            joined_to[r as usize] = leader;
        } else {
            leader = r;
        }
    }
    for c in class.iter_mut() {
        if *c != NO_LINE && joined_to[*c as usize] != NO_LINE {
            *c = joined_to[*c as usize];
        }
    }
    class
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Chains on one line join; a chain on a parallel line, one on a line
    /// whose rounded key equals the first line's but which is not it, and a
    /// vertex off every line stay apart.
    #[test]
    fn chains_join_exactly_when_on_one_line() {
        let points: Vec<Point> = vec![
            [0.0, 0.0],
            [1.0, 0.0],
            [5.0, 0.0],
            [6.0, 0.0],
            [8.0, 0.0],
            [9.0, 1e-300], // the line through 4 and 5 is not y = 0
            [0.0, 1.0],
            [1.0, 1.0],
            [20.0, 0.0],
        ];
        let open: Vec<u32> = (0..9).collect();
        let line_neighbour = [1, 0, 3, 2, 5, 4, 7, 6, NO_LINE];
        let chains = vec![0, 0, 2, 2, 4, 4, 6, 6, NO_LINE];
        let joined = merge_chains_on_one_line(&points, &open, &line_neighbour, chains);
        assert_eq!(joined, vec![0, 0, 0, 0, 4, 4, 6, 6, NO_LINE]);
        // Listed in the other order, the later chain joins the earlier one.
        let chains = vec![0, 0, 2, 2, NO_LINE, NO_LINE, NO_LINE, NO_LINE, NO_LINE];
        let line_neighbour = [1, 0, 3, 2, NO_LINE, NO_LINE, NO_LINE, NO_LINE, NO_LINE];
        let joined = merge_chains_on_one_line(&points, &open, &line_neighbour, chains);
        assert_eq!(joined[..4], [0, 0, 0, 0]);
    }
}
