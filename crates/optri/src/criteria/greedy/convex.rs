//! GT of points in convex position by shortest-diagonal splitting: Thm 4.2
//! (and Corollary 4.1 for convex point sets) of C. Levcopoulos & A. Lingas,
//! *On approximation behavior of the greedy triangulation for convex
//! polygons*, Algorithmica 2 (1987), extended to *weakly* convex position.
//!
//! # Weakly convex position
//! The points are all on the boundary of their convex hull, some possibly on
//! the interior of a hull edge; `P` is the polygon of all of them in hull
//! order, with straight angles at those. A segment `uv` between two points
//! on one hull edge passes through the points between them (or is a side of
//! `P`), so GT never adds it; any other segment between two points has its
//! open interior inside the open polygon (a point of it on the boundary lies
//! on a supporting line through an edge, which then holds `u` and `v`), so
//! it contains no point and is a *diagonal* of `P`. GT therefore adds every
//! side of `P` and, among diagonals, runs the greedy process on `P`: the
//! first diagonal it adds is the shortest one, `d`; every later segment
//! crossing `d` is rejected, the others lie in one of the two parts, and two
//! segments of different parts never cross. So GT is the recursive splitting
//! below; a part is again weakly convex (its angles at `d`'s ends are
//! smaller than in `P`), and a pair of its vertices on one of its edges was
//! already on one edge of `P`. Levcopoulos & Lingas's argument needs nothing
//! else: only that every candidate is a diagonal inside the polygon.
//!
//! `Greedy(P)`: find a shortest diagonal of `P`, split along it, recurse.
//! The subpolygons are independent, so the recursion can take them in any
//! order; here a global heap pops the shortest candidate of *all* current
//! subpolygons, which is the shortest diagonal of its own subpolygon.
//!
//! # Candidates
//! Let `e = uv` be the shortest diagonal of a convex polygon `Q`.
//! * If one side of `e` holds a single vertex, `e` cuts off an ear: it is one
//!   of the `|Q|` ear diagonals `v_{i-1} v_{i+1}`.
//!   It is a diagonal unless the ear vertex has a straight angle or every
//!   other vertex lies on the segment `v_{i-1} v_{i+1}`; both are tested
//!   when the ear is popped.
//! * Otherwise no vertex `z` lies in the closed disc with diameter `uv`: such
//!   a `z` has `|uz|, |zv| < |uv|` (angle `uzv ≥ 90°`), and since its side has
//!   two or more vertices, `z` is not adjacent to both `u` and `v`, say not
//!   to `u`. If `uz` is a diagonal it is shorter than `e`. If not, `u` and
//!   `z` are on one edge of `Q`; the neighbour `z'` of `u` on the way to `z`
//!   lies on the segment `uz`, hence in the disc, and is not adjacent to
//!   `v` (`z ≠ z'` is on its side), and `z'v` is a diagonal (`z'` has a
//!   straight angle, so its only edge line is the one through `u`, which
//!   does not hold `v`: `e` is a diagonal), shorter than `e`. Either way
//!   `e` was not the shortest. An edge with an empty closed diametral disc
//!   belongs to *every* Delaunay triangulation of `Q`'s vertices, so `e` is a
//!   diagonal of the Delaunay triangulation of `Q`, whatever completion it
//!   picks for cocircular points.
//!
//! So the heap holds every ear diagonal and every Delaunay diagonal of every
//! current subpolygon (stale entries are skipped when popped).
//! With straight angles the Delaunay triangulation of `Q`'s vertices has no
//! flat triangle, so each of its edges is a side or a diagonal of `Q`.
//!
//! # One Delaunay triangulation, maintained
//! The previous version rebuilt the Delaunay triangulation of every
//! subpolygon (Chew's algorithm, expected O(|Q|)): Θ(n²) exact in-circle
//! tests in all, and on (nearly) cocircular points each of them needs the
//! full expansion arithmetic (about 3 µs), which made 10⁴ points on a circle
//! take minutes. Here one triangulation `D` of `P` is kept whose restriction
//! to every current subpolygon is a Delaunay triangulation of that
//! subpolygon's vertices:
//! * at the start `D` is a Delaunay triangulation of `P`
//!   ([`convex_delaunay`](super::convex_delaunay), Chew's algorithm);
//! * splitting along a diagonal of `D` keeps `D`: each triangle's open
//!   circumcircle holds no vertex of `Q`, hence none of a part;
//! * cutting off an ear `v` along `ab` (not a diagonal of `D` when `v` has
//!   `D`-edges between `a` and `b`) deletes those edges and re-triangulates the
//!   hole, the convex polygon `a, w_1, …, w_m, b` of `v`'s neighbours, by its
//!   own Delaunay triangulation. The new edges are locally Delaunay inside the
//!   hole; a hole side `w_i w_{i+1}` keeps its outer triangle, whose open
//!   circumcircle held no vertex of `Q` (in particular not the new opposite
//!   vertex), and local Delaunayhood is symmetric; an everywhere locally
//!   Delaunay triangulation is Delaunay (also for cocircular points, in the
//!   closed-disc sense used above).
//!
//! # Cost
//! In-circle tests: expected O(n) for the initial triangulation plus
//! expected O(m) per ear whose vertex has `m` inner `D`-edges, at most the
//! `D`-degree of the cut vertex; length comparisons: O(log n) per heap entry,
//! and entries are created O(1) per split plus one per new `D`-edge. The
//! adjacency lists are sorted vectors (insertion O(degree)). On every input
//! measured (BENCHMARKS.md) this is near-linear; the worst case
//! stays within the expected O(n²) of Thm 4.2, since the `D`-degrees of the cut
//! vertices sum to O(n²). Space is O(n) plus the heap.

