//! The symbolic perturbation; see the kernel's module docs, section
//! "Ties: symbolic perturbation", for the scheme and why base 3.

use super::expansion::{sign_of_sum, two_diff, Expansion};
use super::predicates::{compare_lengths, orient_sign};
use super::Point;
use std::cmp::Ordering;

/// Orientation of points `i, j, k` of `points` under the symbolic perturbation:
/// `1` (counter-clockwise) or `-1` (clockwise), never `0` for distinct points.
///
/// # Panics
/// If two of the indices are equal or two of the points coincide.
pub fn orient_symbolic(points: &[Point], i: u32, j: u32, k: u32) -> i32 {
    let exact = orient_sign(points[i as usize], points[j as usize], points[k as usize]);
    if exact != 0 {
        return exact;
    }
    // Sort the indices ascending and track the permutation's parity.
    let mut idx = [i, j, k];
    let mut parity = 1;
    for a in 0..3 {
        for b in 0..2 - a {
            if idx[b] > idx[b + 1] {
                idx.swap(b, b + 1);
                parity = -parity;
            }
        }
    }
    assert!(
        idx[0] != idx[1] && idx[1] != idx[2],
        "orient_symbolic needs three distinct indices"
    );
    let [pi, pj, pk] = idx.map(|m| points[m as usize]);
    // Coefficients of ε_{y_i}, ε_{x_i}, ε_{y_j} in the perturbed determinant.
    let terms = [
        sign_of_sum(&[pk[0], -pj[0]]),
        sign_of_sum(&[pj[1], -pk[1]]),
        sign_of_sum(&[pi[0], -pk[0]]),
    ];
    let s = terms.into_iter().find(|&t| t != 0).unwrap_or_else(|| {
        panic!("orient_symbolic: coincident points {pi:?} {pj:?} {pk:?}");
    });
    s * parity
}

/// Compares the lengths of segments `ab` and `cd` (indices into `points`)
/// under the symbolic perturbation.
///
/// Returns `Equal` only if the two segments are the same pair of points.
/// Segments sharing an endpoint are handled (coefficients add up).
pub fn compare_lengths_symbolic(points: &[Point], ab: [u32; 2], cd: [u32; 2]) -> Ordering {
    let p = |m: u32| points[m as usize];
    compare_lengths(p(ab[0]), p(ab[1]), p(cd[0]), p(cd[1]))
        .then_with(|| compare_equal_lengths_symbolic(ab.map(|m| (m, p(m))), cd.map(|m| (m, p(m)))))
}

/// The order of [`compare_lengths_symbolic`] between two segments whose
/// lengths are *exactly equal*, each given by its endpoints' indices and
/// points; `Equal` only for the same pair of indices. Coordinate
/// comparisons only, no arithmetic.
///
/// Taking (index, point) pairs lets a caller that keeps the points in
/// another order (a renumbered copy) decide ties on the original indices
/// without looking the points up again.
///
/// Why this closed form: `f(ε) = |ab|² − |cd|²` after the perturbation is
/// `Σ_u (A_u + Σ_v α_v ε_v)² − (B_u + Σ_v β_v ε_v)²`, `A = a − b`,
/// `B = c − d`, `α_v = [v ∈ a] − [v ∈ b]`, `β_v` likewise, and `f(0) = 0`.
/// Its sign is that of the first non-zero coefficient by increasing
/// exponent (kernel docs); the largest perturbation is `ε_{y_m}` for the
/// smallest index `m` of the four, whose monomials `ε_{y_m}`, `ε_{y_m}²`
/// come before every other.
/// * `m` is an endpoint of one segment only, say `ab = {m, u}`: the linear
///   coefficient is `2(m − u)_y` and the square's is `α² − β² = 1`, so
///   `ab` is longer iff `m_y ≥ u_y` (symmetrically for `cd`). The segment
///   holding `m` is the one with the smaller lower index.
/// * `m` is shared, `ab = {m, u}`, `cd = {m, w}`: the linear coefficient
///   is `2(w − u)_y`, the square's `0`; next comes `ε_{x_m}` with
///   `2(w − u)_x`, which is non-zero when `u_y = w_y` as the points are
///   distinct. So `ab` is longer iff `(u_y, u_x) < (w_y, w_x)`
///   lexicographically.
///
/// The test `closed_form_equals_the_coefficient_walk` checks this against
/// the coefficient-by-coefficient evaluation it replaced.
pub fn compare_equal_lengths_symbolic(ab: [(u32, Point); 2], cd: [(u32, Point); 2]) -> Ordering {
    // Each segment as (lower index, its point, the other endpoint's point).
    let by_lower = |s: [(u32, Point); 2]| {
        if s[0].0 < s[1].0 {
            (s[0].0, s[0].1, s[1])
        } else {
            (s[1].0, s[1].1, s[0])
        }
    };
    let (m_ab, p_ab, u) = by_lower(ab);
    let (m_cd, p_cd, w) = by_lower(cd);
    // `Greater` iff the segment holding the smallest index is the longer.
    let longer_if = |holder_is_longer: bool| {
        if holder_is_longer {
            Ordering::Greater
        } else {
            Ordering::Less
        }
    };
    match m_ab.cmp(&m_cd) {
        Ordering::Less => longer_if(p_ab[1] >= u.1[1]),
        Ordering::Greater => longer_if(p_cd[1] >= w.1[1]).reverse(),
        Ordering::Equal if u.0 == w.0 => Ordering::Equal,
        // `ab` is longer iff u < w in (y, x) order.
        Ordering::Equal => (w.1[1], w.1[0])
            .partial_cmp(&(u.1[1], u.1[0]))
            .expect("finite coordinates"),
    }
}

