//! Plain text point files: one `x y` or `x y z` per line, or a table (CSV,
//! TSV, …) whose header row names the coordinate columns
//! ([`InputFormat::Text`]).
//!
//! A third coordinate is an elevation ([`ReadInput::elevations`]): the third
//! column of a headerless file of three columns, or the column a header
//! names `z` (or `elevation`, `ele`, `altitude`, `alt`). Every row has as many columns
//! as the first, so a file mixing `x y` and `x y z` lines is an error naming
//! the first line that differs; a headerless file of four or more columns
//! reads only `x y`, with a warning (which column is `z` would be a guess).
//!
//! [`ReadInput::elevations`]: super::ReadInput::elevations
//! [`InputFormat::Text`]: super::InputFormat::Text

use super::{not_a_number, parse, quoted, strip_comment, Collected};
use crate::error::Result;

/// The header names of a coordinate pair, x first (longitude and easting
/// are x), matched case-insensitively.
const COORDINATE_PAIRS: [(&str, &str); 6] = [
    ("x", "y"),
    ("lon", "lat"),
    ("lng", "lat"),
    ("long", "lat"),
    ("longitude", "latitude"),
    ("easting", "northing"),
];

/// The header names of an elevation column, matched case-insensitively.
const ELEVATION_NAMES: [&str; 5] = ["z", "elevation", "ele", "altitude", "alt"];

/// How many column names a message lists before `…`.
const LISTED_NAMES: usize = 8;

/// The fields of one text line. A line with a comma or semicolon is split
/// at those only, outside double quotes, each field trimmed and without
/// its surrounding double quotes (so a name may hold spaces, or a quoted
/// comma); an empty field is kept as `""`, so the columns never shift
/// (`1,,0` has three fields, the second empty). A line without is split at
/// runs of spaces and tabs.
fn text_fields(line_text: &str) -> Vec<&str> {
    let trimmed = line_text.trim();
    if !trimmed.contains([',', ';']) {
        return trimmed.split_whitespace().collect();
    }
    fn field(raw: &str) -> &str {
        let t = raw.trim();
        t.strip_prefix('"')
            .and_then(|rest| rest.strip_suffix('"'))
            .unwrap_or(t)
    }
    let mut fields = Vec::new();
    let (mut start, mut in_quotes) = (0, false);
    for (i, c) in trimmed.char_indices() {
        match c {
            '"' => in_quotes = !in_quotes,
            ',' | ';' if !in_quotes => {
                fields.push(field(&trimmed[start..i]));
                start = i + 1;
            }
            _ => {}
        }
    }
    fields.push(field(&trimmed[start..]));
    fields
}

/// Where the coordinates are in each row, and how many fields a row has.
struct Columns {
    /// The columns of x and y.
    xy: [usize; 2],
    /// The column of the elevation, if there is one.
    z: Option<usize>,
    /// Every row's field count.
    count: usize,
    /// The line that set it (the header, or the first row).
    line: usize,
    /// Whether a header set them (then the other columns may hold
    /// anything, e.g. names).
    named: bool,
}

pub(super) fn read_text(text: &str) -> Result<Collected> {
    let mut points = Collected::default();
    let mut columns: Option<Columns> = None;
    for (i, raw) in text.lines().enumerate() {
        let line = i + 1;
        let fields = text_fields(strip_comment(raw));
        if fields.is_empty() {
            continue;
        }
        let columns = match &columns {
            Some(columns) => columns,
            None => {
                // A header is allowed only as the first content line and
                // only when none of its fields is a number.
                if fields.iter().all(|t| t.parse::<f64>().is_err()) {
                    let (xy, z, warning) = header_columns(&fields, line)?;
                    points.warnings.extend(warning);
                    columns = Some(Columns {
                        xy,
                        z,
                        count: fields.len(),
                        line,
                        named: true,
                    });
                    continue;
                }
                if fields.len() < 2 {
                    return Err(parse(
                        line,
                        format!("expected 'x y', found a single value {}", quoted(fields[0])),
                    ));
                }
                if fields.len() > 3 {
                    points.warnings.push(ignored_columns(fields.len(), line));
                }
                &*columns.insert(Columns {
                    xy: [0, 1],
                    z: (fields.len() == 3).then_some(2),
                    count: fields.len(),
                    line,
                    named: false,
                })
            }
        };
        // An empty field where a number must be (in a headerless file:
        // anywhere) is reported before the column count it changes.
        let empty = (0..fields.len())
            .find(|&k| fields[k].is_empty() && (!columns.named || columns.reads(k)));
        if let Some(k) = empty {
            return Err(parse(
                line,
                format!(
                    "field {} is empty (two separators in a row, or one at the start or end of \
                     the line); {} must hold a number",
                    k + 1,
                    if columns.named { "it" } else { "every field" }
                ),
            ));
        }
        if fields.len() != columns.count {
            let (n, first) = (columns.count, columns.line);
            return Err(parse(
                line,
                if columns.named {
                    format!(
                        "{} column{}, but the header on line {first} names {n}",
                        fields.len(),
                        plural(fields.len())
                    )
                } else {
                    format!(
                        "{} column{}, but line {first} has {n}; every row must have the same \
                         number of columns",
                        fields.len(),
                        plural(fields.len())
                    )
                },
            ));
        }
        // Without a header every field must be a number, so a stray word is
        // not silently ignored; with one, the columns it names besides the
        // coordinates may hold anything (names, notes).
        if !columns.named {
            if let Some(t) = fields[2..].iter().find(|t| t.parse::<f64>().is_err()) {
                return Err(parse(line, not_a_number(t)));
            }
        }
        let [x, y] = columns.xy;
        points.push(fields[x], fields[y], line)?;
        if let Some(z) = columns.z {
            points.push_elevation(fields[z], line)?;
        }
    }
    Ok(points)
}

