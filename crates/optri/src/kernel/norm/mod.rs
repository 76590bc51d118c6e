//! Normed metrics for minmax-length triangulations and proximity graphs:
//! Euclidean, L1, L∞, Lp (integer p ≥ 3) and polygonal norms, with exact
//! length comparisons and one documented tie-break.
//!
//! After H. Edelsbrunner & T. S. Tan, *A quadratic time algorithm for the
//! minmax length triangulation* (1991), §7 "Arbitrary normed metrics": the
//! General Subgraph Theorem needs a norm whose unit disk `D` is *strictly*
//! convex (the □- and △-Lemmas need a strict triangle inequality), and a
//! non-strictly convex norm (L1, L∞, polygonal) is "simulated" by a strictly
//! convex one. This module makes that simulation exact.
//!
//! # Exact comparisons
//! * Lp (and L1): compare `|dx|ᵖ + |dy|ᵖ`; polygonal norms (L1 and L∞ are
//!   the diamond and the square): `‖v‖ = maxᵢ aᵢ·vx + bᵢ·vy` over the facets,
//!   `(aᵢ, bᵢ)` the facet's outer normal divided by its support value, exact
//!   rationals computed from the vertices.
//! * A floating-point filter decides clear cases; its relative error bound is
//!   derived at each filter. Everything else is decided in exact rational
//!   arithmetic (`num-rational`): coordinate differences of doubles are exact
//!   rationals, so every comparison is exact for every p (no expansion
//!   overflow for large p).
//!
//! # Ties: the simulated strictly convex norm
//! Every comparison of two segment lengths is decided as for the norm
//!
//! ```text
//!   N(v) = ‖v‖_D + η·‖v‖₂          (η > 0 a fixed, small enough real)
//! ```
//!
//! on the points perturbed by the kernel's symbolic perturbation `S′`
//! (`y_m + ε^(3^(2m))`, `x_m + ε^(3^(2m+1))`, ε → 0 *after* η is fixed;
//! see [the kernel's perturbation](crate::kernel#ties-symbolic-perturbation)).
//! `N` is a norm with a strictly convex unit disk for every η > 0 (the sum of
//! a convex and a strictly convex function is strictly convex), so the General
//! Subgraph Theorem and §5–§6 apply to `(S′, N)`; orientations are the
//! kernel's symbolic orientations of the same `S′`, so all decisions come
//! from one point set and one strictly convex norm. Concretely, `ab` versus
//! `cd` is decided by, in this order:
//! 1. `‖·‖_D` of the unperturbed points (for η small, `N`'s order refines it);
//! 2. the Euclidean length of the unperturbed points (the η-term);
//! 3. if both are equal, the perturbation: `N(b′−a′) − N(d′−c′)` is a series
//!    in ε. Its `‖·‖_D` part is exact: `Σ|v_c+δ_c|ᵖ` expanded (Lp), or the
//!    active facet's linear form in `δ` (polygonal norms are piecewise linear,
//!    and of two active facets the one larger on `δ` wins). Its η-part has the
//!    leading term and sign of the squared Euclidean difference (the kernel's
//!    base-3 expansion). The difference's sign is that of the term with the
//!    smallest power of ε; at equal powers the `‖·‖_D` coefficient wins (η is
//!    small). For `p`-th powers the monomials are merged by their exponent in
//!    base 3 with carries (a cube of one variable can meet the next variable).
//!
//! Why this is a legitimate simulation and not just *a* tie-break: the output
//! of the algorithm is a fixed combinatorial function of these decisions; for
//! all small enough η and ε it is an optimal triangulation for `(S′, N)`
//! (Edelsbrunner–Tan, General MinMax Length Theorem), and the longest-edge
//! value of every triangulation is continuous in η and ε, so the output is
//! optimal for `(S, ‖·‖_D)` too. Step 3 is needed because the perturbation of
//! `‖·‖_D` is of order ε while that of η·‖·‖₂ is of order ηε: ordering by the
//! Euclidean perturbation alone (a simpler lexicographic rule) is not the limit
//! of any perturbed strictly convex norm. For the Euclidean metric this
//! module defers to [`crate::kernel::compare_lengths_symbolic`] unchanged.

