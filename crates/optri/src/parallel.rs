//! Data parallelism behind the `parallel` feature.
//!
//! With the feature (the default) this is rayon's prelude. Without it — for
//! `wasm32-unknown-unknown`, or for single-threaded embedding — the same
//! method names run sequentially on ordinary iterators, so algorithm modules
//! are written once against `crate::parallel::prelude::*` and never mention
//! the feature. Results are identical either way: every parallel step in
//! optri is a map, a filter or an associative reduction whose order does not
//! matter, a sort by a total order, or — the minimum-weight LMT loop — tasks
//! sharing monotone atomic flags whose fixed point is unique (the argument
//! is in that loop's docs).

#[cfg(feature = "parallel")]
pub(crate) mod prelude {
    pub(crate) use rayon::iter::FromParallelIterator;
    pub(crate) use rayon::prelude::*;
}

#[cfg(not(feature = "parallel"))]
pub(crate) mod prelude {
    pub(crate) use super::sequential::{
        FromParallelIterator, IntoParallelIterator, ParallelSlice, ParallelSliceMut,
    };
}

#[cfg(not(feature = "parallel"))]
mod sequential {
    use std::cmp::Ordering;

    /// A sequential stand-in for a rayon parallel iterator. Its inherent
    /// methods shadow [`Iterator`]'s where rayon's signatures differ
    /// (`fold` and `reduce` take an identity closure) and keep the wrapper
    /// through adapters, so rayon-style chains compile unchanged.
    pub(crate) struct Seq<I>(I);

    impl<I: Iterator> Iterator for Seq<I> {
        type Item = I::Item;
        #[inline]
        fn next(&mut self) -> Option<I::Item> {
            self.0.next()
        }
        #[inline]
        fn size_hint(&self) -> (usize, Option<usize>) {
            self.0.size_hint()
        }
    }

    impl<I: Iterator> Seq<I> {
        #[inline]
        pub(crate) fn map<B, F: FnMut(I::Item) -> B>(self, f: F) -> Seq<std::iter::Map<I, F>> {
            Seq(self.0.map(f))
        }
        #[inline]
        pub(crate) fn filter<F: FnMut(&I::Item) -> bool>(
            self,
            f: F,
        ) -> Seq<std::iter::Filter<I, F>> {
            Seq(self.0.filter(f))
        }
        #[inline]
        pub(crate) fn enumerate(self) -> Seq<std::iter::Enumerate<I>> {
            Seq(self.0.enumerate())
        }
        #[inline]
        pub(crate) fn zip<J: IntoIterator>(self, other: J) -> Seq<std::iter::Zip<I, J::IntoIter>> {
            Seq(self.0.zip(other))
        }
        #[inline]
        pub(crate) fn flat_map_iter<U: IntoIterator, F: FnMut(I::Item) -> U>(
            self,
            f: F,
        ) -> Seq<std::iter::FlatMap<I, U, F>> {
            Seq(self.0.flat_map(f))
        }
        #[inline]
        pub(crate) fn flatten(self) -> Seq<std::iter::Flatten<I>>
        where
            I::Item: IntoIterator,
        {
            Seq(self.0.flatten())
        }
        #[inline]
        pub(crate) fn with_min_len(self, _: usize) -> Self {
            self
        }
        /// rayon's `chunks`: vectors of `size` consecutive items.
        pub(crate) fn chunks(self, size: usize) -> Seq<std::vec::IntoIter<Vec<I::Item>>> {
            let mut out = Vec::new();
            let mut chunk = Vec::with_capacity(size);
            for item in self.0 {
                chunk.push(item);
                if chunk.len() == size {
                    out.push(std::mem::replace(&mut chunk, Vec::with_capacity(size)));
                }
            }
            if !chunk.is_empty() {
                out.push(chunk);
            }
            Seq(out.into_iter())
        }
        /// rayon's `reduce_with`: `None` for an empty iterator.
        #[inline]
        pub(crate) fn reduce_with<F: FnMut(I::Item, I::Item) -> I::Item>(
            self,
            op: F,
        ) -> Option<I::Item> {
            self.0.reduce(op)
        }
        /// rayon's `fold`: one accumulator per work item; sequentially, one.
        #[inline]
        pub(crate) fn fold<T, Id: Fn() -> T, F: FnMut(T, I::Item) -> T>(
            self,
            identity: Id,
            op: F,
        ) -> Seq<std::iter::Once<T>> {
            Seq(std::iter::once(self.0.fold(identity(), op)))
        }
        /// rayon's `reduce`: `identity()` for an empty iterator.
        #[inline]
        pub(crate) fn reduce<Id: Fn() -> I::Item, F: FnMut(I::Item, I::Item) -> I::Item>(
            self,
            identity: Id,
            op: F,
        ) -> I::Item {
            self.0.fold(identity(), op)
        }
    }

