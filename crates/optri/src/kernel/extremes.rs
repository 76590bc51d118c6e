//! The extreme triangles and corners of a triangulation — smallest and
//! largest area, sharpest and widest angle — chosen by exact comparison in
//! one pass, so that only those four are measured (module `metrics`).
//!
//! Each candidate's filter terms are computed once and kept with the
//! current extreme ([`AreaKey`], [`CornerKey`]); a comparison evaluates the
//! filters of [`compare_areas`] and [`compare_corner_angles`] on the kept
//! terms (their error bounds are derived there) and calls those predicates
//! only when the filter cannot decide. Ties go to the earliest triangle (and
//! within a triangle to the earliest corner), so the choice is the one of a
//! sequential scan whatever the blocks of a parallel one.

use super::predicates::{compare_areas, compare_corner_angles, rounded_cross_dot};
use super::rounding::U;
use super::Point;
use std::cmp::Ordering;

/// A triangle with the filter terms of [`compare_areas`]: the rounded
/// doubled area `|l − r|` and its error scale `|l| + |r|`.
#[derive(Clone, Copy, Debug)]
struct AreaKey {
    corners: [Point; 3],
    doubled: f64,
    scale: f64,
}

impl AreaKey {
    #[inline]
    fn of(corners: [Point; 3]) -> Self {
        let [a, b, c] = corners;
        let l = (b[0] - a[0]) * (c[1] - a[1]);
        let r = (b[1] - a[1]) * (c[0] - a[0]);
        AreaKey {
            corners,
            doubled: (l - r).abs(),
            scale: l.abs() + r.abs(),
        }
    }

    /// Exact: this area against `other`'s.
    #[inline]
    fn compare(&self, other: &Self) -> Ordering {
        filtered(
            self.doubled - other.doubled,
            8.0 * U * (self.scale + other.scale),
            || compare_areas(self.corners, other.corners),
        )
    }
}

/// A corner of a counter-clockwise triangle (apex first) with the filter
/// terms of [`compare_corner_angles`]: rounded cross and dot products and
/// their permanents. The cross product is positive exactly (the corner's
/// orientation), which the filter needs.
#[derive(Clone, Copy, Debug)]
struct CornerKey {
    corner: [Point; 3],
    terms: [f64; 4],
}

impl CornerKey {
    #[inline]
    fn of(corner: [Point; 3]) -> Self {
        CornerKey {
            corner,
            terms: rounded_cross_dot(corner[0], corner[1], corner[2]),
        }
    }

    /// Exact: this angle against `other`'s (both in `(0°, 180°)`).
    #[inline]
    fn compare(&self, other: &Self) -> Ordering {
        let [cp, dp, pcp, pdp] = self.terms;
        let [cq, dq, pcq, pdq] = other.terms;
        filtered(
            dq * cp - dp * cq,
            16.0 * U * (pdq * pcp + pdp * pcq),
            || compare_corner_angles(self.corner, other.corner),
        )
    }
}

/// `later` if it compares as `wins` against `earlier`, else `earlier` (a
/// tie keeps the earlier).
#[inline]
fn keep_first<T>(earlier: T, later: T, compare: impl Fn(&T, &T) -> Ordering, wins: Ordering) -> T {
    if compare(&later, &earlier) == wins {
        later
    } else {
        earlier
    }
}

/// The sign of a filtered difference when it exceeds its error bound
/// `tolerance`, else the `exact` decision.
#[inline]
fn filtered(difference: f64, tolerance: f64, exact: impl FnOnce() -> Ordering) -> Ordering {
    if difference > tolerance {
        Ordering::Greater
    } else if -difference > tolerance {
        Ordering::Less
    } else {
        exact()
    }
}

/// The extremes of a run of counter-clockwise triangles: triangle positions
/// and, for corners, the corner's number `j` (the apex is the triangle's
/// `j`-th point, the rays go to the next two in cyclic order).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Extremes {
    smallest: (usize, AreaKey),
    largest: (usize, AreaKey),
    sharpest: ((usize, usize), CornerKey),
    widest: ((usize, usize), CornerKey),
}

