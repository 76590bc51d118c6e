//! What crosses the boundary: point arrays in, index arrays and JSON texts
//! out, and `optri::Error` as the Python exception that fits it.

use numpy::{PyArray1, PyArray2, PyArrayMethods, PyUntypedArrayMethods};
use optri::{Error, Interruption};
use pyo3::exceptions::{
    PyMemoryError, PyOSError, PyOverflowError, PyRuntimeError, PyTimeoutError, PyTypeError,
    PyValueError,
};
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// The Python exception for a library error, with the library's message:
/// `OSError` for files that cannot be read or written, `TimeoutError` for a
/// run stopped by its `time_limit`, `RuntimeError` for
/// [`Error::Internal`] (a bug in optri), `ValueError` for everything the
/// caller's input or arguments got wrong.
pub(crate) fn to_py_err(e: Error) -> PyErr {
    match e {
        Error::Io(message) => PyOSError::new_err(message),
        Error::Interrupted(Interruption::TimeLimit { .. }) => {
            PyTimeoutError::new_err(e.to_string())
        }
        Error::Internal(_) => PyRuntimeError::new_err(e.to_string()),
        other => PyValueError::new_err(other.to_string()),
    }
}

/// An input error of the file `path`, named as the CLI names it:
/// `PATH:LINE: message` for a parse error.
pub(crate) fn file_err(path: &std::path::Path, e: Error) -> PyErr {
    let source = path.display();
    match e {
        Error::Parse { line, message } if line > 0 => {
            PyValueError::new_err(format!("{source}:{line}: {message}"))
        }
        Error::Parse { message, .. } => PyValueError::new_err(format!("{source}: {message}")),
        // I/O messages already name the path.
        other => to_py_err(other),
    }
}

/// `what` as `(n, 2)` doubles, through `numpy.asarray` (so lists, tuples,
/// integer arrays and any array-like work), copied into the rows the library
/// takes. Nothing is changed silently: complex values and masked entries are
/// refused (`TypeError`), and so is a value that no double represents
/// exactly (an integer beyond 2⁵³, a `longdouble`, a `Fraction` like 1/3:
/// `ValueError` naming the point), since rounding it could merge distinct
/// points or move one across a line. NaN and out-of-range values pass here:
/// `PointSet::new` rejects them naming the point.
pub(crate) fn points_arg(
    py: Python<'_>,
    points: &Bound<'_, PyAny>,
    what: &str,
) -> PyResult<Vec<[f64; 2]>> {
    let (values, _) = float_rows(py, points, what, &[2])?;
    Ok(values.chunks_exact(2).map(|r| [r[0], r[1]]).collect())
}

/// Points and, when given, one elevation per point.
pub(crate) type PointsWithElevations = (Vec<[f64; 2]>, Option<Vec<f64>>);

/// `what` as points with their elevations: an `(n, 2)` array-like as
/// [`points_arg`] takes, with `elevations` (one per point) or without, or an
/// `(n, 3)` one whose third column is the elevation (then `elevations` must
/// be `None`). Elevations are checked as coordinates are (exact doubles
/// here; finite, in range and equal on duplicates when the request runs).
pub(crate) fn points_with_elevations_arg(
    py: Python<'_>,
    points: &Bound<'_, PyAny>,
    elevations: Option<&Bound<'_, PyAny>>,
    what: &str,
) -> PyResult<PointsWithElevations> {
    let (values, width) = float_rows(py, points, what, &[2, 3])?;
    let xy = values.chunks_exact(width).map(|r| [r[0], r[1]]).collect();
    let z = match (width, elevations) {
        (3, Some(_)) => {
            return Err(PyValueError::new_err(format!(
                "{what} has a third column (the elevations) and elevations= is given too; \
                 pass one of them"
            )))
        }
        (3, None) => Some(values.chunks_exact(3).map(|r| r[2]).collect()),
        (_, Some(z)) => {
            let column = py
                .import("numpy")?
                .call_method1("reshape", (z, (-1, 1)))
                .map_err(|e| {
                    PyValueError::new_err(format!(
                        "elevations must be a sequence of numbers: {}",
                        e.value(py)
                    ))
                })?;
            Some(float_rows(py, &column, "elevations", &[1])?.0)
        }
        (_, None) => None,
    };
    Ok((xy, z))
}

