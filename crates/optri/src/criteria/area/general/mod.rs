//! MaxMin-area and MinMax-area triangulations of general point sets (not in
//! convex position): the approximations of T. S. Vassilev, *Optimal area
//! triangulation*, PhD thesis, University of Saskatchewan, 2005, Chapter 3
//! (§3.4, Algorithms 75 and 76; Theorem 74), with Algorithm 76's flips made
//! angle-safe and area-equalising by exact comparisons, an optimum over the
//! triangulations containing `RNG ∪ hull`, and a certified bound on the
//! optimum that proves some results optimal.
//!
//! No polynomial algorithm is known for either criterion on general point
//! sets (Table 4.1 of the thesis). We compute four candidates and return the
//! best under the objective, with every area comparison exact
//! ([`compare_areas`]; a bottleneck value is stored as the corner triple of
//! its triangle, never as a rounded area):
//!
//! 1. **Delaunay**: the Delaunay triangulation `DT` (spade).
//! 2. **Algorithm 75** (thesis L4372–4445): if `DT`'s smallest
//!    angle `α*` is at least 30° (exact: [`angle_at_least_30_degrees`]), the
//!    optimal area *30°-triangulation*: by Theorem 74 (L4336) the relative
//!    neighbourhood graph lies in every triangulation whose angles are all at
//!    least 30°, so each bounded face of `RNG(S) ∪ hull(S)` is triangulated
//!    separately by Klincsek's program ([`optimal_triangulation`]) allowing
//!    only triangles with all three angles ≥ 30°. Feasible because `DT` is
//!    such a triangulation and contains `RNG ∪ hull`. If `α* < 30°` no
//!    30°-triangulation exists (`DT` maximises the smallest angle, Property
//!    13) and the algorithm returns `DT`.
//! 3. **The `RNG ∪ hull` optimum**: the same face
//!    programs without the angle filter, i.e. the optimum over all
//!    triangulations containing `RNG ∪ hull`. Both `DT` and Algorithm 75's
//!    result are in that set, so this candidate is never worse than either
//!    and keeps Algorithm 75's guarantee.
//! 4. **Algorithm 76** (L4466–4520): from `DT`, flip an interior
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
//! *corners* and [`PolygonCycle::is_diagonal`] decides chords between
//! corners. The cost is `O(n log n)` for `DT`, the RNG and the faces,
//! `O(Σ k³)` time and `O(max k²)` memory for faces of `k` corners (cubic in
//! the worst case, e.g. points in convex position, where the RNG is nearly
//! the hull cycle and there is one face; faces above [`MAX_FACE_CORNERS`]
//! skip candidates 2 and 3), `O(n²)` flips worst case for Algorithm 76
//! (`O(n)` observed), and `O(h · n log n)` for the bound (worst case; edges
//! settled by `DT`'s empty triangles are not searched, see
//! [`certified_bound`]). Measured (release,
//! uniform points in the unit square, both objectives): about 10 ms at
//! n = 1000 and 0.1 s at n = 10⁴ (largest face 184 corners).
//!
//! # The angle floor α and the choice of approximation
//! With a floor `α` (the `alpha` option, [`AngleFloor`]: the user's
//! decimal, every corner compared with it exactly) every candidate is an
//! *α-triangulation*, all angles at least `α`: Algorithm 76 flips only
//! when both new triangles meet `α` (the thesis's parameter; without it
//! `α*`), the face programs admit only triangles that meet `α`, and
//! Algorithm 75 uses the stricter of `α` and 30°. `α ≤ α*` is required:
//! `DT` maximises the smallest angle (Property 13), so above `α*` no
//! α-triangulation exists and the run is refused naming `α*`; at or below
//! it `DT` is one and contains `RNG ∪ hull`, so every face program has a
//! solution. For `α ≥ 30°` every α-triangulation is a 30°-triangulation
//! and contains `RNG ∪ hull` (Theorem 74), so the face programs find the
//! optimum over *all* α-triangulations; the result says so in its
//! guarantee. The `approximation` option ([`AreaApproximation`]) computes
//! one candidate (`thesis-75`, `thesis-76`, `rng-hull`; Delaunay stands in
//! when a face exceeds the cap) or all of them (`best`, the default).
//! Candidates skipped because of the cap are reported.
//!
//! # Guarantees
//! The thesis bounds the approximation only relative to `β`, the smallest
//! angle of the *unknown* optimum (Theorem 81, `guarantee.rs`): nothing is
//! guaranteed a priori, so the result is an approximation unless the bound
//! below certifies it, or the face programs under a floor of at least 30°
//! make it optimal among the α-triangulations (Algorithm 75's step 3 is the
//! case α = 30°). Each result reports which, and Theorem 81's factors for
//! its own smallest angle.
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
//! triangulation. Cocircular points: the Delaunay graph's canonical
//! completion (cocircular faces fanned from their smallest index) is the
//! starting point; its smallest angle is the same for every completion. An
//! angle of exactly 30° cannot occur with rational coordinates (`tan 30° =
//! 1/√3`), so Theorem 74's equality case never arises; the
//! theorem assumes general position, and on other inputs Algorithm 75 still
//! returns a valid 30°-triangulation (its optimality among those is what
//! the tests check by enumeration). Equal areas: the first candidate in the
//! order above wins a tie; within a face program, the first split corner
//! (the program's rule); Algorithm 76's order is the FIFO above. Everything
//! works on the distinct-point numbering of [`PointSet`].

