//! The triangle program of one skeleton face, and the certificate that lets
//! the exact front search ([`super::faces`]) skip most of the face's
//! triangles.
//!
//! **The program** (the triangle formulation of Kyoda, Imai, Takeuchi and
//! Tajima 1997, *A branch-and-cut approach for minimum weight
//! triangulation*, ISAAC '97, §2, restricted to one face): one variable
//! `x_t ∈ {0, 1}` per empty candidate triangle `t` of the face, and one row
//! per *side*: a boundary half-edge `h` (face on its left) has
//! `Σ_{t ∋ h} x_t = 1`; an inner candidate edge `e = {u, v}`, `u < v`, has
//! `Σ_{t left of u→v} x_t − Σ_{t left of v→u} x_t = 0`. The cost `c_t` is
//! half the length of each inner side of `t` (boundary sides cost nothing:
//! they are in every triangulation of the face). Every triangulation `T` of
//! the face by these triangles meets the rows (each boundary half-edge has
//! exactly one triangle inside, each inner edge one triangle on each side or
//! none), and `Σ_{t ∈ T} c_t` is the length of its inner edges — the value
//! the front search minimises. That the rows describe *only*
//! triangulations is not needed: the program's solutions are never trusted,
//! only the bound below.
//!
//! **The certificate** (reduced-cost fixing: H. Crowder, E. L. Johnson and
//! M. Padberg 1983, *Solving large-scale zero-one linear programming
//! problems*, Operations Research 31(5), §3; here with every number
//! certified). Take *any* row multipliers `y` (the floating-point dual
//! solution of the LP relaxation, by `microlp`; nothing about them is
//! trusted) and the reduced costs `r_t = c_t − Σ_rows A_{row,t} y_row`. For a
//! triangulation `T` (so `A x_T = b`), `c(T) = b·y + Σ_{t ∈ T} r_t`, hence
//!
//! * `c(T) ≥ L := b·y + Σ_t min(0, r_t)` for every `T`: a lower bound on the
//!   face's optimum, and
//! * if `t ∈ T` then `c(T) ≥ L + r_t` (the other triangles of `T` add at
//!   least their negative reduced costs, which `L` already counts, and
//!   `min(0, r_t) ≤ 0` only lowers `L`).
//!
//! Let `W` be the weight of a triangulation of the face that was actually
//! built (the incumbent: the integer program's answer, re-checked by the
//! front search restricted to its triangles, or else the constrained
//! Delaunay triangles). Then the optimum `OPT ≤ W`, and every triangle with
//! `r_t > W − L` lies in no triangulation of weight `≤ W`, so in no optimal
//! one: dropping it keeps every optimal triangulation. The exact front
//! search on the kept triangles therefore returns an optimal triangulation,
//! and — because it keeps every triangle of every optimum and chooses the
//! first lightest triangle at each front — the same one as the search over
//! all triangles would (the tie-break is unchanged). As a consistency check
//! its weight must not exceed `W` (exactly compared); if it does, the
//! incumbent was not what it claimed and the face is not called solved.
//!
//! `y`, `L`, `W` and every `r_t` are evaluated in interval arithmetic with
//! outward rounding (`next_down`/`next_up` after each operation, lengths by
//! [`LengthInterval`]): a triangle is dropped only when the lower end of
//! `r_t` exceeds the upper end of `W − L`; an undecided comparison keeps it,
//! which is always sound. No epsilon is involved anywhere.

use crate::kernel::{LengthInterval, Point};
use std::collections::{HashMap, HashSet};

/// Branch-and-bound nodes the integer program may spend on the incumbent
/// (a node count, not a time, so the result is deterministic).
const INCUMBENT_NODES: u64 = 2_000;

/// An enclosure `[lo, hi]` of a real number, with outward rounding.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Enclosure {
    lo: f64,
    hi: f64,
}

impl Enclosure {
    const ZERO: Enclosure = Enclosure { lo: 0.0, hi: 0.0 };

    fn exact(x: f64) -> Self {
        Enclosure { lo: x, hi: x }
    }

