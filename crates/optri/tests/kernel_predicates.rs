//! Proof by oracle: the kernel's exact predicates against exact rational /
//! big-integer evaluation, on nearly degenerate inputs where rounded
//! arithmetic gets the sign wrong (near-collinear, near-cocircular, nearly
//! equal lengths and areas, large offsets with small differences, huge and
//! tiny magnitudes), and at the documented coordinate limits 2^201 and
//! 2^-142.

use optri::internals::kernel::{
    angle_at_least_30_degrees, compare_corner_angles, dot_sign, exact_squared_length, in_half_lune,
    same_direction, strictly_inside_wedge, strictly_inside_wedge_symbolic,
};
use optri::kernel::{
    compare_areas, compare_lengths, in_lune, incircle_sign, orient_sign, AreaThreshold,
    MAX_COORDINATE, MIN_COORDINATE,
};
use optri_oracle as oracle;
use optri_oracle::{BigInt, BigRational};
use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};

type Point = [f64; 2];

const SEED_NEARLY_DEGENERATE: u64 = 42;
const SEED_ORIENTATION_AT_LIMITS: u64 = 201;
const SEED_LENGTHS_AT_LIMITS: u64 = 142;
const SEED_LUNES_AT_LIMITS: u64 = 2142;
const SEED_HUGE_AND_TINY_MIXED: u64 = 343;
const SEED_DIAMOND_FILTER: u64 = 46;
const SEED_EXACT_SQUARED_LENGTHS: u64 = 1_000_000;
const SEED_WEDGES: u64 = 360;
const SEED_WEDGES_PERTURBED: u64 = 361;

fn next_up_or_down(v: f64, rng: &mut StdRng) -> f64 {
    let k: i64 = rng.gen_range(-2..=2);
    if v == 0.0 {
        return v;
    }
    f64::from_bits((v.to_bits() as i64 + k) as u64)
}

/// A nearly degenerate configuration of 4 points at the given scale/offset.
fn sample(rng: &mut StdRng, scale: f64, offset: f64) -> [Point; 4] {
    let p = |rng: &mut StdRng| {
        [
            offset + scale * rng.gen_range(-1.0..1.0),
            offset + scale * rng.gen_range(-1.0..1.0),
        ]
    };
    let (a, b) = (p(rng), p(rng));
    match rng.gen_range(0..4) {
        // c on (nearly) the line ab, d nearly so too.
        0 => {
            let t: f64 = rng.gen_range(-2.0..3.0);
            let c = [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])];
            let s: f64 = rng.gen_range(-2.0..3.0);
            let d = [
                a[0] + s * (b[0] - a[0]),
                next_up_or_down(a[1] + s * (b[1] - a[1]), rng),
            ];
            [a, b, c, d]
        }
        // Four points nearly on one circle.
        1 => {
            let centre = p(rng);
            let r = scale * rng.gen_range(0.1..1.0);
            let pt = |rng: &mut StdRng| {
                let th: f64 = rng.gen_range(0.0..std::f64::consts::TAU);
                [centre[0] + r * th.cos(), centre[1] + r * th.sin()]
            };
            let mut v = [pt(rng), pt(rng), pt(rng), pt(rng)];
            // Order the first three counter-clockwise when possible.
            if oracle::orient(v[0], v[1], v[2]) < 0 {
                v.swap(1, 2);
            }
            v
        }
        // cd a rotated copy of ab (equal length when exact), nudged.
        2 => {
            let c = p(rng);
            let d = [
                next_up_or_down(c[0] - (b[1] - a[1]), rng),
                c[1] + (b[0] - a[0]),
            ];
            [a, b, c, d]
        }
        // Integer points offset far from the origin.
        _ => {
            let q = |rng: &mut StdRng| {
                [
                    offset + rng.gen_range(-3..=3) as f64,
                    offset + rng.gen_range(-3..=3) as f64,
                ]
            };
            [q(rng), q(rng), q(rng), q(rng)]
        }
    }
}

#[test]
fn predicates_equal_exact_evaluation_on_nearly_degenerate_inputs() {
    let mut rng = StdRng::seed_from_u64(SEED_NEARLY_DEGENERATE);
    let settings = [
        (1.0, 0.0),
        (1.0, 1e6),
        (1e-3, 2f64.powi(40)),
        (2f64.powi(150), 0.0),
        (2f64.powi(-100), 0.0),
        (2f64.powi(-100), 2f64.powi(-80)),
        (-(2f64.powi(120)), 2f64.powi(160)),
    ];
    let (mut zero_orient, mut zero_incircle, mut equal_lengths) = (0, 0, 0);
    for &(scale, offset) in &settings {
        for _ in 0..3000 {
            let [a, b, c, d] = sample(&mut rng, scale, offset);
            let o = oracle::orient(a, b, c);
            assert_eq!(orient_sign(a, b, c), o, "orient {a:?} {b:?} {c:?}");
            zero_orient += (o == 0) as usize;
            assert_eq!(
                dot_sign(a, b, c),
                oracle::dot_sign(a, b, c),
                "dot {a:?} {b:?} {c:?}"
            );
            let l = oracle::compare_squared_lengths(a, b, c, d);
            assert_eq!(
                compare_lengths(a, b, c, d),
                l,
                "lengths {a:?} {b:?} {c:?} {d:?}"
            );
            equal_lengths += l.is_eq() as usize;
            let ar = oracle::twice_area(a, b, c).cmp(&oracle::twice_area(a, b, d));
            assert_eq!(compare_areas([a, b, c], [a, b, d]), ar, "areas");
            if o > 0 {
                let ic = oracle::incircle(a, b, c, d);
                assert_eq!(
                    incircle_sign(a, b, c, d),
                    ic,
                    "incircle {a:?} {b:?} {c:?} {d:?}"
                );
                zero_incircle += (ic == 0) as usize;
            }
        }
    }
    assert!(
        zero_orient > 300 && zero_incircle > 50 && equal_lengths > 300,
        "{zero_orient} {zero_incircle} {equal_lengths}"
    );
}

// ---------------------------------------------------------------------------
// The documented coordinate limits, 2^201 and 2^-142.
//
// An integer configuration with |coordinates| <= 2^53 is exact in f64, and so
// is its image under scaling by a power of two 2^k (the mantissas do not
// change). Orientation determinants scale by 2^2k and squared lengths too, so
// no predicate may change its answer: the integer answer, computed exactly in
// i128 (products stay below 2^110), is the reference at every scale. Scaling
// by 2^148 puts coordinates up to 2^53 * 2^148 = 2^201, the upper limit;
// scaling by 2^-142 puts the coordinates +-1 at 2^-142, the lower limit.

type IntPoint = [i64; 2];

fn orient_int(a: IntPoint, b: IntPoint, c: IntPoint) -> i32 {
    let d = (b[0] - a[0]) as i128 * (c[1] - a[1]) as i128
        - (b[1] - a[1]) as i128 * (c[0] - a[0]) as i128;
    d.signum() as i32
}

fn squared_length_int(a: IntPoint, b: IntPoint) -> i128 {
    let (dx, dy) = ((a[0] - b[0]) as i128, (a[1] - b[1]) as i128);
    dx * dx + dy * dy
}

fn in_lune_int(p: IntPoint, q: IntPoint, x: IntPoint) -> bool {
    let pq = squared_length_int(p, q);
    squared_length_int(x, p) < pq && squared_length_int(x, q) < pq
}

/// Multiplies by `scale`, a power of two: exact for |v| <= 2^53.
fn scaled(p: IntPoint, scale: f64) -> Point {
    assert!(p[0].unsigned_abs() <= 1 << 53 && p[1].unsigned_abs() <= 1 << 53);
    let q = [p[0] as f64 * scale, p[1] as f64 * scale];
    for v in q {
        assert!(
            v == 0.0 || (MIN_COORDINATE..=MAX_COORDINATE).contains(&v.abs()),
            "{v:e} is outside the documented range"
        );
    }
    q
}

