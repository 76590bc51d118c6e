//! PLY, the polygon file format of Turk (1994, "The PLY Polygon File
//! Format", Stanford Graphics Lab; the header grammar and the three
//! encodings): the reader of the `vertex` element as points
//! ([`InputFormat::Ply`]) and the writer of triangulations and graphs.
//!
//! A PLY file is an ASCII header (`ply`, `format …`, then `element NAME
//! COUNT` each followed by its `property TYPE NAME` or `property list
//! COUNT_TYPE ITEM_TYPE NAME` lines, up to `end_header`) and a body holding
//! the elements in header order: in ASCII one element per line, in binary
//! the properties' values packed in the header's types and byte order.
//!
//! The reader takes the `vertex` element's `x`, `y` and optional `z` (the
//! elevation, [`ReadInput::elevations`]), each of any numeric type, and
//! walks every other element and property to check the body has the
//! structure the header announces. Counts come from the file, so nothing is
//! allocated before the body is known to hold that much: a binary element
//! of fixed-size rows is checked against the bytes left as a whole, and a
//! row with lists consumes at least one byte per row, so a count of 10¹²
//! in a short file ends at the file's end with an error. ASCII values are
//! decimals read as the other text readers read them; binary values are
//! read at their shortest round-trip decimals, as front ends read doubles
//! ([`ReadInput::from_doubles`]).
//!
//! The writer's faces are `property list uchar int vertex_indices` (the
//! convention of the format's own examples) and a graph's edges the
//! `edge` element with `vertex1`, `vertex2`.
//!
//! [`ReadInput::elevations`]: super::ReadInput::elevations
//! [`ReadInput::from_doubles`]: super::ReadInput::from_doubles
//! [`InputFormat::Ply`]: super::InputFormat::Ply

use super::{check_value, not_a_number, parse, quoted, Cells, Collected, Mesh, Shortest};
use crate::error::{Error, Result};
use std::borrow::Cow;
use std::io::Write;

/// Does `bytes` start with PLY's magic line `ply`?
pub(super) fn has_magic(bytes: &[u8]) -> bool {
    bytes.starts_with(b"ply\n") || bytes.starts_with(b"ply\r\n")
}

/// How a PLY body is encoded.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Encoding {
    Ascii,
    BinaryLittleEndian,
    BinaryBigEndian,
}

/// The scalar types of PLY, under their original and their sized names.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Scalar {
    I8,
    U8,
    I16,
    U16,
    I32,
    U32,
    F32,
    F64,
}

impl Scalar {
    fn from_name(name: &str) -> Option<Self> {
        Some(match name {
            "char" | "int8" => Scalar::I8,
            "uchar" | "uint8" => Scalar::U8,
            "short" | "int16" => Scalar::I16,
            "ushort" | "uint16" => Scalar::U16,
            "int" | "int32" => Scalar::I32,
            "uint" | "uint32" => Scalar::U32,
            "float" | "float32" => Scalar::F32,
            "double" | "float64" => Scalar::F64,
            _ => return None,
        })
    }

    fn size(self) -> usize {
        match self {
            Scalar::I8 | Scalar::U8 => 1,
            Scalar::I16 | Scalar::U16 => 2,
            Scalar::I32 | Scalar::U32 | Scalar::F32 => 4,
            Scalar::F64 => 8,
        }
    }

    fn is_integer(self) -> bool {
        !matches!(self, Scalar::F32 | Scalar::F64)
    }

    /// The value of the `self.size()` bytes `b` in byte order `big` (every
    /// value of every type is exact as an `f64`).
    fn decode(self, b: &[u8], big: bool) -> f64 {
        macro_rules! value {
            ($t:ty, $n:literal) => {{
                let bytes: [u8; $n] = b[..$n].try_into().expect("sized by the caller");
                f64::from(if big {
                    <$t>::from_be_bytes(bytes)
                } else {
                    <$t>::from_le_bytes(bytes)
                })
            }};
        }
        match self {
            Scalar::I8 => value!(i8, 1),
            Scalar::U8 => value!(u8, 1),
            Scalar::I16 => value!(i16, 2),
            Scalar::U16 => value!(u16, 2),
            Scalar::I32 => value!(i32, 4),
            Scalar::U32 => value!(u32, 4),
            Scalar::F32 => value!(f32, 4),
            Scalar::F64 => value!(f64, 8),
        }
    }
}

