//! Wavefront `.obj` (Wavefront Technologies, "Object Files (.obj)",
//! Advanced Visualizer manual, appendix B1: the `v`, `f` and `l`
//! statements): the reader of its vertices as points ([`InputFormat::Obj`])
//! and the writer of triangulations (`f`) and graphs (`l`).
//!
//! The reader takes each `v x y [z [w]]` statement as a point, `z` as its
//! elevation ([`ReadInput::elevations`]): every vertex has one or none,
//! like the rows of a text file. Other statements (`vt`, `vn`, `f`, `l`,
//! groups, materials) are skipped; the faces and lines are counted in a
//! warning, since the input is read as points. Values after `z` (the
//! weight `w`, or the colour some tools append) are checked to be numbers
//! and ignored. `#` starts a comment. OBJ has no magic line, so it is read
//! by its extension or name only.
//!
//! The writer numbers vertices from 1, as the format does.
//!
//! [`ReadInput::elevations`]: super::ReadInput::elevations
//! [`InputFormat::Obj`]: super::InputFormat::Obj

use super::{not_a_number, parse, strip_comment, Cells, Collected, Mesh, Shortest};
use crate::error::Result;
use std::io::Write;

/// Reads the `v` statements of the OBJ `text` as points.
pub(super) fn read_obj(text: &str) -> Result<Collected> {
    let mut points = Collected::default();
    // Whether the vertices have `z`, and the line of the first vertex.
    let mut first: Option<(bool, usize)> = None;
    let (mut faces, mut lines) = (0usize, 0usize);
    for (i, raw) in text.lines().enumerate() {
        let line = i + 1;
        let mut tokens = strip_comment(raw).split_whitespace();
        match tokens.next() {
            Some("v") => {}
            Some("f") => {
                faces += 1;
                continue;
            }
            Some("l") => {
                lines += 1;
                continue;
            }
            _ => continue,
        }
        let values: Vec<&str> = tokens.collect();
        if values.len() < 2 {
            return Err(parse(
                line,
                format!(
                    "a vertex needs 'v x y [z]', found {} value{}",
                    values.len(),
                    if values.len() == 1 { "" } else { "s" }
                ),
            ));
        }
        let has_z = values.len() >= 3;
        let (with_z, first_line) = *first.get_or_insert((has_z, line));
        if has_z != with_z {
            return Err(parse(
                line,
                format!(
                    "this vertex has {} values and the first (line {first_line}) {}: either \
                     every vertex has a z or none has",
                    values.len(),
                    if with_z { "has a z" } else { "has none" }
                ),
            ));
        }
        for extra in values.iter().skip(3) {
            extra
                .parse::<f64>()
                .map_err(|_| parse(line, not_a_number(extra)))?;
        }
        points.push(values[0], values[1], line)?;
        if has_z {
            points.push_elevation(values[2], line)?;
        }
    }
    if faces + lines > 0 {
        points.warnings.push(format!(
            "{faces} faces (f) and {lines} lines (l) ignored: the vertices are read as points"
        ));
    }
    Ok(points)
}

/// Writes `mesh` as OBJ: the vertices `v x y z`, then the faces `f a b c`
/// or the lines `l a b`, 1-based.
pub(super) fn write(out: &mut impl Write, mesh: &Mesh) -> std::io::Result<()> {
    let cells = match mesh.cells {
        Cells::Triangles(_) => "counter-clockwise triangles (f)",
        Cells::Edges(_) => "edges (l)",
    };
    writeln!(
        out,
        "# optri: every input point is a vertex (merged duplicates too), then the {cells}, \
         1-based"
    )?;
    for [x, y, z] in mesh.vertices() {
        writeln!(out, "v {} {} {}", Shortest(x), Shortest(y), Shortest(z))?;
    }
    // OBJ counts from 1; input indices are below u32::MAX, so +1 fits a u64.
    let one_based = |v: u32| u64::from(v) + 1;
    match mesh.cells {
        Cells::Triangles(triangles) => {
            for &[a, b, c] in triangles {
                let [a, b, c] = [a, b, c].map(one_based);
                writeln!(out, "f {a} {b} {c}")?;
            }
        }
        Cells::Edges(edges) => {
            for &[a, b] in edges {
                let [a, b] = [a, b].map(one_based);
                writeln!(out, "l {a} {b}")?;
            }
        }
    }
    Ok(())
}
