//! `optri.Triangulation`: one result of `triangulate`, `triangulate_polygon`
//! or `compare`. Every scalar and dictionary attribute is a field of the
//! library's triangulation document (`optri::io::TriangulationReport`, the
//! document `optri triangulate --json` prints), so the Python names are the
//! JSON names and cannot drift from them; the arrays come from the same
//! triangulation the document describes.

use crate::adjacency;
use crate::convert::{
    index_array, int32_array, int32_values, json_text_to_py, point_array, points_arg, to_py_err,
    value_array,
};
use crate::location::{Locator, QueryProblem};
use numpy::{PyArray1, PyArray2};
use optri::io::{self, ReadInput, TriangulationReport, WriteOptions};
use optri::{Phase, Solution};
use pyo3::exceptions::{PyImportError, PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyTuple};
use serde::de::{Deserialize, Deserializer, IgnoredAny, MapAccess, Visitor};
use serde_json::value::RawValue;
use std::fmt;
use std::path::PathBuf;
use std::sync::{Arc, OnceLock};

/// The fields left out of [`Fields`]: the long arrays, which are numpy
/// attributes instead.
const ARRAY_FIELDS: &[&str] = &[
    "triangles",
    "edges",
    "coordinates",
    "duplicates",
    "elevations",
];

/// The fields of a triangulation document as their JSON texts, in document
/// order, without [`ARRAY_FIELDS`] (skipped while parsing, never built).
/// Kept as text so that `json.loads` gives every nested dictionary (stats,
/// timing_ms in phase order) with the library's key order.
struct Fields(Vec<(String, Box<RawValue>)>);

impl<'de> Deserialize<'de> for Fields {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct FieldsVisitor;
        impl<'de> Visitor<'de> for FieldsVisitor {
            type Value = Fields;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str("a JSON object")
            }
            fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Fields, A::Error> {
                let mut fields = Vec::new();
                while let Some(key) = map.next_key::<String>()? {
                    if ARRAY_FIELDS.contains(&key.as_str()) {
                        map.next_value::<IgnoredAny>()?;
                    } else {
                        let value = map.next_value::<Box<RawValue>>()?;
                        fields.push((key, value));
                    }
                }
                Ok(Fields(fields))
            }
        }
        deserializer.deserialize_map(FieldsVisitor)
    }
}

impl Fields {
    fn get(&self, name: &str) -> Option<&str> {
        self.0
            .iter()
            .find(|(key, _)| key == name)
            .map(|(_, value)| value.get())
    }
}

/// An optimal (or, where `exact` is false, best known) triangulation.
///
/// Attributes follow scipy.spatial.Delaunay: `points` (n, 2) float64, every
/// input point; `simplices` (m, 3) int32, counter-clockwise triangles as
/// input indices; `neighbors` (m, 3) int32, the triangle opposite each
/// corner (-1 on the boundary); `vertex_to_simplex` (n,) int32;
/// `convex_hull` (h, 2) int32, the boundary sides; `find_simplex(xi)`,
/// exact point location. Besides: `elevations` (n,) float64 or None;
/// `edges` (k, 2) int64, sorted `[a, b]` pairs with a < b; `duplicates`
/// (d, 2) int64, `[dropped, kept]` input indices of merged duplicate
/// points. The arrays are read-only. The other attributes are the
/// fields of the JSON document `optri triangulate --json` prints (see
/// `document` and `to_json`), written on the first access to one of them
/// (for large inputs that costs about as much as the quality measures of
/// `stats`), and `edges` is built on its first access.
#[pyclass(frozen, module = "optri")]
pub struct Triangulation {
    solution: Solution,
    /// The input with the user's values and the arithmetic: the solution
    /// ran on its working points (the decimals scaled to integers when
    /// they are exact).
    read: Arc<ReadInput>,
    /// `validate`, the library's phases, `total`.
    phases: Vec<Phase>,
    /// The document's fields, written on first use: the document's `stats`
    /// cost about as much as a Delaunay triangulation, so a caller who only
    /// wants the simplices does not pay for them.
    fields: OnceLock<Fields>,
    points: Py<PyArray2<f64>>,
    /// The input's elevations, one per point, if it had them.
    elevations: Option<Py<PyArray1<f64>>>,
    simplices: Py<PyArray2<i32>>,
    duplicates: Py<PyArray2<i64>>,
    /// Built on first use, as `fields`, and so are the attributes below.
    edges: OnceLock<Py<PyArray2<i64>>>,
    /// The triangle across each side, as [`adjacency::neighbors`].
    neighbor_table: OnceLock<Vec<[i64; 3]>>,
    neighbors: OnceLock<Py<PyArray2<i32>>>,
    vertex_to_simplex: OnceLock<Py<PyArray1<i32>>>,
    convex_hull: OnceLock<Py<PyArray2<i32>>>,
    /// `None` when the decimal scale is beyond what the locator takes.
    locator: OnceLock<Option<Locator>>,
}

