//! Validated input points: finite, in the exact range, duplicates merged.

use crate::error::{ElevationProblem, Error, Result};
use crate::kernel::{check_coordinate, orient_sign, CoordinateProblem, Point};
use crate::parallel::prelude::*;
use std::sync::Arc;

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
///
/// Cloning is cheap: the arrays are shared (a [`crate::Triangulation`] keeps
/// its point set this way instead of a copy). Without duplicates or `-0.0`
/// coordinates the input is not stored twice and the index maps are the
/// identity.
#[derive(Clone, Debug)]
pub struct PointSet {
    data: Arc<Data>,
}

#[derive(Debug)]
struct Data {
    distinct: Vec<Point>,
    /// The caller's points, when they differ from `distinct` (duplicates, or
    /// a `-0.0` that `distinct` stores as `0.0`).
    input: Option<Vec<Point>>,
    /// Input index of each distinct point, and distinct index of each input
    /// point; `None` (the identity) without duplicates.
    maps: Option<(Vec<u32>, Vec<u32>)>,
    /// `[dropped, kept]` input indices.
    duplicates: Vec<[u32; 2]>,
    /// An elevation per distinct point ([`PointSet::with_elevations`]).
    elevations: Option<Vec<f64>>,
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
        let (distinct, maps, duplicates) = merge_duplicates(points);
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
        let same_bits = maps.is_none()
            && points
                .iter()
                .zip(&distinct)
                .all(|(p, q)| p[0].to_bits() == q[0].to_bits() && p[1].to_bits() == q[1].to_bits());
        Ok(Self {
            data: Arc::new(Data {
                input: (!same_bits).then(|| points.to_vec()),
                distinct,
                maps,
                duplicates,
                elevations: None,
            }),
        })
    }

    /// These points with an elevation `z` per *input* point (in input
    /// order, duplicates included), for the criteria that read one (e.g.
    /// `minmax-slope`); the others ignore it.
    ///
    /// # Errors
    /// [`Error::InvalidElevations`]: the count differs from the number of
    /// input points, an elevation is not finite or outside the exact range
    /// of coordinates, or two duplicates of one point carry different
    /// elevations (merging them would have to guess).
    pub fn with_elevations(self, z: &[f64]) -> Result<Self> {
        let count = self.input_points().len();
        if z.len() != count {
            return Err(Error::InvalidElevations(ElevationProblem::CountMismatch {
                points: count,
                elevations: z.len(),
            }));
        }
        for (index, &value) in z.iter().enumerate() {
            match check_coordinate(value) {
                Ok(_) => {}
                Err(CoordinateProblem::NonFinite) => {
                    return Err(Error::InvalidElevations(ElevationProblem::NonFinite {
                        index,
                        value,
                    }))
                }
                Err(CoordinateProblem::OutOfRange) => {
                    return Err(Error::InvalidElevations(ElevationProblem::OutOfRange {
                        index,
                        value,
                    }))
                }
            }
        }
        for &[dropped, kept] in self.duplicates() {
            let (a, b) = (z[dropped as usize], z[kept as usize]);
            if a + 0.0 != b + 0.0 {
                return Err(Error::InvalidElevations(
                    ElevationProblem::ConflictingDuplicate {
                        index: dropped as usize,
                        kept: kept as usize,
                    },
                ));
            }
        }
        let elevations = (0..self.len() as u32)
            .map(|d| z[self.input_index(d) as usize] + 0.0)
            .collect();
        let mut data = Arc::try_unwrap(self.data).unwrap_or_else(|shared| Data {
            distinct: shared.distinct.clone(),
            input: shared.input.clone(),
            maps: shared.maps.clone(),
            duplicates: shared.duplicates.clone(),
            elevations: None,
        });
        data.elevations = Some(elevations);
        Ok(Self {
            data: Arc::new(data),
        })
    }

    /// The elevation of each distinct point (indexed like
    /// [`points`](Self::points)), if the input carried them.
    pub fn elevations(&self) -> Option<&[f64]> {
        self.data.elevations.as_deref()
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
        &self.data.distinct
    }

    /// Number of distinct points.
    pub fn len(&self) -> usize {
        self.data.distinct.len()
    }

    /// Always `false`: a `PointSet` has at least three points.
    pub fn is_empty(&self) -> bool {
        false
    }

    /// The caller's points, duplicates included, in input order.
    pub fn input_points(&self) -> &[Point] {
        self.data.input.as_deref().unwrap_or(&self.data.distinct)
    }

    /// Input index of distinct point `d`.
    #[inline]
    pub fn input_index(&self, d: u32) -> u32 {
        self.data
            .maps
            .as_ref()
            .map_or(d, |(to_input, _)| to_input[d as usize])
    }

    /// Distinct index of input point `i`.
    #[inline]
    pub fn distinct_index(&self, i: u32) -> u32 {
        self.data
            .maps
            .as_ref()
            .map_or(i, |(_, to_distinct)| to_distinct[i as usize])
    }

    /// Every merged duplicate as `[dropped, kept]` input indices.
    pub fn duplicates(&self) -> &[[u32; 2]] {
        &self.data.duplicates
    }
}

