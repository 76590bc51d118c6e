//! Triangle's `.node` (points) and `.ele` (triangles) files: the reader
//! of `.node` ([`InputFormat::Node`]) and the writer of both.
//!
//! Triangle's vertex attributes are numbers it interpolates; optri reads
//! the first one as the vertex's elevation ([`ReadInput::elevations`]) when
//! the header declares at least one, checks the others are numbers and
//! ignores them, and writes an elevation as the one attribute.
//!
//! [`ReadInput::elevations`]: super::ReadInput::elevations
//! [`InputFormat::Node`]: super::InputFormat::Node

use super::{not_a_number, parse, quoted, strip_comment, Collected, Shortest};
use crate::error::Result;
use crate::kernel::Point;
use std::fmt::Write;

/// The non-empty lines of a Triangle file, comments stripped, as
/// `(1-based line, tokens)`.
pub(super) fn token_lines(text: &str) -> impl Iterator<Item = (usize, Vec<&str>)> {
    text.lines()
        .enumerate()
        .map(|(i, l)| {
            (
                i + 1,
                strip_comment(l).split_whitespace().collect::<Vec<_>>(),
            )
        })
        .filter(|(_, t)| !t.is_empty())
}

pub(super) fn read_node(text: &str) -> Result<Collected> {
    let mut lines = token_lines(text);
    let Some(section) = read_vertex_section(&mut lines)? else {
        return Ok(Collected::default());
    };
    if let Some((line, _)) = lines.next() {
        return Err(parse(
            line,
            format!(
                "more vertex lines than the {} the header announces",
                section.points.points.len()
            ),
        ));
    }
    Ok(section.points)
}

/// The vertex section of a `.node` or `.poly` file.
pub(super) struct VertexSection {
    /// The vertices in file order.
    pub points: Collected,
    /// The id of the first vertex (0 or 1); the ids run on from it.
    pub first_id: usize,
    /// The line of the section header.
    pub header_line: usize,
}

/// Reads a vertex-section header `n dim attributes boundary_marker` and its
/// `n` vertex lines `id x y [attributes…] [marker]` from `lines`, the first
/// attribute as the elevation; `None` if there are no lines at all.
pub(super) fn read_vertex_section<'t>(
    lines: &mut impl Iterator<Item = (usize, Vec<&'t str>)>,
) -> Result<Option<VertexSection>> {
    let Some((header_line, header)) = lines.next() else {
        return Ok(None);
    };
    let field = |k: usize, what: &str| -> Result<usize> {
        match header.get(k) {
            None if k >= 2 => Ok(0),
            None => Err(parse(header_line, format!("header lacks the {what}"))),
            Some(t) => t.parse().map_err(|_| {
                parse(
                    header_line,
                    format!(
                        "header field {what} {} is not a non-negative integer",
                        quoted(t)
                    ),
                )
            }),
        }
    };
    let count = field(0, "vertex count")?;
    let dimension = field(1, "dimension")?;
    let attributes = field(2, "attribute count")?;
    let markers = field(3, "boundary-marker flag")?;
    if dimension != 2 {
        return Err(parse(
            header_line,
            format!("dimension is {dimension}, only 2 is supported"),
        ));
    }
    if markers > 1 {
        return Err(parse(
            header_line,
            format!("boundary-marker flag must be 0 or 1, found {markers}"),
        ));
    }
    // A count near usize::MAX would overflow the column count (no line can
    // hold that many fields anyway: the line check below refuses the rest).
    let columns = attributes.checked_add(3 + markers).ok_or_else(|| {
        parse(
            header_line,
            format!("attribute count {attributes} is too large"),
        )
    })?;
    let mut points = Collected::default();
    points.points.reserve(count.min(1 << 20));
    let mut first_id = None;
    while points.points.len() < count {
        let Some((line, tokens)) = lines.next() else {
            break;
        };
        if tokens.len() != columns {
            return Err(parse(
                line,
                format!(
                    "expected {columns} fields (id x y{}{}), found {}",
                    if attributes > 0 { " attributes…" } else { "" },
                    if markers > 0 { " marker" } else { "" },
                    tokens.len()
                ),
            ));
        }
        let id: usize = tokens[0].parse().map_err(|_| {
            parse(
                line,
                format!("vertex id {} is not an integer", quoted(tokens[0])),
            )
        })?;
        let base = *first_id.get_or_insert(id);
        if base > 1 || id != base + points.points.len() {
            return Err(parse(
                line,
                format!(
                    "vertex id {id} out of sequence (expected {})",
                    if base > 1 {
                        0
                    } else {
                        base + points.points.len()
                    }
                ),
            ));
        }
        for t in &tokens[3..] {
            t.parse::<f64>().map_err(|_| parse(line, not_a_number(t)))?;
        }
        points.push(tokens[1], tokens[2], line)?;
        if attributes > 0 {
            points.push_elevation(tokens[3], line)?;
        }
    }
    if points.points.len() != count {
        return Err(parse(
            header_line,
            format!(
                "the header announces {count} vertices, the file has {}",
                points.points.len()
            ),
        ));
    }
    Ok(Some(VertexSection {
        points,
        first_id: first_id.unwrap_or(0),
        header_line,
    }))
}

