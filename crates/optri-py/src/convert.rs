//! What crosses the boundary: point arrays in, index arrays and JSON texts
//! out, and `optri::Error` as the Python exception that fits it.

use numpy::{PyArray1, PyArray2, PyArrayMethods, PyUntypedArrayMethods};
use optri::Error;
use pyo3::exceptions::{PyOSError, PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// The Python exception for a library error, with the library's message:
/// `OSError` for files that cannot be read or written, `RuntimeError` for
/// [`Error::Internal`] (a bug in optri), `ValueError` for everything the
/// caller's input or arguments got wrong.
pub(crate) fn to_py_err(e: Error) -> PyErr {
    match e {
        Error::Io(message) => PyOSError::new_err(message),
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

/// `what` as an `(n, 2)` float array, through `numpy.asarray` (so lists,
/// tuples, integer arrays and any array-like work), copied into the rows the
/// library takes. Values are not checked here: `PointSet::new` rejects NaN
/// and out-of-range coordinates naming the point.
pub(crate) fn points_arg(
    py: Python<'_>,
    points: &Bound<'_, PyAny>,
    what: &str,
) -> PyResult<Vec<[f64; 2]>> {
    let numpy = py.import("numpy")?;
    let kwargs = PyDict::new(py);
    kwargs.set_item("dtype", numpy.getattr("float64")?)?;
    let array = numpy
        .call_method("asarray", (points,), Some(&kwargs))
        .map_err(|e| {
            PyValueError::new_err(format!(
                "{what} must be an (n, 2) array-like of numbers: {}",
                e.value(py)
            ))
        })?;
    let array = array.cast_into::<numpy::PyArrayDyn<f64>>().map_err(|_| {
        PyValueError::new_err(format!("{what}: numpy.asarray did not give a float array"))
    })?;
    let shape = array.shape().to_vec();
    if shape.len() != 2 || shape[1] != 2 {
        let shape: Vec<String> = shape.iter().map(ToString::to_string).collect();
        return Err(PyValueError::new_err(format!(
            "{what} must have shape (n, 2), got ({}{})",
            shape.join(", "),
            if shape.len() == 1 { "," } else { "" }
        )));
    }
    let readonly = array.readonly();
    let view = readonly.as_array();
    Ok(view
        .rows()
        .into_iter()
        .map(|row| [row[0], row[1]])
        .collect())
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
