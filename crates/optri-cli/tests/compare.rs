//! `optri compare` end to end: the table, the comparison document (each
//! result the document of `triangulate --json`), the SVG panels, and the
//! errors (unknown criterion lists the valid ones; non-zero exit).

use serde_json::Value;
use std::path::PathBuf;
use std::process::{Command, Output};

const BIN: &str = env!("CARGO_BIN_EXE_optri");

fn tsplib(name: &str) -> String {
    let path = optri_oracle::data_dir().join(format!("tsplib/{name}.tsp"));
    path.to_str().unwrap().to_string()
}

fn scratch(test: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!("compare-{test}"));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn run(args: &[&str]) -> Output {
    Command::new(BIN).args(args).output().unwrap()
}

fn stdout(out: &Output) -> String {
    assert!(
        out.status.success(),
        "stderr: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout.clone()).unwrap()
}

fn stderr(out: &Output) -> String {
    assert_eq!(out.status.code(), Some(1), "{out:?}");
    String::from_utf8(out.stderr.clone()).unwrap()
}

#[test]
fn the_json_holds_the_triangulate_json_of_every_criterion() {
    let file = tsplib("berlin52");
    let doc: Value = serde_json::from_str(&stdout(&run(&["compare", &file, "--json"]))).unwrap();
    assert_eq!(doc["document"], "comparison");
    assert!(doc["timing_ms"]["compare"].is_number());
    let results = doc["results"].as_array().unwrap();
    assert_eq!(results.len(), optri::Criterion::ALL.len());
    for (r, c) in results.iter().zip(optri::Criterion::ALL) {
        assert_eq!(r["criterion"], c.name());
        let single = run(&["triangulate", &file, "--criterion", c.name(), "--json"]);
        if r.get("error").is_some() {
            // Refused by compare, refused by triangulate, with the same message.
            let message = r["error"].as_str().unwrap();
            assert!(stderr(&single).contains(message), "{message}");
            continue;
        }
        let mut single: Value = serde_json::from_str(&stdout(&single)).unwrap();
        let mut r = r.clone();
        // Only the timings differ (the CLI's read/validate/total).
        single.as_object_mut().unwrap().remove("timing_ms");
        r.as_object_mut().unwrap().remove("timing_ms");
        assert_eq!(r, single, "{}", c.name());
        optri::io::triangulation_from_json(&r).unwrap();
    }
    // berlin52 has interior points: min-weight solves them exactly too.
    assert!(results
        .iter()
        .any(|r| r["criterion"] == "min-weight" && r["exact"] == true));
}

#[test]
fn the_table_marks_the_best_values_and_flags_approximations() {
    let file = tsplib("berlin52");
    let text = stdout(&run(&["compare", &file]));
    let header = text
        .lines()
        .find(|l| l.starts_with("criterion"))
        .unwrap_or_else(|| panic!("{text}"));
    for column in [
        "guarantee",
        "max edge",
        "total length",
        "min area",
        "max area",
        "min angle",
        "max angle",
        "time ms",
    ] {
        assert!(header.contains(column), "{header}");
    }
    let row = |name: &str| {
        text.lines()
            .find(|l| l.split_whitespace().next() == Some(name))
            .unwrap_or_else(|| panic!("no row {name}: {text}"))
            .to_string()
    };
    // Min-weight is the lightest (exact on general sets), greedy is not
    // marked, and every criterion's longest edge is the same hull edge here:
    // all marked.
    let greedy_row = row("greedy");
    let cells: Vec<&str> = greedy_row.split_whitespace().collect();
    assert_eq!(cells[1], "exact");
    assert_eq!(&cells[2..5], ["1515.73", "*", "31133.3"], "{greedy_row}");
    let weight_row = row("min-weight");
    let cells: Vec<&str> = weight_row.split_whitespace().collect();
    assert_eq!(cells[1], "exact");
    assert_eq!(
        &cells[2..6],
        ["1515.73", "*", "31042.7", "*"],
        "min-weight has the smallest total length: {text}"
    );
    assert!(row("maxmin-area").contains("approximation (!)"), "{text}");
    assert!(
        text.contains("(!) maxmin-area is not proven optimal"),
        "{text}"
    );
    // Only the criteria that read elevations refuse these 2-D points.
    for line in text.lines().filter(|l| l.starts_with("refused:")) {
        assert!(line.contains("needs an elevation"), "{text}");
    }
}

/// The `*` goes to the exact best, not to every value that looks best at
/// six digits: on a kite whose diagonals differ by 10⁻⁹, the
/// triangulations with the longer diagonal tie with the others in the max
/// edge and total length shown, but are not marked.
#[test]
fn the_best_values_are_decided_exactly() {
    let dir = scratch("exact-best");
    let kite = dir.join("kite.txt");
    std::fs::write(&kite, "-1.000000001 0\n1 0\n0.5 1\n0.5 -1\n").unwrap();
    let file = kite.to_str().unwrap();
    // Which diagonal is shorter, by the oracle's exact squared lengths of
    // the decimals (times 10^9, integers).
    let ac = optri_oracle::squared_length([-1_000_000_001.0, 0.0], [1e9, 0.0]);
    let bd = optri_oracle::squared_length([5e8, 1e9], [5e8, -1e9]);
    assert!(bd < ac);
    let doc: Value = serde_json::from_str(&stdout(&run(&["compare", file, "--json"]))).unwrap();
    let text = stdout(&run(&["compare", file]));
    let (mut long, mut short) = (0, 0);
    for r in doc["results"].as_array().unwrap() {
        let name = r["criterion"].as_str().unwrap();
        if r.get("error").is_some() {
            // A criterion that reads elevations refuses 2-D points.
            assert!(
                r["error"].as_str().unwrap().contains("needs an elevation"),
                "{r}"
            );
            continue;
        }
        let uses_ac = r["edges"]
            .as_array()
            .unwrap()
            .contains(&serde_json::json!([0, 1]));
        let line = text
            .lines()
            .find(|l| l.split_whitespace().next() == Some(name))
            .unwrap_or_else(|| panic!("no row {name}: {text}"));
        // Cells after the name and guarantee: a value, then `*` if marked.
        let tokens: Vec<&str> = line.split_whitespace().skip(2).collect();
        let mut marked = Vec::new();
        for (i, t) in tokens.iter().enumerate() {
            if *t != "*" {
                marked.push(tokens.get(i + 1) == Some(&"*"));
            }
        }
        let shown = |k: usize| tokens.iter().filter(|t| **t != "*").nth(k).copied();
        // Max edge and total length: the same six digits for every row.
        assert_eq!(shown(0), Some("2.00000"), "{line}");
        assert_eq!(shown(1), Some("7.84162"), "{line}");
        assert_eq!(marked[0], !uses_ac, "max edge: {text}");
        assert_eq!(marked[1], !uses_ac, "total length: {text}");
        if uses_ac {
            long += 1;
        } else {
            short += 1;
        }
    }
    assert!(long >= 1 && short >= 1, "{long} {short}");
}

#[test]
fn chosen_criteria_in_order_and_svg_panels() {
    let dir = scratch("svg");
    let svg = dir.join("compare.svg");
    let json = dir.join("compare.json");
    let file = tsplib("berlin52");
    let text = stdout(&run(&[
        "compare",
        &file,
        "--criteria",
        "greedy,DELAUNAY",
        "-o",
        svg.to_str().unwrap(),
        "-o",
        json.to_str().unwrap(),
    ]));
    let rows: Vec<&str> = text
        .lines()
        .filter_map(|l| l.split_whitespace().next())
        .filter(|w| ["greedy", "delaunay"].contains(w))
        .collect();
    assert_eq!(rows, ["greedy", "delaunay"], "{text}");
    assert!(text.contains("wrote "), "{text}");
    let picture = std::fs::read_to_string(&svg).unwrap();
    assert_eq!(picture.matches("<g class=\"panel\"").count(), 2);
    assert!(picture.contains("greedy (exact)"));
    let doc: Value = serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    assert_eq!(doc["results"].as_array().unwrap().len(), 2);
    // A polygon input compares the polygon criteria on its interior.
    let poly = dir.join("l.poly");
    std::fs::write(
        &poly,
        "6 2 0 0\n1 0 0\n2 0 2\n3 1 2\n4 1 1\n5 2 1\n6 2 0\n6 0\n1 1 2\n2 2 3\n3 3 4\n4 4 5\n5 5 6\n6 6 1\n0\n",
    )
    .unwrap();
    let doc: Value = serde_json::from_str(&stdout(&run(&[
        "compare",
        poly.to_str().unwrap(),
        "--json",
    ])))
    .unwrap();
    for r in doc["results"].as_array().unwrap() {
        if r.get("error").is_some() {
            assert!(
                r["error"].as_str().unwrap().contains("needs an elevation"),
                "{r}"
            );
            continue;
        }
        assert_eq!(r["domain"], "polygon", "{r}");
        assert_eq!(r["triangles"].as_array().unwrap().len(), 4);
    }
}

#[test]
fn errors_name_the_problem_and_exit_non_zero() {
    let file = tsplib("berlin52");
    let e = stderr(&run(&["compare", &file, "--criteria", "delaunay,fastest"]));
    assert!(
        e.contains("unknown criterion 'fastest'")
            && e.contains("available: delaunay, minmax-length"),
        "{e}"
    );
    let dir = scratch("errors");
    let e = stderr(&run(&[
        "compare",
        &file,
        "-o",
        dir.join("x.geojson").to_str().unwrap(),
    ]));
    assert!(e.contains("writes .svg") && e.contains(".json"), "{e}");
    let bad = dir.join("bad.txt");
    std::fs::write(&bad, "0 0\n1 1\nfoo 2\n").unwrap();
    let e = stderr(&run(&["compare", bad.to_str().unwrap()]));
    assert!(e.contains("bad.txt:3: 'foo' is not a number"), "{e}");
    let collinear = dir.join("line.txt");
    std::fs::write(&collinear, "0 0\n1 1\n2 2\n").unwrap();
    let e = stderr(&run(&["compare", collinear.to_str().unwrap()]));
    assert!(e.contains("collinear"), "{e}");
}
