//! δ-triangulations by definition: the largest minus the smallest item of
//! a triangulation (triangle areas, all edge lengths, or all interior
//! angles), compared exactly in rational arithmetic, and the optimum by
//! exhaustive search over a list of triangulations.
//!
//! Independent of optri's kernel: areas are rationals; a length difference
//! `√a − √b` against `√c − √d` is decided by squaring twice (case analysis
//! on signs, never a square root); an angle is `arg(u·v, |u×v|)` and a sum
//! of two angles the argument of a complex product, ordered by quadrant and
//! then by a cross product.

use crate::exact::{squared_length, to_rational, twice_area, Point};
use num_rational::BigRational;
use num_traits::{Signed, Zero};
use std::cmp::Ordering;

/// The measure a δ is taken over.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DeltaMeasure {
    /// Triangle areas.
    Area,
    /// Interior angles of the triangles.
    Angle,
    /// Lengths of all edges, boundary included.
    Length,
}

type Q = BigRational;

/// `(u·v, |u×v|)` for the corner at `o` towards `a` and `b`.
fn corner(o: Point, a: Point, b: Point) -> [Q; 2] {
    let r = |p: Point| [to_rational(p[0]), to_rational(p[1])];
    let ([ox, oy], [ax, ay], [bx, by]) = (r(o), r(a), r(b));
    let (ux, uy, vx, vy) = (&ax - &ox, &ay - &oy, &bx - &ox, &by - &oy);
    [&ux * &vx + &uy * &vy, (&ux * &vy - &uy * &vx).abs()]
}

/// The sign of `r + √p − √q` for rationals `p, q ≥ 0`, by squaring.
fn sign_rational_plus_root_difference(r: &Q, p: &Q, q: &Q) -> Ordering {
    let zero = Q::zero();
    let roots = p.cmp(q); // sign of √p − √q
    match (r.cmp(&zero), roots) {
        (Ordering::Equal, s) => s,
        (s, Ordering::Equal) => s,
        (s, t) if s == t => s,
        (Ordering::Greater, _) => {
            // r > 0, √q > √p: compare r + √p with √q, i.e. (r + √p)² = r² + p
            // + 2r√p with q: 2r√p vs q − p − r².
            let rhs = q - p - r * r;
            if rhs.is_negative() {
                Ordering::Greater
            } else {
                let four = Q::from_integer(4.into());
                (four * r * r * p).cmp(&(&rhs * &rhs))
            }
        }
        (Ordering::Less, _) => {
            // r < 0, √p > √q: compare √p with √q − r = √q + |r|:
            // p vs q + r² + 2|r|√q.
            let lhs = p - q - r * r;
            if lhs.is_negative() {
                Ordering::Less
            } else {
                let four = Q::from_integer(4.into());
                (&lhs * &lhs).cmp(&(four * r * r * q))
            }
        }
    }
}

/// Compares `√a − √b` with `√c − √d` (rationals `≥ 0`).
fn compare_root_differences(a: &Q, b: &Q, c: &Q, d: &Q) -> Ordering {
    // √a + √d vs √c + √b; both sides ≥ 0, so compare their squares:
    // (a + d − c − b) + 2√(ad) − 2√(cb).
    let four = Q::from_integer(4.into());
    let r = a + d - c - b;
    sign_rational_plus_root_difference(&r, &(&four * a * d), &(four * c * b))
}

/// 0..=3: the quadrant of a non-zero vector's argument, `[0, π/2)`,
/// `[π/2, π)`, `[π, 3π/2)`, `[3π/2, 2π)`.
fn quadrant([x, y]: &[Q; 2]) -> u8 {
    match (x.cmp(&Q::zero()), y.cmp(&Q::zero())) {
        (Ordering::Greater, Ordering::Equal | Ordering::Greater) => 0,
        (Ordering::Less | Ordering::Equal, Ordering::Greater) => 1,
        (Ordering::Less, Ordering::Less | Ordering::Equal) => 2,
        _ => 3,
    }
}

fn compare_arguments(p: &[Q; 2], q: &[Q; 2]) -> Ordering {
    quadrant(p).cmp(&quadrant(q)).then_with(|| {
        let cross = &p[0] * &q[1] - &p[1] * &q[0];
        Q::zero().cmp(&cross)
    })
}

fn product(p: &[Q; 2], q: &[Q; 2]) -> [Q; 2] {
    [&p[0] * &q[0] - &p[1] * &q[1], &p[0] * &q[1] + &p[1] * &q[0]]
}

/// An item: a triangle (area), a corner `[apex, a, b]` (angle) or a
/// segment `[a, b, b]` (length), as point indices.
type Item = [u32; 3];

impl DeltaMeasure {
    fn items(self, tris: &[[u32; 3]]) -> Vec<Item> {
        let mut items = Vec::new();
        for &[a, b, c] in tris {
            match self {
                DeltaMeasure::Area => items.push([a, b, c]),
                DeltaMeasure::Angle => items.extend([[a, b, c], [b, c, a], [c, a, b]]),
                DeltaMeasure::Length => items.extend([[a, b, b], [b, c, c], [c, a, a]]),
            }
        }
        items
    }

    /// The exact value of an item: `[area, 0]`, `[squared length, 0]` or the
    /// angle's vector `(u·v, |u×v|)`.
    fn key(self, points: &[Point], i: Item) -> [Q; 2] {
        let p = |i: u32| points[i as usize];
        match self {
            DeltaMeasure::Area => [twice_area(p(i[0]), p(i[1]), p(i[2])), Q::zero()],
            DeltaMeasure::Length => [squared_length(p(i[0]), p(i[1])), Q::zero()],
            DeltaMeasure::Angle => corner(p(i[0]), p(i[1]), p(i[2])),
        }
    }