use super::convex_delaunay::ConvexDelaunay;
use crate::error::Result;
use crate::interrupt::Stop;
use crate::kernel::{compare_lengths_symbolic, orient_sign, Point, SquaredLength};
use std::cmp::Ordering;

/// The apex of a heap entry that is a `D`-edge, not an ear diagonal.
const NO_APEX: u32 = u32::MAX;

/// GT edges (hull edges and diagonals) of the convex polygon `polygon` (ccw
/// indices into `points`, not all collinear). With `straight_angles`, some
/// vertices may lie on the segment between their neighbours (weakly convex
/// position); without, the polygon must be strictly convex.
/// [`crate::Error::Interrupted`] when `stop` says so (checked every 1024
/// heap entries).
pub(super) fn greedy_convex(
    points: &[Point],
    polygon: &[u32],
    straight_angles: bool,
    stop: &Stop,
) -> Result<Vec<[u32; 2]>> {
    let k = polygon.len();
    let mut edges: Vec<[u32; 2]> = (0..k).map(|i| [polygon[i], polygon[(i + 1) % k]]).collect();
    if k <= 3 {
        return Ok(edges);
    }
    let mut state = Splitting::new(points, polygon, straight_angles);
    let mut popped = 0usize;
    while edges.len() < 2 * k - 3 {
        if popped.is_multiple_of(1024) {
            stop.check()?;
        }
        popped += 1;
        let Some(c) = state.pop() else {
            break;
        };
        if let Some([a, b]) = state.take(c) {
            edges.push([polygon[a as usize], polygon[b as usize]]);
        }
    }
    debug_assert_eq!(edges.len(), 2 * k - 3, "a convex GT has 2k - 3 edges");
    Ok(edges)
}

/// A neighbour in an adjacency list: its polygon position and whether the
/// edge is a polygon side or a GT diagonal already chosen (a *constraint*)
/// rather than an edge of `D` only.
#[derive(Clone, Copy, Debug)]
struct Neighbour {
    at: u32,
    constraint: bool,
}

/// A heap entry: the segment `ab` (polygon positions) with its certified
/// double-double squared length; `apex` is the ear vertex for an ear
/// diagonal, else [`NO_APEX`].
#[derive(Clone, Copy, Debug)]
struct Candidate {
    key: SquaredLength,
    a: u32,
    b: u32,
    apex: u32,
}

/// The state of the splitting: the triangulation `D` (with its constraints)
/// as adjacency lists, and the candidate heap.
struct Splitting<'a> {
    points: &'a [Point],
    polygon: &'a [u32],
    /// Per position `v`: neighbours sorted counter-clockwise, i.e. by
    /// `(w - v) mod k` (the polygon is convex and ccw). The polygon sides
    /// `v + 1` and `v - 1` are constraints, first and last.
    adjacency: Vec<Vec<Neighbour>>,
    /// Binary min-heap in the exact segment order.
    heap: Vec<Candidate>,
    scratch: ConvexDelaunay,
    hole: Vec<u32>,
    /// May the polygon have straight-angle vertices (weakly convex)?
    straight_angles: bool,
}

