//! Test inputs shared by the test suites, benches and examples: every
//! point-set generator and every named degenerate fixture, one function each.
//!
//! Random generators take an explicit `&mut StdRng`, so a caller names its
//! seed once (`StdRng::seed_from_u64(SEED_…)`) and the same seed gives the
//! same points on every platform. Each doc says what the points are and which
//! degeneracies to expect (repeated points, collinear runs, cocircular
//! subsets). The order of the rand calls is part of each generator's
//! contract: changing it changes every test that uses the generator.
//!
//! Nothing here uses optri; the only predicate is the oracle's exact
//! [`orient`].

use crate::exact::{orient, Point};
use num_traits::AsPrimitive;
use rand::distributions::uniform::SampleUniform;
use rand::rngs::StdRng;
use rand::seq::SliceRandom;
use rand::Rng;
use std::f64::consts::TAU;
use std::ops::Range;

// ---- uniform and clustered floats ----

/// `n` points uniform in the unit square `[0, 1)²` (`rng.gen::<f64>()`, 53
/// random bits per coordinate). Repeated or collinear points are possible
/// but practically never occur.
pub fn uniform_unit_square(rng: &mut StdRng, n: usize) -> Vec<Point> {
    (0..n)
        .map(|_| [rng.gen::<f64>(), rng.gen::<f64>()])
        .collect()
}

/// `n` points uniform in the box `[min[0], max[0]) × [min[1], max[1])`
/// (`rng.gen_range` per coordinate, x first). Practically no degeneracies.
pub fn uniform_in_box(rng: &mut StdRng, n: usize, min: Point, max: Point) -> Vec<Point> {
    (0..n)
        .map(|_| [rng.gen_range(min[0]..max[0]), rng.gen_range(min[1]..max[1])])
        .collect()
}

/// `n` points uniform in the square `[-scale, scale)²`: [`uniform_in_box`]
/// centred on the origin. `scale` sets the magnitude (tiny or huge scales
/// exercise the exact arithmetic); practically no degeneracies.
pub fn uniform_in_square(rng: &mut StdRng, n: usize, scale: f64) -> Vec<Point> {
    uniform_in_box(rng, n, [-scale, -scale], [scale, scale])
}

/// [`uniform_unit_square`] plus the unit square's boundary sampled at the
/// mean spacing `1/k`, `k = ⌈√n⌉` (`4k` more points, a meshing domain): the
/// hull edges are short and the boundary points are collinear in four runs
/// of `k + 1` (the corners are shared).
pub fn boxed(rng: &mut StdRng, n: usize) -> Vec<Point> {
    let mut pts = uniform_unit_square(rng, n);
    let k = (n as f64).sqrt().ceil() as usize;
    for i in 0..k {
        let t = i as f64 / k as f64;
        pts.extend([[t, 0.0], [1.0, t], [1.0 - t, 1.0], [0.0, 1.0 - t]]);
    }
    pts
}

/// `n` points in `clusters` square clusters (sizes differ by at most one,
/// the first clusters take the remainder) with centres uniform in
/// `[-10⁴, 10⁴)²` and half-widths uniform in `[10, 2000)`: sizes over two
/// orders of magnitude, and empty regions that force long edges inside the
/// hull. Clusters may overlap; practically no degeneracies.
pub fn clustered(rng: &mut StdRng, n: usize, clusters: usize) -> Vec<Point> {
    let mut pts = Vec::with_capacity(n);
    for c in 0..clusters {
        let centre = [rng.gen_range(-1e4..1e4), rng.gen_range(-1e4..1e4)];
        let r: f64 = rng.gen_range(10.0..2e3);
        let count = n / clusters + usize::from(c < n % clusters);
        for _ in 0..count {
            pts.push([
                centre[0] + rng.gen_range(-r..r),
                centre[1] + rng.gen_range(-r..r),
            ]);
        }
    }
    pts
}