/// The scales: the upper and lower limits (also negated: a half-turn keeps
/// every predicate), plus ordinary ones.
fn limit_scales() -> [f64; 6] {
    [
        1.0,
        2f64.powi(148),
        -(2f64.powi(148)),
        2f64.powi(-142),
        -(2f64.powi(-142)),
        2f64.powi(60),
    ]
}

/// An offset near a corner of the integer box: after scaling by 2^148 the
/// points lie near (+-2^201, +-2^201).
fn corner(rng: &mut StdRng) -> IntPoint {
    let near = |rng: &mut StdRng| {
        let sign = if rng.gen_bool(0.5) { 1 } else { -1 };
        sign * ((1i64 << 53) - (1 << 51) - rng.gen_range(0..1i64 << 20))
    };
    match rng.gen_range(0..3) {
        0 => [0, 0],
        1 => [near(rng), near(rng)],
        _ => [near(rng), rng.gen_range(-8..=8)],
    }
}

fn add(a: IntPoint, b: IntPoint) -> IntPoint {
    [a[0] + b[0], a[1] + b[1]]
}

/// One of the eight symmetries of the integer grid (exact, length-preserving).
fn symmetry(v: IntPoint, k: u32) -> IntPoint {
    let v = if k & 1 == 1 { [v[1], v[0]] } else { v };
    let v = if k & 2 == 2 { [-v[0], v[1]] } else { v };
    if k & 4 == 4 {
        [v[0], -v[1]]
    } else {
        v
    }
}

/// A near-collinear triple: `b` and `c` on a line through `a` (exactly, or
/// rounded from a real parameter), `c` then nudged by at most one unit; or
/// small integers (at the lower limit after scaling, where +-1 is 2^-142).
fn near_collinear(rng: &mut StdRng) -> [IntPoint; 3] {
    let o = corner(rng);
    // Half the triples stay exactly collinear.
    let nudge = |rng: &mut StdRng| {
        if rng.gen_bool(0.5) {
            [0, 0]
        } else {
            [rng.gen_range(-1..=1), rng.gen_range(-1..=1)]
        }
    };
    match rng.gen_range(0..3) {
        0 => {
            let d = [
                rng.gen_range(-(1i64 << 20)..=1 << 20),
                rng.gen_range(-(1i64 << 20)..=1 << 20),
            ];
            let (m1, m2) = (
                rng.gen_range(-(1i64 << 28)..=1 << 28),
                rng.gen_range(-(1i64 << 28)..=1 << 28),
            );
            let a = add(
                o,
                [rng.gen_range(-1000..=1000), rng.gen_range(-1000..=1000)],
            );
            let b = add(a, [m1 * d[0], m1 * d[1]]);
            let c = add(add(a, [m2 * d[0], m2 * d[1]]), nudge(rng));
            [a, b, c]
        }
        1 => {
            let r = |rng: &mut StdRng| rng.gen_range(-(1i64 << 49)..=1 << 49);
            let a = add(o, [r(rng), r(rng)]);
            let b = add(o, [r(rng), r(rng)]);
            let t: f64 = rng.gen_range(-0.5..1.5);
            let on = |k: usize| (a[k] as f64 + t * (b[k] - a[k]) as f64).round() as i64;
            [a, b, add([on(0), on(1)], nudge(rng))]
        }
        _ => {
            let s = |rng: &mut StdRng| [rng.gen_range(-3..=3), rng.gen_range(-3..=3)];
            [s(rng), s(rng), s(rng)]
        }
    }
}

#[test]
fn orientation_at_the_coordinate_limits_is_scale_invariant() {
    let mut rng = StdRng::seed_from_u64(SEED_ORIENTATION_AT_LIMITS);
    let (mut zeros, mut nonzeros, mut at_top, mut at_bottom) = (0, 0, 0, 0);
    for _ in 0..4000 {
        let [a, b, c] = near_collinear(&mut rng);
        let expected = orient_int(a, b, c);
        (zeros, nonzeros) = if expected == 0 {
            (zeros + 1, nonzeros)
        } else {
            (zeros, nonzeros + 1)
        };
        for scale in limit_scales() {
            let [fa, fb, fc] = [a, b, c].map(|p| scaled(p, scale));
            assert_eq!(
                orient_sign(fa, fb, fc),
                expected,
                "orient {a:?} {b:?} {c:?} scaled by {scale:e}"
            );
            // Cyclic order keeps the sign, a swap flips it.
            assert_eq!(orient_sign(fb, fc, fa), expected);
            assert_eq!(orient_sign(fb, fa, fc), -expected);
            let coords = [fa, fb, fc].concat();
            at_top += coords.iter().any(|v| v.abs() >= 2f64.powi(200)) as usize;
            at_bottom += coords.iter().any(|v| v.abs() == MIN_COORDINATE) as usize;
        }
    }
    assert!(
        zeros > 500 && nonzeros > 500 && at_top > 500 && at_bottom > 500,
        "{zeros} {nonzeros} {at_top} {at_bottom}"
    );
}

/// Two segments with nearly equal lengths: `cd` is a grid symmetry of `ab`
/// (exactly equal), or a Pythagorean pair like (3k, 4k) and (5k, 0), and one
/// endpoint is then nudged by at most one unit.
fn nearly_equal_segments(rng: &mut StdRng) -> [IntPoint; 4] {
    let o = corner(rng);
    let r = |rng: &mut StdRng, bits: u32| rng.gen_range(-(1i64 << bits)..=1 << bits);
    let a = add(o, [r(rng, 40), r(rng, 40)]);
    let c = add(o, [r(rng, 40), r(rng, 40)]);
    let (u, w) = if rng.gen_bool(0.5) {
        let u = [r(rng, 49), r(rng, 49)];
        (u, symmetry(u, rng.gen_range(0..8)))
    } else {
        let k = r(rng, 45);
        let [x, y, z] = [[3, 4, 5], [5, 12, 13], [8, 15, 17]][rng.gen_range(0..3)];
        (
            symmetry([x * k, y * k], rng.gen_range(0..8)),
            symmetry([z * k, 0], rng.gen_range(0..8)),
        )
    };
    let nudge = [rng.gen_range(-1..=1), rng.gen_range(-1..=1)];
    [a, add(a, u), c, add(add(c, w), nudge)]
}

#[test]
fn length_comparison_at_the_coordinate_limits_is_scale_invariant() {
    let mut rng = StdRng::seed_from_u64(SEED_LENGTHS_AT_LIMITS);
    let (mut equal, mut unequal) = (0, 0);
    for _ in 0..4000 {
        let [a, b, c, d] = nearly_equal_segments(&mut rng);
        let expected = squared_length_int(a, b).cmp(&squared_length_int(c, d));
        (equal, unequal) = if expected.is_eq() {
            (equal + 1, unequal)
        } else {
            (equal, unequal + 1)
        };
        for scale in limit_scales() {
            let [fa, fb, fc, fd] = [a, b, c, d].map(|p| scaled(p, scale));
            assert_eq!(
                compare_lengths(fa, fb, fc, fd),
                expected,
                "lengths {a:?} {b:?} {c:?} {d:?} scaled by {scale:e}"
            );
            assert_eq!(compare_lengths(fc, fd, fb, fa), expected.reverse());
        }
    }
    assert!(equal > 300 && unequal > 300, "{equal} {unequal}");
}

/// `p`, `q` and a point `x` on, just inside or just outside the circle of
/// radius |pq| around `p` (a Pythagorean triple makes |xp| = |pq| exact), or
/// anywhere near the lune.
fn lune_case(rng: &mut StdRng) -> [IntPoint; 3] {
    let o = corner(rng);
    let k = rng.gen_range(1..=1i64 << 45);
    let sym = rng.gen_range(0..8);
    let p = add(
        o,
        [rng.gen_range(-1000..=1000), rng.gen_range(-1000..=1000)],
    );
    let q = add(p, symmetry([25 * k, 0], sym));
    let on_circle = match rng.gen_range(0..3) {
        0 => [20 * k, 15 * k],
        1 => [7 * k, 24 * k],
        // Anywhere in the bounding box of the lune.
        _ => [
            rng.gen_range(-25 * k..=50 * k),
            rng.gen_range(-25 * k..=25 * k),
        ],
    };
    let nudge = [rng.gen_range(-1..=1), rng.gen_range(-1..=1)];
    [p, q, add(add(p, symmetry(on_circle, sym)), nudge)]
}