/// A property's type: one value, or a list (its length, then the items).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    Scalar(Scalar),
    List { count: Scalar, item: Scalar },
}

#[derive(Debug)]
struct Property {
    name: String,
    kind: Kind,
}

#[derive(Debug)]
struct Element {
    name: String,
    count: u64,
    /// The header line declaring it.
    line: usize,
    properties: Vec<Property>,
}

impl Element {
    /// The bytes of one row when no property is a list.
    fn fixed_row_size(&self) -> Option<usize> {
        self.properties
            .iter()
            .map(|p| match p.kind {
                Kind::Scalar(s) => Some(s.size()),
                Kind::List { .. } => None,
            })
            .sum()
    }

    /// Where row `row`'s `property` is, at byte `offset` of the file.
    fn place<'a>(&'a self, offset: usize, row: u64, property: &'a Property) -> Place<'a> {
        Place {
            offset,
            element: &self.name,
            row,
            property: &property.name,
        }
    }

    /// The position of the scalar property `name`, if there is one.
    fn scalar(&self, name: &str) -> Result<Option<usize>> {
        match self.properties.iter().position(|p| p.name == name) {
            Some(k) if matches!(self.properties[k].kind, Kind::List { .. }) => Err(parse(
                self.line,
                format!("the vertex property '{name}' is a list, not a number"),
            )),
            found => Ok(found),
        }
    }
}

/// Where the vertex coordinates are among the vertex properties.
struct VertexColumns {
    x: usize,
    y: usize,
    z: Option<usize>,
}

struct Header {
    encoding: Encoding,
    elements: Vec<Element>,
    /// The byte offset of the body.
    body_start: usize,
    /// The line the body starts on (for ASCII messages).
    body_line: usize,
}

/// Reads the header: the lines up to `end_header`.
fn read_header(bytes: &[u8]) -> Result<Header> {
    if !has_magic(bytes) {
        return Err(parse(1, "not a PLY file: the first line must be 'ply'"));
    }
    let mut encoding = None;
    let mut elements: Vec<Element> = Vec::new();
    let mut offset = 0;
    let mut line = 0;
    loop {
        let Some(end) = bytes[offset..].iter().position(|&b| b == b'\n') else {
            return Err(parse(0, "the PLY header has no 'end_header' line"));
        };
        let raw = String::from_utf8_lossy(&bytes[offset..offset + end]);
        offset += end + 1;
        line += 1;
        let tokens: Vec<&str> = raw.split_whitespace().collect();
        match tokens[..] {
            ["ply"] if line == 1 => {}
            [] => {}
            ["comment" | "obj_info", ..] => {}
            ["end_header"] => break,
            ["format", name, version] => {
                if encoding.is_some() {
                    return Err(parse(line, "a second 'format' line"));
                }
                encoding = Some(match name {
                    "ascii" => Encoding::Ascii,
                    "binary_little_endian" => Encoding::BinaryLittleEndian,
                    "binary_big_endian" => Encoding::BinaryBigEndian,
                    _ => {
                        return Err(parse(
                            line,
                            format!(
                                "unsupported PLY format {}; supported: ascii, \
                                 binary_little_endian, binary_big_endian",
                                quoted(name)
                            ),
                        ))
                    }
                });
                if version != "1.0" {
                    return Err(parse(
                        line,
                        format!(
                            "unsupported PLY version {}; supported: 1.0",
                            quoted(version)
                        ),
                    ));
                }
            }
            ["element", name, count] => {
                let count = count.parse().map_err(|_| {
                    parse(
                        line,
                        format!(
                            "the count of element {} is not a non-negative integer: {}",
                            quoted(name),
                            quoted(count)
                        ),
                    )
                })?;
                elements.push(Element {
                    name: name.to_string(),
                    count,
                    line,
                    properties: Vec::new(),
                });
            }
            ["property", ..] => {
                let Some(element) = elements.last_mut() else {
                    return Err(parse(line, "a property before any element"));
                };
                let property = read_property(&tokens, line)?;
                if element.properties.iter().any(|p| p.name == property.name) {
                    return Err(parse(
                        line,
                        format!(
                            "the element {} has two properties {}",
                            quoted(&element.name),
                            quoted(&property.name)
                        ),
                    ));
                }
                element.properties.push(property);
            }
            _ => {
                return Err(parse(
                    line,
                    format!("not a PLY header line: {}", quoted(raw.trim())),
                ))
            }
        }
    }
    let Some(encoding) = encoding else {
        return Err(parse(0, "the PLY header has no 'format' line"));
    };
    Ok(Header {
        encoding,
        elements,
        body_start: offset,
        body_line: line + 1,
    })
}

