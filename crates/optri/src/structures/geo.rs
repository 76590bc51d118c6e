//! Conversions from and to [`geo_types`] (feature `geo-types`): a
//! [`PointSet`] from and to a `MultiPoint`, a [`Triangulation`] to
//! `Triangle`s or a `MultiPolygon`, a [`SimplePolygon`] from a `Polygon`.
//! Indices are unchanged: point `i` of a `MultiPoint` is input index `i`,
//! and triangle `k` of [`Triangulation::to_geo_triangles`] is
//! `triangles()[k]`.

use super::{PointSet, SimplePolygon, Triangulation};
use crate::error::{Error, PolygonProblem, Result};
use crate::kernel::Point;
use geo_types::{Coord, LineString, MultiPoint, MultiPolygon, Polygon, Triangle};

fn coord(p: Point) -> Coord<f64> {
    Coord { x: p[0], y: p[1] }
}

impl TryFrom<&MultiPoint<f64>> for PointSet {
    type Error = Error;
    /// Validates the points as [`PointSet::new`] does.
    fn try_from(points: &MultiPoint<f64>) -> Result<Self> {
        let points: Vec<Point> = points.iter().map(|p| [p.x(), p.y()]).collect();
        PointSet::new(&points)
    }
}

impl From<&PointSet> for MultiPoint<f64> {
    /// The input points, duplicates included, in input order.
    fn from(points: &PointSet) -> Self {
        points
            .input_points()
            .iter()
            .map(|&[x, y]| geo_types::Point::new(x, y))
            .collect()
    }
}

impl TryFrom<&Polygon<f64>> for SimplePolygon {
    type Error = Error;
    /// The exterior ring (closing vertex dropped), validated as
    /// [`SimplePolygon::new`] does; ring position `i` is input index `i`.
    ///
    /// # Errors
    /// [`Error::InvalidPolygon`] with [`PolygonProblem::HasHoles`] for a
    /// polygon with interior rings, and the errors of [`SimplePolygon::new`].
    fn try_from(polygon: &Polygon<f64>) -> Result<Self> {
        if !polygon.interiors().is_empty() {
            return Err(Error::InvalidPolygon(PolygonProblem::HasHoles {
                holes: polygon.interiors().len(),
            }));
        }
        let mut ring: Vec<Point> = polygon.exterior().coords().map(|c| [c.x, c.y]).collect();
        if ring.len() > 1 && ring.first() == ring.last() {
            ring.pop();
        }
        SimplePolygon::new(&ring)
    }
}

impl Triangulation {
    /// The triangles as `geo_types::Triangle`s, counter-clockwise, in the
    /// order of [`triangles`](Self::triangles).
    pub fn to_geo_triangles(&self) -> Vec<Triangle<f64>> {
        let pts = self.points();
        self.triangles()
            .iter()
            .map(|t| {
                let [a, b, c] = t.map(|i| coord(pts[i as usize]));
                Triangle::new(a, b, c)
            })
            .collect()
    }

    /// The triangles as a `MultiPolygon` of closed counter-clockwise rings.
    pub fn to_multi_polygon(&self) -> MultiPolygon<f64> {
        let pts = self.points();
        self.triangles()
            .iter()
            .map(|t| {
                let ring: Vec<Coord<f64>> = [t[0], t[1], t[2], t[0]]
                    .map(|i| coord(pts[i as usize]))
                    .to_vec();
                Polygon::new(LineString::new(ring), Vec::new())
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::delaunay;

    #[test]
    fn conversions_keep_indices_and_refuse_holes() {
        let mp: MultiPoint<f64> =
            vec![(0.0, 0.0), (4.0, 0.0), (0.0, 3.0), (4.0, 3.0), (0.0, 0.0)].into();
        let ps = PointSet::try_from(&mp).unwrap();
        assert_eq!(ps.duplicates(), &[[4, 0]]);
        assert_eq!(MultiPoint::from(&ps), mp);
        let t = delaunay(&ps).unwrap();
        let tris = t.to_geo_triangles();
        assert_eq!(tris.len(), t.triangles().len());
        for (g, tri) in tris.iter().zip(t.triangles()) {
            let p = t.points()[tri[0] as usize];
            assert_eq!(g.v1(), coord(p));
        }
        let mpoly = t.to_multi_polygon();
        assert_eq!(mpoly.0.len(), 2);
        assert_eq!(mpoly.0[0].exterior().0.len(), 4);
        let square = Polygon::new(
            LineString::from(vec![
                (0.0, 0.0),
                (2.0, 0.0),
                (2.0, 2.0),
                (0.0, 2.0),
                (0.0, 0.0),
            ]),
            vec![],
        );
        assert_eq!(SimplePolygon::try_from(&square).unwrap().len(), 4);
        let holed = Polygon::new(
            square.exterior().clone(),
            vec![LineString::from(vec![
                (0.5, 0.5),
                (1.0, 0.5),
                (0.5, 1.0),
                (0.5, 0.5),
            ])],
        );
        let e = SimplePolygon::try_from(&holed).unwrap_err();
        assert_eq!(
            e,
            Error::InvalidPolygon(PolygonProblem::HasHoles { holes: 1 })
        );
        assert_eq!(
            e.to_string(),
            "not a simple polygon: polygons with holes are not supported yet (this one has 1)"
        );
    }
}
