//! Simple polygons as input ([`crate::triangulate_polygon`]): the polygon
//! solvers of `delaunay`, `minmax-length`, `greedy` and `min-weight`, and the
//! one run of the [polygon program](crate::polygon_program) on a
//! [`SimplePolygon`] that the decomposable criteria (these and the area ones)
//! share.
//!
//! # The polygon program on a simple polygon
//! Klincsek's dynamic program (G. T. Klincsek, *Minimal triangulations of
//! polygonal domains*, Ann. Discrete Math. 9, 1980; Algorithm 21 of T. S.
//! Vassilev, *Optimal area triangulation*, PhD thesis, University of
//! Saskatchewan, 2005, whose listing omits the visibility test) runs over the
//! polygon's corners in counter-clockwise order. A chord may be used only if
//! it is a diagonal ([`SimplePolygon::is_diagonal`]: its open segment inside
//! the polygon, exact) and a triangle only if its three corners are not
//! collinear (a straight 180° vertex is then always the corner of a proper
//! triangle). Chords inside a simple polygon split it into two simple
//! polygons, so the recursion is exact. The diagonal table costs O(n) per
//! chord, O(n³) in all (skipped for a strictly convex polygon, where every
//! chord is a diagonal), computed in parallel; the program is O(n³) time and
//! O(n²) memory.
//!
//! | criterion | on a polygon | optimality |
//! |---|---|---|
//! | `min-weight` | polygon program, total length of the diagonals (certified intervals, exact sums of square roots on ties) | exact |
//! | `minmax-length` | polygon program, longest diagonal, exact length comparisons | exact |
//! | `delaunay` | spade's constrained Delaunay triangulation with the boundary as constraints | exact |
//! | `greedy` | shortest diagonal first (symbolic length order), crossing none taken | exact |
//!
//! The longest edge of a polygon triangulation is the longer of the longest
//! boundary edge, which every triangulation has, and the longest diagonal; so
//! minimising the longest diagonal minimises the longest edge.
//!
//! # Degenerate input
//! Ties between equal lengths: the program keeps the first best split corner
//! (see [`crate::polygon_program`]), so some optimum is returned. The greedy
//! order is [`crate::kernel::segment_order`] on the ring positions, a total
//! order, so the greedy triangulation is unique. spade picks one Delaunay
//! completion for cocircular corners; every one is constrained Delaunay.

use super::min_weight::TotalLength;
use super::{Diagnostics, Optimality, Options, Solved};
use crate::error::{Error, Result, UnsupportedReason};
use crate::kernel::{compare_lengths, orient_sign, properly_cross, segment_order, Point};
use crate::parallel::prelude::*;
use crate::polygon_program::{optimal_triangulation, LargestDiagonal, Objective};
use crate::structures::{PlanarGraph, SimplePolygon, Triangulation};
use crate::timing::{timed, Phase, Stopwatch};
use spade::{ConstrainedDelaunayTriangulation, Point2, Triangulation as _};
use std::collections::HashMap;

/// Largest polygon the polygon program accepts (O(n²) tables, O(n³) time).
pub const MAX_POLYGON_VERTICES: usize = 4000;

/// The point at corner `c` (counter-clockwise position `c`) of `polygon`.
pub(crate) fn corner_point(polygon: &SimplePolygon) -> impl Fn(usize) -> Point + '_ {
    let (vertices, ccw) = (polygon.vertices(), polygon.counter_clockwise());
    move |c| vertices[ccw[c] as usize]
}

/// `table[i * k + j]` for corners `i < j`: is the chord a diagonal? Boundary
/// edges are `false`. Rows in parallel; every chord is a diagonal of a
/// strictly convex polygon.
fn diagonal_table(polygon: &SimplePolygon) -> Vec<bool> {
    let k = polygon.len();
    let ccw = polygon.counter_clockwise();
    let convex = polygon.is_strictly_convex();
    let rows: Vec<Vec<bool>> = (0..k)
        .into_par_iter()
        .map(|i| {
            (0..k)
                .map(|j| {
                    let boundary = j <= i + 1 || (i == 0 && j == k - 1);
                    !boundary && (convex || polygon.is_diagonal(ccw[i] as usize, ccw[j] as usize))
                })
                .collect()
        })
        .collect();
    rows.concat()
}

/// Refuses polygons above [`MAX_POLYGON_VERTICES`].
pub(crate) fn check_size(polygon: &SimplePolygon, criterion: &'static str) -> Result<()> {
    if polygon.len() > MAX_POLYGON_VERTICES {
        return Err(Error::Unsupported {
            criterion,
            reason: UnsupportedReason::TooManyPoints {
                limit: MAX_POLYGON_VERTICES,
                distinct: polygon.len(),
                because: "Klincsek's O(n³) program with O(n²) tables",
            },
        });
    }
    Ok(())
}

