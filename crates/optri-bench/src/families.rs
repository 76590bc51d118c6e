//! The input families of the `families` harness: natural inputs that are
//! hard for some construction (convex position, cocircular and nearly
//! cocircular points, collinear runs, clusters a few ulps wide, repeated
//! points), each generated from a seed at a requested size. Integer
//! coordinates are exact doubles (below 2⁵³), so "on a circle" and "on a
//! parabola" hold exactly where the family says so.

use optri::kernel::Point;
use rand::{rngs::StdRng, Rng, SeedableRng};
use std::f64::consts::TAU;

/// What a family generates: a point set, or a simple polygon (its ring).
#[derive(Clone, Copy, PartialEq, Eq)]
pub enum Shape {
    /// A point set, for every criterion.
    Points,
    /// A simple polygon, for the criteria that take polygons.
    Polygon,
}

/// One family: a name for the command line and a generator.
pub struct Family {
    /// The name on the command line and in the table.
    pub name: &'static str,
    /// What it is, for `--help`.
    pub description: &'static str,
    /// Points or polygon.
    pub shape: Shape,
    /// The points (or the ring) for about `n` points.
    pub generate: fn(usize, &mut StdRng) -> Vec<Point>,
}

/// Every family, in table order.
pub const FAMILIES: &[Family] = &[
    Family {
        name: "uniform",
        description: "uniform random points in the unit square",
        shape: Shape::Points,
        generate: uniform,
    },
    Family {
        name: "near-circle",
        description: "points of a circle of radius n rounded to integers",
        shape: Shape::Points,
        generate: near_circle,
    },
    Family {
        name: "cocircular",
        description: "integer points on x²+y²=r², r=5·13·17·29·37·41 (at most 2916)",
        shape: Shape::Points,
        generate: cocircular,
    },
    Family {
        name: "polygon-f64",
        description: "regular n-gon (cos, sin) in doubles",
        shape: Shape::Points,
        generate: regular_polygon,
    },
    Family {
        name: "polygon-6dp",
        description: "the regular n-gon rounded to 6 decimals (as the integers 10⁶·x)",
        shape: Shape::Points,
        generate: regular_polygon_rounded,
    },
    Family {
        name: "parabola",
        description: "(x, x²) for n consecutive integers x",
        shape: Shape::Points,
        generate: parabola,
    },
    Family {
        name: "parabola+10%",
        description: "the parabola with 10% of the points random integers inside",
        shape: Shape::Points,
        generate: parabola_with_interior,
    },
    Family {
        name: "grid",
        description: "the √n × √n integer grid",
        shape: Shape::Points,
        generate: grid,
    },
    Family {
        name: "two-lines",
        description: "integer points on the lines y = x and y = -x",
        shape: Shape::Points,
        generate: two_lines,
    },
    Family {
        name: "ulp-clusters",
        description: "10 clusters, each a random set of a 2-D grid of ulp steps",
        shape: Shape::Points,
        generate: ulp_clusters,
    },
    Family {
        name: "duplicates",
        description: "n/2 uniform points, each given twice",
        shape: Shape::Points,
        generate: duplicates,
    },
    Family {
        name: "star-polygon",
        description: "a star-shaped polygon, random integer radii at equal angles",
        shape: Shape::Polygon,
        generate: star_polygon,
    },
    Family {
        name: "star-alternating",
        description:
            "a star-shaped polygon, radii alternating 1 and 1/2 at equal angles (cos, sin)",
        shape: Shape::Polygon,
        generate: alternating_star,
    },
    Family {
        name: "regular-polygon",
        description: "the regular n-gon (cos, sin) as a polygon: nearly cocircular, convex",
        shape: Shape::Polygon,
        generate: regular_polygon,
    },
];

fn uniform(n: usize, rng: &mut StdRng) -> Vec<Point> {
    (0..n).map(|_| [rng.gen(), rng.gen()]).collect()
}

/// The points at `n` equal angles on the circle of radius `n`, rounded to
/// integers (convex position up to rounding; repeats removed).
fn near_circle(n: usize, _: &mut StdRng) -> Vec<Point> {
    let r = n as f64;
    let mut points: Vec<Point> = (0..n)
        .map(|k| {
            let a = TAU * k as f64 / n as f64;
            [(r * a.cos()).round(), (r * a.sin()).round()]
        })
        .collect();
    points.dedup();
    points
}

/// The integer points of the circle `x² + y² = r²` for `r` the product of
/// the primes 5, 13, 17, 29, 37, 41 (all `1 mod 4`): `r² ≈ 2.4·10¹⁵ < 2⁵³`,
/// so every point is exact and all of them are exactly cocircular. They are
/// the Gaussian integers `u · ∏ πᵢ^kᵢ π̄ᵢ^(2-kᵢ)` (a unit times one choice
/// per prime `pᵢ = πᵢ π̄ᵢ`): 4 · 3⁶ = 2916 points; the first `n` by angle.
fn cocircular(n: usize, _: &mut StdRng) -> Vec<Point> {
    // pᵢ = aᵢ² + bᵢ².
    let primes: [(i64, i64); 6] = [(1, 2), (2, 3), (1, 4), (2, 5), (1, 6), (4, 5)];
    let mul = |(a, b): (i64, i64), (c, d): (i64, i64)| (a * c - b * d, a * d + b * c);
    let mut values = vec![(1i64, 0i64)];
    for &(a, b) in &primes {
        let pi = (a, b);
        let conj = (a, -b);
        let factors = [mul(pi, pi), mul(pi, conj), mul(conj, conj)];
        values = values
            .iter()
            .flat_map(|&v| factors.iter().map(move |&f| mul(v, f)))
            .collect();
    }
    let mut points: Vec<Point> = values
        .iter()
        .flat_map(|&(x, y)| [(x, y), (-y, x), (-x, -y), (y, -x)])
        .map(|(x, y)| [x as f64, y as f64])
        .collect();
    points.sort_by(|p, q| p[1].atan2(p[0]).total_cmp(&q[1].atan2(q[0])));
    points.dedup();
    points.truncate(n);
    points
}

