//! Triangle's `.poly` (a planar straight-line graph): the reader of one
//! closed boundary ([`InputFormat::Poly`]).
//!
//! The file holds a vertex section (as in `.node`), a segment section
//! `m boundary_marker` then `id a b [marker]` per segment, a hole section
//! `h` then `id x y` per hole, and optionally regional attributes (ignored).
//! optri reads a simple polygon from it: the segments must form exactly one
//! closed cycle through every vertex, and there must be no holes. The ring
//! starts at the first segment's first endpoint and follows that segment, so
//! a file whose segments are `1 2, 2 3, …, n 1` gives its vertices in file
//! order.
//!
//! [`InputFormat::Poly`]: super::InputFormat::Poly

use super::node::{read_vertex_section, token_lines};
use super::{parse, quoted, Collected, HOLES_UNSUPPORTED};
use crate::error::Result;

/// Reads the vertices of a `.poly` file in file order and its boundary ring
/// as positions into them, in boundary order (no closing vertex). An empty
/// file gives an empty ring.
pub(super) fn read_poly(text: &str) -> Result<(Collected, Vec<usize>)> {
    let mut lines = token_lines(text);
    let Some(vertices) = read_vertex_section(&mut lines)? else {
        return Ok((Collected::default(), Vec::new()));
    };
    let n = vertices.points.points.len();
    if n == 0 {
        return Err(parse(
            vertices.header_line,
            "the vertex count is 0 (vertices in a separate .node file); optri reads .poly \
             files that list their vertices",
        ));
    }
    let base = vertices.first_id;
    let Some((segment_header_line, header)) = lines.next() else {
        return Err(parse(
            0,
            "the file ends after the vertices: a .poly file needs a segment section (the \
             boundary)",
        ));
    };
    let number = |t: &str, line: usize, what: &str| -> Result<usize> {
        t.parse().map_err(|_| {
            parse(
                line,
                format!("{what} {} is not a non-negative integer", quoted(t)),
            )
        })
    };
    let m = number(header[0], segment_header_line, "segment count")?;
    let markers = match header.get(1) {
        None => 0,
        Some(t) => number(t, segment_header_line, "segment boundary-marker flag")?,
    };
    if header.len() > 2 || markers > 1 {
        return Err(parse(
            segment_header_line,
            "the segment header is `count boundary_marker` (flag 0 or 1)",
        ));
    }
    // neighbours[v]: the (at most two) vertices joined to v, with the line of
    // the segment.
    let mut neighbours: Vec<Vec<(usize, usize)>> = vec![Vec::new(); n];
    let mut first_segment = None;
    for k in 0..m {
        let Some((line, tokens)) = lines.next() else {
            return Err(parse(
                segment_header_line,
                format!("the segment header announces {m} segments, the file has {k}"),
            ));
        };
        if tokens.len() != 3 + markers {
            return Err(parse(
                line,
                format!(
                    "expected {} fields (id a b{}), found {}",
                    3 + markers,
                    if markers > 0 { " marker" } else { "" },
                    tokens.len()
                ),
            ));
        }
        let id = number(tokens[0], line, "segment id")?;
        if id != base + k {
            return Err(parse(
                line,
                format!("segment id {id} out of sequence (expected {})", base + k),
            ));
        }
        let mut ends = [0; 2];
        for (e, t) in ends.iter_mut().zip(&tokens[1..3]) {
            let v = number(t, line, "segment endpoint")?;
            if v < base || v - base >= n {
                return Err(parse(
                    line,
                    format!(
                        "segment endpoint {v} is not a vertex (ids run from {base} to {})",
                        base + n - 1
                    ),
                ));
            }
            *e = v - base;
        }
        let [a, b] = ends;
        if a == b {
            return Err(parse(
                line,
                format!("segment {id} joins vertex {} to itself", a + base),
            ));
        }
        for (v, w) in [(a, b), (b, a)] {
            if let Some(&(_, earlier)) = neighbours[v].iter().find(|&&(x, _)| x == w) {
                return Err(parse(
                    line,
                    format!(
                        "segment {id} repeats the segment {}-{} of line {earlier}",
                        a + base,
                        b + base
                    ),
                ));
            }
            if neighbours[v].len() == 2 {
                return Err(parse(
                    line,
                    format!(
                        "segment {id} is the third at vertex {} (the boundary must be one \
                         closed cycle, two segments per vertex)",
                        v + base
                    ),
                ));
            }
            neighbours[v].push((w, line));
        }
        first_segment.get_or_insert((a, b));
    }
    if let Some(v) = neighbours.iter().position(|s| s.len() < 2) {
        return Err(parse(
            segment_header_line,
            format!(
                "vertex {} is on {} segment(s); the segments must form one closed cycle \
                 through every vertex",
                v + base,
                neighbours[v].len()
            ),
        ));
    }
    // Every vertex has degree 2 and n >= 1, so m = n >= 3 and a first segment exists.
    let Some((start, next)) = first_segment else {
        return Err(parse(segment_header_line, "no segments"));
    };
    let mut ring = vec![start];
    let (mut previous, mut current) = (start, next);
    while current != start {
        ring.push(current);
        let &(following, _) = neighbours[current]
            .iter()
            .find(|&&(w, _)| w != previous)
            .unwrap_or(&neighbours[current][0]);
        (previous, current) = (current, following);
    }
    if ring.len() != n {
        let mut on_ring = vec![false; n];
        ring.iter().for_each(|&v| on_ring[v] = true);
        let v = on_ring.iter().position(|&x| !x).unwrap_or(0);
        return Err(parse(
            neighbours[v][0].1,
            format!(
                "the segments form more than one cycle: the first closes after {} vertices, \
                 vertex {} is on another one (optri reads one closed boundary)",
                ring.len(),
                v + base
            ),
        ));
    }
    if let Some((line, tokens)) = lines.next() {
        let holes = number(tokens[0], line, "hole count")?;
        if tokens.len() != 1 {
            return Err(parse(line, "the hole header is one number, the hole count"));
        }
        if holes > 0 {
            return Err(parse(
                line,
                format!("{HOLES_UNSUPPORTED}: the file lists {holes} hole(s)"),
            ));
        }
        // Regional attributes and area constraints are not used.
    }
    Ok((vertices.points, ring))
}

