//! The [`Triangulation`] type: triangles over a [`PointSet`] covering a
//! [`Domain`] (the convex hull of the points, or a simple polygon's
//! interior), exact validation, and quality measures.

use crate::error::{Error, Result};
use crate::kernel::reporting::{
    angle_deg, area_scaled, exact_total_length, length_scaled, LengthSum, Rounding,
};
use crate::kernel::{
    self, compare_areas, compare_corner_angles, compare_length_sums, compare_lengths, orient_sign,
    Corners, Extremes, Point, TriangleMeasure,
};
use crate::parallel::prelude::*;
use crate::spatial::convex_hull_cycle;
use crate::structures::{Csr, Measure, PointSet, SimplePolygon};
#[cfg(feature = "io")]
use serde::Serialize;
use std::sync::OnceLock;

/// The region a [`Triangulation`] covers.
#[derive(Clone, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum Domain {
    /// The convex hull of the point set; every distinct point is a vertex.
    ConvexHull,
    /// The interior of a simple polygon whose vertices are the point set:
    /// the boundary cycle as input indices, counter-clockwise.
    Polygon {
        /// Ring positions (= input indices) in counter-clockwise order.
        boundary: Vec<u32>,
    },
}

/// A triangulation of a point set.
///
/// Triangles are counter-clockwise triples of *input* indices (for merged
/// duplicates, the index of the first occurrence). A triangulation produced
/// by optri always passes [`validate`](Self::validate).
#[derive(Clone, Debug)]
pub struct Triangulation {
    point_set: PointSet,
    triangles: Vec<[u32; 3]>,
    domain: Domain,
    /// [`stats`](Self::stats) and what re-expresses them, computed on first
    /// use: every front end reports them more than once (the document, its
    /// weight gap, the CLI's summary), and at 10⁶ points each computation
    /// sorts 6·10⁶ edges.
    stats: OnceLock<Measured>,
}

/// Quality measures of a triangulation, for reporting: every length, area
/// and angle is the exact value correctly rounded to the nearest `f64`
/// (once), and the extreme edges, triangles and corners are chosen by exact
/// comparison. So a triangle of positive area never reports area 0, and a
/// certified bound ([`crate::CertifiedBound`]) that is the same quantity as
/// a measure has the same value.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "io", derive(Serialize))]
pub struct Stats {
    /// Length of the longest edge.
    pub max_edge_length: f64,
    /// The longest edge, as input indices (chosen exactly).
    pub longest_edge: [u32; 2],
    /// Sum of all edge lengths (the *weight*), correctly rounded as a whole.
    pub total_edge_length: f64,
    /// Smallest triangle area.
    pub min_area: f64,
    /// Largest triangle area.
    pub max_area: f64,
    /// The triangle of smallest area, as input indices (counter-clockwise),
    /// chosen by exact area comparison (ties: the first in
    /// [`Triangulation::triangles`] order); `min_area` is its area.
    pub smallest_triangle: [u32; 3],
    /// The triangle of largest area, chosen as `smallest_triangle` is;
    /// `max_area` is its area.
    pub largest_triangle: [u32; 3],
    /// Smallest interior angle, degrees (positive for every proper
    /// triangle: in the kernel's coordinate range an angle's sine is at
    /// least 2⁻⁷⁹³, so no angle is below about 10⁻²³⁷ degrees).
    pub min_angle_deg: f64,
    /// Largest interior angle, degrees (180 only when it is within half an
    /// ulp of 180°, about 1.4·10⁻¹⁴ degrees: an extreme needle).
    pub max_angle_deg: f64,
    /// Smallest altitude of a triangle (the height measure of Bern,
    /// Edelsbrunner, Eppstein, Mitchell & Tan 1993).
    pub min_height: f64,
    /// The triangle of smallest altitude (exact comparison; ties: the first
    /// in [`Triangulation::triangles`] order).
    pub min_height_triangle: [u32; 3],
    /// Largest eccentricity: the distance from a triangle's circumcentre to
    /// the closed triangle, 0 for a triangle without an obtuse angle.
    pub max_eccentricity: f64,
    /// The triangle of largest eccentricity, chosen as
    /// `min_height_triangle` is (the first triangle when none is obtuse).
    pub max_eccentricity_triangle: [u32; 3],
    /// Largest slope (gradient magnitude of the linear interpolant of the
    /// elevations) when the points carry elevations
    /// ([`PointSet::with_elevations`]), else `None` (and not written).
    #[cfg_attr(feature = "io", serde(skip_serializing_if = "Option::is_none"))]
    pub max_slope: Option<f64>,
    /// The steepest triangle, chosen as `min_height_triangle` is.
    #[cfg_attr(feature = "io", serde(skip_serializing_if = "Option::is_none"))]
    pub max_slope_triangle: Option<[u32; 3]>,
    /// Number of triangles.
    pub triangles: usize,
    /// Number of edges.
    pub edges: usize,
    /// Number of boundary points: on the convex hull (collinear boundary
    /// points included), or every vertex of a polygon domain.
    pub hull_points: usize,
}

