//! The faces the LMT-skeleton leaves and their exact triangulation.
//!
//! When the certain edges (with the hull) connect every point — the usual
//! case — the faces of their plane graph are traced directly, by the exact
//! angular order at each vertex ([`traced_faces`]); each is then one closed
//! walk with no point inside. Otherwise the certain edges are inserted as
//! constraints into a constrained Delaunay triangulation (spade); its
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

use super::face_program::{FaceProgram, Prices};
use super::skeleton::{ccw_from_east, Skeleton};
use super::TotalLength;
use crate::kernel::{compare_length_sums, dot_sign, orient_sign, LengthInterval, Point};
use crate::parallel::prelude::*;
use crate::polygon_program::optimal_triangulation;
use spade::handles::{FixedDirectedEdgeHandle, FixedFaceHandle, InnerTag};
use spade::{ConstrainedDelaunayTriangulation, HasPosition, Point2, Triangulation as _};
use std::cmp::Ordering;
use std::cmp::Reverse;
use std::collections::{BTreeSet, BinaryHeap, HashMap, HashSet};

/// Largest number of fronts the exact search memoises per region (by
/// default).
pub(crate) const FRONT_BUDGET: usize = 400_000;

struct Vertex {
    position: Point2<f64>,
    id: u32,
}

impl HasPosition for Vertex {
    type Scalar = f64;
    fn position(&self) -> Point2<f64> {
        self.position
    }
}

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
pub(crate) fn solve_regions(
    pts: &[Point],
    sk: &Skeleton,
    budget: usize,
) -> crate::error::Result<Vec<RegionResult>> {
    solve_regions_within(pts, sk, budget, super::MAX_POINTS)
}