#[test]
fn lune_membership_at_the_coordinate_limits_is_scale_invariant() {
    let mut rng = StdRng::seed_from_u64(SEED_LUNES_AT_LIMITS);
    let (mut inside, mut outside, mut on_circle) = (0, 0, 0);
    for _ in 0..4000 {
        let [p, q, x] = lune_case(&mut rng);
        let expected = in_lune_int(p, q, x);
        let side = orient_int(p, q, x);
        if expected {
            inside += 1;
        } else {
            outside += 1;
        }
        on_circle += (squared_length_int(x, p) == squared_length_int(p, q)) as usize;
        for scale in limit_scales() {
            let [fp, fq, fx] = [p, q, x].map(|v| scaled(v, scale));
            assert_eq!(
                in_lune(fp, fq, fx),
                expected,
                "lune {p:?} {q:?} {x:?} scaled by {scale:e}"
            );
            assert_eq!(in_lune(fq, fp, fx), expected, "the lune is symmetric");
            assert_eq!(in_half_lune(fp, fq, fx), expected && side >= 0);
            assert_eq!(in_half_lune(fq, fp, fx), expected && side <= 0);
        }
    }
    assert!(
        inside > 500 && outside > 500 && on_circle > 100,
        "{inside} {outside} {on_circle}"
    );
}

#[test]
fn predicates_equal_exact_evaluation_with_huge_and_tiny_coordinates_mixed() {
    // Coordinates near +-2^201 next to coordinates near 2^-142: the
    // differences span 2^343, beyond i128, so the oracle's rationals decide.
    let mut rng = StdRng::seed_from_u64(SEED_HUGE_AND_TINY_MIXED);
    let big = |rng: &mut StdRng| {
        let sign = if rng.gen_bool(0.5) { 1.0 } else { -1.0 };
        sign * (MAX_COORDINATE - rng.gen_range(0..4) as f64 * 2f64.powi(148))
    };
    let tiny = |rng: &mut StdRng| rng.gen_range(-4..=4) as f64 * MIN_COORDINATE;
    let coordinate = |rng: &mut StdRng| match rng.gen_range(0..3) {
        0 => big(rng),
        1 => tiny(rng),
        _ => 0.0,
    };
    let point = |rng: &mut StdRng| [coordinate(rng), coordinate(rng)];
    let (mut zero_orient, mut equal_lengths) = (0, 0);
    for _ in 0..20000 {
        let [a, b, c, d] = [
            point(&mut rng),
            point(&mut rng),
            point(&mut rng),
            point(&mut rng),
        ];
        let o = oracle::orient(a, b, c);
        assert_eq!(orient_sign(a, b, c), o, "orient {a:?} {b:?} {c:?}");
        zero_orient += (o == 0) as usize;
        let l = oracle::compare_squared_lengths(a, b, c, d);
        assert_eq!(
            compare_lengths(a, b, c, d),
            l,
            "lengths {a:?} {b:?} {c:?} {d:?}"
        );
        equal_lengths += l.is_eq() as usize;
        let lune = oracle::compare_squared_lengths(c, a, a, b).is_lt()
            && oracle::compare_squared_lengths(c, b, a, b).is_lt();
        assert_eq!(in_lune(a, b, c), lune, "lune {a:?} {b:?} {c:?}");
    }
    assert!(
        zero_orient > 500 && equal_lengths > 100,
        "{zero_orient} {equal_lengths}"
    );
}

// ---------------------------------------------------------------------------
// compare_areas on different triangles whose areas are equal or differ by
// about one rounding: the filter must hand every such case to the exact
// fallback.

#[test]
fn compare_areas_on_near_ties_matches_exact_areas() {
    const SEED: u64 = 0xa4ea_5eed;
    let mut rng = StdRng::seed_from_u64(SEED);
    let (mut cases, mut equal) = (0usize, 0usize);
    for _ in 0..20_000 {
        let scale: f64 = [1.0, 1e-9, 1e12, 3.0e40][rng.gen_range(0..4)];
        let offset = [0.0, 1e6, -7.5e15][rng.gen_range(0..3)] * scale.min(1.0);
        let p = |rng: &mut StdRng| {
            [
                offset + scale * rng.gen_range(-1.0..1.0),
                offset + scale * rng.gen_range(-1.0..1.0),
            ]
        };
        let t1 = [p(&mut rng), p(&mut rng), p(&mut rng)];
        // The same triangle translated, reflected or with rotated corners
        // (equal exact area up to the rounding of the moved coordinates),
        // then each coordinate nudged by a few ulps or not at all.
        let shift = [
            scale * rng.gen_range(-1.0..1.0),
            scale * rng.gen_range(-1.0..1.0),
        ];
        let mut t2 = match rng.gen_range(0..3) {
            0 => t1.map(|q| [q[0] + shift[0], q[1] + shift[1]]),
            1 => [t1[1], t1[2], t1[0]],
            _ => t1.map(|q| [-q[0], q[1]]),
        };
        if rng.gen_bool(0.5) {
            for q in &mut t2 {
                q[0] = next_up_or_down(q[0], &mut rng);
                q[1] = next_up_or_down(q[1], &mut rng);
            }
        }
        let exact =
            oracle::twice_area(t1[0], t1[1], t1[2]).cmp(&oracle::twice_area(t2[0], t2[1], t2[2]));
        assert_eq!(compare_areas(t1, t2), exact, "{t1:?} {t2:?}");
        assert_eq!(compare_areas(t2, t1), exact.reverse());
        cases += 1;
        equal += exact.is_eq() as usize;
    }
    assert_eq!(cases, 20_000);
    assert!(equal > 5_000, "{equal}");
}

// ---------------------------------------------------------------------------
// Angle predicates: the 30° test and the comparison of two corner angles,
// both degree-4 polynomials in the coordinate differences.

/// Cross and dot product of `a − o` and `b − o`, exactly in i128 (differences
/// below 2^30, so products of four stay below 2^122).
fn cross_dot_int(o: IntPoint, a: IntPoint, b: IntPoint) -> (i128, i128) {
    let (ux, uy) = ((a[0] - o[0]) as i128, (a[1] - o[1]) as i128);
    let (vx, vy) = ((b[0] - o[0]) as i128, (b[1] - o[1]) as i128);
    (ux * vy - uy * vx, ux * vx + uy * vy)
}

/// The definition: `u·v ≤ 0` or `4(u·v)² ≤ 3|u|²|v|²` (the textbook form, not
/// the kernel's `3(u×v)² ≥ (u·v)²`).
fn at_least_30_int(o: IntPoint, a: IntPoint, b: IntPoint) -> bool {
    let (_, d) = cross_dot_int(o, a, b);
    let (u2, v2) = (squared_length_int(a, o), squared_length_int(b, o));
    // 3|u|²|v|² can reach 2^122 · 3: compare 4d² ≤ 3 u2 v2 as
    // (2d)² ≤ 3 u2 v2 in i128 (below 2^125).
    d <= 0 || 4 * d * d <= 3 * u2 * v2
}

/// Angle at `p[0]` versus angle at `q[0]`, by the definition: compare
/// `cos θ = D/(|u||v|)` (decreasing), squared with signs, as exact rationals.
fn compare_angles_int(p: [IntPoint; 3], q: [IntPoint; 3]) -> std::cmp::Ordering {
    use oracle::{BigInt, BigRational};
    let cos_key = |c: [IntPoint; 3]| {
        let (_, d) = cross_dot_int(c[0], c[1], c[2]);
        let n = squared_length_int(c[1], c[0]) * squared_length_int(c[2], c[0]);
        // sign(d) · d² / (|u|²|v|²) orders like cos θ (all below 2^121).
        BigRational::new(BigInt::from(d * d.abs()), BigInt::from(n))
    };
    // Larger cosine, smaller angle.
    cos_key(q).cmp(&cos_key(p))
}

