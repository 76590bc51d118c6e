//! Tests of the JSON result documents.

use super::*;
use crate::io::{awkward_points, points_of, read_str, InputFormat};
use crate::{delaunay, triangulate, Criterion, PointSet};
use serde_json::json;

/// The fields of every triangulation document, in order.
const TRIANGULATION_FIELDS: &[&str] = &[
    "schema_version",
    "document",
    "domain",
    "points",
    "distinct_points",
    "duplicates",
    "stats",
    "triangles",
    "edges",
    "coordinates",
];
/// The fields a triangulation document has when it describes a run.
const RUN_FIELDS: &[&str] = &[
    "criterion",
    "exact",
    "optimality",
    "algorithm",
    "algorithm_detail",
    "diagnostics",
    "timing_ms",
];
const STATS_FIELDS: &[&str] = &[
    "max_edge_length",
    "longest_edge",
    "total_edge_length",
    "min_area",
    "max_area",
    "smallest_triangle",
    "largest_triangle",
    "min_angle_deg",
    "max_angle_deg",
    "min_height",
    "min_height_triangle",
    "max_eccentricity",
    "max_eccentricity_triangle",
    "triangles",
    "edges",
    "hull_points",
];
const GRAPH_FIELDS: &[&str] = &[
    "schema_version",
    "document",
    "points",
    "edges",
    "coordinates",
];
const GRAPH_RUN_FIELDS: &[&str] = &["kind", "distinct_points", "duplicates", "timing_ms"];

fn keys(v: &Value) -> Vec<&str> {
    let mut k: Vec<&str> = v.as_object().unwrap().keys().map(String::as_str).collect();
    k.sort_unstable();
    k
}