/// `given` as rows of one of the `widths` (the first given names the
/// expected shape), through `numpy.asarray`, checked as [`points_arg`]
/// describes: the values row by row, and the width found.
fn float_rows(
    py: Python<'_>,
    given: &Bound<'_, PyAny>,
    what: &str,
    widths: &[usize],
) -> PyResult<(Vec<f64>, usize)> {
    let shapes: Vec<String> = widths.iter().map(|w| format!("(n, {w})")).collect();
    let shapes = shapes.join(" or ");
    let numpy = py.import("numpy")?;
    let ma = numpy.getattr("ma")?;
    if ma.call_method1("isMaskedArray", (given,))?.is_truthy()?
        && ma
            .call_method1("getmaskarray", (given,))?
            .call_method0("any")?
            .is_truthy()?
    {
        return Err(PyTypeError::new_err(format!(
            "{what} is a masked array with masked entries; pass the points to use \
             (e.g. points[~points.mask.any(axis=1)].data)"
        )));
    }
    let not_numbers = |e: PyErr| {
        if e.is_instance_of::<PyMemoryError>(py) {
            return e;
        }
        PyValueError::new_err(format!(
            "{what} must be an {shapes} array-like of numbers: {}",
            e.value(py)
        ))
    };
    let given = numpy
        .call_method1("asarray", (given,))
        .map_err(not_numbers)?;
    let dtype = given.getattr("dtype")?;
    let kind: String = dtype.getattr("kind")?.extract()?;
    if kind == "c" {
        return Err(PyTypeError::new_err(format!(
            "{what} must be real numbers, got {} values",
            dtype.str()?
        )));
    }
    let no_copy = PyDict::new(py);
    no_copy.set_item("copy", false)?;
    let array = given
        .call_method("astype", (numpy.getattr("float64")?,), Some(&no_copy))
        .map_err(not_numbers)?;
    let array = array.cast_into::<numpy::PyArrayDyn<f64>>().map_err(|_| {
        PyValueError::new_err(format!("{what}: numpy.asarray did not give a float array"))
    })?;
    let shape = array.shape().to_vec();
    if shape.len() != 2 || !widths.contains(&shape[1]) {
        let shape: Vec<String> = shape.iter().map(ToString::to_string).collect();
        return Err(PyValueError::new_err(format!(
            "{what} must have shape {shapes}, got ({}{})",
            shape.join(", "),
            if shape.len() == 1 { "," } else { "" }
        )));
    }
    if dtype.ne(numpy.getattr("float64")?)? {
        check_exact(py, &numpy, &given, array.as_any())?;
    }
    let readonly = array.readonly();
    let view = readonly.as_array();
    let (n, width) = (shape[0], shape[1]);
    let mut values = Vec::new();
    values
        .try_reserve_exact(n.saturating_mul(width))
        .map_err(|_| {
            PyMemoryError::new_err(format!(
                "cannot hold {n} points ({} bytes)",
                n.saturating_mul(8 * width)
            ))
        })?;
    values.extend(view.iter().copied());
    Ok((values, width))
}