impl<'a> Splitting<'a> {
    fn new(points: &'a [Point], polygon: &'a [u32], straight_angles: bool) -> Self {
        let k = polygon.len();
        let mut scratch = ConvexDelaunay::new();
        scratch.triangulate(points, polygon, straight_angles);
        let mut adjacency: Vec<Vec<Neighbour>> = (0..k)
            .map(|v| {
                vec![
                    Neighbour {
                        at: ((v + 1) % k) as u32,
                        constraint: true,
                    },
                    Neighbour {
                        at: ((v + k - 1) % k) as u32,
                        constraint: true,
                    },
                ]
            })
            .collect();
        let diagonals: Vec<[u32; 2]> = scratch.diagonals().collect();
        for &[a, b] in &diagonals {
            for (x, y) in [(a, b), (b, a)] {
                adjacency[x as usize].push(Neighbour {
                    at: y,
                    constraint: false,
                });
            }
        }
        let mut state = Self {
            points,
            polygon,
            adjacency,
            heap: Vec::new(),
            scratch,
            hole: Vec::new(),
            straight_angles,
        };
        for v in 0..k as u32 {
            let mut list = std::mem::take(&mut state.adjacency[v as usize]);
            list.sort_unstable_by_key(|n| state.rel(v, n.at));
            state.adjacency[v as usize] = list;
        }
        for [a, b] in diagonals {
            state.push(a, b, NO_APEX);
        }
        for v in 0..k as u32 {
            state.push_sector(v, 1);
        }
        state
    }

    /// `(w - v) mod k`: the sort key of `w` in `v`'s list.
    #[inline]
    fn rel(&self, v: u32, w: u32) -> u32 {
        let k = self.polygon.len() as u32;
        if w >= v {
            w - v
        } else {
            w + k - v
        }
    }

    /// Where `w` is (or would be inserted) in `v`'s list.
    fn find(&self, v: u32, w: u32) -> Result<usize, usize> {
        let r = self.rel(v, w);
        self.adjacency[v as usize].binary_search_by_key(&r, |n| self.rel(v, n.at))
    }

    fn insert(&mut self, v: u32, w: u32, constraint: bool) {
        let i = self.find(v, w).expect_err("a new edge");
        self.adjacency[v as usize].insert(i, Neighbour { at: w, constraint });
    }

    fn remove(&mut self, v: u32, w: u32) {
        let i = self.find(v, w).expect("an existing edge");
        self.adjacency[v as usize].remove(i);
    }

    /// Pushes the ear diagonal of the sector of `v` holding list slot `slot`
    /// (an index in `1..len`): the constraints `c_i`, `c_j` around it bound the
    /// subpolygon's sides at `v`; with `D`-edges between them, `c_i c_j` is an
    /// ear diagonal that is not a `D`-edge (otherwise it is one, or a side).
    fn push_sector(&mut self, v: u32, slot: usize) {
        let list = &self.adjacency[v as usize];
        let Some(i) = list[..slot].iter().rposition(|n| n.constraint) else {
            return;
        };
        let Some(j) = list[slot..]
            .iter()
            .position(|n| n.constraint)
            .map(|j| j + slot)
        else {
            return;
        };
        if j - i >= 2 {
            let (a, b) = (list[i].at, list[j].at);
            self.push(a, b, v);
        }
    }

    /// Is `x` before `y` in the exact segment order? The double-double keys
    /// decide unless the squared lengths agree to about 10⁻³⁰ relative
    /// ([`SquaredLength::certainly_compare`]). A rounded `f64` key could not
    /// decide the chords of one offset of a regular polygon sampled with
    /// cos/sin, equal up to rounding; with these keys only exact
    /// ties such as mirror-image chords reach the exact comparison and the
    /// symbolic tie-break.
    #[inline]
    fn before(&self, x: &Candidate, y: &Candidate) -> bool {
        if let Some(order) = x.key.certainly_compare(y.key) {
            return order == Ordering::Less;
        }
        // A segment is often in the heap twice (as a `D`-edge and as an
        // ear diagonal, or from two sector updates); equal to itself, it
        // needs no exact arithmetic. On 10⁴ points sampled on a circle
        // these were 29 of 40 thousand exact comparisons.
        if (x.a, x.b) == (y.a, y.b) || (x.a, x.b) == (y.b, y.a) {
            return false;
        }
        let p = self.polygon;
        compare_lengths_symbolic(
            self.points,
            [p[x.a as usize], p[x.b as usize]],
            [p[y.a as usize], p[y.b as usize]],
        ) == Ordering::Less
    }

    fn push(&mut self, a: u32, b: u32, apex: u32) {
        let (pa, pb) = (
            self.points[self.polygon[a as usize] as usize],
            self.points[self.polygon[b as usize] as usize],
        );
        let key = SquaredLength::of_segment(pa, pb);
        self.heap.push(Candidate { key, a, b, apex });
        self.sift_up(self.heap.len() - 1);
    }