mod polygon;
mod series;

use super::expansion::{sign_of_sum, two_diff, Expansion};
use super::predicates::compare_lengths;
use super::symbolic::{compare_lengths_symbolic, orient_symbolic};
use super::{check_coordinate, Point, UNIT_ROUNDOFF as U};
use num_rational::BigRational;
use num_traits::Signed;
use polygon::PolygonNorm;
use series::{exponent, power_series, var, Series};
use std::cmp::Ordering;
use std::fmt;

/// Largest exponent accepted by [`Metric::lp`] (the exact tie-break expands
/// `(v + δ)ᵖ`, O(p²) exact terms per coordinate).
pub const MAX_LP_EXPONENT: u32 = 64;

/// Why a metric description is refused.
#[derive(Clone, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum MetricProblem {
    /// `lp:P` with P = 0 or above [`MAX_LP_EXPONENT`].
    ExponentOutOfRange(u32),
    /// Not one of `euclidean`, `l1`, `linf`, `lp:P`, `polygon:x1,y1,...`.
    UnknownMetric(String),
    /// A polygon coordinate that is not a number, not finite or out of the
    /// kernel's range.
    BadCoordinate(String),
    /// Fewer than 4 vertices or an odd number of them.
    VertexCount(usize),
    /// Vertex `i + k/2` is not `−vertex i` (the disk must be centrally
    /// symmetric about the origin); names `i`.
    NotCentrallySymmetric(usize),
    /// The vertices do not go once around the origin turning strictly the
    /// same way at every vertex (not convex, a repeated vertex, three
    /// consecutive vertices on a line, or the origin not strictly inside);
    /// names the first offending vertex.
    NotStrictlyConvex(usize),
}

impl fmt::Display for MetricProblem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            MetricProblem::ExponentOutOfRange(p) => {
                write!(f, "lp:{p}: the exponent must be an integer 1 ≤ P ≤ {MAX_LP_EXPONENT}")
            }
            MetricProblem::UnknownMetric(s) => write!(
                f,
                "unknown metric {s:?} (expected euclidean, l1, linf, lp:P or polygon:x1,y1,x2,y2,...)"
            ),
            MetricProblem::BadCoordinate(s) => {
                write!(f, "polygon norm: {s:?} is not a finite coordinate in range")
            }
            MetricProblem::VertexCount(k) => write!(
                f,
                "polygon norm: {k} vertices; a centrally symmetric polygon has an even number ≥ 4"
            ),
            MetricProblem::NotCentrallySymmetric(i) => write!(
                f,
                "polygon norm: not centrally symmetric about the origin (vertex {i} and the \
                 vertex half-way round are not opposite)"
            ),
            MetricProblem::NotStrictlyConvex(i) => write!(
                f,
                "polygon norm: not a convex polygon around the origin with strict corners \
                 (at vertex {i})"
            ),
        }
    }
}

fn rational(v: f64) -> BigRational {
    BigRational::from_float(v).expect("kernel coordinates are finite")
}

fn diff(a: f64, b: f64) -> BigRational {
    rational(a) - rational(b)
}

fn to_f64(r: &BigRational) -> f64 {
    use num_traits::ToPrimitive;
    r.to_f64().unwrap_or(f64::NAN)
}

#[derive(Clone, Debug)]
enum Kind {
    Euclidean,
    /// p ≥ 3.
    Power(u32),
    L1(PolygonNorm),
    LInf(PolygonNorm),
    Polygon(PolygonNorm),
}

/// A norm on the plane (see the module docs). `Metric::default()` is Euclidean.
#[derive(Clone, Debug)]
pub struct Metric(Kind);

impl Default for Metric {
    fn default() -> Self {
        Metric::euclidean()
    }
}