/// Refuses the first value of `given` that its double in `doubles` does not
/// equal exactly (compared in `given`'s own type: integers exactly, Python
/// objects by Python's exact mixed comparisons). Non-finite doubles are
/// left to `PointSet::new`.
fn check_exact(
    py: Python<'_>,
    numpy: &Bound<'_, PyModule>,
    given: &Bound<'_, PyAny>,
    doubles: &Bound<'_, PyAny>,
) -> PyResult<()> {
    // Casting an out-of-range double back to an integer type warns; the
    // comparison then fails, which is the answer.
    let quiet = PyDict::new(py);
    quiet.set_item("all", "ignore")?;
    let errstate = numpy.call_method("errstate", (), Some(&quiet))?;
    errstate.call_method0("__enter__")?;
    let warnings = py.import("warnings")?;
    let catcher = warnings.call_method0("catch_warnings")?;
    catcher.call_method0("__enter__")?;
    warnings.call_method1("simplefilter", ("ignore",))?;
    let back = doubles.call_method1("astype", (given.getattr("dtype")?,));
    let differs = back.and_then(|back| {
        let unequal = back.call_method1("__ne__", (given,))?;
        let finite = numpy.call_method1("isfinite", (doubles,))?;
        numpy.call_method1("logical_and", (unequal, finite))
    });
    catcher.call_method1("__exit__", (py.None(), py.None(), py.None()))?;
    errstate.call_method1("__exit__", (py.None(), py.None(), py.None()))?;
    let differs = differs?;
    let found = numpy.call_method1("argwhere", (differs,))?;
    if found.len()? == 0 {
        return Ok(());
    }
    let first = found.get_item(0)?;
    let (i, j): (usize, usize) = (first.get_item(0)?.extract()?, first.get_item(1)?.extract()?);
    let value = given.get_item((i, j))?;
    let double: f64 = doubles.get_item((i, j))?.extract()?;
    Err(PyValueError::new_err(format!(
        "point {i} has coordinate {} that no double represents exactly (the nearest is {double:?}); \
         optri computes exactly with doubles, so rounding it would change the input: scale or \
         shift the points so that every coordinate is a double (integers up to 2**53)",
        value.str()?
    )))
}

/// A read-only `(len, K)` int64 array of index tuples: read-only because a
/// result object hands out the same array on every access.
pub(crate) fn index_array<const K: usize>(
    py: Python<'_>,
    rows: &[[u32; K]],
) -> PyResult<Py<PyArray2<i64>>> {
    let flat: Vec<i64> = rows.iter().flatten().map(|&i| i64::from(i)).collect();
    let array = PyArray1::from_vec(py, flat).reshape([rows.len(), K])?;
    array.getattr("flags")?.setattr("writeable", false)?;
    Ok(array.unbind())
}

/// `values` as int32, scipy's dtype for `simplices`, `neighbors` and the
/// other index arrays of `scipy.spatial.Delaunay`: `OverflowError` for an
/// index beyond 2³¹ − 1 (more points or triangles than int32 can number).
pub(crate) fn int32_values(values: impl IntoIterator<Item = i64>) -> PyResult<Vec<i32>> {
    values
        .into_iter()
        .map(|v| {
            i32::try_from(v).map_err(|_| {
                PyOverflowError::new_err(format!(
                    "index {v} does not fit the int32 index arrays (scipy's convention)"
                ))
            })
        })
        .collect()
}

/// A read-only `(len, K)` int32 array of index tuples, as [`int32_values`].
pub(crate) fn int32_array<const K: usize, T: Copy + Into<i64>>(
    py: Python<'_>,
    rows: &[[T; K]],
) -> PyResult<Py<PyArray2<i32>>> {
    let flat = int32_values(rows.iter().flatten().map(|&i| i.into()))?;
    let array = PyArray1::from_vec(py, flat).reshape([rows.len(), K])?;
    array.getattr("flags")?.setattr("writeable", false)?;
    Ok(array.unbind())
}

/// A read-only `(n,)` float64 array (e.g. elevations).
pub(crate) fn value_array(py: Python<'_>, values: &[f64]) -> PyResult<Py<PyArray1<f64>>> {
    let array = PyArray1::from_slice(py, values);
    array.getattr("flags")?.setattr("writeable", false)?;
    Ok(array.unbind())
}

/// A read-only `(n, 2)` float64 array of points.
pub(crate) fn point_array(py: Python<'_>, points: &[[f64; 2]]) -> PyResult<Py<PyArray2<f64>>> {
    let flat: Vec<f64> = points.iter().flatten().copied().collect();
    let array = PyArray1::from_vec(py, flat).reshape([points.len(), 2])?;
    array.getattr("flags")?.setattr("writeable", false)?;
    Ok(array.unbind())
}

/// A JSON text as a Python object, parsed by the standard `json` module, so
/// that the keys keep the order in which the library wrote them.
pub(crate) fn json_text_to_py<'py>(py: Python<'py>, text: &str) -> PyResult<Bound<'py, PyAny>> {
    py.import("json")?.call_method1("loads", (text,))
}
