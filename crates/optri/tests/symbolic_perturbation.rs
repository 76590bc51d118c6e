//! Proof by oracle: `kernel::symbolic` against an independent expansion of
//! the perturbed predicates as polynomials in ε with exact rational
//! coefficients (`optri_oracle::symbolic`), on thousands of degenerate cases.

use optri::internals::kernel::segment_order;
use optri::kernel::{compare_lengths_symbolic, orient_symbolic};
use optri_oracle as oracle;
use optri_oracle::inputs::{cocircular_seven_with_centre, distinct_lattice_points, shuffled_grid};
use rand::rngs::StdRng;
use rand::seq::SliceRandom;
use rand::SeedableRng;
use std::cmp::Ordering;

type Point = [f64; 2];

const SEED_DEGENERATE_SETS: u64 = 2024;
const SEED_ORIENTATION: u64 = 77;
const SEED_SEGMENT_ORDER: u64 = 5;

fn degenerate_sets() -> Vec<(String, Vec<Point>)> {
    let mut rng = StdRng::seed_from_u64(SEED_DEGENERATE_SETS);
    let mut sets = vec![
        ("grid 3x3".to_string(), shuffled_grid(&mut rng, 3, 3, 1.0)),
        ("grid 4x3".to_string(), shuffled_grid(&mut rng, 4, 3, 1.0)),
        (
            "grid 3x3 step 0.1".to_string(),
            shuffled_grid(&mut rng, 3, 3, 0.1),
        ),
        (
            "grid 3x3 huge".to_string(),
            shuffled_grid(&mut rng, 3, 3, -(2f64.powi(150))),
        ),
        ("cocircular r=5".to_string(), cocircular_seven_with_centre()),
    ];
    // Small random integer sets: many collinear triples and equal lengths.
    for k in 0..6 {
        let pts = distinct_lattice_points(&mut rng, 8, -2..3, -2..3);
        sets.push((format!("random small {k}"), pts));
    }
    sets
}

#[test]
fn orientation_matches_the_polynomial_expansion() {
    let mut checked = 0;
    let mut degenerate = 0;
    let mut rng = StdRng::seed_from_u64(SEED_ORIENTATION);
    let mut sets = degenerate_sets();
    sets.push(("grid 4x4".into(), shuffled_grid(&mut rng, 4, 4, 1.0)));
    // Two crossing lines of five points each, plus two off-line points.
    let mut lines: Vec<Point> = (0..5)
        .flat_map(|k| [[k as f64, 2.0 * k as f64], [k as f64, 7.0 - k as f64]])
        .collect();
    lines.extend([[1.5, 0.0], [-1.0, 3.0]]);
    lines.shuffle(&mut rng);
    sets.push(("two lines".into(), lines));
    for (label, pts) in sets {
        let n = pts.len() as u32;
        for i in 0..n {
            for j in 0..n {
                for k in 0..n {
                    if i == j || j == k || i == k {
                        continue;
                    }
                    let expected = oracle::orient_perturbed(&pts, i, j, k);
                    assert_ne!(expected, 0);
                    let got = orient_symbolic(&pts, i, j, k);
                    assert_eq!(got, expected, "{label}: orient({i}, {j}, {k})");
                    checked += 1;
                    let p = |m: u32| pts[m as usize];
                    degenerate += (oracle::orient(p(i), p(j), p(k)) == 0) as usize;
                }
            }
        }
    }
    assert!(checked > 8000 && degenerate > 700, "{checked} {degenerate}");
}

fn segments(n: u32) -> Vec<[u32; 2]> {
    (0..n)
        .flat_map(|i| (i + 1..n).map(move |j| [i, j]))
        .collect()
}