/// A `property TYPE NAME` or `property list COUNT_TYPE ITEM_TYPE NAME` line.
fn read_property(tokens: &[&str], line: usize) -> Result<Property> {
    let scalar = |name: &str| {
        Scalar::from_name(name).ok_or_else(|| {
            parse(
                line,
                format!(
                    "unknown property type {}; PLY's are char, uchar, short, ushort, int, uint, \
                     float, double (or int8 … float64)",
                    quoted(name)
                ),
            )
        })
    };
    let (kind, name) = match tokens {
        ["property", "list", count, item, name] => {
            let count = scalar(count)?;
            if !count.is_integer() {
                return Err(parse(
                    line,
                    "the length type of a list must be an integer type",
                ));
            }
            let item = scalar(item)?;
            (Kind::List { count, item }, name)
        }
        ["property", kind, name] if *kind != "list" => (Kind::Scalar(scalar(kind)?), name),
        _ => {
            return Err(parse(
                line,
                "expected 'property TYPE NAME' or 'property list COUNT_TYPE ITEM_TYPE NAME'",
            ))
        }
    };
    Ok(Property {
        name: name.to_string(),
        kind,
    })
}

/// Reads the `vertex` element of the PLY file `bytes` as points.
pub(super) fn read_ply(bytes: &[u8]) -> Result<Collected> {
    if bytes.iter().all(u8::is_ascii_whitespace) {
        // Nothing at all, as for every reader: no points.
        return Ok(Collected::default());
    }
    let header = read_header(bytes)?;
    let mut vertices = header.elements.iter().filter(|e| e.name == "vertex");
    let vertex = vertices
        .next()
        .ok_or_else(|| parse(0, "the PLY header declares no 'vertex' element"))?;
    if let Some(second) = vertices.next() {
        return Err(parse(second.line, "a second 'vertex' element"));
    }
    let lacks = |name: &str| {
        parse(
            vertex.line,
            format!("the vertex element has no property '{name}'"),
        )
    };
    let columns = VertexColumns {
        x: vertex.scalar("x")?.ok_or_else(|| lacks("x"))?,
        y: vertex.scalar("y")?.ok_or_else(|| lacks("y"))?,
        z: vertex.scalar("z")?,
    };
    let mut points = Collected::default();
    let skipped: Vec<String> = vertex
        .properties
        .iter()
        .map(|p| p.name.as_str())
        .filter(|name| !["x", "y", "z"].contains(name))
        .map(quoted)
        .collect();
    if !skipped.is_empty() {
        points
            .warnings
            .push(format!("vertex properties ignored: {}", skipped.join(", ")));
    }
    for element in header.elements.iter().filter(|e| e.name != "vertex") {
        points.warnings.push(format!(
            "element {} ({} items) ignored: the vertices are read as points",
            quoted(&element.name),
            element.count
        ));
    }
    let body = &bytes[header.body_start..];
    match header.encoding {
        Encoding::Ascii => read_ascii_body(&header, body, &columns, &mut points)?,
        Encoding::BinaryLittleEndian => {
            read_binary_body(&header, body, false, &columns, &mut points)?
        }
        Encoding::BinaryBigEndian => read_binary_body(&header, body, true, &columns, &mut points)?,
    }
    Ok(points)
}

