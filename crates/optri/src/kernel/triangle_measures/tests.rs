//! The measures against independent exact evaluations: angles by the
//! largest squared-cosine key over all three corners, heights as the
//! smallest of the three altitudes, eccentricity from the explicit
//! circumcentre and its distance to the closed triangle, slope from the
//! gradient solved by Cramer's rule.

use super::*;
use crate::kernel::orient_sign;
use num_traits::One;
use rand::{rngs::StdRng, Rng, SeedableRng};

fn rat(v: f64) -> BigRational {
    BigRational::from_float(v).unwrap()
}

fn sub(p: Point, q: Point) -> [BigRational; 2] {
    [rat(p[0]) - rat(q[0]), rat(p[1]) - rat(q[1])]
}

fn dot(u: &[BigRational; 2], v: &[BigRational; 2]) -> BigRational {
    &u[0] * &v[0] + &u[1] * &v[1]
}

fn cross(u: &[BigRational; 2], v: &[BigRational; 2]) -> BigRational {
    &u[0] * &v[1] - &u[1] * &v[0]
}

/// Squared distance from `p` to the closed segment `ab`.
fn segment_distance2(
    p: &[BigRational; 2],
    a: &[BigRational; 2],
    b: &[BigRational; 2],
) -> BigRational {
    let ab = [&b[0] - &a[0], &b[1] - &a[1]];
    let ap = [&p[0] - &a[0], &p[1] - &a[1]];
    let t = dot(&ap, &ab) / dot(&ab, &ab);
    let t = t.max(BigRational::zero()).min(BigRational::one());
    let q = [&a[0] + &t * &ab[0], &a[1] + &t * &ab[1]];
    let d = [&p[0] - &q[0], &p[1] - &q[1]];
    dot(&d, &d)
}

/// The independent value (squared; the angle as −cos θ·|cos θ| of the
/// largest corner).
fn reference(measure: TriangleMeasure, t: &Corners) -> BigRational {
    let ([a, b, c], z) = *t;
    match measure {
        TriangleMeasure::LargestAngle => (0..3)
            .map(|i| {
                let [o, p, q] = rotate([a, b, c], i);
                let (u, v) = (sub(p, o), sub(q, o));
                let d = dot(&u, &v);
                let key = &d * &d / (dot(&u, &u) * dot(&v, &v));
                if d.is_negative() {
                    key
                } else {
                    -key
                }
            })
            .max()
            .unwrap(),
        TriangleMeasure::SmallestHeight => {
            let cr = cross(&sub(b, a), &sub(c, a));
            [(a, b), (b, c), (c, a)]
                .iter()
                .map(|&(p, q)| {
                    let e = sub(p, q);
                    &cr * &cr / dot(&e, &e)
                })
                .min()
                .unwrap()
        }
        TriangleMeasure::Eccentricity => {
            // Circumcentre m relative to a: solves 2 m·u = |u|², 2 m·v = |v|².
            let (u, v) = (sub(b, a), sub(c, a));
            let (uu, vv) = (dot(&u, &u), dot(&v, &v));
            let det = cross(&u, &v) * BigRational::from_integer(2.into());
            let m = [
                (&uu * &v[1] - &vv * &u[1]) / &det,
                (&vv * &u[0] - &uu * &v[0]) / &det,
            ];
            let zero = [BigRational::zero(), BigRational::zero()];
            // Inside the closed triangle: all three orientations agree.
            let side = |p: &[BigRational; 2], q: &[BigRational; 2]| {
                let s = cross(
                    &[&q[0] - &p[0], &q[1] - &p[1]],
                    &[&m[0] - &p[0], &m[1] - &p[1]],
                );
                s.signum()
            };
            let orientation = cross(&u, &v).signum();
            let inside = [side(&zero, &u), side(&u, &v), side(&v, &zero)]
                .iter()
                .all(|s| s.is_zero() || *s == orientation);
            if inside {
                BigRational::zero()
            } else {
                [
                    segment_distance2(&m, &zero, &u),
                    segment_distance2(&m, &u, &v),
                    segment_distance2(&m, &v, &zero),
                ]
                .into_iter()
                .min()
                .unwrap()
            }
        }
        TriangleMeasure::Slope => {
            let (u, v) = (sub(b, a), sub(c, a));
            let (du, dv) = (rat(z[1]) - rat(z[0]), rat(z[2]) - rat(z[0]));
            let det = cross(&u, &v);
            // g·u = du, g·v = dv.
            let gx = (&du * &v[1] - &dv * &u[1]) / &det;
            let gy = (&u[0] * &dv - &v[0] * &du) / &det;
            &gx * &gx + &gy * &gy
        }
    }
}

