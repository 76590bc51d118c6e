//! `--metric` on `triangulate --criterion minmax-length` and `graph --kind
//! rng|mst`: the JSON names the metric and its longest edge, matches the
//! library, and bad metrics or criteria without metrics exit 1 with a message.

use serde_json::Value;
use std::io::Write;
use std::process::{Command, Output, Stdio};

const BIN: &str = env!("CARGO_BIN_EXE_optri");

/// A 5×4 integer grid (full of L1 and L∞ ties) plus two off-grid points.
const POINTS: &str = "0 0\n1 0\n2 0\n3 0\n4 0\n0 1\n1 1\n2 1\n3 1\n4 1\n0 2\n1 2\n2 2\n3 2\n4 2\n0 3\n1 3\n2 3\n3 3\n4 3\n1.5 4.5\n-1 1.5\n";

fn run_stdin(args: &[&str]) -> Output {
    let mut child = Command::new(BIN)
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let _ = child.stdin.take().unwrap().write_all(POINTS.as_bytes());
    child.wait_with_output().unwrap()
}

fn json(out: &Output) -> Value {
    assert!(
        out.status.success(),
        "stderr: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).unwrap()
}

fn library_points() -> optri::PointSet {
    let pts: Vec<[f64; 2]> = POINTS
        .lines()
        .map(|l| {
            let v: Vec<f64> = l.split_whitespace().map(|s| s.parse().unwrap()).collect();
            [v[0], v[1]]
        })
        .collect();
    optri::PointSet::new(&pts).unwrap()
}

#[test]
fn minmax_length_reports_the_metric_and_matches_the_library() {
    for metric in ["l1", "linf", "lp:3", "polygon:2,0,1,2,-1,2,-2,0,-1,-2,1,-2"] {
        let v = json(&run_stdin(&[
            "triangulate",
            "-",
            "--criterion",
            "minmax-length",
            "--metric",
            metric,
            "--json",
        ]));
        let m = optri::kernel::Metric::parse(metric).unwrap();
        assert_eq!(v["metric"]["name"], m.name().as_str());
        let options = optri::Options::default().with_metric(m);
        let s =
            optri::triangulate_with(&library_points(), optri::Criterion::MinMaxLength, &options)
                .unwrap();
        let (edge, length) = s.longest_edge_under_metric();
        assert_eq!(
            v["metric"]["max_edge_length"].as_f64().unwrap(),
            length,
            "{metric}"
        );
        assert_eq!(v["metric"]["longest_edge"], serde_json::json!(edge));
        assert_eq!(
            v["triangles"].as_array().unwrap().len(),
            s.triangulation.triangles().len()
        );
    }
    // The Euclidean default writes no metric field.
    let v = json(&run_stdin(&[
        "triangulate",
        "-",
        "--criterion",
        "minmax-length",
        "--json",
    ]));
    assert!(v.get("metric").is_none());
}

#[test]
fn graphs_take_a_metric() {
    for kind in ["hull", "rng", "mst"] {
        let v = json(&run_stdin(&[
            "graph", "-", "--kind", kind, "--metric", "linf", "--json",
        ]));
        assert_eq!(v["metric"], "linf");
        let options = optri::Options::default().with_metric(optri::kernel::Metric::linf());
        let k = optri::GraphKind::from_name(kind).unwrap();
        let edges = optri::graph(library_points().input_points(), k, &options)
            .unwrap()
            .edges;
        assert_eq!(v["edges"], serde_json::json!(edges));
    }
}

#[test]
fn bad_metrics_and_criteria_without_metrics_fail() {
    for (args, needle) in [
        (
            vec![
                "triangulate",
                "-",
                "--criterion",
                "delaunay",
                "--metric",
                "l1",
            ],
            "does not take a metric",
        ),
        (
            vec![
                "triangulate",
                "-",
                "--criterion",
                "maxmin-area",
                "--metric",
                "linf",
            ],
            "does not take a metric",
        ),
        (
            vec!["graph", "-", "--kind", "gabriel", "--metric", "l1"],
            "does not take a metric",
        ),
        (
            vec![
                "triangulate",
                "-",
                "--criterion",
                "minmax-length",
                "--metric",
                "lp:0",
            ],
            "exponent",
        ),
        (
            vec![
                "triangulate",
                "-",
                "--criterion",
                "minmax-length",
                "--metric",
                "l7",
            ],
            "unknown metric",
        ),
        (
            vec![
                "triangulate",
                "-",
                "--criterion",
                "minmax-length",
                "--metric",
                "polygon:1,0,0,1,-1,0,0,-2",
            ],
            "centrally symmetric",
        ),
        (
            vec![
                "triangulate",
                "-",
                "--criterion",
                "minmax-length",
                "--metric",
                "polygon:1,0,1,1,1,2,-1,0,-1,-1,-1,-2",
            ],
            "convex",
        ),
    ] {
        let out = run_stdin(&args);
        assert_eq!(out.status.code(), Some(1), "{args:?}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains(needle), "{args:?}: {err}");
    }
}
