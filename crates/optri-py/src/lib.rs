//! Python bindings of optri: the extension module `optri`, built by maturin
//! as an abi3 wheel (`pip install ./crates/optri-py`).
//!
//! The module is a thin front end over the library's registry
//! ([`optri::Criterion::ALL`], [`optri::GraphKind::ALL`], their `info()`
//! and `from_name`) and its one result schema ([`optri::io::TriangulationReport`]): a
//! criterion that lands in the registry is callable from Python without a
//! change here, and every result attribute is a field of the document
//! `optri triangulate --json` prints. Conventions follow `scipy.spatial`:
//! `(n, 2)` float arrays in, `(m, 3)` / `(k, 2)` int64 index arrays out.
//!
//! Errors: the library's message, as `ValueError` for bad input and
//! arguments, `OSError` for files, `RuntimeError` for a bug. Nothing here
//! panics on input; a panic inside the library would surface as pyo3's
//! `PanicException`, never an abort. The GIL is released while the library
//! works (`Python::detach`), so other Python threads run meanwhile.

mod convert;
mod triangulation;

use convert::{file_err, index_array, json_text_to_py, point_array, points_arg, to_py_err};
use numpy::PyArray2;
use optri::io::{self, GraphReport, Input, InputFormat, ReadInput};
use optri::{Criterion, Error, GraphKind, Options, Phase, PointSet, SimplePolygon};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use std::path::PathBuf;
use std::sync::Arc;
use std::time::Instant;
use triangulation::Triangulation;

fn ms_since(start: Instant) -> f64 {
    start.elapsed().as_secs_f64() * 1e3
}

/// The library's options for `criteria` from Python keyword arguments, each
/// checked against the option names the registry lists for them
/// ([`optri::CriterionInfo::options`]).
///
/// Keywords are the options the registry lists for the criteria
/// (`CriterionInfo::options`, e.g. minmax-length's `metric`); anything else
/// is refused naming what is available.
fn options_from(criteria: &[Criterion], kwargs: Option<&Bound<'_, PyDict>>) -> PyResult<Options> {
    let options = Options::default();
    let Some(kwargs) = kwargs else {
        return Ok(options);
    };
    let mut available: Vec<&str> = criteria
        .iter()
        .flat_map(|c| c.info().options.iter().copied())
        .collect();
    available.sort_unstable();
    available.dedup();
    let whose = match criteria {
        [one] => format!("criterion {}", one.name()),
        _ => "these criteria".to_string(),
    };
    let mut options = options;
    for (key, value) in kwargs.iter() {
        let key: String = key.extract()?;
        if !available.contains(&key.as_str()) {
            return Err(PyValueError::new_err(format!(
                "unknown option '{key}' for {whose}; available: {}",
                if available.is_empty() {
                    "none".to_string()
                } else {
                    available.join(", ")
                }
            )));
        }
        match key.as_str() {
            "metric" => {
                let text: String = value.extract().map_err(|_| {
                    PyValueError::new_err(
                        "metric must be a string: euclidean, l1, linf, lp:P or polygon:x1,y1,...",
                    )
                })?;
                let metric = optri::kernel::Metric::parse(&text)
                    .map_err(|e| PyValueError::new_err(format!("metric: {e}")))?;
                options = options.with_metric(metric);
            }
            _ => {
                return Err(PyValueError::new_err(format!(
                    "option '{key}' of {whose} is not passed through by these Python bindings yet"
                )))
            }
        }
    }
    Ok(options)
}

/// The options of a graph: its metric (`None`: Euclidean), read by the RNG
/// and the MST.
fn graph_options(metric: Option<&str>) -> PyResult<Options> {
    Ok(match metric {
        None => Options::default(),
        Some(m) => Options::default().with_metric(
            optri::kernel::Metric::parse(m)
                .map_err(|e| PyValueError::new_err(format!("metric: {e}")))?,
        ),
    })
}

/// Python floats read at their decimal values ([`io::doubles_as_decimals`]:
/// each coordinate's shortest repr when every one has at most 15
/// significant digits), the validated working points, and the `validate`
/// phase.
fn point_set(points: Vec<[f64; 2]>) -> optri::Result<(Arc<ReadInput>, PointSet, Phase)> {
    let start = Instant::now();
    let read = io::doubles_as_decimals(Input::Points(points));
    let set = PointSet::new(read.working_points())?;
    Ok((
        Arc::new(read),
        set,
        Phase {
            name: "validate",
            ms: ms_since(start),
        },
    ))
}

