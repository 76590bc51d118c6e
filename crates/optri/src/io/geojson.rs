//! GeoJSON: the reader of `Point`/`MultiPoint` geometries
//! ([`InputFormat::GeoJson`]) and the writers of triangulations (`Polygon`s)
//! and graphs (`LineString`s), both with their points as `Point`s so that
//! they read back.
//!
//! A position's optional third value is the point's elevation
//! ([`ReadInput::elevations`]): either every position read has one or none
//! has (a document mixing `[x, y]` and `[x, y, z]` is an error naming the
//! first position that differs), and the writers write `[x, y, z]` when the
//! points have elevations. An optri document's `elevations` are read with its
//! `coordinates`.
//!
//! [`ReadInput::elevations`]: super::ReadInput::elevations
//! [`InputFormat::GeoJson`]: super::InputFormat::GeoJson

use super::json::document_coordinates;
use super::{check_value, parse, shown, Input, HOLES_UNSUPPORTED};
use crate::error::Result;
use crate::kernel::Point;
use serde::ser::{Serialize, Serializer};
use serde_json::Value;

/// The JSON type name of `v`, for messages.
fn json_type(v: &Value) -> &'static str {
    match v {
        Value::Null => "null",
        Value::Bool(_) => "a boolean",
        Value::Number(_) => "a number",
        Value::String(_) => "a string",
        Value::Array(_) => "an array",
        Value::Object(_) => "an object",
    }
}

/// Reads a GeoJSON document as points or, when it holds no `Point` or
/// `MultiPoint` but one `Polygon` (or a `MultiPolygon` of one polygon), and
/// `polygons` is set, as that polygon's outer ring (closing vertex dropped);
/// with the elevations, one per point, when the positions have a third value.
pub(super) fn read_geojson_input(text: &str, polygons: bool) -> Result<(Input, Option<Vec<f64>>)> {
    if text.trim().is_empty() {
        return Ok((Input::Points(Vec::new()), None));
    }
    let root: Value =
        serde_json::from_str(text).map_err(|e| parse(e.line(), format!("invalid JSON: {e}")))?;
    let mut found = GeoJsonPoints::default();
    // optri's own JSON documents (no "type"): their "coordinates", or the
    // "points" array of earlier versions, and their "elevations".
    let geojson = root.get("type").is_some();
    if let Some((name, list)) = document_coordinates(&root).filter(|_| !geojson) {
        collect_positions(list, name, &mut found.points)?;
        let (points, z) = found.points.finish();
        let z = match root.get("elevations") {
            Some(list) if z.is_none() => Some(document_elevations(list, points.len())?),
            _ => z,
        };
        return Ok((Input::Points(points), z));
    }
    collect_geojson(&root, "the document", &mut found)?;
    if found.points.is_empty() && polygons && !found.polygons.is_empty() {
        let (ring, z) = polygon_ring(&found.polygons)?.finish();
        return Ok((Input::Polygon(ring), z));
    }
    if found.points.is_empty() {
        let what = if found.skipped.is_empty() {
            "no geometries at all".to_string()
        } else {
            let counts: Vec<String> = found
                .skipped
                .iter()
                .map(|(kind, n)| format!("{n} {kind}"))
                .collect();
            format!("only {}", counts.join(", "))
        };
        return Err(parse(
            0,
            format!("GeoJSON: no Point or MultiPoint geometry found (the document has {what})"),
        ));
    }
    let (points, z) = found.points.finish();
    Ok((Input::Points(points), z))
}

/// An optri document's `elevations`: `count` numbers, each checked as a
/// coordinate is.
fn document_elevations(list: &Value, count: usize) -> Result<Vec<f64>> {
    let bad = |m: String| parse(0, format!("\"elevations\": {m}"));
    let Some(list) = list.as_array() else {
        return Err(bad(format!("expected an array, found {}", json_type(list))));
    };
    if list.len() != count {
        return Err(bad(format!(
            "{} elevations for {count} coordinates",
            list.len()
        )));
    }
    list.iter()
        .enumerate()
        .map(|(k, v)| {
            let value = v
                .as_f64()
                .ok_or_else(|| bad(format!("[{k}] is {}, not a number", json_type(v))))?;
            check_value(value, "elevation", &v.to_string(), 0)
                .map_err(|e| bad(format!("[{k}]: {e}")))
        })
        .collect()
}

