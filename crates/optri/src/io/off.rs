//! OFF, the Object File Format of Geomview (Phillips, Levy and Munzner
//! 1993, "Geomview: An Interactive Geometry Viewer", Notices of the AMS;
//! the format as in Geomview's manual, section "OFF Files"): the writer of
//! triangulations. OFF holds vertices and polygonal faces only, so a
//! graph's edges are refused before writing
//! ([`OutputFormat::from_path_for_graph`]).
//!
//! [`OutputFormat::from_path_for_graph`]: super::OutputFormat::from_path_for_graph

use super::{Cells, Mesh, Shortest};
use std::io::Write;

/// Writes the triangles of `mesh` as OFF: `OFF`, `n m 0`, the vertices
/// `x y z`, then the faces `3 a b c` (0-based, counter-clockwise). No
/// comment line: some OFF readers take none.
///
/// # Errors
/// Those of `out`, and [`std::io::ErrorKind::InvalidInput`] for a graph.
pub(super) fn write(out: &mut impl Write, mesh: &Mesh) -> std::io::Result<()> {
    let Cells::Triangles(triangles) = mesh.cells else {
        return Err(std::io::Error::new(
            std::io::ErrorKind::InvalidInput,
            "OFF holds faces, not a graph's edges",
        ));
    };
    writeln!(out, "OFF\n{} {} 0", mesh.points.len(), triangles.len())?;
    for [x, y, z] in mesh.vertices() {
        writeln!(out, "{} {} {}", Shortest(x), Shortest(y), Shortest(z))?;
    }
    for [a, b, c] in triangles {
        writeln!(out, "3 {a} {b} {c}")?;
    }
    Ok(())
}
