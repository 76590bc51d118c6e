//! Decimal input is taken at its value: points collinear as written stay
//! collinear (the hull keeps them as boundary points, no criterion returns a
//! triangle that is flat in decimal terms), checked against integer
//! arithmetic on the decimals, independently of the reader's scaling.

use optri::io::{read, Arithmetic, InputFormat, ReadInput, ReadOptions, Source};
use optri::{graph, triangulate, Criterion, GraphKind, PointSet};
use rand::{rngs::StdRng, Rng, SeedableRng};

/// `text` read in `format` as points, with its decimal values.
fn read_points_exact(text: &str, format: InputFormat) -> optri::Result<ReadInput> {
    read(
        Source::Text(text),
        &ReadOptions::default().with_format(format),
    )
}

/// `v / 10^k` written as a decimal with `k` places.
fn decimal(v: i64, k: u32) -> String {
    let p = 10i64.pow(k);
    let sign = if v < 0 { "-" } else { "" };
    format!(
        "{sign}{}.{:0width$}",
        v.abs() / p,
        v.abs() % p,
        width = k as usize
    )
}

/// Twice the signed area of integer points, exactly.
fn orient(a: [i64; 2], b: [i64; 2], c: [i64; 2]) -> i128 {
    let (a, b, c) = (a.map(i128::from), b.map(i128::from), c.map(i128::from));
    (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
}

/// Asserts that no triangle of `triangles` is flat or clockwise over the
/// integer points `ints` (the decimals times 10^k).
fn assert_no_flat_triangle(triangles: &[[u32; 3]], ints: &[[i64; 2]], what: &str) {
    for t in triangles {
        let [a, b, c] = t.map(|i| ints[i as usize]);
        assert!(
            orient(a, b, c) > 0,
            "{what}: triangle {t:?} is flat as written"
        );
    }
}

#[test]
fn points_collinear_as_written_stay_collinear() {
    let mut rng = StdRng::seed_from_u64(14);
    let (mut cases, mut binary_not_collinear) = (0, 0);
    for _ in 0..300 {
        let k = rng.gen_range(1..=3u32);
        // A run of three points p, p + d, p + 2d (collinear as written) on
        // the hull, and points on one side of its line.
        let p = [rng.gen_range(-900..900i64), rng.gen_range(-900..900i64)];
        let d = [rng.gen_range(1..300i64), rng.gen_range(-300..300i64)];
        let mut ints = vec![
            p,
            [p[0] + d[0], p[1] + d[1]],
            [p[0] + 2 * d[0], p[1] + 2 * d[1]],
        ];
        // Normal pointing to the left of d: the other points go there.
        let n = [-d[1], d[0]];
        for _ in 0..rng.gen_range(2..7) {
            let (s, t) = (rng.gen_range(0..=200i64), rng.gen_range(1..=3i64));
            ints.push([
                p[0] + s * d[0] / 100 + t * n[0],
                p[1] + s * d[1] / 100 + t * n[1],
            ]);
        }
        let text: String = ints
            .iter()
            .map(|q| format!("{} {}\n", decimal(q[0], k), decimal(q[1], k)))
            .collect();
        let read = read_points_exact(&text, InputFormat::Text).unwrap();
        assert_eq!(read.arithmetic, Arithmetic::DecimalExact, "{text}");
        let Ok(points) = PointSet::new(read.working_points()) else {
            continue; // a point landed on another
        };
        if !points.duplicates().is_empty() {
            continue;
        }
        // Did rounding to doubles break the collinearity? (Then the test
        // would fail without decimal exactness.)
        let doubles = read.input.points();
        if optri::kernel::orient_sign(doubles[0], doubles[1], doubles[2]) != 0 {
            binary_not_collinear += 1;
        }
        cases += 1;
        // p + d is on the hull as written (every other point is on or to
        // the left of the line), so the hull keeps it as a vertex.
        assert!(ints.iter().all(|&q| orient(ints[0], ints[2], q) >= 0));
        let hull = graph(
            read.working_points(),
            GraphKind::Hull,
            &optri::Options::default(),
        )
        .unwrap();
        assert!(
            hull.edges.iter().any(|e| e[0] == 1),
            "{text}: the middle point is on the hull as written"
        );
        for criterion in [
            Criterion::Delaunay,
            Criterion::MinMaxLength,
            Criterion::Greedy,
        ] {
            let solution = triangulate(&points, criterion).unwrap();
            solution.triangulation.validate().unwrap();
            assert_no_flat_triangle(solution.triangulation.triangles(), &ints, &text);
        }
    }
    assert!(cases >= 250, "{cases}");
    assert!(
        binary_not_collinear >= 50,
        "{binary_not_collinear} of {cases}"
    );
}

#[test]
fn the_classic_tenths_are_collinear() {
    let text = "0.1 0.3\n0.2 0.6\n0.3 0.9\n0.3 0.1\n";
    let read = read_points_exact(text, InputFormat::Text).unwrap();
    assert_eq!(read.arithmetic, Arithmetic::DecimalExact);
    assert_eq!(read.scale_exponent(), 1);
    assert_eq!(read.working_points()[2], [3.0, 9.0]);
    // As doubles, 0.1·3 is not 0.3: the three points are not collinear.
    let d = read.input.points();
    assert_ne!(optri::kernel::orient_sign(d[0], d[1], d[2]), 0);
    let points = PointSet::new(read.working_points()).unwrap();
    for criterion in [
        Criterion::Delaunay,
        Criterion::MinMaxLength,
        Criterion::Greedy,
    ] {
        let t = triangulate(&points, criterion).unwrap().triangulation;
        // Collinear as written: (0.2, 0.6) is a hull vertex and the one
        // triangle that would be flat is absent.
        assert_eq!(t.triangles().len(), 2, "{criterion:?}");
        assert_eq!(t.stats().hull_points, 4);
    }
}

#[test]
fn drilling_file_fl1577_has_no_flat_triangle_as_written() {
    // fl1577 writes `1.21488e+03` (two places) and `2.66e+02`-like values
    // with up to three places.
    let path = optri_oracle::data_dir().join("tsplib/fl1577.tsp");
    let text = std::fs::read_to_string(&path).unwrap();
    let read = read_points_exact(&text, InputFormat::Tsplib).unwrap();
    assert_eq!(read.arithmetic, Arithmetic::DecimalExact);
    let k = read.scale_exponent();
    assert_eq!(k, 3);
    // The integers, computed independently of the reader's scaler.
    let ints: Vec<[i64; 2]> = read
        .input
        .points()
        .iter()
        .map(|p| p.map(|v| (v * 10f64.powi(k)).round() as i64))
        .collect();
    for (w, i) in read.working_points().iter().zip(&ints) {
        assert_eq!(w.map(|v| v as i64), *i);
    }
    let points = PointSet::new(read.working_points()).unwrap();
    for criterion in [Criterion::Delaunay, Criterion::Greedy] {
        let t = triangulate(&points, criterion).unwrap().triangulation;
        t.validate().unwrap();
        assert_no_flat_triangle(t.triangles(), &ints, "fl1577");
    }
}

#[test]
fn inputs_that_do_not_scale_are_binary64() {
    for text in [
        "0.1 0.1\n1 0\n0 0.12345678901234567\n",
        "1e20 0\n0 1\n1 1\n0.5 0\n",
        "0x10 0\n",
    ] {
        match read_points_exact(text, InputFormat::Text) {
            Ok(read) => {
                assert_eq!(read.arithmetic, Arithmetic::Binary64, "{text}");
                assert!(read.scaled.is_none());
            }
            Err(e) => assert!(e.to_string().contains("not a number"), "{e}"),
        }
    }
    // GeoJSON: short literals are decimals; a long one makes the document binary64.
    let short = r#"{"type":"MultiPoint","coordinates":[[0.1,0.3],[0.2,0.6],[0.3,0.9],[0.3,0.1]]}"#;
    let read = read_points_exact(short, InputFormat::GeoJson).unwrap();
    assert_eq!(
        (read.arithmetic, read.scale_exponent()),
        (Arithmetic::DecimalExact, 1)
    );
    let long = short.replace("0.1]", "0.10000000000000001]");
    let read = read_points_exact(&long, InputFormat::GeoJson).unwrap();
    assert_eq!(read.arithmetic, Arithmetic::Binary64);
    // .node files and polygons keep their decimals too, in ring order.
    let node = "4 2 0 0\n0 0.1 0.3\n1 0.2 0.6\n2 0.3 0.9\n3 0.3 0.1\n";
    let read = read_points_exact(node, InputFormat::Node).unwrap();
    assert_eq!(read.working_points()[1], [2.0, 6.0]);
    let poly = "3 2\n1 0.5 0\n2 0 0.25\n3 0 0\n3 0\n1 1 3\n2 3 2\n3 2 1\n";
    let options = ReadOptions::default()
        .with_format(InputFormat::Poly)
        .with_polygons(true);
    let read = optri::io::read(Source::Text(poly), &options).unwrap();
    assert_eq!(
        read.working_points(),
        [[50.0, 0.0], [0.0, 0.0], [0.0, 25.0]]
    );
    assert_eq!(read.input.points(), [[0.5, 0.0], [0.0, 0.0], [0.0, 0.25]]);
}