/// Positions as read: the points, and their elevations while every
/// position so far had a third value.
#[derive(Default)]
struct PositionList {
    points: Vec<Point>,
    elevations: Vec<f64>,
    /// Where the first position is and whether it has an elevation: all
    /// others must agree.
    first: Option<(String, bool)>,
}

impl PositionList {
    /// Appends the position `v` found at `at`.
    fn push(&mut self, v: &Value, at: &str) -> Result<()> {
        let (p, z) = position(v, at)?;
        let (first_at, with_z) = self
            .first
            .get_or_insert_with(|| (at.to_string(), z.is_some()));
        if *with_z != z.is_some() {
            let dims = |z: bool| if z { "[x, y, z]" } else { "[x, y]" };
            return Err(parse(
                0,
                format!(
                    "GeoJSON: {at}: the position is {} but {first_at} is {}; give every \
                     position an elevation or none",
                    dims(z.is_some()),
                    dims(*with_z)
                ),
            ));
        }
        self.points.push(p);
        self.elevations.extend(z);
        Ok(())
    }

    fn is_empty(&self) -> bool {
        self.points.is_empty()
    }

    /// The points, and their elevations if every position had one.
    fn finish(self) -> (Vec<Point>, Option<Vec<f64>>) {
        let with_z = self.first.is_some_and(|(_, z)| z);
        (self.points, with_z.then_some(self.elevations))
    }
}

/// The outer ring of the one polygon among `polygons` (`Polygon` and
/// `MultiPolygon` geometries with where they are), without its closing
/// vertex.
fn polygon_ring(polygons: &[(String, &Value)]) -> Result<PositionList> {
    // Every polygon as (where, its rings).
    let mut all: Vec<(String, &Value)> = Vec::new();
    for (at, geometry) in polygons {
        let kind = geometry.get("type").and_then(Value::as_str).unwrap_or("");
        let Some(coordinates) = geometry.get("coordinates") else {
            return Err(parse(
                0,
                format!("GeoJSON: {at}: {kind} lacks \"coordinates\""),
            ));
        };
        if kind == "MultiPolygon" {
            let Some(list) = coordinates.as_array() else {
                return Err(parse(
                    0,
                    format!(
                        "GeoJSON: {at}: expected an array of polygons, found {}",
                        json_type(coordinates)
                    ),
                ));
            };
            for (k, p) in list.iter().enumerate() {
                all.push((format!("{at}.coordinates[{k}]"), p));
            }
        } else {
            all.push((at.clone(), coordinates));
        }
    }
    if all.len() != 1 {
        let places: Vec<&str> = all.iter().map(|(at, _)| at.as_str()).take(4).collect();
        return Err(parse(
            0,
            format!(
                "GeoJSON: the document has {} polygons ({}{}) and no points; optri \
                 triangulates one simple polygon per file",
                all.len(),
                places.join(", "),
                if all.len() > places.len() {
                    ", …"
                } else {
                    ""
                }
            ),
        ));
    }
    let (at, rings) = &all[0];
    let Some(rings) = rings.as_array() else {
        return Err(parse(
            0,
            format!(
                "GeoJSON: {at}: expected an array of rings, found {}",
                json_type(rings)
            ),
        ));
    };
    match rings.len() {
        0 => return Err(parse(0, format!("GeoJSON: {at}: the polygon has no ring"))),
        1 => {}
        k => {
            return Err(parse(
                0,
                format!(
                    "GeoJSON: {at}: {HOLES_UNSUPPORTED} (the polygon has {} hole ring(s))",
                    k - 1
                ),
            ))
        }
    }
    let mut ring = PositionList::default();
    collect_positions(&rings[0], &format!("{at}[0]"), &mut ring)?;
    let n = ring.points.len();
    // The closing vertex repeats the first, elevation included (else the
    // ring's one point would have two elevations).
    if n > 1 && ring.points[0] == ring.points[n - 1] {
        if ring.elevations.first() != ring.elevations.last() {
            return Err(parse(
                0,
                format!(
                    "GeoJSON: {at}[0]: the ring closes at its first point with another \
                     elevation ({} and {})",
                    ring.elevations[0],
                    ring.elevations[n - 1]
                ),
            ));
        }
        ring.points.pop();
        ring.elevations.truncate(n - 1);
    }
    Ok(ring)
}