/// [`Stats`] with what re-expresses them exactly: the enclosure of the
/// total length (for other units) and the extreme corners (triangle
/// position, corner number: see [`Triangulation::corner`]).
#[derive(Clone, Debug)]
struct Measured {
    stats: Stats,
    /// Positions of the worst triangles in height, eccentricity and slope.
    lowest: usize,
    most_eccentric: usize,
    steepest: Option<usize>,
    length_sum: LengthSum,
    sharpest: (usize, usize),
    widest: (usize, usize),
}

/// Edges or triangles per parallel task of [`Triangulation::stats`].
const MEASURE_BLOCK: usize = 4096;

impl Triangulation {
    /// Wraps triangles given as *distinct* indices of `point_set` (internal
    /// algorithms work on distinct points), orienting each counter-clockwise.
    pub(crate) fn from_distinct(point_set: &PointSet, triangles: Vec<[u32; 3]>) -> Self {
        let pts = point_set.points();
        let triangles = triangles
            .into_iter()
            .map(|[a, b, c]| {
                let [a, b, c] =
                    if orient_sign(pts[a as usize], pts[b as usize], pts[c as usize]) < 0 {
                        [a, c, b]
                    } else {
                        [a, b, c]
                    };
                [a, b, c].map(|d| point_set.input_index(d))
            })
            .collect();
        Self {
            point_set: point_set.clone(),
            triangles,
            domain: Domain::ConvexHull,
            stats: OnceLock::new(),
        }
    }

    /// Wraps triangles of a simple polygon given as ring positions,
    /// orienting each counter-clockwise.
    pub(crate) fn from_polygon_positions(
        polygon: &SimplePolygon,
        triangles: Vec<[u32; 3]>,
    ) -> Self {
        let t = Self::from_distinct(polygon.point_set(), triangles);
        Self {
            domain: Domain::Polygon {
                boundary: polygon.counter_clockwise().to_vec(),
            },
            ..t
        }
    }

    /// The same triangles and domain over `point_set`, which holds the same
    /// points in the same order at other values: the user's doubles of a
    /// triangulation validated on their decimals scaled to integers (the
    /// decisions were made there; see `io::ReadInput::from_doubles`).
    #[cfg(feature = "io")]
    pub(crate) fn with_point_set(self, point_set: PointSet) -> Self {
        debug_assert_eq!(
            point_set.input_points().len(),
            self.point_set.input_points().len()
        );
        Self {
            point_set,
            stats: OnceLock::new(),
            ..self
        }
    }

    /// Builds a triangulation from triangles given as input indices and
    /// checks it with [`validate`](Self::validate).
    pub fn from_triangles(point_set: &PointSet, triangles: Vec<[u32; 3]>) -> Result<Self> {
        let t = Self {
            point_set: point_set.clone(),
            triangles,
            domain: Domain::ConvexHull,
            stats: OnceLock::new(),
        };
        t.validate()?;
        Ok(t)
    }

