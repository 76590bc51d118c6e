//! The faces the LMT-skeleton leaves and their exact triangulation.
//!
//! When the certain edges (with the hull) connect every point — the usual
//! case — the faces of their plane graph are traced directly, by the exact
//! angular order at each vertex ([`regions::traced_faces`]); each is then one closed
//! walk with no point inside. Otherwise the certain edges are inserted as
//! constraints into a constrained Delaunay triangulation
//! ([`ConstrainedDelaunay`](crate::structures::ConstrainedDelaunay)); its
//! triangles joined across unconstrained edges form the *regions*: the faces
//! of the skeleton, with their holes and isolated points. A
//! region is *simple* when its boundary is one closed walk (weakly simple:
//! a dangling certain edge is walked twice) with no point inside; Klincsek's
//! program ([`crate::polygon_program`]) then finds its minimum-weight
//! triangulation over the candidate diagonals exactly (certified intervals,
//! exact sums of square roots on undecided comparisons). Other regions
//! (holes, isolated points) go to an exact search over the region's empty
//! candidate triangles: a front of half-edges still to be covered is
//! advanced one triangle at a time on its first half-edge, and the best
//! completion of each front is memoised (the untriangulated part is exactly
//! the part left of the front, so the best completion depends on the front
//! alone) — a dynamic program over fronts, exact by the same comparisons,
//! within a budget of fronts. Faces the plain search cannot finish go to
//! the triangle program ([`super::face_program`]): its certified dual bound
//! prices the search; when the priced search still runs out, a certified
//! branch and bound on edges over the program (Kyoda, Imai, Takeuchi and
//! Tajima 1997, §3; [`branch_and_bound`]) decides the face, each node's
//! bound certified the same way. The constrained Delaunay triangles (or the
//! best triangulation built) are a region's fallback when the budget runs
//! out, with the least open node bound as its certified lower bound.
//!
//! | file | what |
//! |---|---|
//! | `mod.rs` | the regions solved one by one ([`solve_regions`]), a region's [`FaceView`] and its fallback bound |
//! | `regions.rs` | the regions: traced faces, or constrained Delaunay regions |
//! | `polygon.rs` | Klincsek's program on a simple region |
//! | `search.rs` | the region's candidate triangles and the exact front search |
//! | `branch_and_bound.rs` | the triangle program's certificate, prices and branch and bound |

mod branch_and_bound;
mod polygon;
mod regions;
mod search;

use super::skeleton::Skeleton;
use crate::interrupt::Stop;
use crate::kernel::{LengthInterval, Point};
use crate::parallel::prelude::*;
use crate::structures::PolygonCycle;
use branch_and_bound::{solve_by_program, ProgramOutcome};
use search::{face_triangles, search};
use std::collections::{HashMap, HashSet};

/// Largest number of fronts the exact search memoises per region (by
/// default).
pub(crate) const FRONT_BUDGET: usize = 400_000;

/// How one region was solved.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub(crate) enum Method {
    Triangle,
    Polygon,
    Search,
    /// The search on the triangles the program's certificate keeps
    /// ([`super::face_program`]).
    Program,
    /// Not solved exactly: the constrained Delaunay triangles.
    Fallback,
}

/// One region's triangles and what it took.
pub(crate) struct RegionResult {
    pub triangles: Vec<[u32; 3]>,
    pub method: Method,
    pub corners: usize,
    pub holes: usize,
    pub inner_points: usize,
    /// Fronts explored (search only).
    pub fronts: usize,
    /// The triangle program, if one was set up: its triangles, those the
    /// certificate kept, and the fronts of the search on those.
    pub program: Option<ProgramStats>,
    /// Certified lower bound of the weight of the region's inner edges.
    pub lower: f64,
}

/// What the triangle program of a region did.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct ProgramStats {
    pub triangles: usize,
    /// Triangles kept by the certificate (0 without one).
    pub kept: usize,
    /// Fronts of the priced searches (root and nodes).
    pub fronts: usize,
    /// Branch-and-bound nodes evaluated (0: decided at the root).
    pub nodes: usize,
}

