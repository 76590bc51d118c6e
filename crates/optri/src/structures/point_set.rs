//! Validated input points: finite, in the exact range, duplicates merged.

use crate::error::{Error, Result};
use crate::kernel::{check_coordinate, orient_sign, CoordinateProblem, Point};
use std::collections::HashMap;

/// A validated set of points in the plane.
///
/// Built from the caller's points; coordinates must be finite and within the
/// exact range (see [`crate::kernel`]). Exact duplicates are merged: the first
/// occurrence is kept, and every later one is reported in
/// [`duplicates`](Self::duplicates). Algorithms work on the *distinct* points
/// (indices `0..len()`, in order of first occurrence); every output maps back
/// to *input* indices.
///
/// Construction requires at least three distinct, non-collinear points, so
/// every `PointSet` can be triangulated.
#[derive(Clone, Debug)]
pub struct PointSet {
    input: Vec<Point>,
    distinct: Vec<Point>,
    /// Input index of each distinct point.
    input_index: Vec<u32>,
    /// Distinct index of each input point.
    distinct_index: Vec<u32>,
    /// `[dropped, kept]` input indices.
    duplicates: Vec<[u32; 2]>,
}

impl PointSet {
    /// Validates `points` and merges duplicates.
    ///
    /// # Errors
    /// [`Error::NonFiniteCoordinate`], [`Error::CoordinateOutOfRange`] (naming
    /// the first bad point), [`Error::TooManyPoints`], [`Error::TooFewPoints`],
    /// [`Error::AllCollinear`].
    pub fn new(points: &[Point]) -> Result<Self> {
        if points.len() >= u32::MAX as usize {
            return Err(Error::TooManyPoints {
                count: points.len(),
            });
        }
        for (index, p) in points.iter().enumerate() {
            for &value in p {
                match check_coordinate(value) {
                    Ok(_) => {}
                    Err(CoordinateProblem::NonFinite) => {
                        return Err(Error::NonFiniteCoordinate { index, value })
                    }
                    Err(CoordinateProblem::OutOfRange) => {
                        return Err(Error::CoordinateOutOfRange { index, value })
                    }
                }
            }
        }
        let mut seen: HashMap<[u64; 2], u32> = HashMap::with_capacity(points.len());
        let mut distinct = Vec::with_capacity(points.len());
        let mut input_index = Vec::with_capacity(points.len());
        let mut distinct_index = Vec::with_capacity(points.len());
        let mut duplicates = Vec::new();
        for (i, p) in points.iter().enumerate() {
            // -0.0 and 0.0 are the same point.
            let key = [(p[0] + 0.0).to_bits(), (p[1] + 0.0).to_bits()];
            match seen.get(&key) {
                Some(&d) => {
                    duplicates.push([i as u32, input_index[d as usize]]);
                    distinct_index.push(d);
                }
                None => {
                    let d = distinct.len() as u32;
                    seen.insert(key, d);
                    distinct.push([p[0] + 0.0, p[1] + 0.0]);
                    input_index.push(i as u32);
                    distinct_index.push(d);
                }
            }
        }
        if distinct.len() < 3 {
            return Err(Error::TooFewPoints {
                distinct: distinct.len(),
            });
        }
        let (a, b) = (distinct[0], distinct[1]);
        if distinct[2..].iter().all(|&c| orient_sign(a, b, c) == 0) {
            return Err(Error::AllCollinear {
                distinct: distinct.len(),
            });
        }
        Ok(Self {
            input: points.to_vec(),
            distinct,
            input_index,
            distinct_index,
            duplicates,
        })
    }

    /// Maps distinct-index edges to sorted `[min, max]` input-index pairs.
    pub(crate) fn to_input_edges(&self, edges: impl Iterator<Item = [u32; 2]>) -> Vec<[u32; 2]> {
        let mut out: Vec<[u32; 2]> = edges
            .map(|[u, v]| {
                let (a, b) = (self.input_index(u), self.input_index(v));
                [a.min(b), a.max(b)]
            })
            .collect();
        out.sort_unstable();
        out
    }