#[cfg(test)]
mod tests {
    use crate::io::{line_of, ring_of, InputFormat};

    const SQUARE: &str = "# a square\n4 2 0 1\n1 0 0 1\n2 1 0 1\n3 1 1 1\n4 0 1 1\n\
                          4 1\n1 1 2 1\n2 2 3 1\n3 3 4 1\n4 4 1 1\n0\n";

    #[test]
    fn poly_rings_and_errors() {
        let square = vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        assert_eq!(ring_of(SQUARE, InputFormat::Poly).unwrap(), square);
        // Segments in any order and direction; no hole section; 0-based ids.
        let shuffled = "4 2\n0 0 0\n1 1 0\n2 1 1\n3 0 1\n4 0\n0 0 1\n1 3 2\n2 0 3\n3 1 2\n";
        assert_eq!(
            ring_of(shuffled, InputFormat::Poly).unwrap(),
            vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]
        );
        let holes = SQUARE.replace("\n0\n", "\n1\n1 0.5 0.5\n");
        let (line, m) = line_of(ring_of(&holes, InputFormat::Poly).unwrap_err());
        assert_eq!(line, 12);
        assert!(m.contains("holes are not supported yet"), "{m}");
        // A third segment at a vertex.
        let (line, m) = line_of(
            ring_of(
                "4 2\n0 0 0\n1 1 0\n2 1 1\n3 0 1\n5 0\n0 0 1\n1 1 2\n2 2 3\n3 3 0\n4 0 2\n",
                InputFormat::Poly,
            )
            .unwrap_err(),
        );
        assert_eq!(line, 11);
        assert!(m.contains("third at vertex 0"), "{m}");
        // Two triangles: two cycles.
        let (line, m) = line_of(
            ring_of(
                "6 2\n0 0 0\n1 1 0\n2 0 1\n3 5 5\n4 6 5\n5 5 6\n6 0\n\
                 0 0 1\n1 1 2\n2 2 0\n3 3 4\n4 4 5\n5 5 3\n",
                InputFormat::Poly,
            )
            .unwrap_err(),
        );
        assert_eq!(line, 12);
        assert!(m.contains("more than one cycle"), "{m}");
        // An open path: a vertex on one segment.
        let (line, m) = line_of(
            ring_of(
                "3 2\n0 0 0\n1 1 0\n2 0 1\n2 0\n0 0 1\n1 1 2\n",
                InputFormat::Poly,
            )
            .unwrap_err(),
        );
        assert_eq!(line, 5);
        assert!(m.contains("vertex 0 is on 1 segment"), "{m}");
        for (text, line, needle) in [
            ("3 2\n0 0 0\n1 1 0\n2 0 1\n", 0, "segment section"),
            (
                "3 2\n0 0 0\n1 1 0\n2 0 1\n3 0\n0 0 1\n1 1 7\n",
                7,
                "not a vertex",
            ),
            (
                "3 2\n0 0 0\n1 1 0\n2 0 1\n3 0\n0 0 1\n1 1 1\n",
                7,
                "to itself",
            ),
            (
                "3 2\n0 0 0\n1 1 0\n2 0 1\n3 0\n0 0 1\n1 1 0\n",
                7,
                "repeats",
            ),
            (
                "3 2\n0 0 0\n1 1 0\n2 0 1\n3 0\n0 0 1\n1 1 2\n",
                5,
                "announces 3",
            ),
            ("0 2 0 0\n3 0\n", 1, "separate .node"),
        ] {
            let (l, m) = line_of(ring_of(text, InputFormat::Poly).unwrap_err());
            assert_eq!((l, m.contains(needle)), (line, true), "{text}: {m}");
        }
    }
}
