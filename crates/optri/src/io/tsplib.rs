//! TSPLIB `.tsp` files with a `NODE_COORD_SECTION` ([`InputFormat::Tsplib`]).
//!
//! [`InputFormat::Tsplib`]: super::InputFormat::Tsplib

use super::{parse, quoted, shown, Collected};
use crate::error::Result;

pub(super) fn read_tsplib(text: &str) -> Result<Collected> {
    let mut dimension: Option<(usize, usize)> = None;
    let mut in_coordinates = false;
    let mut section_line = None;
    let mut points = Collected::default();
    let mut last_id = 0usize;
    for (i, raw) in text.lines().enumerate() {
        let line = i + 1;
        let trimmed = raw.trim();
        if trimmed.is_empty() {
            continue;
        }
        if trimmed == "EOF" {
            break;
        }
        let first = trimmed
            .split_whitespace()
            .next()
            .unwrap_or("")
            .trim_end_matches(':');
        if in_coordinates && !first.ends_with("_SECTION") {
            let tokens: Vec<&str> = trimmed.split_whitespace().collect();
            if tokens.len() != 3 {
                return Err(parse(
                    line,
                    format!(
                        "expected 'id x y' in NODE_COORD_SECTION, found {} fields",
                        tokens.len()
                    ),
                ));
            }
            let id: usize = tokens[0].parse().map_err(|_| {
                parse(
                    line,
                    format!("node id {} is not an integer", quoted(tokens[0])),
                )
            })?;
            if id != last_id + 1 {
                return Err(parse(
                    line,
                    format!("node id {id} out of sequence (expected {})", last_id + 1),
                ));
            }
            last_id = id;
            points.push(tokens[1], tokens[2], line)?;
            continue;
        }
        if in_coordinates {
            // Another section follows the coordinates (e.g. a tour); the
            // points are complete.
            break;
        }
        if first == "NODE_COORD_SECTION" {
            in_coordinates = true;
            section_line = Some(line);
            continue;
        }
        if first.ends_with("_SECTION") {
            return Err(parse(
                line,
                format!(
                    "{} before any NODE_COORD_SECTION: the file has no coordinates",
                    shown(first, "")
                ),
            ));
        }
        let Some((key, value)) = trimmed.split_once(':') else {
            return Err(parse(
                line,
                format!(
                    "expected a header line 'KEY : VALUE', found {}",
                    quoted(trimmed)
                ),
            ));
        };
        let (key, value) = (key.trim(), value.trim());
        match key {
            "DIMENSION" => {
                let n = value.parse().map_err(|_| {
                    parse(
                        line,
                        format!("DIMENSION {} is not a non-negative integer", quoted(value)),
                    )
                })?;
                dimension = Some((n, line));
            }
            "EDGE_WEIGHT_TYPE" => match value {
                "EUC_2D" | "ATT" | "GEO" | "CEIL_2D" | "MAN_2D" | "MAX_2D" => {}
                _ => {
                    return Err(parse(
                        line,
                        format!(
                            "EDGE_WEIGHT_TYPE {} has no planar coordinates; \
                             supported: EUC_2D, CEIL_2D, MAN_2D, MAX_2D, ATT, GEO",
                            shown(value, "")
                        ),
                    ))
                }
            },
            "NODE_COORD_TYPE" if value != "TWOD_COORDS" => {
                return Err(parse(
                    line,
                    format!(
                        "NODE_COORD_TYPE {} is not supported (only TWOD_COORDS)",
                        shown(value, "")
                    ),
                ))
            }
            _ => {}
        }
    }
    let Some(section_line) = section_line else {
        return Err(parse(
            0,
            "no NODE_COORD_SECTION found: the file has no coordinates",
        ));
    };
    if let Some((n, line)) = dimension {
        if n != points.points.len() {
            return Err(parse(
                line,
                format!(
                    "DIMENSION is {n}, but NODE_COORD_SECTION (line {section_line}) has {} nodes",
                    points.points.len()
                ),
            ));
        }
    }
    Ok(points)
}