/// One criterion on a validated point set, timed as the CLI times it
/// (`validate`, the library's phases, `total` since `start`).
fn solve(
    read: &Arc<ReadInput>,
    set: &PointSet,
    validate: &Phase,
    criterion: Criterion,
    options: &Options,
) -> optri::Result<Timed> {
    let start = Instant::now();
    let solution = optri::triangulate_with(set, criterion, options)?;
    Ok(timed(solution, read, validate, start))
}

/// `solution` with its phases between `validate` and `total` (since `start`,
/// plus the validation).
fn timed(
    solution: optri::Solution,
    read: &Arc<ReadInput>,
    validate: &Phase,
    start: Instant,
) -> Timed {
    let mut phases = vec![validate.clone()];
    phases.extend(solution.phases.iter().cloned());
    phases.push(Phase {
        name: "total",
        ms: validate.ms + ms_since(start),
    });
    Timed {
        solution,
        read: Arc::clone(read),
        phases,
    }
}

/// A library result, the input it was computed from (the user's values and
/// the arithmetic) and the phases its document reports.
struct Timed {
    solution: optri::Solution,
    read: Arc<ReadInput>,
    phases: Vec<Phase>,
}

impl Timed {
    fn into_py(self, py: Python<'_>) -> PyResult<Triangulation> {
        Triangulation::new(py, self.solution, self.read, self.phases)
    }
}

/// Triangulates the convex hull of ``points`` by ``criterion``.
///
/// ``points``: an (n, 2) array-like of floats (duplicates are merged and
/// reported in ``duplicates``). Each float is taken at the decimal its repr
/// shows when every coordinate's repr has at most 15 significant digits
/// (``coordinate_arithmetic`` is then "decimal-exact": 0.1, 0.2, 0.3 are
/// collinear as written); otherwise at its binary value ("binary64").
/// ``criterion``: a name from ``criteria()``,
/// case-insensitive. Keyword arguments are the criterion's options from the
/// registry (``criteria()[i]["options"]``). Returns a ``Triangulation``.
///
/// Raises ValueError with the library's message for NaN or infinite
/// coordinates, a wrong shape, fewer than 3 distinct points, all points
/// collinear, an unknown criterion or option, or an input the criterion
/// does not support (e.g. min-weight on points not in convex position).
#[pyfunction]
#[pyo3(signature = (points, criterion = "delaunay", **options))]
fn triangulate(
    py: Python<'_>,
    points: &Bound<'_, PyAny>,
    criterion: &str,
    options: Option<&Bound<'_, PyDict>>,
) -> PyResult<Triangulation> {
    let criterion = Criterion::from_name(criterion).map_err(to_py_err)?;
    let options = options_from(&[criterion], options)?;
    let points = points_arg(py, points, "points")?;
    let result = py
        .detach(|| {
            let (read, set, validate) = point_set(points)?;
            solve(&read, &set, &validate, criterion, &options)
        })
        .map_err(to_py_err)?;
    result.into_py(py)
}

/// Triangulates the interior of the simple polygon ``vertices`` (an (n, 2)
/// array-like ring in boundary order, either orientation, the closing
/// vertex not repeated) by ``criterion``. Indices in the result are ring
/// positions and ``domain`` is "polygon".
///
/// Raises ValueError for a ring that is not a simple polygon (naming the
/// edges that meet or the repeated vertex), a criterion that takes no
/// polygons, or the other input errors of ``triangulate``.
#[pyfunction]
#[pyo3(signature = (vertices, criterion = "delaunay", **options))]
fn triangulate_polygon(
    py: Python<'_>,
    vertices: &Bound<'_, PyAny>,
    criterion: &str,
    options: Option<&Bound<'_, PyDict>>,
) -> PyResult<Triangulation> {
    let criterion = Criterion::from_name(criterion).map_err(to_py_err)?;
    let options = options_from(&[criterion], options)?;
    let ring = points_arg(py, vertices, "vertices")?;
    let result = py
        .detach(|| {
            let start = Instant::now();
            let read = Arc::new(io::doubles_as_decimals(Input::Polygon(ring)));
            let polygon = SimplePolygon::new(read.working_points())?;
            let validate = Phase {
                name: "validate",
                ms: ms_since(start),
            };
            let start = Instant::now();
            let solution = optri::triangulate_polygon_with(&polygon, criterion, &options)?;
            Ok::<_, Error>(timed(solution, &read, &validate, start))
        })
        .map_err(to_py_err)?;
    result.into_py(py)
}

