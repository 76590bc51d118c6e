//! Python bindings of optri: the extension module `optri`, built by maturin
//! as an abi3 wheel (`pip install ./crates/optri-py`).
//!
//! The module is a thin front end over the library's registry
//! ([`optri::Criterion::ALL`], [`optri::GraphKind::ALL`], their `info()`
//! and `from_name`) and its one result schema ([`optri::io::TriangulationReport`]): a
//! criterion that lands in the registry is callable from Python without a
//! change here, and every result attribute is a field of the document
//! `optri triangulate --json` prints. Conventions follow `scipy.spatial`:
//! `(n, 2)` float arrays in; `simplices`, `neighbors`, `vertex_to_simplex`,
//! `convex_hull` and `find_simplex` as scipy's `Delaunay` gives them (int32),
//! the other index arrays (`edges`, `duplicates`, `graph`) int64.
//!
//! Errors: the library's message, as `ValueError` for bad input and
//! arguments, `OSError` for files, `RuntimeError` for a bug. Nothing here
//! panics on input; a panic inside the library would surface as pyo3's
//! `PanicException`, never an abort. The GIL is released while the library
//! works (`Python::detach`), so other Python threads run meanwhile.

mod adjacency;
mod convert;
mod location;
mod triangulation;

use convert::{
    file_err, index_array, json_text_to_py, point_array, points_arg, points_with_elevations_arg,
    to_py_err,
};
use numpy::PyArray2;
use optri::io::{self, Input, InputFormat, ReadInput, ReadOptions, Source, Threshold};
use optri::request::{Outcome, Request, Results, Task};
use optri::{Cancel, Error, Options, Phase};
use pyo3::exceptions::{PyMemoryError, PyRuntimeError, PyTypeError};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::path::PathBuf;
use std::sync::Arc;
use triangulation::Triangulation;

/// A request for `task` on `input` with the keyword arguments as options
/// by name: each checked against what the task reads (the registry's
/// declarations), its value a string or a number. The input is read at the
/// decimals Python shows ([`ReadInput::from_doubles`]) when the request
/// runs, on its own thread.
fn request(task: Task, input: Input, kwargs: Option<&Bound<'_, PyDict>>) -> PyResult<Pending> {
    let mut options = Options::default();
    if let Some(kwargs) = kwargs {
        for (key, value) in kwargs.iter() {
            let key: String = key.extract()?;
            let text = if let Ok(text) = value.extract::<String>() {
                text
            } else if value.is_instance_of::<pyo3::types::PyBool>() {
                return Err(PyTypeError::new_err(format!(
                    "option {key} takes a string or a number, not a bool"
                )));
            } else if let Ok(number) = value.extract::<f64>() {
                number.to_string()
            } else {
                return Err(PyTypeError::new_err(format!(
                    "option {key} takes a string or a number, not {}",
                    value.get_type().name()?
                )));
            };
            task.set_option(&mut options, &key, &text)
                .map_err(to_py_err)?;
        }
    }
    Ok(Pending {
        task,
        input,
        elevations: None,
        options,
    })
}

/// A request before its input is read: [`run`] builds and runs it.
struct Pending {
    task: Task,
    input: Input,
    /// One per point of `input`, checked when the request runs.
    elevations: Option<Vec<f64>>,
    options: Options,
}

impl Pending {
    /// This request with `elevations`, if any.
    fn with_elevations(self, elevations: Option<Vec<f64>>) -> Self {
        Self { elevations, ..self }
    }
}

/// How often a waiting call looks for Ctrl-C (and other signals).
const SIGNAL_POLL: std::time::Duration = std::time::Duration::from_millis(50);

/// Bytes of working memory reserved per point before a run, so that a
/// request far beyond this machine's memory fails with `MemoryError` up
/// front instead of aborting the interpreter inside the library (a
/// Delaunay triangulation alone keeps about 100 bytes per point).
const WORKING_BYTES_PER_POINT: usize = 256;

