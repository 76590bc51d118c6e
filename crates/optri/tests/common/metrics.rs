//! The normed metrics the metric tests run under, each with the oracle's
//! independently written norm, and the value of a triangulation under it.

use optri::kernel::Metric;
use optri::Triangulation;
use optri_oracle::norm::Norm;

/// L1, L∞, L3, a hexagon norm and the Euclidean one (whose product path must
/// not change), each paired with `optri_oracle::norm::Norm`.
pub fn metrics_with_oracle_norms() -> Vec<(Metric, Norm)> {
    let hexagon = Metric::parse("polygon:2,0,1,2,-1,2,-2,0,-1,-2,1,-2").unwrap();
    let hex_norm = Norm::Polygon(hexagon.unit_polygon().unwrap().to_vec());
    vec![
        (Metric::l1(), Norm::L1),
        (Metric::linf(), Norm::LInf),
        (Metric::lp(3).unwrap(), Norm::Lp(3)),
        (hexagon, hex_norm),
        (Metric::euclidean(), Norm::Lp(2)),
    ]
}

/// The exact key of `t`'s longest edge under `norm` (the oracle's lengths).
pub fn longest_edge_key(norm: &Norm, t: &Triangulation) -> num_rational::BigRational {
    norm.max_edge_key(t.points(), t.triangles())
}