    /// Builds a triangulation of a simple polygon's interior from triangles
    /// given as ring positions and checks it with [`validate`](Self::validate).
    pub fn from_polygon_triangles(
        polygon: &SimplePolygon,
        triangles: Vec<[u32; 3]>,
    ) -> Result<Self> {
        let t = Self {
            point_set: polygon.point_set().clone(),
            triangles,
            domain: Domain::Polygon {
                boundary: polygon.counter_clockwise().to_vec(),
            },
            stats: OnceLock::new(),
        };
        t.validate()?;
        Ok(t)
    }

    /// The region this triangulation covers.
    pub fn domain(&self) -> &Domain {
        &self.domain
    }

    /// The validated point set.
    pub fn point_set(&self) -> &PointSet {
        &self.point_set
    }

    /// The caller's points (duplicates included), indexed by input index.
    pub fn points(&self) -> &[Point] {
        self.point_set.input_points()
    }

    /// Counter-clockwise triangles as input indices.
    pub fn triangles(&self) -> &[[u32; 3]] {
        &self.triangles
    }

    /// All edges as `[min, max]` input-index pairs, sorted.
    pub fn edges(&self) -> Vec<[u32; 2]> {
        // Sorted as `min << 32 | max`: one integer comparison per step (the
        // same order as the pairs').
        let mut keys: Vec<u64> = self
            .triangles
            .par_iter()
            .flat_map_iter(|t| [[t[0], t[1]], [t[1], t[2]], [t[2], t[0]]])
            .map(|[a, b]| (u64::from(a.min(b)) << 32) | u64::from(a.max(b)))
            .collect();
        keys.par_sort_unstable();
        keys.dedup();
        keys.into_iter()
            .map(|k| [(k >> 32) as u32, k as u32])
            .collect()
    }

    fn point(&self, i: u32) -> Point {
        self.point_set.input_points()[i as usize]
    }

    /// The longest edge, chosen by exact length comparison (ties: the
    /// smallest index pair).
    pub fn longest_edge(&self) -> [u32; 2] {
        self.stats().longest_edge
    }

    /// The longest of `edges` (exact; ties: the first).
    fn longest_of(&self, edges: &[[u32; 2]]) -> [u32; 2] {
        let mut best = edges[0];
        for &e in &edges[1..] {
            if compare_lengths(
                self.point(e[0]),
                self.point(e[1]),
                self.point(best[0]),
                self.point(best[1]),
            ) == std::cmp::Ordering::Greater
            {
                best = e;
            }
        }
        best
    }

    /// Quality measures.
    pub fn stats(&self) -> Stats {
        self.measured().stats.clone()
    }

    fn measured(&self) -> &Measured {
        self.stats.get_or_init(|| self.measure())
    }

    /// The measures of the points divided by `10^k`: lengths divided by
    /// `10^k` and areas by `10^2k`, each from the exact value and rounded
    /// once; angles, counts and the chosen edges and triangles unchanged.
    /// (Decimal input is triangulated as integers `10^k` times the user's
    /// decimals.)
    pub fn stats_over_power_of_ten(&self, k: i32) -> Stats {
        let m = self.measured();
        if k == 0 {
            return m.stats.clone();
        }
        let s = &m.stats;
        let area = |t: [u32; 3]| {
            let [a, b, c] = self.corners(t);
            area_scaled(a, b, c, k)
        };
        Stats {
            max_edge_length: length_scaled(
                self.point(s.longest_edge[0]),
                self.point(s.longest_edge[1]),
                k,
            ),
            total_edge_length: self.total_length(m.length_sum, k, None),
            min_area: area(s.smallest_triangle),
            max_area: area(s.largest_triangle),
            min_height: self.reported_over_power_of_ten(
                TriangleMeasure::SmallestHeight,
                m.lowest,
                k,
            ),
            max_eccentricity: self.reported_over_power_of_ten(
                TriangleMeasure::Eccentricity,
                m.most_eccentric,
                k,
            ),
            max_slope: m
                .steepest
                .map(|i| self.reported_over_power_of_ten(TriangleMeasure::Slope, i, k)),
            ..s.clone()
        }
    }

    fn reported_over_power_of_ten(&self, measure: TriangleMeasure, i: usize, k: i32) -> f64 {
        measure.reported_over_power_of_ten(&self.measure_corners(i), k)
    }

