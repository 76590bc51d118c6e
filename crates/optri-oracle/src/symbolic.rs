//! Independent evaluation of optri's symbolic perturbation
//! (simulation of simplicity with base-3 exponents):
//!
//! ```text
//!   y_m ← y_m + ε^(3^(2m))      x_m ← x_m + ε^(3^(2m+1))
//! ```
//!
//! Each predicate is expanded as a polynomial in `ε` with exact rational
//! coefficients, and its sign for infinitesimal `ε > 0` is the sign of the
//! lowest-order non-zero coefficient. Both predicates here have total degree
//! 2 in the perturbation variables, and the order of two exponents
//! `3^r + 3^s` (`r ≤ s`, or a single `3^r`) depends only on the relative order
//! of the ranks involved (base-3 digits ≤ 2 are unique). So the ranks of the
//! involved points are compressed to `0, 1, 2, …` by index order, which keeps
//! exponents below `2 · 3^8`.

use crate::exact::{to_rational, Point};
use num_rational::BigRational;
use num_traits::{Signed, Zero};
use std::cmp::Ordering;
use std::collections::BTreeMap;

/// A polynomial in `ε`: exponent → coefficient (no zero coefficients stored).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct EpsilonPolynomial(BTreeMap<u64, BigRational>);

impl EpsilonPolynomial {
    fn constant_plus_epsilon_power(c: f64, exponent: u64) -> Self {
        let mut m = BTreeMap::new();
        let c = to_rational(c);
        if !c.is_zero() {
            m.insert(0, c);
        }
        m.insert(exponent, BigRational::from_integer(1.into()));
        Self(m)
    }
    fn add_term(&mut self, e: u64, c: BigRational) {
        let entry = self.0.entry(e).or_insert_with(BigRational::zero);
        *entry += c;
        if entry.is_zero() {
            self.0.remove(&e);
        }
    }
    fn sub(&self, o: &Self) -> Self {
        let mut r = self.clone();
        for (&e, c) in &o.0 {
            r.add_term(e, -c.clone());
        }
        r
    }
    fn add(&self, o: &Self) -> Self {
        let mut r = self.clone();
        for (&e, c) in &o.0 {
            r.add_term(e, c.clone());
        }
        r
    }
    fn mul(&self, o: &Self) -> Self {
        let mut r = Self::default();
        for (&e, c) in &self.0 {
            for (&f, d) in &o.0 {
                r.add_term(e + f, c * d);
            }
        }
        r
    }
    /// The sign for infinitesimal `ε > 0`: of the lowest-order coefficient
    /// (`0` only for the zero polynomial).
    pub fn sign(&self) -> i32 {
        match self.0.values().next() {
            None => 0,
            Some(c) if c.is_positive() => 1,
            Some(_) => -1,
        }
    }
}

/// Perturbed coordinates `(x, y)` of the given point indices, with ranks
/// compressed by index order.
fn perturbed(points: &[Point], indices: &[u32]) -> Vec<(EpsilonPolynomial, EpsilonPolynomial)> {
    let mut sorted = indices.to_vec();
    sorted.sort_unstable();
    sorted.dedup();
    indices
        .iter()
        .map(|m| {
            let r = sorted.binary_search(m).unwrap() as u32;
            let p = points[*m as usize];
            (
                EpsilonPolynomial::constant_plus_epsilon_power(p[0], 3u64.pow(2 * r + 1)),
                EpsilonPolynomial::constant_plus_epsilon_power(p[1], 3u64.pow(2 * r)),
            )
        })
        .collect()
}

/// The perturbed orientation determinant of points `i, j, k` as a polynomial.
pub fn orient_polynomial(points: &[Point], i: u32, j: u32, k: u32) -> EpsilonPolynomial {
    let c = perturbed(points, &[i, j, k]);
    let (a, b, d) = (&c[0], &c[1], &c[2]);
    let ux = b.0.sub(&a.0);
    let uy = b.1.sub(&a.1);
    let vx = d.0.sub(&a.0);
    let vy = d.1.sub(&a.1);
    ux.mul(&vy).sub(&uy.mul(&vx))
}

/// The perturbed orientation of points `i, j, k` (indices into `points`):
/// `1`, `-1`, or `0` if two indices are equal.
pub fn orient_perturbed(points: &[Point], i: u32, j: u32, k: u32) -> i32 {
    orient_polynomial(points, i, j, k).sign()
}

/// `|ab|² − |cd|²` under the perturbation, as a polynomial.
pub fn length_difference_polynomial(
    points: &[Point],
    ab: [u32; 2],
    cd: [u32; 2],
) -> EpsilonPolynomial {
    let c = perturbed(points, &[ab[0], ab[1], cd[0], cd[1]]);
    let sq = |p: &(EpsilonPolynomial, EpsilonPolynomial),
              q: &(EpsilonPolynomial, EpsilonPolynomial)| {
        let dx = p.0.sub(&q.0);
        let dy = p.1.sub(&q.1);
        dx.mul(&dx).add(&dy.mul(&dy))
    };
    sq(&c[0], &c[1]).sub(&sq(&c[2], &c[3]))
}

/// Compares `|ab|` with `|cd|` under the perturbation (`Equal` only if the
/// polynomial vanishes, i.e. the same segment).
pub fn compare_lengths_perturbed(points: &[Point], ab: [u32; 2], cd: [u32; 2]) -> Ordering {
    length_difference_polynomial(points, ab, cd).sign().cmp(&0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn agrees_with_exact_predicates_when_not_degenerate() {
        let pts = [[0.0, 0.0], [3.0, 1.0], [1.0, 4.0], [0.5, 0.25]];
        assert_eq!(orient_perturbed(&pts, 0, 1, 2), 1);
        assert_eq!(orient_perturbed(&pts, 0, 2, 1), -1);
        assert_eq!(
            compare_lengths_perturbed(&pts, [0, 1], [0, 2]),
            Ordering::Less
        );
        assert_eq!(
            compare_lengths_perturbed(&pts, [1, 0], [0, 1]),
            Ordering::Equal
        );
    }

    #[test]
    fn resolves_collinear_and_equal_cases_by_index() {
        // Three collinear points on the x-axis. The lowest-order variable is
        // y_0 (exponent 3^0 = 1); the determinant (x1−x0)(y2−y0) − (y1−y0)(x2−x0)
        // has ∂/∂y0 = −(x1−x0) + (x2−x0) = 1 > 0.
        let pts = [[0.0, 0.0], [1.0, 0.0], [2.0, 0.0]];
        let p = orient_polynomial(&pts, 0, 1, 2);
        assert_eq!(p.sign(), 1);
        assert_eq!(p.0.keys().next(), Some(&1));
        // Equal lengths sharing endpoint 0: |01| = |02| on a unit L.
        let l = [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]];
        // f = |01|² − |02|²: lowest term comes from y_0 (exponent 1):
        // ∂/∂y0 = 2(y0−y1)·1 − 2(y0−y2) = 0 − (−2) = 2 > 0.
        assert_eq!(
            compare_lengths_perturbed(&l, [0, 1], [0, 2]),
            Ordering::Greater
        );
    }
}