/// Runs `request` on a thread of its own, without the GIL, and waits for it
/// while looking for signals: Ctrl-C raises the request's cancellation flag
/// and `KeyboardInterrupt` at once (the run stops at its next check and its
/// thread ends by itself).
fn run(py: Python<'_>, pending: Pending) -> PyResult<Outcome> {
    let points = pending.input.points().len();
    let mut probe: Vec<u8> = Vec::new();
    probe
        .try_reserve_exact(points.saturating_mul(WORKING_BYTES_PER_POINT))
        .map_err(|_| {
            PyMemoryError::new_err(format!(
                "{points} points need about {} MB of working memory, which this process cannot get",
                points.saturating_mul(WORKING_BYTES_PER_POINT) >> 20
            ))
        })?;
    drop(probe);
    let cancel = Cancel::new();
    let Pending {
        task,
        input,
        elevations,
        options,
    } = pending;
    let options = options.with_cancel(cancel.clone());
    let (send, receive) = std::sync::mpsc::sync_channel(1);
    std::thread::Builder::new()
        .name("optri".to_string())
        .spawn(move || {
            let mut read = ReadInput::from_doubles(input);
            if let Some(z) = elevations {
                read = read.with_elevations(z);
            }
            let request = Request::new(read, task).with_options(options);
            let outcome = request.run().map(|mut outcome| {
                outcome.finish();
                outcome
            });
            // The caller may have gone (Ctrl-C): nobody to tell then.
            let _ = send.send(outcome);
        })
        .map_err(|e| PyRuntimeError::new_err(format!("cannot start the run's thread: {e}")))?;
    let receive = std::sync::Mutex::new(receive);
    loop {
        let waited = py.detach(|| match receive.lock() {
            Ok(receive) => receive.recv_timeout(SIGNAL_POLL),
            Err(_) => Err(std::sync::mpsc::RecvTimeoutError::Disconnected),
        });
        match waited {
            Ok(outcome) => return outcome.map_err(to_py_err),
            Err(std::sync::mpsc::RecvTimeoutError::Timeout) => {
                if let Err(interrupt) = py.check_signals() {
                    cancel.cancel();
                    return Err(interrupt);
                }
            }
            Err(std::sync::mpsc::RecvTimeoutError::Disconnected) => {
                return Err(PyRuntimeError::new_err(
                    "internal error: the run ended without a result (a bug in optri; please \
                     report it with the input)",
                ))
            }
        }
    }
}

/// The `Triangulation` of a triangulate request's outcome.
fn triangulation_of(py: Python<'_>, outcome: Outcome) -> PyResult<Triangulation> {
    let (read, phases, results) = outcome.into_parts();
    match results {
        Results::Triangulation(solution) => {
            Triangulation::new(py, *solution, Arc::new(read), phases)
        }
        _ => Err(PyRuntimeError::new_err(
            "internal error: not a triangulation",
        )),
    }
}

/// Triangulates the convex hull of ``points`` by ``criterion``.
///
/// ``points``: an (n, 2) array-like of floats (duplicates are merged and
/// reported in ``duplicates``), or (n, 3) whose third column is each
/// point's elevation; ``elevations=`` (one float per point) gives them
/// with an (n, 2) array instead. Elevations are kept in the result
/// (``elevations``) for the criteria that read them; the others ignore
/// them. Each float is taken at the decimal its repr
/// shows when every coordinate's repr has at most 15 significant digits
/// (``coordinate_arithmetic`` is then "decimal-exact": 0.1, 0.2, 0.3 are
/// collinear as written); otherwise at its binary value ("binary64").
/// ``criterion``: a name from ``criteria()``, case-insensitive. Keyword
/// arguments are options by name (``registry()["options"]``): those the
/// criterion lists (``criteria()[i]["options"]``, e.g. ``metric="l1"`` for
/// minmax-length) and the run controls every criterion takes
/// (``time_limit=`` seconds). Returns a ``Triangulation``.
///
/// Raises ValueError with the library's message for NaN or infinite
/// coordinates or elevations, elevations that are not one per point or
/// differ between duplicates, a wrong shape, fewer than 3 distinct points, all points
/// collinear, an unknown criterion or option, or an input the criterion
/// does not support; TypeError for an option value that is neither a string
/// nor a number; TimeoutError for a run stopped by its time limit;
/// KeyboardInterrupt on Ctrl-C (the run is cancelled).
#[pyfunction]
#[pyo3(signature = (points, criterion = "delaunay", *, elevations = None, **options))]
fn triangulate(
    py: Python<'_>,
    points: &Bound<'_, PyAny>,
    criterion: &str,
    elevations: Option<&Bound<'_, PyAny>>,
    options: Option<&Bound<'_, PyDict>>,
) -> PyResult<Triangulation> {
    let task = Task::triangulate(criterion).map_err(to_py_err)?;
    let (points, z) = points_with_elevations_arg(py, points, elevations, "points")?;
    let request = request(task, Input::Points(points), options)?.with_elevations(z);
    triangulation_of(py, run(py, request)?)
}

