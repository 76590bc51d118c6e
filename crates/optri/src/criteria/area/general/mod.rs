//! MaxMin-area and MinMax-area triangulations of general point sets (not in
//! convex position): the approximations of T. S. Vassilev, *Optimal area
//! triangulation*, PhD thesis, University of Saskatchewan, 2005, Chapter 3
//! (§3.4, Algorithms 75 and 76; Theorem 74) as repaired in the project's
//! implementation brief (`shared/notes/area-optimal.md` §4), plus a certified
//! bound on the optimum that proves some results optimal.
//!
//! No polynomial algorithm is known for either criterion on general point
//! sets (Table 4.1 of the thesis). We compute four candidates and return the
//! best under the objective, with every area comparison exact
//! ([`compare_areas`]; a bottleneck value is stored as the corner triple of
//! its triangle, never as a rounded area):
//!
//! 1. **Delaunay**: the Delaunay triangulation `DT` (spade).
//! 2. **Algorithm 75** (thesis L4372–4445, brief §4.1): if `DT`'s smallest
//!    angle `α*` is at least 30° (exact: [`angle_at_least_30_degrees`]), the
//!    optimal area *30°-triangulation*: by Theorem 74 (L4336) the relative
//!    neighbourhood graph lies in every triangulation whose angles are all at
//!    least 30°, so each bounded face of `RNG(S) ∪ hull(S)` is triangulated
//!    separately by Klincsek's program ([`optimal_triangulation`]) allowing
//!    only triangles with all three angles ≥ 30°. Feasible because `DT` is
//!    such a triangulation and contains `RNG ∪ hull`. If `α* < 30°` no
//!    30°-triangulation exists (`DT` maximises the smallest angle, Property
//!    13) and the algorithm returns `DT`.
//! 3. **The `RNG ∪ hull` optimum** (brief §4.1, "Option"): the same face
//!    programs without the angle filter, i.e. the optimum over all
//!    triangulations containing `RNG ∪ hull`. Both `DT` and Algorithm 75's
//!    result are in that set, so this candidate is never worse than either
//!    and keeps Algorithm 75's guarantee.
//! 4. **Algorithm 76** (L4466–4520, brief §4.2): from `DT`, flip an interior
//!    edge `xy` of a strictly convex quadrilateral `x b y a` to `ab` while
//!    (i) `xy` is locally Delaunay (`b` strictly outside the circle `xya`:
//!    a *reverse* Delaunay flip), (ii) the flip equalises areas,
//!    `min(A(axb), A(bya)) > min(A(xya), A(yxb))`, and (iii) both new
//!    triangles keep every angle at least `α*` ([`compare_corner_angles`]).
//!    Both pairs cover the same quadrilateral, so (ii) is equivalent to
//!    `max(A(axb), A(bya)) < max(A(xya), A(yxb))`: one rule serves MaxMin and
//!    MinMax, and the result is one triangulation `T̃₃` for both, never worse
//!    than `DT` under either objective (every flip raises the pair's minimum
//!    and lowers its maximum). Edges are processed first-in first-out,
//!    starting with `DT`'s interior edges in triangle order; a flip enqueues
//!    the four outer sides of its quadrilateral. *Termination:* a reverse
//!    Delaunay flip raises the lifted (paraboloid) surface, strictly above
//!    the removed edge, and the surface never descends, so a removed edge
//!    never returns: at most `C(n, 2)` flips.
//!
//! The faces of `RNG ∪ hull` are *weakly* simple polygons (zero-width cracks,
//! repeated vertices), not simple as L3891 says: the program indexes boundary
//! *corners* and [`PolygonCycle::is_diagonal`] decides chords between corners
//! (brief §5). The cost is `O(n log n)` for `DT`, the RNG and the faces,
//! `O(Σ k³)` time and `O(max k²)` memory for faces of `k` corners (cubic in
//! the worst case, e.g. points in convex position, where the RNG is nearly
//! the hull cycle and there is one face; faces above [`MAX_FACE_CORNERS`]
//! skip candidates 2 and 3), `O(n²)` flips worst case for Algorithm 76
//! (`O(n)` observed), and `O(h · n log n)` for the bound. Measured (release,
//! uniform points in the unit square, both objectives): about 10 ms at
//! n = 1000 and 0.1 s at n = 10⁴ (largest face 184 corners).
//!
//! # Guarantees
//! The thesis bounds the approximation only relative to `β`, the smallest
//! angle of the *unknown* optimum (Theorem 81, brief §4.3): nothing is
//! guaranteed a priori, so the result is an approximation unless the bound
//! below certifies it.
//!
//! # The certified bound
//! Let `ab` be an edge of the convex hull between consecutive hull points
//! (collinear hull points are vertices). Every triangulation `T` of `S`
//! contains `ab` (no segment between points of `S` crosses it and no point
//! lies on it) and exactly one triangle `abr` on its inner side, with `r`
//! strictly inside the hull's half-plane of `ab`; that triangle is *empty*
//! (its closed region holds no point of `S` but its corners), because `T`
//! uses every point as a vertex.
//!
//! * **MaxMin**: `μ(T) ≤ A(abr) ≤ M(ab)`, the largest area of an empty
//!   triangle on `ab`, for every `T` and every hull edge, so the optimum
//!   `μ* ≤ min_ab M(ab)`. An apex `r` is empty iff no other point `q` of the
//!   open half-plane has both `∠bаq ≤ ∠bar` and `∠abq ≤ ∠abr` (the closed
//!   triangle is the intersection of the two closed wedges at `a` and `b`
//!   with the half-plane, and the open segment `ab` holds no point): the
//!   empty apexes are the minimal points of the two angles. Sorting the
//!   points by the angle at `a` (ties by the angle at `b`) and keeping those
//!   whose angle at `b` is a strict running minimum finds them, exactly by
//!   orientation tests, in `O(n log n)` per edge.
//! * **MinMax**: `λ(T) ≥ A(abr) ≥ m(ab) = min_r A(abr)` over all `r` in the
//!   open half-plane, for every `T` and every hull edge, so the optimum
//!   `λ* ≥ max_ab m(ab)`; `O(n)` per edge. (The nearest point to the line
//!   `ab` always spans an empty triangle, so emptiness would not raise this.)
//!
//! The bound is reported as its triangle. A result whose smallest (largest)
//! area equals it is optimal, and is reported `exact`.
//!
//! # Degenerate input
//! Collinear points: flat triangles are never allowed (exact orientation);
//! collinear hull points are hull vertices and their hull edges are in every
//! triangulation. Cocircular points: spade's Delaunay completion is the
//! starting point; its smallest angle is the same for every completion. An
//! angle of exactly 30° cannot occur with rational coordinates (`tan 30° =
//! 1/√3`), so Theorem 74's equality case (brief §4.1) never arises; the
//! theorem assumes general position, and on other inputs Algorithm 75 still
//! returns a valid 30°-triangulation (its optimality among those is what
//! the tests check by enumeration). Equal areas: the first candidate in the
//! order above wins a tie; within a face program, the first split corner
//! (the program's rule); Algorithm 76's order is the FIFO above. Everything
//! works on the distinct-point numbering of [`PointSet`].

