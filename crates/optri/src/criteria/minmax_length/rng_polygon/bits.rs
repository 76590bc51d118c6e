//! The per-pair tables of §6 steps 1–3 as bits: one row per corner `a` of a
//! region of `k` corners, bit `o` of row `a` describing the position pair
//! `(a, a + o mod k)` (offsets, so that a row lists the corners in the
//! boundary order from `a + 1`, which is the order the scans read them).
//!
//! A region in convex position has Θ(k²) visible pairs, a third of them
//! with an empty half-lune, so lists of `u32` offsets cost about 3 bytes a
//! pair; a bit matrix costs an eighth of a byte and is read row by row.
//! Rows that answer predecessor / successor queries (the partners of §6
//! step 2) carry a 64-ary summary tree: bit `i` of a level is set iff word
//! `i` of the level below is non-zero, so a query reads one word per level,
//! O(log₆₄ k) words (three levels up to k = 262 144).

use crate::parallel::prelude::*;

/// Bits per word.
pub(super) const WORD: usize = 64;

/// `rows` rows of `bits` bits each, row-major in one allocation.
pub(super) struct BitRows {
    bits: usize,
    /// Words per row: level 0 and, if summarised, the summary levels.
    stride: usize,
    /// Start and length (in words) of each level within a row; level 0 first.
    levels: Vec<(usize, usize)>,
    words: Vec<u64>,
}

/// One row of a [`BitRows`].
#[derive(Clone, Copy)]
pub(super) struct Row<'a> {
    words: &'a [u64],
    levels: &'a [(usize, usize)],
}

impl BitRows {
    /// All-zero rows; with `summarised`, the rows answer [`Row::pred`] and
    /// [`Row::succ`].
    pub fn new(rows: usize, bits: usize, summarised: bool) -> Self {
        let mut levels = vec![(0, bits.div_ceil(WORD).max(1))];
        let mut stride = levels[0].1;
        while summarised && levels.last().is_some_and(|&(_, len)| len > 1) {
            let len = levels.last().map_or(1, |&(_, len)| len.div_ceil(WORD));
            levels.push((stride, len));
            stride += len;
        }
        Self {
            bits,
            stride,
            levels,
            words: vec![0; rows * stride],
        }
    }

    pub fn rows(&self) -> usize {
        self.words.len() / self.stride
    }

    pub fn row(&self, r: usize) -> Row<'_> {
        Row {
            words: &self.words[r * self.stride..(r + 1) * self.stride],
            levels: &self.levels,
        }
    }

    /// Fills every row: `set(r, level_0)` sets the bits of row `r` in its
    /// (zeroed) level 0; then the summaries are built. In parallel if
    /// `parallel`.
    pub fn fill(&mut self, parallel: bool, set: impl Fn(usize, &mut [u64]) + Sync + Send) {
        let (len0, levels) = (self.levels[0].1, &self.levels);
        let fill_row = |(r, row): (usize, &mut [u64])| {
            set(r, &mut row[..len0]);
            summarise(row, levels);
        };
        if parallel {
            self.words
                .par_chunks_mut(self.stride)
                .enumerate()
                .for_each(fill_row);
        } else {
            self.words
                .chunks_mut(self.stride)
                .enumerate()
                .for_each(fill_row);
        }
    }

    /// `f(first_row, words)` on consecutive blocks of `rows_per_block` rows
    /// (the block's words, one row after the other), in parallel if
    /// `parallel`. The matrix must not be summarised (`f` may change bits).
    pub fn blocks_mut(
        &mut self,
        rows_per_block: usize,
        parallel: bool,
        f: impl Fn(usize, &mut [u64]) + Sync + Send,
    ) {
        assert_eq!(self.levels.len(), 1, "summaries would go stale");
        let size = rows_per_block * self.stride;
        let block = |(i, words): (usize, &mut [u64])| f(i * rows_per_block, words);
        if parallel {
            self.words.par_chunks_mut(size).enumerate().for_each(block);
        } else {
            self.words.chunks_mut(size).enumerate().for_each(block);
        }
    }

    /// Words per row.
    pub fn stride(&self) -> usize {
        self.stride
    }

    /// The skewed transpose of a square offset matrix (`rows = bits = k`):
    /// bit `k − o` of row `a + o mod k` is set iff bit `o` of row `a` is —
    /// the same pair seen from its other end. Built in blocks of 64 target
    /// rows: each block reads 64 consecutive bits of every source row and
    /// writes its own rows only, so the blocks run in parallel and every
    /// source row is touched once per block (O(k²/64) words read).
    pub fn transposed(&self, parallel: bool, summarised: bool) -> Self {
        let k = self.bits;
        assert_eq!(self.rows(), k, "a square offset matrix");
        let mut out = Self::new(k, k, summarised);
        let (stride, len0, levels) = (out.stride, out.levels[0].1, &out.levels);
        let block = |(blk, chunk): (usize, &mut [u64])| {
            let b0 = blk * WORD;
            let rows = chunk.len() / stride;
            for a in 0..k {
                let src = &self.row(a).words[..self.levels[0].1];
                // Offsets of the targets b0 .. b0 + rows seen from a: a run
                // starting at (b0 − a) mod k that may wrap past k to 0.
                let start = (b0 + k - a) % k;
                let head = rows.min(k - start);
                let mut window = bits_window(src, start, head);
                if head < rows {
                    window |= bits_window(src, 0, rows - head) << head;
                }
                while window != 0 {
                    let j = window.trailing_zeros() as usize;
                    window &= window - 1;
                    // Target b = b0 + j sees a at offset (a − b) mod k.
                    let o = (a + k - (b0 + j)) % k;
                    chunk[j * stride + o / WORD] |= 1 << (o % WORD);
                }
            }
            for row in chunk.chunks_mut(stride) {
                debug_assert!(row[len0..].iter().all(|&w| w == 0));
                summarise(row, levels);
            }
        };
        let block_words = WORD * stride;
        if parallel {
            out.words
                .par_chunks_mut(block_words)
                .enumerate()
                .for_each(block);
        } else {
            out.words
                .chunks_mut(block_words)
                .enumerate()
                .for_each(block);
        }
        out
    }
}