/// `v` rotated by `deg` degrees and scaled by `t`, rounded to integers.
fn rotated(v: IntPoint, deg: f64, t: f64) -> IntPoint {
    let (s, c) = deg.to_radians().sin_cos();
    [
        (t * (c * v[0] as f64 - s * v[1] as f64)).round() as i64,
        (t * (s * v[0] as f64 + c * v[1] as f64)).round() as i64,
    ]
}

/// A corner at `o` between `w` and `x·w + y·w⊥`, where `x/y` is a Pell
/// approximation of √3 (`x² − 3y² = 1` or `−2`, after `iterations` steps of
/// `(x, y) → (2x + 3y, x + 2y)`): its angle is within about `1/x²` of 30°,
/// so `|3C² − D²|` is tiny next to `C² + D²` and the filter must defer.
/// Differences stay below 2^30 for at most 14 steps.
fn pell_corner(rng: &mut StdRng, o: IntPoint, iterations: u32) -> [IntPoint; 3] {
    let (mut x, mut y): (i64, i64) = if rng.gen_bool(0.5) { (2, 1) } else { (1, 1) };
    for _ in 0..iterations {
        (x, y) = (2 * x + 3 * y, x + 2 * y);
    }
    let w = [rng.gen_range(-3..=3), rng.gen_range(1..=3)];
    let m = rng.gen_range(1..=3);
    let v = [x * w[0] - y * w[1], x * w[1] + y * w[0]];
    let u = [m * w[0], m * w[1]];
    if rng.gen_bool(0.5) {
        [o, add(o, u), add(o, v)]
    } else {
        [o, add(o, v), add(o, u)]
    }
}

/// A corner `(o, a, b)` whose angle is near 30° (a ray rotated by 30° and
/// rounded, then nudged), near 0°, 90° or 180°, or anything.
fn corner_near_30(rng: &mut StdRng) -> [IntPoint; 3] {
    let o = corner(rng);
    if rng.gen_bool(0.25) {
        let iterations = rng.gen_range(3..=14);
        return pell_corner(rng, o, iterations);
    }
    let bits = rng.gen_range(2..=28);
    let r = |rng: &mut StdRng| rng.gen_range(-(1i64 << bits)..=1 << bits);
    let mut u = [r(rng), r(rng)];
    if u == [0, 0] {
        u = [1, 0];
    }
    let deg = match rng.gen_range(0..6) {
        0..=2 => 30.0,
        3 => 0.0,
        4 => [90.0, 180.0, 150.0][rng.gen_range(0..3)],
        _ => rng.gen_range(0.0..180.0),
    };
    let sign = if rng.gen_bool(0.5) { 1.0 } else { -1.0 };
    let t = rng.gen_range(0.5..2.0);
    let mut v = rotated(u, sign * deg, t);
    v = add(v, [rng.gen_range(-1..=1), rng.gen_range(-1..=1)]);
    if v == [0, 0] {
        v = u;
    }
    [o, add(o, u), add(o, v)]
}

#[test]
fn thirty_degree_test_equals_exact_integer_evaluation_at_every_scale() {
    let mut rng = StdRng::seed_from_u64(30);
    let (mut yes, mut no, mut close) = (0, 0, 0);
    let cases = 6000;
    for _ in 0..cases {
        let [o, a, b] = corner_near_30(&mut rng);
        let expected = at_least_30_int(o, a, b);
        (yes, no) = if expected {
            (yes + 1, no)
        } else {
            (yes, no + 1)
        };
        // "Close": |E| is tiny next to its scale, so the filter cannot decide.
        let (c, d) = cross_dot_int(o, a, b);
        let e = 3 * c * c - d * d;
        close += (d > 0 && e.unsigned_abs() < (c * c + d * d).unsigned_abs() >> 48) as usize;
        for scale in limit_scales() {
            let [fo, fa, fb] = [o, a, b].map(|p| scaled(p, scale));
            assert_eq!(
                angle_at_least_30_degrees(fo, fa, fb),
                expected,
                "30° at {o:?} between {a:?} and {b:?}, scaled by {scale:e}"
            );
            assert_eq!(angle_at_least_30_degrees(fo, fb, fa), expected);
        }
    }
    assert!(
        yes > 1500 && no > 1500 && close > 50,
        "{yes} {no} {close} of {cases}"
    );
}

#[test]
fn corner_angle_comparison_equals_exact_integer_evaluation_at_every_scale() {
    let mut rng = StdRng::seed_from_u64(3045);
    let (mut equal, mut unequal, mut close) = (0, 0, 0);
    let cases = 6000;
    for _ in 0..cases {
        // One case in five: two Pell corners, both within about 1/x² of
        // 30°, whose angles differ by far less than the filter resolves.
        let pell = rng.gen_range(0..5) == 0;
        let p = if pell {
            let (k, o) = (rng.gen_range(10..=14), corner(&mut rng));
            pell_corner(&mut rng, o, k)
        } else {
            corner_near_30(&mut rng)
        };
        let (u, v) = (
            [p[1][0] - p[0][0], p[1][1] - p[0][1]],
            [p[2][0] - p[0][0], p[2][1] - p[0][1]],
        );
        // q: the same angle exactly (a grid symmetry, an integer multiple,
        // or a rotation by the Pythagorean angle of (3, 4), which scales by
        // 5), then possibly nudged; or an unrelated near-30° corner.
        let o = corner(&mut rng);
        let q = match if pell { 4 } else { rng.gen_range(0..4) } {
            0 => {
                let k = rng.gen_range(0..8);
                [o, add(o, symmetry(u, k)), add(o, symmetry(v, k))]
            }
            1 => {
                let (m1, m2) = (rng.gen_range(1..=3), rng.gen_range(1..=3));
                [
                    o,
                    add(o, [m1 * u[0], m1 * u[1]]),
                    add(o, [m2 * v[0], m2 * v[1]]),
                ]
            }
            2 => {
                let turn = |w: IntPoint| [3 * w[0] - 4 * w[1], 4 * w[0] + 3 * w[1]];
                [o, add(o, turn(u)), add(o, turn(v))]
            }
            3 => corner_near_30(&mut rng),
            _ => {
                let k = rng.gen_range(10..=14);
                pell_corner(&mut rng, o, k)
            }
        };
        let q = if pell || rng.gen_bool(0.5) {
            q
        } else {
            [
                q[0],
                q[1],
                add(q[2], [rng.gen_range(-1..=1), rng.gen_range(-1..=1)]),
            ]
        };
        if q[2] == q[0] {
            continue;
        }
        let expected = compare_angles_int(p, q);
        let ((cp, dp), (cq, dq)) = (
            cross_dot_int(p[0], p[1], p[2]),
            cross_dot_int(q[0], q[1], q[2]),
        );
        let (f1, f2) = (dq * cp.abs(), dp * cq.abs());
        close += (f1 != f2
            && (f1 - f2).unsigned_abs() < (f1.unsigned_abs() + f2.unsigned_abs()) >> 48)
            as usize;
        (equal, unequal) = if expected.is_eq() {
            (equal + 1, unequal)
        } else {
            (equal, unequal + 1)
        };
        for scale in limit_scales() {
            let fp = p.map(|x| scaled(x, scale));
            let fq = q.map(|x| scaled(x, scale));
            assert_eq!(
                compare_corner_angles(fp, fq),
                expected,
                "angle {p:?} versus {q:?}, scaled by {scale:e}"
            );
            assert_eq!(compare_corner_angles(fq, fp), expected.reverse());
            assert_eq!(
                compare_corner_angles([fp[0], fp[2], fp[1]], fq),
                expected,
                "the angle does not depend on the order of its rays"
            );
        }
    }
    assert!(
        equal > 1000 && unequal > 1000 && close > 30,
        "{equal} {unequal} {close} of {cases}"
    );
}