impl PartialEq for Metric {
    fn eq(&self, other: &Self) -> bool {
        self.name() == other.name()
    }
}
impl Eq for Metric {}

impl fmt::Display for Metric {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.name())
    }
}

impl Metric {
    /// The Euclidean norm (the default).
    pub fn euclidean() -> Self {
        Metric(Kind::Euclidean)
    }
    /// The L1 (Manhattan) norm, `|dx| + |dy|`.
    pub fn l1() -> Self {
        let v = [[1.0, 0.0], [0.0, 1.0], [-1.0, 0.0], [0.0, -1.0]];
        Metric(Kind::L1(
            PolygonNorm::new(&v).expect("the diamond is valid"),
        ))
    }
    /// The L∞ (Chebyshev) norm, `max(|dx|, |dy|)`.
    pub fn linf() -> Self {
        let v = [[1.0, 1.0], [-1.0, 1.0], [-1.0, -1.0], [1.0, -1.0]];
        Metric(Kind::LInf(
            PolygonNorm::new(&v).expect("the square is valid"),
        ))
    }
    /// The Lp norm for an integer `1 ≤ p ≤` [`MAX_LP_EXPONENT`] (`lp(1)` is
    /// [`Metric::l1`], `lp(2)` is [`Metric::euclidean`]).
    pub fn lp(p: u32) -> Result<Self, MetricProblem> {
        match p {
            1 => Ok(Metric::l1()),
            2 => Ok(Metric::euclidean()),
            3..=MAX_LP_EXPONENT => Ok(Metric(Kind::Power(p))),
            _ => Err(MetricProblem::ExponentOutOfRange(p)),
        }
    }
    /// The norm whose unit disk is the convex polygon with these vertices
    /// (either orientation): an even number ≥ 4 of them, centrally symmetric
    /// about the origin (vertex `i + k/2` is `−vertex i`), strictly convex
    /// corners.
    pub fn polygon(vertices: &[Point]) -> Result<Self, MetricProblem> {
        for v in vertices.iter().flatten() {
            if check_coordinate(*v).is_err() {
                return Err(MetricProblem::BadCoordinate(v.to_string()));
            }
        }
        Ok(Metric(Kind::Polygon(PolygonNorm::new(vertices)?)))
    }
    /// Parses `euclidean`, `l2`, `l1`, `linf`, `lp:P` or
    /// `polygon:x1,y1,x2,y2,...` (the names [`Metric::name`] prints).
    pub fn parse(s: &str) -> Result<Self, MetricProblem> {
        let t = s.trim();
        match t.to_ascii_lowercase().as_str() {
            "euclidean" | "l2" => return Ok(Metric::euclidean()),
            "l1" | "manhattan" => return Ok(Metric::l1()),
            "linf" | "chebyshev" => return Ok(Metric::linf()),
            _ => {}
        }
        if let Some(p) = t.strip_prefix("lp:") {
            let p: u32 = p
                .trim()
                .parse()
                .map_err(|_| MetricProblem::UnknownMetric(s.to_string()))?;
            return Metric::lp(p);
        }
        if let Some(list) = t.strip_prefix("polygon:") {
            let mut coords = Vec::new();
            for c in list.split(',') {
                let v: f64 = c
                    .trim()
                    .parse()
                    .map_err(|_| MetricProblem::BadCoordinate(c.trim().to_string()))?;
                coords.push(v);
            }
            if coords.len() % 2 == 1 {
                return Err(MetricProblem::BadCoordinate(format!(
                    "{} numbers (x,y pairs expected)",
                    coords.len()
                )));
            }
            let vs: Vec<Point> = coords.chunks(2).map(|c| [c[0], c[1]]).collect();
            return Metric::polygon(&vs);
        }
        Err(MetricProblem::UnknownMetric(s.to_string()))
    }

