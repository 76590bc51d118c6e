//! The three item measures of the δ-triangulations and their exact ranks.
//!
//! Every triangle of the polygon gets a *low* and a *high* rank: the ranks,
//! in the exact order of the measure, of its smallest and largest item (its
//! area twice for δ-area; its shortest and longest side for δ-length; its
//! smallest and largest angle for δ-angle). Every item of a triangulation
//! is an item of one of its triangles (each edge borders one), so a
//! triangulation's largest item is the largest high of its triangles and its
//! smallest item the smallest low: the sweep compares ranks only, and exact
//! measures enter in two places, the sort that ranks the items and the
//! comparison of differences (`kernel::differences`).

use crate::kernel::{
    compare_angle_differences, compare_area_differences, compare_areas, compare_corner_angles,
    compare_length_differences, compare_lengths, orient_sign, Point,
};
use std::cmp::Ordering;

/// What δ measures.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Measure {
    /// Triangle areas.
    Area,
    /// The interior angles of the triangles.
    Angle,
    /// Edge lengths, boundary edges included.
    Length,
}

/// An item as corners: a triangle `[a, b, c]` (area), a corner
/// `[apex, a, b]` (angle) or a segment `[a, b, _]` (length).
pub(crate) type Item = [u32; 3];

impl Measure {
    /// The exact order of two items.
    pub(crate) fn compare(self, point: &impl Fn(usize) -> Point, s: Item, t: Item) -> Ordering {
        let p = |i: Item| i.map(|c| point(c as usize));
        let (s, t) = (p(s), p(t));
        match self {
            Measure::Area => compare_areas(s, t),
            Measure::Angle => compare_corner_angles(s, t),
            Measure::Length => compare_lengths(s[0], s[1], t[0], t[1]),
        }
    }

    /// The exact order of the differences `high₁ − low₁` and
    /// `high₂ − low₂`.
    pub(crate) fn compare_differences(
        self,
        point: &impl Fn(usize) -> Point,
        [high1, low1]: [Item; 2],
        [high2, low2]: [Item; 2],
    ) -> Ordering {
        let p = |i: Item| i.map(|c| point(c as usize));
        let items = [high1, low1, high2, low2].map(p);
        match self {
            Measure::Area => compare_area_differences(items),
            Measure::Angle => compare_angle_differences(items),
            Measure::Length => compare_length_differences(items.map(|[a, b, _]| [a, b])),
        }
    }

    /// A rounded value that orders items approximately: only the sort's
    /// speed depends on it (nearly sorted input), never its result.
    fn rough(self, point: &impl Fn(usize) -> Point, item: Item) -> f64 {
        let [o, a, b] = item.map(|c| point(c as usize));
        let (ux, uy, vx, vy) = (a[0] - o[0], a[1] - o[1], b[0] - o[0], b[1] - o[1]);
        match self {
            Measure::Area => (ux * vy - uy * vx).abs(),
            Measure::Angle => (ux * vy - uy * vx).abs().atan2(ux * vx + uy * vy),
            Measure::Length => ux * ux + uy * uy,
        }
    }

    /// The items of the triangle of corners `[i, m, j]`.
    fn items(self, [i, m, j]: [u32; 3]) -> Vec<Item> {
        match self {
            Measure::Area => vec![[i, m, j]],
            Measure::Angle => vec![[i, m, j], [m, j, i], [j, i, m]],
            Measure::Length => vec![[i, m, 0], [m, j, 0], [i, j, 0]],
        }
    }

    /// The δ of the triangles `triangles` (corner triples, none flat): its
    /// largest and smallest item, chosen exactly.
    pub(crate) fn extremes(
        self,
        point: &impl Fn(usize) -> Point,
        triangles: &[[u32; 3]],
    ) -> [Item; 2] {
        let mut items = triangles.iter().flat_map(|&t| self.items(t));
        let first = items.next().expect("a triangulation has a triangle");
        items.fold([first, first], |[high, low], item| {
            [
                if self.compare(point, item, high) == Ordering::Greater {
                    item
                } else {
                    high
                },
                if self.compare(point, item, low) == Ordering::Less {
                    item
                } else {
                    low
                },
            ]
        })
    }
}

/// No rank: the triangle is flat, so never allowed.
pub(crate) const FLAT: u32 = u32::MAX;