// Registered as a criterion by `criteria/area` (in progress); until then only
// the tests call it.

use crate::error::{Error, Result};
use crate::graphs::rng_from_delaunay;
use crate::kernel::{
    angle_at_least_30_degrees, compare_areas, compare_corner_angles, incircle_sign, orient_sign,
    Point,
};
use crate::polygon_program::{optimal_triangulation, Objective};
use crate::spatial::convex_hull_cycle;
use crate::structures::{DelaunayGraph, PlanarGraph, PointSet, PolygonCycle, NO_TRIANGLE};
use std::cmp::Ordering;
use std::collections::VecDeque;

/// Which bottleneck is optimised.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum AreaObjective {
    /// Maximise the smallest triangle area.
    MaxMin,
    /// Minimise the largest triangle area.
    MinMax,
}

/// The best triangulation found, which candidate it is, and the bound.
#[derive(Clone, Debug)]
pub(crate) struct GeneralAreaResult {
    /// Triangles as distinct-point indices.
    pub triangles: Vec<[u32; 3]>,
    /// The winning candidate (one of [`CANDIDATE_NAMES`]).
    pub algorithm: String,
    /// Proven optimal: the result attains [`Self::bound`].
    pub exact: bool,
    /// A triangle whose (doubled) area bounds the optimum (module docs): for
    /// MaxMin an upper bound on the optimal smallest area, for MinMax a lower
    /// bound on the optimal largest area. `None` never happens today (every
    /// accepted point set has a hull edge); kept for inputs without one.
    pub bound: Option<[u32; 3]>,
}

/// Candidate 1.
pub(crate) const DELAUNAY: &str = "Delaunay";
/// Candidate 2.
pub(crate) const ALGORITHM_75: &str =
    "Vassilev Algorithm 75: optimal 30°-triangulation of the RNG ∪ hull faces";
/// Candidate 3.
pub(crate) const RNG_HULL_OPTIMUM: &str = "optimum over triangulations containing RNG ∪ hull";
/// Candidate 4.
pub(crate) const ALGORITHM_76: &str =
    "Vassilev Algorithm 76: angle-safe area-equalising reverse-Delaunay flips";
/// The candidates in their tie-breaking order.
#[cfg_attr(not(test), allow(dead_code))] // the ratio tests print them
pub(crate) const CANDIDATE_NAMES: [&str; 4] =
    [DELAUNAY, ALGORITHM_75, RNG_HULL_OPTIMUM, ALGORITHM_76];

/// One candidate triangulation with its bottleneck triangle.
#[derive(Clone, Debug)]
pub(crate) struct Candidate {
    pub name: &'static str,
    pub triangles: Vec<[u32; 3]>,
    /// The smallest (MaxMin) or largest (MinMax) triangle.
    pub bottleneck: [u32; 3],
}

/// Faces of `RNG ∪ hull` with more corners than this are not given to the
/// cubic face program: if any face is larger, candidates 2 (step 3) and 3
/// are skipped and the result is the better of Delaunay and Algorithm 76.
/// Near-convex inputs (most points on the hull) are the ones that reach it;
/// points in convex position belong to the convex-polygon algorithm anyway.
/// Measured worst case: 500 points on a circle, one face, about 4 s (nearly
/// all triangles tie in area up to rounding, so most comparisons take the
/// exact path); 900 took 21 s.
pub(crate) const MAX_FACE_CORNERS: usize = 500;

/// Every candidate, in [`CANDIDATE_NAMES`] order, with what the algorithms
/// learnt on the way.
#[cfg_attr(not(test), allow(dead_code))] // statistics read by the tests
pub(crate) struct Candidates {
    /// The candidates computed: all four, or without the face programs
    /// (Algorithm 75's step 3 and the `RNG ∪ hull` optimum) when a face
    /// exceeds the cap.
    pub list: Vec<Candidate>,
    /// Corners of the largest face of `RNG ∪ hull`.
    pub largest_face: usize,
    /// `DT`'s smallest angle as a corner `[apex, a, b]`.
    pub smallest_angle: [u32; 3],
    /// Did Algorithm 75 run its step 3 (`α* ≥ 30°`)?
    pub thirty_degrees: bool,
    /// Flips made by Algorithm 76.
    pub flips: usize,
}

/// The best of the four candidates under `objective`, with the certified
/// bound (module docs).
///
/// # Errors
/// [`Error::Internal`] if spade fails or a face program finds no
/// triangulation (a bug).
pub(crate) fn area_general(
    points: &PointSet,
    objective: AreaObjective,
) -> Result<GeneralAreaResult> {
    let pts = points.points();
    let candidates = candidates(points, objective)?;
    let mut best = 0;
    for (i, c) in candidates.list.iter().enumerate() {
        if objective.better(pts, c.bottleneck, candidates.list[best].bottleneck) {
            best = i;
        }
    }
    let winner = &candidates.list[best];
    let bound = certified_bound(pts, &convex_hull_cycle(pts), objective);
    let exact = bound.is_some_and(|b| area_order(pts, winner.bottleneck, b) == Ordering::Equal);
    Ok(GeneralAreaResult {
        triangles: winner.triangles.clone(),
        algorithm: winner.name.to_string(),
        exact,
        bound,
    })
}

/// The four candidates of the module docs for `objective`.
pub(crate) fn candidates(points: &PointSet, objective: AreaObjective) -> Result<Candidates> {
    candidates_with_cap(points, objective, MAX_FACE_CORNERS)
}

/// [`candidates`] with the face-size cap `max_face` instead of
/// [`MAX_FACE_CORNERS`].
fn candidates_with_cap(
    points: &PointSet,
    objective: AreaObjective,
    max_face: usize,
) -> Result<Candidates> {
    let pts = points.points();
    let g = DelaunayGraph::with_topology(pts)?;
    let with_bottleneck = |name: &'static str, triangles: Vec<[u32; 3]>| Candidate {
        name,
        bottleneck: objective.bottleneck(pts, &triangles),
        triangles,
    };
    let smallest_angle = smallest_angle(pts, &g.triangles);
    let [o, a, b] = smallest_angle.map(|v| pts[v as usize]);
    let thirty_degrees = angle_at_least_30_degrees(o, a, b);
    let faces = rng_hull_faces(pts, &g);
    let largest_face = faces.iter().map(Vec::len).max().unwrap_or(0);
    let mut list = vec![with_bottleneck(DELAUNAY, g.triangles.clone())];
    if !thirty_degrees {
        list.push(with_bottleneck(ALGORITHM_75, g.triangles.clone()));
    }
    if largest_face <= max_face {
        if thirty_degrees {
            let fat = triangulate_faces(pts, &faces, objective, true)?;
            list.push(with_bottleneck(ALGORITHM_75, fat));
        }
        let rng_hull = triangulate_faces(pts, &faces, objective, false)?;
        list.push(with_bottleneck(RNG_HULL_OPTIMUM, rng_hull));
    }
    let (algorithm_76, flips) = algorithm_76(pts, &g, smallest_angle);
    list.push(with_bottleneck(ALGORITHM_76, algorithm_76));
    Ok(Candidates {
        list,
        largest_face,
        smallest_angle,
        thirty_degrees,
        flips,
    })
}