    /// Rounding to nearest is within half an ulp of the exact sum, so one
    /// step outwards on each side encloses it, whatever the signs.
    fn plus(self, other: Self) -> Self {
        Enclosure {
            lo: (self.lo + other.lo).next_down(),
            hi: (self.hi + other.hi).next_up(),
        }
    }

    fn minus(self, other: Self) -> Self {
        self.plus(Enclosure {
            lo: -other.hi,
            hi: -other.lo,
        })
    }

    fn min_zero(self) -> Self {
        Enclosure {
            lo: self.lo.min(0.0),
            hi: self.hi.min(0.0),
        }
    }
}

/// What a row of the program stands for.
#[derive(Clone, Copy, PartialEq, Eq, Hash, Debug)]
enum Side {
    /// A boundary half-edge `(a, b)`, the face on its left: covered once.
    Boundary(u32, u32),
    /// An inner candidate edge (its id): balanced.
    Inner(u32),
}

/// The triangle program of one face (module docs).
pub(super) struct FaceProgram {
    /// Per row: does the right-hand side equal one (boundary half-edge)?
    boundary_row: Vec<bool>,
    /// Per triangle: its three sides' rows and coefficients (±1).
    entries: Vec<[(u32, i8); 3]>,
    /// Per triangle: the certified cost (half its inner sides' lengths).
    cost: Vec<Enclosure>,
}

impl FaceProgram {
    /// The program of the face whose boundary half-edges are `boundary`
    /// (face on their left) over the triangles `tris` (counter-clockwise,
    /// none with a half-edge whose reverse is a non-dangling boundary
    /// half-edge) with candidate edge ids `tri_edges`.
    pub(super) fn new(
        pts: &[Point],
        boundary: &HashSet<(u32, u32)>,
        tris: &[[u32; 3]],
        tri_edges: &[[u32; 3]],
    ) -> Self {
        let mut row_of: HashMap<Side, u32> = HashMap::new();
        let mut boundary_row = Vec::new();
        let mut entries = Vec::with_capacity(tris.len());
        let mut cost = Vec::with_capacity(tris.len());
        for (t, ids) in tris.iter().zip(tri_edges) {
            let mut row = [(0u32, 0i8); 3];
            let mut c = LengthInterval::ZERO;
            for s in 0..3 {
                let (a, b) = (t[s], t[(s + 1) % 3]);
                let (side, sign) = if boundary.contains(&(a, b)) {
                    (Side::Boundary(a, b), 1)
                } else {
                    let l = LengthInterval::of_segment(pts[a as usize], pts[b as usize]);
                    c = c.plus(l);
                    (Side::Inner(ids[s]), if a < b { 1 } else { -1 })
                };
                let next = row_of.len() as u32;
                let r = *row_of.entry(side).or_insert_with(|| {
                    boundary_row.push(matches!(side, Side::Boundary(..)));
                    next
                });
                row[s] = (r, sign);
            }
            entries.push(row);
            // Halving is exact in binary floating point (lengths are far
            // from the subnormal range: see `crate::kernel`).
            cost.push(Enclosure {
                lo: 0.5 * c.lo,
                hi: 0.5 * c.hi,
            });
        }
        FaceProgram {
            boundary_row,
            entries,
            cost,
        }
    }

    pub(super) fn triangles(&self) -> usize {
        self.entries.len()
    }

    fn scale(&self) -> f64 {
        let s = self.cost.iter().map(|c| c.hi).fold(0.0f64, f64::max);
        if s > 0.0 {
            s
        } else {
            1.0
        }
    }