/// The low and high ranks of every triangle `i < m < j` of a polygon of `k`
/// corners, and an item of each rank.
pub(crate) struct RankedTriangles {
    k: usize,
    /// `offsets[i * k + j]`: the slot of triangle `(i, i + 1, j)`; the
    /// triangle `(i, m, j)` is at `offsets[i * k + j] + m − i − 1`.
    offsets: Vec<u32>,
    /// Per slot: the low rank, or [`FLAT`].
    pub(crate) low: Vec<u32>,
    /// Per slot: the high rank.
    pub(crate) high: Vec<u32>,
    /// An item of each rank, in increasing order of measure.
    pub(crate) representative: Vec<Item>,
}

impl RankedTriangles {
    /// Ranks the items of every non-flat triangle of corners `0..k` (corner
    /// `c` at `point(c)`) under `measure`. O(k³ log k) comparisons, O(k³)
    /// memory; flat triangles get [`FLAT`].
    pub(crate) fn new(measure: Measure, k: usize, point: &impl Fn(usize) -> Point) -> Self {
        let mut offsets = vec![0u32; k * k];
        let mut slots = 0u32;
        let mut corners: Vec<[u32; 3]> = Vec::new();
        for i in 0..k {
            for j in i + 2..k {
                offsets[i * k + j] = slots;
                slots += (j - i - 1) as u32;
                corners.extend((i + 1..j).map(|m| [i as u32, m as u32, j as u32]));
            }
        }
        let flat: Vec<bool> = corners
            .iter()
            .map(|t| {
                let [a, b, c] = t.map(|c| point(c as usize));
                orient_sign(a, b, c) == 0
            })
            .collect();
        // The items to rank and, per slot, the indices of its items.
        let mut items: Vec<Item> = Vec::new();
        let per_slot: usize = match measure {
            Measure::Area => 1,
            _ => 3,
        };
        let mut slot_items: Vec<u32> = Vec::with_capacity(corners.len() * per_slot);
        let edge = |a: u32, b: u32| (a as usize * k + b as usize) as u32;
        if measure == Measure::Length {
            items.extend((0..k * k).map(|e| [(e / k) as u32, (e % k) as u32, 0]));
        }
        for (s, &t) in corners.iter().enumerate() {
            if flat[s] {
                continue;
            }
            let [i, m, j] = t;
            match measure {
                Measure::Length => slot_items.extend([edge(i, m), edge(m, j), edge(i, j)]),
                _ => {
                    for item in measure.items(t) {
                        slot_items.push(items.len() as u32);
                        items.push(item);
                    }
                }
            }
        }
        let rank = ranks(measure, point, &items);
        let (ranks_of, representative) = rank;
        let (mut low, mut high) = (vec![FLAT; corners.len()], vec![0; corners.len()]);
        let mut next = slot_items.iter();
        for s in 0..corners.len() {
            if flat[s] {
                continue;
            }
            let of_slot: Vec<u32> = next
                .by_ref()
                .take(per_slot)
                .map(|&x| ranks_of[x as usize])
                .collect();
            low[s] = *of_slot.iter().min().expect("a triangle has an item");
            high[s] = *of_slot.iter().max().expect("a triangle has an item");
        }
        Self {
            k,
            offsets,
            low,
            high,
            representative,
        }
    }

    /// The slot of the triangle of corners `i < m < j`.
    #[inline]
    pub(crate) fn slot(&self, i: usize, m: usize, j: usize) -> usize {
        self.offsets[i * self.k + j] as usize + m - i - 1
    }
}

/// The rank of each item (equal measures, equal ranks) and an item per
/// rank, by one exact sort (after a rough one that only saves comparisons).
fn ranks(
    measure: Measure,
    point: &impl Fn(usize) -> Point,
    items: &[Item],
) -> (Vec<u32>, Vec<Item>) {
    let rough: Vec<f64> = items.iter().map(|&i| measure.rough(point, i)).collect();
    let mut order: Vec<u32> = (0..items.len() as u32).collect();
    order.sort_unstable_by(|&a, &b| rough[a as usize].total_cmp(&rough[b as usize]));
    // Nearly sorted now: the stable sort's run detection makes this pass
    // close to linear.
    let exact = |a: u32, b: u32| measure.compare(point, items[a as usize], items[b as usize]);
    order.sort_by(|&a, &b| exact(a, b));
    let mut rank = vec![0u32; items.len()];
    let mut representative: Vec<Item> = Vec::new();
    for (position, &x) in order.iter().enumerate() {
        if position == 0 || exact(order[position - 1], x) != Ordering::Equal {
            representative.push(items[x as usize]);
        }
        rank[x as usize] = representative.len() as u32 - 1;
    }
    (rank, representative)
}