impl Triangulation {
    /// The result object of `solution`, timed by `phases`.
    pub(crate) fn new(
        py: Python<'_>,
        solution: Solution,
        read: Arc<ReadInput>,
        phases: Vec<Phase>,
    ) -> PyResult<Self> {
        let t = &solution.triangulation;
        Ok(Triangulation {
            points: point_array(py, read.input.points())?,
            elevations: match &read.elevations {
                Some(z) => Some(value_array(py, z)?),
                None => None,
            },
            simplices: int32_array(py, t.triangles())?,
            duplicates: index_array(py, t.point_set().duplicates())?,
            edges: OnceLock::new(),
            neighbor_table: OnceLock::new(),
            neighbors: OnceLock::new(),
            vertex_to_simplex: OnceLock::new(),
            convex_hull: OnceLock::new(),
            locator: OnceLock::new(),
            fields: OnceLock::new(),
            solution,
            read,
            phases,
        })
    }

    fn report(&self) -> TriangulationReport<'_> {
        TriangulationReport::of_solution(&self.solution)
            .with_input(&self.read)
            .with_timing(&self.phases)
    }

    /// The document's fields, written (without the GIL) on first use. Two
    /// threads may both write them; one result is kept, and they are equal.
    fn fields(&self, py: Python<'_>) -> PyResult<&Fields> {
        if let Some(fields) = self.fields.get() {
            return Ok(fields);
        }
        let report = self.report();
        let fields = py
            .detach(|| {
                let text = serde_json::to_string(&report)?;
                serde_json::from_str::<Fields>(&text)
            })
            .map_err(|e| PyRuntimeError::new_err(format!("the JSON document: {e}")))?;
        Ok(self.fields.get_or_init(|| fields))
    }

    /// The point locator, built (without the GIL) on first use.
    fn locator(&self, py: Python<'_>) -> PyResult<&Locator> {
        let locator = match self.locator.get() {
            Some(locator) => locator,
            None => {
                let t = &self.solution.triangulation;
                let (points, exponent) = (self.read.working_points(), self.read.scale_exponent());
                let convex = matches!(t.domain(), optri::Domain::ConvexHull);
                let neighbors = self.neighbor_table(py);
                let built =
                    py.detach(|| Locator::new(points, t.triangles(), neighbors, convex, exponent));
                self.locator.get_or_init(|| built)
            }
        };
        locator.as_ref().ok_or_else(|| {
            PyValueError::new_err(format!(
                "find_simplex: the points were decimals computed times 10^{}, beyond the \
                 10^±22 it locates exactly",
                self.read.scale_exponent()
            ))
        })
    }

    /// The triangle across each side, computed (without the GIL) on first
    /// use.
    fn neighbor_table(&self, py: Python<'_>) -> &[[i64; 3]] {
        if let Some(table) = self.neighbor_table.get() {
            return table;
        }
        let triangles = self.solution.triangulation.triangles();
        let table = py.detach(|| adjacency::neighbors(triangles));
        self.neighbor_table.get_or_init(|| table)
    }

    /// The document field `name` (`None` when the document has no such
    /// field, as for `bound` on most results).
    fn field<'py>(&self, py: Python<'py>, name: &str) -> PyResult<Bound<'py, PyAny>> {
        match self.fields(py)?.get(name) {
            Some(text) => json_text_to_py(py, text),
            None => Ok(py.None().into_bound(py)),
        }
    }
}