    /// rayon's `into_par_iter`, for everything iterable.
    pub(crate) trait IntoParallelIterator: IntoIterator + Sized {
        #[inline]
        fn into_par_iter(self) -> Seq<Self::IntoIter> {
            Seq(self.into_iter())
        }
    }
    impl<I: IntoIterator> IntoParallelIterator for I {}

    /// rayon's slice methods that borrow.
    pub(crate) trait ParallelSlice<T> {
        fn par_iter(&self) -> Seq<std::slice::Iter<'_, T>>;
        fn par_chunks(&self, size: usize) -> Seq<std::slice::Chunks<'_, T>>;
    }
    impl<T> ParallelSlice<T> for [T] {
        #[inline]
        fn par_iter(&self) -> Seq<std::slice::Iter<'_, T>> {
            Seq(self.iter())
        }
        #[inline]
        fn par_chunks(&self, size: usize) -> Seq<std::slice::Chunks<'_, T>> {
            Seq(self.chunks(size))
        }
    }

    /// rayon's slice methods that mutate.
    pub(crate) trait ParallelSliceMut<T> {
        fn par_iter_mut(&mut self) -> Seq<std::slice::IterMut<'_, T>>;
        fn par_chunks_mut(&mut self, size: usize) -> Seq<std::slice::ChunksMut<'_, T>>;
        fn par_sort_unstable(&mut self)
        where
            T: Ord;
        fn par_sort_unstable_by<F: FnMut(&T, &T) -> Ordering>(&mut self, compare: F);
        // Only the LMT-skeleton's reference build (tests, `internals`) sorts by key.
        #[cfg(any(test, feature = "internals"))]
        fn par_sort_unstable_by_key<K: Ord, F: FnMut(&T) -> K>(&mut self, key: F);
    }
    impl<T> ParallelSliceMut<T> for [T] {
        #[inline]
        fn par_iter_mut(&mut self) -> Seq<std::slice::IterMut<'_, T>> {
            Seq(self.iter_mut())
        }
        #[inline]
        fn par_chunks_mut(&mut self, size: usize) -> Seq<std::slice::ChunksMut<'_, T>> {
            Seq(self.chunks_mut(size))
        }
        #[inline]
        fn par_sort_unstable(&mut self)
        where
            T: Ord,
        {
            self.sort_unstable()
        }
        #[inline]
        fn par_sort_unstable_by<F: FnMut(&T, &T) -> Ordering>(&mut self, compare: F) {
            self.sort_unstable_by(compare)
        }
        #[cfg(any(test, feature = "internals"))]
        #[inline]
        fn par_sort_unstable_by_key<K: Ord, F: FnMut(&T) -> K>(&mut self, key: F) {
            self.sort_unstable_by_key(key)
        }
    }

    /// rayon's `FromParallelIterator`: every collection.
    pub(crate) trait FromParallelIterator<T>: FromIterator<T> {}
    impl<T, C: FromIterator<T>> FromParallelIterator<T> for C {}
}
