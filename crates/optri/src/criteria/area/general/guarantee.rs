//! What the seeds prove for a general-set area result that is not certified
//! optimal: T. S. Vassilev, *Optimal area triangulation*, PhD thesis,
//! University of Saskatchewan, 2005, §3.4–3.5 (Property 77, Theorem 81,
//! Table 3.2).
//!
//! Theorem 81: for `0° < β < α ≤ 30°`, an α-triangulation `T_α` and a
//! β-triangulation `T_β` of the same points, the triangles matched by
//! Aichholzer et al.'s matching (Property 78) have area ratios
//! `f₁ ≤ A_α/A_β ≤ f₂` with
//!
//! ```text
//!   f₁ = tan α · tan²β · tan(β/2)
//!   f₂ = max( 1/(tan β · tan²α · tan(α/2)),  1/(2k₁² · sin 2β · tan(α/2)) )
//!   k₁ = (2 cos α)^(−i),  i = ⌈180°/(2α) − ½⌉
//! ```
//!
//! where the second term of `f₂` is the placement (d) of the proof, which
//! exists only when `2β + 7α ≤ 180°` (L5835, L7491): the theorem's statement
//! omits the condition, Table 3.2 applies it (the tests recompute the table).
//! With `T_β` the optimum, the result's smallest area is at least `f₁` times
//! the optimal one (MaxMin, factor `1/f₁`) and its largest area at most `f₂`
//! times the optimal one (MinMax). `β`, the smallest angle of the unknown
//! optimum, is not known, so the factors are stated for a few `β`; the
//! certified bound is what holds on the input.

use super::super::AreaBottleneck;

/// `(1/f₁, f₂)` of Theorem 81 (module docs) for `0 < β < α ≤ 30` degrees,
/// evaluated in floating point (documentation, never a decision).
pub fn theorem_81_factors(alpha: f64, beta: f64) -> (f64, f64) {
    let (a, b) = (alpha.to_radians(), beta.to_radians());
    let f1 = a.tan() * b.tan().powi(2) * (b / 2.0).tan();
    let mut f2 = 1.0 / (b.tan() * a.tan().powi(2) * (a / 2.0).tan());
    if 2.0 * beta + 7.0 * alpha <= 180.0 {
        let i = (180.0 / (2.0 * alpha) - 0.5).ceil();
        let k1 = (2.0 * a.cos()).powf(-i);
        f2 = f2.max(1.0 / (2.0 * k1 * k1 * (2.0 * b).sin() * (a / 2.0).tan()));
    }
    (1.0 / f1, f2)
}

/// The values of `β` the factors are stated for, as Table 3.2 samples them:
/// `α − 2°, α − 4°, …, α − 10°` above 0, or `α/2` when none is.
pub(super) fn sample_betas(alpha: f64) -> Vec<f64> {
    let betas: Vec<f64> = (1..=5)
        .map(|k| alpha - 2.0 * f64::from(k))
        .filter(|&b| b > 0.0)
        .collect();
    if betas.is_empty() {
        vec![alpha / 2.0]
    } else {
        betas
    }
}

/// Theorem 81's factor for `objective` at `α` (the result's smallest angle,
/// capped at 30°: an α-triangulation for α > 30° is a 30°-triangulation),
/// for each sampled `β`: `(β, factor)`.
pub(super) fn sampled_factors(objective: AreaBottleneck, alpha: f64) -> Vec<[f64; 2]> {
    let alpha = alpha.min(30.0);
    sample_betas(alpha)
        .into_iter()
        .map(|beta| {
            let (maxmin, minmax) = theorem_81_factors(alpha, beta);
            let factor = match objective {
                AreaBottleneck::MaxMin => maxmin,
                AreaBottleneck::MinMax => minmax,
            };
            [beta, factor]
        })
        .collect()
}

