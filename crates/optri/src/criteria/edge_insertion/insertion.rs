//! The edge-insertion step (Bern, Edelsbrunner, Eppstein, Mitchell & Tan,
//! DCG 10, 1993, §3; Figure 1.7 of the thesis): insert the segment `a–v`,
//! delete every edge it crosses, and retriangulate the two sides of the
//! deleted region, keeping every edge that did not cross.
//!
//! The sides are weakly simple: when all edges but one at a vertex cross
//! `a–v`, that vertex hangs into the side on its remaining edge, and the
//! side's walk passes the edge twice. Each walk position is its own corner
//! ([`PolygonCycle`]), so the polygon program triangulates such a side with
//! the usual corner rule. The retriangulation is the *lexicographic
//! bottleneck* optimum (the decreasing vector of badness values is
//! minimised): with ties between worst triangles, a plain bottleneck
//! retriangulation can leave an improvable triangulation unimproved.

use crate::kernel::{orient_sign, properly_cross, Corners, Point, TriangleMeasure};
use crate::polygon_program::{optimal_triangulation, Objective};
use crate::structures::PolygonCycle;
use std::cell::RefCell;
use std::cmp::Ordering;
use std::collections::{BTreeSet, HashMap};

/// A measure on the triangles of one point set: exact badness
/// comparisons and anchors by vertex index.
pub(crate) struct Badness<'a> {
    pub measure: TriangleMeasure,
    pub points: &'a [Point],
    /// One elevation per point (zeros when the measure reads none).
    pub elevations: &'a [f64],
}

impl Badness<'_> {
    fn corners(&self, t: [u32; 3]) -> Corners {
        (
            t.map(|i| self.points[i as usize]),
            t.map(|i| self.elevations[i as usize]),
        )
    }

    /// `Greater` when `s` is the worse triangle. Exact.
    pub fn compare(&self, s: [u32; 3], t: [u32; 3]) -> Ordering {
        if s == t {
            return Ordering::Equal;
        }
        self.measure
            .compare_badness(&self.corners(s), &self.corners(t))
    }

    /// The triangle rotated so that its anchor comes first (orientation
    /// kept).
    pub fn anchored(&self, t: [u32; 3]) -> [u32; 3] {
        let i = self.measure.anchor(&self.corners(t));
        [t[i], t[(i + 1) % 3], t[(i + 2) % 3]]
    }

    /// Sorts triangles worst first.
    pub fn sort_worst_first(&self, triangles: &mut [[u32; 3]]) {
        triangles.sort_by(|&s, &t| self.compare(t, s).then(s.cmp(&t)));
    }

    /// Compares two lists sorted worst first, lexicographically by badness
    /// (a prefix is smaller).
    pub fn compare_sorted(&self, s: &[[u32; 3]], t: &[[u32; 3]]) -> Ordering {
        for (&x, &y) in s.iter().zip(t) {
            let o = self.compare(x, y);
            if o != Ordering::Equal {
                return o;
            }
        }
        s.len().cmp(&t.len())
    }

    #[cfg(any(test, feature = "internals"))]
    /// The reported value of a triangle (degrees for angles).
    pub fn reported(&self, t: [u32; 3]) -> f64 {
        self.measure.reported(&self.corners(t))
    }

    #[cfg(any(test, feature = "internals"))]
    /// The worst triangle of a non-empty list.
    pub fn worst(&self, triangles: &[[u32; 3]]) -> Option<[u32; 3]> {
        triangles.iter().copied().reduce(|w, t| {
            if self.compare(t, w) == Ordering::Greater {
                t
            } else {
                w
            }
        })
    }
}

/// A triangle with its smallest index first, orientation kept.
fn canonical(t: [u32; 3]) -> [u32; 3] {
    let i = (0..3).min_by_key(|&i| t[i]).expect("three corners");
    [t[i], t[(i + 1) % 3], t[(i + 2) % 3]]
}

/// A triangulation under edge insertions: counter-clockwise triangles and,
/// for each directed edge, the apex of the triangle on its left.
pub(crate) struct Mesh {
    triangles: BTreeSet<[u32; 3]>,
    apex: HashMap<[u32; 2], u32>,
}