#[test]
fn angle_predicates_equal_rational_evaluation_on_fractional_coordinates() {
    use oracle::{to_rational, BigRational};
    let mut rng = StdRng::seed_from_u64(3030);
    let rational_cross_dot = |o: Point, a: Point, b: Point| {
        let d = |p: Point, k: usize| to_rational(p[k]) - to_rational(o[k]);
        let (ux, uy, vx, vy) = (d(a, 0), d(a, 1), d(b, 0), d(b, 1));
        (
            ux.clone() * vy.clone() - uy.clone() * vx.clone(),
            ux * vx + uy * vy,
        )
    };
    let zero = BigRational::from_integer(0.into());
    let three = BigRational::from_integer(3.into());
    let (mut yes, mut no, mut equal) = (0, 0, 0);
    let cases = 6000;
    for i in 0..cases {
        let (scale, offset) = [
            (1.0, 0.0),
            (1e-3, 2f64.powi(40)),
            (2f64.powi(-100), 2f64.powi(-80)),
            (2f64.powi(150), -(2f64.powi(152))),
        ][i % 4];
        let pt = |rng: &mut StdRng| {
            [
                offset + scale * rng.gen_range(-1.0..1.0),
                offset + scale * rng.gen_range(-1.0..1.0),
            ]
        };
        let (o, a) = (pt(&mut rng), pt(&mut rng));
        let u = [a[0] - o[0], a[1] - o[1]];
        let deg: f64 = if rng.gen_bool(0.7) {
            30.0
        } else {
            rng.gen_range(0.0..180.0)
        };
        let (s, c) = deg.to_radians().sin_cos();
        let b = [
            next_up_or_down(o[0] + c * u[0] - s * u[1], &mut rng),
            next_up_or_down(o[1] + s * u[0] + c * u[1], &mut rng),
        ];
        if a == o || b == o {
            continue;
        }
        let (cr, dt) = rational_cross_dot(o, a, b);
        let expected =
            dt <= zero || dt.clone() * dt.clone() <= three.clone() * cr.clone() * cr.clone();
        (yes, no) = if expected {
            (yes + 1, no)
        } else {
            (yes, no + 1)
        };
        assert_eq!(
            angle_at_least_30_degrees(o, a, b),
            expected,
            "30° {o:?} {a:?} {b:?}"
        );
        // Against a mirrored copy of the corner, nudged by an ulp: the same
        // or an almost equal angle.
        let mirror = |p: Point| [2.0 * o[0] - p[0], p[1]];
        let q = [
            o,
            mirror(a),
            [next_up_or_down(mirror(b)[0], &mut rng), mirror(b)[1]],
        ];
        if q[2] == o {
            continue;
        }
        let (cq, dq) = rational_cross_dot(q[0], q[1], q[2]);
        let abs = |r: BigRational| if r < zero { -r } else { r };
        // θp < θq ⟺ D_q|C_p| − D_p|C_q| < 0, for non-flat corners.
        if cr != zero && cq != zero {
            let f = dq * abs(cr) - dt * abs(cq);
            let want = f.cmp(&zero);
            equal += want.is_eq() as usize;
            assert_eq!(
                compare_corner_angles([o, a, b], q),
                want,
                "{o:?} {a:?} {b:?} vs {q:?}"
            );
        }
    }
    assert!(yes > 1000 && no > 1000 && equal > 100, "{yes} {no} {equal}");
}

#[test]
fn flat_corners_are_0_or_180_degrees() {
    let (o, e, w, n) = ([0.0, 0.0], [1.0, 0.0], [-2.0, 0.0], [0.0, 1.0]);
    assert!(!angle_at_least_30_degrees(o, e, [3.0, 0.0]));
    assert!(angle_at_least_30_degrees(o, e, w));
    assert!(angle_at_least_30_degrees(o, e, n));
    use std::cmp::Ordering::*;
    assert_eq!(compare_corner_angles([o, e, [3.0, 0.0]], [o, e, n]), Less);
    assert_eq!(compare_corner_angles([o, e, w], [o, e, n]), Greater);
    assert_eq!(compare_corner_angles([o, e, w], [o, n, [0.0, -5.0]]), Equal);
    assert_eq!(compare_corner_angles([o, e, e], [o, w, w]), Equal);
}

/// Two triangles of (nearly) equal area: `def` is `abc` sheared along `ab`
/// (`c` moved parallel to `ab`: exactly the same area), mirrored by a grid
/// symmetry and translated, then one corner nudged by at most one unit.
fn nearly_equal_areas(rng: &mut StdRng) -> [IntPoint; 6] {
    let o = corner(rng);
    let r = |rng: &mut StdRng, bits: u32| rng.gen_range(-(1i64 << bits)..=1 << bits);
    let a = add(o, [r(rng, 20), r(rng, 20)]);
    let d = [r(rng, 24), r(rng, 24)];
    let b = add(a, d);
    let c = add(a, [r(rng, 24), r(rng, 24)]);
    let t = r(rng, 3);
    let c2 = add(c, [t * d[0], t * d[1]]);
    let k = rng.gen_range(0..8);
    let shift = add(corner(rng), [r(rng, 20), r(rng, 20)]);
    let image = |p: IntPoint| add(shift, symmetry([p[0] - o[0], p[1] - o[1]], k));
    let nudge = if rng.gen_bool(0.5) {
        [0, 0]
    } else {
        [rng.gen_range(-1..=1), rng.gen_range(-1..=1)]
    };
    [a, b, c, image(a), image(b), add(image(c2), nudge)]
}

#[test]
fn area_comparison_at_the_coordinate_limits_is_scale_invariant() {
    let mut rng = StdRng::seed_from_u64(2201);
    let twice_area_int = |a: IntPoint, b: IntPoint, c: IntPoint| {
        ((b[0] - a[0]) as i128 * (c[1] - a[1]) as i128
            - (b[1] - a[1]) as i128 * (c[0] - a[0]) as i128)
            .abs()
    };
    let (mut equal, mut unequal) = (0, 0);
    for _ in 0..4000 {
        let [a, b, c, d, e, f] = nearly_equal_areas(&mut rng);
        let expected = twice_area_int(a, b, c).cmp(&twice_area_int(d, e, f));
        (equal, unequal) = if expected.is_eq() {
            (equal + 1, unequal)
        } else {
            (equal, unequal + 1)
        };
        for scale in limit_scales() {
            let [fa, fb, fc, fd, fe, ff] = [a, b, c, d, e, f].map(|p| scaled(p, scale));
            assert_eq!(
                compare_areas([fa, fb, fc], [fd, fe, ff]),
                expected,
                "areas {a:?} {b:?} {c:?} vs {d:?} {e:?} {f:?} scaled by {scale:e}"
            );
            assert_eq!(
                compare_areas([fd, ff, fe], [fb, fa, fc]),
                expected.reverse()
            );
        }
    }
    assert!(equal > 1000 && unequal > 1000, "{equal} {unequal}");
}

