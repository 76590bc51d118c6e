//! The MaxMin-area decision problem in the public API (Vassilev 2005,
//! Algorithm 49 as repaired: O(n²) per query once the table is built).

use super::convex::MaxMinTable;
use super::MAX_CONVEX_VERTICES;
use crate::error::{Error, Result, UnsupportedReason};
use crate::interrupt::Stop;
use crate::spatial::convex_hull_cycle;
use crate::structures::{PointSet, SimplePolygon, Triangulation};

const CRITERION: &str = "maxmin-area";

/// Answers "is there a triangulation whose smallest *doubled* triangle area
/// is at least `A`?" for a strictly convex polygon, exactly, in O(n²) per
/// query after an O(n² log n) build (Algorithm 49 with prefix counts instead
/// of van Emde Boas queues; the MaxMin sleeve table of Algorithm 44 steps
/// i–iii). `A` is any `f64`, compared exactly with the areas.
///
/// ```
/// use optri::{MaxMinAreaDecision, SimplePolygon};
/// let square = SimplePolygon::new(&[[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]])?;
/// let decision = MaxMinAreaDecision::new(&square)?;
/// assert!(decision.admits(4.0));   // both triangles have doubled area 4
/// assert!(!decision.admits(4.0000001));
/// # Ok::<(), optri::Error>(())
/// ```
pub struct MaxMinAreaDecision<'a> {
    polygon: &'a SimplePolygon,
    table: MaxMinTable<'a>,
}

impl<'a> MaxMinAreaDecision<'a> {
    /// Builds the table, O(n² log n) time and O(n²) space.
    ///
    /// # Errors
    /// [`Error::Unsupported`] if the polygon is not strictly convex (use the
    /// `maxmin-area` criterion through the polygon program instead) or has
    /// more than 12 000 vertices.
    pub fn new(polygon: &'a SimplePolygon) -> Result<Self> {
        if !polygon.is_strictly_convex() {
            return Err(Error::Unsupported {
                criterion: CRITERION,
                reason: UnsupportedReason::NotStrictlyConvex,
            });
        }
        if polygon.len() > MAX_CONVEX_VERTICES {
            return Err(Error::Unsupported {
                criterion: CRITERION,
                reason: UnsupportedReason::TooManyPoints {
                    limit: MAX_CONVEX_VERTICES,
                    distinct: polygon.len(),
                    because: "Algorithm 44's O(n²) tables",
                },
            });
        }
        let table = MaxMinTable::new(
            polygon.vertices(),
            polygon.counter_clockwise(),
            &Stop::default(),
        )?;
        Ok(Self { polygon, table })
    }

    /// Is there a triangulation whose smallest doubled area is at least
    /// `doubled_area`? O(n²). `NaN` is never admitted; any value ≤ 0 is.
    pub fn admits(&self, doubled_area: f64) -> bool {
        !doubled_area.is_nan() && self.table.admits_doubled_area(doubled_area)
    }

    /// A triangulation whose smallest doubled area is at least
    /// `doubled_area`, if one exists (Theorem 51's construction), O(n²).
    pub fn witness(&self, doubled_area: f64) -> Option<Triangulation> {
        if doubled_area.is_nan() {
            return None;
        }
        let triangles = self.table.witness_doubled_area(doubled_area)?;
        Some(Triangulation::from_polygon_positions(
            self.polygon,
            triangles,
        ))
    }

    /// The MaxMin-area optimum by sorting the table's values and binary
    /// searching them with the decision (the second route to the optimum;
    /// `maxmin-area` itself uses Algorithm 44's range-max step iv).
    /// O(n² log n).
    pub fn optimum(&self) -> Triangulation {
        Triangulation::from_polygon_positions(self.polygon, self.table.optimum_by_search())
    }
}

/// One decision on a point set in strictly convex position: is there a
/// triangulation of `points` whose smallest doubled area is at least
/// `doubled_area`? Builds the table each call (O(n² log n)); keep a
/// [`MaxMinAreaDecision`] to ask many thresholds.
///
/// # Errors
/// As [`MaxMinAreaDecision::new`], and [`UnsupportedReason::NotStrictlyConvex`]
/// when some point is not a strictly convex hull vertex.
pub fn maxmin_area_at_least(points: &PointSet, doubled_area: f64) -> Result<bool> {
    let pts = points.points();
    let hull = convex_hull_cycle(pts);
    let ring: Vec<_> = hull.iter().map(|&v| pts[v as usize]).collect();
    if hull.len() != pts.len() {
        return Err(Error::Unsupported {
            criterion: CRITERION,
            reason: UnsupportedReason::NotStrictlyConvex,
        });
    }
    let polygon = SimplePolygon::new(&ring)?;
    Ok(MaxMinAreaDecision::new(&polygon)?.admits(doubled_area))
}