/// Triangulates the interior of the simple polygon ``vertices`` (an (n, 2)
/// array-like ring in boundary order, either orientation, the closing
/// vertex not repeated; or (n, 3) with elevations, or ``elevations=`` as
/// for ``triangulate``) by ``criterion``. Indices in the result are ring
/// positions and ``domain`` is "polygon".
///
/// Raises ValueError for a ring that is not a simple polygon (naming the
/// edges that meet or the repeated vertex), a criterion that takes no
/// polygons, or the other input errors of ``triangulate``.
#[pyfunction]
#[pyo3(signature = (vertices, criterion = "delaunay", *, elevations = None, **options))]
fn triangulate_polygon(
    py: Python<'_>,
    vertices: &Bound<'_, PyAny>,
    criterion: &str,
    elevations: Option<&Bound<'_, PyAny>>,
    options: Option<&Bound<'_, PyDict>>,
) -> PyResult<Triangulation> {
    let task = Task::triangulate(criterion).map_err(to_py_err)?;
    let (ring, z) = points_with_elevations_arg(py, vertices, elevations, "vertices")?;
    let request = request(task, Input::Polygon(ring), options)?.with_elevations(z);
    triangulation_of(py, run(py, request)?)
}

/// Triangulates ``points`` by several criteria: a dict from criterion name
/// to its result, in the order asked (``criteria=None``: every criterion of
/// the registry, in registry order). A criterion that refuses the input is
/// reported, not dropped: its value is the ``ValueError`` it would raise
/// (not raised), e.g. min-weight's refusal of a metric. Keyword arguments
/// are options, as for ``triangulate`` (those any of the criteria reads);
/// ``points`` and ``elevations=`` are as for ``triangulate``.
#[pyfunction]
#[pyo3(signature = (points, criteria = None, *, elevations = None, **options))]
fn compare(
    py: Python<'_>,
    points: &Bound<'_, PyAny>,
    criteria: Option<Vec<String>>,
    elevations: Option<&Bound<'_, PyAny>>,
    options: Option<&Bound<'_, PyDict>>,
) -> PyResult<Py<PyDict>> {
    let task = Task::compare(&criteria.unwrap_or_default()).map_err(to_py_err)?;
    let (points, z) = points_with_elevations_arg(py, points, elevations, "points")?;
    let request = request(task, Input::Points(points), options)?.with_elevations(z);
    let (read, phases, results) = run(py, request)?.into_parts();
    let Results::Comparison(results) = results else {
        return Err(PyRuntimeError::new_err("internal error: not a comparison"));
    };
    let read = Arc::new(read);
    let validate: Vec<Phase> = phases
        .iter()
        .filter(|p| p.name == "validate")
        .cloned()
        .collect();
    let dict = PyDict::new(py);
    for (criterion, result) in results {
        match result {
            Ok(solution) => {
                // Each result is timed as `triangulate` times it: the
                // validation, its own phases, and their total.
                let mut own = validate.clone();
                own.extend(solution.phases.iter().cloned());
                let total = own.iter().map(|p| p.ms).sum();
                own.push(Phase {
                    name: "total",
                    ms: total,
                });
                let t = Triangulation::new(py, solution, Arc::clone(&read), own)?;
                dict.set_item(criterion.name(), Py::new(py, t)?)?;
            }
            Err(e) => dict.set_item(criterion.name(), to_py_err(e).into_value(py))?,
        }
    }
    Ok(dict.unbind())
}