/// What [`collect_geojson`] gathers: the points, the polygon geometries
/// (with where they are), and how many geometries of each point-less type
/// were skipped (in first-seen order, for the message when nothing else is
/// found).
#[derive(Default)]
struct GeoJsonPoints<'v> {
    points: PositionList,
    polygons: Vec<(String, &'v Value)>,
    skipped: Vec<(&'static str, usize)>,
}

/// Appends the points of a GeoJSON object; `at` describes where it is, for
/// messages (JSON values carry no line numbers, so errors name the path).
fn collect_geojson<'v>(v: &'v Value, at: &str, found: &mut GeoJsonPoints<'v>) -> Result<()> {
    /// Valid GeoJSON geometries that hold no points of their own.
    const POINTLESS: [&str; 4] = ["LineString", "MultiLineString", "Polygon", "MultiPolygon"];
    let bad = |m: String| Err(parse(0, format!("GeoJSON: {at}: {m}")));
    let Some(kind) = v.get("type").and_then(Value::as_str) else {
        return bad(format!(
            "expected an object with a \"type\", found {}",
            json_type(v)
        ));
    };
    let member = |name: &str| match v.get(name) {
        Some(x) => Ok(x),
        None => Err(parse(0, format!("GeoJSON: {at}: {kind} lacks \"{name}\""))),
    };
    match kind {
        "FeatureCollection" => {
            let Some(features) = member("features")?.as_array() else {
                return bad("\"features\" is not an array".into());
            };
            for (k, f) in features.iter().enumerate() {
                collect_geojson(f, &format!("features[{k}]"), found)?;
            }
        }
        "Feature" => match member("geometry")? {
            Value::Null => {}
            g => collect_geojson(g, &format!("{at}.geometry"), found)?,
        },
        "GeometryCollection" => {
            let Some(geometries) = member("geometries")?.as_array() else {
                return bad("\"geometries\" is not an array".into());
            };
            for (k, g) in geometries.iter().enumerate() {
                collect_geojson(g, &format!("{at}.geometries[{k}]"), found)?;
            }
        }
        "Point" => found.points.push(member("coordinates")?, at)?,
        "MultiPoint" => collect_positions(member("coordinates")?, at, &mut found.points)?,
        other => {
            // Skipping lines and polygons lets a triangulation's GeoJSON be
            // read back as its points; an unknown type is more likely a
            // typo, which must not silently drop points.
            let Some(&kind) = POINTLESS.iter().find(|&&k| k == other) else {
                return bad(format!(
                    "{} is not a GeoJSON geometry type (points are read from Point and \
                     MultiPoint; LineString, Polygon and their Multi forms are skipped)",
                    shown(other, "\"")
                ));
            };
            if matches!(kind, "Polygon" | "MultiPolygon") {
                found.polygons.push((at.to_string(), v));
            }
            match found.skipped.iter_mut().find(|(k, _)| *k == kind) {
                Some((_, n)) => *n += 1,
                None => found.skipped.push((kind, 1)),
            }
        }
    }
    Ok(())
}

fn collect_positions(list: &Value, at: &str, out: &mut PositionList) -> Result<()> {
    let Some(list) = list.as_array() else {
        return Err(parse(
            0,
            format!(
                "GeoJSON: {at}: expected an array of positions, found {}",
                json_type(list)
            ),
        ));
    };
    for (k, p) in list.iter().enumerate() {
        out.push(p, &format!("{at}[{k}]"))?;
    }
    Ok(())
}