/// The diamond filter's quick rejection never rejects a point the exact
/// predicates put inside a diamond triangle (both base angles strictly below
/// the diamond angle), on points on and within a few ulps of the triangles'
/// sides, at large offsets and at huge and tiny scales; and it does reject
/// the points well outside (it is not vacuous).
#[test]
fn certainly_outside_diamonds_never_rejects_an_inside_point() {
    use optri::internals::kernel::{angle_below_diamond, certainly_outside_diamonds};
    let mut rng = StdRng::seed_from_u64(SEED_DIAMOND_FILTER);
    let tan = 833.0 / 1024.0;
    let (mut inside, mut rejected, mut far) = (0usize, 0usize, 0usize);
    for round in 0..20_000 {
        let scale = [1.0, 2f64.powi(-100), 2f64.powi(150), 1.0][round % 4];
        let offset = if round % 4 == 3 { 1e9 } else { 0.0 };
        let a = [
            offset + scale * rng.gen_range(-1.0..1.0),
            offset + scale * rng.gen_range(-1.0..1.0),
        ];
        let b = [
            offset + scale * rng.gen_range(-1.0..1.0),
            offset + scale * rng.gen_range(-1.0..1.0),
        ];
        if a == b {
            continue;
        }
        let (wx, wy) = (b[0] - a[0], b[1] - a[1]);
        let side = if rng.gen_bool(0.5) { 1.0 } else { -1.0 };
        let apex = [
            a[0] + 0.5 * wx - side * 0.5 * tan * wy,
            a[1] + 0.5 * wy + side * 0.5 * tan * wx,
        ];
        // A point on a side of the triangle (or a little beyond), nudged by
        // a few ulps or a tiny relative amount.
        let t: f64 = rng.gen_range(-0.05..1.05);
        let (p, q) = match rng.gen_range(0..3) {
            0 => (a, apex),
            1 => (apex, b),
            _ => (a, b),
        };
        let mut c = [p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])];
        if rng.gen_bool(0.5) {
            c = [
                next_up_or_down(c[0], &mut rng),
                next_up_or_down(c[1], &mut rng),
            ];
        } else {
            let e = scale * 1e-11 * rng.gen_range(-1.0..1.0);
            c = [c[0] + e, c[1] - e];
        }
        let exactly_inside = angle_below_diamond(a, b, c) && angle_below_diamond(b, a, c);
        if exactly_inside {
            inside += 1;
            assert!(
                !certainly_outside_diamonds(a, b, c),
                "rejected an inside point: a {a:?}, b {b:?}, c {c:?}"
            );
        }
        if certainly_outside_diamonds(a, b, c) {
            rejected += 1;
        }
        // Far from both triangles: beyond the apex's height.
        let d = [
            a[0] + 0.5 * wx - side * 0.6 * wy,
            a[1] + 0.5 * wy + side * 0.6 * wx,
        ];
        far += certainly_outside_diamonds(a, b, d) as usize;
    }
    assert!(inside > 3000, "too few inside points: {inside}");
    assert!(
        rejected > 1000,
        "the filter rejected only {rejected} points near the sides"
    );
    assert!(far > 19_000, "the filter rejected only {far} far points");
}

/// `DiamondTriangles::position` is the exact decision (`orient_sign` and
/// `angle_below_diamond` at both ends) on points on and within a few ulps of
/// the triangles' sides and of the line, at huge and tiny scales and large
/// offsets, and on random points; its filter answers most of them (it is
/// exercised) and the exact path the rest.
#[test]
fn diamond_positions_are_the_exact_decisions() {
    use optri::internals::kernel::{angle_below_diamond, DiamondPosition, DiamondTriangles};
    let mut rng = StdRng::seed_from_u64(SEED_DIAMOND_FILTER + 1);
    let tan = 833.0 / 1024.0;
    let mut seen = [0usize; 3];
    for round in 0..40_000 {
        let scale = [1.0, 2f64.powi(-100), 2f64.powi(150), 1.0][round % 4];
        let offset = if round % 4 == 3 { 1e9 } else { 0.0 };
        let p = |rng: &mut StdRng| {
            [
                offset + scale * rng.gen_range(-1.0..1.0),
                offset + scale * rng.gen_range(-1.0..1.0),
            ]
        };
        let (a, b) = (p(&mut rng), p(&mut rng));
        if a == b {
            continue;
        }
        let (wx, wy) = (b[0] - a[0], b[1] - a[1]);
        let side = if rng.gen_bool(0.5) { 1.0 } else { -1.0 };
        let apex = [
            a[0] + 0.5 * wx - side * 0.5 * tan * wy,
            a[1] + 0.5 * wy + side * 0.5 * tan * wx,
        ];
        let c = match rng.gen_range(0..4) {
            0 => p(&mut rng),
            k => {
                let (u, v) = [(a, apex), (apex, b), (a, b)][k - 1];
                let t: f64 = rng.gen_range(-0.05..1.05);
                let c = [u[0] + t * (v[0] - u[0]), u[1] + t * (v[1] - u[1])];
                if rng.gen_bool(0.5) {
                    [
                        next_up_or_down(c[0], &mut rng),
                        next_up_or_down(c[1], &mut rng),
                    ]
                } else {
                    // Towards the triangle's inside by a small relative amount.
                    let e = scale * 10f64.powi(rng.gen_range(-14..-2));
                    [c[0] - side * e * wy, c[1] + side * e * wx]
                }
            }
        };
        if c == a || c == b {
            continue;
        }
        let o = orient_sign(a, b, c);
        let expected = if o != 0 && angle_below_diamond(a, b, c) && angle_below_diamond(b, a, c) {
            if o > 0 {
                DiamondPosition::Left
            } else {
                DiamondPosition::Right
            }
        } else {
            DiamondPosition::Outside
        };
        assert_eq!(
            DiamondTriangles::new(a, b).position(c),
            expected,
            "a {a:?}, b {b:?}, c {c:?}"
        );
        seen[expected as usize] += 1;
    }
    assert!(seen.iter().all(|&k| k > 3000), "{seen:?}");
}

/// `exact_squared_length` claims exactness only when it holds: wherever it
/// answers for both segments, the numbers compare as the exact rational
/// lengths do (nearly degenerate samples at every scale, where it must
/// often decline), and it always answers on integer coordinates below 2²⁵,
/// as a six-decimal file scaled by 10⁶ gives, negative ones included.
#[test]
fn exact_squared_lengths_are_exact_where_claimed() {
    let mut rng = StdRng::seed_from_u64(SEED_EXACT_SQUARED_LENGTHS);
    let (mut claimed, mut declined, mut ties) = (0, 0, 0);
    let settings = [
        (1.0, 0.0),
        (1e6, 0.0),
        (1e-3, 2f64.powi(40)),
        (2f64.powi(-100), 0.0),
        (2f64.powi(150), 0.0),
        (2f64.powi(24), -(2f64.powi(24))),
    ];
    for &(scale, offset) in &settings {
        for _ in 0..3000 {
            let [a, b, c, d] = sample(&mut rng, scale, offset);
            match (exact_squared_length(a, b), exact_squared_length(c, d)) {
                (Some(s), Some(t)) => {
                    let expected = oracle::compare_squared_lengths(a, b, c, d);
                    assert_eq!(s.total_cmp(&t), expected, "{a:?} {b:?} {c:?} {d:?}");
                    claimed += 1;
                    ties += expected.is_eq() as usize;
                }
                _ => declined += 1,
            }
        }
    }
    for _ in 0..3000 {
        let q = |rng: &mut StdRng| {
            let limit = (1i64 << 25) - 1;
            [
                rng.gen_range(-limit..=limit) as f64,
                rng.gen_range(-limit..=limit) as f64,
            ]
        };
        let (a, b) = (q(&mut rng), q(&mut rng));
        let length = exact_squared_length(a, b).expect("integers below 2^25 are exact");
        let (dx, dy) = ((a[0] - b[0]) as i128, (a[1] - b[1]) as i128);
        assert_eq!(length as i128, dx * dx + dy * dy);
    }
    assert!(
        claimed > 1000 && declined > 1000 && ties > 100,
        "{claimed} {declined} {ties}"
    );
}

/// The wedge at `o` from ray `first` counter-clockwise to ray `last` by
/// angular order in exact rationals, independent of the kernel's case
/// analysis: directions are ordered by the half-turn `[0, π)` or
/// `[π, 2π)` they lie in, measured from `first − o`, then by their cross
/// product; `x` is inside iff it is not on the ray `first` and comes before
/// `last` (or `last` is on the ray `first`: a full turn).
fn wedge_by_angular_order(o: Point, first: Point, last: Point, x: Point) -> bool {
    use oracle::{to_rational, BigRational};
    let offset = |p: Point| {
        [
            to_rational(p[0]) - to_rational(o[0]),
            to_rational(p[1]) - to_rational(o[1]),
        ]
    };
    let zero = BigRational::from_integer(0.into());
    let cross = |a: &[BigRational; 2], b: &[BigRational; 2]| {
        (a[0].clone() * b[1].clone() - a[1].clone() * b[0].clone()).cmp(&zero)
    };
    let dot = |a: &[BigRational; 2], b: &[BigRational; 2]| {
        (a[0].clone() * b[0].clone() + a[1].clone() * b[1].clone()).cmp(&zero)
    };
    let (u, w, d) = (offset(first), offset(last), offset(x));
    if d[0] == zero && d[1] == zero {
        return false;
    }
    use std::cmp::Ordering::{Equal, Greater};
    let at_zero = |a: &[BigRational; 2]| cross(&u, a) == Equal && dot(&u, a) == Greater;
    let half = |a: &[BigRational; 2]| u8::from(!(cross(&u, a) == Greater || at_zero(a)));
    let before = |a: &[BigRational; 2], b: &[BigRational; 2]| {
        half(a) < half(b) || (half(a) == half(b) && cross(a, b) == Greater)
    };
    !at_zero(&d) && (at_zero(&w) || before(&d, &w))
}

