//! The measures against the oracle's independent exact evaluations
//! (`optri_oracle::bottleneck_measures`): angles by the law of cosines over
//! all three corners, heights as the smallest of the three altitudes,
//! eccentricity from the explicit circumcentre and its distance to the
//! closed triangle, slope from the gradient solved by Cramer's rule.

use super::*;
use crate::kernel::orient_sign;
use rand::{rngs::StdRng, Rng, SeedableRng};

/// The independent value: the oracle's badness (`−h²` for heights, so
/// negated back), on the triangle's corners as a point list.
fn reference(measure: TriangleMeasure, t: &Corners) -> BigRational {
    use optri_oracle::bottleneck_measures::{badness, Bottleneck};
    let b = match measure {
        TriangleMeasure::LargestAngle => Bottleneck::MinMaxAngle,
        TriangleMeasure::SmallestHeight => Bottleneck::MaxMinHeight,
        TriangleMeasure::Eccentricity => Bottleneck::MinMaxEccentricity,
        TriangleMeasure::Slope => Bottleneck::MinMaxSlope,
    };
    let value = badness(b, &t.0, &t.1, [0, 1, 2]);
    if measure == TriangleMeasure::SmallestHeight {
        -value
    } else {
        value
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

/// `worst_ties` (cached exact values, congruence shortcut) against the
/// plain pairwise comparison, on lattice triangles full of ties: copies
/// moved, turned by quarter turns and mirrored, and random ones.
#[test]
fn worst_ties_match_pairwise_comparisons() {
    let mut rng = StdRng::seed_from_u64(41);
    for round in 0..60 {
        let base: Vec<[Point; 3]> = (0..3)
            .map(|_| {
                [0; 3].map(|_| {
                    [
                        f64::from(rng.gen_range(-4..5)),
                        f64::from(rng.gen_range(-4..5)),
                    ]
                })
            })
            .filter(|t| orient_sign(t[0], t[1], t[2]) != 0)
            .collect();
        if base.is_empty() {
            continue;
        }
        let mut list: Vec<Corners> = Vec::new();
        for _ in 0..12 {
            let t = base[rng.gen_range(0..base.len())];
            let (dx, dy) = (
                f64::from(rng.gen_range(-9..10)),
                f64::from(rng.gen_range(-9..10)),
            );
            let turn = rng.gen_range(0..4);
            let mirror = rng.gen_bool(0.5);
            let moved = t.map(|[x, y]| {
                let (x, y) = if mirror { (-x, y) } else { (x, y) };
                let (x, y) = match turn {
                    0 => (x, y),
                    1 => (-y, x),
                    2 => (-x, -y),
                    _ => (y, -x),
                };
                [x + dx, y + dy]
            });
            let z = [0; 3].map(|_| f64::from(rng.gen_range(-2..3)));
            list.push((moved, if round % 2 == 0 { [0.0; 3] } else { z }));
        }
        for measure in [
            TriangleMeasure::LargestAngle,
            TriangleMeasure::SmallestHeight,
            TriangleMeasure::Eccentricity,
            TriangleMeasure::Slope,
        ] {
            let naive: Vec<usize> = (0..list.len())
                .filter(|&i| {
                    list.iter()
                        .all(|u| measure.compare_badness(&list[i], u) != Ordering::Less)
                })
                .collect();
            assert_eq!(
                measure.worst_ties(list.iter().copied()),
                naive,
                "{measure:?} {round}"
            );
        }
    }
}