const MEASURES: [TriangleMeasure; 4] = [
    TriangleMeasure::LargestAngle,
    TriangleMeasure::SmallestHeight,
    TriangleMeasure::Eccentricity,
    TriangleMeasure::Slope,
];

fn random_triangle(rng: &mut StdRng, span: i64, scale: f64, shift: f64) -> Option<Corners> {
    let mut c = || (rng.gen_range(-span..=span) as f64) * scale + shift;
    let t = [[c(), c()], [c(), c()], [c(), c()]];
    if orient_sign(t[0], t[1], t[2]) == 0 {
        return None;
    }
    let z = [
        rng.gen_range(0..4) as f64,
        rng.gen_range(0..4) as f64,
        rng.gen_range(0..4) as f64,
    ];
    Some((t, z))
}

fn check_pairs(seed: u64, span: i64, scale: f64, shift: f64, pairs: usize) -> usize {
    let mut rng = StdRng::seed_from_u64(seed);
    let mut equal = 0;
    let mut done = 0;
    while done < pairs {
        let (Some(s), Some(t)) = (
            random_triangle(&mut rng, span, scale, shift),
            random_triangle(&mut rng, span, scale, shift),
        ) else {
            continue;
        };
        done += 1;
        for m in MEASURES {
            let want = reference(m, &s).cmp(&reference(m, &t));
            assert_eq!(m.compare_values(&s, &t), want, "{m:?} {s:?} {t:?}");
            assert_eq!(exact_squared_value(m, &s), reference(m, &s), "{m:?} {s:?}");
            equal += usize::from(want == Ordering::Equal);
        }
    }
    equal
}

#[test]
fn comparisons_agree_with_independent_evaluations() {
    // Tiny boxes give many exact ties (right angles, isosceles, equal slopes).
    let ties = check_pairs(1, 3, 1.0, 0.0, 3000);
    assert!(ties > 300, "only {ties} ties");
    check_pairs(2, 1000, 1.0, 0.0, 1000);
    check_pairs(3, 1 << 40, 1.0, -7.5, 300);
    // Extremes: the filter gives up and the exact path decides.
    check_pairs(4, 50, 2f64.powi(190), 0.0, 200);
    check_pairs(5, 50, 2f64.powi(-130), 0.0, 200);
    check_pairs(6, 50, 1.0, 2f64.powi(40), 200);
}

#[test]
fn anchors_follow_their_rules() {
    // Right isosceles triangle: the right angle is opposite the hypotenuse.
    let t = ([[0.0, 0.0], [2.0, 0.0], [0.0, 2.0]], [0.0; 3]);
    assert_eq!(TriangleMeasure::LargestAngle.anchor(&t), 0);
    assert_eq!(TriangleMeasure::Eccentricity.anchor(&t), 0);
    // Equilateral-like tie: the first corner.
    let e = ([[0.0, 0.0], [4.0, 0.0], [2.0, 3.0]], [0.0; 3]);
    assert_eq!(TriangleMeasure::SmallestHeight.anchor(&e), 2);
    // Slope: z = x on a triangle whose middle vertex in y is corner 2, while
    // the middle elevation is corner 1.
    let s = ([[0.0, 0.0], [1.0, 10.0], [5.0, 3.0]], [0.0, 1.0, 5.0]);
    assert_eq!(TriangleMeasure::Slope.anchor(&s), 2);
    let s = ([[0.0, 0.0], [3.0, 10.0], [5.0, 3.0]], [0.0, 3.0, 5.0]);
    assert_eq!(TriangleMeasure::Slope.anchor(&s), 2);
}

#[test]
fn reported_values_are_correctly_rounded() {
    let t = ([[0.0, 0.0], [3.0, 0.0], [0.0, 4.0]], [0.0, 3.0, 0.0]);
    assert_eq!(TriangleMeasure::LargestAngle.reported(&t), 90.0);
    assert_eq!(TriangleMeasure::SmallestHeight.reported(&t), 2.4);
    assert_eq!(TriangleMeasure::Eccentricity.reported(&t), 0.0);
    assert_eq!(TriangleMeasure::Slope.reported(&t), 1.0);
    let obtuse = ([[0.0, 0.0], [4.0, 0.0], [2.0, 1.0]], [0.0; 3]);
    // Circumcentre (2, −1.5): distance 1.5 to the base.
    assert_eq!(TriangleMeasure::Eccentricity.reported(&obtuse), 1.5);
    let h = ([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]], [0.0, 1.0, 1.0]);
    assert_eq!(TriangleMeasure::Slope.reported(&h), 2f64.sqrt());
    assert_eq!(TriangleMeasure::SmallestHeight.reported(&h), 0.5f64.sqrt());
}