/// [`solve_regions`] with Klincsek's program on faces of at most
/// `polygon_limit` corners (the tests lower it to reach the fallback).
fn solve_regions_within(
    pts: &[Point],
    sk: &Skeleton,
    budget: usize,
    polygon_limit: usize,
) -> crate::error::Result<Vec<RegionResult>> {
    if let Some(cycles) = traced_faces(pts, sk) {
        let solved: Vec<RegionResult> = cycles
            .into_par_iter()
            .map(|cycle| {
                let region = Region {
                    cycles: vec![cycle],
                    inner: Vec::new(),
                    cdt_triangles: Vec::new(),
                };
                solve_region(pts, sk, region, budget, polygon_limit)
            })
            .collect();
        // A simple face falls back only when Klincsek's program cannot run
        // on it (too many corners): that needs the constrained Delaunay
        // triangles, so all faces go the general way (rare).
        if solved.iter().all(|r| r.method != Method::Fallback) {
            return Ok(solved);
        }
    }
    let regions = regions(pts, sk)?;
    Ok(regions
        .into_par_iter()
        .map(|r| solve_region(pts, sk, r, budget, polygon_limit))
        .collect())
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
fn traced_faces(pts: &[Point], sk: &Skeleton) -> Option<Vec<Vec<u32>>> {
    let n = pts.len();
    let certain: Vec<[u32; 2]> = sk
        .edges
        .iter()
        .zip(&sk.certain)
        .filter(|(_, &c)| c)
        .map(|(&e, _)| e)
        .collect();
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
    let mut offsets = vec![0u32; n + 1];
    for &[u, v] in &certain {
        offsets[u as usize + 1] += 1;
        offsets[v as usize + 1] += 1;
    }
    for v in 0..n {
        offsets[v + 1] += offsets[v];
    }
    let mut to = vec![0u32; offsets[n] as usize];
    let mut fill = offsets.clone();
    for &[u, v] in &certain {
        to[fill[u as usize] as usize] = v;
        fill[u as usize] += 1;
        to[fill[v as usize] as usize] = u;
        fill[v as usize] += 1;
    }
    drop(fill);
    drop(certain);
    let around = |v: usize| offsets[v] as usize..offsets[v + 1] as usize;
    let mut slices: Vec<&mut [u32]> = Vec::with_capacity(n);
    {
        let mut rest = &mut to[..];
        for v in 0..n {
            let (head, tail) = rest.split_at_mut(around(v).len());
            slices.push(head);
            rest = tail;
        }
    }
    // Two certain edges in one direction would overlap: not a plane graph
    // (never expected; the general way then decides).
    let plane = slices.par_iter_mut().enumerate().all(|(v, list)| {
        let a = pts[v];
        list.sort_unstable_by(|&x, &y| ccw_from_east(a, pts[x as usize], pts[y as usize]));
        list.windows(2)
            .all(|w| ccw_from_east(a, pts[w[0] as usize], pts[w[1] as usize]) == Ordering::Less)
    });
    drop(slices);
    if !plane {
        return None;
    }
    // next(u → v) = v → w, w the neighbour of v just clockwise of u: the
    // face left of u → v continues along it.
    let source: Vec<u32> = (0..n as u32)
        .flat_map(|v| std::iter::repeat_n(v, around(v as usize).len()))
        .collect();
    let next: Vec<u32> = (0..to.len())
        .into_par_iter()
        .map(|h| {
            let (u, v) = (source[h], to[h] as usize);
            let range = around(v);
            let list = &to[range.clone()];
            let b = pts[v];
            let i = list.partition_point(|&x| {
                ccw_from_east(b, pts[x as usize], pts[u as usize]) == Ordering::Less
            });
            debug_assert_eq!(list[i], u);
            (range.start + (i + list.len() - 1) % list.len()) as u32
        })
        .collect();
    // The outer face holds the hull's edges reversed: `hull[1] → hull[0]`.
    let hull = crate::spatial::convex_hull_cycle(pts);
    let outer = around(hull[1] as usize)
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

fn regions(pts: &[Point], sk: &Skeleton) -> crate::error::Result<Vec<Region>> {
    let vertices: Vec<Vertex> = pts
        .iter()
        .enumerate()
        .map(|(i, p)| Vertex {
            position: Point2::new(p[0], p[1]),
            id: i as u32,
        })
        .collect();
    let constraints: Vec<[usize; 2]> = sk
        .edges
        .iter()
        .zip(&sk.certain)
        .filter(|(_, &c)| c)
        .map(|(e, _)| [e[0] as usize, e[1] as usize])
        .collect();
    let cdt = ConstrainedDelaunayTriangulation::<Vertex>::bulk_load_cdt(vertices, constraints)
        .map_err(|e| crate::error::Error::Internal(format!("spade's CDT failed: {e:?}")))?;
    let id = |d: FixedDirectedEdgeHandle| {
        let e = cdt.directed_edge(d);
        (e.from().data().id, e.to().data().id)
    };
    let is_boundary = |d: FixedDirectedEdgeHandle| {
        let e = cdt.directed_edge(d);
        cdt.is_constraint_edge(e.as_undirected().fix()) || e.rev().face().is_outer()
    };
    // Flood fill faces across unconstrained edges.
    let faces: Vec<FixedFaceHandle<InnerTag>> = cdt.fixed_inner_faces().collect();
    let mut region_of: HashMap<FixedFaceHandle<InnerTag>, u32> =
        HashMap::with_capacity(faces.len());
    let mut out: Vec<Region> = Vec::new();
    for &f in &faces {
        if region_of.contains_key(&f) {
            continue;
        }
        let r = out.len() as u32;
        let mut stack = vec![f];
        region_of.insert(f, r);
        let mut members = Vec::new();
        let mut boundary: Vec<FixedDirectedEdgeHandle> = Vec::new();
        while let Some(g) = stack.pop() {
            members.push(g);
            for d in cdt.face(g).adjacent_edges() {
                if is_boundary(d.fix()) {
                    boundary.push(d.fix());
                } else if let Some(h) = d.rev().face().as_inner() {
                    if let std::collections::hash_map::Entry::Vacant(slot) =
                        region_of.entry(h.fix())
                    {
                        slot.insert(r);
                        stack.push(h.fix());
                    }
                }
            }
        }
        // Boundary walks: after u → v, turn around v through the region to
        // the next boundary half-edge leaving v.
        let mut next: HashMap<FixedDirectedEdgeHandle, FixedDirectedEdgeHandle> = HashMap::new();
        for &d in &boundary {
            let mut e = cdt.directed_edge(d).next();
            while !is_boundary(e.fix()) {
                e = e.rev().next();
            }
            next.insert(d, e.fix());
        }
        let mut used: HashSet<FixedDirectedEdgeHandle> = HashSet::new();
        let mut cycles = Vec::new();
        let mut sorted = boundary.clone();
        sorted.sort_unstable_by_key(|d| id(*d));
        for &d in &sorted {
            if used.contains(&d) {
                continue;
            }
            let mut cycle = Vec::new();
            let mut e = d;
            while used.insert(e) {
                cycle.push(id(e).0);
                e = next[&e];
            }
            cycles.push(cycle);
        }
        let on_boundary: HashSet<u32> = cycles.iter().flatten().copied().collect();
        let mut cdt_triangles = Vec::with_capacity(members.len());
        let mut inner = BTreeSet::new();
        for g in members {
            let t = cdt.face(g).vertices().map(|v| v.data().id);
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

/// Ccw position of direction `v → x` from the ray `v → r`, for exact
/// comparisons: `Less` if `x` comes before `y` sweeping counter-clockwise
/// from `r` (a direction on the ray itself is first).
fn ccw_compare(v: Point, r: Point, x: Point, y: Point) -> Ordering {
    let half = |w: Point| {
        let o = orient_sign(v, r, w);
        if o > 0 || (o == 0 && dot_sign(v, r, w) > 0) {
            0
        } else {
            1
        }
    };
    let (hx, hy) = (half(x), half(y));
    if hx != hy {
        return hx.cmp(&hy);
    }
    match orient_sign(v, x, y) {
        1 => Ordering::Less,
        -1 => Ordering::Greater,
        _ => Ordering::Equal,
    }
}

/// A corner of a region: vertex `v` with the boundary going `prev → v →
/// next`, the region on the left, so its interior at `v` is the sweep from
/// `next` counter-clockwise to `prev` (all around when `prev == next`).
#[derive(Clone, Copy)]
struct Corner {
    prev: u32,
    v: u32,
    next: u32,
}

impl Corner {
    /// Is the sweep from `b` counter-clockwise to `c` around `v` (less than
    /// 180°) inside the corner's interior sweep?
    fn contains_sweep(&self, pts: &[Point], b: u32, c: u32) -> bool {
        let p = |i: u32| pts[i as usize];
        let (v, r) = (p(self.v), p(self.next));
        let on_ray = |w: u32| orient_sign(v, r, p(w)) == 0 && dot_sign(v, r, p(w)) > 0;
        // b at position ≥ 0 always; c at the ray means 360°.
        let c_top = on_ray(c);
        let prev_top = on_ray(self.prev);
        if c_top {
            return prev_top;
        }
        if prev_top {
            return true; // the interior is all around; b < c as a triangle
        }
        // b ≤ c automatically (ccw triangle, < 180°) unless the sweep passes
        // the ray: then b is after c.
        if ccw_compare(v, r, p(b), p(c)) != Ordering::Less {
            return false;
        }
        ccw_compare(v, r, p(c), p(self.prev)) != Ordering::Greater
    }

    /// Is the direction `v → w` strictly inside the interior sweep?
    fn contains_direction(&self, pts: &[Point], w: u32) -> bool {
        let p = |i: u32| pts[i as usize];
        let (v, r) = (p(self.v), p(self.next));
        let on_ray = |w: u32| orient_sign(v, r, p(w)) == 0 && dot_sign(v, r, p(w)) > 0;
        if on_ray(w) {
            return false;
        }
        if on_ray(self.prev) {
            return true;
        }
        ccw_compare(v, r, p(w), p(self.prev)) == Ordering::Less
    }
}

/// The corners of a region, per vertex.
fn corners_of(region: &Region) -> HashMap<u32, Vec<Corner>> {
    let mut corners_at: HashMap<u32, Vec<Corner>> = HashMap::new();
    for cycle in &region.cycles {
        let k = cycle.len();
        for i in 0..k {
            let c = Corner {
                prev: cycle[(i + k - 1) % k],
                v: cycle[i],
                next: cycle[(i + 1) % k],
            };
            corners_at.entry(c.v).or_default().push(c);
        }
    }
    corners_at
}

fn solve_region(
    pts: &[Point],
    sk: &Skeleton,
    region: Region,
    budget: usize,
    polygon_limit: usize,
) -> RegionResult {
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
        return result;
    }
    let corners_at = corners_of(&region);
    let inner: HashSet<u32> = region.inner.iter().copied().collect();
    let mut incumbent = None;
    let mut program_lower = 0.0f64;
    if region.cycles.len() == 1 && region.inner.is_empty() {
        if let Some(t) = solve_polygon(pts, sk, &region.cycles[0], polygon_limit) {
            result.triangles = t;
            result.method = Method::Polygon;
            return result;
        }
    } else {
        let face = face_triangles(pts, sk, &region, &corners_at, &inner);
        // Most faces with holes are small: the plain search first, within
        // a fraction of the budget.
        let quick = budget.min(QUICK_FRONTS);
        let (solved, fronts) = search(pts, sk, &region, &face, None, quick);
        let solved = solved.found();
        result.fronts = fronts;
        if let Some(s) = solved {
            result.triangles = s.triangles;
            result.method = Method::Search;
            return result;
        }
        let (outcome, stats) = solve_by_program(pts, sk, &region, &face, budget);
        result.program = Some(stats);
        match outcome {
            ProgramOutcome::Solved(t) => {
                result.triangles = t;
                result.method = Method::Program;
                return result;
            }
            ProgramOutcome::Unsolved {
                incumbent: best,
                lower,
            } => {
                incumbent = best;
                program_lower = lower.unwrap_or(0.0);
                if lower.is_none() && budget > quick {
                    // No certificate: the plain search with the whole budget.
                    let (solved, fronts) = search(pts, sk, &region, &face, None, budget);
                    let solved = solved.found();
                    result.fronts = fronts;
                    if let Some(s) = solved {
                        result.triangles = s.triangles;
                        result.method = Method::Search;
                        return result;
                    }
                }
            }
        }
    }
    // Fallback with a certified lower bound: the region's inner edges number
    // 3(V − 1 + h − b) + b_h (Euler), each at least as long as the shortest
    // candidates inside; or the program's bound, if larger.
    result.lower = lower_bound(pts, sk, &region, &corners_at, &inner).max(program_lower);
    result.triangles = incumbent.unwrap_or(region.cdt_triangles);
    result
}

/// Fronts the plain search may memoise before the triangle program is set
/// up (at most the budget).
const QUICK_FRONTS: usize = 20_000;

enum ProgramOutcome {
    /// Proven optimal (module docs of [`super::face_program`]).
    Solved(Vec<[u32; 3]>),
    /// Not proven: the best triangulation of the region built (checked by
    /// the search), if any, and the certified lower bound on its optimum,
    /// if the certificate held.
    Unsolved {
        incumbent: Option<Vec<[u32; 3]>>,
        lower: Option<f64>,
    },
}

/// The triangle program of a region, its certificate, the triangles it
/// fixes out and the exact search on the rest ([`super::face_program`]).
fn solve_by_program(
    pts: &[Point],
    sk: &Skeleton,
    region: &Region,
    face: &FaceTriangles,
    budget: usize,
) -> (ProgramOutcome, ProgramStats) {
    let program = FaceProgram::new(pts, &face.boundary, &face.tris, &face.tri_edges);
    let mut stats = ProgramStats {
        triangles: program.triangles(),
        ..ProgramStats::default()
    };
    // The incumbent: the integer program's triangles, re-checked by the
    // search restricted to them (which finds them only if they triangulate
    // the region), else the constrained Delaunay triangles.
    let checked = program.integer_solution().and_then(|chosen| {
        let mut price = vec![f64::INFINITY; face.tris.len()];
        for t in chosen {
            price[t] = 0.0;
        }
        let only = Prices { price, slack: 0.0 };
        search(pts, sk, region, face, Some(&only), face.tris.len() + 1)
            .0
            .found()
    });
    let (incumbent, incumbent_weight) = match checked {
        Some(s) => (s.triangles, s.value),
        None => {
            let w = inner_edge_weight(pts, &face.boundary, &region.cdt_triangles);
            (region.cdt_triangles.clone(), w)
        }
    };
    let unsolved = |lower| ProgramOutcome::Unsolved {
        incumbent: Some(incumbent.clone()),
        lower,
    };
    let Some(certificate) = program.dual().and_then(|y| program.certify(&y)) else {
        return (unsolved(None), stats);
    };
    let Some(prices) = certificate.prices(incumbent_weight.hi) else {
        return (unsolved(None), stats);
    };
    stats.kept = prices.price.iter().filter(|&&p| p <= prices.slack).count();
    let (solved, fronts) = search(
        pts,
        sk,
        region,
        face,
        Some(&prices),
        budget.min(ROOT_FRONTS),
    );
    stats.fronts = fronts;
    match solved {
        SearchOutcome::Found(solved) => {
            // Consistency: the optimum found is no heavier than the
            // incumbent (exactly); otherwise the incumbent was not a
            // triangulation of that weight and nothing is proven.
            if super::compare_weights(pts, &solved.triangles, &incumbent) == Ordering::Greater {
                return (unsolved(None), stats);
            }
            (ProgramOutcome::Solved(solved.triangles), stats)
        }
        // No triangulation within the slack of a true incumbent: a wrong
        // certificate or incumbent; nothing is proven.
        SearchOutcome::NoTriangulation => (unsolved(None), stats),
        SearchOutcome::OverBudget => {
            let root = Node {
                bound: certificate.lower,
                kept: prices.price.iter().map(|&p| p <= prices.slack).collect(),
                forced: Vec::new(),
                searched: true,
            };
            let best = Incumbent {
                triangles: incumbent,
                weight: incumbent_weight,
            };
            let limits = Limits {
                nodes: budget / FRONTS_PER_NODE,
                node_fronts: NODE_FRONTS,
            };
            branch_and_bound(pts, sk, region, face, root, best, limits, &mut stats)
        }
    }
}

/// Fronts the priced search at the root may memoise before the program
/// branches (at most the budget).
const ROOT_FRONTS: usize = 100_000;

/// Fronts the priced search at a branch-and-bound node may memoise.
const NODE_FRONTS: usize = 20_000;

/// A branch-and-bound node is charged as this many fronts of the budget:
/// the default budget allows 2000 nodes, a budget of one front none (the
/// work is counted, not timed, so the result is deterministic).
const FRONTS_PER_NODE: usize = 200;

/// The work the branch and bound may do.
#[derive(Clone, Copy)]
struct Limits {
    /// Nodes evaluated.
    nodes: usize,
    /// Fronts per node's priced search.
    node_fronts: usize,
}

/// A node of the branch and bound: the triangulations of the face by its
/// kept triangles that contain every forced edge.
struct Node {
    /// Certified lower bound on the inner-edge weight of those
    /// triangulations (the parent's, until the node's own program is
    /// solved).
    bound: f64,
    /// Per triangle of the face: still allowed?
    kept: Vec<bool>,
    /// Edge ids fixed into the triangulation.
    forced: Vec<u32>,
    /// The priced search was already run on it (the root).
    searched: bool,
}

/// The lightest triangulation of the face built so far and its certified
/// inner-edge weight.
struct Incumbent {
    triangles: Vec<[u32; 3]>,
    weight: LengthInterval,
}

/// Branch and bound over the face program, on edges (Kyoda et al. 1997, §3:
/// an edge is in or out; here the triangles crossing an edge that is in,
/// or using an edge that is out, are dropped from the node).
///
/// Each node's bound is the certificate of [`super::face_program`] for the
/// node's program: the face with its forced edges as extra boundary (both
/// half-edges covered once, their lengths a constant added to the bound)
/// over the node's triangles, so it bounds every triangulation of the node,
/// whatever the solver returned. A node is pruned when its certified bound
/// is at least the incumbent's weight (upper end): it holds no strictly
/// lighter triangulation, and on ties the incumbent is kept (the integer
/// program's answer, then the first strictly lighter one found, nodes taken
/// in order of bound, then creation). Otherwise its triangles priced above
/// the slack are dropped (reduced-cost fixing, inherited by the children),
/// the priced exact search runs on the rest within [`NODE_FRONTS`]: when it
/// finishes, the node is decided (its first lightest triangulation within
/// the slack, compared exactly with the incumbent, or none); else the node
/// branches on the inner edge whose LP usage is most fractional, weighted
/// by its length. The face is solved when no node is left; when the node
/// budget runs out, the certified lower bound is the least bound of the
/// open nodes (or the incumbent's).
#[allow(clippy::too_many_arguments)]
fn branch_and_bound(
    pts: &[Point],
    sk: &Skeleton,
    region: &Region,
    face: &FaceTriangles,
    root: Node,
    mut best: Incumbent,
    limits: Limits,
    stats: &mut ProgramStats,
) -> (ProgramOutcome, ProgramStats) {
    let mut nodes: Vec<Node> = vec![root];
    // Open nodes by bound, then creation (a min-heap on both).
    let mut open: BinaryHeap<Reverse<(BoundKey, usize)>> = BinaryHeap::new();
    open.push(Reverse((BoundKey(nodes[0].bound), 0)));
    // Least bound of the nodes given up on (no certificate or no branch).
    let mut abandoned = f64::INFINITY;
    while let Some(Reverse((_, id))) = open.pop() {
        let node = std::mem::replace(
            &mut nodes[id],
            Node {
                bound: 0.0,
                kept: Vec::new(),
                forced: Vec::new(),
                searched: false,
            },
        );
        if node.bound >= best.weight.hi {
            continue; // pruned by a lighter incumbent found since
        }
        if stats.nodes >= limits.nodes {
            abandoned = abandoned.min(node.bound);
            continue;
        }
        stats.nodes += 1;
        match evaluate(pts, sk, region, face, node, &mut best, limits, stats) {
            Evaluated::Closed => {}
            Evaluated::Abandoned(bound) => abandoned = abandoned.min(bound),
            Evaluated::Branch([a, b]) => {
                for child in [a, b] {
                    open.push(Reverse((BoundKey(child.bound), nodes.len())));
                    nodes.push(child);
                }
            }
        }
    }
    let Incumbent { triangles, weight } = best;
    if abandoned == f64::INFINITY {
        return (ProgramOutcome::Solved(triangles), *stats);
    }
    let lower = abandoned.min(weight.lo);
    (
        ProgramOutcome::Unsolved {
            incumbent: Some(triangles),
            lower: Some(lower),
        },
        *stats,
    )
}

/// A certified bound, ordered totally (bounds are finite).
#[derive(Clone, Copy, PartialEq)]
struct BoundKey(f64);

impl Eq for BoundKey {}

impl PartialOrd for BoundKey {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for BoundKey {
    fn cmp(&self, other: &Self) -> Ordering {
        self.0.total_cmp(&other.0)
    }
}

enum Evaluated {
    /// Pruned or decided.
    Closed,
    /// Neither decided nor split: its certified bound stays open.
    Abandoned(f64),
    Branch([Node; 2]),
}

#[allow(clippy::too_many_arguments)]
/// One node of [`branch_and_bound`]: its program, certificate, pruning,
/// priced search, and else its two children.
fn evaluate(
    pts: &[Point],
    sk: &Skeleton,
    region: &Region,
    face: &FaceTriangles,
    node: Node,
    best: &mut Incumbent,
    limits: Limits,
    stats: &mut ProgramStats,
) -> Evaluated {
    let members: Vec<usize> = (0..face.tris.len()).filter(|&t| node.kept[t]).collect();
    let mut boundary = face.boundary.clone();
    let mut forced_length = LengthInterval::ZERO;
    for &e in &node.forced {
        let [u, v] = sk.edges[e as usize];
        boundary.insert((u, v));
        boundary.insert((v, u));
        forced_length =
            forced_length.plus(LengthInterval::of_segment(pts[u as usize], pts[v as usize]));
    }
    let tris: Vec<[u32; 3]> = members.iter().map(|&t| face.tris[t]).collect();
    let tri_edges: Vec<[u32; 3]> = members.iter().map(|&t| face.tri_edges[t]).collect();
    let program = FaceProgram::new(pts, &boundary, &tris, &tri_edges);
    let Some(certificate) = program.dual().and_then(|y| program.certify(&y)) else {
        return Evaluated::Abandoned(node.bound);
    };
    // The forced edges are in every triangulation of the node: their
    // length is a constant of its program's objective.
    let own = (certificate.lower + forced_length.lo).next_down();
    let bound = own.max(node.bound);
    if bound >= best.weight.hi {
        return Evaluated::Closed;
    }
    // Slack W − L rounded up, with the node's own bound (its prices).
    let slack = (best.weight.hi - own).next_up();
    let mut price = vec![f64::INFINITY; face.tris.len()];
    let mut kept = vec![false; face.tris.len()];
    for (i, &t) in members.iter().enumerate() {
        let p = certificate.reduced()[i].max(0.0);
        if p <= slack {
            price[t] = p;
            kept[t] = true;
        }
    }
    if !node.searched {
        let prices = Prices { price, slack };
        let (outcome, fronts) = search(pts, sk, region, face, Some(&prices), limits.node_fronts);
        stats.fronts += fronts;
        match outcome {
            SearchOutcome::Found(found) => {
                if super::compare_weights(pts, &found.triangles, &best.triangles) == Ordering::Less
                {
                    *best = Incumbent {
                        triangles: found.triangles,
                        weight: found.value,
                    };
                }
                return Evaluated::Closed;
            }
            SearchOutcome::NoTriangulation => return Evaluated::Closed,
            SearchOutcome::OverBudget => {}
        }
    }
    let Some(e) = program
        .primal()
        .and_then(|x| branching_edge(pts, sk, &boundary, &members, face, &x))
    else {
        return Evaluated::Abandoned(bound);
    };
    let crossing: HashSet<u32> = sk.crossing(pts, e).iter().copied().collect();
    let mut with = Node {
        bound,
        kept: kept.clone(),
        forced: node.forced.clone(),
        searched: false,
    };
    with.forced.push(e);
    let mut without = Node {
        bound,
        kept,
        forced: node.forced,
        searched: false,
    };
    for (t, ids) in face.tri_edges.iter().enumerate() {
        if ids.iter().any(|f| crossing.contains(f)) {
            with.kept[t] = false;
        }
        if ids.contains(&e) {
            without.kept[t] = false;
        }
    }
    Evaluated::Branch([with, without])
}

/// The inner edge (not boundary, not forced) of the node whose usage in the
/// LP solution `x` (over the node's triangles `members`) is fractional,
/// with the largest `length · min(u, 1 − u)`; ties to the smallest id.
fn branching_edge(
    pts: &[Point],
    sk: &Skeleton,
    boundary: &HashSet<(u32, u32)>,
    members: &[usize],
    face: &FaceTriangles,
    x: &[f64],
) -> Option<u32> {
    let mut usage: HashMap<u32, f64> = HashMap::new();
    for (i, &t) in members.iter().enumerate() {
        let (corners, ids) = (face.tris[t], face.tri_edges[t]);
        for s in 0..3 {
            let (a, b) = (corners[s], corners[(s + 1) % 3]);
            // Each edge counted on one side (left of the lower index).
            if a < b && !boundary.contains(&(a, b)) {
                *usage.entry(ids[s]).or_insert(0.0) += x[i];
            }
        }
    }
    // An integral usage (the relaxation's optimum is a triangulation, the
    // bound short of the incumbent only by rounding or ties): branch on its
    // longest edge instead; the node with the edge forced loses every
    // triangle crossing it, the other loses the edge.
    let integral = usage.values().all(|&u| u.min(1.0 - u) <= FRACTIONAL);
    let mut choice: Option<(f64, u32)> = None;
    for (&e, &u) in &usage {
        let fraction = if integral {
            if u <= 0.5 {
                continue;
            }
            1.0
        } else {
            u.min(1.0 - u)
        };
        if fraction <= FRACTIONAL {
            continue;
        }
        let [a, b] = sk.edges[e as usize];
        let l = LengthInterval::of_segment(pts[a as usize], pts[b as usize]);
        let score = fraction * l.hi;
        let better = match choice {
            None => true,
            Some((s, f)) => score > s || (score == s && e < f),
        };
        if better {
            choice = Some((score, e));
        }
    }
    choice.map(|(_, e)| e)
}

/// LP usages closer than this to 0 or 1 count as integral when choosing a
/// branching edge (a heuristic choice only: any edge is a sound branch).
const FRACTIONAL: f64 = 1e-6;

/// Certified weight of the edges of `triangles` that are not on the
/// boundary (`boundary`: half-edges).
fn inner_edge_weight(
    pts: &[Point],
    boundary: &HashSet<(u32, u32)>,
    triangles: &[[u32; 3]],
) -> LengthInterval {
    super::edges_of(triangles)
        .into_iter()
        .filter(|&[a, b]| !boundary.contains(&(a, b)) && !boundary.contains(&(b, a)))
        .fold(LengthInterval::ZERO, |s, [a, b]| {
            s.plus(LengthInterval::of_segment(pts[a as usize], pts[b as usize]))
        })
}

/// Is the candidate edge `u → w` inside the region at `u`?
fn leaves_into(
    pts: &[Point],
    corners_at: &HashMap<u32, Vec<Corner>>,
    inner: &HashSet<u32>,
    u: u32,
    w: u32,
) -> bool {
    inner.contains(&u)
        || corners_at
            .get(&u)
            .is_some_and(|cs| cs.iter().any(|c| c.contains_direction(pts, w)))
}

fn lower_bound(
    pts: &[Point],
    sk: &Skeleton,
    region: &Region,
    corners_at: &HashMap<u32, Vec<Corner>>,
    inner: &HashSet<u32>,
) -> f64 {
    let vertices: HashSet<u32> = region
        .cycles
        .iter()
        .flatten()
        .copied()
        .chain(region.inner.iter().copied())
        .collect();
    let half_edges: usize = region.cycles.iter().map(Vec::len).sum();
    let mut boundary: HashSet<[u32; 2]> = HashSet::new();
    for c in &region.cycles {
        for i in 0..c.len() {
            let (a, b) = (c[i], c[(i + 1) % c.len()]);
            boundary.insert([a.min(b), a.max(b)]);
        }
    }
    let h = region.cycles.len() as i64 - 1;
    let needed = 3 * (vertices.len() as i64 - 1 + h - boundary.len() as i64) + half_edges as i64;
    let mut lengths: Vec<f64> = Vec::new();
    for (e, &[u, v]) in sk.edges.iter().enumerate() {
        if sk.alive[e]
            && !sk.certain[e]
            && vertices.contains(&u)
            && vertices.contains(&v)
            && leaves_into(pts, corners_at, inner, u, v)
            && leaves_into(pts, corners_at, inner, v, u)
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

/// Klincsek's program on a simple region (one boundary walk, no inner
/// point), over the candidate diagonals inside it.
fn solve_polygon(
    pts: &[Point],
    sk: &Skeleton,
    cycle: &[u32],
    limit: usize,
) -> Option<Vec<[u32; 3]>> {
    let k = cycle.len();
    if k > limit {
        return None; // O(k²) tables: the region keeps its fallback
    }
    let corner = |i: usize| Corner {
        prev: cycle[(i + k - 1) % k],
        v: cycle[i],
        next: cycle[(i + 1) % k],
    };
    let p = |i: usize| pts[cycle[i] as usize];
    let solved = optimal_triangulation(
        k,
        |i, j| {
            let (u, w) = (cycle[i], cycle[j]);
            u != w
                && sk.edge_id(u, w).is_some_and(|e| sk.alive[e as usize])
                && corner(i).contains_direction(pts, w)
                && corner(j).contains_direction(pts, u)
        },
        |i, m, j| orient_sign(p(i), p(m), p(j)) != 0,
        &TotalLength { point: &p },
    )?;
    Some(
        solved
            .triangles
            .into_iter()
            .map(|t| {
                let t = t.map(|c| cycle[c]);
                if orient_sign(pts[t[0] as usize], pts[t[1] as usize], pts[t[2] as usize]) > 0 {
                    t
                } else {
                    [t[0], t[2], t[1]]
                }
            })
            .collect(),
    )
}

/// A region's empty candidate triangles (counter-clockwise, in the
/// skeleton's order) with their edge ids, and its boundary half-edges.
/// Triangles with a half-edge on the outer side of the boundary (the
/// reverse of a boundary half-edge that does not dangle) are left out: the
/// search could never place them.
pub(super) struct FaceTriangles {
    pub tris: Vec<[u32; 3]>,
    pub tri_edges: Vec<[u32; 3]>,
    /// The boundary half-edges, the region on their left.
    pub boundary: HashSet<(u32, u32)>,
}

fn face_triangles(
    pts: &[Point],
    sk: &Skeleton,
    region: &Region,
    corners_at: &HashMap<u32, Vec<Corner>>,
    inner: &HashSet<u32>,
) -> FaceTriangles {
    let vertices: HashSet<u32> = region
        .cycles
        .iter()
        .flatten()
        .copied()
        .chain(region.inner.iter().copied())
        .collect();
    let boundary: HashSet<(u32, u32)> = region
        .cycles
        .iter()
        .flat_map(|c| (0..c.len()).map(move |i| (c[i], c[(i + 1) % c.len()])))
        .collect();
    let outside = |h: (u32, u32)| {
        let reverse = (h.1, h.0);
        boundary.contains(&reverse) && !boundary.contains(&h)
    };
    let in_region = |t: [u32; 3]| {
        let [a, b, c] = t;
        if inner.contains(&a) {
            return true;
        }
        corners_at
            .get(&a)
            .is_some_and(|cs| cs.iter().any(|co| co.contains_sweep(pts, b, c)))
    };
    let mut tris = Vec::new();
    let mut tri_edges = Vec::new();
    for (corners, ids) in &sk.triangles {
        if !corners.iter().all(|v| vertices.contains(v))
            || !ids.iter().all(|&e| sk.alive[e as usize])
            || !in_region(*corners)
            || (0..3).any(|s| outside((corners[s], corners[(s + 1) % 3])))
        {
            continue;
        }
        tris.push(*corners);
        tri_edges.push(*ids);
    }
    FaceTriangles {
        tris,
        tri_edges,
        boundary,
    }
}

/// A region solved by the search: its triangles and the certified weight
/// of their inner edges.
struct Searched {
    triangles: Vec<[u32; 3]>,
    value: LengthInterval,
}

/// What the search decided.
enum SearchOutcome {
    /// The first lightest triangulation within the slack.
    Found(Searched),
    /// Every completion was explored: none within the slack (or none at
    /// all).
    NoTriangulation,
    /// The budget ran out: nothing is known.
    OverBudget,
}

impl SearchOutcome {
    fn found(self) -> Option<Searched> {
        match self {
            SearchOutcome::Found(s) => Some(s),
            _ => None,
        }
    }
}

/// The exact search over fronts (module docs), on the triangles of `face`,
/// skipping every partial triangulation whose `prices` exceed their slack.
/// `None` when the budget ran out (or no triangulation exists, which the
/// skeleton's soundness rules out for the whole face, and which prices may
/// cause). With the certificate's prices (excess reduced costs) and slack
/// `W − L`, no triangulation of weight at most `W` is skipped
/// ([`super::face_program`]).
///
/// With prices, a front's best completion depends on the slack left to it:
/// each memoised front keeps the slack it was solved with (`+∞` if no
/// completion was skipped for its price) and is solved again for a larger
/// one. A completion found under slack `s` is the first lightest among
/// those within `s`, so on the path of the first lightest triangulation
/// within the root slack every front is answered as without prices: the
/// search returns the same triangulation as the unpriced search whenever
/// that one is within the slack (ties broken alike).
fn search(
    pts: &[Point],
    sk: &Skeleton,
    region: &Region,
    face: &FaceTriangles,
    prices: Option<&Prices>,
    budget: usize,
) -> (SearchOutcome, usize) {
    let (tris, tri_edges) = (&face.tris, &face.tri_edges);
    let slack = prices.map_or(f64::INFINITY, |p| p.slack);
    let price = |t: usize| prices.map_or(0.0, |p| p.price[t]);
    let mut by_half_edge: HashMap<(u32, u32), Vec<u32>> = HashMap::new();
    for (t, corners) in tris.iter().enumerate() {
        if price(t) > slack {
            continue;
        }
        for s in 0..3 {
            by_half_edge
                .entry((corners[s], corners[(s + 1) % 3]))
                .or_default()
                .push(t as u32);
        }
    }
    let mut state = SearchState {
        pts,
        sk,
        tris,
        tri_edges,
        price: prices.map(|p| p.price.as_slice()),
        by_half_edge: &by_half_edge,
        front: BTreeSet::new(),
        filled: HashSet::new(),
        placed: HashMap::new(),
        blocked: HashMap::new(),
        memo: HashMap::new(),
        over_budget: false,
        computed: 0,
        budget,
    };
    let mut boundary_edges = BTreeSet::new();
    for cycle in &region.cycles {
        let k = cycle.len();
        for i in 0..k {
            let (a, b) = (cycle[i], cycle[(i + 1) % k]);
            state.front.insert((a, b));
            if let Some(e) = sk.edge_id(a, b) {
                boundary_edges.insert(e);
            }
        }
    }
    // The far side of a boundary half-edge is outside, unless the edge
    // dangles into the region (walked both ways).
    let outside: Vec<(u32, u32)> = state
        .front
        .iter()
        .map(|&(a, b)| (b, a))
        .filter(|h| !state.front.contains(h))
        .collect();
    state.filled.extend(outside);
    for e in boundary_edges {
        state.place(e);
    }
    let (best, _) = state.solve(slack);
    let fronts = state.computed;
    if state.over_budget {
        return (SearchOutcome::OverBudget, fronts);
    }
    let Some(best) = best else {
        return (SearchOutcome::NoTriangulation, fronts);
    };
    // Rebuild the triangles by replaying the memoised choices.
    let mut triangles = Vec::new();
    let mut front: BTreeSet<(u32, u32)> = region
        .cycles
        .iter()
        .flat_map(|c| (0..c.len()).map(move |i| (c[i], c[(i + 1) % c.len()])))
        .collect();
    while !front.is_empty() {
        let key: Vec<(u32, u32)> = front.iter().copied().collect();
        let Some((_, Some(entry))) = state.memo.get(&key) else {
            // Unreachable: every front on the best path was memoised.
            return (SearchOutcome::OverBudget, fronts);
        };
        let t = tris[entry.triangle as usize];
        triangles.push(t);
        for s in 0..3 {
            let h = (t[s], t[(s + 1) % 3]);
            if !front.remove(&h) {
                front.insert((h.1, h.0));
            }
        }
    }
    (
        SearchOutcome::Found(Searched {
            triangles,
            value: best.value,
        }),
        fronts,
    )
}

#[derive(Clone)]
struct Best {
    value: LengthInterval,
    /// The inner edges of the completion (edge ids).
    edges: Vec<u32>,
    triangle: u32,
}

/// A front's memo entry: the slack it was solved with and its best
/// completion.
type FrontMemo = (f64, Option<Best>);

struct SearchState<'a> {
    pts: &'a [Point],
    sk: &'a Skeleton,
    tris: &'a [[u32; 3]],
    tri_edges: &'a [[u32; 3]],
    by_half_edge: &'a HashMap<(u32, u32), Vec<u32>>,
    front: BTreeSet<(u32, u32)>,
    filled: HashSet<(u32, u32)>,
    placed: HashMap<u32, ()>,
    blocked: HashMap<u32, u32>,
    /// Per triangle, its price ([`Prices`]).
    price: Option<&'a [f64]>,
    /// Per front: the slack it was solved with and its best completion.
    memo: HashMap<Vec<(u32, u32)>, FrontMemo>,
    over_budget: bool,
    /// Fronts solved (a front solved again for a larger slack counts again).
    computed: usize,
    budget: usize,
}

impl SearchState<'_> {
    fn place(&mut self, e: u32) {
        self.placed.insert(e, ());
        for &f in self.sk.crossing(self.pts, e) {
            *self.blocked.entry(f).or_insert(0) += 1;
        }
    }

    fn unplace(&mut self, e: u32) {
        self.placed.remove(&e);
        for &f in self.sk.crossing(self.pts, e) {
            *self.blocked.get_mut(&f).unwrap() -= 1;
        }
    }

    fn length(&self, e: u32) -> LengthInterval {
        let [u, v] = self.sk.edges[e as usize];
        LengthInterval::of_segment(self.pts[u as usize], self.pts[v as usize])
    }

    fn segments(&self, edges: &[u32]) -> Vec<[Point; 2]> {
        edges
            .iter()
            .map(|&e| {
                let [u, v] = self.sk.edges[e as usize];
                [self.pts[u as usize], self.pts[v as usize]]
            })
            .collect()
    }

    /// Is completion `a` strictly lighter than `b`? Exact.
    fn lighter(&self, a: &Best, b: &Best) -> bool {
        match a.value.certainly_compare(b.value) {
            Some(o) => o == Ordering::Less,
            None => {
                let (mut x, mut y) = (a.edges.clone(), b.edges.clone());
                x.sort_unstable();
                y.sort_unstable();
                let common: Vec<u32> = x
                    .iter()
                    .filter(|e| y.binary_search(e).is_ok())
                    .copied()
                    .collect();
                x.retain(|e| common.binary_search(e).is_err());
                y.retain(|e| common.binary_search(e).is_err());
                compare_length_sums(&self.segments(&x), &self.segments(&y)) == Ordering::Less
            }
        }
    }

    /// The first lightest completion of the front whose prices add up to at
    /// most `slack`, and whether no completion was skipped for its price
    /// (the answer then holds for every slack).
    fn solve(&mut self, slack: f64) -> (Option<Best>, bool) {
        let Some(&first) = self.front.iter().next() else {
            let done = Best {
                value: LengthInterval::ZERO,
                edges: Vec::new(),
                triangle: u32::MAX,
            };
            return (Some(done), true);
        };
        let key: Vec<(u32, u32)> = self.front.iter().copied().collect();
        if let Some((solved_with, known)) = self.memo.get(&key) {
            // Solved with at least this slack: every completion within it
            // was considered.
            if *solved_with >= slack {
                return (known.clone(), *solved_with == f64::INFINITY);
            }
        }
        if self.computed >= self.budget {
            self.over_budget = true;
            return (None, false);
        }
        self.computed += 1;
        let mut complete = true;
        let mut best: Option<Best> = None;
        let options: Vec<u32> = self.by_half_edge.get(&first).cloned().unwrap_or_default();
        'triangles: for t in options {
            let corners = self.tris[t as usize];
            let ids = self.tri_edges[t as usize];
            let halves = [0, 1, 2].map(|s| (corners[s], corners[(s + 1) % 3]));
            for (s, h) in halves.iter().enumerate() {
                let e = ids[s];
                if self.filled.contains(h) {
                    continue 'triangles;
                }
                if !self.placed.contains_key(&e) && self.blocked.get(&e).copied().unwrap_or(0) > 0 {
                    continue 'triangles;
                }
            }
            let price = self.price.map_or(0.0, |p| p[t as usize]);
            if price > slack {
                complete = false;
                continue;
            }
            // Rounded up: the true slack left is never underestimated.
            let rest = if slack == f64::INFINITY {
                slack
            } else {
                (slack - price).next_up()
            };
            // Apply.
            let mut new_edges = Vec::new();
            let mut removed = Vec::new();
            let mut added = Vec::new();
            for (s, &h) in halves.iter().enumerate() {
                let e = ids[s];
                if !self.placed.contains_key(&e) {
                    self.place(e);
                    new_edges.push(e);
                }
                self.filled.insert(h);
                if self.front.remove(&h) {
                    removed.push(h);
                } else {
                    self.front.insert((h.1, h.0));
                    added.push((h.1, h.0));
                }
            }
            let (sub, sub_complete) = self.solve(rest);
            complete &= sub_complete;
            // Undo.
            for h in &added {
                self.front.remove(h);
            }
            for h in &removed {
                self.front.insert(*h);
            }
            for h in &halves {
                self.filled.remove(h);
            }
            for &e in &new_edges {
                self.unplace(e);
            }
            if self.over_budget {
                return (None, false);
            }
            if let Some(sub) = sub {
                let mut value = sub.value;
                for &e in &new_edges {
                    value = value.plus(self.length(e));
                }
                let mut edges = sub.edges;
                edges.extend_from_slice(&new_edges);
                let candidate = Best {
                    value,
                    edges,
                    triangle: t,
                };
                if best.as_ref().is_none_or(|b| self.lighter(&candidate, b)) {
                    best = Some(candidate);
                }
            }
        }
        let solved_with = if complete { f64::INFINITY } else { slack };
        self.memo.insert(key, (solved_with, best.clone()));
        (best, complete)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

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

    /// The faces traced from the certain edges are exactly the constrained
    /// Delaunay regions (same walks, same starts), and they are traced
    /// exactly when every region is simple: on random, clustered, grid,
    /// lattice (collinear runs, cocircular quadruples) and wheel sets, with
    /// both outcomes met.
    #[test]
    fn traced_faces_are_the_constrained_delaunay_regions() {
        use optri_oracle::inputs;
        use rand::{rngs::StdRng, SeedableRng};
        let mut rng = StdRng::seed_from_u64(21);
        let mut sets: Vec<Vec<Point>> = vec![
            inputs::uniform_unit_square(&mut rng, 2000),
            inputs::clustered(&mut rng, 1500, 12),
            inputs::shuffled_grid(&mut rng, 30, 30, 1.0),
            inputs::grid_subset(&mut rng, 40, 40, 0.5),
            inputs::distinct_lattice_points(&mut rng, 600, -20i64..20, -20i64..20),
            inputs::uniform_in_square(&mut rng, 1000, 1e12),
        ];
        for k in [13, 15, 17] {
            sets.push(ring_with(k, [0.0, 0.0]));
        }
        let (mut traced, mut general) = (0, 0);
        for pts in &sets {
            let candidates = super::super::skeleton::diamond_candidates(pts);
            let sk = super::super::skeleton::lmt_skeleton(pts, candidates).unwrap();
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

    /// A simple face too large for Klincsek's program (the limit lowered to
    /// five corners) sends every face the general way: its fallback is the
    /// constrained Delaunay triangles, so the faces still triangulate the
    /// hull, and the larger faces are reported unsolved.
    #[test]
    fn a_face_beyond_the_program_limit_takes_the_general_way() {
        use optri_oracle::inputs;
        use rand::{rngs::StdRng, SeedableRng};
        let mut rng = StdRng::seed_from_u64(5);
        let pts = inputs::uniform_unit_square(&mut rng, 400);
        let candidates = super::super::skeleton::diamond_candidates(&pts);
        let sk = super::super::skeleton::lmt_skeleton(&pts, candidates).unwrap();
        assert!(traced_faces(&pts, &sk).is_some());
        let results = solve_regions_within(&pts, &sk, FRONT_BUDGET, 5).unwrap();
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
        let usual = solve_regions(&pts, &sk, FRONT_BUDGET).unwrap();
        assert!(usual.iter().all(|r| r.method != Method::Fallback));
        assert_eq!(usual.len(), results.len());
    }

    /// Every face with an inner point of three small wheels (13 and 17 rim
    /// points around the origin, 15 around `(3, −7)`), with the plain
    /// search's optimum of the face.
    fn for_each_wheel_face(
        mut visit: impl FnMut(usize, &[Point], &Skeleton, &Region, &FaceTriangles, Searched),
    ) {
        for (k, centre) in [(13, [0.0, 0.0]), (15, [3.0, -7.0]), (17, [0.0, 0.0])] {
            let pts = ring_with(k, centre);
            let candidates = super::super::skeleton::diamond_candidates(&pts);
            let sk = super::super::skeleton::lmt_skeleton(&pts, candidates).unwrap();
            for region in regions(&pts, &sk).unwrap() {
                if region.inner.is_empty() {
                    continue;
                }
                let corners_at = corners_of(&region);
                let inner: HashSet<u32> = region.inner.iter().copied().collect();
                let face = face_triangles(&pts, &sk, &region, &corners_at, &inner);
                let reference = search(&pts, &sk, &region, &face, None, FRONT_BUDGET)
                    .0
                    .found()
                    .expect("the plain search decides small wheels");
                visit(k, &pts, &sk, &region, &face, reference);
            }
        }
    }

    /// The branch and bound started from a poor incumbent (the constrained
    /// Delaunay triangles), with node searches too small to finish until
    /// enough edges are fixed, must branch and still return a triangulation
    /// exactly as light as the plain search's optimum. A bound rounded the
    /// wrong way or pruning on a bound below the incumbent (a strictly
    /// lighter triangulation discarded) breaks this.
    #[test]
    fn branch_and_bound_from_a_poor_incumbent_reaches_the_optimum() {
        let mut branched = 0;
        let mut faces = 0;
        for_each_wheel_face(|k, pts, sk, region, face, reference| {
            let program = FaceProgram::new(pts, &face.boundary, &face.tris, &face.tri_edges);
            let weight = inner_edge_weight(pts, &face.boundary, &region.cdt_triangles);
            let certificate = program.dual().and_then(|y| program.certify(&y)).unwrap();
            let prices = certificate.prices(weight.hi).unwrap();
            let root = Node {
                bound: certificate.lower,
                kept: prices.price.iter().map(|&p| p <= prices.slack).collect(),
                forced: Vec::new(),
                searched: false,
            };
            let best = Incumbent {
                triangles: region.cdt_triangles.clone(),
                weight,
            };
            let limits = Limits {
                nodes: 5_000,
                node_fronts: 40,
            };
            let mut stats = ProgramStats::default();
            let (outcome, _) =
                branch_and_bound(pts, sk, region, face, root, best, limits, &mut stats);
            let ProgramOutcome::Solved(t) = outcome else {
                panic!("wheel {k}: not solved in {} nodes", stats.nodes);
            };
            assert_eq!(
                super::super::compare_weights(pts, &t, &reference.triangles),
                Ordering::Equal,
                "wheel {k}: branch and bound and plain search differ"
            );
            faces += 1;
            branched += usize::from(stats.nodes > 1);
        });
        assert!(faces >= 3, "only {faces} faces with an inner point");
        assert!(branched >= 2, "only {branched} faces branched");
    }

    /// A node with every inner edge of an optimum forced has only the
    /// optimum's triangles left, so its certified bound must enclose the
    /// optimum's inner weight from below, tightly: the forced edges' length
    /// is counted exactly once (counting it twice or not at all fails).
    #[test]
    fn a_node_with_the_optimum_forced_is_bounded_by_its_weight() {
        let mut checked = 0;
        for_each_wheel_face(|k, pts, sk, region, face, reference| {
            let optimum = inner_edge_weight(pts, &face.boundary, &reference.triangles);
            let forced: Vec<u32> = super::super::edges_of(&reference.triangles)
                .into_iter()
                .filter(|&[a, b]| {
                    !face.boundary.contains(&(a, b)) && !face.boundary.contains(&(b, a))
                })
                .map(|[a, b]| sk.edge_id(a, b).expect("an optimum edge is a candidate"))
                .collect();
            assert!(!forced.is_empty(), "wheel {k}: no inner edge");
            let crossing: HashSet<u32> = forced
                .iter()
                .flat_map(|&e| sk.crossing(pts, e).iter().copied())
                .collect();
            let node = Node {
                bound: 0.0,
                kept: face
                    .tri_edges
                    .iter()
                    .map(|ids| !ids.iter().any(|f| crossing.contains(f)))
                    .collect(),
                forced,
                searched: true,
            };
            // An incumbent a little heavier than the optimum: a correct
            // bound stays below it, so the node is neither pruned nor
            // split (every inner edge is forced) and returns its bound.
            let heavier = optimum.hi * (1.0 + 1e-6);
            let mut best = Incumbent {
                triangles: region.cdt_triangles.clone(),
                weight: LengthInterval {
                    lo: heavier,
                    hi: heavier,
                },
            };
            let limits = Limits {
                nodes: 10,
                node_fronts: 40,
            };
            let mut stats = ProgramStats::default();
            let outcome = evaluate(pts, sk, region, face, node, &mut best, limits, &mut stats);
            let Evaluated::Abandoned(bound) = outcome else {
                panic!("wheel {k}: the node was pruned or split");
            };
            assert!(
                bound <= optimum.hi,
                "wheel {k}: bound {bound} above {optimum:?}"
            );
            assert!(
                bound >= optimum.lo * (1.0 - 1e-9),
                "wheel {k}: bound {bound} far below {optimum:?}"
            );
            checked += 1;
        });
        assert!(checked >= 3, "only {checked} faces checked");
    }
}