mod guarantee;

use super::polygon::BottleneckArea;
use super::AreaBottleneck;
use crate::criteria::{ApproximationReport, AreaApproximation, Guarantee};
use crate::error::{Error, Result};
use crate::graphs::rng_from_delaunay;
use crate::interrupt::Stop;
use crate::kernel::metrics::angle_deg;
use crate::kernel::{
    angle_at_least_30_degrees, compare_areas, compare_corner_angles, incircle_sign, orient_sign,
    AngleFloor, Point,
};
use crate::polygon_program::optimal_triangulation;
use crate::spatial::{convex_hull_cycle, empty_apexes};
use crate::structures::{DelaunayGraph, PlanarGraph, PointSet, PolygonCycle, NO_TRIANGLE};
use std::cmp::Ordering;
use std::collections::{HashMap, HashSet, VecDeque};

/// The best triangulation found, which candidate it is, and the bound.
#[derive(Clone, Debug)]
pub(crate) struct GeneralAreaResult {
    /// Triangles as distinct-point indices.
    pub triangles: Vec<[u32; 3]>,
    /// The winning candidate's name ([`DELAUNAY`], [`ALGORITHM_75`],
    /// [`RNG_HULL_OPTIMUM`] or [`ALGORITHM_76`]).
    pub algorithm: String,
    /// Proven optimal: the result attains [`Self::bound`].
    pub exact: bool,
    /// A triangle whose (doubled) area bounds the optimum (module docs): for
    /// MaxMin an upper bound on the optimal smallest area, for MinMax a lower
    /// bound on the optimal largest area. `None` never happens today (every
    /// accepted point set has a hull edge); kept for inputs without one.
    pub bound: Option<[u32; 3]>,
    /// How the result was obtained and its guarantee (distinct indices).
    pub report: ApproximationReport,
}

/// What the caller asks of the approximation: the candidates and the angle
/// floor.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Settings<'a> {
    /// Every angle of every candidate at least this (module docs).
    pub alpha: Option<&'a AngleFloor>,
    pub approximation: AreaApproximation,
}

/// Which triangles a face program may use, and which flips Algorithm 76
/// may make: every angle at least a floor, decided exactly.
#[derive(Clone, Copy, Debug)]
enum AngleRule<'a> {
    /// Every triangle.
    Any,
    /// Every angle at least 30° (Algorithm 75).
    Thirty,
    /// Every angle at least that of a corner (Algorithm 76 at `α*`).
    Corner([Point; 3]),
    /// Every angle at least the user's floor.
    Floor(&'a AngleFloor),
}

impl AngleRule<'_> {
    /// Does every angle of the triangle `abc` meet the rule?
    fn admits(self, a: Point, b: Point, c: Point) -> bool {
        let corners = [[a, b, c], [b, c, a], [c, a, b]];
        match self {
            AngleRule::Any => true,
            AngleRule::Thirty => corners
                .into_iter()
                .all(|[o, p, q]| angle_at_least_30_degrees(o, p, q)),
            AngleRule::Corner(alpha) => corners
                .into_iter()
                .all(|corner| compare_corner_angles(corner, alpha) != Ordering::Less),
            AngleRule::Floor(floor) => floor.admits_triangle(a, b, c),
        }
    }

    /// The rule's floor in degrees, for the rules that have a fixed one.
    fn degrees(self) -> Option<f64> {
        match self {
            AngleRule::Thirty => Some(30.0),
            AngleRule::Floor(floor) => Some(floor.degrees()),
            AngleRule::Any | AngleRule::Corner(_) => None,
        }
    }
}