/// Bits `start .. start + len` (`len ≤ 64`) of `words`, as the low bits.
#[inline]
fn bits_window(words: &[u64], start: usize, len: usize) -> u64 {
    if len == 0 {
        return 0;
    }
    let (w, s) = (start / WORD, start % WORD);
    let mut x = words[w] >> s;
    if s != 0 && w + 1 < words.len() {
        x |= words[w + 1] << (WORD - s);
    }
    if len < WORD {
        x &= (1 << len) - 1;
    }
    x
}

/// Rebuilds the summary levels of `row` from its level 0.
fn summarise(row: &mut [u64], levels: &[(usize, usize)]) {
    for l in 1..levels.len() {
        let ((below, below_len), (at, len)) = (levels[l - 1], levels[l]);
        for i in 0..len {
            let mut w = 0u64;
            for j in 0..WORD.min(below_len - i * WORD) {
                if row[below + i * WORD + j] != 0 {
                    w |= 1 << j;
                }
            }
            row[at + i] = w;
        }
    }
}

/// The set bits in `lo ..= hi` of the words `word(w)`, in increasing order.
fn ones_of<'a>(
    lo: usize,
    hi: usize,
    word: impl Fn(usize) -> u64 + 'a,
) -> impl Iterator<Item = usize> + 'a {
    let words = if lo > hi {
        0..0
    } else {
        lo / WORD..hi / WORD + 1
    };
    words.flat_map(move |w| {
        let mut m = word(w) & in_range(w, lo, hi);
        std::iter::from_fn(move || {
            (m != 0).then(|| {
                let j = m.trailing_zeros() as usize;
                m &= m - 1;
                w * WORD + j
            })
        })
    })
}

/// The bits of word `w` that lie in `lo ..= hi`.
#[inline]
pub(super) fn in_range(w: usize, lo: usize, hi: usize) -> u64 {
    let mut m = !0u64;
    if w == lo / WORD {
        m &= !0u64 << (lo % WORD);
    }
    if w == hi / WORD && hi % WORD != WORD - 1 {
        m &= (1u64 << (hi % WORD + 1)) - 1;
    }
    if w < lo / WORD || w > hi / WORD {
        m = 0;
    }
    m
}

/// Sets bit `o` of a level-0 slice.
#[inline]
pub(super) fn set(level_0: &mut [u64], o: usize) {
    level_0[o / WORD] |= 1 << (o % WORD);
}