/// Reads an ASCII body: each element row on a line of its own (blank lines
/// skipped), its values separated by spaces.
fn read_ascii_body(
    header: &Header,
    body: &[u8],
    columns: &VertexColumns,
    points: &mut Collected,
) -> Result<()> {
    let text: Cow<'_, str> = String::from_utf8_lossy(body);
    let mut lines = text
        .lines()
        .enumerate()
        .map(|(i, l)| (header.body_line + i, l))
        .filter(|(_, l)| !l.trim().is_empty());
    let mut last_line = header.body_line;
    for element in &header.elements {
        if element.properties.is_empty() {
            continue;
        }
        let is_vertex = element.name == "vertex";
        if is_vertex {
            points
                .points
                .reserve(element.count.min(body.len() as u64 / 4) as usize);
        }
        let mut values: Vec<&str> = Vec::new();
        for row in 0..element.count {
            let Some((line, text)) = lines.next() else {
                return Err(parse(
                    last_line,
                    format!(
                        "the file ends after {row} of the {} {} rows the header announces",
                        element.count,
                        quoted(&element.name)
                    ),
                ));
            };
            last_line = line;
            let mut tokens = text.split_whitespace();
            values.clear();
            for property in &element.properties {
                let mut take = || {
                    tokens.next().ok_or_else(|| {
                        parse(
                            line,
                            format!(
                                "{} row {row} ends before its property {}",
                                quoted(&element.name),
                                quoted(&property.name)
                            ),
                        )
                    })
                };
                match property.kind {
                    Kind::Scalar(_) => {
                        let token = take()?;
                        token
                            .parse::<f64>()
                            .map_err(|_| parse(line, not_a_number(token)))?;
                        values.push(token);
                    }
                    Kind::List { .. } => {
                        let token = take()?;
                        let length: u64 = token.parse().map_err(|_| {
                            parse(
                                line,
                                format!(
                                    "the length of list {} is not a non-negative integer: {}",
                                    quoted(&property.name),
                                    quoted(token)
                                ),
                            )
                        })?;
                        for _ in 0..length {
                            let item = take()?;
                            item.parse::<f64>()
                                .map_err(|_| parse(line, not_a_number(item)))?;
                        }
                        values.push(token);
                    }
                }
            }
            if let Some(extra) = tokens.next() {
                return Err(parse(
                    line,
                    format!(
                        "{} row {row} has more values than its properties take, from {}",
                        quoted(&element.name),
                        quoted(extra)
                    ),
                ));
            }
            if is_vertex {
                points.push(values[columns.x], values[columns.y], line)?;
                if let Some(z) = columns.z {
                    points.push_elevation(values[z], line)?;
                }
            }
        }
    }
    if let Some((line, _)) = lines.next() {
        return Err(parse(
            line,
            "more lines than the elements of the header announce",
        ));
    }
    Ok(())
}

/// Where a binary read is, for messages: the absolute byte offset, the
/// element's name and row, the property.
struct Place<'a> {
    offset: usize,
    element: &'a str,
    row: u64,
    property: &'a str,
}

impl Place<'_> {
    fn error(&self, what: &str) -> Error {
        parse(
            0,
            format!(
                "byte {} ({} row {}, property {}): {what}",
                self.offset,
                quoted(self.element),
                self.row,
                quoted(self.property)
            ),
        )
    }
}

