//! Finding a vector's slot by a device's packed name (`value::pack`): every device access of an
//! implementation does, by name or by address, so it is a small hash table built at load
//! rather than a search of the slots.

use crate::small::Small;

/// How many devices a vector's tables hold inline (the golden set's vectors list 6 to 14); a
/// vector with more keeps them on the heap.
pub(crate) const INLINE_SLOTS: usize = 16;

/// Places in the table: at least twice the slots it indexes, so a probe mostly hits at once and
/// there is always an empty place to end a search.
const PLACES: usize = 2 * INLINE_SLOTS;

/// Each slot's packed name (0 for a name longer than 8 bytes, never looked up), and an
/// open-addressing table of them when the slots fit (else the names are searched in order).
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct SlotKeys {
    keys: Small<u64, INLINE_SLOTS>,
    /// slot + 1 at the place of its key (0: empty); unused beyond `INLINE_SLOTS` slots.
    places: [u8; PLACES],
}

/// The first place to probe for `key` (Fibonacci hashing: the top bits of a multiple).
#[inline]
fn place(key: u64) -> usize {
    (key.wrapping_mul(0x9E37_79B9_7F4A_7C15) >> (64 - PLACES.trailing_zeros())) as usize
}

impl SlotKeys {
    /// The table of `keys` (distinct but for 0s), slot by slot.
    pub(crate) fn new(keys: &[u64]) -> SlotKeys {
        const { assert!(PLACES.is_power_of_two() && INLINE_SLOTS < u8::MAX as usize) };
        let mut places = [0u8; PLACES];
        if keys.len() <= INLINE_SLOTS {
            for (slot, &key) in keys.iter().enumerate().filter(|(_, &k)| k != 0) {
                let mut p = place(key);
                while places[p] != 0 {
                    p = (p + 1) % PLACES;
                }
                places[p] = slot as u8 + 1;
            }
        }
        SlotKeys { keys: Small::from_slice(keys), places }
    }

    /// The slot whose name packs to `key` (not 0).
    // Always inlined: for a constant name (`Memory::set_bit("SM709", ..)` in an emulator's
    // crate) the first place to probe folds at compile time, and the look-up is a few loads
    // rather than a call per device access.
    #[inline(always)]
    pub(crate) fn find(&self, key: u64) -> Option<usize> {
        if self.keys.len() > INLINE_SLOTS {
            return self.keys.find(key);
        }
        let mut p = place(key);
        loop {
            let slot = usize::from(self.places[p]).checked_sub(1)?;
            if self.keys[slot] == key {
                return Some(slot);
            }
            p = (p + 1) % PLACES;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::value::pack;

    #[test]
    fn every_slot_is_found_by_its_name_and_nothing_else() {
        for n in [0, 1, 8, 14, INLINE_SLOTS, INLINE_SLOTS + 5] {
            let names: Vec<String> = (0..n).map(|i| format!("D{}", 100 + i)).collect();
            let mut keys: Vec<u64> = names.iter().map(|s| pack(s)).collect();
            if n > 2 {
                keys[1] = 0; // a name longer than 8 bytes: never found by a key
            }
            let table = SlotKeys::new(&keys);
            for (slot, &key) in keys.iter().enumerate().filter(|(_, &k)| k != 0) {
                assert_eq!(table.find(key), Some(slot), "{n} slots: {}", names[slot]);
            }
            for absent in ["D99", "SM709", "P_EQ", "D1000"] {
                assert_eq!(table.find(pack(absent)), None, "{n} slots: {absent}");
            }
        }
    }
}
