//! Exact series in the perturbation's `ε` for the tie-break of the
//! simulated strictly convex norm (the norm module's docs, "Ties", step 3):
//! exponents `Σ digit·3^pos` in base 3 with carries, rational coefficients,
//! and the expansion of `|v_c + δ_c|ᵖ` (H. Edelsbrunner & E. P. Mücke,
//! *Simulation of Simplicity*, ACM TOG 9(1), 1990, with the kernel's
//! base-3 exponents).

use super::super::Point;
use super::diff;
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};
use std::cmp::Ordering;
use std::collections::BTreeMap;

/// The position of the perturbation variable of coordinate `c` (0 = x,
/// 1 = y) of point `m` in the base-3 exponent: `ε^(3^pos)`.
pub(super) fn var(m: u32, c: usize) -> u64 {
    2 * m as u64 + if c == 0 { 1 } else { 0 }
}

/// An exponent of ε, `Σ digit·3^pos`, normalised to base-3 digits and stored
/// from the highest position down, so that the derived order is numeric.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(super) struct Exponent(Vec<(u64, u64)>);

impl Ord for Exponent {
    fn cmp(&self, other: &Self) -> Ordering {
        for (x, y) in self.0.iter().zip(&other.0) {
            if x.0 != y.0 {
                return x.0.cmp(&y.0);
            }
            if x.1 != y.1 {
                return x.1.cmp(&y.1);
            }
        }
        self.0.len().cmp(&other.0.len())
    }
}
impl PartialOrd for Exponent {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

pub(super) fn exponent(terms: &[(u64, u64)]) -> Exponent {
    let mut digits: BTreeMap<u64, u64> = BTreeMap::new();
    for &(pos, k) in terms {
        if k > 0 {
            *digits.entry(pos).or_insert(0) += k;
        }
    }
    // Carry in base 3.
    let mut out = Vec::new();
    let mut carry = 0u64;
    let mut pos = match digits.keys().next() {
        Some(&p) => p,
        None => return Exponent(out),
    };
    loop {
        let d = digits.remove(&pos).unwrap_or(0) + carry;
        if !d.is_multiple_of(3) {
            out.push((pos, d % 3));
        }
        carry = d / 3;
        if carry == 0 {
            match digits.keys().next() {
                Some(&p) => pos = p,
                None => break,
            }
        } else {
            pos += 1;
        }
    }
    out.reverse();
    Exponent(out)
}

/// A finite series `Σ coefficient · ε^exponent`.
#[derive(Clone, Debug, Default)]
pub(super) struct Series(BTreeMap<Exponent, BigRational>);

impl Series {
    pub(super) fn add(&mut self, e: Exponent, c: BigRational) {
        if c.is_zero() {
            return;
        }
        let entry = self.0.entry(e).or_insert_with(BigRational::zero);
        *entry += c;
    }
    pub(super) fn subtract(&mut self, other: &Series) {
        for (e, c) in &other.0 {
            self.add(e.clone(), -c.clone());
        }
    }
    /// The smallest exponent with a non-zero coefficient, and its sign.
    pub(super) fn leading(&self) -> Option<(Exponent, Ordering)> {
        self.0
            .iter()
            .find(|(_, c)| !c.is_zero())
            .map(|(e, c)| (e.clone(), c.cmp(&BigRational::zero())))
    }
}

fn binomial(n: u32, k: u32) -> BigInt {
    let mut r = BigInt::one();
    for i in 0..k {
        r = r * BigInt::from(n - i) / BigInt::from(i + 1);
    }
    r
}

/// `Σ_c |v_c + δ_c|ᵖ − |v_c|ᵖ` for segment `ab` (`v = b − a`,
/// `δ_c = ε_{b,c} − ε_{a,c}`), expanded exactly.
pub(super) fn power_series(points: &[Point], ab: [u32; 2], p: u32) -> Series {
    let [a, b] = ab;
    let (pa, pb) = (points[a as usize], points[b as usize]);
    let mut s = Series::default();
    for c in 0..2 {
        let v = diff(pb[c], pa[c]);
        let (tb, ta) = (var(b, c), var(a, c));
        // (σ·(t_b − t_a))^k = σ^k Σ_j C(k,j) t_b^j (−t_a)^(k−j)
        let mut add_power = |k: u32, sigma: i32, scale: BigRational| {
            for j in 0..=k {
                let sign =
                    if (k - j) % 2 == 1 { -1 } else { 1 } * if k % 2 == 1 { sigma } else { 1 };
                let coef = &scale * BigRational::from_integer(binomial(k, j) * BigInt::from(sign));
                s.add(exponent(&[(tb, j as u64), (ta, (k - j) as u64)]), coef);
            }
        };
        if v.is_zero() {
            // |δ| = σδ, σ the sign of the dominant (lower-position) variable.
            let sigma = if tb < ta { 1 } else { -1 };
            add_power(p, sigma, BigRational::one());
        } else {
            let sigma = if v.is_positive() { 1 } else { -1 };
            let m = v.abs();
            for k in 1..=p {
                let scale = BigRational::from_integer(binomial(p, k))
                    * num_traits::pow(m.clone(), (p - k) as usize);
                add_power(k, sigma, scale);
            }
        }
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exponents_carry_in_base_3() {
        // t0³ = ε^3 equals the next variable's ε^(3^1).
        assert_eq!(exponent(&[(0, 3)]), exponent(&[(1, 1)]));
        assert!(exponent(&[(0, 2)]) < exponent(&[(1, 1)]));
        assert!(exponent(&[(0, 1), (1, 1)]) > exponent(&[(1, 1)]));
        assert!(exponent(&[(2, 1)]) > exponent(&[(0, 2), (1, 2)]));
    }
}