fn regular_polygon(n: usize, _: &mut StdRng) -> Vec<Point> {
    (0..n)
        .map(|k| {
            let a = TAU * k as f64 / n as f64;
            [a.cos(), a.sin()]
        })
        .collect()
}

/// The regular polygon rounded to 6 decimals, as the integers `10⁶ · x`
/// that the front ends triangulate for decimal input (every criterion is
/// invariant under the scaling).
fn regular_polygon_rounded(n: usize, rng: &mut StdRng) -> Vec<Point> {
    let mut points: Vec<Point> = regular_polygon(n, rng)
        .iter()
        .map(|p| p.map(|c| (c * 1e6).round()))
        .collect();
    points.dedup();
    points
}

fn parabola(n: usize, _: &mut StdRng) -> Vec<Point> {
    let half = (n / 2) as i64;
    (0..n as i64)
        .map(|k| {
            let x = k - half;
            [x as f64, (x * x) as f64]
        })
        .collect()
}

fn parabola_with_interior(n: usize, rng: &mut StdRng) -> Vec<Point> {
    let inside = n / 10;
    let mut points = parabola(n - inside, rng);
    let half = ((n - inside) / 2) as i64;
    let top = (half * half) as f64;
    for _ in 0..inside {
        let x = rng.gen_range(-half + 1..half);
        let floor = (x * x + 1) as f64;
        points.push([x as f64, rng.gen_range(floor..top).round()]);
    }
    points
}

fn grid(n: usize, _: &mut StdRng) -> Vec<Point> {
    let side = (n as f64).sqrt().round().max(2.0) as usize;
    (0..side * side)
        .map(|i| [(i % side) as f64, (i / side) as f64])
        .collect()
}

/// Integer points on two lines crossing at the origin (a circle sweep's
/// worst case: every new point flips edges to many earlier ones).
fn two_lines(n: usize, _: &mut StdRng) -> Vec<Point> {
    let quarter = (n / 4).max(1) as i64;
    let mut points = vec![[0.0, 0.0]];
    for t in 1..=quarter {
        let t = t as f64;
        points.extend([[t, t], [-t, -t], [t, -t], [-t, t]]);
    }
    points
}

/// 10 clusters near `(1 + c, 1 + c²/8)`; each point is its centre moved by
/// a random number of ulps (below `4·√(n/10)`) in each coordinate.
fn ulp_clusters(n: usize, rng: &mut StdRng) -> Vec<Point> {
    let span = 4 * ((n / 10) as f64).sqrt().ceil() as u64 + 1;
    (0..n)
        .map(|i| {
            let c = (i % 10) as f64;
            let centre = [1.0 + c, 1.0 + c * c / 8.0];
            centre.map(|x: f64| f64::from_bits(x.to_bits() + rng.gen_range(0..span)))
        })
        .collect()
}

fn duplicates(n: usize, rng: &mut StdRng) -> Vec<Point> {
    let half = uniform(n / 2, rng);
    half.iter().chain(&half).copied().collect()
}

/// A star-shaped polygon: vertex `k` at angle `2πk/n` and a random integer
/// radius in `[n/2, n]`, counter-clockwise. Simple: its vertices are sorted
/// by angle around the origin, which is inside.
fn star_polygon(n: usize, rng: &mut StdRng) -> Vec<Point> {
    let r = n.max(8) as f64;
    let mut ring: Vec<Point> = (0..n)
        .map(|k| {
            let a = TAU * k as f64 / n as f64;
            let radius = rng.gen_range(r / 2.0..=r);
            [(radius * a.cos()).round(), (radius * a.sin()).round()]
        })
        .collect();
    ring.dedup();
    ring
}

/// A star-shaped polygon: vertex `k` at angle `2πk/n` and radius 1 for
/// even `k`, 1/2 for odd `k` (`n` rounded up to even), counter-clockwise.
/// The outer and the inner vertices each lie nearly on a circle (in convex
/// position): spade's constrained bulk load, a circle sweep, took more
/// than 30 s on 10⁵ vertices.
fn alternating_star(n: usize, _: &mut StdRng) -> Vec<Point> {
    let n = n.max(8).next_multiple_of(2);
    (0..n)
        .map(|k| {
            let a = TAU * k as f64 / n as f64;
            let radius = if k % 2 == 0 { 1.0 } else { 0.5 };
            [radius * a.cos(), radius * a.sin()]
        })
        .collect()
}

/// The family named `name`.
pub fn family(name: &str) -> Option<&'static Family> {
    FAMILIES.iter().find(|f| f.name == name)
}

/// The input of `family` at size `n`, from a fixed seed.
pub fn generate(family: &Family, n: usize) -> Vec<Point> {
    (family.generate)(n, &mut StdRng::seed_from_u64(2026))
}