    /// The canonical name: `euclidean`, `l1`, `linf`, `lp:P`,
    /// `polygon:x1,y1,...` (counter-clockwise vertices).
    pub fn name(&self) -> String {
        match &self.0 {
            Kind::Euclidean => "euclidean".into(),
            Kind::Power(p) => format!("lp:{p}"),
            Kind::L1(_) => "l1".into(),
            Kind::LInf(_) => "linf".into(),
            Kind::Polygon(poly) => {
                let c: Vec<String> = poly
                    .vertices
                    .iter()
                    .flatten()
                    .map(|v| format!("{v}"))
                    .collect();
                format!("polygon:{}", c.join(","))
            }
        }
    }

    /// Is this the Euclidean norm?
    pub fn is_euclidean(&self) -> bool {
        matches!(self.0, Kind::Euclidean)
    }

    /// Is the unit disk strictly convex (Euclidean, Lp with p ≥ 2)? The others
    /// are simulated (module docs).
    pub fn is_strictly_convex(&self) -> bool {
        matches!(self.0, Kind::Euclidean | Kind::Power(_))
    }

    /// The polygon's counter-clockwise vertices for polygonal norms (L1, L∞
    /// included).
    pub fn unit_polygon(&self) -> Option<&[Point]> {
        match &self.0 {
            Kind::L1(p) | Kind::LInf(p) | Kind::Polygon(p) => Some(&p.vertices),
            _ => None,
        }
    }

    /// A bound `R` with `‖v‖_∞ ≤ R·‖v‖` for every `v` (the unit disk lies in
    /// the square of half-side `R`).
    pub fn sup_radius(&self) -> f64 {
        match &self.0 {
            Kind::Euclidean | Kind::Power(_) => 1.0,
            Kind::L1(p) | Kind::LInf(p) | Kind::Polygon(p) => p
                .vertices
                .iter()
                .map(|v| v[0].abs().max(v[1].abs()))
                .fold(0.0, f64::max),
        }
    }

    /// The length of `ab` in this norm, rounded (for reporting only; every
    /// decision uses the exact comparisons).
    pub fn length(&self, a: Point, b: Point) -> f64 {
        let (dx, dy) = ((b[0] - a[0]).abs(), (b[1] - a[1]).abs());
        match &self.0 {
            Kind::Euclidean => dx.hypot(dy),
            Kind::Power(p) => {
                let m = dx.max(dy);
                if m == 0.0 {
                    return 0.0;
                }
                let r = dx.min(dy) / m;
                m * (1.0 + r.powi(*p as i32)).powf(1.0 / *p as f64)
            }
            Kind::L1(_) => dx + dy,
            Kind::LInf(_) => dx.max(dy),
            Kind::Polygon(poly) => poly.value_f64(b[0] - a[0], b[1] - a[1]),
        }
    }