/// Reads a binary body in byte order `big`.
fn read_binary_body(
    header: &Header,
    body: &[u8],
    big: bool,
    columns: &VertexColumns,
    points: &mut Collected,
) -> Result<()> {
    let mut at = 0usize;
    let truncated = |place: &Place, needed: u64| {
        place.error(&format!(
            "the file ends here: {needed} more bytes needed, {} left",
            body.len() - (place.offset - header.body_start)
        ))
    };
    let mut values = Vec::new();
    for element in &header.elements {
        let is_vertex = element.name == "vertex";
        let place =
            |at: usize, row: u64, property| element.place(header.body_start + at, row, property);
        if let Some(row_size) = element.fixed_row_size() {
            // Fixed-size rows: the whole element must fit in what is left
            // before a row is read or a vertex allocated.
            let needed = element.count.checked_mul(row_size as u64);
            let left = (body.len() - at) as u64;
            if needed.is_none_or(|n| n > left) {
                return Err(parse(
                    0,
                    format!(
                        "byte {}: the {} {} rows of {row_size} bytes the header announces need \
                         {} bytes, the file has {left} left",
                        header.body_start + at,
                        element.count,
                        quoted(&element.name),
                        needed.map_or_else(|| "more than 2^64".to_string(), |n| n.to_string())
                    ),
                ));
            }
            if !is_vertex {
                at += needed.unwrap_or(0) as usize;
                continue;
            }
            points.points.reserve(element.count as usize);
        } else if is_vertex {
            // Every row holds at least one list length of at least a byte.
            points
                .points
                .reserve(element.count.min((body.len() - at) as u64) as usize);
        }
        for row in 0..element.count {
            values.clear();
            for property in &element.properties {
                match property.kind {
                    Kind::Scalar(s) => {
                        let Some(b) = body.get(at..at + s.size()) else {
                            return Err(truncated(&place(at, row, property), s.size() as u64));
                        };
                        values.push((s.decode(b, big), at));
                        at += s.size();
                    }
                    Kind::List { count, item } => {
                        let Some(b) = body.get(at..at + count.size()) else {
                            return Err(truncated(&place(at, row, property), count.size() as u64));
                        };
                        let length = count.decode(b, big);
                        if length < 0.0 {
                            return Err(place(at, row, property)
                                .error(&format!("a list of negative length {length}")));
                        }
                        at += count.size();
                        // At most 2^32 items of at most 8 bytes: no overflow.
                        let items = length as u64 * item.size() as u64;
                        if items > (body.len() - at) as u64 {
                            return Err(truncated(&place(at, row, property), items));
                        }
                        at += items as usize;
                        values.push((length, at));
                    }
                }
            }
            if is_vertex {
                let coordinate = |k: usize, what: &str| -> Result<f64> {
                    let (value, offset) = values[k];
                    check_value(value, what, &value.to_string(), 0).map_err(|e| {
                        let place = place(offset, row, &element.properties[k]);
                        match e {
                            Error::Parse { message, .. } => place.error(&message),
                            other => other,
                        }
                    })
                };
                let p = [
                    coordinate(columns.x, "coordinate")?,
                    coordinate(columns.y, "coordinate")?,
                ];
                points.push_binary(p);
                if let Some(z) = columns.z {
                    points.elevations.push(coordinate(z, "elevation")?);
                }
            }
        }
    }
    if at != body.len() {
        return Err(parse(
            0,
            format!(
                "byte {}: {} bytes after the last element the header announces",
                header.body_start + at,
                body.len() - at
            ),
        ));
    }
    Ok(())
}

/// Writes `mesh` as PLY, its body in ASCII or binary little-endian.
///
/// # Errors
/// Those of `out`, and [`std::io::ErrorKind::InvalidInput`] for more
/// points than a PLY `int` index can number.
pub(super) fn write(out: &mut impl Write, mesh: &Mesh, ascii: bool) -> std::io::Result<()> {
    if i32::try_from(mesh.points.len()).is_err() {
        return Err(std::io::Error::new(
            std::io::ErrorKind::InvalidInput,
            "more points than PLY's int vertex indices can number",
        ));
    }
    let format = if ascii {
        "ascii"
    } else {
        "binary_little_endian"
    };
    writeln!(out, "ply\nformat {format} 1.0")?;
    writeln!(
        out,
        "comment optri: every input point is a vertex (merged duplicates too), indices 0-based"
    )?;
    writeln!(out, "element vertex {}", mesh.points.len())?;
    writeln!(
        out,
        "property double x\nproperty double y\nproperty double z"
    )?;
    match mesh.cells {
        Cells::Triangles(t) => writeln!(
            out,
            "element face {}\nproperty list uchar int vertex_indices",
            t.len()
        )?,
        Cells::Edges(e) => writeln!(
            out,
            "element edge {}\nproperty int vertex1\nproperty int vertex2",
            e.len()
        )?,
    }
    writeln!(out, "end_header")?;
    for [x, y, z] in mesh.vertices() {
        if ascii {
            writeln!(out, "{} {} {}", Shortest(x), Shortest(y), Shortest(z))?;
        } else {
            for v in [x, y, z] {
                out.write_all(&v.to_le_bytes())?;
            }
        }
    }
    // Indices are input indices, below the point count, checked above to
    // fit an `int`.
    let index = |v: u32| v as i32;
    match mesh.cells {
        Cells::Triangles(triangles) => {
            for &[a, b, c] in triangles {
                if ascii {
                    writeln!(out, "3 {a} {b} {c}")?;
                } else {
                    out.write_all(&[3])?;
                    for v in [a, b, c] {
                        out.write_all(&index(v).to_le_bytes())?;
                    }
                }
            }
        }
        Cells::Edges(edges) => {
            for &[a, b] in edges {
                if ascii {
                    writeln!(out, "{a} {b}")?;
                } else {
                    for v in [a, b] {
                        out.write_all(&index(v).to_le_bytes())?;
                    }
                }
            }
        }
    }
    Ok(())
}