impl Columns {
    /// Whether column `k` holds a number that is read (x, y or z).
    fn reads(&self, k: usize) -> bool {
        self.xy.contains(&k) || self.z == Some(k)
    }
}

fn plural(n: usize) -> &'static str {
    if n == 1 {
        ""
    } else {
        "s"
    }
}

/// A header field as a column name: trimmed, without surrounding quotes.
fn column_name(field: &str) -> &str {
    let name = field.trim();
    let unquoted = ['"', '\'']
        .iter()
        .find_map(|&q| name.strip_prefix(q).and_then(|rest| rest.strip_suffix(q)));
    unquoted.unwrap_or(name).trim()
}

/// The columns of x and y that the header `fields` on `line` names, the
/// elevation's column if it names one, and a warning naming the other
/// columns (skipped) if there are any.
///
/// # Errors
/// When a field is empty, or the header names no coordinate pair, more than
/// one, one of the pair's columns twice, or more than one elevation column.
fn header_columns(
    fields: &[&str],
    line: usize,
) -> Result<([usize; 2], Option<usize>, Option<String>)> {
    let names: Vec<&str> = fields.iter().map(|f| column_name(f)).collect();
    if let Some(k) = names.iter().position(|n| n.is_empty()) {
        return Err(parse(
            line,
            format!(
                "header field {} is empty (two separators in a row, or one at the start or end \
                 of the line); every column needs a name",
                k + 1
            ),
        ));
    }
    let columns_named = |name: &str| -> Vec<usize> {
        (0..names.len())
            .filter(|&k| names[k].eq_ignore_ascii_case(name))
            .collect()
    };
    let mut found: Vec<(&str, &str, [usize; 2])> = Vec::new();
    for (x_name, y_name) in COORDINATE_PAIRS {
        let (xs, ys) = (columns_named(x_name), columns_named(y_name));
        if xs.is_empty() || ys.is_empty() {
            continue;
        }
        for (name, at) in [(x_name, &xs), (y_name, &ys)] {
            if at.len() > 1 {
                return Err(parse(
                    line,
                    format!(
                        "the header names the column {name} twice (columns {} and {})",
                        at[0] + 1,
                        at[1] + 1
                    ),
                ));
            }
        }
        found.push((x_name, y_name, [xs[0], ys[0]]));
    }
    let accepted = COORDINATE_PAIRS.map(|(x, y)| format!("{x}/{y}")).join(", ");
    let xy = match found[..] {
        [(_, _, xy)] => xy,
        [] => {
            return Err(parse(
                line,
                format!(
                    "the header names no coordinate columns (found {}); it must name one pair \
                     of: {accepted} (case-insensitive; x is the longitude or easting)",
                    listed(names.len(), names.iter().map(|n| quoted(n)))
                ),
            ))
        }
        _ => {
            let pairs: Vec<String> = found.iter().map(|(x, y, _)| format!("{x}/{y}")).collect();
            return Err(parse(
                line,
                format!(
                    "the header names more than one pair of coordinate columns ({}); keep one \
                     pair and rename the other columns",
                    pairs.join(", ")
                ),
            ));
        }
    };
    let elevation_columns: Vec<usize> = (0..names.len())
        .filter(|&k| {
            ELEVATION_NAMES
                .iter()
                .any(|n| names[k].eq_ignore_ascii_case(n))
        })
        .collect();
    let z = match elevation_columns[..] {
        [] => None,
        [z] => Some(z),
        [a, b, ..] => {
            return Err(parse(
                line,
                format!(
                    "the header names more than one elevation column ({} in column {} and {} \
                     in column {}); keep one and rename the others",
                    quoted(names[a]),
                    a + 1,
                    quoted(names[b]),
                    b + 1
                ),
            ))
        }
    };
    let read = |k: &usize| xy.contains(k) || z == Some(*k);
    let skipped = (0..names.len())
        .filter(|k| !read(k))
        .map(|k| format!("{} (column {})", quoted(names[k]), k + 1));
    let count = names.len() - 2 - usize::from(z.is_some());
    let warning = (count > 0).then(|| {
        let elevation = z.map_or(String::new(), |z| {
            format!(", the elevation is {} (column {})", quoted(names[z]), z + 1)
        });
        format!(
            "line {line}: skipping {count} column{} {}; x and y are {} and {} (columns {} and \
             {}){elevation}",
            plural(count),
            listed(count, skipped),
            quoted(names[xy[0]]),
            quoted(names[xy[1]]),
            xy[0] + 1,
            xy[1] + 1
        )
    });
    Ok((xy, z, warning))
}

