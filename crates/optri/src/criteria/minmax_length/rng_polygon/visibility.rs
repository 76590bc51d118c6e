//! The corners visible from a corner, in angular order (§6 step 1): the
//! walk through the region's Delaunay triangles described in [`super`].

use super::bits::set;
use super::{RngPolygon, NONE};
use crate::kernel::LengthOrder;

impl<L: LengthOrder> RngPolygon<'_, L> {
    /// Positions visible from corner `a` (diagonals and the two boundary
    /// edges), in counter-clockwise angular order, which for a (weakly)
    /// simple polygon is boundary order from `a + 1` to `a − 1`.
    #[cfg(test)]
    pub(super) fn visible(&self, a: usize) -> Vec<usize> {
        let mut row = vec![0u64; self.k.div_ceil(64)];
        self.visible_offsets(a, &mut row);
        (1..self.k)
            .filter(|&o| row[o / 64] >> (o % 64) & 1 == 1)
            .map(|o| self.at(a, o))
            .collect()
    }

    /// [`Self::visible`] as bits: sets bit `off(a, b)` of `row` (zeroed, at
    /// least `k` bits) for every position `b` visible from `a`. Setting bits
    /// puts them in boundary order, which is angular order, without a sort.
    pub(super) fn visible_offsets(&self, a: usize, row: &mut [u64]) {
        let o = self.v[a];
        let mut mark = |b: u32| set(row, self.off(a, b as usize));
        // (triangle, edge j, r, l): edge j of the triangle, seen from o
        // through the wedge from ray o→r (clockwise side) to ray o→l.
        let mut stack: Vec<(u32, u8, u32, u32)> = Vec::new();
        let (mut t, mut i) = self.fan_start[a];
        loop {
            let (c, pos) = (&self.corners[t as usize], &self.positions[t as usize]);
            let (i1, i2) = ((i as usize + 1) % 3, (i as usize + 2) % 3);
            mark(pos[i1]);
            mark(pos[i2]);
            if self.neighbours[t as usize][i1] != NONE {
                stack.push((t, i1 as u8, c[i1], c[i2]));
            }
            let next = self.neighbours[t as usize][i2];
            if next == NONE {
                break;
            }
            t = next;
            i = self.corners[t as usize]
                .iter()
                .position(|&w| w == o)
                .unwrap_or(0) as u8;
        }
        while let Some((t, j, r, l)) = stack.pop() {
            let c = &self.corners[t as usize];
            let x = c[j as usize];
            let t2 = self.neighbours[t as usize][j as usize];
            let c2 = &self.corners[t2 as usize];
            // In t2 the shared edge runs x → ... reversed: y = c2[iy], x = c2[iy+1], z = c2[iy+2].
            let ix = c2.iter().position(|&w| w == x).unwrap_or(0);
            let (iy, iz) = ((ix + 2) % 3, (ix + 1) % 3);
            let z = c2[iz];
            if z == o {
                continue; // a crack copy of o: nothing beyond is visible
            }
            let right_of_l = self.geo.orient(o, z, l) > 0;
            let left_of_r = self.geo.orient(o, r, z) > 0;
            if left_of_r && right_of_l {
                mark(self.positions[t2 as usize][iz]);
            }
            let n2 = &self.neighbours[t2 as usize];
            if left_of_r && n2[ix] != NONE {
                stack.push((t2, ix as u8, r, if right_of_l { z } else { l }));
            }
            if right_of_l && n2[iz] != NONE {
                stack.push((t2, iz as u8, if left_of_r { z } else { r }, l));
            }
            let _ = iy;
        }
        // Offset 0 is `a` itself (a fan corner can be a crack copy of it).
        row[0] &= !1;
    }
}

#[cfg(test)]
mod tests {
    use super::super::{regions, rng_perturbed, rng_perturbed_flags, Counters, Mesh, RngPolygon};
    use crate::kernel::Point;
    use crate::spatial::convex_hull_cycle;
    use crate::structures::DelaunayGraph;
    use rand::{rngs::StdRng, Rng, SeedableRng};

    /// Seeds of the point sets, with their grid width (`None`: uniform).
    const SEEDS_AND_GRIDS: [(u64, Option<u32>); 4] =
        [(1, None), (2, Some(6)), (3, None), (4, Some(10))];

    /// `n` random points, sorted and distinct: on a `width × width` integer
    /// grid (many ties), or uniform in `[0, 1000)²`.
    fn random_points(n: usize, seed: u64, width: Option<u32>) -> Vec<Point> {
        let mut rng = StdRng::seed_from_u64(seed);
        let mut pts: Vec<Point> = (0..n)
            .map(|_| match width {
                Some(w) => [rng.gen_range(0..w) as f64, rng.gen_range(0..w) as f64],
                None => [rng.gen_range(0.0..1000.0), rng.gen_range(0.0..1000.0)],
            })
            .collect();
        pts.sort_by(|a, b| a[0].total_cmp(&b[0]).then(a[1].total_cmp(&b[1])));
        pts.dedup();
        pts
    }

    #[test]
    fn visibility_walk_matches_the_diagonal_test() {
        let counters = Counters::default();
        for (seed, grid) in SEEDS_AND_GRIDS {
            let pts = random_points(60, seed, grid);
            let g = DelaunayGraph::with_topology(&pts).unwrap();
            let rng = rng_perturbed(&pts, &g);
            let flags = rng_perturbed_flags(&pts, &g);
            let hull = convex_hull_cycle(&pts);
            let mesh = Mesh::new(&g, &flags);
            for r in regions(&pts, &rng, &hull) {
                let f = RngPolygon::new(&pts, &r, &mesh, &counters).unwrap();
                let k = r.len();
                for a in 0..k {
                    let vis = f.visible(a);
                    let want: Vec<usize> = (1..k)
                        .map(|o| (a + o) % k)
                        .filter(|&b| {
                            f.off(a, b) == 1 || f.off(a, b) == k - 1 || f.geo.is_diagonal(a, b)
                        })
                        .collect();
                    assert_eq!(vis, want, "region {r:?} corner {a}");
                }
            }
        }
    }
}