/// A region: its boundary walks (vertex cycles, region on the left), its
/// isolated points and its constrained Delaunay triangles.
struct Region {
    cycles: Vec<Vec<u32>>,
    inner: Vec<u32>,
    cdt_triangles: Vec<[u32; 3]>,
}

/// The regions of the skeleton, solved (in parallel); the exact search
/// memoises at most `budget` fronts per region.
///
/// # Errors
/// [`crate::Error::Interrupted`] when `stop` says so (read before each
/// region and inside Klincsek's program).
pub(crate) fn solve_regions(
    pts: &[Point],
    sk: &Skeleton,
    budget: usize,
    stop: &Stop,
) -> crate::error::Result<Vec<RegionResult>> {
    solve_regions_within(pts, sk, budget, super::MAX_POINTS, stop)
}

/// [`solve_regions`] with Klincsek's program on faces of at most
/// `polygon_limit` corners (the tests lower it to reach the fallback).
fn solve_regions_within(
    pts: &[Point],
    sk: &Skeleton,
    budget: usize,
    polygon_limit: usize,
    stop: &Stop,
) -> crate::error::Result<Vec<RegionResult>> {
    if let Some(cycles) = regions::traced_faces(pts, sk) {
        let solved = cycles
            .into_par_iter()
            .map(|cycle| {
                let region = Region {
                    cycles: vec![cycle],
                    inner: Vec::new(),
                    cdt_triangles: Vec::new(),
                };
                solve_region(pts, sk, region, budget, polygon_limit, stop)
            })
            .collect::<crate::error::Result<Vec<RegionResult>>>()?;
        // A simple face falls back only when Klincsek's program cannot run
        // on it (too many corners): that needs the constrained Delaunay
        // triangles, so all faces go the general way (rare).
        if solved.iter().all(|r| r.method != Method::Fallback) {
            return Ok(solved);
        }
    }
    stop.check()?;
    let regions = regions::regions(pts, sk)?;
    regions
        .into_par_iter()
        .map(|r| solve_region(pts, sk, r, budget, polygon_limit, stop))
        .collect()
}

fn solve_region(
    pts: &[Point],
    sk: &Skeleton,
    region: Region,
    budget: usize,
    polygon_limit: usize,
    stop: &Stop,
) -> crate::error::Result<RegionResult> {
    stop.check()?;
    let corners: usize = region.cycles.iter().map(Vec::len).sum();
    let mut result = RegionResult {
        triangles: Vec::new(),
        method: Method::Fallback,
        corners,
        holes: region.cycles.len().saturating_sub(1),
        inner_points: region.inner.len(),
        fronts: 0,
        program: None,
        lower: 0.0,
    };
    if region.cycles.len() == 1 && region.inner.is_empty() && region.cycles[0].len() == 3 {
        // One walk of three half-edges: a (counter-clockwise) empty triangle.
        let c = &region.cycles[0];
        result.triangles = vec![[c[0], c[1], c[2]]];
        result.method = Method::Triangle;
        return Ok(result);
    }
    let mut incumbent = None;
    let mut program_lower = 0.0f64;
    let mut view = None;
    if region.cycles.len() == 1 && region.inner.is_empty() {
        if let Some(t) = polygon::solve_polygon(pts, sk, &region.cycles[0], polygon_limit, stop)? {
            result.triangles = t;
            result.method = Method::Polygon;
            return Ok(result);
        }
    } else {
        let face = face_triangles(sk, view.insert(FaceView::new(pts, &region)));
        // Most faces with holes are small: the plain search first, within
        // a fraction of the budget.
        let quick = budget.min(QUICK_FRONTS);
        if plain_search(pts, sk, &region, &face, quick, &mut result) {
            return Ok(result);
        }
        let (outcome, stats) = solve_by_program(pts, sk, &region, &face, budget);
        result.program = Some(stats);
        match outcome {
            ProgramOutcome::Solved(t) => {
                result.triangles = t;
                result.method = Method::Program;
                return Ok(result);
            }
            ProgramOutcome::Unsolved {
                incumbent: best,
                lower,
            } => {
                incumbent = best;
                program_lower = lower.unwrap_or(0.0);
                if lower.is_none() && budget > quick {
                    // No certificate: the plain search with the whole budget.
                    if plain_search(pts, sk, &region, &face, budget, &mut result) {
                        return Ok(result);
                    }
                }
            }
        }
    }
    // Fallback with a certified lower bound: the region's inner edges number
    // 3(V − 1 + h − b) + b_h (Euler), each at least as long as the shortest
    // candidates inside; or the program's bound, if larger.
    result.lower = view
        .unwrap_or_else(|| FaceView::new(pts, &region))
        .lower_bound(pts, sk)
        .max(program_lower);
    result.triangles = incumbent.unwrap_or(region.cdt_triangles);
    Ok(result)
}