/// `n` points in `clusters` Gaussian clusters (sizes differ by at most one,
/// the first clusters take the remainder) with centres uniform in the unit
/// square and standard deviation `sigma` in each coordinate, drawn by the
/// Box–Muller transform (two uniforms give the x and y offsets; the first
/// uniform is taken from `(0, 1]` so that its logarithm is finite). Dense
/// cores thinning out into sparse tails: the density varies within every
/// cluster, not only between clusters. Practically no degeneracies.
pub fn gaussian_clusters(rng: &mut StdRng, n: usize, clusters: usize, sigma: f64) -> Vec<Point> {
    let mut pts = Vec::with_capacity(n);
    for c in 0..clusters {
        let centre = [rng.gen::<f64>(), rng.gen::<f64>()];
        let count = n / clusters + usize::from(c < n % clusters);
        for _ in 0..count {
            let radius = sigma * (-2.0 * (1.0 - rng.gen::<f64>()).ln()).sqrt();
            let angle = TAU * rng.gen::<f64>();
            pts.push([
                centre[0] + radius * angle.cos(),
                centre[1] + radius * angle.sin(),
            ]);
        }
    }
    pts
}

// ---- integer lattices ----

/// `n` integer points drawn independently from `xs × ys` (x first): on a
/// small range, many repeated points, collinear triples and equal lengths;
/// all points may be collinear. The integer type `T` is part of the
/// sequence: `rand` draws 32 bits per coordinate for `i32` (what an
/// unsuffixed literal range is) and 64 for `i64`.
pub fn lattice_points<T>(rng: &mut StdRng, n: usize, xs: Range<T>, ys: Range<T>) -> Vec<Point>
where
    T: SampleUniform + PartialOrd + AsPrimitive<f64>,
{
    (0..n)
        .map(|_| {
            [
                rng.gen_range(xs.clone()).as_(),
                rng.gen_range(ys.clone()).as_(),
            ]
        })
        .collect()
}

/// `n` *distinct* integer points from `xs × ys`, drawn as in
/// [`lattice_points`] with repeats skipped, and drawn again until they are
/// not all collinear (so `xs × ys` must hold `n` points not on one line).
/// Collinear triples and equal lengths remain on small ranges.
pub fn distinct_lattice_points<T>(
    rng: &mut StdRng,
    n: usize,
    xs: Range<T>,
    ys: Range<T>,
) -> Vec<Point>
where
    T: SampleUniform + PartialOrd + AsPrimitive<f64>,
{
    loop {
        let mut pts: Vec<Point> = Vec::with_capacity(n);
        while pts.len() < n {
            let p = [
                rng.gen_range(xs.clone()).as_(),
                rng.gen_range(ys.clone()).as_(),
            ];
            if !pts.contains(&p) {
                pts.push(p);
            }
        }
        if n < 3 || (2..n).any(|k| orient(pts[0], pts[1], pts[k]) != 0) {
            return pts;
        }
    }
}

/// The full `w × h` grid with the given spacing, `x` major: point
/// `h·x + y` is `(x·spacing, y·spacing)`. Collinear rows, columns and
/// diagonals, cocircular quadruples, many equal lengths; a negative spacing
/// mirrors it.
pub fn grid(w: usize, h: usize, spacing: f64) -> Vec<Point> {
    (0..w)
        .flat_map(|x| (0..h).map(move |y| [x as f64 * spacing, y as f64 * spacing]))
        .collect()
}

/// [`grid`] in a shuffled index order (`SliceRandom::shuffle`), so that the
/// index order, which drives symbolic tie-breaking, is unrelated to position.
pub fn shuffled_grid(rng: &mut StdRng, w: usize, h: usize, spacing: f64) -> Vec<Point> {
    let mut v = grid(w, h, spacing);
    v.shuffle(rng);
    v
}

