//! Plain text point files: one `x y` per line ([`InputFormat::Text`]).
//!
//! [`InputFormat::Text`]: super::InputFormat::Text

use super::{parse, strip_comment, Collected};
use crate::error::Result;

/// The fields of one text line. Whitespace runs separate fields, and so does
/// each comma or semicolon (with any whitespace around it); an empty field
/// between two of them, or before or after one, is an error: skipping it
/// would silently shift the columns (`1,,0` would read as `1 0`).
fn text_fields(line_text: &str, line: usize) -> Result<Vec<&str>> {
    let trimmed = line_text.trim();
    if trimmed.is_empty() {
        return Ok(Vec::new());
    }
    let mut fields = Vec::new();
    for part in trimmed.split([',', ';']) {
        let before = fields.len();
        fields.extend(part.split_whitespace());
        if fields.len() == before {
            return Err(parse(
                line,
                format!(
                    "field {} is empty (two separators in a row, or one at the start or end \
                     of the line); every field must hold a number",
                    before + 1
                ),
            ));
        }
    }
    Ok(fields)
}

pub(super) fn read_text(text: &str) -> Result<Collected> {
    let mut points = Collected::default();
    // Column count of the first data row and its line, to report ragged rows.
    let mut columns: Option<(usize, usize)> = None;
    let mut seen_content = false;
    // Columns of x and y: named by the header, else the first two.
    let mut xy_columns = [0, 1];
    let mut header_columns = None;
    for (i, raw) in text.lines().enumerate() {
        let line = i + 1;
        let tokens = text_fields(strip_comment(raw), line)?;
        if tokens.is_empty() {
            continue;
        }
        let first_content = !seen_content;
        seen_content = true;
        // A header (e.g. `x,y`) is allowed only as the first content line and
        // only when none of its tokens is a number.
        if first_content && tokens.iter().all(|t| t.parse::<f64>().is_err()) {
            let named = |name: &str| tokens.iter().position(|t| t.eq_ignore_ascii_case(name));
            if let (Some(x), Some(y)) = (named("x"), named("y")) {
                xy_columns = [x, y];
                header_columns = Some((tokens.len(), line));
            }
            continue;
        }
        match columns {
            None => {
                if tokens.len() < 2 {
                    return Err(parse(
                        line,
                        format!("expected 'x y', found a single value '{}'", tokens[0]),
                    ));
                }
                if let Some((n, header)) = header_columns.filter(|&(n, _)| n != tokens.len()) {
                    return Err(parse(
                        line,
                        format!(
                            "{} columns, but the header on line {header} names {n}",
                            tokens.len()
                        ),
                    ));
                }
                columns = Some((tokens.len(), line));
                if header_columns.is_none() && tokens.len() > 2 {
                    points.warnings.push(ignored_columns(tokens.len(), line));
                }
            }
            Some((n, first)) if n != tokens.len() => {
                return Err(parse(
                    line,
                    format!(
                        "{} column{}, but line {first} has {n}; every row must have the same number \
                         of columns",
                        tokens.len(),
                        if tokens.len() == 1 { "" } else { "s" }
                    ),
                ));
            }
            Some(_) => {}
        }
        // Extra columns must still be numbers, so a stray word is not ignored.
        for (k, t) in tokens.iter().enumerate() {
            if !xy_columns.contains(&k) {
                t.parse::<f64>()
                    .map_err(|_| parse(line, format!("'{t}' is not a number")))?;
            }
        }
        points.push(tokens[xy_columns[0]], tokens[xy_columns[1]], line)?;
    }
    Ok(points)
}

/// The warning for rows of `columns > 2` values without a header naming
/// `x` and `y` (e.g. an `x y z` cloud): the first two are read.
fn ignored_columns(columns: usize, line: usize) -> String {
    let ignored = if columns == 3 {
        "column 3".to_string()
    } else {
        format!("columns 3 to {columns}")
    };
    format!(
        "line {line}: rows have {columns} columns and no header names them; reading columns 1 \
         and 2 as x y and ignoring {ignored} (a header line such as `x y z` names them)"
    )
}

#[cfg(test)]
mod tests {
    use crate::io::{line_of, read_points, read_points_exact, InputFormat};
    use crate::kernel::Point;