/// A GeoJSON position `[x, y]` or `[x, y, z]`, with `z` if there is one.
fn position(v: &Value, at: &str) -> Result<(Point, Option<f64>)> {
    let bad = || {
        parse(
            0,
            format!(
                "GeoJSON: {at}: expected a position [x, y], found {}",
                shown(&v.to_string(), "")
            ),
        )
    };
    let a = v.as_array().ok_or_else(bad)?;
    if !(2..=3).contains(&a.len()) {
        return Err(bad());
    }
    let mut values = [0.0; 3];
    for (k, c) in values.iter_mut().enumerate().take(a.len()) {
        let value = a[k].as_f64().ok_or_else(bad)?;
        let what = if k == 2 { "elevation" } else { "coordinate" };
        *c = check_value(value, what, &a[k].to_string(), 0)
            .map_err(|e| parse(0, format!("GeoJSON: {at}: {e}")))?;
    }
    let [x, y, z] = values;
    Ok(([x, y], (a.len() == 3).then_some(z)))
}

/// A GeoJSON `FeatureCollection` with one `Polygon` per triangle (properties:
/// `triangle` number and its input-index `vertices`) and, if
/// `include_points`, one `Point` per input point (property `index`).
/// Positions are `[x, y, z]` when the point set has elevations.
#[cfg(test)]
pub(crate) fn triangulation_to_geojson(
    t: &crate::structures::Triangulation,
    include_points: bool,
) -> Value {
    let elevations = super::input_elevations(t.point_set());
    to_value(&TriangulationFeatures {
        points: t.points(),
        elevations: elevations.as_deref(),
        triangles: t.triangles(),
        include_points,
    })
}

#[cfg(test)]
fn to_value(v: &impl Serialize) -> Value {
    // Strings, numbers and arrays only.
    serde_json::to_value(v).expect("a GeoJSON document always converts to a JSON value")
}

/// The triangulation's `FeatureCollection`, serialised feature by feature
/// (so a writer streams it without building a value tree).
pub(super) struct TriangulationFeatures<'a> {
    pub(super) points: &'a [Point],
    /// One per point: the third value of every position.
    pub(super) elevations: Option<&'a [f64]>,
    pub(super) triangles: &'a [[u32; 3]],
    pub(super) include_points: bool,
}

/// A graph's `FeatureCollection`, serialised feature by feature.
pub(super) struct GraphFeatures<'a> {
    pub(super) points: &'a [Point],
    /// One per point: the third value of every position.
    pub(super) elevations: Option<&'a [f64]>,
    pub(super) edges: &'a [[u32; 2]],
}

/// The points with their elevations, if any, as GeoJSON positions.
#[derive(Clone, Copy)]
struct Positions<'a> {
    points: &'a [Point],
    elevations: Option<&'a [f64]>,
}

impl Positions<'_> {
    /// Point `i`'s position: `[x, y]`, or `[x, y, z]`.
    fn at(&self, i: usize) -> Position {
        Position(self.points[i], self.elevations.map(|z| z[i]))
    }
}

/// A GeoJSON position: `[x, y]`, or `[x, y, z]` with an elevation.
#[derive(Clone, Copy)]
struct Position(Point, Option<f64>);

impl Serialize for Position {
    fn serialize<S: Serializer>(&self, serializer: S) -> std::result::Result<S::Ok, S::Error> {
        use serde::ser::SerializeSeq;
        let Position([x, y], z) = *self;
        let mut seq = serializer.serialize_seq(Some(2 + usize::from(z.is_some())))?;
        seq.serialize_element(&x)?;
        seq.serialize_element(&y)?;
        if let Some(z) = z {
            seq.serialize_element(&z)?;
        }
        seq.end()
    }
}

#[derive(serde::Serialize)]
struct Feature<C, P> {
    #[serde(rename = "type")]
    kind: &'static str,
    geometry: Geometry<C>,
    properties: P,
}