/// Each point of the unit-spacing `w × h` [`grid`] kept with probability
/// `p` (one `gen_bool` per grid point, in grid order), then shuffled
/// (Fisher–Yates drawing `usize` indices). The grid's degeneracies with
/// holes; too few or only collinear points are possible.
pub fn grid_subset(rng: &mut StdRng, w: usize, h: usize, p: f64) -> Vec<Point> {
    let mut pts: Vec<Point> = grid(w, h, 1.0)
        .into_iter()
        .filter(|_| rng.gen_bool(p))
        .collect();
    for i in (1..pts.len()).rev() {
        pts.swap(i, rng.gen_range(0..=i));
    }
    pts
}

/// Points on a few lines, plus noise: `lines` (drawn from the range) runs,
/// each starting at an integer point of `[-5, 5)²` and stepping by an integer
/// vector of `[-3, 3]²`, with `run_length` (drawn) points each; then `noise`
/// (drawn) integer points of `[-8, 8)²`. Many points on open segments, lines
/// crossing at points, repeated points (a zero step repeats the start), and
/// possibly all collinear.
pub fn collinear_runs(
    rng: &mut StdRng,
    lines: Range<i32>,
    run_length: Range<i32>,
    noise: Range<i32>,
) -> Vec<Point> {
    let mut pts = Vec::new();
    for _ in 0..rng.gen_range(lines) {
        let (a, d) = (
            [rng.gen_range(-5..5) as f64, rng.gen_range(-5..5) as f64],
            [rng.gen_range(-3..4) as f64, rng.gen_range(-3..4) as f64],
        );
        for t in 0..rng.gen_range(run_length.clone()) {
            pts.push([a[0] + t as f64 * d[0], a[1] + t as f64 * d[1]]);
        }
    }
    for _ in 0..rng.gen_range(noise) {
        pts.push([rng.gen_range(-8..8) as f64, rng.gen_range(-8..8) as f64]);
    }
    pts
}

// ---- circles ----

/// All integer points on the circle `x² + y² = r²` (every sign and
/// coordinate-swap variant of the Pythagorean triples), by increasing `x`:
/// exactly cocircular, strictly convex position.
pub fn integer_circle_points(r: i64) -> Vec<Point> {
    let mut v = Vec::new();
    for x in -r..=r {
        let y2 = r * r - x * x;
        let y = (y2 as f64).sqrt().round() as i64;
        if y * y == y2 {
            v.push([x as f64, y as f64]);
            if y != 0 {
                v.push([x as f64, -y as f64]);
            }
        }
    }
    v
}

/// `n` points at equally spaced angles `2πi/n` on the unit circle, each
/// radius `1 + jitter·u` with `u` uniform in `[0, 1)`: convex position (for
/// a small `jitter`), nearly cocircular; the O(n²) worst case of the
/// minmax-length polygon algorithm.
pub fn perturbed_circle(rng: &mut StdRng, n: usize, jitter: f64) -> Vec<Point> {
    (0..n)
        .map(|i| {
            let a = i as f64 / n as f64 * TAU;
            let r = 1.0 + jitter * rng.gen::<f64>();
            [r * a.cos(), r * a.sin()]
        })
        .collect()
}

/// The regular `n`-gon of radius `r` as a user would sample it: `(r cos
/// 2πi/n, r sin 2πi/n)` in `f64`. Nearly cocircular (exactly so only where
/// rounding allows), equal side lengths up to rounding; convex position or
/// not, strictly or not, as rounding decides. Long runs of equal lengths
/// once made the greedy triangulation quadratic here.
pub fn sampled_circle(n: usize, r: f64) -> Vec<Point> {
    (0..n)
        .map(|i| {
            let a = TAU * i as f64 / n as f64;
            [r * a.cos(), r * a.sin()]
        })
        .collect()
}

/// A fan: `(i, 0)` for `0 ≤ i < n`, then the apex `(⌊n/2⌋, 1)`. All points
/// but one are collinear, so it has exactly one triangulation; its many
/// equal lengths once made the greedy triangulation quadratic.
pub fn fan(n: usize) -> Vec<Point> {
    let mut pts: Vec<Point> = (0..n).map(|i| [i as f64, 0.0]).collect();
    pts.push([(n / 2) as f64, 1.0]);
    pts
}