/// The plain exact search on `face` within `budget` fronts: records the
/// fronts it took and, if it decided the region, its triangles.
fn plain_search(
    pts: &[Point],
    sk: &Skeleton,
    region: &Region,
    face: &search::FaceTriangles,
    budget: usize,
    result: &mut RegionResult,
) -> bool {
    let (outcome, fronts) = search(pts, sk, region, face, None, budget);
    result.fronts = fronts;
    let Some(solved) = outcome.found() else {
        return false;
    };
    result.triangles = solved.triangles;
    result.method = Method::Search;
    true
}

/// Fronts the plain search may memoise before the triangle program is set
/// up (at most the budget).
const QUICK_FRONTS: usize = 20_000;

/// A region seen from its corners: the polygon cycle of each boundary walk,
/// the corners at each point, the isolated points, every point of the
/// region and its boundary half-edges (the region on their left).
struct FaceView<'a> {
    region: &'a Region,
    cycles: Vec<PolygonCycle<'a>>,
    /// Per point: its corners, as (cycle, corner).
    corners_at: HashMap<u32, Vec<(usize, usize)>>,
    inner: HashSet<u32>,
    vertices: HashSet<u32>,
    boundary: HashSet<(u32, u32)>,
}

impl<'a> FaceView<'a> {
    fn new(pts: &'a [Point], region: &'a Region) -> Self {
        let cycles: Vec<PolygonCycle> = region
            .cycles
            .iter()
            .map(|c| PolygonCycle::exact(pts, c))
            .collect();
        let mut corners_at: HashMap<u32, Vec<(usize, usize)>> = HashMap::new();
        for (i, cycle) in region.cycles.iter().enumerate() {
            for (c, &v) in cycle.iter().enumerate() {
                corners_at.entry(v).or_default().push((i, c));
            }
        }
        let vertices = region
            .cycles
            .iter()
            .flatten()
            .chain(&region.inner)
            .copied()
            .collect();
        let boundary = region
            .cycles
            .iter()
            .flat_map(|c| (0..c.len()).map(move |i| (c[i], c[(i + 1) % c.len()])))
            .collect();
        FaceView {
            region,
            cycles,
            corners_at,
            inner: region.inner.iter().copied().collect(),
            vertices,
            boundary,
        }
    }

    /// Does the segment from `u` towards `w` enter the region at `u` (an
    /// isolated point, or strictly inside one of its corners)?
    fn leaves_into(&self, u: u32, w: u32) -> bool {
        self.inner.contains(&u)
            || self.corners_at.get(&u).is_some_and(|cs| {
                cs.iter()
                    .any(|&(i, c)| self.cycles[i].leaves_corner_into(c, w))
            })
    }

    /// Is the counter-clockwise triangle `[a, b, c]` inside the region at
    /// `a` (an isolated point, or within one of its corners)?
    fn contains_triangle_at(&self, [a, b, c]: [u32; 3]) -> bool {
        self.inner.contains(&a)
            || self.corners_at.get(&a).is_some_and(|cs| {
                cs.iter()
                    .any(|&(i, k)| self.cycles[i].contains_triangle_corner(k, b, c))
            })
    }

