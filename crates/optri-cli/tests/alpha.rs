//! `--alpha` and `--approximation` on `triangulate --criterion
//! maxmin-area|minmax-area`: the JSON reports the approximation, α*, the α
//! used and the guarantee, every angle meets α, and α above α* or an
//! unknown approximation exit 1 with a message.

use serde_json::Value;
use std::io::Write;
use std::process::{Command, Output, Stdio};

const BIN: &str = env!("CARGO_BIN_EXE_optri");

/// Scattered integer points (not in convex position).
const POINTS: &str = "0 0\n9 1\n17 0\n20 8\n16 17\n8 20\n1 14\n6 6\n12 5\n14 11\n7 13\n10 9\n";

fn run(args: &[&str]) -> Output {
    let mut child = Command::new(BIN)
        .args(["triangulate", "-", "--json"])
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

#[test]
fn alpha_and_approximation_reach_the_report() {
    let base = json(&run(&["--criterion", "minmax-area"]));
    let report = &base["approximation"];
    assert_eq!(report["choice"], "best");
    assert!(report["alpha"].is_null());
    let star = report["delaunay_smallest_angle"]["degrees"]
        .as_f64()
        .unwrap();
    assert_eq!(
        report["delaunay_smallest_angle"]["corner"]
            .as_array()
            .unwrap()
            .len(),
        3
    );
    let alpha = ((star / 2.0) * 100.0).floor() / 100.0;
    let text = alpha.to_string();
    for criterion in ["minmax-area", "maxmin-area"] {
        let v = json(&run(&[
            "--criterion",
            criterion,
            "--alpha",
            &text,
            "--approximation",
            "thesis-76",
        ]));
        let report = &v["approximation"];
        assert_eq!(report["choice"], "thesis-76");
        assert_eq!(report["alpha"].as_f64(), Some(alpha));
        assert_eq!(report["candidates"].as_array().unwrap().len(), 1);
        assert!(report["flips"].is_u64());
        assert!(v["stats"]["min_angle_deg"].as_f64().unwrap() >= alpha);
        let guarantee = &report["guarantee"];
        assert!(guarantee["statement"].is_string());
        if guarantee["kind"] == "approximation" {
            assert!(!guarantee["theorem_81"].as_array().unwrap().is_empty());
        }
    }
}

#[test]
fn alpha_above_the_delaunay_angle_and_unknown_approximations_exit_1() {
    let out = run(&["--criterion", "maxmin-area", "--alpha", "61"]);
    assert_eq!(out.status.code(), Some(1));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains("--alpha") || stderr.contains("α* = "),
        "{stderr}"
    );
    assert!(stderr.contains("α* = "), "{stderr}");
    let out = run(&["--criterion", "maxmin-area", "--approximation", "thesis-77"]);
    assert_eq!(out.status.code(), Some(1));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains("thesis-76"), "{stderr}");
    let out = run(&["--criterion", "delaunay", "--alpha", "10"]);
    assert_eq!(out.status.code(), Some(1));
}