/// Triangle's `.node` and `.ele` texts. Numbering is 0-based and equals the
/// input index; every input point is listed (duplicates too), with its
/// elevation as the one attribute when the point set has elevations.
#[cfg(test)]
pub(crate) fn triangulation_to_triangle_files(
    t: &crate::structures::Triangulation,
) -> (String, String) {
    let elevations = super::input_elevations(t.point_set());
    (
        node_text(t.points(), elevations.as_deref()),
        ele_text(t.triangles()),
    )
}

/// A `.node` text of `points`, 0-based ids (= input indices), with the
/// `elevations` (one per point) as the one attribute.
pub(super) fn node_text(pts: &[Point], elevations: Option<&[f64]>) -> String {
    let mut node = String::with_capacity(pts.len() * 24);
    let _ = writeln!(node, "# optri: input points, 0-based (id = input index)");
    match elevations {
        Some(_) => {
            let _ = writeln!(node, "# attribute 1: elevation");
            let _ = writeln!(node, "{} 2 1 0", pts.len());
        }
        None => {
            let _ = writeln!(node, "{} 2 0 0", pts.len());
        }
    }
    for (i, p) in pts.iter().enumerate() {
        let _ = write!(node, "{i} {} {}", Shortest(p[0]), Shortest(p[1]));
        if let Some(z) = elevations {
            let _ = write!(node, " {}", Shortest(z[i]));
        }
        node.push('\n');
    }
    node
}

/// An `.ele` text of counter-clockwise triangles over 0-based `.node` ids.
pub(super) fn ele_text(triangles: &[[u32; 3]]) -> String {
    let mut ele = String::with_capacity(triangles.len() * 20);
    let _ = writeln!(
        ele,
        "# optri: counter-clockwise triangles over the 0-based .node ids"
    );
    let _ = writeln!(ele, "{} 3 0", triangles.len());
    for (k, [a, b, c]) in triangles.iter().enumerate() {
        let _ = writeln!(ele, "{k} {a} {b} {c}");
    }
    ele
}