    #[test]
    fn text_accepts_separators_comments_and_a_header() {
        let text = "x,y\n# a comment\n1 2\n\n3,4 # trailing\n5\t6\n7;8\n";
        assert_eq!(
            read_points(text, InputFormat::Text).unwrap(),
            vec![[1.0, 2.0], [3.0, 4.0], [5.0, 6.0], [7.0, 8.0]]
        );
        // Consistent extra columns are allowed; x, y are the first two, with
        // a warning naming what is ignored unless a header names the columns.
        let read = read_points_exact("1 2 9\n3 4 9\n", InputFormat::Text).unwrap();
        assert_eq!(read.input.points(), [[1.0, 2.0], [3.0, 4.0]]);
        assert_eq!(
            read.warnings,
            [
                "line 1: rows have 3 columns and no header names them; reading columns 1 and 2 \
              as x y and ignoring column 3 (a header line such as `x y z` names them)"
            ]
        );
        let read = read_points_exact("# c\n1 2 9 8\n3 4 9 8\n", InputFormat::Text).unwrap();
        assert!(
            read.warnings[0].starts_with("line 2:") && read.warnings[0].contains("columns 3 to 4")
        );
        for named in ["x y z\n1 2 9\n3 4 9\n", "1 2\n3 4\n"] {
            assert!(read_points_exact(named, InputFormat::Text)
                .unwrap()
                .warnings
                .is_empty());
        }
        assert_eq!(
            read_points("\u{feff}-1e3 2.5E-2\r\n", InputFormat::Text).unwrap(),
            vec![[-1000.0, 0.025]]
        );
        // A header naming x and y picks those columns.
        assert_eq!(
            read_points("id;Y;X\n1;2;3\n2;5;6\n", InputFormat::Text).unwrap(),
            vec![[3.0, 2.0], [6.0, 5.0]]
        );
        let (line, m) = line_of(read_points("id,x,y\n1,2\n", InputFormat::Text).unwrap_err());
        assert_eq!(line, 2);
        assert!(m.contains("header on line 1"), "{m}");
    }

    #[test]
    fn text_errors_name_the_line_and_the_token() {
        let (line, m) = line_of(read_points("0 0\n1 1\n2 oops\n", InputFormat::Text).unwrap_err());
        assert_eq!(line, 3);
        assert!(m.contains("'oops'"), "{m}");
        let (line, m) = line_of(read_points("0 0\n1 1 1\n", InputFormat::Text).unwrap_err());
        assert_eq!(line, 2);
        assert!(m.contains("line 1"), "{m}");
        let (line, _) = line_of(read_points("0 0\n1 nan\n", InputFormat::Text).unwrap_err());
        assert_eq!(line, 2);
        let (line, m) = line_of(read_points("0 0\n\n-inf 1\n", InputFormat::Text).unwrap_err());
        assert_eq!(line, 3);
        assert!(m.contains("finite"), "{m}");
        // Overflowing literals become infinite and are rejected, as are values
        // outside the exact range.
        let (line, _) = line_of(read_points("1e400 0\n", InputFormat::Text).unwrap_err());
        assert_eq!(line, 1);
        let (line, m) = line_of(read_points("1 2\n1e100 0\n", InputFormat::Text).unwrap_err());
        assert_eq!(line, 2);
        assert!(m.contains("range"), "{m}");
        let (line, _) = line_of(read_points("1\n", InputFormat::Text).unwrap_err());
        assert_eq!(line, 1);
        // A header is only allowed at the top.
        let (line, _) = line_of(read_points("1 2\nx y\n", InputFormat::Text).unwrap_err());
        assert_eq!(line, 2);
        let (line, m) = line_of(read_points("# only\n\nx y\n", InputFormat::Text).unwrap_err());
        assert_eq!(line, 0);
        assert!(m.contains("no points"), "{m}");
        assert_eq!(
            line_of(read_points("", InputFormat::Text).unwrap_err()).0,
            0
        );
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
            let (line, m) = line_of(read_points(text, InputFormat::Text).unwrap_err());
            assert_eq!(line, bad_line, "{text:?}: {m}");
            assert!(m.contains("empty"), "{m}");
        }
        assert_eq!(
            read_points("0 \t 0\n\t1   0  \n0,\t1 # c,,\n", InputFormat::Text).unwrap(),
            vec![[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]
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
                read_points(&text, InputFormat::Text).unwrap(),
                points,
                "{text}"
            );
            // Corrupt one data line: the error names exactly that line.
            let k = rng.gen_range(0..data_lines.len());
            let bad = ["1.2.3", "nan", "-inf", "x1", "1e999", "0x10"][rng.gen_range(0..6)];
            let mut corrupted = lines.clone();
            corrupted[data_lines[k] - 1] = format!("{bad} 0");
            let (line, m) =
                line_of(read_points(&corrupted.join("\n"), InputFormat::Text).unwrap_err());
            assert_eq!(line, data_lines[k], "{m}");
            assert!(m.contains(bad), "{m}");
        }
    }
}