/// `strictly_inside_wedge` against the angular-order reference on small
/// integer configurations (collinear rays, straight and reflex corners,
/// full turns with `last` on the ray `first` or equal to it, `x` on either
/// ray or at `o`), on nearly degenerate doubles and at huge and tiny
/// magnitudes; every kind of corner and both answers occur often.
#[test]
fn wedges_match_the_angular_order() {
    let mut rng = StdRng::seed_from_u64(SEED_WEDGES);
    let mut seen = [[0usize; 2]; 4]; // per corner kind: [outside, inside]
    let mut check = |o: Point, first: Point, last: Point, x: Point| {
        if first == o || last == o {
            return;
        }
        let expected = wedge_by_angular_order(o, first, last, x);
        assert_eq!(
            strictly_inside_wedge(o, first, last, x),
            expected,
            "o {o:?}, first {first:?}, last {last:?}, x {x:?}"
        );
        let kind = match oracle::orient(o, first, last) {
            1 => 0,
            -1 => 1,
            _ if oracle::dot_sign(o, first, last) < 0 => 2,
            _ => 3,
        };
        seen[kind][expected as usize] += 1;
    };
    let small = |rng: &mut StdRng| [rng.gen_range(-3..=3) as f64, rng.gen_range(-3..=3) as f64];
    for _ in 0..40_000 {
        let (o, first) = (small(&mut rng), small(&mut rng));
        let last = match rng.gen_range(0..4) {
            // On the line of the first ray: a half or a full turn.
            0 => {
                let k = [-2.0, -1.0, 1.0, 2.0][rng.gen_range(0..4)];
                [o[0] + k * (first[0] - o[0]), o[1] + k * (first[1] - o[1])]
            }
            1 => first,
            _ => small(&mut rng),
        };
        let x = match rng.gen_range(0..6) {
            0 => o,
            1 => first,
            2 => last,
            _ => small(&mut rng),
        };
        check(o, first, last, x);
    }
    for &(scale, offset) in &[
        (1.0, 0.0),
        (1e-3, 2f64.powi(40)),
        (2f64.powi(-120), 0.0),
        (2f64.powi(180), 0.0),
    ] {
        for _ in 0..5000 {
            let [o, first, last, x] = sample(&mut rng, scale, offset);
            check(o, first, last, x);
            // The same corner with x exactly on the line through o and
            // first, on either side.
            let k = [-3.0, 2.0][rng.gen_range(0..2)];
            let on_line = [o[0] + k * (first[0] - o[0]), o[1] + k * (first[1] - o[1])];
            check(o, first, last, on_line);
        }
    }
    assert!(
        seen.iter().all(|kind| kind[0] > 500 && kind[1] > 500),
        "{seen:?}"
    );
}

/// `strictly_inside_wedge_symbolic` against the same angular order on the
/// perturbed points (the oracle's perturbed orientation), on lattice sets
/// full of collinear triples; the perturbation never leaves a direction on
/// a ray but its own point's.
#[test]
fn perturbed_wedges_match_the_perturbed_angular_order() {
    let mut rng = StdRng::seed_from_u64(SEED_WEDGES_PERTURBED);
    let mut answers = [0usize; 2];
    for _ in 0..200 {
        let mut points: Vec<Point> = Vec::new();
        while points.len() < 8 {
            let p = [rng.gen_range(-2..=2) as f64, rng.gen_range(-2..=2) as f64];
            if !points.contains(&p) {
                points.push(p);
            }
        }
        for _ in 0..100 {
            let label = |rng: &mut StdRng| rng.gen_range(0..points.len() as u32);
            let (o, first, last, x) = (
                label(&mut rng),
                label(&mut rng),
                label(&mut rng),
                label(&mut rng),
            );
            if first == o || last == o {
                continue;
            }
            let orient = |a: u32, b: u32, c: u32| oracle::orient_perturbed(&points, a, b, c);
            // Angles from the ray `first`: half-turn, then orientation.
            let half = |a: u32| u8::from(!(a == first || orient(o, first, a) > 0));
            let before = |a: u32, b: u32| {
                half(a) < half(b) || (half(a) == half(b) && a != b && orient(o, a, b) > 0)
            };
            let expected = x != o && x != first && (last == first || before(x, last));
            assert_eq!(
                strictly_inside_wedge_symbolic(&points, o, first, last, x),
                expected,
                "{points:?}: o {o}, first {first}, last {last}, x {x}"
            );
            answers[expected as usize] += 1;
        }
    }
    assert!(answers.iter().all(|&k| k > 3000), "{answers:?}");
}

/// Zero-length rays bound no wedge and are refused; a zero direction is
/// inside no wedge; `same_direction` is the ray rule.
#[test]
fn zero_lengths_in_wedges() {
    let o = [1.0, 1.0];
    assert!(!strictly_inside_wedge(o, [2.0, 1.0], [1.0, 2.0], o));
    assert!(!strictly_inside_wedge(o, [2.0, 1.0], [2.0, 1.0], o));
    assert!(strictly_inside_wedge(o, [2.0, 1.0], [2.0, 1.0], [0.0, 1.0]));
    assert!(!strictly_inside_wedge(
        o,
        [2.0, 1.0],
        [3.0, 1.0],
        [5.0, 1.0]
    ));
    assert!(same_direction(o, [2.0, 1.0], [5.0, 1.0]));
    assert!(!same_direction(o, [2.0, 1.0], [0.0, 1.0]));
    assert!(!same_direction(o, [2.0, 1.0], o));
    for (first, last) in [(o, [2.0, 1.0]), ([2.0, 1.0], o)] {
        let refused =
            std::panic::catch_unwind(|| strictly_inside_wedge(o, first, last, [0.0, 0.0]));
        assert!(refused.is_err(), "first {first:?}, last {last:?}");
    }
    let points = [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]];
    let refused = std::panic::catch_unwind(|| strictly_inside_wedge_symbolic(&points, 0, 0, 1, 2));
    assert!(refused.is_err());
    assert!(!strictly_inside_wedge_symbolic(&points, 0, 1, 2, 0));
}

// ---------------------------------------------------------------------------
// Area thresholds: a doubled area against `m · 10^x`, exactly.

/// `m · 10^x` as an exact rational.
fn decimal_rational(m: u128, x: i64) -> BigRational {
    let ten = BigInt::from(10).pow(x.unsigned_abs() as u32);
    let m = BigRational::from_integer(BigInt::from(m));
    if x >= 0 {
        m * BigRational::from_integer(ten)
    } else {
        m / BigRational::from_integer(ten)
    }
}

