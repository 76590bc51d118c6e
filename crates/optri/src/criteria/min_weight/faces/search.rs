//! The exact search over fronts (module docs of `faces`) on a region's
//! empty candidate triangles, optionally priced by the triangle program's
//! certificate.

use super::super::face_program::Prices;
use super::super::skeleton::Skeleton;
use super::{FaceView, Region};
use crate::kernel::{compare_length_sums, LengthInterval, Point};
use std::cmp::Ordering;
use std::collections::{BTreeSet, HashMap, HashSet};

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

pub(super) fn face_triangles(sk: &Skeleton, view: &FaceView) -> FaceTriangles {
    let boundary = &view.boundary;
    let outside = |h: (u32, u32)| {
        let reverse = (h.1, h.0);
        boundary.contains(&reverse) && !boundary.contains(&h)
    };
    let mut tris = Vec::new();
    let mut tri_edges = Vec::new();
    for (corners, ids) in &sk.triangles {
        if !corners.iter().all(|v| view.vertices.contains(v))
            || !ids.iter().all(|&e| sk.alive[e as usize])
            || !view.contains_triangle_at(*corners)
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
        boundary: boundary.clone(),
    }
}

/// A region solved by the search: its triangles and the certified weight
/// of their inner edges.
pub(super) struct Searched {
    pub(super) triangles: Vec<[u32; 3]>,
    pub(super) value: LengthInterval,
}

/// What the search decided.
pub(super) enum SearchOutcome {
    /// The first lightest triangulation within the slack.
    Found(Searched),
    /// Every completion was explored: none within the slack (or none at
    /// all).
    NoTriangulation,
    /// The budget ran out: nothing is known.
    OverBudget,
}

impl SearchOutcome {
    pub(super) fn found(self) -> Option<Searched> {
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
pub(super) fn search(
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