/// Loop steps between two checks of the stop token: a check reads the
/// clock, about as costly as a few orientation tests.
const STOP_CHECK_EVERY: usize = 1024;

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

/// Every candidate, in the tie-breaking order of the module docs, with what the algorithms
/// learnt on the way.
#[cfg_attr(not(test), allow(dead_code))] // the angle statistics serve the tests
pub(crate) struct Candidates<'a> {
    /// The candidates computed: those the approximation asks for (all four
    /// for `best`), without the face programs (Algorithm 75's step 3 and
    /// the `RNG ∪ hull` optimum) when a face exceeds the cap; Delaunay
    /// when nothing else is left.
    pub list: Vec<Candidate>,
    /// The candidates skipped, each with why.
    pub skipped: Vec<(&'static str, String)>,
    /// A floor such that one candidate is optimal among the triangulations
    /// meeting it (Algorithm 75's step 3; the face programs under a floor
    /// of at least 30°, by Theorem 74).
    optimum_rule: Option<AngleRule<'a>>,
    /// Corners of the largest face of `RNG ∪ hull`.
    pub largest_face: usize,
    /// `DT`'s smallest angle as a corner `[apex, a, b]`.
    pub smallest_angle: [u32; 3],
    /// Did Algorithm 75 run its step 3 (`α* ≥ 30°`)?
    pub thirty_degrees: bool,
    /// Flips made by Algorithm 76.
    pub flips: usize,
}

/// The best of the candidates `settings` asks for under `objective`, with
/// the certified bound and the guarantee (module docs).
///
/// # Errors
/// [`Error::InvalidOption`] if the floor exceeds the Delaunay
/// triangulation's smallest angle; [`Error::Internal`] if spade fails or a
/// face program finds no triangulation (a bug); [`Error::Interrupted`]
/// when `stop` says so (checked between faces, flips and searched hull
/// edges).
pub(crate) fn area_general(
    points: &PointSet,
    objective: AreaBottleneck,
    settings: Settings<'_>,
    stop: &Stop,
) -> Result<GeneralAreaResult> {
    best_of(
        points,
        objective,
        settings,
        &candidates(points, objective, settings, stop)?,
        stop,
    )
}