#[cfg(test)]
mod tests {
    use crate::io::{line_of, points_of, read, InputFormat, ReadOptions, Source};

    #[test]
    fn tsplib_headers_sections_and_errors() {
        let text = "NAME : t\nTYPE: TSP\nDIMENSION : 3\nEDGE_WEIGHT_TYPE : EUC_2D\n\
                    NODE_COORD_SECTION\n 1 0 0\n2 1.5e+01 0\n3 0 -2\nEOF\n\n";
        assert_eq!(
            points_of(text, InputFormat::Tsplib).unwrap(),
            vec![[0.0, 0.0], [15.0, 0.0], [0.0, -2.0]]
        );
        // No EOF line is fine (pr1002 has none).
        let text = "DIMENSION: 1\nNODE_COORD_SECTION\n1 4 5\n";
        assert_eq!(
            points_of(text, InputFormat::Tsplib).unwrap(),
            vec![[4.0, 5.0]]
        );
        let (line, m) = line_of(
            points_of(
                "DIMENSION: 3\nNODE_COORD_SECTION\n1 0 0\n2 1 1\nEOF\n",
                InputFormat::Tsplib,
            )
            .unwrap_err(),
        );
        assert_eq!(line, 1);
        assert!(m.contains("DIMENSION is 3"), "{m}");
        let (line, m) = line_of(
            points_of(
                "DIMENSION: 2\nEDGE_WEIGHT_TYPE: EXPLICIT\nEDGE_WEIGHT_SECTION\n0 1\n",
                InputFormat::Tsplib,
            )
            .unwrap_err(),
        );
        assert_eq!(line, 2);
        assert!(m.contains("EXPLICIT"), "{m}");
        let (line, _) = line_of(
            points_of("NODE_COORD_SECTION\n1 0 0\n2 x 1\n", InputFormat::Tsplib).unwrap_err(),
        );
        assert_eq!(line, 3);
        let (line, _) = line_of(points_of("NAME: x\n", InputFormat::Tsplib).unwrap_err());
        assert_eq!(line, 0);
    }

    /// The points of the file at `path`, its format by extension.
    fn file_points(path: &std::path::Path) -> Vec<crate::kernel::Point> {
        read(Source::Path(path), &ReadOptions::default())
            .unwrap()
            .input
            .points()
            .to_vec()
    }

    #[test]
    fn every_shared_tsplib_file_reads_with_its_dimension() {
        // (file, DIMENSION) from the data folder's tsplib/README.md.
        let expected = [
            ("berlin52", 52),
            ("kroA100", 100),
            ("ch150", 150),
            ("a280", 280),
            ("lin318", 318),
            ("pr1002", 1002),
            ("u1060", 1060),
            ("vm1084", 1084),
            ("pcb3038", 3038),
            ("fl1577", 1577),
            ("fnl4461", 4461),
            ("att532", 532),
            ("ali535", 535),
            ("ts225", 225),
        ];
        let dir = optri_oracle::data_dir().join("tsplib");
        for (name, n) in expected {
            let path = dir.join(format!("{name}.tsp"));
            let points = file_points(&path);
            assert_eq!(points.len(), n, "{name}");
            assert_eq!(
                InputFormat::sniff(&std::fs::read_to_string(&path).unwrap()),
                InputFormat::Tsplib
            );
        }
        // Spot checks against the files' text.
        let a280 = file_points(&dir.join("a280.tsp"));
        assert_eq!(a280[170], a280[171]);
        let ali = file_points(&dir.join("ali535.tsp"));
        assert_eq!(ali[3], [5.15, -3.56]);
        let berlin = file_points(&dir.join("berlin52.tsp"));
        assert_eq!(berlin[51], [1740.0, 245.0]);
    }
}