/// The distinct points in order of first occurrence (`-0.0` stored as `0.0`),
/// the index maps (`None` if there are no duplicates) and the `[dropped,
/// kept]` pairs. Sorting the indices by coordinate bits groups equal points
/// in O(n log n) with one index array of scratch (a hash map of every point
/// cost ten times the memory at 10⁷ points).
#[allow(clippy::type_complexity)]
fn merge_duplicates(points: &[Point]) -> (Vec<Point>, Option<(Vec<u32>, Vec<u32>)>, Vec<[u32; 2]>) {
    // -0.0 and 0.0 are the same point.
    let key = |i: u32| {
        let p = points[i as usize];
        [(p[0] + 0.0).to_bits(), (p[1] + 0.0).to_bits()]
    };
    let mut order: Vec<u32> = (0..points.len() as u32).collect();
    order.par_sort_unstable_by(|&i, &j| key(i).cmp(&key(j)).then(i.cmp(&j)));
    // first[i]: the first occurrence of point i (itself if none earlier).
    let mut first: Vec<u32> = Vec::new();
    for w in 1..order.len() {
        if key(order[w - 1]) == key(order[w]) {
            if first.is_empty() {
                first = (0..points.len() as u32).collect();
            }
            first[order[w] as usize] = first[order[w - 1] as usize];
        }
    }
    drop(order);
    let normalised = |p: &Point| [p[0] + 0.0, p[1] + 0.0];
    if first.is_empty() {
        return (points.iter().map(normalised).collect(), None, Vec::new());
    }
    let mut distinct = Vec::new();
    let mut to_input = Vec::new();
    let mut duplicates = Vec::new();
    // Reuse `first` as the distinct index of every input point: a first
    // occurrence precedes its duplicates, so it is numbered before them.
    for i in 0..points.len() {
        let f = first[i] as usize;
        if f == i {
            first[i] = distinct.len() as u32;
            distinct.push(normalised(&points[i]));
            to_input.push(i as u32);
        } else {
            duplicates.push([i as u32, f as u32]);
            first[i] = first[f];
        }
    }
    (distinct, Some((to_input, first)), duplicates)
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
    fn elevations_follow_the_distinct_points_and_bad_ones_are_named() {
        let pts = [[0.0, 0.0], [1.0, 0.0], [0.0, 0.0], [0.0, 1.0]];
        let ps = PointSet::new(&pts).unwrap();
        assert_eq!(ps.elevations(), None);
        let z = ps.clone().with_elevations(&[5.0, 6.0, 5.0, -7.0]).unwrap();
        assert_eq!(z.elevations(), Some(&[5.0, 6.0, -7.0][..]));
        assert_eq!(z.points(), ps.points());
        assert_eq!(
            ps.clone()
                .with_elevations(&[5.0, 6.0, 4.0, 7.0])
                .unwrap_err(),
            Error::InvalidElevations(ElevationProblem::ConflictingDuplicate { index: 2, kept: 0 })
        );
        assert_eq!(
            ps.clone().with_elevations(&[1.0, 2.0, 1.0]).unwrap_err(),
            Error::InvalidElevations(ElevationProblem::CountMismatch {
                points: 4,
                elevations: 3
            })
        );
        let e = ps
            .clone()
            .with_elevations(&[1.0, f64::NAN, 1.0, 0.0])
            .unwrap_err();
        assert!(e.to_string().contains("point 1"), "{e}");
        assert!(matches!(
            ps.with_elevations(&[1.0, 1e300, 1.0, 0.0]),
            Err(Error::InvalidElevations(ElevationProblem::OutOfRange {
                index: 1,
                ..
            }))
        ));
    }

    #[test]
    fn error_messages_name_the_problem() {
        let e = PointSet::new(&[[0.0, 0.0], [1.0, f64::NAN], [1.0, 1.0]]).unwrap_err();
        assert!(e.to_string().contains("point 1"), "{e}");
        let e = PointSet::new(&[[0.0, 0.0], [1.0, 1.0]]).unwrap_err();
        assert!(e.to_string().contains("at least 3 distinct points"), "{e}");
    }
}
