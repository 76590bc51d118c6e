//! Decimal input taken at its value.
//!
//! Files write decimals (`0.1`, `1.21488e+03`), and the nearest binary double
//! of a decimal is usually not the decimal: `0.1`, `0.2`, `0.3` are not
//! collinear as doubles although `(0.1, 0.1)`, `(0.2, 0.2)`, `(0.3, 0.3)` are
//! as written. The readers therefore keep every coordinate's decimal value
//! `m · 10^e` as they go ([`DecimalScaler`]). When one common factor `10^k`
//! turns every coordinate into an integer of magnitude below 2⁵³, those
//! integers are exact doubles, and triangulating them decides every predicate
//! on the decimals themselves: every criterion is invariant under a uniform
//! scaling (lengths scale by `10^k`, areas by `10^2k`, angles not at all, so
//! every comparison keeps its sign, and the symbolic tie-break depends only
//! on the point numbering). The front end triangulates [`Scaled::points`]
//! and reports the user's values ([`ReadInput::input`]) and the measures in
//! the user's units (`TriangulationReport::with_input`).
//!
//! Otherwise (a coordinate with more than 16 significant digits, or digits
//! spanning more than 2⁵³ after scaling) the algorithms run on the nearest
//! doubles, exactly as before, and the JSON says so
//! (`"coordinate_arithmetic": "binary64"`).
//!
//! Front ends whose numbers arrive as doubles (Python floats, the numbers of
//! a web request) use the same rule:
//! [`ReadInput::from_doubles`](super::ReadInput::from_doubles) reads each
//! double as its shortest round-trip decimal when every one has at most 15
//! significant digits (`0.1` typed in Python is the decimal 0.1; a computed
//! `0.1 + 0.2 = 0.30000000000000004` has 17 and keeps the input binary64).
//!
//! GeoJSON numbers are parsed by serde_json, which keeps no text; a double
//! whose shortest round-trip decimal has at most 15 significant digits *is*
//! that decimal's reading (every decimal of at most 15 digits survives the
//! round trip to binary64, so two such decimals never share a double). The
//! GeoJSON reader therefore trusts shortest decimals only when no number
//! literal in the document has more than 15 significant digits
//! ([`json_literals_are_short`]).

use super::quoted;
use crate::error::{Error, Result};
use crate::kernel::Point;

/// 2⁵³: integers of smaller magnitude are exact doubles.
const EXACT_INTEGER_LIMIT: u64 = 1 << 53;

/// Every decimal of at most this many significant digits is the shortest
/// round-trip decimal of its nearest double (binary64 carries 15.95 decimal
/// digits), so reading such a double back as that decimal is unambiguous.
const SHORTEST_DIGITS: usize = 15;

/// How the algorithms computed with the coordinates, as the JSON's
/// `"coordinate_arithmetic"` says.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Arithmetic {
    /// On the decimal values as written: every coordinate times one common
    /// `10^k` is an integer below 2⁵³ (exact as a double).
    DecimalExact,
    /// On the nearest binary doubles of the written values (the decimals did
    /// not scale to integers below 2⁵³, or the input was given as doubles).
    Binary64,
}

impl Arithmetic {
    /// `"decimal-exact"` or `"binary64"`.
    pub fn name(self) -> &'static str {
        match self {
            Arithmetic::DecimalExact => "decimal-exact",
            Arithmetic::Binary64 => "binary64",
        }
    }
}

/// The input scaled to integers: `points[i] = user[i] · 10^exponent`, every
/// coordinate an integer of magnitude below 2⁵³ (so exactly a double).
#[derive(Clone, Debug, PartialEq)]
pub struct Scaled {
    /// `k` in `10^k` (negative when every coordinate is a multiple of a power
    /// of ten, e.g. `-3` for `1000 2000 …`).
    pub exponent: i32,
    /// The scaled points, in input order.
    pub points: Vec<Point>,
}