/// The best of `candidates` under `objective` (the first of the best), with
/// the certified bound (module docs).
///
/// # Errors
/// [`Error::Interrupted`] when `stop` says so.
pub(crate) fn best_of(
    points: &PointSet,
    objective: AreaBottleneck,
    settings: Settings<'_>,
    candidates: &Candidates<'_>,
    stop: &Stop,
) -> Result<GeneralAreaResult> {
    let pts = points.points();
    let mut best = 0;
    for (i, c) in candidates.list.iter().enumerate() {
        if objective.better(
            |v| pts[v as usize],
            c.bottleneck,
            candidates.list[best].bottleneck,
        ) {
            best = i;
        }
    }
    let winner = &candidates.list[best];
    let bound = certified_bound(
        pts,
        &convex_hull_cycle(pts),
        &candidates.list[0].triangles,
        objective,
        stop,
    )?;
    let exact = bound.is_some_and(|b| area_order(pts, winner.bottleneck, b) == Ordering::Equal);
    let corner_degrees =
        |[o, a, b]: [u32; 3]| angle_deg(pts[o as usize], pts[a as usize], pts[b as usize]);
    let smallest_angle_degrees = corner_degrees(smallest_angle(pts, &winner.triangles));
    let guarantee = if exact {
        Guarantee {
            kind: "optimal",
            alpha_degrees: None,
            statement: "optimal: the result attains the certified bound".to_string(),
            smallest_angle_degrees,
            theorem_81: Vec::new(),
        }
    } else {
        let names: Vec<&str> = candidates.list.iter().map(|c| c.name).collect();
        let mut statement = format!(
            "not proven optimal; the optimum is within the certified bound; no worse than {}",
            names.join(", ")
        );
        let mut kind = "approximation";
        let mut alpha_degrees = None;
        if let Some((rule, degrees)) = candidates
            .optimum_rule
            .and_then(|r| Some((r, r.degrees()?)))
        {
            let meets = winner
                .triangles
                .iter()
                .all(|t| rule.admits(pts[t[0] as usize], pts[t[1] as usize], pts[t[2] as usize]));
            if meets {
                kind = "optimal-among-alpha-triangulations";
                alpha_degrees = Some(degrees);
                statement = format!(
                    "optimal among the triangulations whose angles are all at least {degrees}° \
                     (every 30°-triangulation contains RNG ∪ hull, Vassilev's Theorem 74, so the \
                     face programs search them all); over all triangulations the optimum is \
                     within the certified bound"
                );
            } else {
                statement.push_str(&format!(
                    "; no worse than the optimum among the triangulations whose angles are all \
                     at least {degrees}°"
                ));
            }
        }
        Guarantee {
            kind,
            alpha_degrees,
            statement: format!(
                "{statement}. {}",
                guarantee::theorem_81_statement(objective, smallest_angle_degrees)
            ),
            smallest_angle_degrees,
            theorem_81: guarantee::sampled_factors(objective, smallest_angle_degrees),
        }
    };
    let report = ApproximationReport {
        choice: settings.approximation,
        candidate: winner.name,
        candidates: candidates.list.iter().map(|c| c.name).collect(),
        skipped: candidates.skipped.clone(),
        delaunay_smallest_angle: candidates.smallest_angle,
        delaunay_smallest_angle_degrees: corner_degrees(candidates.smallest_angle),
        alpha_degrees: settings.alpha.map(AngleFloor::degrees),
        flips: candidates.flips,
        guarantee,
    };
    Ok(GeneralAreaResult {
        triangles: winner.triangles.clone(),
        algorithm: winner.name.to_string(),
        exact,
        bound,
        report,
    })
}

/// The candidates of the module docs that `settings` asks for, under
/// `objective`.
pub(crate) fn candidates<'a>(
    points: &PointSet,
    objective: AreaBottleneck,
    settings: Settings<'a>,
    stop: &Stop,
) -> Result<Candidates<'a>> {
    candidates_with_cap(points, objective, settings, MAX_FACE_CORNERS, stop)
}

