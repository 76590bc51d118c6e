//! The triangle program of a region (module docs of
//! `face_program`): its certified bound prices the exact search, and when
//! the priced search runs out, a certified branch and bound on edges
//! (Kyoda, Imai, Takeuchi and Tajima 1997, §3) decides the region.

use super::super::face_program::{FaceProgram, Prices};
use super::super::skeleton::Skeleton;
use super::search::{search, FaceTriangles, SearchOutcome};
use super::{ProgramStats, Region};
use crate::kernel::{LengthInterval, Point};
use std::cmp::Ordering;
use std::cmp::Reverse;
use std::collections::{BinaryHeap, HashMap, HashSet};

pub(super) enum ProgramOutcome {
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
pub(super) fn solve_by_program(
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
            if super::super::compare_weights(pts, &solved.triangles, &incumbent)
                == Ordering::Greater
            {
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
                if super::super::compare_weights(pts, &found.triangles, &best.triangles)
                    == Ordering::Less
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
    super::super::edges_of(triangles)
        .into_iter()
        .filter(|&[a, b]| !boundary.contains(&(a, b)) && !boundary.contains(&(b, a)))
        .fold(LengthInterval::ZERO, |s, [a, b]| {
            s.plus(LengthInterval::of_segment(pts[a as usize], pts[b as usize]))
        })
}

#[cfg(test)]
mod tests {
    use super::super::search::{face_triangles, Searched};
    use super::super::{FaceView, FRONT_BUDGET};
    use super::*;

    /// Every face with an inner point of three small wheels (13 and 17 rim
    /// points around the origin, 15 around `(3, −7)`), with the plain
    /// search's optimum of the face.
    fn for_each_wheel_face(
        mut visit: impl FnMut(usize, &[Point], &Skeleton, &Region, &FaceTriangles, Searched),
    ) {
        for (k, centre) in [(13, [0.0, 0.0]), (15, [3.0, -7.0]), (17, [0.0, 0.0])] {
            let pts = super::super::ring_with(k, centre);
            let candidates = super::super::super::skeleton::diamond_candidates(&pts);
            let sk = super::super::super::skeleton::lmt_skeleton(&pts, candidates).unwrap();
            for region in super::super::regions::regions(&pts, &sk).unwrap() {
                if region.inner.is_empty() {
                    continue;
                }
                let face = face_triangles(&sk, &FaceView::new(&pts, &region));
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
                super::super::super::compare_weights(pts, &t, &reference.triangles),
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
            let forced: Vec<u32> = super::super::super::edges_of(&reference.triangles)
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