/// Triangulates ``points`` by several criteria: a dict from criterion name
/// to ``Triangulation``, in registry order.
///
/// ``criteria=None`` runs every criterion of the registry that accepts the
/// input and leaves out those that refuse it (e.g. min-weight on points not
/// in convex position); a list of names runs exactly those and raises
/// ValueError if one refuses the input. Keyword arguments are options, as
/// for ``triangulate``.
#[pyfunction]
#[pyo3(signature = (points, criteria = None, **options))]
fn compare(
    py: Python<'_>,
    points: &Bound<'_, PyAny>,
    criteria: Option<Vec<String>>,
    options: Option<&Bound<'_, PyDict>>,
) -> PyResult<Py<PyDict>> {
    let every = criteria.is_none();
    let chosen: Vec<Criterion> = match criteria {
        None => Criterion::ALL.to_vec(),
        Some(names) => names
            .iter()
            .map(|name| Criterion::from_name(name))
            .collect::<optri::Result<_>>()
            .map_err(to_py_err)?,
    };
    let options = options_from(&chosen, options)?;
    let points = points_arg(py, points, "points")?;
    let results = py
        .detach(|| {
            let (read, set, validate) = point_set(points)?;
            let mut results = Vec::with_capacity(chosen.len());
            for &criterion in &chosen {
                match solve(&read, &set, &validate, criterion, &options) {
                    Ok(result) => results.push((criterion, result)),
                    // "Every criterion that accepts the input."
                    Err(Error::Unsupported { .. }) if every => {}
                    Err(e) => return Err(e),
                }
            }
            Ok(results)
        })
        .map_err(to_py_err)?;
    let dict = PyDict::new(py);
    for (criterion, result) in results {
        dict.set_item(criterion.name(), result.into_py(py)?)?;
    }
    Ok(dict.unbind())
}

/// The edges of the proximity graph ``kind`` of ``points`` as a (k, 2) int64
/// array of input indices: ``[min, max]`` pairs, sorted, except "hull",
/// whose edges ``[a, b]`` go counter-clockwise. Kinds: ``graph_kinds()``
/// ("hull", "delaunay", "rng", "gabriel", "mst"). Raises ValueError for an
/// unknown kind or bad points.
#[pyfunction]
#[pyo3(signature = (points, kind, metric=None))]
fn graph<'py>(
    py: Python<'py>,
    points: &Bound<'py, PyAny>,
    kind: &str,
    metric: Option<&str>,
) -> PyResult<Bound<'py, PyArray2<i64>>> {
    let kind = GraphKind::from_name(kind).map_err(to_py_err)?;
    let options = graph_options(metric)?;
    let points = points_arg(py, points, "points")?;
    let (edges, _phases) = py
        .detach(|| {
            let (_, set, _) = point_set(points)?;
            optri::graph_with(&set, kind, &options)
        })
        .map_err(to_py_err)?;
    Ok(index_array(py, &edges)?.into_bound(py))
}

/// The JSON document ``optri graph --kind KIND --json`` prints for
/// ``points``, as a dict (kind, distinct_points, duplicates, timing_ms,
/// edges, coordinates).
#[pyfunction]
fn graph_document<'py>(
    py: Python<'py>,
    points: &Bound<'py, PyAny>,
    kind: &str,
) -> PyResult<Bound<'py, PyAny>> {
    let kind = GraphKind::from_name(kind).map_err(to_py_err)?;
    let points = points_arg(py, points, "points")?;
    let text = py
        .detach(|| {
            let start = Instant::now();
            let (read, set, validate) = point_set(points)?;
            let (edges, phases) = optri::graph(&set, kind)?;
            let mut timing = vec![validate];
            timing.extend(phases);
            timing.push(Phase {
                name: "total",
                ms: ms_since(start),
            });
            let report = GraphReport::of_graph(&set, kind, &edges)
                .with_input(&read)
                .with_timing(&timing);
            serde_json::to_string(&report)
                .map_err(|e| Error::Internal(format!("cannot write the JSON document: {e}")))
        })
        .map_err(to_py_err)?;
    json_text_to_py(py, &text)
}

