//! The area decision problems in the public API (T. S. Vassilev, *Optimal
//! Area Triangulation*, PhD thesis, University of Saskatchewan, 2005,
//! §2.4): "is there a triangulation whose smallest triangle has area at
//! least A?" by Algorithm 49 (in one shot, [`decide_area`], or O(n²) per
//! query once its table is built, [`MaxMinAreaDecision`]), and "…whose
//! largest triangle has area at most A?" and every input the convex
//! algorithm does not take by the criteria's optima, compared exactly.

use super::convex::{maxmin_admits, MaxMinTable};
use super::{solve_points, solve_polygon, AreaBottleneck, MAX_CONVEX_VERTICES};
use crate::criteria::{Optimality, Options, Solved};
use crate::error::{Error, Result, UnsupportedReason};
use crate::interrupt::Stop;
use crate::kernel::{AreaThreshold, Point};
use crate::spatial::{convex_hull_cycle, is_strictly_convex_cycle};
use crate::structures::{PointSet, SimplePolygon, Triangulation};
use crate::timing::{timed, Phase};
use std::cmp::Ordering;

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

/// What an area decision asks of a triangulation.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AreaQuestion {
    /// `maxmin-area`: every triangle's area at least the threshold.
    SmallestAtLeast,
    /// `minmax-area`: every triangle's area at most the threshold.
    LargestAtMost,
}

impl AreaQuestion {
    fn kind(self) -> AreaBottleneck {
        match self {
            AreaQuestion::SmallestAtLeast => AreaBottleneck::MaxMin,
            AreaQuestion::LargestAtMost => AreaBottleneck::MinMax,
        }
    }

    /// The registry name of the criterion the question bounds.
    pub fn criterion(self) -> &'static str {
        self.kind().criterion()
    }

    /// Does the triangle meet the threshold? Exact.
    fn meets(self, threshold: &AreaThreshold, triangle: [Point; 3]) -> bool {
        let order = threshold.compare(triangle);
        match self {
            AreaQuestion::SmallestAtLeast => order != Ordering::Less,
            AreaQuestion::LargestAtMost => order != Ordering::Greater,
        }
    }

    /// Does every triangle of `triangulation` meet the threshold?
    fn all_meet(self, threshold: &AreaThreshold, triangulation: &Triangulation) -> bool {
        let p = triangulation.points();
        triangulation
            .triangles()
            .iter()
            .all(|t| self.meets(threshold, t.map(|v| p[v as usize])))
    }
}

/// The answer to an area decision ([`decide_area`]).
#[derive(Clone, Debug)]
pub struct AreaDecision {
    /// `Some(true)`: a triangulation meets the threshold (the `witness`);
    /// `Some(false)`: none does (proven); `None`: not decided (a general
    /// point set whose optimum the approximation did not certify, and
    /// neither its result nor its certified bound settles the threshold).
    pub answer: Option<bool>,
    /// Which algorithm decided, in words.
    pub method: &'static str,
    /// Whether the decision read a proven optimum or decided directly
    /// (Algorithm 49); `false` when it read an approximation (its answer,
    /// when not `None`, is still proven: by the witness or by the bound).
    pub exact: bool,
    /// A triangulation meeting the threshold, when the answer is yes.
    pub witness: Option<Triangulation>,
    /// Timed phases.
    pub phases: Vec<Phase>,
}

/// The method of a decision by Algorithm 49 in one shot.
const ONE_SHOT: &str = "Vassilev's Algorithm 49 in one shot: the sleeve program of Algorithm 44 \
     as a boolean program against the threshold, then the 2-2 diagonal and search-pair steps \
     (Lemma 50), O(n^2) time and space";
/// The method of a decision that compares an exact optimum.
const OPTIMUM: &str = "the criterion's exact optimum compared exactly with the threshold";
/// The method of a decision on an approximation.
const APPROXIMATION: &str = "the criterion's certified approximation: yes if its triangulation \
     meets the threshold, no if its certified bound excludes it, else unknown";

/// Decides exactly whether some triangulation of `input` (a point set's
/// hull or a polygon's interior) has every triangle's *doubled* area at
/// least (`SmallestAtLeast`) or at most (`LargestAtMost`) `threshold`:
///
/// - points in strictly convex position or a strictly convex polygon,
///   `SmallestAtLeast`: Algorithm 49 in one shot, O(n²);
/// - otherwise where the criterion is exact (convex position, simple
///   polygons): its optimum compared with the threshold;
/// - general point sets: the certified approximation decides when its
///   result meets the threshold (yes) or its bound excludes it (no); else
///   the answer is `None`.
///
/// Reads `options`' time limit and cancellation.
///
/// ```
/// use optri::kernel::AreaThreshold;
/// use optri::{decide_area, AreaQuestion, Options, PointSet};
/// let square = PointSet::new(&[[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]])?;
/// let at = |doubled| AreaThreshold::new(doubled, 0);
/// let yes = decide_area(&square, AreaQuestion::SmallestAtLeast, &at(4), &Options::default())?;
/// assert_eq!(yes.answer, Some(true));
/// let no = decide_area(&square, AreaQuestion::SmallestAtLeast, &at(5), &Options::default())?;
/// assert_eq!(no.answer, Some(false));
/// # Ok::<(), optri::Error>(())
/// ```
///
/// # Errors
/// [`Error::Unsupported`] where the criterion refuses the input (too many
/// points), [`Error::Interrupted`](crate::Error::Interrupted) when stopped.
pub fn decide_area<T: DecisionInput + ?Sized>(
    input: &T,
    question: AreaQuestion,
    threshold: &AreaThreshold,
    options: &Options,
) -> Result<AreaDecision> {
    let options = options.started();
    options.stop().check()?;
    let mut phases = Vec::new();
    let (answer, method, exact, witness) =
        input.decide(question, threshold, &options, &mut phases)?;
    Ok(AreaDecision {
        answer,
        method,
        exact,
        witness,
        phases,
    })
}