#[pymethods]
impl Triangulation {
    /// (n, 2) float64: every input point, merged duplicates included.
    #[getter]
    fn points<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<f64>> {
        self.points.bind(py).clone()
    }

    /// (n,) float64: the elevation of every input point, when the input
    /// had them (an (n, 3) array or ``elevations=``), else None.
    #[getter]
    fn elevations<'py>(&self, py: Python<'py>) -> Option<Bound<'py, PyArray1<f64>>> {
        self.elevations.as_ref().map(|z| z.bind(py).clone())
    }

    /// (m, 3) int32: the triangles as input indices, counter-clockwise.
    #[getter]
    fn simplices<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<i32>> {
        self.simplices.bind(py).clone()
    }

    /// (m, 3) int32: `neighbors[i, j]` is the triangle that shares with
    /// triangle `i` the side opposite its corner `simplices[i, j]`, -1 where
    /// that side is on the boundary (scipy's meaning).
    #[getter]
    fn neighbors<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<i32>>> {
        if let Some(array) = self.neighbors.get() {
            return Ok(array.bind(py).clone());
        }
        let array = int32_array(py, self.neighbor_table(py))?;
        Ok(self.neighbors.get_or_init(|| array).bind(py).clone())
    }

    /// (n,) int32: for each input point, the smallest index of a triangle
    /// with it as a corner; a merged duplicate maps as the point it was
    /// merged into (scipy gives -1 for the duplicates Qhull drops), so the
    /// triangle always contains the point.
    #[getter]
    fn vertex_to_simplex<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray1<i32>>> {
        if let Some(array) = self.vertex_to_simplex.get() {
            return Ok(array.bind(py).clone());
        }
        let t = &self.solution.triangulation;
        let n = self.read.input.points().len();
        let values = py
            .detach(|| adjacency::vertex_to_simplex(t.triangles(), n, t.point_set().duplicates()));
        let array = PyArray1::from_vec(py, int32_values(values)?);
        array.getattr("flags")?.setattr("writeable", false)?;
        let array = array.unbind();
        Ok(self
            .vertex_to_simplex
            .get_or_init(|| array)
            .bind(py)
            .clone())
    }

    /// (h, 2) int32: the boundary sides of the triangulated domain, each
    /// `[a, b]` with the domain on its left, in counter-clockwise order from
    /// the smallest vertex index. For points, the convex hull's edges (every
    /// point on the hull boundary is a vertex, so a side between collinear
    /// hull points is one edge each); for a polygon, the polygon's sides.
    #[getter]
    fn convex_hull<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<i32>>> {
        if let Some(array) = self.convex_hull.get() {
            return Ok(array.bind(py).clone());
        }
        let triangles = self.solution.triangulation.triangles();
        let neighbors = self.neighbor_table(py);
        let sides = py.detach(|| adjacency::boundary(triangles, neighbors));
        let array = int32_array(py, &sides)?;
        Ok(self.convex_hull.get_or_init(|| array).bind(py).clone())
    }

    /// The index of a triangle containing each query point, -1 for a point
    /// outside every triangle: ``xi`` is an array-like of shape (..., 2),
    /// the result an int32 array of shape (...). Exact: containment is
    /// decided by exact orientation signs, and a query on a side or a
    /// corner shared by several triangles gets the smallest of their
    /// indices. Queries are taken as the points were: when the run was
    /// "decimal-exact" on decimals scaled by 10**k, a query whose two
    /// coordinates' reprs are decimals with at most k places (at most 15
    /// significant digits) is located at those decimals, so
    /// ``find_simplex(points)`` finds every point; any other query at its
    /// binary value. Raises ValueError for a query coordinate that is NaN,
    /// infinite, or non-zero below 2**-142 in magnitude.
    fn find_simplex<'py>(
        &self,
        py: Python<'py>,
        xi: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let array = py
            .import("numpy")?
            .call_method1("asarray", (xi,))
            .map_err(|e| {
                PyValueError::new_err(format!(
                    "xi must be an array-like of shape (..., 2): {}",
                    e.value(py)
                ))
            })?;
        let shape: Vec<usize> = array.getattr("shape")?.extract()?;
        let Some((&2, leading)) = shape.split_last() else {
            return Err(PyValueError::new_err(format!(
                "xi must have shape (..., 2), got {:?}",
                shape
            )));
        };
        let rows = array.call_method1("reshape", ((-1i64, 2i64),))?;
        let queries = points_arg(py, &rows, "xi")?;
        let locator = self.locator(py)?;
        let found = py.detach(|| {
            queries
                .iter()
                .enumerate()
                .map(|(k, &q)| locator.locate(q).map_err(|problem| (k, q, problem)))
                .collect::<Result<Vec<i64>, _>>()
        });
        let found = found.map_err(|(k, q, problem)| {
            let why = match problem {
                QueryProblem::NonFinite => "is not finite",
                QueryProblem::TooSmall => {
                    "has a non-zero coordinate below 2**-142 in magnitude, beyond the exact range"
                }
            };
            PyValueError::new_err(format!("query {k} ({}, {}) {why}", q[0], q[1]))
        })?;
        let result = PyArray1::from_vec(py, int32_values(found)?);
        result.call_method1("reshape", (PyTuple::new(py, leading)?,))
    }

    /// A ``matplotlib.tri.Triangulation`` of ``points`` and ``simplices``
    /// (for ``triplot``, ``tripcolor``, ``tricontour``). Needs matplotlib,
    /// imported here: ImportError naming it when it is missing.
    fn to_matplotlib<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let tri = py.import("matplotlib.tri").map_err(|e| {
            PyImportError::new_err(format!(
                "Triangulation.to_matplotlib needs matplotlib (pip install matplotlib): {}",
                e.value(py)
            ))
        })?;
        let columns = self.points.bind(py).getattr("T")?;
        tri.getattr("Triangulation")?.call1((
            columns.get_item(0)?,
            columns.get_item(1)?,
            self.simplices.bind(py),
        ))
    }

    /// The triangles as a GeoJSON-like MultiPolygon (the ``__geo_interface__``
    /// protocol, so ``shapely.geometry.shape(t)`` works): a dict with
    /// "type" and "coordinates", one polygon per simplex, its one ring
    /// closed and counter-clockwise, in the input coordinates.
    #[getter]
    fn __geo_interface__<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let points = self.read.input.points();
        let polygons: Vec<[[(f64, f64); 4]; 1]> = self
            .solution
            .triangulation
            .triangles()
            .iter()
            .map(|&[a, b, c]| {
                [[a, b, c, a].map(|v| {
                    let p = points[v as usize];
                    (p[0], p[1])
                })]
            })
            .collect();
        let dict = PyDict::new(py);
        dict.set_item("type", "MultiPolygon")?;
        dict.set_item("coordinates", polygons)?;
        Ok(dict)
    }

    /// (k, 2) int64: every edge once, `[a, b]` with a < b, sorted.
    #[getter]
    fn edges<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<i64>>> {
        if let Some(edges) = self.edges.get() {
            return Ok(edges.bind(py).clone());
        }
        let t = &self.solution.triangulation;
        let edges = index_array(py, &py.detach(|| t.edges()))?;
        Ok(self.edges.get_or_init(|| edges).bind(py).clone())
    }

    /// (d, 2) int64: merged duplicates as `[dropped, kept]` input indices;
    /// a dropped index appears in no simplex.
    #[getter]
    fn duplicates<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<i64>> {
        self.duplicates.bind(py).clone()
    }

    /// The criterion's registry name, e.g. "minmax-length".
    #[getter]
    fn criterion<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        self.field(py, "criterion")
    }

    /// True iff the result is provably optimal for the criterion.
    #[getter]
    fn exact<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        self.field(py, "exact")
    }

    /// The guarantee: "exact", "up-to-rounding" or "approximation".
    #[getter]
    fn optimality<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        self.field(py, "optimality")
    }

    /// A certified bound on the optimum when the result is not proven
    /// optimal and the criterion certifies one, else None.
    #[getter]
    fn bound<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        self.field(py, "bound")
    }

    /// maxmin-area / minmax-area on general point sets: the approximation,
    /// the Delaunay smallest angle, the ``alpha`` used, the candidates, the
    /// flips and the guarantee (a dict, see docs/json-schema.md), else None.
    #[getter]
    fn approximation<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        self.field(py, "approximation")
    }

    /// The algorithm that ran, in words.
    #[getter]
    fn algorithm<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        self.field(py, "algorithm")
    }

    /// What the triangles cover: "convex-hull" or "polygon".
    #[getter]
    fn domain<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        self.field(py, "domain")
    }

    /// The number of distinct points after merging duplicates.
    #[getter]
    fn distinct_points<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        self.field(py, "distinct_points")
    }

    /// Quality measures, the CLI's `stats`: max_edge_length, longest_edge,
    /// total_edge_length, min_area, max_area, min_angle_deg, max_angle_deg,
    /// min_height, max_eccentricity (with their triangles), max_slope and
    /// max_slope_triangle (only for points with elevations), triangles,
    /// edges, hull_points.
    #[getter]
    fn stats<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        self.field(py, "stats")
    }

    /// Counters the algorithm reported (may be empty).
    #[getter]
    fn diagnostics<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        self.field(py, "diagnostics")
    }

    /// Wall-clock milliseconds per phase: "validate", the library's phases,
    /// "total".
    #[getter]
    fn timing_ms<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        self.field(py, "timing_ms")
    }

    /// The whole JSON document (schema version `optri.SCHEMA_VERSION`) as a
    /// dict, arrays as lists: `json.loads(self.to_json())`.
    #[getter]
    fn document<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        json_text_to_py(py, &self.to_json(false)?)
    }

    /// The JSON document `optri triangulate --json` prints for this result
    /// (one line; `pretty=True` indents it as `-o FILE.json` does).
    #[pyo3(signature = (pretty = false))]
    fn to_json(&self, pretty: bool) -> PyResult<String> {
        let report = self.report();
        let text = if pretty {
            serde_json::to_string_pretty(&report)
        } else {
            serde_json::to_string(&report)
        };
        text.map_err(|e| PyRuntimeError::new_err(format!("cannot write the JSON document: {e}")))
    }

    /// Writes the triangulation to `path`, the format by its extension as
    /// the CLI's `-o`: .json (this document), .svg, .geojson, .ele or .edge
    /// (and the .node beside it), .obj, .ply (binary) or .off. Returns the
    /// paths written.
    fn write(&self, py: Python<'_>, path: PathBuf) -> PyResult<Vec<PathBuf>> {
        let report = self.report();
        py.detach(|| io::write(report, &path, &WriteOptions::default()))
            .map_err(to_py_err)
    }

    fn __repr__(&self) -> String {
        let t = &self.solution.triangulation;
        format!(
            "Triangulation(criterion={:?}, exact={}, domain={:?}, points={}, simplices={})",
            self.solution.criterion.name(),
            if self.solution.exact { "True" } else { "False" },
            match self.solution.triangulation.domain() {
                optri::Domain::Polygon { .. } => "polygon",
                _ => "convex-hull",
            },
            t.points().len(),
            t.triangles().len(),
        )
    }
}