/// Exact order of the areas of two triangles given by point indices.
#[inline]
fn area_order(pts: &[Point], s: [u32; 3], t: [u32; 3]) -> Ordering {
    if s == t {
        return Ordering::Equal;
    }
    compare_areas(s.map(|v| pts[v as usize]), t.map(|v| pts[v as usize]))
}

impl AreaObjective {
    /// Is bottleneck `s` strictly better than `t`?
    fn better(self, pts: &[Point], s: [u32; 3], t: [u32; 3]) -> bool {
        let order = area_order(pts, s, t);
        match self {
            AreaObjective::MaxMin => order == Ordering::Greater,
            AreaObjective::MinMax => order == Ordering::Less,
        }
    }

    /// The worse (the new bottleneck) of two triangles.
    fn worse(self, pts: &[Point], s: [u32; 3], t: [u32; 3]) -> [u32; 3] {
        if self.better(pts, s, t) {
            t
        } else {
            s
        }
    }

    /// The bottleneck triangle of a (non-empty) triangulation.
    pub(crate) fn bottleneck(self, pts: &[Point], triangles: &[[u32; 3]]) -> [u32; 3] {
        triangles
            .iter()
            .copied()
            .reduce(|s, t| self.worse(pts, s, t))
            .expect("a triangulation has a triangle")
    }
}

/// `DT`'s smallest angle as a corner `[apex, a, b]` (exact comparisons).
fn smallest_angle(pts: &[Point], triangles: &[[u32; 3]]) -> [u32; 3] {
    let corner = |c: [u32; 3]| c.map(|v| pts[v as usize]);
    let mut best: Option<[u32; 3]> = None;
    for t in triangles {
        for k in 0..3 {
            let c = [t[k], t[(k + 1) % 3], t[(k + 2) % 3]];
            if best.is_none_or(|b| compare_corner_angles(corner(c), corner(b)) == Ordering::Less) {
                best = Some(c);
            }
        }
    }
    best.expect("a Delaunay triangulation has a triangle")
}

/// The bounded faces of `RNG(S) ∪ hull(S)` as counter-clockwise corner
/// cycles (a vertex repeats at a crack or a pinch point). The graph is
/// connected (the RNG contains every minimum spanning tree) and plane (a
/// subgraph of `DT`), so each face has one boundary walk.
pub(crate) fn rng_hull_faces(pts: &[Point], g: &DelaunayGraph) -> Vec<Vec<u32>> {
    let mut edges = rng_from_delaunay(pts, g);
    let hull = convex_hull_cycle(pts);
    for i in 0..hull.len() {
        edges.push([hull[i], hull[(i + 1) % hull.len()]]);
    }
    for e in &mut edges {
        *e = [e[0].min(e[1]), e[0].max(e[1])];
    }
    edges.sort_unstable();
    edges.dedup();
    PlanarGraph::new(pts, &edges)
        .bounded_faces(pts)
        .into_iter()
        .map(|f| f.vertices)
        .collect()
}

/// Each face triangulated by the polygon program under `objective`, with
/// only triangles whose angles are all at least 30° if `thirty_degrees`.
fn triangulate_faces(
    pts: &[Point],
    faces: &[Vec<u32>],
    objective: AreaObjective,
    thirty_degrees: bool,
) -> Result<Vec<[u32; 3]>> {
    let p = |v: u32| pts[v as usize];
    let mut out = Vec::with_capacity(2 * pts.len());
    for face in faces {
        let region = PolygonCycle::exact(pts, face);
        let convex = region.is_strictly_convex();
        let v = face.as_slice();
        let allowed = |i: usize, m: usize, j: usize| {
            let (a, b, c) = (p(v[i]), p(v[m]), p(v[j]));
            orient_sign(a, b, c) > 0
                && (!thirty_degrees
                    || (angle_at_least_30_degrees(a, b, c)
                        && angle_at_least_30_degrees(b, c, a)
                        && angle_at_least_30_degrees(c, a, b)))
        };
        let solved = optimal_triangulation(
            face.len(),
            |i, j| convex || region.is_diagonal(i, j),
            allowed,
            &FaceBottleneck {
                pts,
                vertices: v,
                objective,
            },
        )
        .ok_or_else(|| {
            Error::Internal(format!(
                "a face of RNG ∪ hull with {} corners has no {}triangulation",
                face.len(),
                if thirty_degrees { "30°-" } else { "" }
            ))
        })?;
        out.extend(solved.triangles.into_iter().map(|t| t.map(|c| v[c])));
    }
    Ok(out)
}

/// The bottleneck area of a face triangulation as a point triple (`None`
/// while there is no triangle: the neutral value, +∞ for MaxMin and 0 for
/// MinMax).
struct FaceBottleneck<'a> {
    pts: &'a [Point],
    vertices: &'a [u32],
    objective: AreaObjective,
}

impl Objective for FaceBottleneck<'_> {
    type Value = Option<[u32; 3]>;
    fn empty(&self) -> Self::Value {
        None
    }
    fn diagonal(&self, _: usize, _: usize) -> Option<Self::Value> {
        None
    }
    fn triangle(&self, i: usize, m: usize, j: usize) -> Option<Self::Value> {
        Some(Some([self.vertices[i], self.vertices[m], self.vertices[j]]))
    }
    fn combine(&self, s: Self::Value, t: Self::Value) -> Self::Value {
        match (s, t) {
            (None, x) | (x, None) => x,
            (Some(s), Some(t)) => Some(self.objective.worse(self.pts, s, t)),
        }
    }
    fn better(&self, s: Self::Value, t: Self::Value) -> bool {
        match (s, t) {
            (_, None) => false,
            (None, Some(_)) => true,
            (Some(s), Some(t)) => self.objective.better(self.pts, s, t),
        }
    }
}