/// A decimal `±m · 10^e` with `m < 2⁵³` and no trailing zero digit in `m`
/// (`m == 0` for zero).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Decimal {
    negative: bool,
    mantissa: u64,
    exponent: i64,
}

/// Parses a decimal literal `[+-]digits[.digits][(e|E)[+-]digits]` (either
/// digit run may be empty, not both). `None` for anything else (`inf`,
/// `nan`, hex) and for more than 16 significant digits, which cannot scale
/// below 2⁵³.
fn parse_decimal(token: &str) -> Option<Decimal> {
    let (negative, mantissa, exponent) = parse_decimal_digits(token, 16)?;
    if mantissa >= u128::from(EXACT_INTEGER_LIMIT) {
        return None;
    }
    Some(Decimal {
        negative,
        mantissa: mantissa as u64,
        exponent,
    })
}

/// A decimal literal as `(negative, m, e)`, its value `±m · 10^e` with no
/// trailing zero digit in `m` (`e = 0` for zero); `None` for anything but
/// a decimal literal and for more than `max_digits ≤ 38` significant digits.
fn parse_decimal_digits(token: &str, max_digits: usize) -> Option<(bool, u128, i64)> {
    let bytes = token.as_bytes();
    let mut i = 0;
    let negative = match bytes.first() {
        Some(b'-') => {
            i = 1;
            true
        }
        Some(b'+') => {
            i = 1;
            false
        }
        _ => false,
    };
    let mut mantissa: u128 = 0;
    let mut exponent: i64 = 0;
    let mut digits = 0usize; // significant digits taken into `mantissa`
    let mut pending_zeros: i64 = 0; // zeros after the last nonzero digit
    let mut any_digit = false;
    let mut after_point = false;
    while i < bytes.len() {
        match bytes[i] {
            b'0'..=b'9' => {
                any_digit = true;
                let d = u128::from(bytes[i] - b'0');
                if after_point {
                    exponent -= 1;
                }
                if d == 0 {
                    if digits > 0 {
                        pending_zeros += 1;
                    }
                } else {
                    // Flush the zeros between two nonzero digits.
                    for _ in 0..pending_zeros {
                        mantissa = mantissa.checked_mul(10)?;
                        digits += 1;
                    }
                    pending_zeros = 0;
                    mantissa = mantissa.checked_mul(10)?.checked_add(d)?;
                    digits += 1;
                    if digits > max_digits {
                        return None;
                    }
                }
            }
            b'.' if !after_point => after_point = true,
            b'e' | b'E' => break,
            _ => return None,
        }
        i += 1;
    }
    if !any_digit {
        return None;
    }
    // The dropped trailing zeros belong to the exponent.
    exponent += pending_zeros;
    if i < bytes.len() {
        // An exponent part.
        let rest = &token[i + 1..];
        let (sign, digits) = match rest.as_bytes().first() {
            Some(b'-') => (-1i64, &rest[1..]),
            Some(b'+') => (1, &rest[1..]),
            _ => (1, rest),
        };
        if digits.is_empty() || !digits.bytes().all(|b| b.is_ascii_digit()) {
            return None;
        }
        // Saturate: a huge exponent fails the 2⁵³ test anyway.
        let e: i64 = digits.parse().unwrap_or(i64::MAX / 4).min(i64::MAX / 4);
        exponent = exponent.checked_add(sign * e)?;
    }
    if mantissa == 0 {
        exponent = 0;
    }
    Some((negative, mantissa, exponent))
}

/// Collects the decimal value of every coordinate, in order, scaled by the
/// smallest common `10^k` that makes each an integer; gives up (for good)
/// when a coordinate is not a short decimal or a scaled value reaches 2⁵³.
///
/// When a later coordinate needs more decimal places than `k`, every earlier
/// value is multiplied by the missing power of ten; each such step multiplies
/// the largest magnitude by at least 10, so there are at most 16 of them and
/// the collection stays linear.
#[derive(Clone, Debug)]
pub(crate) struct DecimalScaler {
    /// The scaled coordinates, `x0 y0 x1 y1 …`; `None` once given up.
    scaled: Option<Vec<f64>>,
    /// `k`, once a nonzero coordinate was seen.
    exponent: Option<i64>,
    /// The largest magnitude in `scaled`.
    largest: u64,
}

