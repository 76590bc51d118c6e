//! Polygonal unit disks — L1, L∞ and any centrally symmetric convex
//! polygon — validated, with their facet functionals `‖v‖ = maxᵢ aᵢ·vx +
//! bᵢ·vy` as exact rationals and rounded (the norm module's docs, "Exact
//! comparisons"; H. Edelsbrunner & T. S. Tan, *A quadratic time algorithm
//! for the minmax length triangulation*, 1991, §7).

use super::super::predicates::orient_sign;
use super::super::{Point, UNIT_ROUNDOFF as U};
use super::{rational, to_f64, MetricProblem};
use num_rational::BigRational;

/// A polygonal unit disk: its counter-clockwise vertices and facet functionals.
#[derive(Clone, Debug)]
pub(super) struct PolygonNorm {
    pub(super) vertices: Vec<Point>,
    pub(super) facets: Vec<[BigRational; 2]>,
    facets_f64: Vec<[f64; 2]>,
    /// An upper bound on `max |aᵢ| + |bᵢ|` (for the filter).
    pub(super) weight: f64,
}

impl PolygonNorm {
    pub(super) fn new(vertices: &[Point]) -> Result<Self, MetricProblem> {
        let k = vertices.len();
        if k < 4 || k % 2 == 1 {
            return Err(MetricProblem::VertexCount(k));
        }
        for i in 0..k / 2 {
            let (v, w) = (vertices[i], vertices[i + k / 2]);
            if v[0] != -w[0] || v[1] != -w[1] {
                return Err(MetricProblem::NotCentrallySymmetric(i));
            }
        }
        let o = [0.0, 0.0];
        let mut vs = vertices.to_vec();
        if orient_sign(o, vs[0], vs[1]) < 0 {
            vs.reverse();
        }
        // Strictly convex corners, the origin strictly left of every edge,
        // and exactly one edge crossing the ray from the origin along +x
        // (winding number one, so not a star polygon).
        let mut crossings = 0;
        for i in 0..k {
            let (a, b, c) = (vs[i], vs[(i + 1) % k], vs[(i + 2) % k]);
            if orient_sign(o, a, b) <= 0 || orient_sign(a, b, c) <= 0 {
                return Err(MetricProblem::NotStrictlyConvex((i + 1) % k));
            }
            // Edge a→b (counter-clockwise about o) crosses the +x ray iff a is
            // below or on it and b above it (half-open, counts once).
            if a[1] <= 0.0 && b[1] > 0.0 && orient_sign(o, a, b) > 0 {
                crossings += 1;
            }
        }
        if crossings != 1 {
            return Err(MetricProblem::NotStrictlyConvex(0));
        }
        let mut facets = Vec::with_capacity(k);
        let mut facets_f64 = Vec::with_capacity(k);
        let mut weight: f64 = 0.0;
        for i in 0..k {
            let (a, b) = (vs[i], vs[(i + 1) % k]);
            let (ax, ay, bx, by) = (
                rational(a[0]),
                rational(a[1]),
                rational(b[0]),
                rational(b[1]),
            );
            // Outer normal (e_y, −e_x) of e = b − a; support value cross(a, b) > 0.
            let support = &ax * &by - &ay * &bx;
            let fa = (&by - &ay) / &support;
            let fb = (&ax - &bx) / &support;
            let f = [to_f64(&fa), to_f64(&fb)];
            weight = weight.max(f[0].abs() + f[1].abs());
            facets.push([fa, fb]);
            facets_f64.push(f);
        }
        Ok(PolygonNorm {
            vertices: vs,
            facets,
            facets_f64,
            weight: weight * (1.0 + 8.0 * U),
        })
    }

    pub(super) fn value_f64(&self, dx: f64, dy: f64) -> f64 {
        self.facets_f64
            .iter()
            .map(|f| f[0] * dx + f[1] * dy)
            .fold(f64::NEG_INFINITY, f64::max)
    }

    pub(super) fn value_exact(&self, dx: &BigRational, dy: &BigRational) -> BigRational {
        self.facets
            .iter()
            .map(|f| &f[0] * dx + &f[1] * dy)
            .max()
            .expect("at least 4 facets")
    }
}