type Decided = (Option<bool>, &'static str, bool, Option<Triangulation>);

/// A point set or a polygon, for [`decide_area`] (sealed by its private
/// method).
pub trait DecisionInput: sealed::Decide {}

impl DecisionInput for PointSet {}
impl DecisionInput for SimplePolygon {}

mod sealed {
    use super::*;

    /// How a decision runs on an input kind.
    pub trait Decide {
        fn decide(
            &self,
            question: AreaQuestion,
            threshold: &AreaThreshold,
            options: &Options,
            phases: &mut Vec<Phase>,
        ) -> Result<Decided>;
    }

    impl Decide for PointSet {
        fn decide(
            &self,
            question: AreaQuestion,
            threshold: &AreaThreshold,
            options: &Options,
            phases: &mut Vec<Phase>,
        ) -> Result<Decided> {
            let pts = self.points();
            let hull = convex_hull_cycle(pts);
            let convex = hull.len() == pts.len() && is_strictly_convex_cycle(pts, &hull);
            if convex && question == AreaQuestion::SmallestAtLeast {
                let witness = one_shot(pts, &hull, threshold, options, phases)?
                    .map(|w| Triangulation::from_distinct(self, w));
                return Ok((Some(witness.is_some()), ONE_SHOT, true, witness));
            }
            let solved = solve_points(self, question.kind(), options, phases)?;
            Ok(read_solution(question, threshold, solved, |i| {
                self.input_points()[i as usize]
            }))
        }
    }

    impl Decide for SimplePolygon {
        fn decide(
            &self,
            question: AreaQuestion,
            threshold: &AreaThreshold,
            options: &Options,
            phases: &mut Vec<Phase>,
        ) -> Result<Decided> {
            if self.is_strictly_convex() && question == AreaQuestion::SmallestAtLeast {
                let ring = self.counter_clockwise();
                let witness = one_shot(self.vertices(), ring, threshold, options, phases)?
                    .map(|w| Triangulation::from_polygon_positions(self, w));
                return Ok((Some(witness.is_some()), ONE_SHOT, true, witness));
            }
            let solved = solve_polygon(self, question.kind(), options.stop(), phases)?;
            let points = self.point_set().input_points();
            Ok(read_solution(question, threshold, solved, |i| {
                points[i as usize]
            }))
        }
    }
}

/// Algorithm 49 in one shot on the strictly convex counter-clockwise
/// `ring` (indices into `points`), timed as `decide`: a witness's
/// triangles, or `None`.
fn one_shot(
    points: &[Point],
    ring: &[u32],
    threshold: &AreaThreshold,
    options: &Options,
    phases: &mut Vec<Phase>,
) -> Result<Option<Vec<[u32; 3]>>> {
    let n = ring.len();
    if n > MAX_CONVEX_VERTICES {
        return Err(Error::Unsupported {
            criterion: CRITERION,
            reason: UnsupportedReason::TooManyPoints {
                limit: MAX_CONVEX_VERTICES,
                distinct: n,
                because: "Algorithm 49's O(n²) tables",
            },
        });
    }
    timed(phases, "decide", || {
        maxmin_admits(points, ring, |t| threshold.compare(t), options.stop())
    })
}

/// The decision a solved criterion gives: its optimum compared with the
/// threshold when exact; otherwise yes when its triangulation meets the
/// threshold, no when its certified bound (a triangle, `point` its corners
/// by input index) is beyond it, else unknown.
fn read_solution(
    question: AreaQuestion,
    threshold: &AreaThreshold,
    solved: Solved,
    point: impl Fn(u32) -> Point,
) -> Decided {
    let triangulation = solved.triangulation;
    let meets = question.all_meet(threshold, &triangulation);
    let witness = meets.then_some(triangulation);
    if solved.optimality == Optimality::Exact {
        return (Some(meets), OPTIMUM, true, witness);
    }
    if meets {
        return (Some(true), APPROXIMATION, false, witness);
    }
    // MaxMin: the optimum's smallest area is at most the bound triangle's;
    // MinMax: the optimum's largest area is at least it. Either way, a
    // bound triangle that fails the threshold excludes it.
    let excluded = solved
        .bound
        .and_then(|b| b.triangle)
        .is_some_and(|t| !question.meets(threshold, t.map(&point)));
    (excluded.then_some(false), APPROXIMATION, false, None)
}