#[test]
fn area_thresholds_match_exact_rationals_at_and_next_to_the_area() {
    const SEED: u64 = 0x0dec_13a1;
    let mut rng = StdRng::seed_from_u64(SEED);
    let (mut cases, mut equal) = (0usize, 0usize);
    for round in 0..4000 {
        // Integer triangles (decimal-exact input scaled to integers) and
        // binary triangles at several magnitudes.
        let scale: f64 = [1.0, 1e-9, 1e12, 3.0e40, 1e-40][round % 5];
        let integer = round % 5 == 0;
        let p = |rng: &mut StdRng| -> Point {
            if integer {
                [
                    rng.gen_range(-1_000_000i64..1_000_000) as f64,
                    rng.gen_range(-1_000_000i64..1_000_000) as f64,
                ]
            } else {
                [
                    scale * rng.gen_range(-1.0..1.0),
                    scale * rng.gen_range(-1.0..1.0),
                ]
            }
        };
        let t = [p(&mut rng), p(&mut rng), p(&mut rng)];
        let exact = oracle::twice_area(t[0], t[1], t[2]);
        if exact == BigRational::from_integer(BigInt::from(0)) {
            continue;
        }
        // The decimal just below the area at x digits, then its neighbours.
        let x: i64 = if integer {
            rng.gen_range(-3..3)
        } else {
            let magnitude = (scale * scale).log10().round() as i64;
            magnitude - rng.gen_range(0..30)
        };
        let floor = (exact.clone() / decimal_rational(1, x))
            .floor()
            .to_integer();
        let Ok(m) = u128::try_from(&floor) else {
            continue;
        };
        for m in [m.saturating_sub(1), m, m + 1, m + 2] {
            let want = exact.cmp(&decimal_rational(m, x));
            let got = AreaThreshold::new(m, x).compare(t);
            assert_eq!(got, want, "{t:?} against {m}e{x}");
            cases += 1;
            equal += want.is_eq() as usize;
        }
    }
    assert!(cases > 10_000, "{cases}");
    assert!(equal > 500, "{equal}");
    // Thresholds beyond every area, zero, and a degenerate triangle.
    let t = [[0.0, 0.0], [MAX_COORDINATE, 0.0], [0.0, MAX_COORDINATE]];
    assert_eq!(
        AreaThreshold::new(1, 130).compare(t),
        std::cmp::Ordering::Less
    );
    assert_eq!(
        AreaThreshold::new(1, -200).compare(t),
        std::cmp::Ordering::Greater
    );
    let tiny = [[0.0, 0.0], [MIN_COORDINATE, 0.0], [0.0, MIN_COORDINATE]];
    // Its doubled area is 2⁻²⁸⁴ ≈ 1.2e-86.
    assert_eq!(
        AreaThreshold::new(1, -80).compare(tiny),
        std::cmp::Ordering::Less
    );
    assert_eq!(
        AreaThreshold::new(1, -90).compare(tiny),
        std::cmp::Ordering::Greater
    );
    assert_eq!(
        AreaThreshold::new(1, -200).compare(tiny),
        std::cmp::Ordering::Greater
    );
    assert_eq!(
        AreaThreshold::new(0, 5).compare(tiny),
        std::cmp::Ordering::Greater
    );
    let flat = [[0.0, 0.0], [1.0, 1.0], [2.0, 2.0]];
    assert_eq!(
        AreaThreshold::new(0, 0).compare(flat),
        std::cmp::Ordering::Equal
    );
    assert_eq!(
        AreaThreshold::new(1, -300).compare(flat),
        std::cmp::Ordering::Less
    );
    // Decimal coordinates as doubles: 0.1 · 1 is no double's area.
    let tenth = [[0.0, 0.0], [0.1, 0.0], [0.0, 1.0]];
    let want = oracle::twice_area(tenth[0], tenth[1], tenth[2]).cmp(&decimal_rational(1, -1));
    assert_eq!(AreaThreshold::new(1, -1).compare(tenth), want);
    assert_ne!(want, std::cmp::Ordering::Equal);
}

const SEED_ANGLE_FLOOR: u64 = 0xA1FA;

/// `AngleFloor` against exact references: at 30° the integer definition
/// (`at_least_30_int`), at 45° `|u×v| ≥ u·v`, at 60° `(u×v)² ≥ 3(u·v)²`,
/// each at every scale of the coordinate range; at other floors a rational
/// tangent reference where it decides (`tan α` from the platform within
/// 10⁻¹² relative); and across a floor, corners a few units in the last
/// place apart switch from below to at least exactly once.
#[test]
fn angle_floor_equals_exact_references() {
    use optri::kernel::AngleFloor;
    let mut rng = StdRng::seed_from_u64(SEED_ANGLE_FLOOR);
    let thirty = AngleFloor::new(30.0).unwrap();
    for _ in 0..2000 {
        let [o, a, b] = corner_near_30(&mut rng);
        let expected = at_least_30_int(o, a, b);
        for scale in limit_scales() {
            let [fo, fa, fb] = [o, a, b].map(|p| scaled(p, scale));
            assert_eq!(thirty.admits(fo, fa, fb), expected, "{o:?} {a:?} {b:?}");
        }
    }
    type Reference = fn(i128, i128) -> bool;
    let exact: [(f64, Reference); 2] = [
        (45.0, |c, d| d <= 0 || c.abs() >= d),
        (60.0, |c, d| d <= 0 || c * c >= 3 * d * d),
    ];
    let (mut equal, mut decided) = (0, 0);
    for (degrees, reference) in exact {
        let floor = AngleFloor::new(degrees).unwrap();
        for _ in 0..2000 {
            let o = corner(&mut rng);
            let bits = rng.gen_range(2..=28);
            let r = |rng: &mut StdRng| rng.gen_range(-(1i64 << bits)..=1 << bits);
            let u = [r(&mut rng), r(&mut rng)];
            let sign = if rng.gen_bool(0.5) { 1.0 } else { -1.0 };
            let v = if degrees == 45.0 && rng.gen_bool(0.25) {
                // Exactly 45°: u plus u turned a quarter.
                let s = sign as i64;
                [u[0] - s * u[1], u[1] + s * u[0]]
            } else {
                add(
                    rotated(u, sign * degrees, rng.gen_range(0.5..2.0)),
                    [rng.gen_range(-1..=1), rng.gen_range(-1..=1)],
                )
            };
            if u == [0, 0] || v == [0, 0] {
                continue;
            }
            let (a, b) = (add(o, u), add(o, v));
            let (c, d) = cross_dot_int(o, a, b);
            equal += (c.abs() == d) as usize;
            for scale in limit_scales() {
                let [fo, fa, fb] = [o, a, b].map(|p| scaled(p, scale));
                assert_eq!(floor.admits(fo, fa, fb), reference(c, d), "{degrees}°");
            }
        }
    }
    for degrees in [0.5, 12.5, 25.3, 37.1, 59.9] {
        let floor = AngleFloor::new(degrees).unwrap();
        let tan = degrees.to_radians().tan();
        let (lo, hi) = (
            oracle::to_rational(tan * (1.0 - 1e-12)),
            oracle::to_rational(tan * (1.0 + 1e-12)),
        );
        for _ in 0..1000 {
            let u = [
                rng.gen_range(1..1i64 << 28),
                rng.gen_range(-(1i64 << 28)..1 << 28),
            ];
            let v = add(
                rotated(u, degrees, rng.gen_range(0.5..2.0)),
                [rng.gen_range(-2..=2), rng.gen_range(-2..=2)],
            );
            let (c, d) = cross_dot_int([0, 0], u, v);
            if d <= 0 {
                continue;
            }
            let ratio = oracle::BigRational::new(c.abs().into(), d.into());
            let expected = if ratio >= hi {
                true
            } else if ratio < lo {
                false
            } else {
                continue;
            };
            let [fo, fa, fb] = [[0, 0], u, v].map(|p| scaled(p, 1.0));
            assert_eq!(floor.admits(fo, fa, fb), expected, "{degrees}° {u:?} {v:?}");
            decided += 1;
        }
        // Corners (0,0), (1,0), (1, t) for t a few ulps around tan α.
        let mut t = tan;
        for _ in 0..8 {
            t = t.next_down();
        }
        let mut switches = 0;
        let mut previous = floor.admits([0.0, 0.0], [1.0, 0.0], [1.0, t]);
        for _ in 0..16 {
            t = t.next_up();
            let now = floor.admits([0.0, 0.0], [1.0, 0.0], [1.0, t]);
            assert!(now || !previous, "{degrees}°: not monotone at {t}");
            switches += (now != previous) as usize;
            previous = now;
        }
        assert!(switches <= 1, "{degrees}°");
    }
    assert!(equal >= 100 && decided >= 4000, "{equal} {decided}");
}
