//! Exact floating-point expansion arithmetic (Shewchuk 1997, §2).
//!
//! An *expansion* is a sum of `f64` components that are non-overlapping and
//! sorted by increasing magnitude, so its sign is the sign of its last
//! non-zero component. The `robust` crate keeps these routines private, so the
//! few we need for exact length and area comparisons live here.
//!
//! Exactness requires that no intermediate result overflows or underflows;
//! [`crate::PointSet`] enforces the coordinate range that guarantees this
//! (see [`crate::kernel::MAX_COORDINATE`]).

/// `a + b = s + e` exactly, with `s = fl(a + b)` (Knuth's TwoSum).
#[inline]
pub fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bv = s - a;
    let av = s - bv;
    (s, (a - av) + (b - bv))
}

/// `a - b = s + e` exactly, with `s = fl(a - b)`.
#[inline]
pub fn two_diff(a: f64, b: f64) -> (f64, f64) {
    two_sum(a, -b)
}

/// `a * b = p + e` exactly, with `p = fl(a * b)`; the error term comes from a
/// fused multiply-add, which is exact whenever the product does not underflow.
#[inline]
pub fn two_product(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    (p, a.mul_add(b, -p))
}

/// A growable exact sum of `f64` terms.
///
/// Terms are added one by one with Shewchuk's GROW-EXPANSION (with zero
/// elimination), which keeps the components non-overlapping and increasing.
#[derive(Clone, Debug, Default)]
pub struct Expansion {
    components: Vec<f64>,
}

impl Expansion {
    /// The empty sum (zero).
    pub fn new() -> Self {
        Self {
            components: Vec::with_capacity(32),
        }
    }

    /// Adds one term exactly.
    pub fn add(&mut self, b: f64) {
        let mut q = b;
        let mut out = 0;
        for i in 0..self.components.len() {
            let (s, e) = two_sum(q, self.components[i]);
            q = s;
            if e != 0.0 {
                self.components[out] = e;
                out += 1;
            }
        }
        self.components.truncate(out);
        if q != 0.0 {
            self.components.push(q);
        }
    }

    /// Adds the exact product `a * b`.
    pub fn add_product(&mut self, a: f64, b: f64) {
        let (p, e) = two_product(a, b);
        self.add(e);
        self.add(p);
    }

    /// Adds `sign * (a + b) * (c + d)` exactly, for exact two-term values.
    pub fn add_two_term_product(&mut self, (a, b): (f64, f64), (c, d): (f64, f64), sign: f64) {
        self.add_product(sign * a, c);
        self.add_product(sign * a, d);
        self.add_product(sign * b, c);
        self.add_product(sign * b, d);
    }

    /// Adds `sign * a * b` exactly, for expansions `a` and `b` and `sign` a
    /// power of two times ±1 (so that scaling a component is exact): every
    /// pair of components is multiplied exactly by [`two_product`].
    pub fn add_expansion_product(&mut self, a: &Expansion, b: &Expansion, sign: f64) {
        for &x in &a.components {
            for &y in &b.components {
                self.add_product(sign * x, y);
            }
        }
    }

    /// Adds `factor * other` exactly (each component's product by
    /// [`two_product`]).
    pub fn add_scaled(&mut self, other: &Expansion, factor: f64) {
        for &x in &other.components {
            self.add_product(x, factor);
        }
    }

    /// The components, non-overlapping, in increasing magnitude.
    pub fn components(&self) -> &[f64] {
        &self.components
    }

    /// The exact sign of the sum: -1, 0 or 1.
    pub fn sign(&self) -> i32 {
        match self.components.last() {
            None => 0,
            Some(&v) if v > 0.0 => 1,
            Some(_) => -1,
        }
    }
}

/// Sums of at most this many terms are expanded on the stack by
/// [`sign_of_sum`] (an expansion of `k` terms has at most `k` components);
/// longer ones use an [`Expansion`]. A chosen size: the length predicates
/// need at most 24 terms.
const STACK_TERMS: usize = 32;

/// The exact sign of `terms[0] + terms[1] + …`.
///
/// Called in the inner loops of exact sorts (every tie of rounded lengths),
/// so short sums avoid the heap: the same GROW-EXPANSION as
/// [`Expansion::add`] in a stack buffer, skipping zero terms (adding zero
/// leaves the sum unchanged).
pub fn sign_of_sum(terms: &[f64]) -> i32 {
    if terms.len() > STACK_TERMS {
        let mut e = Expansion::new();
        for &t in terms {
            e.add(t);
        }
        return e.sign();
    }
    let mut components = [0.0; STACK_TERMS];
    let mut len = 0;
    for &b in terms {
        if b == 0.0 {
            continue;
        }
        let mut q = b;
        let mut out = 0;
        for i in 0..len {
            let (s, e) = two_sum(q, components[i]);
            q = s;
            if e != 0.0 {
                components[out] = e;
                out += 1;
            }
        }
        len = out;
        if q != 0.0 {
            components[len] = q;
            len += 1;
        }
    }
    match len {
        0 => 0,
        _ if components[len - 1] > 0.0 => 1,
        _ => -1,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn two_sum_is_exact_where_naive_sum_loses_bits() {
        let (s, e) = two_sum(1.0, 1e-20);
        assert_eq!(s, 1.0);
        assert_eq!(e, 1e-20);
    }

    #[test]
    fn sign_of_sum_sees_cancelled_tiny_terms() {
        // 1e16 + 1 - 1e16 is 0 in naive f64 (ties to even) but 1 exactly.
        assert_eq!(1e16 + 1.0 - 1e16, 0.0);
        assert_eq!(sign_of_sum(&[1e16, 1.0, -1e16]), 1);
        assert_eq!(sign_of_sum(&[1e16, -1.0, -1e16]), -1);
        assert_eq!(sign_of_sum(&[1e16, -1e16]), 0);
        assert_eq!(sign_of_sum(&[]), 0);
    }

    #[test]
    fn sign_of_sum_on_the_stack_agrees_with_the_expansion() {
        // Sums with zeros, cancellations and components far apart, on both
        // sides of the stack buffer's size.
        let tiny = 2f64.powi(-60);
        let pattern = [
            1e16, 0.0, 1.0, -1e16, tiny, -tiny, 3.0, -4.0, 0.5, -0.5, 1e-300,
        ];
        for len in [0, 1, 2, 5, 11, STACK_TERMS, STACK_TERMS + 1, 40] {
            for shift in 0..pattern.len() {
                let terms: Vec<f64> = (0..len)
                    .map(|i| {
                        pattern[(i + shift) % pattern.len()] * if i % 3 == 0 { -1.0 } else { 1.0 }
                    })
                    .collect();
                let mut e = Expansion::new();
                for &t in &terms {
                    e.add(t);
                }
                assert_eq!(sign_of_sum(&terms), e.sign(), "{terms:?}");
            }
        }
    }

    #[test]
    fn products_of_expansions_are_exact() {
        // (1 + 2^-60)(1 - 2^-60) = 1 - 2^-120, invisible in f64.
        let tiny = 2f64.powi(-60);
        let (mut a, mut b) = (Expansion::new(), Expansion::new());
        a.add(1.0);
        a.add(tiny);
        b.add(1.0);
        b.add(-tiny);
        let mut e = Expansion::new();
        e.add_expansion_product(&a, &b, 2.0);
        e.add(-2.0);
        assert_eq!(e.sign(), -1);
        e.add(2.0 * tiny * tiny);
        assert_eq!(e.sign(), 0);
    }
}