impl<'a> Row<'a> {
    /// Level 0: the row's bits, 64 to a word.
    #[inline]
    pub fn level_0(&self) -> &'a [u64] {
        &self.words[..self.levels[0].1]
    }

    #[cfg(test)]
    pub fn contains(&self, o: usize) -> bool {
        self.words[o / WORD] >> (o % WORD) & 1 == 1
    }

    /// The largest set bit below `o`. The row must be summarised.
    pub fn pred(&self, o: usize) -> Option<usize> {
        let mut i = o;
        for (l, &(start, _)) in self.levels.iter().enumerate() {
            let (w, bit) = (i / WORD, i % WORD);
            let below = self.words[start + w] & ((1u64 << bit) - 1);
            if below != 0 {
                let mut found = w * WORD + (WORD - 1 - below.leading_zeros() as usize);
                // Down the tree: the highest set bit of each word below.
                for &(start, _) in self.levels[..l].iter().rev() {
                    let word = self.words[start + found];
                    found = found * WORD + (WORD - 1 - word.leading_zeros() as usize);
                }
                return Some(found);
            }
            i = w;
        }
        None
    }

    /// The smallest set bit above `o`. The row must be summarised.
    pub fn succ(&self, o: usize) -> Option<usize> {
        let mut i = o;
        for (l, &(start, len)) in self.levels.iter().enumerate() {
            let (w, bit) = (i / WORD, i % WORD);
            if w >= len {
                return None;
            }
            // Bits strictly above `bit` (none for bit 63: bit 0 of !1 is 0).
            let above = self.words[start + w] & (!1u64).wrapping_shl(bit as u32);
            if above != 0 {
                let mut found = w * WORD + above.trailing_zeros() as usize;
                for &(start, _) in self.levels[..l].iter().rev() {
                    let word = self.words[start + found];
                    found = found * WORD + word.trailing_zeros() as usize;
                }
                return Some(found);
            }
            i = w;
        }
        None
    }

    /// The set bits in `lo ..= hi` of `self & !minus_1 & !minus_2`, in
    /// increasing order.
    #[cfg(test)]
    pub fn ones_without(
        self,
        minus_1: Row<'a>,
        minus_2: Row<'a>,
        lo: usize,
        hi: usize,
    ) -> impl Iterator<Item = usize> + 'a {
        let (a, b, c) = (self.level_0(), minus_1.level_0(), minus_2.level_0());
        ones_of(lo, hi, move |w| a[w] & !b[w] & !c[w])
    }

    /// The set bits in `lo ..= hi`, in increasing order.
    pub fn ones_in(self, lo: usize, hi: usize) -> impl Iterator<Item = usize> + 'a {
        let a = self.level_0();
        ones_of(lo, hi, move |w| a[w])
    }

    /// The set bits, in increasing order.
    pub fn ones(self) -> impl Iterator<Item = usize> + 'a {
        self.level_0().iter().enumerate().flat_map(|(w, &word)| {
            let mut m = word;
            std::iter::from_fn(move || {
                (m != 0).then(|| {
                    let j = m.trailing_zeros() as usize;
                    m &= m - 1;
                    w * WORD + j
                })
            })
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{rngs::StdRng, Rng, SeedableRng};

    /// Seed of the random bit patterns.
    const PATTERNS_SEED: u64 = 11;

    /// Random k × k offset matrices of several densities (sparse runs as in
    /// convex position, single bits, dense), against sorted lists: the
    /// predecessor / successor queries and the skewed transpose.
    #[test]
    fn queries_and_transpose_match_sorted_lists() {
        let mut rng = StdRng::seed_from_u64(PATTERNS_SEED);
        for &k in &[1usize, 2, 3, 63, 64, 65, 130, 300, 4095, 4097, 5000] {
            let rows = if k <= 300 { k } else { 70 };
            for density in [0.0, 0.002, 0.3, 1.0] {
                let lists: Vec<Vec<usize>> = (0..rows)
                    .map(|_| (0..k).filter(|_| rng.gen_bool(density)).collect())
                    .collect();
                let mut m = BitRows::new(rows, k, true);
                m.fill(rows % 2 == 0, |r, level_0| {
                    for &o in &lists[r] {
                        set(level_0, o);
                    }
                });
                for (r, list) in lists.iter().enumerate() {
                    let row = m.row(r);
                    assert_eq!(row.ones().collect::<Vec<_>>(), *list);
                    for _ in 0..50 {
                        let o = rng.gen_range(0..k);
                        let pred = list.iter().rev().find(|&&x| x < o).copied();
                        let succ = list.iter().find(|&&x| x > o).copied();
                        assert_eq!(row.pred(o), pred, "k={k} row {r} pred({o})");
                        assert_eq!(row.succ(o), succ, "k={k} row {r} succ({o})");
                        assert_eq!(row.contains(o), list.contains(&o));
                        let (lo, hi) = (rng.gen_range(0..k), rng.gen_range(0..k));
                        let other = m.row((r + 1) % rows);
                        let want: Vec<usize> = list
                            .iter()
                            .copied()
                            .filter(|&x| lo <= x && x <= hi && !other.contains(x))
                            .collect();
                        let got: Vec<usize> = row.ones_without(other, other, lo, hi).collect();
                        assert_eq!(got, want, "k={k} row {r} {lo}..={hi}");
                        let want: Vec<usize> = list
                            .iter()
                            .copied()
                            .filter(|&x| lo <= x && x <= hi)
                            .collect();
                        assert_eq!(row.ones_in(lo, hi).collect::<Vec<_>>(), want);
                    }
                }
                if rows == k {
                    let t = m.transposed(k % 2 == 0, true);
                    for a in 0..k {
                        for b in 0..k {
                            let o = (b + k - a) % k;
                            assert_eq!(
                                t.row(b).contains((k - o) % k),
                                m.row(a).contains(o),
                                "k={k} pair {a} {b}"
                            );
                        }
                    }
                    for b in 0..k {
                        let row = t.row(b);
                        let list: Vec<usize> = row.ones().collect();
                        for o in 0..k {
                            assert_eq!(row.pred(o), list.iter().rev().find(|&&x| x < o).copied());
                            assert_eq!(row.succ(o), list.iter().find(|&&x| x > o).copied());
                        }
                    }
                }
            }
        }
    }
}