    /// The triangle with the smallest angle (chosen exactly, ties: the
    /// first), as input indices.
    #[cfg(feature = "io")]
    pub(crate) fn sharpest_triangle(&self) -> [u32; 3] {
        self.triangles[self.measured().sharpest.0]
    }

    /// The triangle that attains `measure` (the one [`Stats`] reports:
    /// chosen exactly, ties the first), as input indices; `None` for the
    /// edge measures and for the slope without elevations.
    pub fn worst_triangle(&self, measure: Measure) -> Option<[u32; 3]> {
        let m = self.measured();
        let position = match measure {
            Measure::MaxEdgeLength | Measure::TotalEdgeLength => return None,
            Measure::MinArea => return Some(m.stats.smallest_triangle),
            Measure::MaxArea => return Some(m.stats.largest_triangle),
            Measure::MinAngle => m.sharpest.0,
            Measure::MaxAngle => m.widest.0,
            Measure::MinHeight => m.lowest,
            Measure::MaxEccentricity => m.most_eccentric,
            Measure::MaxSlope => m.steepest?,
        };
        Some(self.triangles[position])
    }

    /// Exact comparison of one measure of this triangulation with the same
    /// measure of `other` (for ranking criteria: the rounded values may tie
    /// where the exact ones do not).
    pub fn compare_measure(&self, other: &Triangulation, measure: Measure) -> std::cmp::Ordering {
        let (m, n) = (self.measured(), other.measured());
        let (s, t) = (&m.stats, &n.stats);
        match measure {
            Measure::MaxEdgeLength => {
                let ([a, b], [c, d]) = (s.longest_edge, t.longest_edge);
                compare_lengths(self.point(a), self.point(b), other.point(c), other.point(d))
            }
            Measure::MinArea => compare_areas(
                self.corners(s.smallest_triangle),
                other.corners(t.smallest_triangle),
            ),
            Measure::MaxArea => compare_areas(
                self.corners(s.largest_triangle),
                other.corners(t.largest_triangle),
            ),
            Measure::MinAngle => compare_corner_angles(
                self.corners(self.corner(m.sharpest)),
                other.corners(other.corner(n.sharpest)),
            ),
            Measure::MaxAngle => compare_corner_angles(
                self.corners(self.corner(m.widest)),
                other.corners(other.corner(n.widest)),
            ),
            Measure::MinHeight => TriangleMeasure::SmallestHeight.compare_values(
                &self.measure_corners(m.lowest),
                &other.measure_corners(n.lowest),
            ),
            Measure::MaxEccentricity => TriangleMeasure::Eccentricity.compare_values(
                &self.measure_corners(m.most_eccentric),
                &other.measure_corners(n.most_eccentric),
            ),
            Measure::MaxSlope => match (m.steepest, n.steepest) {
                (Some(i), Some(j)) => TriangleMeasure::Slope
                    .compare_values(&self.measure_corners(i), &other.measure_corners(j)),
                // A triangulation without elevations has no slope: it sorts
                // first, as `None` does.
                (i, j) => i.is_some().cmp(&j.is_some()),
            },
            Measure::TotalEdgeLength => {
                // Correct rounding is monotone: different rounded totals are
                // ordered as the exact ones.
                let (x, y) = (s.total_edge_length, t.total_edge_length);
                if x != y {
                    return x.total_cmp(&y);
                }
                let (e, f) = (self.edges(), other.edges());
                if e == f && self.points() == other.points() {
                    return std::cmp::Ordering::Equal;
                }
                let segments = |t: &Triangulation, edges: &[[u32; 2]]| -> Vec<[Point; 2]> {
                    edges
                        .iter()
                        .map(|&[a, b]| [t.point(a), t.point(b)])
                        .collect()
                };
                compare_length_sums(&segments(self, &e), &segments(other, &f))
            }
        }
    }

    fn corners(&self, t: [u32; 3]) -> [Point; 3] {
        t.map(|i| self.point(i))
    }