impl Default for DecimalScaler {
    fn default() -> Self {
        Self {
            scaled: Some(Vec::new()),
            exponent: None,
            largest: 0,
        }
    }
}

impl DecimalScaler {
    /// A scaler that has given up (the input is binary64).
    pub(super) fn given_up() -> Self {
        Self {
            scaled: None,
            exponent: None,
            largest: 0,
        }
    }

    /// Records the next coordinate, written as `token`.
    pub(super) fn push(&mut self, token: &str) {
        match parse_decimal(token) {
            Some(d) => self.push_decimal(d),
            None => self.scaled = None,
        }
    }

    /// Records the next coordinate from its double, trusting its shortest
    /// round-trip decimal when that has at most 15 significant digits (see
    /// the module docs for when that is sound); gives up otherwise.
    pub(super) fn push_shortest(&mut self, value: f64) {
        if self.scaled.is_none() {
            return;
        }
        // `{:e}` is Rust's shortest round-trip decimal, in scientific form:
        // `d.ddde±x`, so the mantissa's digits are the significant ones.
        let shortest = format!("{value:e}");
        let digits = shortest
            .split('e')
            .next()
            .map_or(0, |m| m.bytes().filter(u8::is_ascii_digit).count());
        if digits > SHORTEST_DIGITS {
            self.scaled = None;
            return;
        }
        self.push(&shortest);
    }

    fn push_decimal(&mut self, d: Decimal) {
        let Some(scaled) = self.scaled.as_mut() else {
            return;
        };
        if d.mantissa == 0 {
            scaled.push(0.0);
            return;
        }
        // `m · 10^e` is an integer after scaling by `10^k` iff `k ≥ -e`.
        let need = -d.exponent;
        let k = match self.exponent {
            None => need,
            Some(k) if need > k => {
                let Some(factor) = power_of_ten(need - k).filter(|&f| {
                    self.largest
                        .checked_mul(f)
                        .is_some_and(|v| v < EXACT_INTEGER_LIMIT)
                }) else {
                    self.scaled = None;
                    return;
                };
                // Exact: integers below 2⁵³ times a power of ten below 2⁵³
                // whose product is below 2⁵³.
                let factor = factor as f64;
                for v in scaled.iter_mut() {
                    *v *= factor;
                }
                self.largest *= factor as u64;
                need
            }
            Some(k) => k,
        };
        self.exponent = Some(k);
        let Some(magnitude) = power_of_ten(k + d.exponent)
            .and_then(|f| d.mantissa.checked_mul(f))
            .filter(|&v| v < EXACT_INTEGER_LIMIT)
        else {
            self.scaled = None;
            return;
        };
        self.largest = self.largest.max(magnitude);
        let v = magnitude as f64;
        scaled.push(if d.negative { -v } else { v });
    }

    /// The arithmetic and, when it is decimal-exact with `k ≠ 0`, the
    /// scaled points (with `k == 0` the user's doubles are the integers).
    pub(super) fn finish(self) -> (Arithmetic, Option<Scaled>) {
        let Some(scaled) = self.scaled else {
            return (Arithmetic::Binary64, None);
        };
        let exponent = self.exponent.unwrap_or(0);
        let Ok(exponent) = i32::try_from(exponent) else {
            return (Arithmetic::Binary64, None);
        };
        if exponent == 0 {
            return (Arithmetic::DecimalExact, None);
        }
        let points = scaled.chunks_exact(2).map(|c| [c[0], c[1]]).collect();
        (Arithmetic::DecimalExact, Some(Scaled { exponent, points }))
    }
}