/// The first [`LISTED_NAMES`] of the `count` `items`, comma-separated,
/// then `…` with how many there are in all (only those listed are made).
fn listed(count: usize, items: impl Iterator<Item = String>) -> String {
    let mut text = items.take(LISTED_NAMES).collect::<Vec<_>>().join(", ");
    if count > LISTED_NAMES {
        text.push_str(&format!(", … ({count} in all)"));
    }
    text
}

/// The warning for rows of `columns > 3` values without a header naming
/// the coordinates: the first two are read, and no elevation (which column
/// holds it would be a guess).
fn ignored_columns(columns: usize, line: usize) -> String {
    format!(
        "line {line}: rows have {columns} columns and no header names them; reading columns 1 \
         and 2 as x y and ignoring columns 3 to {columns} (a header line such as `x y z` names \
         them; a column named z is read as the elevation)"
    )
}

#[cfg(test)]
mod tests {
    use crate::io::{line_of, points_of, read_str, InputFormat};
    use crate::kernel::Point;

    #[test]
    fn text_accepts_separators_comments_and_a_header() {
        let text = "x,y\n# a comment\n1 2\n\n3,4 # trailing\n5\t6\n7;8\n";
        assert_eq!(
            points_of(text, InputFormat::Text).unwrap(),
            vec![[1.0, 2.0], [3.0, 4.0], [5.0, 6.0], [7.0, 8.0]]
        );
        // Three columns without a header are x y z; more are allowed, x, y
        // being the first two, with a warning naming what is ignored unless a
        // header names the columns.
        let read = read_str("1 2 9\n3 4 -9.5\n", InputFormat::Text).unwrap();
        assert_eq!(read.input.points(), [[1.0, 2.0], [3.0, 4.0]]);
        assert_eq!(read.elevations, Some(vec![9.0, -9.5]));
        assert!(read.warnings.is_empty(), "{:?}", read.warnings);
        let read = read_str("# c\n1 2 9 8\n3 4 9 8\n", InputFormat::Text).unwrap();
        assert_eq!(read.elevations, None);
        assert_eq!(
            read.warnings,
            [
                "line 2: rows have 4 columns and no header names them; reading columns 1 and 2 \
                 as x y and ignoring columns 3 to 4 (a header line such as `x y z` names them; \
                 a column named z is read as the elevation)"
            ]
        );
        for plain in ["x y\n1 2\n3 4\n", "1 2\n3 4\n"] {
            assert!(read_str(plain, InputFormat::Text)
                .unwrap()
                .warnings
                .is_empty());
        }
        // A header names the skipped columns, and the warning names them.
        let read = read_str("x y w\n1 2 9\n3 4 9\n", InputFormat::Text).unwrap();
        assert_eq!(
            read.warnings,
            ["line 1: skipping 1 column 'w' (column 3); x and y are 'x' and 'y' (columns 1 and 2)"]
        );
        assert_eq!(read.elevations, None);
        assert_eq!(
            points_of("\u{feff}-1e3 2.5E-2\r\n", InputFormat::Text).unwrap(),
            vec![[-1000.0, 0.025]]
        );
        // A header naming x and y picks those columns.
        assert_eq!(
            points_of("id;Y;X\n1;2;3\n2;5;6\n", InputFormat::Text).unwrap(),
            vec![[3.0, 2.0], [6.0, 5.0]]
        );
        let (line, m) = line_of(points_of("id,x,y\n1,2\n", InputFormat::Text).unwrap_err());
        assert_eq!(line, 2);
        assert!(m.contains("header on line 1"), "{m}");
    }