/// Every criterion of the registry, in display order: a list of dicts with
/// "name", "description", "optimality" (the guarantee on accepted inputs),
/// "options" (the keyword arguments it takes), "polygons" (whether
/// ``triangulate_polygon`` takes it) and "reference" (the paper).
#[pyfunction]
fn criteria(py: Python<'_>) -> PyResult<Bound<'_, PyList>> {
    let list = PyList::empty(py);
    for &criterion in Criterion::ALL {
        let info = criterion.info();
        let entry = PyDict::new(py);
        entry.set_item("name", info.name)?;
        entry.set_item("description", info.description)?;
        entry.set_item("optimality", info.optimality.name())?;
        entry.set_item("options", info.options.to_vec())?;
        entry.set_item("polygons", criterion.supports_polygons())?;
        entry.set_item("reference", info.reference)?;
        list.append(entry)?;
    }
    Ok(list)
}

/// Every proximity graph kind of the registry: a list of dicts with "name"
/// and "description".
#[pyfunction]
fn graph_kinds(py: Python<'_>) -> PyResult<Bound<'_, PyList>> {
    let list = PyList::empty(py);
    for &kind in GraphKind::ALL {
        let entry = PyDict::new(py);
        entry.set_item("name", kind.name())?;
        entry.set_item("description", kind.description())?;
        list.append(entry)?;
    }
    Ok(list)
}

fn input_format(format: Option<&str>) -> PyResult<Option<InputFormat>> {
    format
        .map(InputFormat::from_name)
        .transpose()
        .map_err(to_py_err)
}

/// Reads a point file with the library's readers and returns an (n, 2)
/// float64 array in file order. ``format``: "text", "node", "poly", "tsplib"
/// or "geojson"; by default from the extension, else from the content.
///
/// Raises ValueError naming the file and line of the first problem (e.g.
/// "pts.txt:3: 'x' is not a number") and OSError when the file cannot be
/// read.
#[pyfunction]
#[pyo3(signature = (path, format = None))]
fn read_points<'py>(
    py: Python<'py>,
    path: PathBuf,
    format: Option<&str>,
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let format = input_format(format)?;
    let points = py
        .detach(|| io::read_points_file(&path, format))
        .map_err(|e| file_err(&path, e))?;
    Ok(point_array(py, &points)?.into_bound(py))
}

/// Reads a simple polygon's ring (a Triangle .poly, or a GeoJSON Polygon in
/// a file without points) as an (n, 2) float64 array in boundary order, for
/// ``triangulate_polygon``. Raises as ``read_points``, and ValueError when
/// the file holds points rather than a polygon.
#[pyfunction]
#[pyo3(signature = (path, format = None))]
fn read_polygon<'py>(
    py: Python<'py>,
    path: PathBuf,
    format: Option<&str>,
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let format = input_format(format)?;
    let ring = py
        .detach(|| io::read_polygon_file(&path, format))
        .map_err(|e| file_err(&path, e))?;
    Ok(point_array(py, &ring)?.into_bound(py))
}

/// Exact optimal planar triangulations and proximity graphs.
///
/// ``triangulate(points, criterion)`` returns a ``Triangulation`` (attributes
/// as scipy.spatial.Delaunay: ``points``, ``simplices``; plus ``exact``,
/// ``algorithm``, ``stats``, ``timing_ms``, ``duplicates`` and the whole JSON
/// ``document``); ``graph(points, kind)`` an edge array; ``compare`` every
/// criterion at once; ``criteria()`` and ``graph_kinds()`` list the
/// registry; ``read_points(path)`` reads the library's file formats.
#[pymodule]
#[pyo3(name = "optri")]
fn optri_module(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    m.add("SCHEMA_VERSION", io::SCHEMA_VERSION)?;
    m.add_class::<Triangulation>()?;
    m.add_function(wrap_pyfunction!(triangulate, m)?)?;
    m.add_function(wrap_pyfunction!(triangulate_polygon, m)?)?;
    m.add_function(wrap_pyfunction!(compare, m)?)?;
    m.add_function(wrap_pyfunction!(graph, m)?)?;
    m.add_function(wrap_pyfunction!(graph_document, m)?)?;
    m.add_function(wrap_pyfunction!(criteria, m)?)?;
    m.add_function(wrap_pyfunction!(graph_kinds, m)?)?;
    m.add_function(wrap_pyfunction!(read_points, m)?)?;
    m.add_function(wrap_pyfunction!(read_polygon, m)?)?;
    Ok(())
}