#[derive(serde::Serialize)]
struct Geometry<C> {
    #[serde(rename = "type")]
    kind: &'static str,
    coordinates: C,
}

#[derive(serde::Serialize)]
struct TriangleProperties {
    triangle: usize,
    vertices: [u32; 3],
}

#[derive(serde::Serialize)]
struct PointProperties {
    index: usize,
}

#[derive(serde::Serialize)]
struct EdgeProperties {
    edge: [u32; 2],
}

fn feature<C, P>(geometry: &'static str, coordinates: C, properties: P) -> Feature<C, P> {
    Feature {
        kind: "Feature",
        geometry: Geometry {
            kind: geometry,
            coordinates,
        },
        properties,
    }
}

/// `{"type": "FeatureCollection", "features": [...]}` with the features of
/// `items` then of `points`, streamed.
fn feature_collection<S: Serializer, T: Serialize>(
    serializer: S,
    items: impl Iterator<Item = T>,
    points: Option<Positions<'_>>,
) -> std::result::Result<S::Ok, S::Error> {
    use serde::ser::{SerializeMap, SerializeSeq};
    struct Features<'a, I> {
        items: std::cell::Cell<Option<I>>,
        points: Option<Positions<'a>>,
    }
    impl<I: Iterator<Item = T>, T: Serialize> Serialize for Features<'_, I> {
        fn serialize<S: Serializer>(&self, serializer: S) -> std::result::Result<S::Ok, S::Error> {
            let mut seq = serializer.serialize_seq(None)?;
            for item in self.items.take().into_iter().flatten() {
                seq.serialize_element(&item)?;
            }
            if let Some(positions) = self.points {
                for i in 0..positions.points.len() {
                    let point = positions.at(i);
                    seq.serialize_element(&feature("Point", point, PointProperties { index: i }))?;
                }
            }
            seq.end()
        }
    }
    let mut map = serializer.serialize_map(Some(2))?;
    map.serialize_entry("type", "FeatureCollection")?;
    map.serialize_entry(
        "features",
        &Features {
            items: std::cell::Cell::new(Some(items)),
            points,
        },
    )?;
    map.end()
}

impl Serialize for TriangulationFeatures<'_> {
    fn serialize<S: Serializer>(&self, serializer: S) -> std::result::Result<S::Ok, S::Error> {
        let positions = Positions {
            points: self.points,
            elevations: self.elevations,
        };
        let triangles = self.triangles.iter().enumerate().map(move |(k, tri)| {
            let ring = [tri[0], tri[1], tri[2], tri[0]].map(|i| positions.at(i as usize));
            feature(
                "Polygon",
                [ring],
                TriangleProperties {
                    triangle: k,
                    vertices: *tri,
                },
            )
        });
        feature_collection(
            serializer,
            triangles,
            self.include_points.then_some(positions),
        )
    }
}