/// Theorem 81 in words for `objective` and the result's smallest angle
/// `alpha` (degrees).
pub(super) fn theorem_81_statement(objective: AreaBottleneck, alpha: f64) -> String {
    let a = alpha.min(30.0);
    let factors: Vec<String> = sampled_factors(objective, alpha)
        .into_iter()
        .map(|[beta, factor]| format!("{factor:.2} at β = {beta}°"))
        .collect();
    let (measure, direction, factor) = match objective {
        AreaBottleneck::MaxMin => (
            "smallest area",
            "at least the optimal one divided by",
            "1/f₁ = 1/(tan α·tan²β·tan(β/2))",
        ),
        AreaBottleneck::MinMax => (
            "largest area",
            "at most the optimal one times",
            "f₂ = max(1/(tan β·tan²α·tan(α/2)), 1/(2k₁²·sin 2β·tan(α/2)) when 2β + 7α ≤ 180°)",
        ),
    };
    format!(
        "Vassilev's Theorem 81 with α = {a}° (the result is an α-triangulation): if an optimal \
         triangulation has smallest angle β < α, the result's {measure} is {direction} \
         {factor}: {}",
        factors.join(", ")
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Table 3.2 of the thesis (L7546–7690): α, β, 1/f₁, f₂ as printed.
    const TABLE_3_2: [[f64; 4]; 50] = [
        [30.0, 28.0, 24.57, 21.06],
        [30.0, 26.0, 31.54, 22.96],
        [30.0, 24.0, 41.11, 25.15],
        [30.0, 22.0, 54.59, 27.71],
        [30.0, 20.0, 74.15, 30.76],
        [28.0, 26.0, 34.25, 29.09],
        [28.0, 24.0, 44.64, 31.86],
        [28.0, 22.0, 59.27, 35.11],
        [28.0, 20.0, 80.51, 38.98],
        [28.0, 18.0, 112.48, 43.66],
        [26.0, 24.0, 48.66, 40.90],
        [26.0, 22.0, 64.62, 45.07],
        [26.0, 20.0, 87.77, 50.03],
        [26.0, 18.0, 122.62, 56.04],
        [26.0, 16.0, 177.43, 63.50],
        [24.0, 22.0, 70.79, 58.74],
        [24.0, 20.0, 96.15, 65.21],
        [24.0, 18.0, 134.32, 73.04],
        [24.0, 16.0, 194.37, 82.77],
        [24.0, 14.0, 294.26, 95.19],
        [22.0, 20.0, 105.96, 86.59],
        [22.0, 18.0, 148.02, 97.00],
        [22.0, 16.0, 214.19, 109.91],
        [22.0, 14.0, 324.27, 126.40],
        [22.0, 12.0, 521.22, 884.24],
        [20.0, 18.0, 164.31, 750.86],
        [20.0, 16.0, 237.76, 832.85],
        [20.0, 14.0, 359.96, 940.09],
        [20.0, 12.0, 578.58, 1085.09],
        [20.0, 10.0, 1010.05, 1290.41],
        [18.0, 16.0, 266.34, 3693.27],
        [18.0, 14.0, 403.22, 4168.80],
        [18.0, 12.0, 648.12, 4811.80],
        [18.0, 10.0, 1131.45, 5722.28],
        [18.0, 8.0, 2228.31, 7100.40],
        [16.0, 14.0, 456.90, 19320.47],
        [16.0, 12.0, 734.40, 22300.46],
        [16.0, 10.0, 1282.08, 26520.11],
        [16.0, 8.0, 2524.96, 32907.05],
        [16.0, 6.0, 6023.76, 43626.28],
        [14.0, 12.0, 844.62, 28557.64],
        [14.0, 10.0, 1474.48, 33961.27],
        [14.0, 8.0, 2903.89, 42140.29],
        [14.0, 6.0, 6927.76, 55867.17],
        [14.0, 4.0, 23488.63, 83460.37],
        [12.0, 10.0, 1729.56, 167255.17],
        [12.0, 8.0, 3406.25, 207535.87],
        [12.0, 6.0, 8126.23, 275139.11],
        [12.0, 4.0, 27552.07, 411032.29],
        [12.0, 2.0, 221022.46, 820062.07],
    ];

    /// The rows of Table 3.2 for α = 10° and 8°.
    const TABLE_3_2_LAST: [[f64; 4]; 7] = [
        [10.0, 8.0, 4106.13, 4126162.52],
        [10.0, 6.0, 9795.92, 5470228.84],
        [10.0, 4.0, 33213.14, 8172013.99],
        [10.0, 2.0, 266435.54, 16304214.75],
        [8.0, 6.0, 12290.27, 116323732.58],
        [8.0, 4.0, 41670.26, 173776855.99],
        [8.0, 2.0, 334278.46, 346707088.60],
    ];

    /// Theorem 81's formulas, with placement (d) only where it exists,
    /// reproduce every printed value of Table 3.2 to its two decimals.
    #[test]
    fn theorem_81_recomputes_table_3_2() {
        let mut rows = 0;
        for [alpha, beta, inverse_f1, f2] in TABLE_3_2.iter().chain(&TABLE_3_2_LAST) {
            let (a, b) = theorem_81_factors(*alpha, *beta);
            // Printed to two decimals; the largest values are printed from
            // a computation with about eleven significant digits.
            let close = |x: f64, printed: f64| (x - printed).abs() <= 0.005 + printed * 1e-10;
            assert!(
                close(a, *inverse_f1),
                "α={alpha} β={beta}: 1/f1 {a} vs {inverse_f1}"
            );
            assert!(close(b, *f2), "α={alpha} β={beta}: f2 {b} vs {f2}");
            rows += 1;
        }
        assert_eq!(rows, 57);
        // Without the side condition f₂(30°, 28°) would be the case (d)
        // term, about 60.77, not the printed 21.06.
        let a = 30f64.to_radians();
        let b = 28f64.to_radians();
        let k1 = (2.0 * a.cos()).powf(-3.0); // i = ⌈180/60 − ½⌉ = 3
        let unconditional = 1.0 / (2.0 * k1 * k1 * (2.0 * b).sin() * (a / 2.0).tan());
        assert!((unconditional - 60.77).abs() < 0.01, "{unconditional}");
    }

    #[test]
    fn sampled_betas_follow_the_table() {
        assert_eq!(sample_betas(30.0), [28.0, 26.0, 24.0, 22.0, 20.0]);
        assert_eq!(sample_betas(5.0), [3.0, 1.0]);
        assert_eq!(sample_betas(1.5), [0.75]);
        let statement = theorem_81_statement(AreaBottleneck::MaxMin, 41.0);
        assert!(statement.contains("α = 30°") && statement.contains("24.57 at β = 28°"));
    }
}