    #[test]
    fn csv_headers_name_the_coordinate_columns() {
        // Every accepted pair, in any case, quoted or not, x = lon/easting.
        for header in [
            "id,lon,lat",
            "id,LNG,Lat",
            "id,long,lat",
            "id,\"Longitude\",\"Latitude\"",
            "id, 'easting' ,northing",
            "id;X;Y",
        ] {
            let text = format!("{header}\n7,1.5,2.5\n8,3,4\n");
            let read = read_str(&text, InputFormat::Text).unwrap();
            assert_eq!(read.input.points(), [[1.5, 2.5], [3.0, 4.0]], "{header}");
            assert_eq!(read.warnings.len(), 1, "{header}");
            assert!(
                read.warnings[0].contains("'id' (column 1)"),
                "{:?}",
                read.warnings
            );
        }
        // Latitude first: the roles come from the names, not the order.
        assert_eq!(
            points_of("lat,lon\n2,1\n4,3\n", InputFormat::Text).unwrap(),
            vec![[1.0, 2.0], [3.0, 4.0]]
        );
        // Skipped columns may hold names, and may be empty.
        let read = read_str(
            "name,x,y,note\nZürich,8.5,47.4,\"big city\"\nBern,7.4,46.9,\n",
            InputFormat::Text,
        )
        .unwrap();
        assert_eq!(read.input.points(), [[8.5, 47.4], [7.4, 46.9]]);
        assert!(
            read.warnings[0].contains("'name' (column 1), 'note' (column 4)"),
            "{:?}",
            read.warnings
        );
        // Names may hold spaces and, quoted, commas; quoted numbers are
        // numbers.
        let read = read_str(
            "city;lon;lat\n\"Zürich, CH\";\"8.5\";47.4\nNew York ; -74 ; 40.7\n",
            InputFormat::Text,
        )
        .unwrap();
        assert_eq!(read.input.points(), [[8.5, 47.4], [-74.0, 40.7]]);
        // But the coordinates must be numbers, and present.
        for (text, needle) in [
            ("name,x,y\nBern,7.4,oops\n", "'oops' is not a number"),
            ("name,x,y\nBern,,46.9\n", "field 2 is empty"),
            ("name,x,y\nBern,7.4\n", "header on line 1 names 3"),
            ("name,x,y\nBern,7 4,46\n", "'7 4' is not a number"),
        ] {
            let (line, m) = line_of(points_of(text, InputFormat::Text).unwrap_err());
            assert_eq!(line, 2, "{text}");
            assert!(m.contains(needle), "{text}: {m}");
        }
        // A header without a coordinate pair, with two pairs, or with a
        // coordinate column twice is an error on its line.
        for (text, needles) in [
            (
                "id,a,b\n1,2,3\n",
                &[
                    "found 'id', 'a', 'b'",
                    "x/y, lon/lat, lng/lat",
                    "easting/northing",
                ][..],
            ),
            ("x,lat\n1,2\n", &["no coordinate columns", "'x', 'lat'"]),
            (
                "x,y,lon,lat\n1,2,3,4\n",
                &["more than one pair", "x/y, lon/lat"],
            ),
            ("x,y,X\n1,2,3\n", &["column x twice (columns 1 and 3)"]),
        ] {
            let (line, m) = line_of(points_of(text, InputFormat::Text).unwrap_err());
            assert_eq!(line, 1, "{text}");
            for needle in needles {
                assert!(m.contains(needle), "{text}: {m}");
            }
        }
        // Headerless files keep the first two columns, all numbers.
        let (line, m) = line_of(points_of("1,2,3\n4,5,Bern\n", InputFormat::Text).unwrap_err());
        assert_eq!(line, 2);
        assert!(m.contains("'Bern' is not a number"), "{m}");
        // Many skipped columns are listed up to a point.
        let header: Vec<String> = (0..20).map(|k| format!("c{k}")).collect();
        let text = format!("{},x,y\n{}1,2\n", header.join(","), "0,".repeat(20));
        let warning = &read_str(&text, InputFormat::Text).unwrap().warnings[0];
        assert!(
            warning.contains("skipping 20 columns") && warning.contains("… (20 in all)"),
            "{warning}"
        );
    }