    /// Moves the entry at `i` up while it is before its parent.
    fn sift_up(&mut self, mut i: usize) {
        let entry = self.heap[i];
        while i > 0 {
            let parent = (i - 1) / 2;
            if !self.before(&entry, &self.heap[parent]) {
                break;
            }
            self.heap[i] = self.heap[parent];
            i = parent;
        }
        self.heap[i] = entry;
    }

    /// Pops the first candidate. Bottom-up: the hole at the root sinks
    /// along the smaller children to a leaf (one comparison a level), and
    /// the last entry, which usually belongs near the bottom, rises from
    /// there; about half the comparisons of the textbook sift-down.
    fn pop(&mut self) -> Option<Candidate> {
        let last = self.heap.pop()?;
        if self.heap.is_empty() {
            return Some(last);
        }
        let top = self.heap[0];
        let len = self.heap.len();
        let mut i = 0;
        loop {
            let l = 2 * i + 1;
            if l >= len {
                break;
            }
            let r = l + 1;
            let child = if r < len && self.before(&self.heap[r], &self.heap[l]) {
                r
            } else {
                l
            };
            self.heap[i] = self.heap[child];
            i = child;
        }
        self.heap[i] = last;
        self.sift_up(i);
        Some(top)
    }

    /// Takes the popped candidate if it is still a diagonal of a current
    /// subpolygon (then it is that subpolygon's shortest diagonal: every
    /// candidate of it is in the heap) and returns it as a GT edge.
    fn take(&mut self, c: Candidate) -> Option<[u32; 2]> {
        let (a, b) = (c.a, c.b);
        if c.apex == NO_APEX {
            let i = self.find(a, b).ok()?;
            if self.adjacency[a as usize][i].constraint {
                return None;
            }
            self.adjacency[a as usize][i].constraint = true;
            let j = self.find(b, a).expect("symmetric lists");
            self.adjacency[b as usize][j].constraint = true;
            // The split creates new sectors on both sides at `a` and `b`.
            for (x, s) in [(a, i), (b, j)] {
                self.push_sector(x, s);
                self.push_sector(x, s + 1);
            }
            return Some([a, b]);
        }
        let v = c.apex;
        let ia = self.find(v, a).ok()?;
        let ib = self.find(v, b).ok()?;
        let list = &self.adjacency[v as usize];
        if !(list[ia].constraint && list[ib].constraint && ia + 2 <= ib)
            || list[ia + 1..ib].iter().any(|n| n.constraint)
        {
            return None; // the sector was split or its ear already cut
        }
        if self.straight_angles {
            // `ab` passes through `v` (straight angle), or through all of
            // `w_1..w_m` if `w_1` is on it: then the subpolygon is a
            // triangle `a v b` with points on its side `ab`, where the only
            // diagonals are the `D`-edges at `v`. Neither changes later, so
            // the entry is dropped for good.
            let p = |i: u32| self.points[self.polygon[i as usize] as usize];
            let w1 = list[ia + 1].at;
            if orient_sign(p(a), p(v), p(b)) == 0 || orient_sign(p(a), p(w1), p(b)) == 0 {
                return None;
            }
        }
        // Cut the ear: delete v's D-edges to w_1..w_m, add the side ab,
        // re-triangulate the hole a, w_1, …, w_m, b (ccw).
        self.hole.clear();
        self.hole.push(a);
        self.hole.extend(list[ia + 1..ib].iter().map(|n| n.at));
        self.hole.push(b);
        self.adjacency[v as usize].drain(ia + 1..ib);
        let hole = std::mem::take(&mut self.hole);
        for &w in &hole[1..hole.len() - 1] {
            self.remove(w, v);
        }
        self.insert(a, b, true);
        self.insert(b, a, true);
        if hole.len() >= 4 {
            let vertices: Vec<u32> = hole.iter().map(|&h| self.polygon[h as usize]).collect();
            self.scratch
                .triangulate(self.points, &vertices, self.straight_angles);
            let diagonals: Vec<[u32; 2]> = self.scratch.diagonals().collect();
            for [x, y] in diagonals {
                let (x, y) = (hole[x as usize], hole[y as usize]);
                self.insert(x, y, false);
                self.insert(y, x, false);
                self.push(x, y, NO_APEX);
            }
        }
        // Sectors that changed: at a and b beside the new side, at each w_i
        // where v was.
        for &x in &hole {
            let slot = if x == a {
                self.find(a, b).expect("just added")
            } else if x == b {
                self.find(b, a).expect("just added") + 1
            } else {
                self.find(x, v).expect_err("just removed")
            };
            if slot >= 1 && slot < self.adjacency[x as usize].len() {
                self.push_sector(x, slot);
            }
        }
        self.hole = hole;
        Some([a, b])
    }
}