/// The edges of the proximity graph ``kind`` of ``points`` as a (k, 2) int64
/// array of input indices: ``[min, max]`` pairs, sorted, except "hull",
/// whose edges ``[a, b]`` go counter-clockwise. Kinds: ``graph_kinds()``
/// ("hull", "delaunay", "rng", "gabriel", "mst"). Two distinct points and
/// points all on one line are accepted, as by the CLI (the graph is then
/// the path through them). Keyword arguments are options (``metric`` for
/// "rng" and "mst"). Raises ValueError for an unknown kind or bad points.
#[pyfunction]
#[pyo3(signature = (points, kind, **options))]
fn graph<'py>(
    py: Python<'py>,
    points: &Bound<'py, PyAny>,
    kind: &str,
    options: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyArray2<i64>>> {
    let task = Task::graph(kind).map_err(to_py_err)?;
    let points = points_arg(py, points, "points")?;
    let outcome = run(py, request(task, Input::Points(points), options)?)?;
    let (_, graph) = outcome
        .graph()
        .ok_or_else(|| PyRuntimeError::new_err("internal error: not a graph"))?;
    Ok(index_array(py, &graph.edges)?.into_bound(py))
}

/// The JSON document ``optri graph --kind KIND --json`` prints for
/// ``points``, as a dict (kind, distinct_points, duplicates, timing_ms,
/// edges, coordinates). Keyword arguments as for ``graph``.
#[pyfunction]
#[pyo3(signature = (points, kind, **options))]
fn graph_document<'py>(
    py: Python<'py>,
    points: &Bound<'py, PyAny>,
    kind: &str,
    options: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyAny>> {
    let task = Task::graph(kind).map_err(to_py_err)?;
    let points = points_arg(py, points, "points")?;
    let outcome = run(py, request(task, Input::Points(points), options)?)?;
    let text = serde_json::to_string(&outcome.document())
        .map_err(|e| PyRuntimeError::new_err(format!("cannot write the JSON document: {e}")))?;
    json_text_to_py(py, &text)
}

/// Decides exactly whether some triangulation of ``points`` (their convex
/// hull; with ``polygon=True``, the interior of the simple polygon whose
/// ring they are) has every triangle's area at least ``at_least``
/// (criterion "maxmin-area") or at most ``at_most`` ("minmax-area"). Areas
/// are triangle areas (not doubled) in the input's units, as the
/// ``min_area`` / ``max_area`` of ``stats``. A threshold is a number or a
/// decimal string, taken exactly as the decimal it prints as (``0.1`` is
/// one tenth). Returns the decision document as a dict: "answer" (True,
/// False, or None when a general point set's approximation cannot settle
/// it), "method", "exact", "witness" (a triangulation document, when the
/// answer is True), "threshold", "threshold_decimal", "timing_ms".
/// Keyword arguments are options (``time_limit``).
///
/// Raises ValueError for another criterion, both or neither bound, the
/// bound the criterion does not take, a negative, NaN or infinite
/// threshold, and the input errors of ``triangulate``.
#[pyfunction]
#[pyo3(signature = (points, criterion, *, at_least = None, at_most = None, polygon = false, **options))]
fn decide<'py>(
    py: Python<'py>,
    points: &Bound<'py, PyAny>,
    criterion: &str,
    at_least: Option<&Bound<'py, PyAny>>,
    at_most: Option<&Bound<'py, PyAny>>,
    polygon: bool,
    options: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyAny>> {
    let at_least = threshold_arg(at_least, "at_least")?;
    let at_most = threshold_arg(at_most, "at_most")?;
    let task = Task::decide(criterion, at_least, at_most).map_err(to_py_err)?;
    let input = if polygon {
        Input::Polygon(points_arg(py, points, "vertices")?)
    } else {
        Input::Points(points_arg(py, points, "points")?)
    };
    let outcome = run(py, request(task, input, options)?)?;
    let text = serde_json::to_string(&outcome.document())
        .map_err(|e| PyRuntimeError::new_err(format!("cannot write the JSON document: {e}")))?;
    json_text_to_py(py, &text)
}