    /// Floating-point row multipliers of the LP relaxation, from the dual
    /// program `max Σ_{boundary rows} y_r` subject to `Aᵀy ≤ c` (solved by
    /// `microlp`); `None` if the solver fails. Untrusted: see
    /// [`Self::certify`].
    pub(super) fn dual(&self) -> Option<Vec<f64>> {
        use microlp::{ComparisonOp, OptimizationDirection, Problem};
        let scale = self.scale();
        let mut problem = Problem::new(OptimizationDirection::Maximize);
        // A box on the multipliers keeps the program bounded when no
        // triangulation uses only these triangles (a branch-and-bound node
        // of [`super::faces`]): its optimum then grows with the box, above
        // any incumbent. The certificate holds for every `y`, so the box
        // costs nothing in soundness; it is wide enough (each multiplier of
        // an optimum is a sum of at most one cost per row, costs scaled to
        // at most 1) not to cut the bound of a feasible node.
        let width = 2.0 * self.boundary_row.len() as f64 + 2.0;
        let ys: Vec<microlp::Variable> = self
            .boundary_row
            .iter()
            .map(|&b| problem.add_var(if b { 1.0 } else { 0.0 }, (-width, width)))
            .collect();
        for (row, c) in self.entries.iter().zip(&self.cost) {
            let expr: Vec<(microlp::Variable, f64)> = row
                .iter()
                .map(|&(r, s)| (ys[r as usize], f64::from(s)))
                .collect();
            problem.add_constraint(expr, ComparisonOp::Le, 0.5 * (c.lo + c.hi) / scale);
        }
        let outcome = problem.solve().ok()?;
        let solution = outcome.solution()?;
        Some(ys.iter().map(|&y| solution.var_value(y) * scale).collect())
    }

    /// A floating-point optimum `x` of the LP relaxation (`min c·x`, `A x =
    /// b`, `0 ≤ x ≤ 1`) by `microlp`, `None` if the solver fails. Untrusted:
    /// it only chooses the branching edge of [`super::faces`]' branch and
    /// bound, which is sound whatever it is.
    pub(super) fn primal(&self) -> Option<Vec<f64>> {
        let (problem, xs) = self.problem(false);
        let outcome = problem.solve().ok()?;
        let solution = outcome.solution()?;
        Some(xs.iter().map(|&x| solution.var_value(x)).collect())
    }

    /// The program for `microlp` (`min c·x`, `A x = b`, one variable per
    /// triangle, binary or in `[0, 1]`), with the rounded midpoints of the
    /// certified costs, scaled: the solver's answer is only a candidate.
    fn problem(&self, binary: bool) -> (microlp::Problem, Vec<microlp::Variable>) {
        use microlp::{ComparisonOp, OptimizationDirection, Problem};
        let scale = self.scale();
        let mut problem = Problem::new(OptimizationDirection::Minimize);
        let xs: Vec<microlp::Variable> = self
            .cost
            .iter()
            .map(|c| {
                let cost = 0.5 * (c.lo + c.hi) / scale;
                if binary {
                    problem.add_binary_var(cost)
                } else {
                    problem.add_var(cost, (0.0, 1.0))
                }
            })
            .collect();
        for (r, row) in self.rows(&xs).into_iter().enumerate() {
            let rhs = if self.boundary_row[r] { 1.0 } else { 0.0 };
            problem.add_constraint(row, ComparisonOp::Eq, rhs);
        }
        (problem, xs)
    }

    /// The rows of the program over the variables `xs` (one per triangle).
    fn rows(&self, xs: &[microlp::Variable]) -> Vec<Vec<(microlp::Variable, f64)>> {
        let mut rows: Vec<Vec<(microlp::Variable, f64)>> =
            vec![Vec::new(); self.boundary_row.len()];
        for (t, row) in self.entries.iter().enumerate() {
            for &(r, s) in row {
                rows[r as usize].push((xs[t], f64::from(s)));
            }
        }
        rows
    }

    /// The triangles (indices) of the integer program's best solution within
    /// [`INCUMBENT_NODES`] nodes, `None` if it has none. Untrusted: the
    /// caller re-checks it as a triangulation.
    pub(super) fn integer_solution(&self) -> Option<Vec<usize>> {
        let (problem, xs) = self.problem(true);
        let mut options = microlp::SolveOptions::default();
        options.node_limit = Some(INCUMBENT_NODES);
        let outcome = problem.solve_with(options).ok()?;
        let solution = outcome.solution()?;
        Some(
            xs.iter()
                .enumerate()
                .filter(|(_, &x)| solution.var_value(x) > 0.5)
                .map(|(t, _)| t)
                .collect(),
        )
    }