/// `n` points on the circle of radius `r` at angles uniform in `[0, 2π)`
/// (`rng.gen_range`), rounded to integers: nearly cocircular, repeated
/// points on a small circle, convex position or not (rounding decides).
pub fn rounded_circle(rng: &mut StdRng, n: usize, r: f64) -> Vec<Point> {
    (0..n)
        .map(|_| {
            let a: f64 = rng.gen_range(0.0..TAU);
            [(r * a.cos()).round(), (r * a.sin()).round()]
        })
        .collect()
}

/// `n` points on the circle of radius `r` at angles `2π·u`, `u =
/// rng.gen::<f64>()`, rounded to `f64` only: nearly cocircular, a stress
/// test for the in-circle predicate.
pub fn circle_at_random_angles(rng: &mut StdRng, n: usize, r: f64) -> Vec<Point> {
    (0..n)
        .map(|_| {
            let a: f64 = rng.gen::<f64>() * TAU;
            [r * a.cos(), r * a.sin()]
        })
        .collect()
}

/// `n` points on an arc of a random span in `[0.5, 3)` radians (less than a
/// half circle) of radius 1000, each radius jittered by up to 10⁻⁹
/// relative: nearly cocircular, usually semicircular and in convex position
/// (the jitter decides).
pub fn jittered_arc(rng: &mut StdRng, n: usize) -> Vec<Point> {
    let span = rng.gen_range(0.5..3.0);
    (0..n)
        .map(|_| {
            let a: f64 = rng.gen_range(0.0..span);
            let r = 1e3 * (1.0 + rng.gen_range(-1e-9..1e-9));
            [r * a.cos(), r * a.sin()]
        })
        .collect()
}

// ---- convex position, exactly ----

/// The integer points `(i, i²)`, `0 ≤ i < n`, on the parabola `y = x²`:
/// strictly convex and semicircular (the base joins the extreme points and
/// every other point sees it at an obtuse angle), sorted by `x`.
pub fn parabola(n: usize) -> Vec<Point> {
    (0..n).map(|i| [i as f64, (i * i) as f64]).collect()
}

/// `n` integer points `(x, x²)` with distinct `x` sampled from `0..span`
/// (`rand::seq::index::sample`, in sampled order): strictly convex and
/// semicircular, as [`parabola`].
pub fn random_parabola(rng: &mut StdRng, n: usize, span: usize) -> Vec<Point> {
    rand::seq::index::sample(rng, span, n)
        .into_iter()
        .map(|x| [x as f64, (x as f64) * (x as f64)])
        .collect()
}

/// `n ≥ 4` points in strictly convex position, exactly: a lens of the integer
/// parabolas `y = x²` and `y = 2m² − x²`, `m = 2n`, with the corners
/// `(±m, m²)` first, then `⌊(n−2)/2⌋` lower and the rest upper points at
/// distinct random abscissae in `(−m, m)` (lower sampled first). Not
/// semicircular: the two corners are the farthest pair and not adjacent.
pub fn convex_lens(rng: &mut StdRng, n: usize) -> Vec<Point> {
    let m = 2 * n as i64;
    let mut side = |k: usize| -> Vec<i64> {
        rand::seq::index::sample(rng, (2 * m - 1) as usize, k)
            .into_iter()
            .map(|i| i as i64 - m + 1)
            .collect()
    };
    let lower = side((n - 2) / 2);
    let upper = side(n - 2 - (n - 2) / 2);
    let mut pts: Vec<Point> = vec![[-m as f64, (m * m) as f64], [m as f64, (m * m) as f64]];
    pts.extend(lower.iter().map(|&x| [x as f64, (x * x) as f64]));
    pts.extend(
        upper
            .iter()
            .map(|&x| [x as f64, (2 * m * m - x * x) as f64]),
    );
    pts
}