/// The optimal triangulation of `polygon` under `objective`, whose corner
/// `c` is [`corner_point`]`(polygon)(c)`: diagonals only, no flat triangle.
/// Records the phases `"diagonals"` and `"polygon program"`.
pub(crate) fn polygon_program<O: Objective>(
    polygon: &SimplePolygon,
    criterion: &'static str,
    objective: &O,
    phases: &mut Vec<Phase>,
) -> Result<Triangulation> {
    check_size(polygon, criterion)?;
    let mut stopwatch = Stopwatch::new(phases);
    let k = polygon.len();
    let table = diagonal_table(polygon);
    stopwatch.lap("diagonals");
    let p = corner_point(polygon);
    let solved = optimal_triangulation(
        k,
        |i, j| table[i * k + j],
        |i, m, j| orient_sign(p(i), p(m), p(j)) > 0,
        objective,
    )
    .ok_or_else(|| Error::Internal("a simple polygon without a triangulation".into()))?;
    stopwatch.lap("polygon program");
    let ccw = polygon.counter_clockwise();
    let triangles = solved
        .triangles
        .into_iter()
        .map(|t| t.map(|c| ccw[c]))
        .collect();
    Ok(Triangulation::from_polygon_positions(polygon, triangles))
}

/// `min-weight` on a polygon: the polygon program with the total length of
/// the diagonals (the boundary's length is the same in every triangulation).
pub(crate) fn solve_min_weight(
    polygon: &SimplePolygon,
    _: &Options,
    phases: &mut Vec<Phase>,
) -> Result<Solved> {
    let p = corner_point(polygon);
    let triangulation = polygon_program(polygon, "min-weight", &TotalLength { point: &p }, phases)?;
    Ok(Solved {
        triangulation,
        algorithm: "Klincsek dynamic program on the polygon, O(n^3), exact sums of square roots"
            .to_string(),
        optimality: Optimality::Exact,
        diagnostics: Diagnostics::default(),
        bound: None,
    })
}

/// `minmax-length` on a polygon: the polygon program with the longest
/// diagonal as a bottleneck, compared exactly.
pub(crate) fn solve_minmax_length(
    polygon: &SimplePolygon,
    _: &Options,
    phases: &mut Vec<Phase>,
) -> Result<Solved> {
    let p = corner_point(polygon);
    let objective = LargestDiagonal::new(polygon.len(), |s: [usize; 2], t: [usize; 2]| {
        compare_lengths(p(s[0]), p(s[1]), p(t[0]), p(t[1]))
    });
    let triangulation = polygon_program(polygon, "minmax-length", &objective, phases)?;
    Ok(Solved {
        triangulation,
        algorithm: "Klincsek dynamic program on the polygon, O(n^3), exact length comparisons"
            .to_string(),
        optimality: Optimality::Exact,
        diagnostics: Diagnostics::default(),
        bound: None,
    })
}

/// `greedy` on a polygon: [`greedy_polygon`].
pub(crate) fn solve_greedy(
    polygon: &SimplePolygon,
    _: &Options,
    phases: &mut Vec<Phase>,
) -> Result<Solved> {
    let triangulation = timed(phases, "greedy", || greedy_polygon(polygon))?;
    Ok(Solved {
        triangulation,
        algorithm: "greedy on the polygon's diagonals: shortest first by the exact symbolic \
                    length order, each kept unless it crosses a kept one, O(n^3)"
            .to_string(),
        optimality: Optimality::Exact,
        diagnostics: Diagnostics::default(),
        bound: None,
    })
}

/// The greedy triangulation of a simple polygon: its diagonals
/// ([`SimplePolygon::is_diagonal`]) in the order of
/// [`crate::kernel::segment_order`] (exact squared length, ties by the
/// kernel's perturbation of the ring positions), each kept unless it crosses
/// one kept earlier. Two diagonals conflict only by crossing properly: their
/// open segments contain no vertex, so they cannot overlap or touch
/// elsewhere. Chords are tested for crossings first and for being diagonals
/// only then; O(n³) worst case.
pub(crate) fn greedy_polygon(polygon: &SimplePolygon) -> Result<Triangulation> {
    let pts = polygon.vertices();
    let n = pts.len();
    let mut chords: Vec<[u32; 2]> = Vec::with_capacity(n * (n - 1) / 2);
    for a in 0..n as u32 {
        for b in a + 2..n as u32 {
            if !(a == 0 && b as usize == n - 1) {
                chords.push([a, b]);
            }
        }
    }
    let order = segment_order(pts);
    chords.par_sort_unstable_by(|s, t| order(s, t));
    let p = |i: u32| pts[i as usize];
    let mut kept: Vec<[u32; 2]> = Vec::with_capacity(n.saturating_sub(3));
    for [a, b] in chords {
        if kept.len() == n - 3 {
            break;
        }
        let crossing = kept
            .iter()
            .rev()
            .any(|&[c, d]| properly_cross(p(a), p(b), p(c), p(d)));
        if !crossing && polygon.is_diagonal(a as usize, b as usize) {
            kept.push([a, b]);
        }
    }
    if kept.len() != n - 3 {
        return Err(Error::Internal(format!(
            "the greedy diagonals of a {n}-gon are {} (not n - 3)",
            kept.len()
        )));
    }
    let mut edges = kept;
    edges.extend((0..n as u32).map(|i| [i, (i + 1) % n as u32]));
    let mut triangles = Vec::with_capacity(n - 2);
    for face in PlanarGraph::new(pts, &edges).bounded_faces(pts) {
        match face.vertices[..] {
            [a, b, c] => triangles.push([a, b, c]),
            _ => {
                return Err(Error::Internal(format!(
                    "a face of the greedy polygon triangulation has {} corners",
                    face.vertices.len()
                )))
            }
        }
    }
    Ok(Triangulation::from_polygon_positions(polygon, triangles))
}

