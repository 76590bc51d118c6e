//! The area criteria of T. S. Vassilev, *Optimal area triangulation*, PhD
//! thesis, University of Saskatchewan, 2005: MaxMin area (maximise the
//! smallest triangle) and MinMax area (minimise the largest).

#[allow(dead_code)] // the registry entries arrive with the polygon criteria
pub(crate) mod convex;