/// `n` points in strictly convex position without randomness: the lens of
/// [`convex_lens`] (`m = 2n`) sampled at evenly spaced abscissae, a lower and
/// an upper point at each (for even `n ≥ 4`).
pub fn convex_lens_evenly_spaced(n: usize) -> Vec<Point> {
    let m = 2 * n as i64;
    let mut pts: Vec<Point> = Vec::with_capacity(n);
    for k in 0..n as i64 {
        let x = -m + 1 + (k / 2) * ((2 * m - 2) / (n as i64 / 2));
        let y = if k % 2 == 0 { x * x } else { 2 * m * m - x * x };
        pts.push([x as f64, y as f64]);
    }
    pts
}

/// The shape of [`convex_by_construction`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ConvexShape {
    /// The parabola `y = x²`, `|x| < 3n`.
    Parabola,
    /// The lens between `y = x²` and `y = 2m² − x²`, `|x| ≤ m = 2n`, with
    /// both corners (`n ≥ 4`).
    Lens,
}

/// `k` distinct integers from `lo..hi`, sorted.
fn sample_sorted(rng: &mut StdRng, lo: i64, hi: i64, k: usize) -> Vec<i64> {
    let mut v: Vec<i64> = rand::seq::index::sample(rng, (hi - lo) as usize, k)
        .into_iter()
        .map(|i| i as i64 + lo)
        .collect();
    v.sort_unstable();
    v
}

/// Adds, between consecutive chain points with coordinates of equal parity,
/// their (integer) midpoint with probability 1/2: a point on the open hull
/// edge, so the set stays in (non-strictly) convex position.
fn with_midpoints(rng: &mut StdRng, chain: Vec<[i64; 2]>) -> Vec<[i64; 2]> {
    let mut out = Vec::new();
    for w in chain.windows(2) {
        out.push(w[0]);
        let (a, b) = (w[0], w[1]);
        if (a[0] + b[0]) % 2 == 0 && (a[1] + b[1]) % 2 == 0 && rng.gen_bool(0.5) {
            out.push([(a[0] + b[0]) / 2, (a[1] + b[1]) / 2]);
        }
    }
    out.extend(chain.last());
    out
}

/// `n ≥ 3` integer points in convex position by construction (distinct
/// sorted abscissae on the chains of `shape`), with `collinear_midpoints`
/// also integer midpoints of hull edges (points on open hull edges: convex,
/// not strictly; a few more than `n` points); shuffled (Fisher–Yates drawing
/// `usize` indices), so the input order is not the polygon order.
pub fn convex_by_construction(
    rng: &mut StdRng,
    n: usize,
    shape: ConvexShape,
    collinear_midpoints: bool,
) -> Vec<Point> {
    let chains: Vec<Vec<[i64; 2]>> = match shape {
        ConvexShape::Parabola => {
            let span = 3 * n as i64;
            let xs = sample_sorted(rng, -span, span, n);
            vec![xs.iter().map(|&x| [x, x * x]).collect()]
        }
        ConvexShape::Lens => {
            let m = 2 * n as i64;
            let lower = sample_sorted(rng, -m + 1, m, (n - 2) / 2);
            let upper = sample_sorted(rng, -m + 1, m, n - 2 - (n - 2) / 2);
            // Both chains run from corner to corner: (−m, m²) and (m, m²).
            let corner = |x: i64| [x, m * m];
            let mut low = vec![corner(-m)];
            low.extend(lower.iter().map(|&x| [x, x * x]));
            low.push(corner(m));
            let mut up = vec![corner(m)];
            up.extend(upper.iter().rev().map(|&x| [x, 2 * m * m - x * x]));
            up.push(corner(-m));
            vec![low, up]
        }
    };
    let mut pts: Vec<[i64; 2]> = Vec::new();
    for chain in chains {
        let chain = if collinear_midpoints {
            with_midpoints(rng, chain)
        } else {
            chain
        };
        for p in chain {
            if !pts.contains(&p) {
                pts.push(p);
            }
        }
    }
    for i in (1..pts.len()).rev() {
        pts.swap(i, rng.gen_range(0..=i));
    }
    pts.into_iter()
        .map(|p| [p[0] as f64, p[1] as f64])
        .collect()
}