/// Algorithm 76 from `DT` with the angle floor `alpha` (a corner
/// `[apex, a, b]`; `DT`'s smallest angle): the triangles and the number of
/// flips (module docs for the rule, the order and termination).
fn algorithm_76(pts: &[Point], g: &DelaunayGraph, alpha: [u32; 3]) -> (Vec<[u32; 3]>, usize) {
    let p = |v: u32| pts[v as usize];
    let alpha = alpha.map(p);
    let mut tri = g.triangles.clone();
    let mut nb = g.topology.neighbours.clone();
    let mut queue: VecDeque<(u32, usize, [u32; 2])> = VecDeque::new();
    for (t, n) in nb.iter().enumerate() {
        for (j, &u) in n.iter().enumerate() {
            if u != NO_TRIANGLE && u as usize > t {
                queue.push_back((t as u32, j, [tri[t][j], tri[t][(j + 1) % 3]]));
            }
        }
    }
    let angles_ok = |[a, b, c]: [Point; 3]| {
        [[a, b, c], [b, c, a], [c, a, b]]
            .into_iter()
            .all(|corner| compare_corner_angles(corner, alpha) != Ordering::Less)
    };
    let mut flips = 0;
    while let Some((t, j, [x, y])) = queue.pop_front() {
        let t = t as usize;
        if tri[t][j] != x || tri[t][(j + 1) % 3] != y || nb[t][j] == NO_TRIANGLE {
            continue; // stale: the side changed since it was queued
        }
        let a = tri[t][(j + 2) % 3];
        let u = nb[t][j] as usize;
        let i = (0..3)
            .find(|&i| tri[u][i] == y)
            .expect("neighbours share the side");
        let b = tri[u][(i + 2) % 3];
        let (pa, pb, px, py) = (p(a), p(b), p(x), p(y));
        // A strictly convex quadrilateral x b y a; xy locally Delaunay.
        if orient_sign(pa, pb, px) >= 0
            || orient_sign(pa, pb, py) <= 0
            || incircle_sign(px, py, pa, pb) >= 0
        {
            continue;
        }
        let smaller = |s: [u32; 3], r: [u32; 3]| {
            if area_order(pts, s, r) == Ordering::Greater {
                r
            } else {
                s
            }
        };
        let (new1, new2) = ([a, x, b], [b, y, a]);
        let old = smaller([x, y, a], [y, x, b]);
        if area_order(pts, smaller(new1, new2), old) != Ordering::Greater
            || !angles_ok(new1.map(p))
            || !angles_ok(new2.map(p))
        {
            continue;
        }
        // t = (x, y, a), u = (y, x, b) become t = (a, x, b), u = (b, y, a).
        let n_ya = nb[t][(j + 1) % 3];
        let n_ax = nb[t][(j + 2) % 3];
        let n_xb = nb[u][(i + 1) % 3];
        let n_by = nb[u][(i + 2) % 3];
        tri[t] = new1;
        nb[t] = [n_ax, n_xb, u as u32];
        tri[u] = new2;
        nb[u] = [n_by, n_ya, t as u32];
        for (n, from, to) in [(n_xb, u, t), (n_ya, t, u)] {
            if n != NO_TRIANGLE {
                for s in nb[n as usize].iter_mut() {
                    if *s == from as u32 {
                        *s = to as u32;
                    }
                }
            }
        }
        flips += 1;
        for (w, k) in [(t, 0), (t, 1), (u, 0), (u, 1)] {
            if nb[w][k] != NO_TRIANGLE {
                queue.push_back((w as u32, k, [tri[w][k], tri[w][(k + 1) % 3]]));
            }
        }
    }
    (tri, flips)
}