    /// The distinct points, in order of first occurrence.
    pub fn points(&self) -> &[Point] {
        &self.distinct
    }

    /// Number of distinct points.
    pub fn len(&self) -> usize {
        self.distinct.len()
    }

    /// Always `false`: a `PointSet` has at least three points.
    pub fn is_empty(&self) -> bool {
        false
    }

    /// The caller's points, duplicates included, in input order.
    pub fn input_points(&self) -> &[Point] {
        &self.input
    }

    /// Input index of distinct point `d`.
    #[inline]
    pub fn input_index(&self, d: u32) -> u32 {
        self.input_index[d as usize]
    }

    /// Distinct index of input point `i`.
    #[inline]
    pub fn distinct_index(&self, i: u32) -> u32 {
        self.distinct_index[i as usize]
    }

    /// Every merged duplicate as `[dropped, kept]` input indices.
    pub fn duplicates(&self) -> &[[u32; 2]] {
        &self.duplicates
    }
}

impl TryFrom<&[Point]> for PointSet {
    type Error = Error;
    fn try_from(points: &[Point]) -> Result<Self> {
        PointSet::new(points)
    }
}

impl TryFrom<Vec<Point>> for PointSet {
    type Error = Error;
    fn try_from(points: Vec<Point>) -> Result<Self> {
        PointSet::new(&points)
    }
}

impl TryFrom<&[(f64, f64)]> for PointSet {
    type Error = Error;
    fn try_from(points: &[(f64, f64)]) -> Result<Self> {
        let v: Vec<Point> = points.iter().map(|&(x, y)| [x, y]).collect();
        PointSet::new(&v)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn duplicates_are_merged_and_reported_with_input_indices() {
        let ps =
            PointSet::new(&[[0.0, 0.0], [1.0, 0.0], [0.0, 0.0], [0.0, 1.0], [-0.0, 0.0]]).unwrap();
        assert_eq!(ps.len(), 3);
        assert_eq!(ps.duplicates(), &[[2, 0], [4, 0]]);
        assert_eq!(ps.input_index(2), 3);
        assert_eq!(ps.distinct_index(4), 0);
    }

    #[test]
    fn bad_inputs_give_typed_errors() {
        assert!(matches!(
            PointSet::new(&[[0.0, 0.0], [f64::NAN, 1.0], [1.0, 1.0]]),
            Err(Error::NonFiniteCoordinate { index: 1, .. })
        ));
        assert!(matches!(
            PointSet::new(&[[0.0, 0.0], [1.0, f64::INFINITY], [1.0, 1.0]]),
            Err(Error::NonFiniteCoordinate { index: 1, .. })
        ));
        assert!(matches!(
            PointSet::new(&[[0.0, 0.0], [1.0, 1e300], [1.0, 1.0]]),
            Err(Error::CoordinateOutOfRange { index: 1, .. })
        ));
        assert!(matches!(
            PointSet::new(&[[0.0, 0.0], [1.0, 1e-300], [1.0, 1.0]]),
            Err(Error::CoordinateOutOfRange { index: 1, .. })
        ));
        assert_eq!(
            PointSet::new(&[]).unwrap_err(),
            Error::TooFewPoints { distinct: 0 }
        );
        assert_eq!(
            PointSet::new(&[[0.0, 0.0], [1.0, 1.0], [1.0, 1.0]]).unwrap_err(),
            Error::TooFewPoints { distinct: 2 }
        );
        assert_eq!(
            PointSet::new(&[[0.0, 0.0], [1.0, 1.0], [3.0, 3.0], [-2.0, -2.0]]).unwrap_err(),
            Error::AllCollinear { distinct: 4 }
        );
    }

    #[test]
    fn error_messages_name_the_problem() {
        let e = PointSet::new(&[[0.0, 0.0], [1.0, f64::NAN], [1.0, 1.0]]).unwrap_err();
        assert!(e.to_string().contains("point 1"), "{e}");
        let e = PointSet::new(&[[0.0, 0.0], [1.0, 1.0]]).unwrap_err();
        assert!(e.to_string().contains("at least 3 distinct points"), "{e}");
    }
}