    /// Exact comparison of `‖b − a‖` with `‖d − c‖` in this norm alone (no
    /// tie-break).
    pub fn compare_norm(&self, a: Point, b: Point, c: Point, d: Point) -> Ordering {
        let (dx1, dy1, dx2, dy2) = (b[0] - a[0], b[1] - a[1], d[0] - c[0], d[1] - c[1]);
        // Each rounded difference has relative error ≤ u.
        let decided = |l1: f64, l2: f64, e1: f64, e2: f64| -> Option<Ordering> {
            let ok = |v: f64| v.is_finite() && (v == 0.0 || (1e-280..1e280).contains(&v));
            if !(ok(l1) && ok(l2) && ok(e1) && ok(e2)) {
                return None;
            }
            if l1 - l2 > e1 + e2 {
                Some(Ordering::Greater)
            } else if l2 - l1 > e1 + e2 {
                Some(Ordering::Less)
            } else {
                None
            }
        };
        match &self.0 {
            Kind::Euclidean => compare_lengths(a, b, c, d),
            Kind::Power(p) => {
                // |d̃|ᵖ by repeated squaring: ≤ p factors of (1+u) from the
                // difference and ≤ 2·log₂p + 1 from the products, one more from
                // the sum; (2p + 8)·u bounds the total relative error for p ≤ 64.
                let p = *p;
                let s1 = dx1.abs().powi(p as i32) + dy1.abs().powi(p as i32);
                let s2 = dx2.abs().powi(p as i32) + dy2.abs().powi(p as i32);
                let g = (2 * p + 8) as f64 * U;
                decided(s1, s2, g * s1, g * s2).unwrap_or_else(|| {
                    let e = |dx: BigRational, dy: BigRational| {
                        num_traits::pow(dx.abs(), p as usize)
                            + num_traits::pow(dy.abs(), p as usize)
                    };
                    e(diff(b[0], a[0]), diff(b[1], a[1]))
                        .cmp(&e(diff(d[0], c[0]), diff(d[1], c[1])))
                })
            }
            Kind::L1(_) => {
                let (s1, s2) = (dx1.abs() + dy1.abs(), dx2.abs() + dy2.abs());
                // (1+u)² per sum.
                decided(s1, s2, 3.0 * U * s1, 3.0 * U * s2)
                    .unwrap_or_else(|| self.compare_polygon_exact(a, b, c, d))
            }
            Kind::LInf(_) => {
                let (s1, s2) = (dx1.abs().max(dy1.abs()), dx2.abs().max(dy2.abs()));
                decided(s1, s2, 2.0 * U * s1, 2.0 * U * s2)
                    .unwrap_or_else(|| self.compare_polygon_exact(a, b, c, d))
            }
            Kind::Polygon(poly) => {
                // Per facet: a rounded coefficient (u), a rounded difference
                // (u), two products and a sum (3u): |error| ≤ 5u(1+u)⁵ ·
                // (|a||dx| + |b||dy|) ≤ 6u · weight · (|dx̃| + |dỹ|)(1+u).
                let (s1, s2) = (poly.value_f64(dx1, dy1), poly.value_f64(dx2, dy2));
                let e = |dx: f64, dy: f64| 7.0 * U * poly.weight * (dx.abs() + dy.abs());
                decided(s1, s2, e(dx1, dy1), e(dx2, dy2))
                    .unwrap_or_else(|| self.compare_polygon_exact(a, b, c, d))
            }
        }
    }

    fn compare_polygon_exact(&self, a: Point, b: Point, c: Point, d: Point) -> Ordering {
        let poly = self.polygon_norm().expect("a polygonal norm");
        poly.value_exact(&diff(b[0], a[0]), &diff(b[1], a[1]))
            .cmp(&poly.value_exact(&diff(d[0], c[0]), &diff(d[1], c[1])))
    }

    fn polygon_norm(&self) -> Option<&PolygonNorm> {
        match &self.0 {
            Kind::L1(p) | Kind::LInf(p) | Kind::Polygon(p) => Some(p),
            _ => None,
        }
    }

    /// Exact comparison by the norm, then (if equal) by the Euclidean length:
    /// steps 1–2 of the tie-break, without the perturbation.
    pub fn compare_norm_then_euclidean(&self, a: Point, b: Point, c: Point, d: Point) -> Ordering {
        self.compare_norm(a, b, c, d).then_with(|| {
            if self.is_euclidean() {
                Ordering::Equal
            } else {
                compare_lengths(a, b, c, d)
            }
        })
    }

