//! Proof by oracle: the kernel's exact predicates against exact rational /
//! big-integer evaluation, on nearly degenerate inputs where rounded
//! arithmetic gets the sign wrong (near-collinear, near-cocircular, nearly
//! equal lengths and areas, large offsets with small differences, huge and
//! tiny magnitudes), and at the documented coordinate limits 2^201 and
//! 2^-142.

use optri::kernel::{
    compare_areas, compare_lengths, dot_sign, in_half_lune, in_lune, incircle_sign, orient_sign,
    MAX_COORDINATE, MIN_COORDINATE,
};
use optri_oracle as oracle;
use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};

type Point = [f64; 2];

const SEED_NEARLY_DEGENERATE: u64 = 42;
const SEED_ORIENTATION_AT_LIMITS: u64 = 201;
const SEED_LENGTHS_AT_LIMITS: u64 = 142;
const SEED_LUNES_AT_LIMITS: u64 = 2142;
const SEED_HUGE_AND_TINY_MIXED: u64 = 343;

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