/// `10^p` for `0 ≤ p ≤ 15` (below 2⁵³), else `None`.
fn power_of_ten(p: i64) -> Option<u64> {
    (0..=15).contains(&p).then(|| 10u64.pow(p as u32))
}

/// Does every number literal of the JSON `text` have at most 15 significant
/// digits? Then each number's shortest round-trip decimal is the decimal
/// written. Strings (and their escapes) are skipped.
pub(super) fn json_literals_are_short(text: &str) -> bool {
    let bytes = text.as_bytes();
    let mut i = 0;
    while i < bytes.len() {
        match bytes[i] {
            b'"' => {
                i += 1;
                while i < bytes.len() && bytes[i] != b'"' {
                    i += if bytes[i] == b'\\' { 2 } else { 1 };
                }
                i += 1;
            }
            b'-' | b'0'..=b'9' => {
                let start = i;
                while i < bytes.len()
                    && matches!(bytes[i], b'-' | b'+' | b'.' | b'e' | b'E' | b'0'..=b'9')
                {
                    i += 1;
                }
                let token = &text[start..i];
                let mantissa = token.split(['e', 'E']).next().unwrap_or("");
                let digits: String = mantissa.chars().filter(char::is_ascii_digit).collect();
                let significant = digits.trim_start_matches('0').trim_end_matches('0');
                if significant.len() > 15 {
                    return false;
                }
            }
            _ => i += 1,
        }
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scaled(tokens: &[&str]) -> (Arithmetic, Option<Scaled>) {
        let mut s = DecimalScaler::default();
        for t in tokens {
            s.push(t);
        }
        s.finish()
    }

    #[test]
    fn decimals_parse_to_their_value() {
        let d = |t: &str| parse_decimal(t).map(|d| (d.negative, d.mantissa, d.exponent));
        assert_eq!(d("0.1"), Some((false, 1, -1)));
        assert_eq!(d("-1.21488e+03"), Some((true, 121488, -2)));
        assert_eq!(d("1500"), Some((false, 15, 2)));
        assert_eq!(d("+.50"), Some((false, 5, -1)));
        assert_eq!(d("7."), Some((false, 7, 0)));
        assert_eq!(d("1.05E-3"), Some((false, 105, -5)));
        assert_eq!(d("-0.000"), Some((true, 0, 0)));
        assert_eq!(d("9007199254740991"), Some((false, 9007199254740991, 0)));
        for bad in [
            "9007199254740993",
            "0.12345678901234567",
            "inf",
            "nan",
            "0x10",
            ".",
            "1e",
            "1.2.3",
            "e5",
            "",
        ] {
            assert_eq!(d(bad), None, "{bad}");
        }
    }

    #[test]
    fn a_common_power_of_ten_scales_every_coordinate() {
        let (a, s) = scaled(&["0.1", "0.1", "0.25", "-3", "1e2", "0"]);
        assert_eq!(a, Arithmetic::DecimalExact);
        let s = s.unwrap();
        assert_eq!(s.exponent, 2);
        assert_eq!(s.points, vec![[10.0, 10.0], [25.0, -300.0], [10000.0, 0.0]]);
        // Integers: the doubles are the values, no copy.
        assert_eq!(
            scaled(&["1", "2", "-7", "0"]),
            (Arithmetic::DecimalExact, None)
        );
        // Multiples of a thousand scale down.
        let (_, s) = scaled(&["1000", "2e3", "3000", "-5000"]);
        assert_eq!(s.unwrap().exponent, -3);
        // Too many digits after scaling, or a non-decimal: binary64.
        assert_eq!(scaled(&["1e15", "0.1"]).0, Arithmetic::Binary64);
        assert_eq!(
            scaled(&["0.1", "0.12345678901234567"]).0,
            Arithmetic::Binary64
        );
        assert_eq!(scaled(&["1e-400", "1"]).0, Arithmetic::Binary64);
    }

    #[test]
    fn doubles_are_read_as_their_shortest_decimals_of_at_most_15_digits() {
        let shortest = |values: &[f64]| {
            let mut s = DecimalScaler::default();
            for &v in values {
                s.push_shortest(v);
            }
            s.finish()
        };
        let (a, s) = shortest(&[0.1, 0.2, -0.3, 12.5]);
        assert_eq!(a, Arithmetic::DecimalExact);
        assert_eq!(s.unwrap().points, vec![[1.0, 2.0], [-3.0, 125.0]]);
        // 17 and 16 significant digits: not a reading of a typed decimal.
        assert_eq!(shortest(&[0.1 + 0.2, 1.0]).0, Arithmetic::Binary64);
        assert_eq!(
            shortest(&[0.123_456_789_012_345_6, 1.0]).0,
            Arithmetic::Binary64
        );
        assert_eq!(
            shortest(&[0.123_456_789_012_345, 1.0]).0,
            Arithmetic::DecimalExact
        );
        assert_eq!(shortest(&[f64::NAN, 1.0]).0, Arithmetic::Binary64);
    }

    #[test]
    fn long_json_literals_are_found_outside_strings() {
        assert!(json_literals_are_short(
            r#"{"a":[0.1,-2.5e-3,1234567890.12345],"b":"0.12345678901234567"}"#
        ));
        assert!(!json_literals_are_short(r#"{"a":[0.10000000000000001]}"#));
        assert!(json_literals_are_short(
            r#"{"a\"":[100000000000000000000000]}"#
        ));
    }
}

/// A user's area threshold, kept as the decimal it was written as: `text`
/// and its exact value `mantissa · 10^exponent` (`≥ 0`). A number that
/// arrives as a double (a Python float, a JSON number) is its shortest
/// round-trip decimal, the text it prints as, so a reported area passed
/// back is the decimal the report showed.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Threshold {
    text: String,
    mantissa: u128,
    exponent: i64,
}

/// Significant digits a threshold may have (its mantissa stays below 10³⁶,
/// so twice it fits a `u128`).
const THRESHOLD_DIGITS: usize = 36;

impl Threshold {
    /// Parses a decimal literal `[+]digits[.digits][(e|E)[+-]digits]`.
    ///
    /// # Errors
    /// [`Error::InvalidOption`] for anything else (`nan`, `inf`, hex, a
    /// negative value, more than 36 significant digits), naming `option`.
    pub fn parse(option: &'static str, text: &str) -> Result<Self> {
        let invalid = |why: &str| Error::InvalidOption {
            option,
            message: format!("{} {why}", quoted(text)),
        };
        let token = text.trim();
        let (negative, mantissa, exponent) = parse_decimal_digits(token, THRESHOLD_DIGITS)
            .ok_or_else(|| {
                invalid(&format!(
                    "is not a decimal number of at most {THRESHOLD_DIGITS} significant digits"
                ))
            })?;
        if negative && mantissa != 0 {
            return Err(invalid("is negative; an area threshold is at least 0"));
        }
        Ok(Self {
            text: token.to_string(),
            mantissa,
            exponent,
        })
    }

    /// A threshold from a double: its shortest round-trip decimal.
    ///
    /// # Errors
    /// [`Error::InvalidOption`] for NaN, an infinity or a negative value.
    pub fn from_f64(option: &'static str, value: f64) -> Result<Self> {
        if !value.is_finite() {
            return Err(Error::InvalidOption {
                option,
                message: format!("{value} is not a finite number"),
            });
        }
        // `{}` is Rust's shortest round-trip decimal.
        Self::parse(option, &format!("{value}"))
    }

    /// The text as given (trimmed).
    pub fn text(&self) -> &str {
        &self.text
    }

    /// The exact value `mantissa · 10^exponent`.
    pub fn value(&self) -> (u128, i64) {
        (self.mantissa, self.exponent)
    }

    /// The nearest double (for display and for documents).
    pub fn to_f64(&self) -> f64 {
        self.text.parse().unwrap_or(f64::NAN)
    }
}
