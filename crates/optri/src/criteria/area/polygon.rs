//! The area objectives of the polygon program: the smallest triangle
//! (maximised, `maxmin-area`) and the largest triangle (minimised,
//! `minmax-area`) of a triangulation, each a bottleneck.
//!
//! A value is the bottleneck triangle itself, as its three corners (never an
//! `f64` area): two values are compared by the kernel's exact
//! [`compare_areas`](crate::kernel::compare_areas) of the triangles' absolute areas (comparisons only: no
//! area is ever stored or rounded).

use super::AreaBottleneck;
use crate::kernel::{orient_sign, Point};
use crate::polygon_program::{optimal_triangulation, Objective};

/// No triangle yet: `+∞` for [`AreaBottleneck::MaxMin`] (the identity of a
/// minimum), `0` for [`AreaBottleneck::MinMax`].
const NONE: [u32; 3] = [u32::MAX; 3];

/// The area bottleneck as an [`Objective`] over corners `0..k`, corner `c`
/// at `point(c)`.
pub(crate) struct BottleneckArea<'a, P: Fn(usize) -> Point> {
    pub(crate) point: &'a P,
    pub(crate) kind: AreaBottleneck,
}

impl<P: Fn(usize) -> Point> BottleneckArea<'_, P> {
    /// Is `s` strictly better than `t` as a bottleneck (`NONE` = the
    /// identity, better than every triangle)?
    fn strictly_better(&self, s: [u32; 3], t: [u32; 3]) -> bool {
        if t == NONE {
            return false;
        }
        if s == NONE {
            return true;
        }
        self.kind.better(|c| (self.point)(c as usize), s, t)
    }
}

impl<P: Fn(usize) -> Point> Objective for BottleneckArea<'_, P> {
    type Value = [u32; 3];
    fn empty(&self) -> [u32; 3] {
        NONE
    }
    fn diagonal(&self, _: usize, _: usize) -> Option<[u32; 3]> {
        None
    }
    fn triangle(&self, i: usize, m: usize, j: usize) -> Option<[u32; 3]> {
        Some([i as u32, m as u32, j as u32])
    }
    /// The worse of the two: the bottleneck of the union.
    fn combine(&self, s: [u32; 3], t: [u32; 3]) -> [u32; 3] {
        if self.strictly_better(s, t) {
            t
        } else {
            s
        }
    }
    fn better(&self, s: [u32; 3], t: [u32; 3]) -> bool {
        self.strictly_better(s, t)
    }
}

/// The optimal triangulation of the counter-clockwise polygon `polygon`
/// (indices into `points`) under `kind`, by the polygon program with every
/// chord allowed (the caller's polygon is convex) and flat triangles
/// forbidden; triangles as indices into `points`.
pub(crate) fn convex_polygon_program(
    points: &[Point],
    polygon: &[u32],
    kind: AreaBottleneck,
) -> Vec<[u32; 3]> {
    let p = |c: usize| points[polygon[c] as usize];
    let solved = optimal_triangulation(
        polygon.len(),
        |_, _| true,
        |i, m, j| orient_sign(p(i), p(m), p(j)) > 0,
        &BottleneckArea { point: &p, kind },
    )
    .expect("a convex polygon has a triangulation without flat triangles");
    solved
        .triangles
        .into_iter()
        .map(|t| t.map(|c| polygon[c]))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The best bottleneck over all triangulations of a convex polygon by
    /// recursion over the apex of the base edge, areas compared exactly as
    /// doubled integer areas (small integer coordinates).
    fn brute(points: &[Point], kind: AreaBottleneck) -> i64 {
        fn twice(p: &[Point], a: usize, b: usize, c: usize) -> i64 {
            let d = (p[b][0] - p[a][0]) * (p[c][1] - p[a][1])
                - (p[b][1] - p[a][1]) * (p[c][0] - p[a][0]);
            d.abs() as i64
        }
        fn best(p: &[Point], i: usize, j: usize, kind: AreaBottleneck) -> Option<i64> {
            if j == i + 1 {
                return Some(match kind {
                    AreaBottleneck::MaxMin => i64::MAX,
                    AreaBottleneck::MinMax => 0,
                });
            }
            let mut out: Option<i64> = None;
            for m in i + 1..j {
                let a = twice(p, i, m, j);
                if a == 0 {
                    continue;
                }
                let (Some(l), Some(r)) = (best(p, i, m, kind), best(p, m, j, kind)) else {
                    continue;
                };
                let v = match kind {
                    AreaBottleneck::MaxMin => a.min(l).min(r),
                    AreaBottleneck::MinMax => a.max(l).max(r),
                };
                out = Some(match (out, kind) {
                    (None, _) => v,
                    (Some(o), AreaBottleneck::MaxMin) => o.max(v),
                    (Some(o), AreaBottleneck::MinMax) => o.min(v),
                });
            }
            out
        }
        best(points, 0, points.len() - 1, kind).unwrap()
    }

    #[test]
    fn bottlenecks_match_a_direct_recursion() {
        // Convex polygons, some with collinear boundary points and many ties.
        let polygons: Vec<Vec<Point>> = vec![
            vec![[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0]],
            vec![
                [0.0, 0.0],
                [2.0, 0.0],
                [4.0, 0.0],
                [4.0, 2.0],
                [2.0, 3.0],
                [0.0, 2.0],
            ],
            vec![
                [0.0, 0.0],
                [1.0, 0.0],
                [3.0, 1.0],
                [4.0, 3.0],
                [3.0, 5.0],
                [1.0, 6.0],
                [-1.0, 4.0],
                [-1.0, 1.0],
            ],
            vec![
                [0.0, 0.0],
                [1.0, 0.0],
                [2.0, 0.0],
                [3.0, 0.0],
                [3.0, 1.0],
                [2.0, 2.0],
                [1.0, 2.0],
                [0.0, 1.0],
            ],
        ];
        for pts in polygons {
            let ring: Vec<u32> = (0..pts.len() as u32).collect();
            for kind in [AreaBottleneck::MaxMin, AreaBottleneck::MinMax] {
                let tris = convex_polygon_program(&pts, &ring, kind);
                assert_eq!(tris.len(), pts.len() - 2);
                let areas = tris.iter().map(|t| {
                    let [a, b, c] = t.map(|i| i as usize);
                    let p = &pts;
                    ((p[b][0] - p[a][0]) * (p[c][1] - p[a][1])
                        - (p[b][1] - p[a][1]) * (p[c][0] - p[a][0]))
                        .abs() as i64
                });
                let got = match kind {
                    AreaBottleneck::MaxMin => areas.min().unwrap(),
                    AreaBottleneck::MinMax => areas.max().unwrap(),
                };
                assert_eq!(got, brute(&pts, kind), "{kind:?} {pts:?}");
            }
        }
    }
}
