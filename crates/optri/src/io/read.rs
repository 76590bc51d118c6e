//! The one reader entry point: [`read`] takes a [`Source`] (text, bytes or
//! a path) and [`ReadOptions`] (the format, or `None` to pick it by
//! extension and then by content; whether a polygon may be returned) and
//! hands the text to the reader of its format.

use super::{geojson, node, obj, parse, ply, poly, text, tsplib, InputFormat, ReadInput};
use crate::error::{Error, Result};
use std::borrow::Cow;
use std::path::Path;

/// Where [`read`] takes its input from.
#[derive(Clone, Copy, Debug)]
pub enum Source<'a> {
    /// Text already in memory (e.g. a web request's field).
    Text(&'a str),
    /// Bytes in memory (e.g. standard input), in any ASCII-compatible
    /// encoding where no number is read (see the module docs of `io`).
    Bytes(&'a [u8]),
    /// A file; its extension picks the format unless
    /// [`ReadOptions::format`] does.
    Path(&'a Path),
}

/// How [`read`] reads.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[non_exhaustive]
pub struct ReadOptions {
    /// The format; `None` (the default) picks it by the path's extension
    /// ([`InputFormat::from_path`]) and otherwise by content
    /// ([`InputFormat::sniff`]).
    pub format: Option<InputFormat>,
    /// Whether a polygon input is returned as [`Input::Polygon`](super::Input::Polygon): a `.poly`,
    /// or a GeoJSON document with one `Polygon` and no points. Otherwise
    /// (the default) every input is points: a `.poly` gives its ring's
    /// vertices in boundary order, and a GeoJSON document without points is
    /// an error.
    pub polygons: bool,
}

impl ReadOptions {
    /// These options with `format` (`None`: by extension, then by content).
    pub fn with_format(mut self, format: impl Into<Option<InputFormat>>) -> Self {
        self.format = format.into();
        self
    }

    /// These options with [`polygons`](Self::polygons) set.
    pub fn with_polygons(mut self, polygons: bool) -> Self {
        self.polygons = polygons;
        self
    }
}

/// Reads points or a polygon from `source`, keeping each coordinate's
/// decimal value: when every coordinate scaled by one common `10^k` is an
/// integer of magnitude below 2⁵³, [`ReadInput::scaled`] holds those
/// integers, on which every predicate decides the decimals as written.
///
/// The formats and what each accepts are those of [`InputFormat`]; a `.poly`
/// is always a polygon, a GeoJSON document is points if it has any
/// `Point`/`MultiPoint` geometry (its polygons are then skipped) and
/// otherwise, with [`ReadOptions::polygons`], a polygon if it has exactly
/// one `Polygon` (or a `MultiPolygon` of one polygon). A polygon's ring is
/// not validated: [`crate::SimplePolygon::new`] does that.
///
/// # Errors
/// [`Error::Io`] naming the path when a file cannot be read;
/// [`Error::Parse`] with the 1-based line of the first problem (line 0 when
/// it concerns the whole input, e.g. no points at all; callers prefix the
/// source's name), e.g. for a GeoJSON polygon with holes ("polygons with
/// holes are not supported yet") or more than one polygon.
pub fn read(source: Source<'_>, options: &ReadOptions) -> Result<ReadInput> {
    let file;
    let (bytes, by_extension) = match source {
        Source::Text(text) => (text.as_bytes(), None),
        Source::Bytes(bytes) => (bytes, None),
        Source::Path(path) => {
            file = std::fs::read(path)
                .map_err(|e| Error::Io(format!("cannot read '{}': {e}", path.display())))?;
            (file.as_slice(), InputFormat::from_path(path).ok())
        }
    };
    let bytes = bytes.strip_prefix(b"\xef\xbb\xbf").unwrap_or(bytes);
    let format = options.format.or(by_extension);
    // PLY is read as bytes (its body may be binary), so its magic line is
    // looked for before any decoding.
    if format == Some(InputFormat::Ply) || format.is_none() && ply::has_magic(bytes) {
        return checked(ply::read_ply(bytes)?.finish(InputFormat::Ply, false, None));
    }
    let text = decode(bytes);
    let format = format.unwrap_or_else(|| InputFormat::sniff(&text));
    read_text(&text, format, options.polygons)
}

/// `bytes` as text: each sequence that is not UTF-8 replaced by U+FFFD.
/// Borrowed when the input is UTF-8.
fn decode(bytes: &[u8]) -> Cow<'_, str> {
    String::from_utf8_lossy(bytes)
}

/// Reads `text` in `format`.
fn read_text(text: &str, format: InputFormat, polygons: bool) -> Result<ReadInput> {
    let read = match format {
        InputFormat::Text => text::read_text(text)?.finish(format, false, None),
        InputFormat::Node => node::read_node(text)?.finish(format, false, None),
        InputFormat::Poly => {
            let (collected, ring) = poly::read_poly(text)?;
            collected.finish(format, polygons, Some(&ring))
        }
        InputFormat::Tsplib => tsplib::read_tsplib(text)?.finish(format, false, None),
        InputFormat::Ply => ply::read_ply(text.as_bytes())?.finish(format, false, None),
        InputFormat::Obj => obj::read_obj(text)?.finish(format, false, None),
        InputFormat::GeoJson => {
            let (input, elevations) = geojson::read_geojson_input(text, polygons)?;
            ReadInput {
                format: Some(format),
                elevations,
                ..ReadInput::from_json_numbers(input, text)
            }
        }
    };
    checked(read)
}

/// `read`, unless it holds no point.
fn checked(read: ReadInput) -> Result<ReadInput> {
    if read.input.points().is_empty() {
        return Err(parse(0, "no points found in the input"));
    }
    Ok(read)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::{line_of, points_of, Input};

    #[test]
    fn sources_of_every_kind_read_alike() {
        let dir = std::env::temp_dir().join(format!("optri-io-read-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let text = "# pts\n0 0\n1 0\n0 1\n";
        let points = vec![[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]];
        for (name, contents) in [("p.txt", text), ("p", text), ("p.dat", text)] {
            let path = dir.join(name);
            std::fs::write(&path, contents).unwrap();
            let read = read(Source::Path(&path), &ReadOptions::default()).unwrap();
            assert_eq!(read.input, Input::Points(points.clone()), "{name}");
            assert_eq!(read.format, Some(InputFormat::Text));
        }
        let options = ReadOptions::default();
        let from_bytes = read(Source::Bytes(text.as_bytes()), &options).unwrap();
        let from_text = read(Source::Text(text), &options).unwrap();
        assert_eq!(from_bytes, from_text);
        // A missing file is an I/O error naming it.
        let e = read(Source::Path(&dir.join("missing.txt")), &options).unwrap_err();
        assert!(
            matches!(&e, Error::Io(m) if m.contains("missing.txt")),
            "{e:?}"
        );
        // The format given wins over the extension.
        let node = dir.join("n.txt");
        std::fs::write(&node, "3 2\n0 0 0\n1 1 0\n2 0 1\n").unwrap();
        let read_node = read(
            Source::Path(&node),
            &ReadOptions::default().with_format(InputFormat::Node),
        )
        .unwrap();
        assert_eq!(read_node.input.points(), points);
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn bytes_that_are_not_utf8_are_accepted_only_where_no_number_is_read() {
        // Latin-1 é (0xE9) in comments of every line-based format.
        let latin1 = |s: &str| -> Vec<u8> {
            s.bytes()
                .flat_map(|b| if b == b'~' { vec![0xE9] } else { vec![b] })
                .collect()
        };
        let options = ReadOptions::default();
        for (text, format) in [
            ("# caf~\n0 0\n1 0 # r~sum~\n0 1\n", InputFormat::Text),
            ("# caf~\n3 2\n0 0 0\n1 1 0 # ~\n2 0 1\n", InputFormat::Node),
            (
                "3 2 # ~\n0 0 0\n1 1 0\n2 0 1\n3 0 # ~\n0 0 1\n1 1 2\n2 2 0\n0\n",
                InputFormat::Poly,
            ),
            (
                "NAME : t\nCOMMENT : caf~ cr~me\nDIMENSION : 3\nNODE_COORD_SECTION\n\
                 1 0 0\n2 1 0\n3 0 1\nEOF\n",
                InputFormat::Tsplib,
            ),
        ] {
            let bytes = latin1(text);
            for options in [options, options.with_format(format)] {
                let read = read(Source::Bytes(&bytes), &options).unwrap();
                assert_eq!(read.format, Some(format), "{text}");
                assert_eq!(
                    read.input.points(),
                    [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]],
                    "{text}"
                );
            }
        }
        // Where a number must be, the line is named.
        for (text, format, bad_line) in [
            ("0 0\n1 0\n0 1~\n", InputFormat::Text, 3),
            ("3 2\n0 0 0\n1 1~ 0\n2 0 1\n", InputFormat::Node, 3),
            ("NODE_COORD_SECTION\n1 0 0\n2 ~ 1\n", InputFormat::Tsplib, 3),
        ] {
            let e = read(Source::Bytes(&latin1(text)), &options.with_format(format));
            let (line, m) = line_of(e.unwrap_err());
            assert_eq!(line, bad_line, "{text}: {m}");
            assert!(m.contains("not UTF-8"), "{m}");
        }
        // The byte-order mark is not part of the first token.
        assert_eq!(
            points_of("\u{feff}-1e3 2.5E-2\r\n", InputFormat::Text).unwrap(),
            vec![[-1000.0, 0.025]]
        );
        let with_bom = [b"\xef\xbb\xbf".as_slice(), b"0 0\n1 0\n0 1\n"].concat();
        assert_eq!(
            read(Source::Bytes(&with_bom), &options)
                .unwrap()
                .input
                .points()
                .len(),
            3
        );
    }
}
