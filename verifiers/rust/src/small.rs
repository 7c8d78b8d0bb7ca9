//! A short list kept inline, without a heap allocation, up to `N` items.
//!
//! Judging a vector reads a handful of small tables (the slot keys, the initial image, the
//! operands, the steps, the expected states) and builds one device image. Kept inline, the tables of one vector sit next
//! to each other inside the vector (and the vectors of a suite next to each other in one array),
//! so a run streams through memory instead of chasing a pointer per table, and a device image
//! costs no allocation. A longer list (a vector copy with more devices than the golden set
//! has) goes to the heap and works the same.

use std::fmt;
use std::ops::{Deref, DerefMut};

/// Up to `N` items inline, more on the heap; reads and writes as a slice.
#[derive(Clone)]
pub(crate) enum Small<T: Clone, const N: usize> {
    /// `len` items at the start of `items` (the rest are copies, never read).
    Inline { len: usize, items: [T; N] },
    /// An empty list, or one longer than `N`.
    Heap(Vec<T>),
}

impl<T: Clone, const N: usize> Small<T, N> {
    /// A copy of `items`.
    #[inline]
    pub(crate) fn from_slice(items: &[T]) -> Small<T, N> {
        match items.first() {
            Some(first) if items.len() <= N => Small::Inline {
                len: items.len(),
                items: std::array::from_fn(|i| items.get(i).unwrap_or(first).clone()),
            },
            _ => Small::Heap(items.to_vec()),
        }
    }

    /// `len` copies of `item`.
    #[inline]
    pub(crate) fn filled(item: T, len: usize) -> Small<T, N> {
        if len <= N {
            Small::Inline { len, items: std::array::from_fn(|_| item.clone()) }
        } else {
            Small::Heap(vec![item; len])
        }
    }
}

impl<const N: usize> Small<u64, N> {
    /// The index of `key`'s first occurrence. An inline list compares all `N` places at once,
    /// without a branch per item (the unused places repeat the first item, so they never give a
    /// lower index than a real one): a look-up costs no mispredicted branch, wherever it stops.
    #[inline]
    pub(crate) fn find(&self, key: u64) -> Option<usize> {
        match self {
            Small::Inline { items, .. } => {
                const { assert!(N <= 64, "one bit per place") };
                let hits = items.iter().enumerate().fold(0u64, |hits, (i, &k)| hits | u64::from(k == key) << i);
                (hits != 0).then(|| hits.trailing_zeros() as usize)
            }
            Small::Heap(items) => items.iter().position(|&k| k == key),
        }
    }
}

impl<T: Clone, const N: usize> Default for Small<T, N> {
    fn default() -> Small<T, N> {
        Small::Heap(Vec::new())
    }
}

impl<T: Clone, const N: usize> Deref for Small<T, N> {
    type Target = [T];
    #[inline]
    fn deref(&self) -> &[T] {
        match self {
            Small::Inline { len, items } => &items[..*len],
            Small::Heap(v) => v,
        }
    }
}

impl<T: Clone, const N: usize> DerefMut for Small<T, N> {
    #[inline]
    fn deref_mut(&mut self) -> &mut [T] {
        match self {
            Small::Inline { len, items } => &mut items[..*len],
            Small::Heap(v) => v,
        }
    }
}

impl<T: Clone, const N: usize> FromIterator<T> for Small<T, N> {
    fn from_iter<I: IntoIterator<Item = T>>(iter: I) -> Small<T, N> {
        let items: Vec<T> = iter.into_iter().collect(); // at load only
        Small::from_slice(&items)
    }
}

impl<T: Clone, const N: usize> From<Vec<T>> for Small<T, N> {
    fn from(items: Vec<T>) -> Small<T, N> {
        if items.is_empty() || items.len() > N {
            Small::Heap(items)
        } else {
            Small::from_slice(&items)
        }
    }
}

impl<T: Clone + PartialEq, const N: usize> PartialEq for Small<T, N> {
    fn eq(&self, other: &Small<T, N>) -> bool {
        **self == **other
    }
}

impl<T: Clone + Eq, const N: usize> Eq for Small<T, N> {}

impl<T: Clone + fmt::Debug, const N: usize> fmt::Debug for Small<T, N> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_list().entries(self.iter()).finish()
    }
}

#[cfg(test)]
mod tests {
    use super::Small;

    #[test]
    fn short_lists_stay_inline_and_long_ones_spill() {
        let short: Small<u16, 4> = Small::from_slice(&[1, 2, 3]);
        assert!(matches!(short, Small::Inline { len: 3, .. }));
        assert_eq!(&*short, &[1, 2, 3]);
        let long: Small<u16, 2> = [1, 2, 3].into_iter().collect();
        assert!(matches!(long, Small::Heap(_)));
        assert_eq!(&*long, &[1, 2, 3]);
        let mut image = short.clone();
        image[0] = 9;
        assert_eq!(&*image, &[9, 2, 3]);
        assert_eq!(&*Small::<u16, 4>::from_slice(&[]), &[] as &[u16]);
        assert_eq!(*short, *long); // the same items, whichever the storage
        assert_eq!(&*Small::<u16, 2>::filled(5, 3), &[5, 5, 5]);
        assert_eq!(&*Small::<u16, 4>::filled(5, 2), &[5, 5]);
        let keys: Small<u64, 8> = Small::from_slice(&[7, 3, 9]);
        assert_eq!((keys.find(7), keys.find(3), keys.find(9), keys.find(4)), (Some(0), Some(1), Some(2), None));
        let spilled: Small<u64, 2> = Small::from_slice(&[7, 3, 9]);
        assert_eq!((spilled.find(9), spilled.find(4)), (Some(2), None));
        let names: Small<String, 2> = Small::from_slice(&["s1".to_owned()]);
        assert_eq!(&*names, &["s1".to_owned()]);
    }
}