/// An `.edge` text (Triangle's: `m 0`, then `id a b` per edge, no boundary
/// markers) over 0-based `.node` ids.
pub(super) fn edge_text(edges: &[[u32; 2]]) -> String {
    let mut text = String::with_capacity(edges.len() * 16);
    let _ = writeln!(text, "# optri: edges over the 0-based .node ids");
    let _ = writeln!(text, "{} 0", edges.len());
    for (k, [a, b]) in edges.iter().enumerate() {
        let _ = writeln!(text, "{k} {a} {b}");
    }
    text
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::{awkward_points, line_of, points_of, read_str, InputFormat};
    use crate::{delaunay, PointSet};

    #[test]
    fn node_files() {
        let text = "# comment\n4 2 1 1\n1 0 0 7 1\n2 1 0 7 1\n3 1 1 7 0\n4 0 1 7 1\n";
        assert_eq!(
            points_of(text, InputFormat::Node).unwrap(),
            vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]
        );
        assert_eq!(
            points_of("3 2 0 0\n0 0 0\n1 1 0\n2 0 1\n", InputFormat::Node).unwrap(),
            vec![[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]
        );
        let (line, _) =
            line_of(points_of("3 2 0 0\n0 0 0\n1 1 0 5\n2 0 1\n", InputFormat::Node).unwrap_err());
        assert_eq!(line, 3);
        let (line, m) =
            line_of(points_of("3 2 0 0\n0 0 0\n1 1 0\n", InputFormat::Node).unwrap_err());
        assert_eq!(line, 1);
        assert!(m.contains("3 vertices"), "{m}");
        let (line, _) =
            line_of(points_of("2 3 0 0\n0 0 0 0\n1 1 0 0\n", InputFormat::Node).unwrap_err());
        assert_eq!(line, 1);
        let (line, _) = line_of(points_of("2 2\n0 0 0\n5 1 0\n", InputFormat::Node).unwrap_err());
        assert_eq!(line, 3);
    }

    #[test]
    fn the_first_attribute_is_the_elevation() {
        let text = "4 2 2 1\n1 0 0 7 -1 1\n2 1 0 6.5 0 1\n3 1 1 7 0 0\n4 0 1 0 0 1\n";
        let read = read_str(text, InputFormat::Node).unwrap();
        assert_eq!(read.elevations, Some(vec![7.0, 6.5, 7.0, 0.0]));
        // No attribute, no elevation (a boundary marker is none).
        let read = read_str("3 2 0 1\n0 0 0 1\n1 1 0 1\n2 0 1 0\n", InputFormat::Node).unwrap();
        assert_eq!(read.elevations, None);
        for (text, bad_line, needle) in [
            (
                "2 2 1 0\n0 0 0 nan\n1 1 0 1\n",
                2,
                "elevation 'nan' is not a finite",
            ),
            (
                "2 2 1 0\n0 0 0 1\n1 1 0 -1e301\n",
                3,
                "outside the exact range",
            ),
            (
                "2 2 1 0\n0 0 0 1\n1 1 0\n",
                3,
                "expected 4 fields (id x y attributes…)",
            ),
        ] {
            let (line, m) = line_of(points_of(text, InputFormat::Node).unwrap_err());
            assert_eq!(line, bad_line, "{text}: {m}");
            assert!(m.contains(needle), "{text}: {m}");
        }
    }

    #[test]
    fn triangle_files_round_trip() {
        let mut pts = awkward_points();
        pts.push([3e40, -5e-20]);
        let t = delaunay(&PointSet::new(&pts).unwrap()).unwrap();
        let (node, ele) = triangulation_to_triangle_files(&t);
        assert_eq!(points_of(&node, InputFormat::Node).unwrap(), pts);
        let rows: Vec<Vec<u32>> = ele
            .lines()
            .filter(|l| !l.starts_with('#'))
            .map(|l| l.split_whitespace().map(|x| x.parse().unwrap()).collect())
            .collect();
        assert_eq!(rows[0], vec![t.triangles().len() as u32, 3, 0]);
        let triangles: Vec<[u32; 3]> = rows[1..]
            .iter()
            .enumerate()
            .map(|(k, r)| {
                assert_eq!(r[0], k as u32);
                [r[1], r[2], r[3]]
            })
            .collect();
        assert_eq!(triangles, t.triangles());
        // Elevations go out as the one attribute and come back, duplicates
        // included.
        let z: Vec<f64> = (0..pts.len()).map(|i| (i % 7) as f64 - 2.5).collect();
        let mut z = z;
        let last = pts.len() - 3; // the duplicate of point 3 (awkward_points)
        z[last] = z[3];
        let with_z = PointSet::new(&pts).unwrap().with_elevations(&z).unwrap();
        let (node, _) = triangulation_to_triangle_files(&delaunay(&with_z).unwrap());
        assert!(node.contains(&format!("{} 2 1 0", pts.len())), "{node}");
        let read = read_str(&node, InputFormat::Node).unwrap();
        assert_eq!(read.input.points(), pts);
        assert_eq!(read.elevations, Some(z));
    }
}