/// `delaunay` on a polygon: [`constrained_delaunay_polygon`].
pub(crate) fn solve_delaunay(
    polygon: &SimplePolygon,
    _: &Options,
    phases: &mut Vec<Phase>,
) -> Result<Solved> {
    let triangulation = timed(phases, "constrained delaunay", || {
        constrained_delaunay_polygon(polygon)
    })?;
    Ok(Solved {
        triangulation,
        algorithm: "spade constrained Delaunay triangulation of the polygon's interior (exact \
                    predicates)"
            .to_string(),
        optimality: Optimality::Exact,
        diagnostics: Diagnostics::default(),
        bound: None,
    })
}

/// The constrained Delaunay triangulation of a simple polygon's interior
/// (D. T. Lee & A. K. Lin, *Generalized Delaunay triangulation for planar
/// graphs*, 1986; L. P. Chew, *Constrained Delaunay triangulations*, 1989):
/// every interior edge is locally Delaunay, which among the triangulations of
/// the polygon maximises the smallest angle. spade triangulates the vertices
/// with the boundary edges as constraints; the inner faces inside the polygon
/// are found combinatorially, from the triangles on the left of the
/// counter-clockwise boundary edges across edges that are not boundary edges
/// (no constraint edge is crossed, so none leaves the polygon).
pub(crate) fn constrained_delaunay_polygon(polygon: &SimplePolygon) -> Result<Triangulation> {
    let pts = polygon.vertices();
    let n = pts.len();
    let vertices: Vec<Point2<f64>> = pts.iter().map(|p| Point2::new(p[0], p[1])).collect();
    let constraints: Vec<[usize; 2]> = (0..n).map(|i| [i, (i + 1) % n]).collect();
    let mut conflicts = 0usize;
    let cdt = ConstrainedDelaunayTriangulation::<Point2<f64>>::try_bulk_load_cdt(
        vertices,
        constraints,
        |_| conflicts += 1,
    )
    .map_err(|e| Error::Internal(format!("spade's constrained bulk load failed: {e:?}")))?;
    if conflicts > 0 || cdt.num_vertices() != n || cdt.num_constraints() != n {
        return Err(Error::Internal(format!(
            "spade's constrained triangulation of a simple {n}-gon has {} vertices, {} \
             constraints and {conflicts} conflicts",
            cdt.num_vertices(),
            cdt.num_constraints()
        )));
    }
    // spade keeps the vertex order of a bulk load without duplicates.
    let triangles: Vec<[u32; 3]> = cdt
        .inner_faces()
        .map(|f| {
            let [a, b, c] = f.vertices().map(|v| v.fix().index() as u32);
            if orient_sign(pts[a as usize], pts[b as usize], pts[c as usize]) < 0 {
                [a, c, b]
            } else {
                [a, b, c]
            }
        })
        .collect();
    let mut by_edge: HashMap<(u32, u32), usize> = HashMap::with_capacity(3 * triangles.len());
    for (t, &[a, b, c]) in triangles.iter().enumerate() {
        for e in [(a, b), (b, c), (c, a)] {
            by_edge.insert(e, t);
        }
    }
    let ccw = polygon.counter_clockwise();
    let boundary = |u: u32, v: u32| {
        let (u, v) = (u as usize, v as usize);
        (u + 1) % n == v || (v + 1) % n == u
    };
    let mut inside = vec![false; triangles.len()];
    let mut stack = Vec::new();
    for c in 0..n {
        let (u, v) = (ccw[c], ccw[(c + 1) % n]);
        let Some(&t) = by_edge.get(&(u, v)) else {
            return Err(Error::Internal(format!(
                "no constrained Delaunay triangle on the inner side of boundary edge ({u}, {v})"
            )));
        };
        stack.push(t);
    }
    while let Some(t) = stack.pop() {
        if inside[t] {
            continue;
        }
        inside[t] = true;
        let [a, b, c] = triangles[t];
        for (u, v) in [(a, b), (b, c), (c, a)] {
            if !boundary(u, v) {
                if let Some(&s) = by_edge.get(&(v, u)) {
                    stack.push(s);
                }
            }
        }
    }
    let kept: Vec<[u32; 3]> = triangles
        .into_iter()
        .zip(inside)
        .filter_map(|(t, keep)| keep.then_some(t))
        .collect();
    if kept.len() != n - 2 {
        return Err(Error::Internal(format!(
            "{} constrained Delaunay triangles inside a {n}-gon",
            kept.len()
        )));
    }
    Ok(Triangulation::from_polygon_positions(polygon, kept))
}