    /// Triangle `i`'s corners and elevations (zeros without elevations), as
    /// the kernel's triangle measures take them.
    fn measure_corners(&self, i: usize) -> Corners {
        let t = self.triangles[i];
        let z = |v: u32| {
            self.point_set
                .elevations()
                .map_or(0.0, |z| z[self.point_set.distinct_index(v) as usize])
        };
        (self.corners(t), t.map(z))
    }

    /// The position of the worst triangle under `measure` (exact; ties: the
    /// first), blocks in parallel.
    fn worst_position(&self, measure: TriangleMeasure) -> usize {
        let n = self.triangles.len();
        (0..n.div_ceil(MEASURE_BLOCK))
            .into_par_iter()
            .map(|b| {
                let start = b * MEASURE_BLOCK;
                let end = (start + MEASURE_BLOCK).min(n);
                let i = measure
                    .worst((start..end).map(|i| self.measure_corners(i)))
                    .expect("a non-empty block");
                start + i
            })
            .reduce_with(|a, b| {
                // `a` precedes `b`: keep it unless `b` is strictly worse.
                let worse = measure
                    .worst([self.measure_corners(a), self.measure_corners(b)].into_iter())
                    .expect("two triangles");
                if worse == 1 {
                    b
                } else {
                    a
                }
            })
            .expect("a triangulation has a triangle")
    }

    /// Corner `j` of triangle `i`: its `j`-th point (the apex), then the
    /// next two in counter-clockwise order.
    fn corner(&self, (i, j): (usize, usize)) -> [u32; 3] {
        let t = self.triangles[i];
        [t[j], t[(j + 1) % 3], t[(j + 2) % 3]]
    }

    /// The total edge length over `10^k` from its enclosure, or exactly
    /// when the enclosure cannot decide (over `edges` when given).
    fn total_length(&self, sum: LengthSum, k: i32, edges: Option<&[[u32; 2]]>) -> f64 {
        sum.rounded(k, Rounding::Nearest).unwrap_or_else(|| {
            let computed;
            let edges = match edges {
                Some(e) => e,
                None => {
                    computed = self.edges();
                    &computed
                }
            };
            exact_total_length(
                edges.len(),
                |i| edges[i].map(|v| self.point(v)),
                k,
                Rounding::Nearest,
            )
        })
    }

    fn measure(&self) -> Measured {
        let edges = self.edges();
        let longest_edge = self.longest_of(&edges);
        let length_sum = edges
            .par_chunks(MEASURE_BLOCK)
            .map(|block| {
                block.iter().fold(LengthSum::ZERO, |sum, &[a, b]| {
                    sum.plus_segment(self.point(a), self.point(b))
                })
            })
            .reduce(|| LengthSum::ZERO, LengthSum::plus);
        let extremes = self
            .triangles
            .par_chunks(MEASURE_BLOCK)
            .enumerate()
            .map(|(b, block)| {
                Extremes::of(b * MEASURE_BLOCK, block.iter().map(|&t| self.corners(t)))
            })
            .reduce_with(Extremes::merge)
            .expect("a triangulation has a triangle");
        let worst = |measure: TriangleMeasure| self.worst_position(measure);
        let (lowest, most_eccentric) = (
            worst(TriangleMeasure::SmallestHeight),
            worst(TriangleMeasure::Eccentricity),
        );
        let steepest = self
            .point_set
            .elevations()
            .map(|_| worst(TriangleMeasure::Slope));
        let reported =
            |measure: TriangleMeasure, i: usize| measure.reported(&self.measure_corners(i));
        let angle = |corner: (usize, usize)| {
            let [o, a, b] = self.corners(self.corner(corner));
            angle_deg(o, a, b)
        };
        let area = |i: usize| {
            let [a, b, c] = self.corners(self.triangles[i]);
            area_scaled(a, b, c, 0)
        };
        let stats = Stats {
            max_edge_length: length_scaled(
                self.point(longest_edge[0]),
                self.point(longest_edge[1]),
                0,
            ),
            longest_edge,
            total_edge_length: self.total_length(length_sum, 0, Some(&edges)),
            min_area: area(extremes.smallest()),
            max_area: area(extremes.largest()),
            smallest_triangle: self.triangles[extremes.smallest()],
            largest_triangle: self.triangles[extremes.largest()],
            min_angle_deg: angle(extremes.sharpest()),
            max_angle_deg: angle(extremes.widest()),
            min_height: reported(TriangleMeasure::SmallestHeight, lowest),
            min_height_triangle: self.triangles[lowest],
            max_eccentricity: reported(TriangleMeasure::Eccentricity, most_eccentric),
            max_eccentricity_triangle: self.triangles[most_eccentric],
            max_slope: steepest.map(|i| reported(TriangleMeasure::Slope, i)),
            max_slope_triangle: steepest.map(|i| self.triangles[i]),
            triangles: self.triangles.len(),
            edges: edges.len(),
            hull_points: match &self.domain {
                Domain::ConvexHull => 2 * self.point_set.len() - 2 - self.triangles.len(),
                Domain::Polygon { boundary } => boundary.len(),
            },
        };
        Measured {
            stats,
            lowest,
            most_eccentric,
            steepest,
            length_sum,
            sharpest: extremes.sharpest(),
            widest: extremes.widest(),
        }
    }