    fn compare_keys(self, s: &[Q; 2], t: &[Q; 2]) -> Ordering {
        match self {
            DeltaMeasure::Angle => compare_arguments(s, t),
            _ => s[0].cmp(&t[0]),
        }
    }

    /// The largest and the smallest item of a triangulation.
    fn extremes(self, points: &[Point], tris: &[[u32; 3]]) -> [Item; 2] {
        let keyed: Vec<(Item, [Q; 2])> = self
            .items(tris)
            .into_iter()
            .map(|i| (i, self.key(points, i)))
            .collect();
        let pick = |want: Ordering| {
            keyed
                .iter()
                .reduce(|a, b| {
                    if self.compare_keys(&b.1, &a.1) == want {
                        b
                    } else {
                        a
                    }
                })
                .expect("a triangle")
                .0
        };
        [pick(Ordering::Greater), pick(Ordering::Less)]
    }

    /// Compares `δ(s)` with `δ(t)` for two triangulations of `points`.
    pub fn compare(self, points: &[Point], s: &[[u32; 3]], t: &[[u32; 3]]) -> Ordering {
        self.compare_extremes(points, self.extremes(points, s), self.extremes(points, t))
    }

    /// Compares `high₁ − low₁` with `high₂ − low₂`.
    fn compare_extremes(
        self,
        points: &[Point],
        [h1, l1]: [Item; 2],
        [h2, l2]: [Item; 2],
    ) -> Ordering {
        let p = |i: u32| points[i as usize];
        match self {
            DeltaMeasure::Area => {
                let a = |i: Item| twice_area(p(i[0]), p(i[1]), p(i[2]));
                (a(h1) - a(l1)).cmp(&(a(h2) - a(l2)))
            }
            DeltaMeasure::Length => {
                let l = |i: Item| squared_length(p(i[0]), p(i[1]));
                compare_root_differences(&l(h1), &l(l1), &l(h2), &l(l2))
            }
            DeltaMeasure::Angle => {
                // θh1 − θl1 vs θh2 − θl2 ⇔ θh1 + θl2 vs θh2 + θl1, each sum
                // in [0, 2π) (no straight angle in a triangulation).
                let w = |i: Item| corner(p(i[0]), p(i[1]), p(i[2]));
                compare_arguments(&product(&w(h1), &w(l2)), &product(&w(h2), &w(l1)))
            }
        }
    }

    /// The least δ among `triangulations` (one of them, the first of
    /// equals). `None` if the list is empty.
    pub fn optimum<'a>(
        self,
        points: &[Point],
        triangulations: &'a [Vec<[u32; 3]>],
    ) -> Option<&'a Vec<[u32; 3]>> {
        let mut best: Option<(&Vec<[u32; 3]>, [Item; 2])> = None;
        for t in triangulations {
            let extremes = self.extremes(points, t);
            let better = best.as_ref().is_none_or(|(_, current)| {
                self.compare_extremes(points, extremes, *current) == Ordering::Less
            });
            if better {
                best = Some((t, extremes));
            }
        }
        best.map(|(t, _)| t)
    }

    /// `δ(tris)` rounded, for messages.
    pub fn approximate(self, points: &[Point], tris: &[[u32; 3]]) -> f64 {
        let [h, l] = self.extremes(points, tris);
        let p = |i: u32| points[i as usize];
        let value = |i: Item| -> f64 {
            let [o, a, b] = i.map(p);
            let (ux, uy, vx, vy) = (a[0] - o[0], a[1] - o[1], b[0] - o[0], b[1] - o[1]);
            match self {
                DeltaMeasure::Area => (ux * vy - uy * vx).abs(),
                DeltaMeasure::Length => ux.hypot(uy),
                DeltaMeasure::Angle => (ux * vy - uy * vx).abs().atan2(ux * vx + uy * vy),
            }
        };
        value(h) - value(l)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn root_differences_by_squaring() {
        let q = |v: i64| Q::from_integer(v.into());
        // √9 − √4 = 1 = √1 − √0
        assert_eq!(
            compare_root_differences(&q(9), &q(4), &q(1), &q(0)),
            Ordering::Equal
        );
        // √2 − 1 ≈ 0.414 < √3 − 1 ≈ 0.732
        assert_eq!(
            compare_root_differences(&q(2), &q(1), &q(3), &q(1)),
            Ordering::Less
        );
        // √8 − √2 = √2 = √2 − 0
        assert_eq!(
            compare_root_differences(&q(8), &q(2), &q(2), &q(0)),
            Ordering::Equal
        );
        // Against floats on a grid, where they are far apart.
        for a in 0..12 {
            for b in 0..12 {
                for c in 0..12 {
                    for d in 0..12 {
                        let f = |v: i64| (v as f64).sqrt();
                        let gap = (f(a) - f(b)) - (f(c) - f(d));
                        if gap.abs() > 1e-9 {
                            let want = gap.partial_cmp(&0.0).unwrap();
                            assert_eq!(
                                compare_root_differences(&q(a), &q(b), &q(c), &q(d)),
                                want,
                                "{a} {b} {c} {d}"
                            );
                        }
                    }
                }
            }
        }
    }

    #[test]
    fn angle_sums_by_quadrant() {
        // A square's triangles: angles 90, 45, 45; δ = 45° either way.
        let square = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        let a = vec![[0, 1, 2], [0, 2, 3]];
        let b = vec![[0, 1, 3], [1, 2, 3]];
        assert_eq!(
            DeltaMeasure::Angle.compare(&square, &a, &b),
            Ordering::Equal
        );
        assert!(
            (DeltaMeasure::Angle.approximate(&square, &a) - std::f64::consts::FRAC_PI_4).abs()
                < 1e-12
        );
    }
}