#[test]
fn length_comparison_matches_the_polynomial_expansion() {
    let mut checked = 0;
    let mut ties = 0;
    let mut shared = 0;
    for (label, pts) in degenerate_sets() {
        let segs = segments(pts.len() as u32);
        for s in &segs {
            for t in &segs {
                // Both endpoint orders, since the perturbation is per point.
                for (a, b) in [(*s, *t), ([s[1], s[0]], *t), (*s, [t[1], t[0]])] {
                    let expected = oracle::compare_lengths_perturbed(&pts, a, b);
                    assert_eq!(expected == Ordering::Equal, s == t, "{label}");
                    let got = compare_lengths_symbolic(&pts, a, b);
                    assert_eq!(got, expected, "{label}: |{a:?}| vs |{b:?}|");
                    checked += 1;
                }
                let p = |m: u32| pts[m as usize];
                if s != t
                    && oracle::compare_squared_lengths(p(s[0]), p(s[1]), p(t[0]), p(t[1]))
                        == Ordering::Equal
                {
                    ties += 1;
                    shared += (s.iter().any(|v| t.contains(v))) as usize;
                }
            }
        }
    }
    assert!(
        checked > 20000 && ties > 1000 && shared > 200,
        "{checked} {ties} {shared}"
    );
}

#[test]
fn segment_order_is_a_total_order_on_grid_segments() {
    let mut rng = StdRng::seed_from_u64(SEED_SEGMENT_ORDER);
    for (w, h) in [(3, 3), (4, 4), (5, 3)] {
        let pts = shuffled_grid(&mut rng, w, h, 1.0);
        let mut sorted = segments(pts.len() as u32);
        sorted.shuffle(&mut rng);
        sorted.sort_by(segment_order(&pts));
        // The same order as sorting by the independent expansion.
        let mut by_oracle = sorted.clone();
        by_oracle.shuffle(&mut rng);
        by_oracle.sort_by(|s, t| oracle::compare_lengths_perturbed(&pts, *s, *t));
        assert_eq!(sorted, by_oracle, "{w}x{h}");
        // Every pair in sorted order compares Less: transitive, antisymmetric.
        for a in 0..sorted.len() {
            for b in a + 1..sorted.len() {
                assert_eq!(
                    compare_lengths_symbolic(&pts, sorted[a], sorted[b]),
                    Ordering::Less,
                    "{w}x{h}: {:?} {:?}",
                    sorted[a],
                    sorted[b]
                );
            }
        }
    }
}

/// Lune and half-lune membership (exact and symbolic) against their
/// definitions evaluated by the oracle.
#[test]
fn lunes_match_their_definitions() {
    use optri::internals::kernel::{in_half_lune, in_half_lune_symbolic};
    use optri::kernel::{in_lune, in_lune_symbolic};
    let mut checked = 0;
    let mut boundary = 0;
    for (label, pts) in degenerate_sets() {
        let n = pts.len() as u32;
        let p = |m: u32| pts[m as usize];
        for a in 0..n {
            for b in 0..n {
                for x in 0..n {
                    if a == b {
                        continue;
                    }
                    let (pa, pb, px) = (p(a), p(b), p(x));
                    let exact = oracle::compare_squared_lengths(px, pa, pa, pb) == Ordering::Less
                        && oracle::compare_squared_lengths(px, pb, pa, pb) == Ordering::Less;
                    assert_eq!(in_lune(pa, pb, px), exact, "{label}: lune({a},{b}) ∋ {x}");
                    let half = exact && oracle::orient(pa, pb, px) >= 0;
                    assert_eq!(in_half_lune(pa, pb, px), half, "{label}");
                    boundary += (oracle::compare_squared_lengths(px, pa, pa, pb) == Ordering::Equal)
                        as usize;
                    if x == a || x == b {
                        assert!(!in_lune_symbolic(&pts, a, b, x));
                        continue;
                    }
                    let sym = oracle::compare_lengths_perturbed(&pts, [x, a], [a, b])
                        == Ordering::Less
                        && oracle::compare_lengths_perturbed(&pts, [x, b], [a, b])
                            == Ordering::Less;
                    assert_eq!(
                        in_lune_symbolic(&pts, a, b, x),
                        sym,
                        "{label}: symbolic lune"
                    );
                    let sym_half = sym && oracle::orient_perturbed(&pts, a, b, x) > 0;
                    assert_eq!(in_half_lune_symbolic(&pts, a, b, x), sym_half, "{label}");
                    checked += 1;
                }
            }
        }
    }
    assert!(checked > 3000 && boundary > 100, "{checked} {boundary}");
}