    /// Checks exactly that this is a triangulation of its [`Domain`].
    ///
    /// Verified: indices are in range and name first occurrences of merged
    /// duplicates; every triangle is strictly counter-clockwise (no flat
    /// triangles); no directed edge is used twice; the unpaired edges are
    /// exactly the domain's boundary edges, counter-clockwise (the convex
    /// hull's, collinear hull points included, or the polygon's); around every
    /// vertex the triangles form one fan that turns once (interior) or less
    /// than once (boundary), so no two triangles overlap; every distinct point
    /// is a vertex; and the triangle count is `2n - h - 2` (`n - 2` for a
    /// polygon). A locally injective triangulated disc whose boundary maps
    /// one-to-one onto a simple closed curve is embedded, so no point can lie
    /// inside an edge or a triangle.
    pub fn validate(&self) -> Result<()> {
        let bad = |m: String| Err(Error::InvalidTriangulation(m));
        let ps = &self.point_set;
        let pts = ps.points();
        let n_input = ps.input_points().len() as u32;
        let n = pts.len();
        let mut tris = Vec::with_capacity(self.triangles.len());
        for (ti, t) in self.triangles.iter().enumerate() {
            if t.iter().any(|&i| i >= n_input) {
                return bad(format!(
                    "triangle {ti} {t:?} has an index out of range (< {n_input})"
                ));
            }
            let d = t.map(|i| ps.distinct_index(i));
            // Indices must be first occurrences: a dropped duplicate's index
            // would make `edges()` list one geometric edge under two names.
            if let Some(&i) = t
                .iter()
                .find(|&&i| ps.input_index(ps.distinct_index(i)) != i)
            {
                return bad(format!(
                    "triangle {ti} {t:?} uses input point {i}, a duplicate of point {}; \
                     use the first occurrence",
                    ps.input_index(ps.distinct_index(i))
                ));
            }
            if d[0] == d[1] || d[1] == d[2] || d[0] == d[2] {
                return bad(format!("triangle {ti} {t:?} repeats a point"));
            }
            if orient_sign(pts[d[0] as usize], pts[d[1] as usize], pts[d[2] as usize]) <= 0 {
                return bad(format!(
                    "triangle {ti} {t:?} is not strictly counter-clockwise (flat or clockwise)"
                ));
            }
            tris.push(d);
        }
        // Fans as one CSR array (no hash map: 10⁷ points must validate in a
        // few hundred MB): at v, one entry (a, b) per triangle (v, a, b),
        // sorted, so directed edge v → a exists iff some entry at v starts
        // with a (binary search).
        let mut fans = Csr::from_pairs(
            n,
            tris.iter()
                .flat_map(|&[a, b, c]| [(a, (b, c)), (b, (c, a)), (c, (a, b))]),
        );
        fans.sort_rows();
        let fan = |v: u32| fans.row(v);
        let has_edge = |u: u32, v: u32| fan(u).binary_search_by(|&(a, _)| a.cmp(&v)).is_ok();
        for v in 0..n as u32 {
            if let Some(w) = fan(v).windows(2).find(|w| w[0].0 == w[1].0) {
                return bad(format!(
                    "directed edge ({v}, {}) is used by two triangles",
                    w[0].0
                ));
            }
        }
        let hull = match &self.domain {
            Domain::ConvexHull => convex_hull_cycle(pts),
            Domain::Polygon { boundary } => {
                boundary.iter().map(|&i| ps.distinct_index(i)).collect()
            }
        };
        let h = hull.len();
        let mut boundary = 0usize;
        for u in 0..n as u32 {
            boundary += fan(u).iter().filter(|&&(v, _)| !has_edge(v, u)).count();
        }
        for i in 0..h {
            let (u, v) = (hull[i], hull[(i + 1) % h]);
            if !has_edge(u, v) || has_edge(v, u) {
                return bad(format!(
                    "boundary edge ({}, {}) of the domain is not a boundary edge of the triangles",
                    ps.input_index(u),
                    ps.input_index(v)
                ));
            }
        }
        if boundary != h {
            return bad(format!(
                "{boundary} boundary edges, but the domain's boundary has {h}"
            ));
        }
        // Fans: at v, each triangle (v, a, b) turns from a to b.
        let mut on_hull = vec![false; n];
        for &v in &hull {
            on_hull[v as usize] = true;
        }
        for v in 0..n {
            let fan = fan(v as u32);
            if fan.is_empty() {
                return bad(format!(
                    "point {} is not a vertex of any triangle",
                    ps.input_index(v as u32)
                ));
            }
            // Entries are sorted by their first vertex and unique there.
            let next = |a: u32| {
                fan.binary_search_by(|&(x, _)| x.cmp(&a))
                    .ok()
                    .map(|k| fan[k].1)
            };
            let start = if on_hull[v] {
                // The fan's first triangle: its `a` is no triangle's `b`.
                let mut seconds: Vec<u32> = fan.iter().map(|&(_, b)| b).collect();
                seconds.sort_unstable();
                match fan
                    .iter()
                    .find(|&&(a, _)| seconds.binary_search(&a).is_err())
                {
                    Some(&(a, _)) => a,
                    None => {
                        return bad(format!(
                            "hull point {} is surrounded by triangles",
                            ps.input_index(v as u32)
                        ))
                    }
                }
            } else {
                fan[0].0
            };
            let o = pts[v];
            let d0 = pts[start as usize];
            // Half-open halves relative to d0: [0, π) is 0, [π, 2π) is 1.
            let half = |x: u32| -> u8 {
                let p = pts[x as usize];
                match orient_sign(o, d0, p) {
                    1 => 0,
                    -1 => 1,
                    _ => (kernel::dot_sign(o, d0, p) < 0) as u8,
                }
            };
            let (mut cur, mut steps, mut wraps) = (start, 0usize, 0usize);
            while let Some(nx) = next(cur) {
                if half(cur) == 1 && half(nx) == 0 {
                    wraps += 1;
                }
                cur = nx;
                steps += 1;
                if cur == start || steps > fan.len() {
                    break;
                }
            }
            let closed = cur == start;
            let ok = if on_hull[v] {
                !closed && steps == fan.len() && wraps == 0
            } else {
                closed && steps == fan.len() && wraps == 1
            };
            if !ok {
                return bad(format!(
                    "the triangles around point {} do not form a single non-overlapping fan",
                    ps.input_index(v as u32)
                ));
            }
        }
        if tris.len() != 2 * n - h - 2 {
            return bad(format!(
                "{} triangles, but {n} points with {h} on the hull need {}",
                tris.len(),
                2 * n - h - 2
            ));
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square_with_center() -> PointSet {
        PointSet::new(&[[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0], [1.0, 1.0]]).unwrap()
    }

    #[test]
    fn a_valid_fan_passes_and_reports_stats() {
        let ps = square_with_center();
        let t =
            Triangulation::from_triangles(&ps, vec![[0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4]])
                .unwrap();
        let s = t.stats();
        assert_eq!(s.triangles, 4);
        assert_eq!(s.edges, 8);
        assert_eq!(s.hull_points, 4);
        assert!((s.max_edge_length - 2.0).abs() < 1e-12);
        assert!((s.min_angle_deg - 45.0).abs() < 1e-9);
        assert!((s.max_angle_deg - 90.0).abs() < 1e-9);
    }

    /// The sorted-key edge list equals the plain pair set, and the cached
    /// stats follow a change of coordinates (`with_point_set`).
    #[test]
    fn edges_are_the_distinct_sorted_pairs_and_stats_follow_the_points() {
        let ps = square_with_center();
        let t =
            Triangulation::from_triangles(&ps, vec![[0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4]])
                .unwrap();
        let pairs: std::collections::BTreeSet<[u32; 2]> = t
            .triangles()
            .iter()
            .flat_map(|t| [[t[0], t[1]], [t[1], t[2]], [t[2], t[0]]])
            .map(|[a, b]| [a.min(b), a.max(b)])
            .collect();
        assert_eq!(t.edges(), pairs.into_iter().collect::<Vec<_>>());
        assert_eq!(t.stats().max_edge_length, 2.0);
        assert_eq!(t.longest_edge(), [0, 1]);
        #[cfg(feature = "io")]
        {
            let wider =
                PointSet::new(&[[0.0, 0.0], [6.0, 0.0], [6.0, 2.0], [0.0, 2.0], [3.0, 1.0]])
                    .unwrap();
            let t = t.with_point_set(wider);
            assert_eq!(t.stats().max_edge_length, 6.0);
            assert!((t.stats().total_edge_length - (16.0 + 4.0 * 10f64.sqrt())).abs() < 1e-12);
        }
    }

    #[test]
    fn invalid_triangulations_are_rejected_with_reasons() {
        let ps = square_with_center();
        let cases: Vec<(Vec<[u32; 3]>, &str)> = vec![
            (vec![[0, 1, 2], [0, 2, 3]], "not a vertex"),
            (
                vec![[0, 4, 1], [1, 2, 4], [2, 3, 4], [3, 0, 4]],
                "counter-clockwise",
            ),
            (vec![[0, 1, 4], [1, 2, 4], [2, 3, 4]], "boundary"),
            (
                vec![[0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4], [0, 1, 2]],
                "used by two",
            ),
            (
                vec![[0, 1, 9], [1, 2, 4], [2, 3, 4], [3, 0, 4]],
                "out of range",
            ),
        ];
        for (tris, why) in cases {
            let e = Triangulation::from_triangles(&ps, tris.clone())
                .unwrap_err()
                .to_string();
            assert!(e.contains(why), "{tris:?}: {e}");
        }
    }

    #[test]
    fn a_point_inside_an_edge_is_rejected() {
        // (1,0) lies on edge (0,0)-(2,0) of a triangle that skips it.
        let ps = PointSet::new(&[[0.0, 0.0], [2.0, 0.0], [1.0, 2.0], [1.0, 0.0]]).unwrap();
        assert!(Triangulation::from_triangles(&ps, vec![[0, 1, 2]]).is_err());
        assert!(Triangulation::from_triangles(&ps, vec![[0, 3, 2], [3, 1, 2]]).is_ok());
    }

    #[test]
    fn a_doubly_covering_mesh_is_rejected() {
        // Hexagon-like fan around the center that winds twice has the wrong
        // count or a bad fan; build a wound-twice fan on 5 outer points.
        let mut pts = vec![[0.0, 0.0]];
        for k in 0..5 {
            let a = std::f64::consts::TAU * k as f64 / 5.0;
            pts.push([a.cos(), a.sin()]);
        }
        let ps = PointSet::new(&pts).unwrap();
        let ok: Vec<[u32; 3]> = (0..5).map(|k| [0, 1 + k, 1 + (k + 1) % 5]).collect();
        assert!(Triangulation::from_triangles(&ps, ok).is_ok());
        let twice: Vec<[u32; 3]> = (0..5)
            .map(|k| [0, 1 + (2 * k) % 5, 1 + (2 * k + 2) % 5])
            .collect();
        assert!(Triangulation::from_triangles(&ps, twice).is_err());
    }
}