    /// Compares the lengths of segments `ab` and `cd` (indices into `points`)
    /// under this norm with the tie-break of the module docs: `Equal` only for
    /// the same pair of points. For the Euclidean norm this is
    /// [`crate::kernel::compare_lengths_symbolic`].
    pub fn compare_lengths_symbolic(
        &self,
        points: &[Point],
        ab: [u32; 2],
        cd: [u32; 2],
    ) -> Ordering {
        if self.is_euclidean() {
            return compare_lengths_symbolic(points, ab, cd);
        }
        let p = |m: u32| points[m as usize];
        let first = self.compare_norm_then_euclidean(p(ab[0]), p(ab[1]), p(cd[0]), p(cd[1]));
        if first != Ordering::Equal {
            return first;
        }
        let same = (ab[0] == cd[0] && ab[1] == cd[1]) || (ab[0] == cd[1] && ab[1] == cd[0]);
        if same {
            return Ordering::Equal;
        }
        let mut norm_part = self.perturbed_norm(points, ab);
        norm_part.subtract(&self.perturbed_norm(points, cd));
        let mut euclid = power_series(points, ab, 2);
        euclid.subtract(&power_series(points, cd, 2));
        match (norm_part.leading(), euclid.leading()) {
            (Some((en, sn)), Some((ee, se))) => {
                if en <= ee {
                    sn
                } else {
                    se
                }
            }
            (Some((_, s)), None) | (None, Some((_, s))) => s,
            (None, None) => compare_lengths_symbolic(points, ab, cd),
        }
    }

    /// Is `x` strictly inside the lune of `pq` under this norm and its
    /// tie-break: `max(|px|, |qx|) < |pq|`?
    pub fn in_lune_symbolic(&self, points: &[Point], p: u32, q: u32, x: u32) -> bool {
        self.compare_lengths_symbolic(points, [p, x], [p, q]) == Ordering::Less
            && self.compare_lengths_symbolic(points, [q, x], [p, q]) == Ordering::Less
    }

    /// Is `x` in the half-lune `η_pq` under this norm and its tie-break:
    /// strictly inside the lune of `pq` and to the left of `p → q` in the
    /// kernel's perturbation `S′` (where no point is on the line, so the
    /// closed and open half-planes agree)? The metric form of
    /// [`crate::kernel::lune::in_half_lune_symbolic`], for §6 step 1's stack scan.
    pub fn in_half_lune_symbolic(&self, points: &[Point], p: u32, q: u32, x: u32) -> bool {
        x != p
            && x != q
            && orient_symbolic(points, p, q, x) > 0
            && self.in_lune_symbolic(points, p, q, x)
    }

    /// `‖v + δ‖ − ‖v‖` (or its p-th power form) for segment `ab` as a series in ε.
    fn perturbed_norm(&self, points: &[Point], ab: [u32; 2]) -> Series {
        match &self.0 {
            Kind::Euclidean => power_series(points, ab, 2),
            Kind::Power(p) => power_series(points, ab, *p),
            Kind::L1(poly) | Kind::LInf(poly) | Kind::Polygon(poly) => {
                let [a, b] = ab;
                let (pa, pb) = (points[a as usize], points[b as usize]);
                let (dx, dy) = (diff(pb[0], pa[0]), diff(pb[1], pa[1]));
                let values: Vec<BigRational> = poly
                    .facets
                    .iter()
                    .map(|f| &f[0] * &dx + &f[1] * &dy)
                    .collect();
                let max = values.iter().max().expect("facets").clone();
                // The active facets (one, or two where v points at a vertex).
                let mut best: Option<Series> = None;
                for (f, value) in poly.facets.iter().zip(&values) {
                    if *value != max {
                        continue;
                    }
                    let mut s = Series::default();
                    for (c, coef) in [(0usize, &f[0]), (1usize, &f[1])] {
                        s.add(exponent(&[(var(b, c), 1)]), coef.clone());
                        s.add(exponent(&[(var(a, c), 1)]), -coef.clone());
                    }
                    best = Some(match best {
                        None => s,
                        Some(prev) => {
                            let mut d = s.clone();
                            d.subtract(&prev);
                            match d.leading() {
                                Some((_, Ordering::Greater)) => s,
                                _ => prev,
                            }
                        }
                    });
                }
                best.expect("an active facet")
            }
        }
    }
}

