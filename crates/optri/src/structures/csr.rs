//! [`Csr`]: items grouped by a key in compressed sparse rows — one array of
//! items, each key's items contiguous, and one array of offsets. The
//! adjacency of a graph, the triangles at each corner, the edges each edge
//! crosses: one counting sort builds them all, in O(keys + items).

/// Items grouped by keys `0..keys`: the items of key `k` are
/// `items[offsets[k]..offsets[k + 1]]`. Offsets are `u32` (half the memory
/// of `usize` at 10⁷ items), so at most `u32::MAX` items.
#[derive(Clone, Debug, Default)]
pub(crate) struct Csr<T> {
    offsets: Vec<u32>,
    items: Vec<T>,
}

impl<T: Copy + Default> Csr<T> {
    /// Groups `pairs` (key, item) by key, each key's items in the order the
    /// pairs give them (a stable counting sort). The iterator is traversed
    /// twice, once to count and once to place.
    ///
    /// # Panics
    /// If a key is `keys` or more, or there are more than `u32::MAX` items.
    pub fn from_pairs<I>(keys: usize, pairs: I) -> Self
    where
        I: Iterator<Item = (u32, T)> + Clone,
    {
        let mut offsets = vec![0u32; keys + 1];
        for (k, _) in pairs.clone() {
            offsets[k as usize + 1] += 1;
        }
        for k in 0..keys {
            offsets[k + 1] = offsets[k]
                .checked_add(offsets[k + 1])
                .expect("a CSR holds at most u32::MAX items");
        }
        let mut fill = offsets[..keys].to_vec();
        let mut items = vec![T::default(); offsets[keys] as usize];
        for (k, item) in pairs {
            let slot = &mut fill[k as usize];
            items[*slot as usize] = item;
            *slot += 1;
        }
        Self { offsets, items }
    }
}

impl<T> Csr<T> {
    /// Number of keys.
    #[inline]
    pub fn keys(&self) -> usize {
        self.offsets.len() - 1
    }

    /// The positions of key `k`'s items in [`Self::items`].
    #[inline]
    pub fn range(&self, k: u32) -> std::ops::Range<usize> {
        self.offsets[k as usize] as usize..self.offsets[k as usize + 1] as usize
    }

    /// The items of key `k`.
    #[inline]
    pub fn row(&self, k: u32) -> &[T] {
        &self.items[self.range(k)]
    }

    /// Every item, key by key.
    #[inline]
    pub fn items(&self) -> &[T] {
        &self.items
    }

    /// Every key's items as its own mutable slice, key by key (to sort or
    /// fill the rows independently; collect them to do so in parallel).
    pub fn rows_mut(&mut self) -> impl Iterator<Item = &mut [T]> + '_ {
        let mut rest = &mut self.items[..];
        self.offsets.windows(2).map(move |w| {
            let (head, tail) = std::mem::take(&mut rest).split_at_mut((w[1] - w[0]) as usize);
            rest = tail;
            head
        })
    }

    /// Sorts each key's items.
    pub fn sort_rows(&mut self)
    where
        T: Ord,
    {
        for k in 0..self.keys() {
            self.items[self.offsets[k] as usize..self.offsets[k + 1] as usize].sort_unstable();
        }
    }

    /// The key of every item position (the inverse of the grouping).
    pub fn key_of_each_item(&self) -> Vec<u32> {
        (0..self.keys() as u32)
            .flat_map(|k| std::iter::repeat_n(k, self.range(k).len()))
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pairs_are_grouped_by_key_in_their_order() {
        let pairs = [(2u32, 'a'), (0, 'b'), (2, 'c'), (3, 'd'), (0, 'e')];
        let mut csr = Csr::from_pairs(5, pairs.iter().copied());
        assert_eq!(csr.keys(), 5);
        assert_eq!(csr.row(0), &['b', 'e']);
        assert_eq!(csr.row(1), &[] as &[char]);
        assert_eq!(csr.row(2), &['a', 'c']);
        assert_eq!(csr.row(3), &['d']);
        assert_eq!(csr.row(4), &[] as &[char]);
        assert_eq!(csr.items(), &['b', 'e', 'a', 'c', 'd']);
        assert_eq!(csr.range(2), 2..4);
        assert_eq!(csr.key_of_each_item(), [0, 0, 2, 2, 3]);
        for row in csr.rows_mut() {
            row.reverse();
        }
        assert_eq!(csr.items(), &['e', 'b', 'c', 'a', 'd']);
        csr.sort_rows();
        assert_eq!(csr.items(), &['b', 'e', 'a', 'c', 'd']);
        let empty: Csr<u8> = Csr::from_pairs(0, std::iter::empty());
        assert_eq!(empty.keys(), 0);
        assert!(empty.items().is_empty());
    }
}