/// One edge insertion: the triangles it removes and those it adds.
pub(crate) struct Insertion {
    pub removed: Vec<[u32; 3]>,
    pub added: Vec<[u32; 3]>,
}

impl Mesh {
    /// A mesh of counter-clockwise triangles.
    pub fn new(triangles: &[[u32; 3]]) -> Self {
        let mut mesh = Mesh {
            triangles: BTreeSet::new(),
            apex: HashMap::new(),
        };
        for &t in triangles {
            mesh.add(t);
        }
        mesh
    }

    fn add(&mut self, t: [u32; 3]) {
        let t = canonical(t);
        self.triangles.insert(t);
        for i in 0..3 {
            self.apex.insert([t[i], t[(i + 1) % 3]], t[(i + 2) % 3]);
        }
    }

    fn remove(&mut self, t: [u32; 3]) {
        let t = canonical(t);
        self.triangles.remove(&t);
        for i in 0..3 {
            self.apex.remove(&[t[i], t[(i + 1) % 3]]);
        }
    }

    /// The triangles, smallest index first, in sorted order.
    pub fn triangles(&self) -> impl Iterator<Item = [u32; 3]> + '_ {
        self.triangles.iter().copied()
    }

    /// Is `[p, q]` an edge (in either direction)?
    pub fn has_edge(&self, p: u32, q: u32) -> bool {
        self.apex.contains_key(&[p, q]) || self.apex.contains_key(&[q, p])
    }

    /// Replaces an insertion's removed triangles by its added ones.
    pub fn apply(&mut self, insertion: &Insertion) {
        for &t in &insertion.removed {
            self.remove(t);
        }
        for &t in &insertion.added {
            self.add(t);
        }
    }

    /// The worst triangles (all tied at the largest badness), sorted.
    pub fn worst_triangles(&self, badness: &Badness) -> Vec<[u32; 3]> {
        let triangles: Vec<[u32; 3]> = self.triangles().collect();
        badness
            .measure
            .worst_ties(triangles.iter().map(|&t| badness.corners(t)))
            .into_iter()
            .map(|i| triangles[i])
            .collect()
    }

    /// The insertion of `a–v` from the triangle `[a, b, c]` (counter-
    /// clockwise, `a` its anchor) with lexicographic-bottleneck sides, if
    /// `a–v` is a valid segment properly crossing `bc`, meeting no edge in
    /// `fixed` (constraints), and the sides can be triangulated; `None` also
    /// when the insertion would add a triangle worse than `[a, b, c]`, which
    /// must be a worst triangle of the mesh (such an insertion is never
    /// accepted).
    pub fn insertion(
        &self,
        badness: &Badness,
        [a, b, c]: [u32; 3],
        v: u32,
        fixed: &dyn Fn(u32, u32) -> bool,
    ) -> Option<Insertion> {
        let points = badness.points;
        let p = |i: u32| points[i as usize];
        if !properly_cross(p(a), p(v), p(b), p(c)) || fixed(b, c) {
            return None;
        }
        // Walk from bc to v (a point on the open segment a–v is the apex of
        // a crossed triangle on the way, so the walk finds it): `left` and `right` are the current crossed
        // edge's endpoints on either side of a → v.
        let (mut left, mut right) = (c, b);
        let mut removed = vec![[a, b, c]];
        let mut left_chain = vec![left];
        let mut right_chain = vec![right];
        loop {
            let s = *self.apex.get(&[left, right])?;
            removed.push([left, right, s]);
            if s == v {
                break;
            }
            match orient_sign(p(a), p(v), p(s)) {
                1 => {
                    left = s;
                    left_chain.push(s);
                }
                -1 => {
                    right = s;
                    right_chain.push(s);
                }
                _ => return None, // s on the open segment a–v: not a valid segment
            }
            if fixed(left, right) {
                return None;
            }
        }
        // Counter-clockwise sides: [a, v, left chain reversed] and
        // [a, right chain, v].
        let mut left_side = vec![a, v];
        left_side.extend(left_chain.iter().rev());
        let mut right_side = vec![a];
        right_side.extend(&right_chain);
        right_side.push(v);
        // An accepted insertion adds no triangle worse than [a, b, c] (a
        // worst triangle, which it removes: the removed vector starts with
        // its value). Each side p → q of a counter-clockwise side polygon is
        // in one triangle of its triangulation, whose third corner is a
        // corner strictly left of p → q; a side where every such triangle
        // is worse rules the insertion out in O(k²) comparisons at most,
        // before the O(k³) program.
        let worst = [a, b, c];
        let edge_fits = |side: &[u32], from: u32, to: u32| {
            side.iter().any(|&w| {
                w != from
                    && w != to
                    && orient_sign(p(from), p(to), p(w)) > 0
                    && badness.compare([from, to, w], worst) != Ordering::Greater
            })
        };
        // From side `first` on: a–v is side 0 of the left polygon and the
        // closing side of the right one.
        let side_fits = |side: &[u32], first: usize| {
            let k = side.len();
            (0..k)
                .map(|i| (first + i) % k)
                .all(|i| edge_fits(side, side[i], side[(i + 1) % k]))
        };
        if !side_fits(&left_side, 0) || !side_fits(&right_side, right_side.len() - 1) {
            return None;
        }
        let mut added = retriangulate(badness, &left_side)?;
        added.extend(retriangulate(badness, &right_side)?);
        Some(Insertion { removed, added })
    }
}

