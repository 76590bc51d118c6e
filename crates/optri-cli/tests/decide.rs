//! End-to-end tests of `optri decide`: the answer at an optimum that
//! `optri triangulate --json` reports is yes (with a witness meeting it
//! exactly), just past it no; convex, polygon, decimal and general inputs;
//! exit code 0 for every decided or unknown answer, 1 for errors.

use optri::io::{triangulation_from_json, Threshold};
use optri_oracle::{twice_area, BigInt, BigRational};
use serde_json::Value;
use std::path::PathBuf;
use std::process::{Command, Output};

const BIN: &str = env!("CARGO_BIN_EXE_optri");

fn scratch(test: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!("decide-{test}"));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn write(dir: &std::path::Path, name: &str, contents: &str) -> String {
    let path = dir.join(name);
    std::fs::write(&path, contents).unwrap();
    path.to_str().unwrap().to_string()
}

fn run(args: &[&str]) -> Output {
    Command::new(BIN).args(args).output().unwrap()
}

fn json(out: &Output) -> Value {
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).unwrap()
}

/// `text` as an exact rational.
fn rational(text: &str) -> BigRational {
    let (m, e) = Threshold::parse("t", text).unwrap().value();
    let ten = BigRational::from_integer(BigInt::from(10).pow(e.unsigned_abs() as u32));
    let m = BigRational::from_integer(BigInt::from(m));
    if e >= 0 {
        m * ten
    } else {
        m / ten
    }
}

/// The reported optimum of `criterion`, then the decision at it and just
/// past it (the next double, an exact decimal past it), all through the
/// binary; the witness is validated and meets the threshold exactly.
fn check_file(file: &str, criterion: &str) {
    let maxmin = criterion == "maxmin-area";
    let optimum = json(&run(&[
        "triangulate",
        file,
        "--criterion",
        criterion,
        "--json",
    ]));
    assert_eq!(optimum["exact"], true);
    let measure = if maxmin { "min_area" } else { "max_area" };
    let value = optimum["stats"][measure].as_f64().unwrap();
    let at = format!("{value}");
    let flag = if maxmin { "--at-least" } else { "--at-most" };
    let yes = json(&run(&[
        "decide",
        file,
        "--criterion",
        criterion,
        flag,
        &at,
        "--json",
    ]));
    assert_eq!(yes["document"], "decision");
    assert_eq!(yes["answer"], true, "{yes}");
    assert_eq!(yes["threshold"], optimum["stats"][measure]);
    let witness = triangulation_from_json(&yes["witness"]).unwrap();
    witness.validate().unwrap();
    let p = witness.points();
    let twice = rational(&at) * BigRational::from_integer(BigInt::from(2));
    // The witness's points are the user's coordinates: decimal areas
    // compared as the exact areas of the nearest doubles would not be
    // exact, so this check is for integer and binary inputs.
    if optimum["coordinate_scale"].is_null() {
        for t in witness.triangles() {
            let area = twice_area(p[t[0] as usize], p[t[1] as usize], p[t[2] as usize]);
            assert!(if maxmin { area >= twice } else { area <= twice });
        }
    }
    assert_eq!(yes["witness"]["stats"][measure], optimum["stats"][measure]);
    let next = if maxmin {
        f64::from_bits(value.to_bits() + 1)
    } else {
        f64::from_bits(value.to_bits() - 1)
    };
    let past_decimal = if maxmin {
        format!(
            "{at}{}000000000000000000001",
            if at.contains('.') { "" } else { "." }
        )
    } else {
        // Below: the decimal with its last digit lowered by a tiny amount.
        format!("{}", value - value * 1e-12)
    };
    for past in [format!("{next}"), past_decimal] {
        let no = run(&["decide", file, "--criterion", criterion, flag, &past]);
        assert!(no.status.success());
        let line = String::from_utf8_lossy(&no.stdout);
        assert!(line.starts_with("no: "), "{past}: {line}");
    }
    let line = run(&["decide", file, "--criterion", criterion, flag, &at]);
    assert!(String::from_utf8_lossy(&line.stdout).starts_with("yes: "));
}