fn sorted(lists: &[&[&'static str]]) -> Vec<&'static str> {
    let mut k: Vec<&str> = lists.concat();
    k.sort_unstable();
    k
}

#[test]
fn json_round_trip_gives_the_same_triangulation() {
    let ps = PointSet::new(&awkward_points()).unwrap();
    let t = delaunay(&ps).unwrap();
    let text = serde_json::to_string(&TriangulationReport::new(&t).to_json()).unwrap();
    let back = triangulation_from_json(&serde_json::from_str(&text).unwrap()).unwrap();
    assert_eq!(back.points(), t.points());
    assert_eq!(back.triangles(), t.triangles());
    assert_eq!(back.point_set().duplicates(), &[[46, 3]]);
    // The points alone read back through the GeoJSON reader.
    assert_eq!(points_of(&text, InputFormat::GeoJson).unwrap(), t.points());
    // Tampering is caught: a flipped triangle no longer validates.
    let mut v = TriangulationReport::new(&t).to_json();
    v["triangles"][0] = json!([
        t.triangles()[0][1],
        t.triangles()[0][0],
        t.triangles()[0][2]
    ]);
    assert!(triangulation_from_json(&v).is_err());
    v["triangles"][0] = json!([0, 1, 999]);
    assert!(triangulation_from_json(&v).is_err());
}

#[test]
fn a_solution_document_has_every_field_in_order_and_reads_back() {
    let pts = awkward_points();
    let ps = PointSet::new(&pts).unwrap();
    let solution = triangulate(&ps, Criterion::Greedy).unwrap();
    let t = &solution.triangulation;
    let v = TriangulationReport::of_solution(&solution).to_json();
    assert_eq!(keys(&v), sorted(&[TRIANGULATION_FIELDS, RUN_FIELDS]));
    assert_eq!(keys(&v["stats"]), sorted(&[STATS_FIELDS]));
    assert_eq!(v["schema_version"], SCHEMA_VERSION);
    assert_eq!(v["document"], "triangulation");
    assert_eq!(v["criterion"], "greedy");
    assert_eq!(v["exact"], true);
    assert_eq!(v["optimality"], "exact");
    assert_eq!(v["algorithm"], solution.algorithm.as_str());
    assert_eq!(v["points"], pts.len());
    assert_eq!(v["distinct_points"], pts.len() - 1);
    assert_eq!(v["duplicates"], json!([[46, 3]]));
    assert_eq!(v["coordinates"], json!(pts));
    assert_eq!(v["triangles"], json!(t.triangles()));
    assert_eq!(v["edges"], json!(t.edges()));
    assert_eq!(v["stats"]["longest_edge"], json!(t.longest_edge()));
    assert_eq!(v["stats"]["triangles"], t.triangles().len());
    assert_eq!(v["diagnostics"], json!({}));
    for phase in &solution.phases {
        assert!(v["timing_ms"][phase.name].is_number(), "{}", phase.name);
    }
    // Serialised directly, the fields come in the documented order:
    // run facts first, the long arrays last.
    let text = serde_json::to_string(&TriangulationReport::of_solution(&solution)).unwrap();
    let order: Vec<usize> = [
        "\"schema_version\"",
        "\"criterion\"",
        "\"points\"",
        "\"stats\"",
        "\"timing_ms\"",
        "\"triangles\":[[",
        "\"coordinates\"",
    ]
    .iter()
    .map(|k| text.find(k).unwrap())
    .collect();
    assert!(order.windows(2).all(|w| w[0] < w[1]), "{order:?}");
    assert!(text.starts_with("{\"schema_version\":1,\"document\":\"triangulation\","));
    let back = triangulation_from_json(&v).unwrap();
    assert_eq!(back.triangles(), t.triangles());
    assert_eq!(points_of(&text, InputFormat::GeoJson).unwrap(), pts);
}

#[test]
fn decimal_documents_read_back_validated_on_their_decimals() {
    // Collinear as written; as doubles (0.2, 0.6) lies off the hull edge,
    // and on one side the two triangles would not cover the doubles' hull.
    // The reading validates where the writer decided, for both sides.
    for text in [
        "0.1 0.3\n0.2 0.6\n0.3 0.9\n0.3 0.1\n",
        "0.3 0.9\n0.2 0.6\n0.1 0.3\n-0.1 0.9\n",
        "0.1 0.7\n0.2 1.4\n0.3 2.1\n0 2\n",
        "0.1 0.7\n0.2 1.4\n0.3 2.1\n1 0\n",
    ] {
        let read = read_str(text, InputFormat::Text).unwrap();
        assert_eq!(read.arithmetic, Arithmetic::DecimalExact);
        let solution = triangulate(
            &PointSet::new(read.working_points()).unwrap(),
            Criterion::Greedy,
        )
        .unwrap();
        assert_eq!(solution.triangulation.triangles().len(), 2, "{text}");
        let v = TriangulationReport::of_solution(&solution)
            .with_input(&read)
            .to_json();
        assert_eq!(v["coordinate_arithmetic"], "decimal-exact");
        let back = triangulation_from_json(&v).unwrap();
        assert_eq!(back.triangles(), solution.triangulation.triangles());
        assert_eq!(back.points(), read.input.points(), "the user's values");
    }
    // A polygon document whose ring repeats its first vertex at the end
    // (found by the fuzzer: the closing vertex is dropped on both sides).
    let ring = [
        [0.0, 0.0],
        [0.2, 0.0],
        [0.2, 0.1],
        [0.1, 0.1],
        [0.0, 0.2],
        [0.0, 0.0],
    ];
    let v = json!({
        "domain": "polygon",
        "coordinates": ring,
        "triangles": [[0, 1, 2], [0, 2, 3], [0, 3, 4]],
    });
    let back = triangulation_from_json(&v).unwrap();
    assert_eq!(back.points(), &ring[..5]);
    assert_eq!(back.triangles().len(), 3);
}

#[test]
fn a_polygon_document_says_its_domain_and_reads_back() {
    // An L-shape, clockwise.
    let ring = [
        [0.0, 0.0],
        [0.0, 2.0],
        [1.0, 2.0],
        [1.0, 1.0],
        [2.0, 1.0],
        [2.0, 0.0],
    ];
    let polygon = SimplePolygon::new(&ring).unwrap();
    let solution = crate::triangulate(&polygon, Criterion::MinWeight).unwrap();
    let v = TriangulationReport::of_solution(&solution).to_json();
    assert_eq!(v["domain"], "polygon");
    assert_eq!(v["coordinates"], json!(ring));
    assert_eq!(v["triangles"].as_array().unwrap().len(), ring.len() - 2);
    let back = triangulation_from_json(&v).unwrap();
    assert_eq!(back.triangles(), solution.triangulation.triangles());
    assert_eq!(back.domain(), solution.triangulation.domain());
    let hull =
        TriangulationReport::new(&delaunay(&PointSet::new(&ring).unwrap()).unwrap()).to_json();
    assert_eq!(hull["domain"], "convex-hull");
    let mut odd = v.clone();
    odd["domain"] = json!("torus");
    let e = triangulation_from_json(&odd).unwrap_err().to_string();
    assert!(e.contains("torus"), "{e}");
}

#[test]
fn bare_documents_omit_the_run_fields() {
    let t = delaunay(&PointSet::new(&awkward_points()).unwrap()).unwrap();
    let v = TriangulationReport::new(&t).to_json();
    assert_eq!(keys(&v), sorted(&[TRIANGULATION_FIELDS]));
    let g = GraphReport::new(t.points(), &t.edges()).to_json();
    assert_eq!(keys(&g), sorted(&[GRAPH_FIELDS]));
    assert_eq!(g["document"], "graph");
    assert_eq!(g["points"], t.points().len());
}

#[test]
fn timing_keeps_the_phase_order_and_sums_a_repeated_phase() {
    let t = delaunay(&PointSet::new(&awkward_points()).unwrap()).unwrap();
    let phases = [
        Phase {
            name: "read",
            ms: 1.0,
        },
        Phase {
            name: "lower bound",
            ms: 0.25,
        },
        Phase {
            name: "rng",
            ms: 2.0,
        },
        Phase {
            name: "lower bound",
            ms: 0.5,
        },
    ];
    let report = TriangulationReport::new(&t).with_timing(&phases);
    let v = report.to_json();
    assert_eq!(keys(&v), sorted(&[TRIANGULATION_FIELDS, &["timing_ms"]]));
    assert_eq!(
        v["timing_ms"],
        json!({"read": 1.0, "lower bound": 0.75, "rng": 2.0})
    );
    let text = serde_json::to_string(&report).unwrap();
    assert!(
        text.contains(r#""timing_ms":{"read":1.0,"lower bound":0.75,"rng":2.0}"#),
        "{text}"
    );
}

#[test]
fn a_graph_document_has_its_kind_and_duplicates_and_reads_back_as_points() {
    let pts = awkward_points();
    let ps = PointSet::new(&pts).unwrap();
    let crate::PointGraph { edges, phases, .. } = crate::graph(
        ps.input_points(),
        GraphKind::Rng,
        &crate::Options::default(),
    )
    .unwrap();
    let v = GraphReport::of_graph(&ps, GraphKind::Rng, &edges)
        .with_timing(&phases)
        .to_json();
    assert_eq!(keys(&v), sorted(&[GRAPH_FIELDS, GRAPH_RUN_FIELDS]));
    assert_eq!(v["kind"], "rng");
    assert_eq!(v["points"], pts.len());
    assert_eq!(v["distinct_points"], ps.len());
    assert_eq!(v["duplicates"], json!([[46, 3]]));
    assert_eq!(v["edges"], json!(edges));
    assert!(v["timing_ms"]["rng"].is_number());
    assert_eq!(
        points_of(&v.to_string(), InputFormat::GeoJson).unwrap(),
        pts
    );
    // A graph is not a triangulation.
    let e = triangulation_from_json(&v).unwrap_err().to_string();
    assert!(
        e.contains("\"graph\"") && e.contains("not \"triangulation\""),
        "{e}"
    );
}

#[test]
fn documents_of_earlier_versions_read_back_and_newer_ones_are_refused() {
    let t = delaunay(&PointSet::new(&awkward_points()).unwrap()).unwrap();
    // What `-o x.json` wrote before schema version 1.
    let old = json!({
        "points": t.points(),
        "triangles": t.triangles(),
        "edges": t.edges(),
        "duplicates": t.point_set().duplicates(),
    });
    let back = triangulation_from_json(&old).unwrap();
    assert_eq!(back.triangles(), t.triangles());
    assert_eq!(back.point_set().duplicates(), &[[46, 3]]);
    assert_eq!(
        points_of(&old.to_string(), InputFormat::GeoJson).unwrap(),
        t.points()
    );
    let mut newer = TriangulationReport::new(&t).to_json();
    newer["schema_version"] = json!(SCHEMA_VERSION + 1);
    let e = triangulation_from_json(&newer).unwrap_err().to_string();
    assert!(e.contains("schema_version 2"), "{e}");
    // A `--json` document of a count without coordinates says so.
    let e = triangulation_from_json(&json!({"points": 3, "triangles": [[0, 1, 2]]}))
        .unwrap_err()
        .to_string();
    assert!(e.contains("no \"coordinates\""), "{e}");
}

#[test]
fn a_comparison_holds_each_run_document_unchanged_and_the_refusals() {
    use crate::{compare, Options};
    let ps = PointSet::new(&awkward_points()).unwrap();
    // Under L1, minmax-length runs and greedy refuses (no metric).
    let results = compare(
        &ps,
        &[Criterion::MinMaxLength, Criterion::Greedy],
        &Options::default().with_metric(crate::kernel::Metric::l1()),
    );
    let v = ComparisonReport::new(&results).to_json();
    assert_eq!(
        keys(&v),
        sorted(&[&["schema_version", "document", "results"]])
    );
    assert_eq!(v["document"], "comparison");
    let entries = v["results"].as_array().unwrap();
    assert_eq!(entries.len(), 2);
    let minmax = results[0].1.as_ref().unwrap();
    assert_eq!(
        entries[0],
        TriangulationReport::of_solution(minmax).to_json()
    );
    assert_eq!(entries[0]["metric"]["name"], "l1");
    let refusal = results[1].1.as_ref().unwrap_err();
    assert_eq!(
        entries[1],
        json!({"criterion": "greedy", "error": refusal.to_string()})
    );
    let phases = [Phase {
        name: "total",
        ms: 1.5,
    }];
    let timed = ComparisonReport::new(&results)
        .with_timing(&phases)
        .to_json();
    assert_eq!(timed["timing_ms"], json!({"total": 1.5}));
}

#[test]
fn the_highlighted_triangles_are_the_exact_extremes() {
    let t = delaunay(&PointSet::new(&awkward_points()).unwrap()).unwrap();
    let s = t.stats();
    let area = |tri: [u32; 3]| {
        let [a, b, c] = tri.map(|i| t.points()[i as usize]);
        crate::kernel::metrics::area(a, b, c)
    };
    assert!(t.triangles().contains(&s.smallest_triangle));
    assert_eq!(area(s.smallest_triangle), s.min_area);
    assert_eq!(area(s.largest_triangle), s.max_area);
    let v = TriangulationReport::new(&t).to_json();
    assert_eq!(v["stats"]["smallest_triangle"], json!(s.smallest_triangle));
    assert_eq!(v["stats"]["largest_triangle"], json!(s.largest_triangle));
}

#[test]
fn the_schema_document_names_every_field() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../../docs/json-schema.md");
    let doc = std::fs::read_to_string(path).unwrap();
    assert!(
        doc.contains(&format!("schema version {SCHEMA_VERSION}")),
        "{path}"
    );
    for field in [
        TRIANGULATION_FIELDS,
        RUN_FIELDS,
        STATS_FIELDS,
        GRAPH_FIELDS,
        GRAPH_RUN_FIELDS,
        &[
            "optimality_bound",
            "results",
            "error",
            "coordinate_arithmetic",
            "coordinate_scale",
        ],
    ]
    .concat()
    {
        assert!(
            doc.contains(&format!("`{field}`")),
            "{path} lacks `{field}`"
        );
    }
}