    #[test]
    fn text_errors_name_the_line_and_the_token() {
        let (line, m) = line_of(points_of("0 0\n1 1\n2 oops\n", InputFormat::Text).unwrap_err());
        assert_eq!(line, 3);
        assert!(m.contains("'oops'"), "{m}");
        let (line, m) = line_of(points_of("0 0\n1 1 1\n", InputFormat::Text).unwrap_err());
        assert_eq!(line, 2);
        assert!(m.contains("line 1"), "{m}");
        let (line, _) = line_of(points_of("0 0\n1 nan\n", InputFormat::Text).unwrap_err());
        assert_eq!(line, 2);
        let (line, m) = line_of(points_of("0 0\n\n-inf 1\n", InputFormat::Text).unwrap_err());
        assert_eq!(line, 3);
        assert!(m.contains("finite"), "{m}");
        // Overflowing literals become infinite and are rejected, as are values
        // outside the exact range.
        let (line, _) = line_of(points_of("1e400 0\n", InputFormat::Text).unwrap_err());
        assert_eq!(line, 1);
        let (line, m) = line_of(points_of("1 2\n1e100 0\n", InputFormat::Text).unwrap_err());
        assert_eq!(line, 2);
        assert!(m.contains("range"), "{m}");
        let (line, _) = line_of(points_of("1\n", InputFormat::Text).unwrap_err());
        assert_eq!(line, 1);
        // A header is only allowed at the top.
        let (line, _) = line_of(points_of("1 2\nx y\n", InputFormat::Text).unwrap_err());
        assert_eq!(line, 2);
        let (line, m) = line_of(points_of("# only\n\nx y\n", InputFormat::Text).unwrap_err());
        assert_eq!(line, 0);
        assert!(m.contains("no points"), "{m}");
        assert_eq!(line_of(points_of("", InputFormat::Text).unwrap_err()).0, 0);
    }

