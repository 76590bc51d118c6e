//! Proof by oracle: the kernel's exact predicates against exact rational /
//! big-integer evaluation, on nearly degenerate inputs where rounded
//! arithmetic gets the sign wrong (near-collinear, near-cocircular, nearly
//! equal lengths and areas, large offsets with small differences, huge and
//! tiny magnitudes).

use optri::kernel::{compare_areas, compare_lengths, dot_sign, incircle_sign, orient_sign};
use optri_oracle as oracle;
use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};

type Point = [f64; 2];

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
    let mut rng = StdRng::seed_from_u64(42);
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