    /// A certified lower bound on the weight of the region's inner edges:
    /// by Euler's formula a triangulation of the region has `3(V − 1 + h −
    /// b) + b_h` inner edges (`V` points, `h` holes, `b` boundary edges,
    /// `b_h` boundary half-edges), each at least as long as the shortest
    /// candidates inside the region.
    fn lower_bound(&self, pts: &[Point], sk: &Skeleton) -> f64 {
        let half_edges: usize = self.region.cycles.iter().map(Vec::len).sum();
        // Undirected boundary edges: a dangling edge is walked both ways.
        let edges = self
            .boundary
            .iter()
            .filter(|&&(a, b)| a < b || !self.boundary.contains(&(b, a)))
            .count();
        let h = self.region.cycles.len() as i64 - 1;
        let needed = 3 * (self.vertices.len() as i64 - 1 + h - edges as i64) + half_edges as i64;
        let mut lengths: Vec<f64> = Vec::new();
        for (e, &[u, v]) in sk.edges.iter().enumerate() {
            if sk.alive[e]
                && !sk.certain[e]
                && self.vertices.contains(&u)
                && self.vertices.contains(&v)
                && self.leaves_into(u, v)
                && self.leaves_into(v, u)
            {
                lengths.push(LengthInterval::of_segment(pts[u as usize], pts[v as usize]).lo);
            }
        }
        lengths.sort_unstable_by(f64::total_cmp);
        let needed = needed.max(0) as usize;
        lengths
            .iter()
            .take(needed)
            .fold(LengthInterval::ZERO, |s, &l| {
                s.plus(LengthInterval { lo: l, hi: l })
            })
            .lo
    }
}

/// `k` points on a circle of radius 1000 and a centre (a wheel: its face
/// with the centre inside is not simple).
#[cfg(test)]
fn ring_with(k: usize, centre: Point) -> Vec<Point> {
    let mut pts: Vec<Point> = (0..k)
        .map(|i| {
            let a = std::f64::consts::TAU * i as f64 / k as f64;
            [1000.0 * a.cos(), 1000.0 * a.sin()]
        })
        .collect();
    pts.push(centre);
    pts
}

#[cfg(test)]
mod tests {
    use super::*;
    use optri_oracle::inputs;
    use rand::{rngs::StdRng, SeedableRng};

    const SEED_BEYOND_THE_LIMIT: u64 = 5;

    /// A simple face too large for Klincsek's program (the limit lowered to
    /// five corners) sends every face the general way: its fallback is the
    /// constrained Delaunay triangles, so the faces still triangulate the
    /// hull, and the larger faces are reported unsolved.
    #[test]
    fn a_face_beyond_the_program_limit_takes_the_general_way() {
        let mut rng = StdRng::seed_from_u64(SEED_BEYOND_THE_LIMIT);
        let pts = inputs::uniform_unit_square(&mut rng, 400);
        let candidates = super::super::skeleton::diamond_candidates(&pts);
        let sk = super::super::skeleton::lmt_skeleton(&pts, candidates).unwrap();
        assert!(regions::traced_faces(&pts, &sk).is_some());
        let results = solve_regions_within(&pts, &sk, FRONT_BUDGET, 5, &Stop::default()).unwrap();
        let large = results.iter().filter(|r| r.corners > 5).count();
        assert!(large > 0);
        for r in &results {
            let expected = if r.corners == 3 {
                Method::Triangle
            } else if r.corners <= 5 {
                Method::Polygon
            } else {
                Method::Fallback
            };
            assert_eq!(r.method, expected);
            assert_eq!(
                r.triangles.len(),
                r.corners - 2,
                "a simple face's triangles"
            );
        }
        let hull = crate::spatial::convex_hull_cycle(&pts).len();
        let triangles: usize = results.iter().map(|r| r.triangles.len()).sum();
        assert_eq!(triangles, 2 * pts.len() - hull - 2);
        // The same as the traced way with the usual limit, face for face
        // where both solved it.
        let usual = solve_regions(&pts, &sk, FRONT_BUDGET, &Stop::default()).unwrap();
        assert!(usual.iter().all(|r| r.method != Method::Fallback));
        assert_eq!(usual.len(), results.len());
    }
}