/// The certified bound of the module docs, as a triangle `[a, b, r]` on a
/// hull edge `ab` (`hull`: the counter-clockwise hull cycle). `None` only
/// without a hull edge that has a point on its inner side (all points
/// collinear, which [`PointSet`] rejects).
pub(crate) fn certified_bound(
    pts: &[Point],
    hull: &[u32],
    objective: AreaObjective,
) -> Option<[u32; 3]> {
    let p = |v: u32| pts[v as usize];
    let h = hull.len();
    let mut bound: Option<[u32; 3]> = None;
    let mut inner: Vec<u32> = Vec::with_capacity(pts.len());
    for e in 0..h {
        let (a, b) = (hull[e], hull[(e + 1) % h]);
        let (pa, pb) = (p(a), p(b));
        inner.clear();
        inner.extend((0..pts.len() as u32).filter(|&r| orient_sign(pa, pb, p(r)) > 0));
        if inner.is_empty() {
            continue;
        }
        let edge_value = match objective {
            AreaObjective::MaxMin => {
                // By the angle at a (counter-clockwise from ab), ties by the
                // angle at b (clockwise from ba): both are orientations.
                inner.sort_unstable_by(|&q, &r| match orient_sign(pa, p(q), p(r)) {
                    1 => Ordering::Less,
                    -1 => Ordering::Greater,
                    _ => orient_sign(pb, p(q), p(r)).cmp(&0),
                });
                let mut lowest_at_b: Option<u32> = None;
                let mut largest: Option<[u32; 3]> = None;
                for &r in &inner {
                    // r is an empty apex iff its angle at b is strictly below
                    // that of every point before it.
                    if lowest_at_b.is_none_or(|m| orient_sign(pb, p(m), p(r)) > 0) {
                        lowest_at_b = Some(r);
                        let t = [a, b, r];
                        if largest.is_none_or(|l| area_order(pts, t, l) == Ordering::Greater) {
                            largest = Some(t);
                        }
                    }
                }
                largest
            }
            AreaObjective::MinMax => inner.iter().map(|&r| [a, b, r]).reduce(|s, t| {
                if area_order(pts, t, s) == Ordering::Less {
                    t
                } else {
                    s
                }
            }),
        };
        let Some(value) = edge_value else { continue };
        // MaxMin: the smallest of the per-edge maxima; MinMax: the largest of
        // the per-edge minima.
        let tighter = bound.is_none_or(|b| match objective {
            AreaObjective::MaxMin => area_order(pts, value, b) == Ordering::Less,
            AreaObjective::MinMax => area_order(pts, value, b) == Ordering::Greater,
        });
        if tighter {
            bound = Some(value);
        }
    }
    bound
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::structures::Triangulation;
    use optri_oracle as oracle;
    use oracle::{to_rational, BigRational};
    use rand::rngs::StdRng;
    use rand::{Rng, SeedableRng};

    const OBJECTIVES: [AreaObjective; 2] = [AreaObjective::MaxMin, AreaObjective::MinMax];

    /// The point-set families of the tests, by name.
    const FAMILIES: [&str; 5] = ["uniform", "real", "clustered", "grid", "collinear runs"];

    /// `n` points of `family` (duplicates possible: `PointSet` merges them).
    fn sample(rng: &mut StdRng, family: &str, n: usize) -> Vec<Point> {
        let int = |rng: &mut StdRng, lo: i32, hi: i32| rng.gen_range(lo..hi) as f64;
        match family {
            "uniform" => (0..n)
                .map(|_| [int(rng, 0, 100), int(rng, 0, 100)])
                .collect(),
            "real" => (0..n)
                .map(|_| [rng.gen_range(0.0..1.0), rng.gen_range(0.0..1.0)])
                .collect(),
            "clustered" => {
                let centres: Vec<Point> = (0..3)
                    .map(|_| [int(rng, 0, 1000), int(rng, 0, 1000)])
                    .collect();
                (0..n)
                    .map(|i| {
                        let c = centres[i % 3];
                        [c[0] + int(rng, -20, 21), c[1] + int(rng, -20, 21)]
                    })
                    .collect()
            }
            "grid" => {
                let side = ((n as f64).sqrt().ceil() as i32 + 1).max(3);
                (0..n)
                    .map(|_| [int(rng, 0, side), int(rng, 0, side)])
                    .collect()
            }
            "collinear runs" => {
                // Points on three lines with integer steps, plus a few others.
                let lines: Vec<(Point, Point)> = (0..3)
                    .map(|_| {
                        (
                            [int(rng, 0, 50), int(rng, 0, 50)],
                            [int(rng, -3, 4), int(rng, -3, 4)],
                        )
                    })
                    .collect();
                (0..n)
                    .map(|i| {
                        if i % 5 == 4 {
                            return [int(rng, 0, 60), int(rng, 0, 60)];
                        }
                        let (a, d) = lines[i % 3];
                        let t = int(rng, 0, 12);
                        [a[0] + t * d[0], a[1] + t * d[1]]
                    })
                    .collect()
            }
            _ => unreachable!(),
        }
    }

    /// The exact doubled bottleneck area of `triangles` (oracle).
    fn value(pts: &[Point], triangles: &[[u32; 3]], objective: AreaObjective) -> BigRational {
        match objective {
            AreaObjective::MaxMin => oracle::min_twice_area(pts, triangles),
            AreaObjective::MinMax => oracle::max_twice_area(pts, triangles),
        }
    }

    fn twice_area(pts: &[Point], t: [u32; 3]) -> BigRational {
        let p = |v: u32| pts[v as usize];
        oracle::twice_area(p(t[0]), p(t[1]), p(t[2]))
    }

    /// Is `s` at least as good as `t` (exact, oracle)?
    fn at_least_as_good(objective: AreaObjective, s: &BigRational, t: &BigRational) -> bool {
        match objective {
            AreaObjective::MaxMin => s >= t,
            AreaObjective::MinMax => s <= t,
        }
    }

    /// The angle at `o` is at least 30°, by the definition in rationals:
    /// `u·v ≤ 0` or `4(u·v)² ≤ 3|u|²|v|²` (independent of the kernel).
    fn at_least_30_rational(o: Point, a: Point, b: Point) -> bool {
        let d = |p: Point, k: usize| to_rational(p[k]) - to_rational(o[k]);
        let (ux, uy, vx, vy) = (d(a, 0), d(a, 1), d(b, 0), d(b, 1));
        let dot = ux.clone() * vx.clone() + uy.clone() * vy.clone();
        let uu = ux.clone() * ux + uy.clone() * uy;
        let vv = vx.clone() * vx + vy.clone() * vy;
        let int = |k: i64| BigRational::from_integer(k.into());
        dot <= int(0) || int(4) * dot.clone() * dot <= int(3) * uu * vv
    }

    fn is_thirty_degree(pts: &[Point], triangles: &[[u32; 3]]) -> bool {
        triangles.iter().all(|t| {
            let [a, b, c] = t.map(|v| pts[v as usize]);
            at_least_30_rational(a, b, c)
                && at_least_30_rational(b, c, a)
                && at_least_30_rational(c, a, b)
        })
    }

    fn edges_of(triangles: &[[u32; 3]]) -> std::collections::HashSet<[u32; 2]> {
        oracle::triangle_edges(triangles).into_iter().collect()
    }

    /// Every candidate validates and is never worse than Delaunay; the
    /// `RNG ∪ hull` optimum is never worse than Algorithm 75; Algorithm 75 is
    /// a 30°-triangulation when it runs; Algorithm 76 stays within `C(n, 2)`
    /// flips and keeps every angle at least `DT`'s smallest; the returned
    /// result is the best candidate.
    #[test]
    fn candidates_are_valid_and_never_worse_than_delaunay() {
        const SEED: u64 = 0xA4EA_0001;
        let mut rng = StdRng::seed_from_u64(SEED);
        let sizes = [3, 4, 5, 7, 10, 16, 30, 60, 120];
        let (mut cases, mut flipped, mut thirty) = (0, 0, 0);
        for family in FAMILIES {
            for &n in &sizes {
                for _ in 0..6 {
                    let input = sample(&mut rng, family, n);
                    let Ok(ps) = PointSet::new(&input) else {
                        continue;
                    };
                    let pts = ps.points();
                    for objective in OBJECTIVES {
                        let c = candidates(&ps, objective).unwrap();
                        assert_eq!(c.list.len(), 4);
                        for (cand, name) in c.list.iter().zip(CANDIDATE_NAMES) {
                            assert_eq!(cand.name, name);
                            Triangulation::from_distinct(&ps, cand.triangles.clone())
                                .validate()
                                .unwrap_or_else(|e| panic!("{family} n={n} {name}: {e}"));
                            assert_eq!(
                                value(pts, &cand.triangles, objective),
                                twice_area(pts, cand.bottleneck)
                            );
                        }
                        let v: Vec<BigRational> = c
                            .list
                            .iter()
                            .map(|cand| value(pts, &cand.triangles, objective))
                            .collect();
                        for (k, vk) in v.iter().enumerate() {
                            assert!(
                                at_least_as_good(objective, vk, &v[0]),
                                "{family} n={n} {objective:?}: {} worse than Delaunay",
                                CANDIDATE_NAMES[k]
                            );
                        }
                        assert!(at_least_as_good(objective, &v[2], &v[1]));
                        if c.thirty_degrees {
                            assert!(is_thirty_degree(pts, &c.list[1].triangles));
                            thirty += 1;
                        } else {
                            assert_eq!(c.list[1].triangles, c.list[0].triangles);
                        }
                        let n_distinct = pts.len();
                        assert!(c.flips <= n_distinct * (n_distinct - 1) / 2);
                        flipped += (c.flips > 0) as usize;
                        let alpha = c.smallest_angle.map(|v| pts[v as usize]);
                        for t in &c.list[3].triangles {
                            for k in 0..3 {
                                let corner =
                                    [t[k], t[(k + 1) % 3], t[(k + 2) % 3]].map(|v| pts[v as usize]);
                                assert_ne!(
                                    compare_corner_angles(corner, alpha),
                                    Ordering::Less,
                                    "Algorithm 76 went below the Delaunay angle"
                                );
                            }
                        }
                        let result = area_general(&ps, objective).unwrap();
                        let best = v.iter().skip(1).fold(&v[0], |b, x| {
                            if at_least_as_good(objective, b, x) {
                                b
                            } else {
                                x
                            }
                        });
                        assert_eq!(&value(pts, &result.triangles, objective), best);
                        cases += 1;
                    }
                }
            }
        }
        assert!(cases >= 500, "{cases} cases");
        assert!(flipped > 50, "Algorithm 76 flipped in only {flipped} cases");
        eprintln!("{cases} cases, Algorithm 76 flipped in {flipped}, step 3 of Algorithm 75 ran in {thirty}");
    }

    /// With the face programs capped away, the candidates are Delaunay,
    /// Algorithm 75 (= Delaunay when its step 3 does not run) and
    /// Algorithm 76, and the result is still valid and no worse than
    /// Delaunay.
    #[test]
    fn face_cap_skips_the_face_programs() {
        const SEED: u64 = 0xA4EA_0005;
        let mut rng = StdRng::seed_from_u64(SEED);
        let mut capped = 0;
        for _ in 0..40 {
            let ps = PointSet::new(&sample(&mut rng, "real", 30)).unwrap();
            let pts = ps.points();
            for objective in OBJECTIVES {
                let c = candidates_with_cap(&ps, objective, 5).unwrap();
                if c.largest_face <= 5 {
                    assert_eq!(c.list.len(), 4);
                    continue;
                }
                let names: Vec<&str> = c.list.iter().map(|k| k.name).collect();
                if c.thirty_degrees {
                    assert_eq!(names, [DELAUNAY, ALGORITHM_76]);
                } else {
                    assert_eq!(names, [DELAUNAY, ALGORITHM_75, ALGORITHM_76]);
                }
                let dt = value(pts, &c.list[0].triangles, objective);
                for k in &c.list {
                    Triangulation::from_distinct(&ps, k.triangles.clone())
                        .validate()
                        .unwrap();
                    assert!(at_least_as_good(
                        objective,
                        &value(pts, &k.triangles, objective),
                        &dt
                    ));
                }
                capped += 1;
            }
        }
        assert!(capped >= 60, "{capped}");
    }

    /// The bound never contradicts the exhaustive optimum, the result never
    /// beats it, and `exact` results attain it (n ≤ 9).
    #[test]
    fn bound_is_a_true_bound_and_exact_results_are_optimal() {
        const SEED: u64 = 0xA4EA_0002;
        let mut rng = StdRng::seed_from_u64(SEED);
        let (mut cases, mut exact, mut fixtures) = (0, 0, 0);
        let mut inputs: Vec<Vec<Point>> = FIXTURES.iter().map(|f| f.to_vec()).collect();
        for i in 0..400 {
            let family = FAMILIES[i % FAMILIES.len()];
            let n = rng.gen_range(3..=9);
            inputs.push(sample(&mut rng, family, n));
        }
        for input in &inputs {
            let Ok(ps) = PointSet::new(input) else {
                continue;
            };
            let pts = ps.points();
            if pts.len() > 9 {
                continue;
            }
            let all = oracle::all_triangulations(pts);
            for objective in OBJECTIVES {
                let optimum = all
                    .iter()
                    .map(|t| value(pts, t, objective))
                    .reduce(|a, b| {
                        if at_least_as_good(objective, &a, &b) {
                            a
                        } else {
                            b
                        }
                    })
                    .unwrap();
                let r = area_general(&ps, objective).unwrap();
                let got = value(pts, &r.triangles, objective);
                assert!(at_least_as_good(objective, &optimum, &got));
                let bound = twice_area(pts, r.bound.expect("a hull edge"));
                assert_eq!(
                    bound,
                    brute_force_bound(pts, objective),
                    "{objective:?} {pts:?}"
                );
                assert!(
                    at_least_as_good(objective, &bound, &optimum),
                    "{objective:?} bound {bound} beats the optimum {optimum} on {pts:?}"
                );
                if r.exact {
                    assert_eq!(got, optimum, "exact but not optimal on {pts:?}");
                    assert_eq!(got, bound);
                    exact += 1;
                }
                cases += 1;
            }
            fixtures += (inputs.iter().position(|x| x == input).unwrap() < FIXTURES.len()) as usize;
        }
        assert_eq!(fixtures, FIXTURES.len());
        assert!(cases >= 600, "{cases} cases");
        assert!(exact >= 50, "only {exact} of {cases} certified");
        eprintln!("{cases} cases, {exact} certified exact");
    }

    /// The bound of the module docs by its definition (oracle predicates):
    /// over hull edges `ab` (counter-clockwise), the largest empty triangle
    /// `abr` (MaxMin), of which the smallest; or the smallest triangle `abr`
    /// (MinMax), of which the largest. O(h n²).
    fn brute_force_bound(pts: &[Point], objective: AreaObjective) -> BigRational {
        let n = pts.len() as u32;
        let p = |v: u32| pts[v as usize];
        let hull = oracle::convex_hull_edges(pts);
        let per_edge = hull.iter().map(|&[a, b]| {
            // The oracle's hull edges are sorted pairs: orient them
            // counter-clockwise (every point on the left or on the line).
            let (a, b) = if (0..n).any(|r| oracle::orient(p(a), p(b), p(r)) < 0) {
                (b, a)
            } else {
                (a, b)
            };
            let inner = (0..n).filter(|&r| oracle::orient(p(a), p(b), p(r)) > 0);
            let areas = inner
                .filter(|&r| {
                    objective == AreaObjective::MinMax
                        || (0..n).all(|q| {
                            q == a
                                || q == b
                                || q == r
                                || oracle::orient(p(a), p(b), p(q)) < 0
                                || oracle::orient(p(b), p(r), p(q)) < 0
                                || oracle::orient(p(r), p(a), p(q)) < 0
                        })
                })
                .map(|r| twice_area(pts, [a, b, r]));
            match objective {
                AreaObjective::MaxMin => areas.max().unwrap(),
                AreaObjective::MinMax => areas.min().unwrap(),
            }
        });
        match objective {
            AreaObjective::MaxMin => per_edge.min().unwrap(),
            AreaObjective::MinMax => per_edge.max().unwrap(),
        }
    }

    /// Small fixtures (distinct points): the square with its centre (one
    /// triangulation), the brief's convex hexagons (§7; MaxMin / MinMax
    /// doubled areas 4 / 8, 9 / 18, 94 / 309) and a lattice with an interior
    /// point.
    const FIXTURES: [&[Point]; 5] = [
        &[[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0], [1.0, 1.0]],
        &[
            [0.0, 0.0],
            [-1.0, 2.0],
            [0.0, 4.0],
            [2.0, 4.0],
            [3.0, 2.0],
            [2.0, 0.0],
        ],
        &[
            [0.0, 0.0],
            [0.0, 3.0],
            [2.0, 5.0],
            [5.0, 5.0],
            [7.0, 2.0],
            [6.0, 0.0],
        ],
        &[
            [-6.0, 10.0],
            [12.0, 11.0],
            [10.0, 3.0],
            [-5.0, -10.0],
            [-9.0, -8.0],
            [-12.0, 8.0],
        ],
        &[
            [0.0, 0.0],
            [3.0, 0.0],
            [0.0, 3.0],
            [3.0, 3.0],
            [1.0, 2.0],
            [2.0, 1.0],
        ],
    ];

    #[test]
    fn fixtures_have_the_briefs_optima() {
        let want = [(2, 2), (4, 8), (9, 18), (94, 309)];
        for (f, (maxmin, minmax)) in FIXTURES.iter().zip(want) {
            let ps = PointSet::new(f).unwrap();
            let pts = ps.points();
            let all = oracle::all_triangulations(pts);
            let best = |o: AreaObjective| {
                all.iter()
                    .map(|t| value(pts, t, o))
                    .reduce(|a, b| if at_least_as_good(o, &a, &b) { a } else { b })
                    .unwrap()
            };
            let int = |k: i64| BigRational::from_integer(k.into());
            assert_eq!(best(AreaObjective::MaxMin), int(maxmin), "{f:?}");
            assert_eq!(best(AreaObjective::MinMax), int(minmax), "{f:?}");
        }
        // The square with its centre has one triangulation, and the bound
        // proves it optimal for both objectives.
        let ps = PointSet::new(FIXTURES[0]).unwrap();
        for objective in OBJECTIVES {
            let r = area_general(&ps, objective).unwrap();
            assert!(r.exact, "{objective:?}");
            assert_eq!(
                twice_area(ps.points(), r.bound.unwrap()),
                BigRational::from_integer(2.into())
            );
        }
    }

    /// Candidate 3 is the optimum over all triangulations containing
    /// `RNG ∪ hull` (exhaustive, n ≤ 9, RNG by the oracle's definition).
    #[test]
    fn rng_hull_candidate_is_optimal_among_triangulations_containing_rng_and_hull() {
        const SEED: u64 = 0xA4EA_0003;
        let mut rng = StdRng::seed_from_u64(SEED);
        let mut cases = 0;
        for i in 0..240 {
            let n = rng.gen_range(4..=9);
            let input = sample(&mut rng, FAMILIES[i % FAMILIES.len()], n);
            let Ok(ps) = PointSet::new(&input) else {
                continue;
            };
            let pts = ps.points();
            let mut fixed = oracle::rng_edges(pts);
            fixed.extend(
                oracle::convex_hull_edges(pts)
                    .into_iter()
                    .map(|[a, b]| [a.min(b), a.max(b)]),
            );
            let containing: Vec<Vec<[u32; 3]>> = oracle::all_triangulations(pts)
                .into_iter()
                .filter(|t| {
                    let e = edges_of(t);
                    fixed.iter().all(|f| e.contains(f))
                })
                .collect();
            assert!(!containing.is_empty(), "DT contains RNG ∪ hull");
            for objective in OBJECTIVES {
                let best = containing
                    .iter()
                    .map(|t| value(pts, t, objective))
                    .reduce(|a, b| {
                        if at_least_as_good(objective, &a, &b) {
                            a
                        } else {
                            b
                        }
                    })
                    .unwrap();
                let c = candidates(&ps, objective).unwrap();
                assert_eq!(value(pts, &c.list[2].triangles, objective), best, "{pts:?}");
                let e = edges_of(&c.list[2].triangles);
                assert!(fixed.iter().all(|f| e.contains(f)));
                cases += 1;
            }
        }
        assert!(cases >= 400, "{cases} cases");
    }

    /// Near-equilateral sets: a patch of the triangular lattice with spacing
    /// 100, each point moved by up to ±`jitter` (integers, so exact).
    fn lattice_patch(rng: &mut StdRng, n: usize, jitter: i32) -> Vec<Point> {
        let mut sites: Vec<Point> = Vec::new();
        for j in 0..4 {
            for i in 0..4 {
                let x = 100.0 * i as f64 + 50.0 * j as f64;
                let y = (100.0 * 3f64.sqrt() / 2.0 * j as f64).round();
                sites.push([x, y]);
            }
        }
        // n sites near a random centre site, so the patch is compact.
        let centre = sites[rng.gen_range(0..sites.len())];
        sites.sort_by(|a, b| {
            let d = |p: &Point| (p[0] - centre[0]).powi(2) + (p[1] - centre[1]).powi(2);
            d(a).total_cmp(&d(b))
        });
        sites
            .into_iter()
            .take(n)
            .map(|p| {
                [
                    p[0] + rng.gen_range(-jitter..=jitter) as f64,
                    p[1] + rng.gen_range(-jitter..=jitter) as f64,
                ]
            })
            .collect()
    }

    /// Theorem 74 by enumeration: every RNG edge (oracle definition) is in
    /// every triangulation whose angles are all at least 30° (rational test);
    /// and Algorithm 75, when it runs its step 3, attains the best area over
    /// the enumerated 30°-triangulations.
    #[test]
    fn theorem_74_and_algorithm_75_by_enumeration() {
        const SEED: u64 = 0xA4EA_0074;
        let mut rng = StdRng::seed_from_u64(SEED);
        let (mut sets, mut thirty_triangulations, mut step_3) = (0, 0, 0);
        for i in 0..600 {
            let n = 6 + i % 3;
            let jitter = [1, 4, 8][(i / 3) % 3];
            let ps = PointSet::new(&lattice_patch(&mut rng, n, jitter)).unwrap();
            let pts = ps.points();
            let rng_edges = oracle::rng_edges(pts);
            let fat: Vec<Vec<[u32; 3]>> = oracle::all_triangulations(pts)
                .into_iter()
                .filter(|t| is_thirty_degree(pts, t))
                .collect();
            for t in &fat {
                let e = edges_of(t);
                for f in &rng_edges {
                    assert!(
                        e.contains(f),
                        "RNG edge {f:?} missing from a 30°-triangulation of {pts:?}"
                    );
                }
            }
            thirty_triangulations += fat.len();
            for objective in OBJECTIVES {
                let c = candidates(&ps, objective).unwrap();
                assert_eq!(
                    c.thirty_degrees,
                    !fat.is_empty(),
                    "DT maximises the smallest angle"
                );
                if !c.thirty_degrees {
                    continue;
                }
                let best = fat
                    .iter()
                    .map(|t| value(pts, t, objective))
                    .reduce(|a, b| {
                        if at_least_as_good(objective, &a, &b) {
                            a
                        } else {
                            b
                        }
                    })
                    .unwrap();
                assert_eq!(value(pts, &c.list[1].triangles, objective), best);
                step_3 += 1;
            }
            sets += 1;
        }
        assert_eq!(sets, 600);
        assert!(
            thirty_triangulations >= 150 && step_3 >= 200,
            "{thirty_triangulations} {step_3}"
        );
        eprintln!("{sets} sets, {thirty_triangulations} 30°-triangulations, Algorithm 75 step 3 in {step_3} runs");
    }

    /// Prints the approximation ratios optimum/result (MaxMin) and
    /// result/optimum (MinMax), mean and worst, per candidate and for the
    /// returned result, against the exhaustive optimum (n ≤ 9), with the
    /// improvement over Delaunay and how often each candidate wins. Run with
    /// `cargo test -p optri --lib area_general_ratios -- --ignored --nocapture`.
    #[test]
    #[ignore]
    fn area_general_ratios() {
        const SEED: u64 = 0xA4EA_0076;
        const SETS_PER_SIZE: usize = 300;
        let mut rng = StdRng::seed_from_u64(SEED);
        let f = |r: &BigRational| oracle::rational_to_f64(r);
        for family in ["real", "uniform"] {
            for objective in OBJECTIVES {
                // Per candidate (+ the result): sum and worst of the ratio to
                // the optimum, sum and best of the improvement over DT.
                let mut ratio = [(0.0f64, 1.0f64); 5];
                let mut over_dt = [(0.0f64, 1.0f64); 5];
                let (mut strict_wins, mut attains_best, mut optimal) = ([0; 4], [0; 4], [0; 5]);
                let (mut cases, mut exact, mut result_optimal) = (0, 0, 0);
                for n in 5..=9 {
                    for _ in 0..SETS_PER_SIZE {
                        let Ok(ps) = PointSet::new(&sample(&mut rng, family, n)) else {
                            continue;
                        };
                        let pts = ps.points();
                        let optimum = oracle::all_triangulations(pts)
                            .iter()
                            .map(|t| value(pts, t, objective))
                            .reduce(|a, b| {
                                if at_least_as_good(objective, &a, &b) {
                                    a
                                } else {
                                    b
                                }
                            })
                            .unwrap();
                        let c = candidates(&ps, objective).unwrap();
                        let r = area_general(&ps, objective).unwrap();
                        let mut values: Vec<BigRational> = c
                            .list
                            .iter()
                            .map(|k| value(pts, &k.triangles, objective))
                            .collect();
                        values.push(value(pts, &r.triangles, objective));
                        let best = &values[4];
                        for k in 0..4 {
                            if &values[k] == best {
                                attains_best[k] += 1;
                                if (0..4).all(|o| o == k || &values[o] != best) {
                                    strict_wins[k] += 1;
                                }
                            }
                        }
                        for (k, v) in values.iter().enumerate() {
                            let (q, d) = match objective {
                                AreaObjective::MaxMin => {
                                    (f(&(optimum.clone() / v)), f(&(v / &values[0])))
                                }
                                AreaObjective::MinMax => {
                                    (f(&(v / &optimum)), f(&(values[0].clone() / v)))
                                }
                            };
                            ratio[k] = (ratio[k].0 + q, ratio[k].1.max(q));
                            over_dt[k] = (over_dt[k].0 + d, over_dt[k].1.max(d));
                            optimal[k] += (v == &optimum) as usize;
                        }
                        exact += r.exact as usize;
                        result_optimal += (values[4] == optimum) as usize;
                        cases += 1;
                    }
                }
                assert!(cases >= 4 * SETS_PER_SIZE, "{cases}");
                let what = match objective {
                    AreaObjective::MaxMin => "MaxMin area: optimum / candidate",
                    AreaObjective::MinMax => "MinMax area: candidate / optimum",
                };
                println!("\n{what} — {family} points, n = 5..9, {cases} sets (seed {SEED:#x})");
                println!(
                    "{:<56} {:>8} {:>8} {:>8} {:>9} {:>9} {:>7} {:>7}",
                    "candidate",
                    "mean",
                    "worst",
                    "optimal",
                    "vs DT avg",
                    "vs DT max",
                    "attains",
                    "strict"
                );
                let names = [
                    DELAUNAY,
                    "Algorithm 75",
                    "RNG ∪ hull optimum",
                    "Algorithm 76",
                    "returned result (best of the four)",
                ];
                for k in 0..5 {
                    let (wins, strict) = if k < 4 {
                        (attains_best[k].to_string(), strict_wins[k].to_string())
                    } else {
                        (String::new(), String::new())
                    };
                    println!(
                        "{:<56} {:>8.4} {:>8.4} {:>8} {:>9.4} {:>9.4} {:>7} {:>7}",
                        names[k],
                        ratio[k].0 / cases as f64,
                        ratio[k].1,
                        optimal[k],
                        over_dt[k].0 / cases as f64,
                        over_dt[k].1,
                        wins,
                        strict
                    );
                }
                println!(
                    "certified exact: {exact} of {cases}; actually optimal: {result_optimal} of {cases}"
                );
            }
        }
    }

    /// Prints the running time of each step at n = 1000 and 10⁴ uniform
    /// points. Run with `cargo test --release -p optri --lib
    /// area_general_timings -- --ignored --nocapture`.
    #[test]
    #[ignore]
    fn area_general_timings() {
        use std::time::Instant;
        const SEED: u64 = 0xA4EA_1000;
        let mut rng = StdRng::seed_from_u64(SEED);
        for n in [1000, 10_000] {
            let input: Vec<Point> = (0..n)
                .map(|_| [rng.gen_range(0.0..1.0), rng.gen_range(0.0..1.0)])
                .collect();
            let ps = PointSet::new(&input).unwrap();
            let pts = ps.points();
            let clock = Instant::now();
            let g = DelaunayGraph::with_topology(pts).unwrap();
            let t_dt = clock.elapsed();
            let clock = Instant::now();
            let faces = rng_hull_faces(pts, &g);
            let t_faces = clock.elapsed();
            let largest = faces.iter().map(Vec::len).max().unwrap();
            let cubes: usize = faces.iter().map(|f| f.len().pow(3)).sum();
            let clock = Instant::now();
            let _ = triangulate_faces(pts, &faces, AreaObjective::MaxMin, false).unwrap();
            let t_maxmin = clock.elapsed();
            let clock = Instant::now();
            let _ = triangulate_faces(pts, &faces, AreaObjective::MinMax, false).unwrap();
            let t_minmax = clock.elapsed();
            let clock = Instant::now();
            let (_, flips) = algorithm_76(pts, &g, smallest_angle(pts, &g.triangles));
            let t_76 = clock.elapsed();
            let hull = convex_hull_cycle(pts);
            let clock = Instant::now();
            let _ = certified_bound(pts, &hull, AreaObjective::MaxMin);
            let t_bound_max = clock.elapsed();
            let clock = Instant::now();
            let _ = certified_bound(pts, &hull, AreaObjective::MinMax);
            let t_bound_min = clock.elapsed();
            let mut totals = Vec::new();
            for objective in OBJECTIVES {
                let clock = Instant::now();
                let r = area_general(&ps, objective).unwrap();
                totals.push((objective, clock.elapsed(), r.algorithm, r.exact));
            }
            println!(
                "n = {n}: Delaunay {t_dt:.2?}; RNG ∪ hull faces {t_faces:.2?} ({} faces, largest {largest} corners, Σk³ = {cubes}); \
                 face programs MaxMin {t_maxmin:.2?}, MinMax {t_minmax:.2?}; Algorithm 76 {t_76:.2?} ({flips} flips); \
                 bound MaxMin {t_bound_max:.2?}, MinMax {t_bound_min:.2?} (h = {})",
                faces.len(),
                hull.len()
            );
            for (objective, t, name, exact) in totals {
                println!("  area_general {objective:?}: {t:.2?}, winner: {name}, exact: {exact}");
            }
        }
        // Convex position: one face with every point, just under and over
        // the cap.
        for n in [500, 501] {
            let input: Vec<Point> = (0..n)
                .map(|i| {
                    let t = std::f64::consts::TAU * i as f64 / n as f64;
                    [1e6 * t.cos(), 1e6 * t.sin()]
                })
                .collect();
            let ps = PointSet::new(&input).unwrap();
            let clock = Instant::now();
            let c = candidates(&ps, AreaObjective::MaxMin).unwrap();
            println!(
                "{n} points on a circle: candidates {:.2?} (largest face {} corners, {} candidates, {} flips)",
                clock.elapsed(),
                c.largest_face,
                c.list.len(),
                c.flips
            );
        }
    }
}