/// Total order on segments used by every length-driven algorithm:
/// the symbolic length order of [`compare_lengths_symbolic`].
///
/// Segments are given as index pairs; the order does not depend on the
/// order of the two endpoints.
pub fn segment_order(points: &[Point]) -> impl Fn(&[u32; 2], &[u32; 2]) -> Ordering + '_ {
    move |s, t| compare_lengths_symbolic(points, *s, *t)
}

/// Sign of `(q − p) × (x − y)` under the kernel's perturbation `S′`.
///
/// For `x`, `y` on the right of `p → q` it is positive iff `x` is closer to
/// the line `pq` than `y`. Ties are broken by the first non-zero coefficient
/// of the ε-expansion, monomials ordered as in [the kernel's perturbation](crate::kernel#ties-symbolic-perturbation)
/// (`ε_r = ε^(3^r)`, rank `2m` for `y_m`, `2m + 1` for `x_m`). Needs four
/// distinct indices, except `x == y` which gives 0.
pub fn height_sign(points: &[Point], p: u32, q: u32, x: u32, y: u32) -> i32 {
    if x == y {
        return 0;
    }
    let pt = |m: u32| points[m as usize];
    let (pp, pq, px, py) = (pt(p), pt(q), pt(x), pt(y));
    // Floating-point filter: four rounded differences, two products and a
    // difference stay within 8u of the magnitudes; 1e-15 is a safe margin.
    let (ab, cd) = (
        (pq[0] - pp[0]) * (px[1] - py[1]),
        (pq[1] - pp[1]) * (px[0] - py[0]),
    );
    let approx = ab - cd;
    if approx.abs() > 1e-15 * (ab.abs() + cd.abs()) {
        return if approx > 0.0 { 1 } else { -1 };
    }
    let mut e = Expansion::new();
    e.add_two_term_product(two_diff(pq[0], pp[0]), two_diff(px[1], py[1]), 1.0);
    e.add_two_term_product(two_diff(pq[1], pp[1]), two_diff(px[0], py[0]), -1.0);
    let exact = e.sign();
    if exact != 0 {
        return exact;
    }
    let ry = |m: u32| 2 * m as u64;
    let rx = |m: u32| 2 * m as u64 + 1;
    let sgn = |a: f64, b: f64| (a > b) as i32 - (a < b) as i32;
    // D = A·B − C·E, A = q_x − p_x, B = x_y − y_y, C = q_y − p_y, E = x_x − y_x.
    let (a, b) = (sgn(pq[0], pp[0]), sgn(px[1], py[1]));
    let (c, d) = (sgn(pq[1], pp[1]), sgn(px[0], py[0]));
    let linear = [
        (rx(q), b),
        (rx(p), -b),
        (ry(x), a),
        (ry(y), -a),
        (ry(q), -d),
        (ry(p), d),
        (rx(x), -c),
        (rx(y), c),
    ];
    let pairs = [
        (rx(q), ry(x), 1),
        (rx(q), ry(y), -1),
        (rx(p), ry(x), -1),
        (rx(p), ry(y), 1),
        (ry(q), rx(x), -1),
        (ry(q), rx(y), 1),
        (ry(p), rx(x), 1),
        (ry(p), rx(y), -1),
    ];
    // Exponent order: compare the largest rank first; a single variable
    // precedes a pair with the same largest rank.
    let mut best: Option<((u64, Option<u64>), i32)> = None;
    let mut consider = |key: (u64, Option<u64>), s: i32| {
        if s != 0 && best.is_none_or(|(k, _)| key < k) {
            best = Some((key, s));
        }
    };
    for (r, s) in linear {
        consider((r, None), s);
    }
    for (r1, r2, s) in pairs {
        consider((r1.max(r2), Some(r1.min(r2))), s);
    }
    best.expect("distinct points have a non-zero perturbed cross product")
        .1
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::cmp::Ordering::*;

    #[test]
    fn orientation_is_antisymmetric_and_never_zero() {
        let pts = [
            [0.0, 0.0],
            [1.0, 1.0],
            [2.0, 2.0],
            [3.0, 0.0],
            [0.0, 5.0],
            [0.0, 7.0],
        ];
        for i in 0..6u32 {
            for j in 0..6u32 {
                for k in 0..6u32 {
                    if i == j || j == k || i == k {
                        continue;
                    }
                    let s = orient_symbolic(&pts, i, j, k);
                    assert!(s == 1 || s == -1);
                    assert_eq!(orient_symbolic(&pts, j, i, k), -s);
                    assert_eq!(orient_symbolic(&pts, j, k, i), s);
                }
            }
        }
    }

    /// The coefficient-by-coefficient evaluation of the perturbed length
    /// difference that [`compare_equal_lengths_symbolic`]'s closed form
    /// replaced (for two distinct segments of exactly equal length).
    fn equal_lengths_by_coefficient_walk(points: &[Point], ab: [u32; 2], cd: [u32; 2]) -> Ordering {
        let [a, b] = ab;
        let [c, d] = cd;
        let p = |m: u32| points[m as usize];
        let alpha = |m: u32| (m == a) as i32 - (m == b) as i32;
        let beta = |m: u32| (m == c) as i32 - (m == d) as i32;
        let mut ms = [a, b, c, d];
        ms.sort_unstable();
        let mut vars: Vec<(u32, usize)> = Vec::new(); // (point, coord) by increasing rank
        for (n, &m) in ms.iter().enumerate() {
            if n > 0 && ms[n - 1] == m {
                continue;
            }
            vars.push((m, 1)); // y first: rank 2m
            vars.push((m, 0)); // then x: rank 2m+1
        }
        let to_ordering = |s: i32| if s > 0 { Greater } else { Less };
        for (n, &(m, u)) in vars.iter().enumerate() {
            let (al, be) = (alpha(m), beta(m));
            let (al_f, be_f) = (al as f64, be as f64);
            let lin = sign_of_sum(&[
                al_f * p(a)[u],
                -al_f * p(b)[u],
                -be_f * p(c)[u],
                be_f * p(d)[u],
            ]);
            if lin != 0 {
                return to_ordering(lin);
            }
            for &(w, uw) in &vars[..n] {
                if uw != u {
                    continue;
                }
                let cross = al * alpha(w) - be * beta(w);
                if cross != 0 {
                    return to_ordering(cross);
                }
            }
            let square = al * al - be * be;
            if square != 0 {
                return to_ordering(square);
            }
        }
        unreachable!("distinct segments always differ under the perturbation")
    }

    #[test]
    fn closed_form_equals_the_coefficient_walk() {
        // Small integer grids (most lengths tie, many segments share an
        // endpoint), numbered in several orders, every pair of distinct
        // segments with exactly equal lengths, plus huge and negative
        // coordinates of the same shape.
        let mut ties = 0;
        for (side, scale, shift) in [
            (4, 1.0, 0.0),
            (5, 3.0, -7.0),
            (4, 1e40, -2e40),
            (3, 1e-30, 0.0),
        ] {
            let base: Vec<Point> = (0..side * side)
                .map(|k| [(k % side) as f64 * scale + shift, (k / side) as f64 * scale])
                .collect();
            for numbering in 0..4usize {
                // A different index order each time: reversed, strided (7 is
                // prime to 9, 16 and 25), rotated.
                let n = base.len();
                let pts: Vec<Point> = (0..n)
                    .map(|i| match numbering {
                        0 => base[i],
                        1 => base[n - 1 - i],
                        2 => base[(i * 7) % n],
                        _ => base[(i + n / 2) % n],
                    })
                    .collect();
                let segs: Vec<[u32; 2]> = (0..n as u32)
                    .flat_map(|i| (i + 1..n as u32).map(move |j| [i, j]))
                    .collect();
                for s in &segs {
                    for t in &segs {
                        let p = |m: u32| pts[m as usize];
                        if s == t || compare_lengths(p(s[0]), p(s[1]), p(t[0]), p(t[1])) != Equal {
                            continue;
                        }
                        ties += 1;
                        let walk = equal_lengths_by_coefficient_walk(&pts, *s, *t);
                        for (s2, t2) in [(*s, *t), ([s[1], s[0]], *t), (*s, [t[1], t[0]])] {
                            assert_eq!(
                                compare_lengths_symbolic(&pts, s2, t2),
                                walk,
                                "{s2:?} {t2:?}"
                            );
                        }
                    }
                }
            }
        }
        assert!(ties > 10_000, "only {ties} ties");
    }

    #[test]
    fn length_order_is_total_and_antisymmetric_on_a_grid() {
        let mut pts = Vec::new();
        for x in 0..3 {
            for y in 0..3 {
                pts.push([x as f64, y as f64]);
            }
        }
        let n = pts.len() as u32;
        let mut segs = Vec::new();
        for i in 0..n {
            for j in i + 1..n {
                segs.push([i, j]);
            }
        }
        for s in &segs {
            for t in &segs {
                let o = compare_lengths_symbolic(&pts, *s, *t);
                assert_eq!(o == Equal, s == t);
                assert_eq!(compare_lengths_symbolic(&pts, *t, *s), o.reverse());
                assert_eq!(compare_lengths_symbolic(&pts, [s[1], s[0]], *t), o);
            }
        }
        // Sorting with it must be consistent (transitive); sort and re-check adjacent pairs.
        let mut sorted = segs.clone();
        sorted.sort_by(segment_order(&pts));
        for w in sorted.windows(2) {
            assert_eq!(compare_lengths_symbolic(&pts, w[0], w[1]), Less);
        }
        for a in 0..sorted.len() {
            for b in a + 1..sorted.len() {
                assert_eq!(compare_lengths_symbolic(&pts, sorted[a], sorted[b]), Less);
            }
        }
    }

    #[test]
    fn shared_endpoint_rule_matches_the_closed_form() {
        // |p-r| vs |p-q| with equal lengths; smallest index decides (see module docs).
        let pts = [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]];
        // p = 0 is the smallest index: sign f = -sign(r_y - q_y), f = |pr|² - |pq|².
        // r = 2 (y=1), q = 1 (y=0): f < 0.
        assert_eq!(compare_lengths_symbolic(&pts, [0, 2], [0, 1]), Less);
        // m = r is the smallest index: sign f = sign(r_y - p_y), else +1.
        let pts2 = [[0.0, 1.0], [1.0, 0.0], [0.0, 0.0]]; // r = 0, q = 1, p = 2
        assert_eq!(compare_lengths_symbolic(&pts2, [2, 0], [2, 1]), Greater);
        let pts3 = [[1.0, 0.0], [0.0, 1.0], [0.0, 0.0]]; // r_y = p_y: the +1 case
        assert_eq!(compare_lengths_symbolic(&pts3, [2, 0], [2, 1]), Greater);
        // m = q is the smallest index: sign f = sign(p_y - q_y), else -1.
        let pts4 = [[0.0, 1.0], [1.0, 0.0], [0.0, 0.0]]; // q = 0, r = 1, p = 2
        assert_eq!(compare_lengths_symbolic(&pts4, [2, 1], [2, 0]), Less);
    }
}
