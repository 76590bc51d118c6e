//! What one run did, counted: which branches of the algorithm ran and how
//! often the safety nets caught something. One [`Counters`] per run, shared
//! by reference with the regions (which run in parallel), and reported as the
//! run's [`Diagnostics`].

use crate::criteria::Diagnostics;
use std::sync::atomic::{AtomicUsize, Ordering};

/// One counter, incremented from any thread.
#[derive(Default)]
pub(crate) struct Count(AtomicUsize);

impl Count {
    #[inline]
    pub fn add(&self, by: usize) {
        self.0.fetch_add(by, Ordering::Relaxed);
    }

    pub fn get(&self) -> u64 {
        self.0.load(Ordering::Relaxed) as u64
    }
}

/// The counters of one run. Each field is reported under its own name.
#[derive(Default)]
pub(crate) struct Counters {
    /// §6 Case 1: the partners of a 2-edge side meet.
    pub case_1: Count,
    /// §6 Case 2: the partners `pp′` and `qq″` cross.
    pub case_2: Count,
    /// Total corners of the §6 Case 2 parts handed to the cubic safety net.
    pub case_2_remainder_vertices: Count,
    /// Flat triangles (corners collinear in `S`) removed by §5.4's repair.
    pub flat_triangles: Count,
    /// §6 Case 2 hull constructions that failed a check, the whole remainder
    /// then going to the cubic program (a bug indicator).
    pub case_2_hull_fallbacks: Count,
    /// §6 Case 2 pockets closed by a 1-edge with `pq` beneath it,
    /// triangulated by §5.1 (step 3.1 with `u_L = v`).
    pub case_2_pockets_by_5_1: Count,
    /// §6 Case 2 pockets triangulated by steps 3.1–3.3 (a `u_L ≠ v`, §5.1
    /// clipped to the pocket, the §5.2 fan-out).
    pub case_2_pockets_by_fan_out: Count,
    /// §6 Case 2 pockets whose step-3 triangulation failed a check and went
    /// to the cubic program (also in `fallbacks`; a bug indicator).
    pub case_2_pocket_fallbacks: Count,
    /// Small regions (fewer than [`super::SMALL_REGION`] corners, more than
    /// four) handed to the cubic program.
    pub small_regions_by_dp: Count,
    /// Small regions whose Delaunay triangles the apex lower bound certified.
    pub small_regions_certified: Count,
    /// Regions (or, counted once, whole inputs) whose Delaunay triangles met
    /// the Length Lemma bound.
    pub regions_certified_by_bound: Count,
    /// Regions, and §6 Case 2 pockets, on which the quadratic algorithm met
    /// an inconsistency and the cubic program took over (a bug indicator).
    pub fallbacks: Count,
}

impl Counters {
    /// The counters under their stable names, every one reported (zeros
    /// included).
    pub fn into_diagnostics(self) -> Diagnostics {
        let mut d = Diagnostics::default();
        for (name, count) in [
            ("case_1", &self.case_1),
            ("case_2", &self.case_2),
            ("case_2_remainder_vertices", &self.case_2_remainder_vertices),
            ("flat_triangles", &self.flat_triangles),
            ("case_2_hull_fallbacks", &self.case_2_hull_fallbacks),
            ("case_2_pockets_by_5_1", &self.case_2_pockets_by_5_1),
            ("case_2_pockets_by_fan_out", &self.case_2_pockets_by_fan_out),
            ("case_2_pocket_fallbacks", &self.case_2_pocket_fallbacks),
            ("small_regions_by_dp", &self.small_regions_by_dp),
            ("small_regions_certified", &self.small_regions_certified),
            (
                "regions_certified_by_bound",
                &self.regions_certified_by_bound,
            ),
            ("fallbacks", &self.fallbacks),
        ] {
            d.add(name, count.get());
        }
        d
    }

    /// The counters the metric path reports (the others stay zero there).
    pub fn into_diagnostics_for_metric(self) -> Diagnostics {
        let mut d = Diagnostics::default();
        for (name, count) in [
            ("case_1", &self.case_1),
            ("case_2", &self.case_2),
            ("case_2_hull_fallbacks", &self.case_2_hull_fallbacks),
            ("case_2_pockets_by_5_1", &self.case_2_pockets_by_5_1),
            ("case_2_pockets_by_fan_out", &self.case_2_pockets_by_fan_out),
            ("case_2_pocket_fallbacks", &self.case_2_pocket_fallbacks),
            ("flat_triangles", &self.flat_triangles),
            ("fallbacks", &self.fallbacks),
        ] {
            d.add(name, count.get());
        }
        d
    }
}
