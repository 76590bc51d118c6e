//! The edge-insertion bottleneck criteria by definition (M. Bern,
//! H. Edelsbrunner, D. Eppstein, S. Mitchell & T. S. Tan, *Edge insertion
//! for optimal triangulations*, DCG 10, 1993): minmax angle, maxmin height,
//! minmax (absolute) eccentricity and minmax slope, as exact rational
//! *badness* keys (larger is worse) and their minimum over every
//! triangulation ([`all_triangulations`], [`polygon_triangulations`]).
//!
//! The forms are chosen independently of optri's: the angle by the law of
//! cosines over squared side lengths, the height as the smallest of the
//! three altitudes, the eccentricity from the explicit circumcentre and its
//! distance to the closed triangle, the slope from the gradient solved by
//! Cramer's rule.

use crate::enumerate::all_triangulations;
use crate::exact::to_rational;
use crate::polygon::polygon_triangulations;
use crate::Point;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};
use std::collections::HashMap;

/// An edge-insertion bottleneck criterion.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Bottleneck {
    /// Minimise the largest angle.
    MinMaxAngle,
    /// Maximise the smallest altitude.
    MaxMinHeight,
    /// Minimise the largest circumcentre-to-triangle distance.
    MinMaxEccentricity,
    /// Minimise the largest gradient of the linear interpolant of `z`.
    MinMaxSlope,
}

impl Bottleneck {
    /// All four.
    pub const ALL: [Bottleneck; 4] = [
        Bottleneck::MinMaxAngle,
        Bottleneck::MaxMinHeight,
        Bottleneck::MinMaxEccentricity,
        Bottleneck::MinMaxSlope,
    ];
}

type Vector = [BigRational; 2];

fn vector(p: Point, q: Point) -> Vector {
    [
        to_rational(q[0]) - to_rational(p[0]),
        to_rational(q[1]) - to_rational(p[1]),
    ]
}

fn dot(u: &Vector, v: &Vector) -> BigRational {
    &u[0] * &v[0] + &u[1] * &v[1]
}

fn cross(u: &Vector, v: &Vector) -> BigRational {
    &u[0] * &v[1] - &u[1] * &v[0]
}

/// Squared distance from `p` to the closed segment `ab`.
fn segment_distance2(p: &Vector, a: &Vector, b: &Vector) -> BigRational {
    let ab = [&b[0] - &a[0], &b[1] - &a[1]];
    let ap = [&p[0] - &a[0], &p[1] - &a[1]];
    let t = (dot(&ap, &ab) / dot(&ab, &ab))
        .max(BigRational::zero())
        .min(BigRational::one());
    let d = [&ap[0] - &t * &ab[0], &ap[1] - &t * &ab[1]];
    dot(&d, &d)
}

/// The badness of triangle `t` (larger is worse), exactly: for angles the
/// largest corner's `−cos θ·|cos θ|`, for heights `−h²`, otherwise the
/// squared value. `z` is read only for slope.
pub fn badness(b: Bottleneck, points: &[Point], z: &[f64], t: [u32; 3]) -> BigRational {
    let p = |i: u32| points[i as usize];
    let [a, bb, c] = t.map(p);
    let (u, v) = (vector(a, bb), vector(a, c));
    let cr = cross(&u, &v);
    match b {
        Bottleneck::MinMaxAngle => {
            // Law of cosines: the angle opposite side s has
            // cos = (q² + r² − s²) / (2qr).
            let sides = [
                dot(&vector(bb, c), &vector(bb, c)),
                dot(&vector(c, a), &vector(c, a)),
                dot(&vector(a, bb), &vector(a, bb)),
            ];
            (0..3)
                .map(|i| {
                    let (s, q, r) = (&sides[i], &sides[(i + 1) % 3], &sides[(i + 2) % 3]);
                    let num = q + r - s;
                    let key = &num * &num / (BigRational::from_integer(4.into()) * q * r);
                    if num.is_negative() {
                        key
                    } else {
                        -key
                    }
                })
                .max()
                .expect("three corners")
        }
        Bottleneck::MaxMinHeight => {
            let smallest = [(a, bb), (bb, c), (c, a)]
                .iter()
                .map(|&(p, q)| {
                    let e = vector(p, q);
                    &cr * &cr / dot(&e, &e)
                })
                .min()
                .expect("three sides");
            -smallest
        }
        Bottleneck::MinMaxEccentricity => {
            let (uu, vv) = (dot(&u, &u), dot(&v, &v));
            let det = &cr * BigRational::from_integer(2.into());
            let m = [
                (&uu * &v[1] - &vv * &u[1]) / &det,
                (&vv * &u[0] - &uu * &v[0]) / &det,
            ];
            let o = [BigRational::zero(), BigRational::zero()];
            let side = |p: &Vector, q: &Vector| {
                cross(
                    &[&q[0] - &p[0], &q[1] - &p[1]],
                    &[&m[0] - &p[0], &m[1] - &p[1]],
                )
                .signum()
            };
            let orientation = cr.signum();
            let inside = [side(&o, &u), side(&u, &v), side(&v, &o)]
                .iter()
                .all(|s| s.is_zero() || *s == orientation);
            if inside {
                BigRational::zero()
            } else {
                [
                    segment_distance2(&m, &o, &u),
                    segment_distance2(&m, &u, &v),
                    segment_distance2(&m, &v, &o),
                ]
                .into_iter()
                .min()
                .expect("three sides")
            }
        }
        Bottleneck::MinMaxSlope => {
            let zi = |i: u32| to_rational(z[i as usize]);
            let (du, dv) = (zi(t[1]) - zi(t[0]), zi(t[2]) - zi(t[0]));
            let gx = (&du * &v[1] - &dv * &u[1]) / &cr;
            let gy = (&u[0] * &dv - &v[0] * &du) / &cr;
            &gx * &gx + &gy * &gy
        }
    }
}

/// The worst triangle's badness in `triangles`.
pub fn bottleneck(
    b: Bottleneck,
    points: &[Point],
    z: &[f64],
    triangles: &[[u32; 3]],
) -> BigRational {
    triangles
        .iter()
        .map(|&t| badness(b, points, z, t))
        .max()
        .expect("no triangles")
}

/// The smallest worst badness over `triangulations` (e.g. every
/// triangulation of `points`), each triangle's badness computed once.
pub fn optimum_over(
    b: Bottleneck,
    points: &[Point],
    z: &[f64],
    triangulations: &[Vec<[u32; 3]>],
) -> BigRational {
    let mut cache: HashMap<[u32; 3], BigRational> = HashMap::new();
    triangulations
        .iter()
        .map(|t| {
            t.iter()
                .map(|&tri| {
                    let mut key = tri;
                    key.sort_unstable();
                    cache
                        .entry(key)
                        .or_insert_with(|| badness(b, points, z, tri))
                        .clone()
                })
                .max()
                .expect("no triangles")
        })
        .min()
        .expect("a triangulation")
}

/// The optimum (smallest worst badness) over every triangulation of the
/// distinct `points` (at most about ten).
pub fn optimum(b: Bottleneck, points: &[Point], z: &[f64]) -> BigRational {
    optimum_over(b, points, z, &all_triangulations(points))
}

/// The optimum over every triangulation of the simple polygon `ring`, `z`
/// per ring position.
pub fn polygon_optimum(b: Bottleneck, ring: &[Point], z: &[f64]) -> BigRational {
    optimum_over(b, ring, z, &polygon_triangulations(ring))
}