impl Serialize for GraphFeatures<'_> {
    fn serialize<S: Serializer>(&self, serializer: S) -> std::result::Result<S::Ok, S::Error> {
        let positions = Positions {
            points: self.points,
            elevations: self.elevations,
        };
        let edges = self.edges.iter().map(move |&[a, b]| {
            feature(
                "LineString",
                [positions.at(a as usize), positions.at(b as usize)],
                EdgeProperties { edge: [a, b] },
            )
        });
        feature_collection(serializer, edges, Some(positions))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::{awkward_points, line_of, points_of, InputFormat};
    use crate::{delaunay, PointSet};

    #[test]
    fn geojson_points_and_errors() {
        let text = r#"{"type":"FeatureCollection","features":[
            {"type":"Feature","geometry":{"type":"Point","coordinates":[1,2]},"properties":{}},
            {"type":"Feature","geometry":{"type":"MultiPoint","coordinates":[[3,4],[5,6]]}},
            {"type":"Feature","geometry":null}]}"#;
        assert_eq!(
            points_of(text, InputFormat::GeoJson).unwrap(),
            vec![[1.0, 2.0], [3.0, 4.0], [5.0, 6.0]]
        );
        assert_eq!(
            points_of(
                r#"{"type":"Point","coordinates":[0.5,-1]}"#,
                InputFormat::GeoJson
            )
            .unwrap(),
            vec![[0.5, -1.0]]
        );
        // Lines and polygons are skipped; a document without any point names
        // what it holds instead.
        assert_eq!(
            points_of(
                r#"{"type":"GeometryCollection","geometries":[
                    {"type":"LineString","coordinates":[[0,0],[1,1]]},
                    {"type":"Point","coordinates":[2,3]}]}"#,
                InputFormat::GeoJson
            )
            .unwrap(),
            vec![[2.0, 3.0]]
        );
        let e = points_of(
            r#"{"type":"FeatureCollection","features":[
                {"type":"Feature","geometry":{"type":"LineString","coordinates":[[0,0],[1,1]]}},
                {"type":"Feature","geometry":{"type":"Polygon","coordinates":[[[0,0],[1,0],[0,1],[0,0]]]}},
                {"type":"Feature","geometry":{"type":"LineString","coordinates":[[0,0],[1,1]]}}]}"#,
            InputFormat::GeoJson,
        )
        .unwrap_err()
        .to_string();
        assert!(
            e.contains("no Point or MultiPoint") && e.contains("2 LineString, 1 Polygon"),
            "{e}"
        );
        let e = points_of(
            r#"{"type":"FeatureCollection","features":[]}"#,
            InputFormat::GeoJson,
        )
        .unwrap_err()
        .to_string();
        assert!(e.contains("no geometries"), "{e}");
        let e = points_of(
            r#"{"type":"Piont","coordinates":[1,2]}"#,
            InputFormat::GeoJson,
        )
        .unwrap_err()
        .to_string();
        assert!(
            e.contains("\"Piont\" is not a GeoJSON geometry type"),
            "{e}"
        );
        let (line, _) = line_of(points_of("{\n\"type\":\n}", InputFormat::GeoJson).unwrap_err());
        assert_eq!(line, 3);
        let e = points_of(
            r#"{"type":"Point","coordinates":[1]}"#,
            InputFormat::GeoJson,
        )
        .unwrap_err()
        .to_string();
        assert!(e.contains("position"), "{e}");
        assert_eq!(
            points_of(
                r#"{"points":[[1,2],[3,4]],"triangles":[]}"#,
                InputFormat::GeoJson
            )
            .unwrap(),
            vec![[1.0, 2.0], [3.0, 4.0]]
        );
    }

    #[test]
    fn three_dimensional_positions_give_elevations_all_or_none() {
        use crate::io::{read, Input, ReadOptions, Source};
        let read_geojson = |text: &str| {
            let options = ReadOptions::default()
                .with_format(InputFormat::GeoJson)
                .with_polygons(true);
            read(Source::Text(text), &options)
        };
        let text = r#"{"type":"FeatureCollection","features":[
            {"type":"Feature","geometry":{"type":"Point","coordinates":[1,2,10]},"properties":{}},
            {"type":"Feature","geometry":{"type":"MultiPoint","coordinates":[[3,4,-0.5],[5,6,0]]}}]}"#;
        let r = read_geojson(text).unwrap();
        assert_eq!(r.input.points(), [[1.0, 2.0], [3.0, 4.0], [5.0, 6.0]]);
        assert_eq!(r.elevations, Some(vec![10.0, -0.5, 0.0]));
        assert_eq!(
            read_geojson(r#"{"type":"Point","coordinates":[1,2]}"#)
                .unwrap()
                .elevations,
            None
        );
        // Mixing is an error naming the first position that differs, and
        // the first position.
        for (text, needles) in [
            (
                r#"{"type":"MultiPoint","coordinates":[[0,0,1],[1,0,2],[0,1]]}"#,
                ["the document[2]: the position is [x, y] but the document[0] is [x, y, z]"],
            ),
            (
                r#"{"type":"FeatureCollection","features":[
                    {"type":"Feature","geometry":{"type":"Point","coordinates":[1,2]}},
                    {"type":"Feature","geometry":{"type":"Point","coordinates":[1,3,5]}}]}"#,
                ["features[1].geometry: the position is [x, y, z] but features[0].geometry is [x, y]"],
            ),
            (
                r#"{"type":"Point","coordinates":[1,2,null]}"#,
                ["expected a position [x, y]"],
            ),
            (
                r#"{"type":"MultiPoint","coordinates":[[0,0,1],[1,0,1e300]]}"#,
                ["the document[1]: elevation '1e+300' is outside the exact range"],
            ),
        ] {
            let e = read_geojson(text).unwrap_err().to_string();
            for needle in needles {
                assert!(e.contains(needle), "{text}: {e}");
            }
        }
        // A polygon's ring: the closing vertex goes with its elevation,
        // which must agree with the first.
        let ring = r#"{"type":"Polygon","coordinates":[[[0,0,1],[2,0,2],[1,2,3],[0,0,1]]]}"#;
        let r = read_geojson(ring).unwrap();
        assert_eq!(
            r.input,
            Input::Polygon(vec![[0.0, 0.0], [2.0, 0.0], [1.0, 2.0]])
        );
        assert_eq!(r.elevations, Some(vec![1.0, 2.0, 3.0]));
        let e = read_geojson(&ring.replace("[0,0,1]]]", "[0,0,4]]]"))
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("closes at its first point with another elevation (1 and 4)"),
            "{e}"
        );
        // An optri document's elevations are read with its coordinates.
        let doc = r#"{"coordinates":[[0,0],[1,0],[0,1]],"elevations":[5,6,7]}"#;
        assert_eq!(
            read_geojson(doc).unwrap().elevations,
            Some(vec![5.0, 6.0, 7.0])
        );
        for (doc, needle) in [
            (
                r#"{"coordinates":[[0,0],[1,0]],"elevations":[5]}"#,
                "1 elevations for 2 coordinates",
            ),
            (
                r#"{"coordinates":[[0,0]],"elevations":["a"]}"#,
                "[0] is a string, not a number",
            ),
            (
                r#"{"coordinates":[[0,0]],"elevations":5}"#,
                "expected an array, found a number",
            ),
        ] {
            let e = read_geojson(doc).unwrap_err().to_string();
            assert!(e.contains(needle), "{doc}: {e}");
        }
    }

    #[test]
    fn geojson_polygon_inputs() {
        use crate::io::{input_of, ring_of, Input};
        let square = vec![[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]];
        // A Feature with a closed outer ring: the closing vertex is dropped.
        let feature = r#"{"type":"Feature","properties":{},"geometry":{"type":"Polygon",
            "coordinates":[[[0,0],[2,0],[2,2],[0,2],[0,0]]]}}"#;
        assert_eq!(
            input_of(feature, InputFormat::GeoJson).unwrap(),
            Input::Polygon(square.clone())
        );
        // Clockwise and unclosed rings are returned as given.
        let clockwise = r#"{"type":"Polygon","coordinates":[[[0,0],[0,2],[2,2],[2,0]]]}"#;
        assert_eq!(
            ring_of(clockwise, InputFormat::GeoJson).unwrap(),
            vec![[0.0, 0.0], [0.0, 2.0], [2.0, 2.0], [2.0, 0.0]]
        );
        // A MultiPolygon of one polygon, in a FeatureCollection.
        let multi = r#"{"type":"FeatureCollection","features":[{"type":"Feature","geometry":
            {"type":"MultiPolygon","coordinates":[[[[0,0],[2,0],[2,2],[0,2],[0,0]]]]}}]}"#;
        assert_eq!(ring_of(multi, InputFormat::GeoJson).unwrap(), square);
        // Holes and several polygons are refused, naming the geometry.
        let holes = r#"{"type":"FeatureCollection","features":[{"type":"Feature","geometry":
            {"type":"Polygon","coordinates":[[[0,0],[4,0],[4,4],[0,4],[0,0]],
            [[1,1],[1,2],[2,2],[1,1]]]}}]}"#;
        let e = input_of(holes, InputFormat::GeoJson)
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("features[0].geometry") && e.contains("holes are not supported yet"),
            "{e}"
        );
        let two = r#"{"type":"MultiPolygon","coordinates":[[[[0,0],[1,0],[0,1],[0,0]]],
            [[[5,5],[6,5],[5,6],[5,5]]]]}"#;
        let e = input_of(two, InputFormat::GeoJson).unwrap_err().to_string();
        assert!(
            e.contains("2 polygons") && e.contains("one simple polygon"),
            "{e}"
        );
        // With points, the document is a point input and polygons (even with
        // holes) are skipped, as read_points does.
        let mixed = r#"{"type":"GeometryCollection","geometries":[
            {"type":"Point","coordinates":[7,7]},
            {"type":"Polygon","coordinates":[[[0,0],[4,0],[4,4],[0,0]],[[1,1],[2,1],[1,2],[1,1]]]}]}"#;
        assert_eq!(
            input_of(mixed, InputFormat::GeoJson).unwrap(),
            Input::Points(vec![[7.0, 7.0]])
        );
        let e = ring_of(mixed, InputFormat::GeoJson)
            .unwrap_err()
            .to_string();
        assert!(e.contains("holds points, not a polygon"), "{e}");
        // read_points keeps refusing a polygon-only document.
        assert!(points_of(feature, InputFormat::GeoJson).is_err());
    }

    #[test]
    fn geojson_round_trip() {
        let pts = awkward_points();
        let t = delaunay(&PointSet::new(&pts).unwrap()).unwrap();
        let v = triangulation_to_geojson(&t, true);
        let features = v["features"].as_array().unwrap();
        assert_eq!(features.len(), t.triangles().len() + pts.len());
        // Each polygon ring maps back, coordinate by coordinate, to its triangle.
        for (k, tri) in t.triangles().iter().enumerate() {
            let ring: Vec<Point> =
                serde_json::from_value(features[k]["geometry"]["coordinates"][0].clone()).unwrap();
            assert_eq!(ring.len(), 4);
            assert_eq!(ring[0], ring[3]);
            for c in 0..3 {
                assert_eq!(ring[c], pts[tri[c] as usize]);
            }
        }
        // The point features, read by the GeoJSON reader, give the input.
        let points_only = serde_json::json!({"type": "FeatureCollection", "features": features[t.triangles().len()..]});
        assert_eq!(
            points_of(&points_only.to_string(), InputFormat::GeoJson).unwrap(),
            pts
        );
        // The whole collection reads back as the points: polygons are skipped.
        assert_eq!(
            points_of(&v.to_string(), InputFormat::GeoJson).unwrap(),
            pts
        );
        // Without the point features there are no points, and the reader
        // says what it found instead.
        let e = points_of(
            &triangulation_to_geojson(&t, false).to_string(),
            InputFormat::GeoJson,
        )
        .unwrap_err()
        .to_string();
        assert!(e.contains("Polygon"), "{e}");
        // With elevations, every position is [x, y, z] and reads back.
        let z: Vec<f64> = (0..pts.len()).map(|i| i as f64 * 0.25).collect();
        let mut z = z;
        z[pts.len() - 2] = z[3]; // the duplicate of point 3 (awkward_points)
        let t = delaunay(&PointSet::new(&pts).unwrap().with_elevations(&z).unwrap()).unwrap();
        let v = triangulation_to_geojson(&t, true);
        assert_eq!(
            v["features"][0]["geometry"]["coordinates"][0][0]
                .as_array()
                .unwrap()
                .len(),
            3
        );
        let options = crate::io::ReadOptions::default().with_format(InputFormat::GeoJson);
        let r = crate::io::read(crate::io::Source::Text(&v.to_string()), &options).unwrap();
        assert_eq!(r.input.points(), pts);
        assert_eq!(r.elevations, Some(z));
    }
}