/// [`candidates`] with the face-size cap `max_face` instead of
/// [`MAX_FACE_CORNERS`].
fn candidates_with_cap<'a>(
    points: &PointSet,
    objective: AreaBottleneck,
    settings: Settings<'a>,
    max_face: usize,
    stop: &Stop,
) -> Result<Candidates<'a>> {
    let pts = points.points();
    let g = DelaunayGraph::with_topology(pts)?;
    let with_bottleneck = |name: &'static str, triangles: Vec<[u32; 3]>| Candidate {
        name,
        bottleneck: bottleneck(pts, objective, &triangles),
        triangles,
    };
    let smallest_angle = smallest_angle(pts, &g.triangles);
    let [o, a, b] = smallest_angle.map(|v| pts[v as usize]);
    if let Some(floor) = settings.alpha {
        // Delaunay maximises the smallest angle (thesis Property 13): above
        // α* no triangulation meets the floor; at or below it Delaunay does.
        if !floor.admits(o, a, b) {
            return Err(Error::InvalidOption {
                option: "alpha",
                message: format!(
                    "α = {}° exceeds the Delaunay triangulation's smallest angle α* = {}° \
                     (corner at point {} between points {} and {}): no triangulation has every \
                     angle at least α",
                    floor.degrees(),
                    angle_deg(o, a, b),
                    points.input_index(smallest_angle[0]),
                    points.input_index(smallest_angle[1]),
                    points.input_index(smallest_angle[2]),
                ),
            });
        }
    }
    let thirty_degrees = angle_at_least_30_degrees(o, a, b);
    let floor_at_least_30 = settings.alpha.filter(|f| f.degrees() >= 30.0);
    let wants = |a: AreaApproximation| {
        settings.approximation == AreaApproximation::Best || settings.approximation == a
    };
    let wants_75 = wants(AreaApproximation::Thesis75);
    let wants_rng_hull = wants(AreaApproximation::RngHull);
    let faces = if (wants_75 && thirty_degrees) || wants_rng_hull {
        rng_hull_faces(pts, &g)
    } else {
        Vec::new()
    };
    let largest_face = faces.iter().map(Vec::len).max().unwrap_or(0);
    let too_large = format!(
        "a face of RNG ∪ hull has {largest_face} corners, above the face programs' cap of \
         {max_face}"
    );
    let mut list = Vec::new();
    let mut skipped = Vec::new();
    let mut optimum_rule = None;
    if settings.approximation == AreaApproximation::Best {
        list.push(with_bottleneck(DELAUNAY, g.triangles.clone()));
    }
    if wants_75 {
        if !thirty_degrees {
            list.push(with_bottleneck(ALGORITHM_75, g.triangles.clone()));
        } else if largest_face <= max_face {
            // A floor above 30° is stricter than Algorithm 75's.
            let rule = floor_at_least_30.map_or(AngleRule::Thirty, AngleRule::Floor);
            let fat = triangulate_faces(pts, &faces, objective, rule, stop)?;
            list.push(with_bottleneck(ALGORITHM_75, fat));
            optimum_rule = Some(rule);
        } else {
            skipped.push((ALGORITHM_75, too_large.clone()));
        }
    }
    if wants_rng_hull {
        if largest_face <= max_face {
            let rule = settings.alpha.map_or(AngleRule::Any, AngleRule::Floor);
            let rng_hull = triangulate_faces(pts, &faces, objective, rule, stop)?;
            list.push(with_bottleneck(RNG_HULL_OPTIMUM, rng_hull));
            if let Some(floor) = floor_at_least_30 {
                optimum_rule = Some(AngleRule::Floor(floor)); // Theorem 74
            }
        } else {
            skipped.push((RNG_HULL_OPTIMUM, too_large));
        }
    }
    let mut flips = 0;
    if wants(AreaApproximation::Thesis76) {
        let rule = settings
            .alpha
            .map_or(AngleRule::Corner([o, a, b]), AngleRule::Floor);
        let (algorithm_76, made) = algorithm_76(pts, &g, rule, stop)?;
        flips = made;
        list.push(with_bottleneck(ALGORITHM_76, algorithm_76));
    }
    if list.is_empty() {
        list.push(with_bottleneck(DELAUNAY, g.triangles.clone()));
    }
    Ok(Candidates {
        list,
        skipped,
        optimum_rule,
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

/// The bottleneck triangle of a (non-empty) triangulation under `objective`:
/// the first of the worst.
pub(crate) fn bottleneck(
    pts: &[Point],
    objective: AreaBottleneck,
    triangles: &[[u32; 3]],
) -> [u32; 3] {
    let point = |v: u32| pts[v as usize];
    triangles
        .iter()
        .copied()
        .reduce(|s, t| if objective.better(point, s, t) { t } else { s })
        .expect("a triangulation has a triangle")
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
/// only triangles that meet `rule`.
fn triangulate_faces(
    pts: &[Point],
    faces: &[Vec<u32>],
    objective: AreaBottleneck,
    rule: AngleRule<'_>,
    stop: &Stop,
) -> Result<Vec<[u32; 3]>> {
    let p = |v: u32| pts[v as usize];
    let mut out = Vec::with_capacity(2 * pts.len());
    for (k, face) in faces.iter().enumerate() {
        // Small faces are most of them: check every few, and before each
        // large one (a face of k corners costs O(k³)).
        if k.is_multiple_of(STOP_CHECK_EVERY) || face.len() > 64 {
            stop.check()?;
        }
        let region = PolygonCycle::exact(pts, face);
        let convex = region.is_strictly_convex();
        let v = face.as_slice();
        let allowed = |i: usize, m: usize, j: usize| {
            let (a, b, c) = (p(v[i]), p(v[m]), p(v[j]));
            orient_sign(a, b, c) > 0 && rule.admits(a, b, c)
        };
        let solved = optimal_triangulation(
            face.len(),
            |i, j| convex || region.is_diagonal(i, j),
            allowed,
            &BottleneckArea {
                point: &|c: usize| p(v[c]),
                kind: objective,
            },
        )
        .ok_or_else(|| {
            Error::Internal(format!(
                "a face of RNG ∪ hull with {} corners has no triangulation under {rule:?}",
                face.len(),
            ))
        })?;
        out.extend(solved.triangles.into_iter().map(|t| t.map(|c| v[c])));
    }
    Ok(out)
}

/// Algorithm 76 from `DT` with the angle floor `rule` (`DT`'s smallest
/// angle, or the user's α): the triangles and the number of flips (module
/// docs for the rule, the order and termination), or
/// [`Error::Interrupted`] when `stop` says so.
fn algorithm_76(
    pts: &[Point],
    g: &DelaunayGraph,
    rule: AngleRule<'_>,
    stop: &Stop,
) -> Result<(Vec<[u32; 3]>, usize)> {
    let p = |v: u32| pts[v as usize];
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
    let angles_ok = |[a, b, c]: [Point; 3]| rule.admits(a, b, c);
    let mut flips = 0;
    let mut popped = 0usize;
    while let Some((t, j, [x, y])) = queue.pop_front() {
        popped += 1;
        if popped.is_multiple_of(STOP_CHECK_EVERY) {
            stop.check()?;
        }
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
    Ok((tri, flips))
}

/// The certified bound of the module docs, as a triangle `[a, b, r]` on a
/// hull edge `ab` (`hull`: the counter-clockwise hull cycle; `triangles`:
/// any triangulation of `pts`, whose triangles on the hull edges are empty
/// and so settle most edges without a search). `None` only without a hull
/// edge that has a point on its inner side (all points collinear, which
/// [`PointSet`] rejects).
///
/// The result is that of the definition, edge by edge in hull order (the
/// first tightest edge; on it the largest empty apex first by the angle at
/// `a`, or the smallest apex of least index), but an edge is searched only
/// if it can be strictly tighter than the bound so far: its triangle in
/// `triangles` is empty, so for MaxMin `M(ab)` is at least its area, and for
/// MinMax `m(ab)` is at most its area. On a lattice, where every empty
/// triangle has the same area (Pick), that settles every edge but the first,
/// and the cost falls from `O(h · n log n)` to `O(n)`.
pub(crate) fn certified_bound(
    pts: &[Point],
    hull: &[u32],
    triangles: &[[u32; 3]],
    objective: AreaBottleneck,
    stop: &Stop,
) -> Result<Option<[u32; 3]>> {
    let h = hull.len();
    let mut apex_of_hull_edge: HashMap<[u32; 2], u32> = HashMap::with_capacity(h);
    let hull_edges: HashSet<[u32; 2]> = (0..h).map(|e| [hull[e], hull[(e + 1) % h]]).collect();
    for t in triangles {
        for k in 0..3 {
            let side = [t[k], t[(k + 1) % 3]];
            // Counter-clockwise triangles hold a hull edge in the hull's
            // direction; a clockwise one would hold it reversed.
            for side in [side, [side[1], side[0]]] {
                if hull_edges.contains(&side) {
                    apex_of_hull_edge.insert(side, t[(k + 2) % 3]);
                }
            }
        }
    }
    let mut bound: Option<[u32; 3]> = None;
    let mut inner: Vec<u32> = Vec::with_capacity(pts.len());
    for e in 0..h {
        let (a, b) = (hull[e], hull[(e + 1) % h]);
        if let (Some(b0), Some(&r)) = (bound, apex_of_hull_edge.get(&[a, b])) {
            let settled = match objective {
                // M(ab) >= A(abr) >= the bound: not strictly smaller.
                AreaBottleneck::MaxMin => area_order(pts, [a, b, r], b0) != Ordering::Less,
                // m(ab) <= A(abr) <= the bound: not strictly larger.
                AreaBottleneck::MinMax => area_order(pts, [a, b, r], b0) != Ordering::Greater,
            };
            if settled {
                continue;
            }
        }
        stop.check()?;
        let Some(value) = edge_bound(pts, a, b, objective, &mut inner) else {
            continue;
        };
        if tightens(pts, objective, value, bound) {
            bound = Some(value);
        }
    }
    Ok(bound)
}

/// Is the edge bound `value` strictly tighter than `bound`? MaxMin keeps the
/// smallest of the per-edge maxima, MinMax the largest of the per-edge
/// minima.
fn tightens(
    pts: &[Point],
    objective: AreaBottleneck,
    value: [u32; 3],
    bound: Option<[u32; 3]>,
) -> bool {
    bound.is_none_or(|b| match objective {
        AreaBottleneck::MaxMin => area_order(pts, value, b) == Ordering::Less,
        AreaBottleneck::MinMax => area_order(pts, value, b) == Ordering::Greater,
    })
}

/// The bound of one hull edge `ab` (module docs): the largest empty triangle
/// `abr` (MaxMin), first by the angle at `a`, or the smallest triangle
/// `abr` of least index `r` (MinMax); `None` without a point on the inner
/// side. `inner` is scratch space.
fn edge_bound(
    pts: &[Point],
    a: u32,
    b: u32,
    objective: AreaBottleneck,
    inner: &mut Vec<u32>,
) -> Option<[u32; 3]> {
    match objective {
        AreaBottleneck::MaxMin => {
            let mut largest: Option<[u32; 3]> = None;
            for r in empty_apexes(pts, a, b, inner) {
                let t = [a, b, r];
                if largest.is_none_or(|l| area_order(pts, t, l) == Ordering::Greater) {
                    largest = Some(t);
                }
            }
            largest
        }
        AreaBottleneck::MinMax => {
            let (pa, pb) = (pts[a as usize], pts[b as usize]);
            inner.clear();
            inner.extend(
                (0..pts.len() as u32).filter(|&r| orient_sign(pa, pb, pts[r as usize]) > 0),
            );
            inner.iter().map(|&r| [a, b, r]).reduce(|s, t| {
                if area_order(pts, t, s) == Ordering::Less {
                    t
                } else {
                    s
                }
            })
        }
    }
}

/// How long each step of the approximation took on one input, and what it
/// worked on (for the benchmark harness; both objectives' face programs and
/// bounds).
#[cfg(feature = "internals")]
pub struct AreaGeneralSteps {
    /// `Delaunay`, `RNG ∪ hull faces`, `face programs MaxMin`, `face
    /// programs MinMax`, `Algorithm 76`, `bound MaxMin`, `bound MinMax`.
    pub phases: Vec<crate::timing::Phase>,
    /// Bounded faces of `RNG ∪ hull`.
    pub faces: usize,
    /// Corners of the largest face.
    pub largest_face: usize,
    /// The sum of the cubes of the faces' corner counts (the programs' work).
    pub cubed_corners: usize,
    /// Flips made by Algorithm 76.
    pub flips: usize,
    /// Points on the convex hull (the bound's edges).
    pub hull_points: usize,
}

/// Runs and times every step of the approximation on `points`.
///
/// # Errors
/// As [`area_general`].
#[cfg(feature = "internals")]
pub(crate) fn step_times(points: &PointSet) -> Result<AreaGeneralSteps> {
    use crate::timing::timed;
    let pts = points.points();
    let mut phases = Vec::new();
    let g = timed(&mut phases, "Delaunay", || {
        DelaunayGraph::with_topology(pts)
    })?;
    let faces = timed(&mut phases, "RNG ∪ hull faces", || {
        rng_hull_faces(pts, &g)
    });
    for (name, objective) in [
        ("face programs MaxMin", AreaBottleneck::MaxMin),
        ("face programs MinMax", AreaBottleneck::MinMax),
    ] {
        timed(&mut phases, name, || {
            triangulate_faces(pts, &faces, objective, AngleRule::Any, &Stop::default())
        })?;
    }
    let (_, flips) = timed(&mut phases, "Algorithm 76", || {
        let corner = smallest_angle(pts, &g.triangles).map(|v| pts[v as usize]);
        algorithm_76(pts, &g, AngleRule::Corner(corner), &Stop::default())
    })?;
    let hull = convex_hull_cycle(pts);
    timed(&mut phases, "bound MaxMin", || {
        certified_bound(
            pts,
            &hull,
            &g.triangles,
            AreaBottleneck::MaxMin,
            &Stop::default(),
        )
    })?;
    timed(&mut phases, "bound MinMax", || {
        certified_bound(
            pts,
            &hull,
            &g.triangles,
            AreaBottleneck::MinMax,
            &Stop::default(),
        )
    })?;
    Ok(AreaGeneralSteps {
        phases,
        faces: faces.len(),
        largest_face: faces.iter().map(Vec::len).max().unwrap_or(0),
        cubed_corners: faces.iter().map(|f| f.len().pow(3)).sum(),
        flips,
        hull_points: hull.len(),
    })
}

#[cfg(test)]
mod tests;