/// Exact sign of `d × (r − p)` for an exact direction `d`: which side of the
/// ray from `p` along `d` the point `r` lies (`1` left, `-1` right).
pub fn side_of_direction(d: Point, p: Point, r: Point) -> i32 {
    let (ry, rx) = (two_diff(r[1], p[1]), two_diff(r[0], p[0]));
    let f = d[0] * (r[1] - p[1]) - d[1] * (r[0] - p[0]);
    let bound = 4.0 * U * (d[0].abs() * (r[1] - p[1]).abs() + d[1].abs() * (r[0] - p[0]).abs());
    if f.abs() > bound && f.abs() > 1e-290 {
        return if f > 0.0 { 1 } else { -1 };
    }
    if d[0] == d[0].trunc() && d[1] == d[1].trunc() && d[0].abs() <= 1.0 && d[1].abs() <= 1.0 {
        return sign_of_sum(&[d[0] * r[1], -d[0] * p[1], -d[1] * r[0], d[1] * p[0]]);
    }
    let mut e = Expansion::new();
    e.add_two_term_product((d[0], 0.0), ry, 1.0);
    e.add_two_term_product((d[1], 0.0), rx, -1.0);
    e.sign()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn polygons_are_validated() {
        assert!(Metric::polygon(&[[1.0, 0.0], [0.0, 1.0], [-1.0, 0.0], [0.0, -1.0]]).is_ok());
        assert_eq!(
            Metric::polygon(&[[1.0, 0.0], [0.0, 1.0], [-1.0, 0.0]]).unwrap_err(),
            MetricProblem::VertexCount(3)
        );
        assert!(matches!(
            Metric::polygon(&[[1.0, 0.0], [0.0, 1.0], [-1.0, 0.0], [0.0, -2.0]]),
            Err(MetricProblem::NotCentrallySymmetric(_))
        ));
        // A valid hexagon; then a collinear corner and a star-shaped order.
        assert!(Metric::polygon(&[
            [1.0, 0.0],
            [1.0, 1.0],
            [0.0, 1.0],
            [-1.0, 0.0],
            [-1.0, -1.0],
            [0.0, -1.0]
        ])
        .is_ok());
        assert!(matches!(
            Metric::polygon(&[
                [1.0, 0.0],
                [1.0, 1.0],
                [1.0, 2.0],
                [-1.0, 0.0],
                [-1.0, -1.0],
                [-1.0, -2.0]
            ]),
            Err(MetricProblem::NotStrictlyConvex(_))
        ));
        assert!(matches!(
            Metric::polygon(&[
                [1.0, 0.0],
                [-1.0, 0.1],
                [0.0, 1.0],
                [-1.0, 0.0],
                [1.0, -0.1],
                [0.0, -1.0]
            ]),
            Err(MetricProblem::NotStrictlyConvex(_))
        ));
        assert!(Metric::parse("lp:0").is_err());
        assert!(Metric::parse("lp:x").is_err());
        assert!(Metric::parse("polygon:1,0,0").is_err());
        assert_eq!(Metric::parse("lp:3").unwrap().name(), "lp:3");
        assert_eq!(Metric::parse("lp:1").unwrap().name(), "l1");
    }

    #[test]
    fn perturbation_never_ties_distinct_segments() {
        let pts: Vec<Point> = (0..4)
            .flat_map(|x| (0..4).map(move |y| [x as f64, y as f64]))
            .collect();
        let segs: Vec<[u32; 2]> = (0..16u32)
            .flat_map(|a| (a + 1..16).map(move |b| [a, b]))
            .collect();
        for m in [Metric::l1(), Metric::linf(), Metric::lp(3).unwrap()] {
            let mut sorted = segs.clone();
            sorted.sort_by(|s, t| m.compare_lengths_symbolic(&pts, *s, *t));
            for w in sorted.windows(2) {
                assert_eq!(
                    m.compare_lengths_symbolic(&pts, w[0], w[1]),
                    Ordering::Less,
                    "{m}"
                );
                assert_eq!(
                    m.compare_lengths_symbolic(&pts, w[1], w[0]),
                    Ordering::Greater
                );
            }
        }
    }
}
