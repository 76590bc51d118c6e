//! Axis-aligned bounding boxes (rounded coordinates are exact here: min and
//! max never round).

use crate::kernel::Point;

/// `[min x, min y, max x, max y]` of `points` (infinite for no points).
pub(crate) fn bounding_box(points: &[Point]) -> [f64; 4] {
    let mut bbox = [
        f64::INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NEG_INFINITY,
    ];
    for p in points {
        bbox[0] = bbox[0].min(p[0]);
        bbox[1] = bbox[1].min(p[1]);
        bbox[2] = bbox[2].max(p[0]);
        bbox[3] = bbox[3].max(p[1]);
    }
    bbox
}