    #[test]
    fn empty_fields_are_errors_but_whitespace_runs_are_one_separator() {
        for (text, bad_line) in [
            ("0,0\n1,,0\n0,1\n", 2),
            ("0,0\n1,0,\n0,1\n", 2),
            ("0;0\n1;0\n;0;1\n", 3),
            ("0 , 0\n1 , , 0\n", 2),
            ("x,,y\n0,0\n", 1),
        ] {
            let (line, m) = line_of(points_of(text, InputFormat::Text).unwrap_err());
            assert_eq!(line, bad_line, "{text:?}: {m}");
            assert!(m.contains("empty"), "{m}");
        }
        assert_eq!(
            points_of("0 \t 0\n\t1   0  \n0,\t1 # c,,\n", InputFormat::Text).unwrap(),
            vec![[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]
        );
    }

    #[test]
    fn a_third_coordinate_is_an_elevation_and_never_dropped_silently() {
        // A header names the elevation column, anywhere and in any case.
        for (text, points, z) in [
            (
                "x y z\n1 2 9\n3 4 8\n",
                [[1.0, 2.0], [3.0, 4.0]],
                [9.0, 8.0],
            ),
            (
                "Z,lon,lat\n9,1,2\n8,3,4\n",
                [[1.0, 2.0], [3.0, 4.0]],
                [9.0, 8.0],
            ),
            (
                "x;y;Elevation\n1;2;-1e-3\n3;4;0\n",
                [[1.0, 2.0], [3.0, 4.0]],
                [-1e-3, 0.0],
            ),
        ] {
            let read = read_str(text, InputFormat::Text).unwrap();
            assert_eq!(read.input.points(), points, "{text}");
            assert_eq!(read.elevations.as_deref(), Some(&z[..]), "{text}");
            assert!(read.warnings.is_empty(), "{text}: {:?}", read.warnings);
        }
        // With other columns skipped, the warning says which one is z.
        let read = read_str("name,lon,lat,alt\nBern,7.4,46.9,540\n", InputFormat::Text).unwrap();
        assert_eq!(read.elevations, Some(vec![540.0]));
        assert_eq!(
            read.warnings,
            [
                "line 1: skipping 1 column 'name' (column 1); x and y are 'lon' and 'lat' \
                 (columns 2 and 3), the elevation is 'alt' (column 4)"
            ]
        );
        // Two-column files have none.
        assert_eq!(
            read_str("0 0\n1 0\n", InputFormat::Text)
                .unwrap()
                .elevations,
            None
        );
        // Mixing two and three columns is an error naming the line, either way.
        for (text, bad_line, counts) in [
            ("0 0 1\n1 0 2\n0 1\n", 3, ("2 columns", "line 1 has 3")),
            ("# c\n0 0\n1 0 5\n", 3, ("3 columns", "line 2 has 2")),
            ("x y z\n0 0 1\n1 0\n", 3, ("2 columns", "names 3")),
        ] {
            let (line, m) = line_of(points_of(text, InputFormat::Text).unwrap_err());
            assert_eq!(line, bad_line, "{text}: {m}");
            assert!(m.contains(counts.0) && m.contains(counts.1), "{text}: {m}");
        }
        // A bad elevation is named with its line, as a coordinate is.
        for (text, bad_line, needle) in [
            (
                "0 0 1\n1 0 nan\n",
                2,
                "elevation 'nan' is not a finite number",
            ),
            (
                "0 0 1\n1 0 1e999\n",
                2,
                "elevation '1e999' is not a finite number",
            ),
            (
                "0 0 1e300\n",
                1,
                "elevation '1e300' is outside the exact range",
            ),
            ("x,y,z\n0,0,\n", 2, "field 3 is empty"),
            (
                "x,y,z,name\n0,0,high,a\n",
                2,
                "elevation 'high' is not a number",
            ),
        ] {
            let (line, m) = line_of(points_of(text, InputFormat::Text).unwrap_err());
            assert_eq!(line, bad_line, "{text}: {m}");
            assert!(m.contains(needle), "{text}: {m}");
        }
        // Two elevation columns would be a guess.
        let (line, m) = line_of(points_of("x,y,z,alt\n0,0,1,2\n", InputFormat::Text).unwrap_err());
        assert_eq!(line, 1);
        assert!(
            m.contains("more than one elevation column ('z' in column 3 and 'alt' in column 4)"),
            "{m}"
        );
    }

    #[test]
    fn random_text_files_read_back_exactly_and_a_corruption_is_located() {
        use rand::{rngs::StdRng, Rng, SeedableRng};
        let mut rng = StdRng::seed_from_u64(11);
        for round in 0..200 {
            let n = rng.gen_range(1..30);
            let points: Vec<Point> = (0..n)
                .map(|_| {
                    let scale = [1.0, 1e-30, 1e40, 3.0][rng.gen_range(0..4)];
                    [
                        rng.gen_range(-1.0..1.0) * scale,
                        rng.gen_range(-5i32..5) as f64,
                    ]
                })
                .collect();
            let separators = [" ", "\t", ",", ";", " , ", "  "];
            let mut lines: Vec<String> = Vec::new();
            let mut data_lines = Vec::new();
            if rng.gen_bool(0.3) {
                lines.push("x y".into());
            }
            for p in &points {
                while rng.gen_bool(0.2) {
                    lines.push(["", "# comment 1 2", "   "][rng.gen_range(0..3)].into());
                }
                let sep = separators[rng.gen_range(0..separators.len())];
                let (x, y) = if rng.gen_bool(0.5) {
                    (format!("{}", p[0]), format!("{}", p[1]))
                } else {
                    (format!("{:e}", p[0]), format!("{:E}", p[1]))
                };
                let comment = if rng.gen_bool(0.2) { " # note" } else { "" };
                lines.push(format!("{x}{sep}{y}{comment}"));
                data_lines.push(lines.len());
            }
            let text = lines.join(if round % 2 == 0 { "\n" } else { "\r\n" });
            assert_eq!(
                points_of(&text, InputFormat::Text).unwrap(),
                points,
                "{text}"
            );
            // Corrupt one data line: the error names exactly that line.
            let k = rng.gen_range(0..data_lines.len());
            let bad = ["1.2.3", "nan", "-inf", "x1", "1e999", "0x10"][rng.gen_range(0..6)];
            let mut corrupted = lines.clone();
            corrupted[data_lines[k] - 1] = format!("{bad} 0");
            let (line, m) =
                line_of(points_of(&corrupted.join("\n"), InputFormat::Text).unwrap_err());
            assert_eq!(line, data_lines[k], "{m}");
            assert!(m.contains(bad), "{m}");
        }
    }
}