/// The lexicographic-bottleneck triangulation of the weakly simple side
/// `corners` (counter-clockwise vertex indices), as vertex triangles.
pub(crate) fn retriangulate(badness: &Badness, corners: &[u32]) -> Option<Vec<[u32; 3]>> {
    if corners.len() == 3 {
        return Some(vec![[corners[0], corners[1], corners[2]]]);
    }
    let cycle = PolygonCycle::exact(badness.points, corners);
    let p = |c: usize| badness.points[corners[c] as usize];
    let objective = LexicographicBottleneck {
        badness,
        corners,
        lists: RefCell::new(vec![Vec::new()]),
    };
    let solved = optimal_triangulation(
        corners.len(),
        |i, j| cycle.is_diagonal(i, j),
        |i, m, j| orient_sign(p(i), p(m), p(j)) > 0,
        &objective,
    )?;
    Some(
        solved
            .triangles
            .into_iter()
            .map(|t| t.map(|c| corners[c]))
            .collect(),
    )
}

/// The decreasing vector of triangle badness values, minimised
/// lexicographically. Values are indices into an arena of lists sorted worst
/// first (`0`: the empty list), so that they are `Copy`; merging two
/// sorted lists keeps the order, and the order is monotone under merging
/// (equal-length lists), so the polygon program's recursion is exact.
struct LexicographicBottleneck<'a, 'b> {
    badness: &'a Badness<'b>,
    corners: &'a [u32],
    lists: RefCell<Vec<Vec<[u32; 3]>>>,
}

impl LexicographicBottleneck<'_, '_> {
    fn push(&self, list: Vec<[u32; 3]>) -> u32 {
        let mut lists = self.lists.borrow_mut();
        lists.push(list);
        (lists.len() - 1) as u32
    }
}

impl Objective for LexicographicBottleneck<'_, '_> {
    type Value = u32;
    fn empty(&self) -> u32 {
        0
    }
    fn diagonal(&self, _: usize, _: usize) -> Option<u32> {
        None
    }
    fn triangle(&self, i: usize, m: usize, j: usize) -> Option<u32> {
        let t = [self.corners[i], self.corners[m], self.corners[j]];
        Some(self.push(vec![t]))
    }
    fn combine(&self, s: u32, t: u32) -> u32 {
        if s == 0 {
            return t;
        }
        if t == 0 {
            return s;
        }
        let merged = {
            let lists = self.lists.borrow();
            let (x, y) = (&lists[s as usize], &lists[t as usize]);
            let mut out = Vec::with_capacity(x.len() + y.len());
            let (mut i, mut j) = (0, 0);
            while i < x.len() || j < y.len() {
                let take_x = j == y.len()
                    || (i < x.len() && self.badness.compare(x[i], y[j]) != Ordering::Less);
                if take_x {
                    out.push(x[i]);
                    i += 1;
                } else {
                    out.push(y[j]);
                    j += 1;
                }
            }
            out
        };
        self.push(merged)
    }
    fn better(&self, s: u32, t: u32) -> bool {
        let lists = self.lists.borrow();
        self.badness
            .compare_sorted(&lists[s as usize], &lists[t as usize])
            == Ordering::Less
    }
}