/// The strictly convex hull of `points`, counter-clockwise, without
/// collinear vertices (Andrew's monotone chain with the exact orientation;
/// duplicates dropped).
pub fn strict_hull(mut points: Vec<Point>) -> Vec<Point> {
    points.sort_by(|a, b| a.partial_cmp(b).expect("finite coordinates"));
    points.dedup();
    if points.len() < 3 {
        return points;
    }
    let chain = |iter: &mut dyn Iterator<Item = Point>| {
        let mut out: Vec<Point> = Vec::new();
        for p in iter {
            while out.len() >= 2 && orient(out[out.len() - 2], out[out.len() - 1], p) <= 0 {
                out.pop();
            }
            out.push(p);
        }
        out.pop();
        out
    };
    let mut hull = chain(&mut points.iter().copied());
    hull.extend(chain(&mut points.iter().rev().copied()));
    hull
}

/// A strictly convex polygon, counter-clockwise: the [`strict_hull`] of `n`
/// random points on an ellipse with semi-axes `radius` and `radius /
/// aspect`, turned by a random angle and rounded to integers (so at most
/// `n` vertices; nearly equal areas everywhere).
pub fn ellipse_polygon(rng: &mut StdRng, n: usize, radius: f64, aspect: f64) -> Vec<Point> {
    let tilt: f64 = rng.gen_range(0.0..std::f64::consts::PI);
    let (s, c) = tilt.sin_cos();
    let points = (0..n)
        .map(|_| {
            let t: f64 = rng.gen_range(0.0..std::f64::consts::TAU);
            let (x, y) = (radius * t.cos(), radius / aspect * t.sin());
            [(c * x - s * y).round(), (s * x + c * y).round()]
        })
        .collect();
    strict_hull(points)
}

// ---- named degenerate fixtures ----

/// The 12 integer points of `x² + y² = 25`, counter-clockwise from `(5, 0)`:
/// exactly cocircular, with equal chords.
pub fn circle_r5_ccw() -> Vec<Point> {
    vec![
        [5.0, 0.0],
        [4.0, 3.0],
        [3.0, 4.0],
        [0.0, 5.0],
        [-3.0, 4.0],
        [-4.0, 3.0],
        [-5.0, 0.0],
        [-4.0, -3.0],
        [-3.0, -4.0],
        [0.0, -5.0],
        [3.0, -4.0],
        [4.0, -3.0],
    ]
}

/// Seven of the points of [`circle_r5_ccw`] (counter-clockwise) and the
/// centre `(0, 0)` last: cocircular boundary, the centre at equal distance 5
/// from all of them, collinear through the centre (`(5, 0)`, `(0, 0)`,
/// `(-5, 0)`), 8 points (small enough to enumerate).
pub fn cocircular_seven_with_centre() -> Vec<Point> {
    vec![
        [5.0, 0.0],
        [3.0, 4.0],
        [0.0, 5.0],
        [-4.0, 3.0],
        [-5.0, 0.0],
        [-3.0, -4.0],
        [4.0, -3.0],
        [0.0, 0.0],
    ]
}

/// The square `[0, side]²` counter-clockwise from the origin, then its
/// centre: cocircular corners, the centre on both diagonals (where they
/// cross) and on the diameter circle of every side.
pub fn square_with_centre(side: f64) -> Vec<Point> {
    let c = side / 2.0;
    vec![[0.0, 0.0], [side, 0.0], [side, side], [0.0, side], [c, c]]
}

/// `k` points `(i, 0)`, `0 ≤ i < k`, then one apex `(⌊k/3⌋, 1)`: a long
/// collinear run (every inner point on an open segment) with one point off
/// the line.
pub fn run_with_apex(k: usize) -> Vec<Point> {
    let mut pts: Vec<Point> = (0..k).map(|i| [i as f64, 0.0]).collect();
    pts.push([(k / 3) as f64, 1.0]);
    pts
}