    /// The certified bounds of the multipliers `y` (module docs); `None` if
    /// `y` has the wrong length or a value that is not finite.
    pub(super) fn certify(&self, y: &[f64]) -> Option<Certificate> {
        if y.len() != self.boundary_row.len() || !y.iter().all(|v| v.is_finite()) {
            return None;
        }
        let mut lower = Enclosure::ZERO;
        for (&b, &v) in self.boundary_row.iter().zip(y) {
            if b {
                lower = lower.plus(Enclosure::exact(v));
            }
        }
        let mut reduced = Vec::with_capacity(self.entries.len());
        for (row, &c) in self.entries.iter().zip(&self.cost) {
            let mut r = c;
            for &(row, s) in row {
                let term = Enclosure::exact(f64::from(s) * y[row as usize]);
                r = r.minus(term);
            }
            lower = lower.plus(r.min_zero());
            reduced.push(r.lo);
        }
        if !lower.lo.is_finite() {
            return None;
        }
        Some(Certificate {
            lower: lower.lo,
            reduced,
        })
    }
}

/// A certified lower bound on a face's optimum and on each triangle's
/// reduced cost (module docs).
#[derive(Clone, Debug)]
pub(super) struct Certificate {
    /// `L`, rounded down: no triangulation of the face is lighter.
    pub lower: f64,
    /// `r_t`, rounded down, per triangle.
    reduced: Vec<f64>,
}

impl Certificate {
    /// The slack `W − L` (rounded up) for an incumbent of weight at most
    /// `incumbent`, `None` when `L > incumbent`, which no true incumbent
    /// allows: the incumbent (or the certificate) is wrong and nothing may
    /// be pruned.
    pub(super) fn slack(&self, incumbent: f64) -> Option<f64> {
        // NaN on either side compares as unordered: no certificate.
        if !matches!(
            self.lower.partial_cmp(&incumbent),
            Some(std::cmp::Ordering::Less | std::cmp::Ordering::Equal)
        ) {
            return None;
        }
        Some((incumbent - self.lower).next_up())
    }

    /// `r_t` rounded down, per triangle of the program.
    pub(super) fn reduced(&self) -> &[f64] {
        &self.reduced
    }

    /// Prices for the pruned search ([`super::faces`]): each triangle's
    /// reduced cost where positive (its lower end), with the slack of
    /// [`Self::slack`]. A triangulation `T` weighs at least `L + Σ_{t ∈ T}
    /// max(0, r_t)` (module docs), so one of weight at most `incumbent` has
    /// prices adding up to at most the slack; a triangle priced above the
    /// slack is in none (reduced-cost fixing).
    pub(super) fn prices(&self, incumbent: f64) -> Option<Prices> {
        let slack = self.slack(incumbent)?;
        Some(Prices {
            price: self.reduced.iter().map(|&r| r.max(0.0)).collect(),
            slack,
        })
    }
}

/// Prices on a face's triangles for the pruned search: a partial
/// triangulation whose triangles' prices add up to more than `slack` is not
/// completed.
pub(super) struct Prices {
    /// Per triangle, non-negative (`+∞`: never used).
    pub price: Vec<f64>,
    pub slack: f64,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn enclosures_round_outwards() {
        let a = Enclosure::exact(0.1).plus(Enclosure::exact(0.2));
        assert!(a.lo < a.hi && a.lo <= 0.3 && 0.3 <= a.hi);
        let d = Enclosure::exact(1.0).minus(Enclosure::exact(1e-30));
        assert!(d.lo < 1.0 && d.hi >= 1.0);
        assert_eq!(
            Enclosure { lo: -1.0, hi: 2.0 }.min_zero(),
            Enclosure { lo: -1.0, hi: 0.0 }
        );
    }

    #[test]
    fn a_wrong_incumbent_below_the_bound_is_rejected() {
        let c = Certificate {
            lower: 10.0,
            reduced: vec![-1.0, 3.0, 0.5],
        };
        assert!(c.prices(9.5).is_none());
        assert!(c.prices(f64::NAN).is_none());
        let p = c.prices(11.0).unwrap();
        assert_eq!(p.price, vec![0.0, 3.0, 0.5]);
        assert!(p.slack >= 1.0 && p.slack < 1.0 + 1e-12);
        // A reduced cost equal to the slack is within it (ties stay).
        assert!(c.prices(13.0).unwrap().slack >= 3.0);
    }
}