/// A threshold argument: a decimal string, or a number read as the
/// decimal it prints as.
fn threshold_arg(
    value: Option<&Bound<'_, PyAny>>,
    option: &'static str,
) -> PyResult<Option<Threshold>> {
    let Some(value) = value.filter(|v| !v.is_none()) else {
        return Ok(None);
    };
    let threshold = if let Ok(text) = value.extract::<String>() {
        Threshold::parse(option, &text)
    } else if value.is_instance_of::<pyo3::types::PyBool>() {
        return Err(PyTypeError::new_err(format!(
            "{option} takes a number or a decimal string, not a bool"
        )));
    } else if value.is_instance_of::<pyo3::types::PyInt>() {
        Threshold::parse(option, &value.str()?.to_string())
    } else if let Ok(number) = value.extract::<f64>() {
        Threshold::from_f64(option, number)
    } else {
        return Err(PyTypeError::new_err(format!(
            "{option} takes a number or a decimal string, not {}",
            value.get_type().name()?
        )));
    };
    threshold.map(Some).map_err(to_py_err)
}

/// The registry listing: the document ``optri criteria --json`` prints and
/// the web API's ``GET /api/criteria`` returns, as a dict: "criteria"
/// (name, description, optimality, inputs, options, reference), "graphs",
/// "options" (name, description, values, default), "input_formats" and
/// "measures" (the ``stats`` keys, with which direction is better).
#[pyfunction]
fn registry<'py>(py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
    json_text_to_py(py, &io::registry_listing().to_string())
}

/// Every criterion of the registry, in display order: the listing's
/// "criteria" (see ``registry()``): dicts with "name", "description",
/// "optimality", "inputs" ("points", "polygon"), "options" (the keyword
/// arguments it takes) and "reference" (the paper).
#[pyfunction]
fn criteria<'py>(py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
    registry(py)?.get_item("criteria")
}

/// Every proximity graph kind of the registry: the listing's "graphs"
/// (dicts with "name", "description" and "options").
#[pyfunction]
fn graph_kinds<'py>(py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
    registry(py)?.get_item("graphs")
}

fn input_format(format: Option<&str>) -> PyResult<Option<InputFormat>> {
    format
        .map(InputFormat::from_name)
        .transpose()
        .map_err(to_py_err)
}

/// Reads a point file with the library's readers and returns an (n, 2)
/// float64 array in file order. ``format``: "text", "node", "poly", "tsplib",
/// "geojson", "ply" or "obj"; by default from the extension, else from the
/// content.
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
    let options = ReadOptions::default().with_format(input_format(format)?);
    let read = py
        .detach(|| io::read(Source::Path(&path), &options))
        .map_err(|e| file_err(&path, e))?;
    Ok(point_array(py, read.input.points())?.into_bound(py))
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
    let options = ReadOptions::default()
        .with_format(input_format(format)?)
        .with_polygons(true);
    let read = py
        .detach(|| io::read(Source::Path(&path), &options))
        .map_err(|e| file_err(&path, e))?;
    let Input::Polygon(ring) = &read.input else {
        let format = read.format.map_or("", InputFormat::name);
        let message = format!(
            "the {format} input holds points, not a polygon (polygons are read from a GeoJSON \
             Polygon or a Triangle .poly)"
        );
        return Err(file_err(&path, Error::Parse { line: 0, message }));
    };
    Ok(point_array(py, ring)?.into_bound(py))
}

/// Exact optimal planar triangulations and proximity graphs.
///
/// ``triangulate(points, criterion)`` returns a ``Triangulation`` (attributes
/// as scipy.spatial.Delaunay: ``points``, ``simplices``, ``neighbors``,
/// ``vertex_to_simplex``, ``convex_hull``, ``find_simplex``; plus ``exact``,
/// ``algorithm``, ``stats``, ``timing_ms``, ``duplicates`` and the whole JSON
/// ``document``); ``graph(points, kind)`` an edge array; ``compare`` every
/// criterion at once; ``decide(points, criterion, at_least=...)`` the area
/// decision problems; ``registry()`` is the registry listing (the JSON of
/// ``optri criteria --json``), ``criteria()`` and ``graph_kinds()`` its parts; ``read_points(path)`` reads the library's file formats.
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
    m.add_function(wrap_pyfunction!(decide, m)?)?;
    m.add_function(wrap_pyfunction!(registry, m)?)?;
    m.add_function(wrap_pyfunction!(criteria, m)?)?;
    m.add_function(wrap_pyfunction!(graph_kinds, m)?)?;
    m.add_function(wrap_pyfunction!(read_points, m)?)?;
    m.add_function(wrap_pyfunction!(read_polygon, m)?)?;
    Ok(())
}
