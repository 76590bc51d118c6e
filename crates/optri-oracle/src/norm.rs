//! Norm lengths for the metric tests, written independently of optri's
//! kernel: exact rationals, no filter, no tie-break (the references compare
//! optimal *values*, which do not depend on how ties are broken).

use crate::exact::to_rational;
use num_rational::BigRational;
use num_traits::Signed;

/// A norm on the plane.
#[derive(Clone, Debug)]
pub enum Norm {
    /// `|dx| + |dy|`.
    L1,
    /// `max(|dx|, |dy|)`.
    LInf,
    /// `(|dx|ᵖ + |dy|ᵖ)^(1/p)`, represented by its p-th power.
    Lp(u32),
    /// The gauge of a centrally symmetric convex polygon (counter-clockwise
    /// vertices around the origin).
    Polygon(Vec<[f64; 2]>),
}

impl Norm {
    /// A key with the same order as the length of `ab` (the length itself,
    /// or its p-th power for `Lp`), exact.
    pub fn key(&self, a: [f64; 2], b: [f64; 2]) -> BigRational {
        let dx = (to_rational(b[0]) - to_rational(a[0])).abs();
        let dy = (to_rational(b[1]) - to_rational(a[1])).abs();
        match self {
            Norm::L1 => dx + dy,
            Norm::LInf => dx.max(dy),
            Norm::Lp(p) => num_traits::pow(dx, *p as usize) + num_traits::pow(dy, *p as usize),
            Norm::Polygon(vs) => {
                let dx = to_rational(b[0]) - to_rational(a[0]);
                let dy = to_rational(b[1]) - to_rational(a[1]);
                // ‖v‖ = max over the vertex pairs (u, w) of cross(v, w − u) / cross(u, w)…
                // written as the smallest t with v/t in every edge's half-plane.
                let k = vs.len();
                (0..k)
                    .map(|i| {
                        let (u, w) = (vs[i], vs[(i + 1) % k]);
                        let (ux, uy) = (to_rational(u[0]), to_rational(u[1]));
                        let (wx, wy) = (to_rational(w[0]), to_rational(w[1]));
                        // Half-plane of edge u→w: cross(w − u, x − u) ≥ 0, i.e.
                        // cross(w − u, x) ≥ cross(w − u, u) = −cross(u, w) ... for x = v/t:
                        // t ≥ −cross(w − u, v) / cross(u, w).
                        let ex = &wx - &ux;
                        let ey = &wy - &uy;
                        let cross_e_v = &ex * &dy - &ey * &dx;
                        let cross_u_w = &ux * &wy - &uy * &wx;
                        -cross_e_v / cross_u_w
                    })
                    .max()
                    .expect("vertices")
            }
        }
    }

    /// The largest key over the edges of `triangles`.
    pub fn max_edge_key(&self, points: &[[f64; 2]], triangles: &[[u32; 3]]) -> BigRational {
        triangles
            .iter()
            .flat_map(|t| [[t[0], t[1]], [t[1], t[2]], [t[2], t[0]]])
            .map(|[a, b]| self.key(points[a as usize], points[b as usize]))
            .max()
            .expect("at least one triangle")
    }

    /// The optimal minmax key over every triangulation, by exhaustive
    /// enumeration ([`crate::all_triangulations`], n ≤ 12).
    pub fn exhaustive_minmax(&self, points: &[[f64; 2]]) -> BigRational {
        crate::all_triangulations(points)
            .iter()
            .map(|t| self.max_edge_key(points, t))
            .min()
            .expect("a triangulation")
    }
}