#[test]
fn decisions_at_and_past_the_reported_optimum() {
    let dir = scratch("optimum");
    // A convex lens (integer), a convex polygon with collinear sides, a
    // simple polygon (Triangle .poly), decimal coordinates.
    let lens = write(
        &dir,
        "lens.txt",
        "-20 400\n20 400\n-7 49\n3 9\n11 121\n-15 575\n-2 796\n9 719\n16 544\n",
    );
    let collinear = write(
        &dir,
        "collinear.txt",
        "0 0\n3 0\n6 0\n8 2\n8 5\n5 7\n2 7\n0 4\n",
    );
    let poly = write(
        &dir,
        "comb.poly",
        "9 2 0 0\n1 0 0\n2 6 0\n3 6 4\n4 5 4\n5 4 1\n6 3 4\n7 2 1\n8 1 4\n9 0 4\n\
         9 0\n1 1 2\n2 2 3\n3 3 4\n4 4 5\n5 5 6\n6 6 7\n7 7 8\n8 8 9\n9 9 1\n0\n",
    );
    let decimal = write(
        &dir,
        "tenths.txt",
        "0.1 0.1\n0.7 0.1\n0.9 0.4\n0.6 0.9\n0.2 0.7\n0.05 0.4\n",
    );
    for file in [&lens, &collinear, &poly, &decimal] {
        check_file(file, "maxmin-area");
        check_file(file, "minmax-area");
    }
    // The convex lens is decided by Algorithm 49 in one shot.
    let doc = json(&run(&[
        "decide",
        &lens,
        "--criterion",
        "maxmin-area",
        "--at-least",
        "1",
        "--json",
    ]));
    assert!(doc["method"].as_str().unwrap().contains("Algorithm 49"));
    assert_eq!(doc["exact"], true);
}

#[test]
fn outputs_and_errors() {
    let dir = scratch("errors");
    let square = write(&dir, "square.txt", "0 0\n2 0\n2 2\n0 2\n");
    let witness = dir.join("witness.svg");
    let document = dir.join("decision.json");
    let out = run(&[
        "decide",
        &square,
        "--criterion",
        "maxmin-area",
        "--at-least",
        "2",
        "-o",
        witness.to_str().unwrap(),
        "-o",
        document.to_str().unwrap(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(std::fs::read_to_string(&witness).unwrap().contains("<svg"));
    let doc: Value = serde_json::from_str(&std::fs::read_to_string(&document).unwrap()).unwrap();
    assert_eq!(doc["answer"], true);
    // A no has no witness to draw.
    let out = run(&[
        "decide",
        &square,
        "--criterion",
        "maxmin-area",
        "--at-least",
        "2.5",
        "-o",
        witness.to_str().unwrap(),
    ]);
    assert_eq!(out.status.code(), Some(1));
    for (args, message) in [
        (
            vec!["--criterion", "maxmin-area", "--at-least", "-1"],
            "--at-least: '-1' is negative",
        ),
        (
            vec!["--criterion", "maxmin-area", "--at-least", "nan"],
            "--at-least: 'nan'",
        ),
        (
            vec!["--criterion", "maxmin-area", "--at-most", "1"],
            "--at-least: maxmin-area",
        ),
        (
            vec!["--criterion", "minmax-area", "--at-least", "1"],
            "--at-most: minmax-area",
        ),
        (
            vec![
                "--criterion",
                "minmax-area",
                "--at-least",
                "1",
                "--at-most",
                "2",
            ],
            "not both",
        ),
        (
            vec!["--criterion", "delaunay", "--at-least", "1"],
            "--criterion: delaunay",
        ),
        (vec!["--criterion", "nope", "--at-least", "1"], "nope"),
    ] {
        let mut all = vec!["decide", square.as_str()];
        all.extend(args);
        let out = run(&all);
        assert_eq!(out.status.code(), Some(1), "{all:?}");
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(stderr.contains(message), "{all:?}: {stderr}");
    }
}
