//! optri's own JSON documents: a triangulation and a graph.

use crate::error::{Error, Result};
use crate::kernel::Point;
use crate::structures::{PointSet, Triangulation};
use serde_json::{json, Value};

/// `{"points": [[x, y], …], "triangles": [[i, j, k], …], "edges": [[a, b], …],
/// "duplicates": [[dropped, kept], …]}` with input indices; triangles are
/// counter-clockwise.
pub fn triangulation_to_json(t: &Triangulation) -> Value {
    json!({
        "points": t.points(),
        "triangles": t.triangles(),
        "edges": t.edges(),
        "duplicates": t.point_set().duplicates(),
    })
}

/// Reads back the output of [`triangulation_to_json`], validating it.
///
/// # Errors
/// [`Error::Parse`] (line 0) for a malformed object; the errors of
/// [`PointSet::new`] and [`Triangulation::from_triangles`].
pub fn triangulation_from_json(value: &Value) -> Result<Triangulation> {
    let bad = |m: &str| Error::Parse {
        line: 0,
        message: format!("triangulation JSON: {m}"),
    };
    let points: Vec<Point> = serde_json::from_value(
        value
            .get("points")
            .cloned()
            .ok_or_else(|| bad("no \"points\""))?,
    )
    .map_err(|e| bad(&format!("\"points\": {e}")))?;
    let triangles: Vec<[u32; 3]> = serde_json::from_value(
        value
            .get("triangles")
            .cloned()
            .ok_or_else(|| bad("no \"triangles\""))?,
    )
    .map_err(|e| bad(&format!("\"triangles\": {e}")))?;
    let point_set = PointSet::new(&points)?;
    if let Some(i) = triangles
        .iter()
        .flatten()
        .find(|&&i| i as usize >= points.len())
    {
        return Err(bad(&format!("triangle index {i} out of range")));
    }
    Triangulation::from_triangles(&point_set, triangles)
}

/// `{"points": [[x, y], …], "edges": [[a, b], …]}` (indices into `points`).
pub fn graph_to_json(points: &[Point], edges: &[[u32; 2]]) -> Value {
    json!({"points": points, "edges": edges})
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::{awkward_points, read_points, InputFormat};
    use crate::{delaunay, PointSet};

    #[test]
    fn json_round_trip_gives_the_same_triangulation() {
        let ps = PointSet::new(&awkward_points()).unwrap();
        let t = delaunay(&ps).unwrap();
        let text = serde_json::to_string(&triangulation_to_json(&t)).unwrap();
        let back = triangulation_from_json(&serde_json::from_str(&text).unwrap()).unwrap();
        assert_eq!(back.points(), t.points());
        assert_eq!(back.triangles(), t.triangles());
        assert_eq!(back.point_set().duplicates(), &[[46, 3]]);
        // The points alone read back through the GeoJSON reader.
        assert_eq!(
            read_points(&text, InputFormat::GeoJson).unwrap(),
            t.points()
        );
        // Tampering is caught: a flipped triangle no longer validates.
        let mut v = triangulation_to_json(&t);
        v["triangles"][0] = json!([
            t.triangles()[0][1],
            t.triangles()[0][0],
            t.triangles()[0][2]
        ]);
        assert!(triangulation_from_json(&v).is_err());
        v["triangles"][0] = json!([0, 1, 999]);
        assert!(triangulation_from_json(&v).is_err());
    }
}