impl Extremes {
    /// The extremes of `triangles` (strictly counter-clockwise, at least
    /// one), numbered from `first`.
    ///
    /// # Panics
    /// If `triangles` is empty.
    pub(crate) fn of(first: usize, triangles: impl IntoIterator<Item = [Point; 3]>) -> Self {
        let mut triangles = triangles.into_iter();
        let t = triangles.next().expect("at least one triangle");
        let corner =
            |t: [Point; 3], j: usize| CornerKey::of([t[j], t[(j + 1) % 3], t[(j + 2) % 3]]);
        let area = AreaKey::of(t);
        let corner0 = corner(t, 0);
        let mut e = Extremes {
            smallest: (first, area),
            largest: (first, area),
            sharpest: ((first, 0), corner0),
            widest: ((first, 0), corner0),
        };
        e.add_corners(first, t, 1, corner);
        for (i, t) in (first + 1..).zip(triangles) {
            let area = AreaKey::of(t);
            if area.compare(&e.smallest.1).is_lt() {
                e.smallest = (i, area);
            }
            if area.compare(&e.largest.1).is_gt() {
                e.largest = (i, area);
            }
            e.add_corners(i, t, 0, corner);
        }
        e
    }

    /// Takes triangle `i`'s corners from `from` on as candidates.
    #[inline]
    fn add_corners(
        &mut self,
        i: usize,
        t: [Point; 3],
        from: usize,
        corner: impl Fn([Point; 3], usize) -> CornerKey,
    ) {
        for j in from..3 {
            let c = corner(t, j);
            if c.compare(&self.sharpest.1).is_lt() {
                self.sharpest = ((i, j), c);
            }
            if c.compare(&self.widest.1).is_gt() {
                self.widest = ((i, j), c);
            }
        }
    }

    /// The extremes of this run followed by `later` (ties keep this run's).
    pub(crate) fn merge(self, later: Self) -> Self {
        use Ordering::{Greater, Less};
        Extremes {
            smallest: keep_first(
                self.smallest,
                later.smallest,
                |a, b| a.1.compare(&b.1),
                Less,
            ),
            largest: keep_first(
                self.largest,
                later.largest,
                |a, b| a.1.compare(&b.1),
                Greater,
            ),
            sharpest: keep_first(
                self.sharpest,
                later.sharpest,
                |a, b| a.1.compare(&b.1),
                Less,
            ),
            widest: keep_first(self.widest, later.widest, |a, b| a.1.compare(&b.1), Greater),
        }
    }

    /// The position of the triangle of smallest area.
    pub(crate) fn smallest(&self) -> usize {
        self.smallest.0
    }

    /// The position of the triangle of largest area.
    pub(crate) fn largest(&self) -> usize {
        self.largest.0
    }

    /// The sharpest corner: (triangle position, corner number).
    pub(crate) fn sharpest(&self) -> (usize, usize) {
        self.sharpest.0
    }

    /// The widest corner: (triangle position, corner number).
    pub(crate) fn widest(&self) -> (usize, usize) {
        self.widest.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn extremes_are_exact_and_ties_keep_the_first() {
        // Two congruent right triangles (ties), a thin one and a big one.
        let triangles = [
            [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]],
            [[5.0, 5.0], [6.0, 5.0], [5.0, 6.0]],
            [[0.0, 0.0], [1e8, 1.0], [-1e8, 1.0 + 2f64.powi(-30)]],
            [[0.0, 0.0], [10.0, 0.0], [0.0, 10.0]],
        ];
        let all = Extremes::of(0, triangles);
        assert_eq!(all.smallest(), 0);
        assert_eq!(all.largest(), 2);
        // The thin triangle's corners at (1e8, 1) and (−1e8, …) are the
        // sharpest; the one at the origin, nearly flat, the widest.
        assert_eq!(all.widest(), (2, 0));
        assert!(all.sharpest().0 == 2 && all.sharpest().1 != 0);
        // Any split into runs gives the same choice.
        for split in 1..4 {
            let merged = Extremes::of(0, triangles[..split].iter().copied())
                .merge(Extremes::of(split, triangles[split..].iter().copied()));
            assert_eq!(merged.smallest(), all.smallest());
            assert_eq!(merged.largest(), all.largest());
            assert_eq!(merged.sharpest(), all.sharpest());
            assert_eq!(merged.widest(), all.widest());
        }
        // The two right triangles tie corner for corner: the first one's
        // corners are chosen.
        let right = Extremes::of(0, triangles[..2].iter().copied());
        assert_eq!(right.widest(), (0, 0));
        assert_eq!(right.sharpest(), (0, 1));
    }
}
