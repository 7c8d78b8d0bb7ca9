//! A device image for one vector: the "execute on my memory" side of the crate.
//!
//! An emulator that only wants to implement "execute this instruction" gets the vector's devices
//! as a [`Memory`], reads and writes words and bits by address, and leaves the stepping, the
//! reporting and the comparison to [`OnMemory`](crate::OnMemory). A write to a device the vector
//! does not list is kept apart, so the runner can report it (the contract forbids it).

use crate::keys::INLINE_SLOTS;
use crate::small::Small;
use crate::value::{Address, Value};
use crate::vector::{Step, Vector, NO_SLOT};

/// The devices of one vector, slot-aligned with [`Vector::devices`], plus any device written
/// outside the vector. The image of a vector of the usual size lives inline (building one
/// allocates nothing).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Memory<'v> {
    vector: &'v Vector,
    values: Small<Value, INLINE_SLOTS>,
    outside: Vec<(String, Value)>,
}

impl<'v> Memory<'v> {
    /// The vector's initial devices.
    #[inline]
    pub fn new(vector: &'v Vector) -> Memory<'v> {
        // A copy of the whole inline table: a fixed size, no loop over the slots.
        Memory { vector, values: vector.initial_image().clone(), outside: Vec::new() }
    }

    /// The vector this image belongs to.
    #[inline]
    pub fn vector(&self) -> &'v Vector {
        self.vector
    }

    /// Every listed device's value, slot by slot.
    #[inline]
    pub fn values(&self) -> &[Value] {
        &self.values
    }

    /// Devices written that the vector does not list (empty for a conforming implementation).
    #[inline]
    pub fn outside(&self) -> &[(String, Value)] {
        &self.outside
    }

    /// Every device of the image by name: the listed ones in the vector's order, then those
    /// written outside it. What [`Steps::devices`](crate::Steps::devices) takes as a step's report.
    pub fn image(&self) -> impl Iterator<Item = (&str, Value)> {
        let listed = self.vector.devices().iter().zip(self.values()).map(|(a, v)| (a.name(), *v));
        listed.chain(self.outside.iter().map(|(name, v)| (name.as_str(), *v)))
    }

    /// Apply a step's `set` (values written by the outside world before the execution).
    #[inline]
    pub fn apply_set(&mut self, step: &Step) {
        for &(slot, v) in step.set() {
            self.values[slot] = v;
        }
    }

    /// The device `base` + `offset` (D100 + 2 is D102), if it holds a value. A device without a
    /// number is found by name at offset 0.
    #[inline]
    pub fn get_at(&self, base: &Address, offset: u32) -> Option<Value> {
        match base.number() {
            Some(n) => match self.vector.slot_at(base, offset) {
                Some(i) => Some(self.values[i]),
                None if self.outside.is_empty() => None,
                None => self.outside_get(&format!("{}{}", base.kind(), n.checked_add(offset)?)),
            },
            None if offset == 0 => self.get(base.name()),
            None => None,
        }
    }

    /// A device by name, if it holds a value.
    #[inline]
    pub fn get(&self, name: &str) -> Option<Value> {
        match self.vector.slot(name) {
            Some(i) => Some(self.values[i]),
            None if self.outside.is_empty() => None,
            None => self.outside_get(name),
        }
    }

    fn outside_get(&self, name: &str) -> Option<Value> {
        self.outside.iter().find(|(n, _)| n == name).map(|&(_, v)| v)
    }

    /// Write a device by name.
    // Always inlined, into the emulator's crate too: an emulator names a flag as a constant
    // (`SM709`), whose key (`pack`) then folds at compile time, and the write is a slot look-up.
    #[inline(always)]
    pub fn set(&mut self, name: &str, value: Value) {
        match self.vector.slot(name) {
            Some(i) => self.values[i] = value,
            None => self.set_outside(name.to_owned(), value),
        }
    }

    fn set_outside(&mut self, name: String, value: Value) {
        match self.outside.iter_mut().find(|(n, _)| *n == name) {
            Some(entry) => entry.1 = value,
            None => self.outside.push((name, value)),
        }
    }

    /// Write the device `base` + `offset`.
    #[inline]
    pub fn set_at(&mut self, base: &Address, offset: u32, value: Value) {
        match base.number() {
            Some(n) => match self.vector.slot_at(base, offset) {
                Some(i) => self.values[i] = value,
                None => self.set_outside(format!("{}{}", base.kind(), n.saturating_add(offset)), value),
            },
            None => self.set(base.name(), value),
        }
    }

    /// The word at `base` + `offset`. A device the vector does not list reads as 0 (the contract
    /// leaves it to the implementation); a bit reads as 0 or 1.
    #[inline]
    pub fn word(&self, base: &Address, offset: u32) -> u16 {
        self.get_at(base, offset).map_or(0, word_of)
    }

    /// The word `offset` words into the device operand `operand` (`s1` and 1 for (s1)+1), as
    /// [`Memory::word`] reads it; `None` when the vector has no device operand of that name.
    // Always inlined, into the emulator's crate too, for the reason of `Memory::set`: the
    // operand's name is a constant there (`s1`), whose key then folds at compile time.
    #[inline(always)]
    pub fn operand_word(&self, operand: &str, offset: u32) -> Option<u16> {
        let (base, slots) = self.vector.operand_device(operand)?;
        Some(self.word_with(base, slots, offset as usize))
    }

    /// The first `N` words of the device operand `operand` ((s1), (s1)+1, ...), as
    /// [`Memory::word`] reads them; `None` when the vector has no device operand of that name.
    /// The slots of an operand's first words are found when the vector is loaded, so this is
    /// the quick way to read an instruction's operands.
    // Always inlined, as `Memory::operand_word`.
    #[inline(always)]
    pub fn operand_words<const N: usize>(&self, operand: &str) -> Option<[u16; N]> {
        let (base, slots) = self.vector.operand_device(operand)?;
        // A plain loop, not `array::from_fn`: its closure, instantiated in the emulator's crate,
        // was left as a call per word there.
        let mut words = [0; N];
        for (k, word) in words.iter_mut().enumerate() {
            *word = self.word_with(base, slots, k);
        }
        Some(words)
    }

    #[inline]
    fn word_with(&self, base: &Address, slots: &[u8], offset: usize) -> u16 {
        match slots.get(offset) {
            Some(&slot) if slot != NO_SLOT => word_of(self.values[usize::from(slot)]),
            _ => self.word_by_address(base, offset),
        }
    }

    /// [`Memory::word`] for a word whose slot was not found at load: kept out of line, so that
    /// the slot read above stays small enough to be inlined into the emulator's crate.
    #[cold]
    #[inline(never)]
    fn word_by_address(&self, base: &Address, offset: usize) -> u16 {
        self.word(base, offset as u32)
    }

    /// Write the word at `base` + `offset`.
    #[inline]
    pub fn set_word(&mut self, base: &Address, offset: u32, word: u16) {
        self.set_at(base, offset, Value::Word(word));
    }

    /// The bit `name` (an unlisted bit reads as off; a word as "not zero").
    #[inline]
    pub fn bit(&self, name: &str) -> bool {
        match self.get(name) {
            Some(Value::Bit(b)) => b,
            Some(Value::Word(w)) => w != 0,
            None => false,
        }
    }

    /// Write the bit `name`.
    #[inline(always)]
    pub fn set_bit(&mut self, name: &str, on: bool) {
        self.set(name, Value::Bit(on));
    }

    /// Whether `base` .. `base + words - 1` all exist, by the vector's `assumes.device_sizes`.
    /// A device type whose size the vector does not state is taken to exist.
    #[inline]
    pub fn in_range(&self, base: &Address, words: u32) -> bool {
        match (base.number(), self.vector.size_of_kind(base)) {
            (Some(n), Some(size)) => u64::from(n) + u64::from(words) <= u64::from(size),
            _ => true,
        }
    }
}

/// A device's value read as a word (a bit as 0 or 1).
#[inline]
fn word_of(value: Value) -> u16 {
    match value {
        Value::Word(w) => w,
        Value::Bit(b) => u16::from(b),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn vector() -> Vector {
        Vector::from_request(&serde_json::json!({
            "id": "t", "family": "f", "instruction": "I",
            "assumes": {"device_sizes": {"D": 8000}},
            "initial": {"devices": {"D7998": 1, "D7999": 2, "M10": false}, "operands": {}},
            "steps": [{}],
        }))
        .unwrap()
    }

    #[test]
    fn offsets_reach_listed_and_unlisted_devices() {
        let v = vector();
        let mut m = Memory::new(&v);
        let base = Address::parse("D7998");
        assert_eq!((m.word(&base, 0), m.word(&base, 1), m.word(&base, 2)), (1, 2, 0));
        m.set_word(&base, 2, 7);
        assert_eq!(m.outside(), &[("D8000".to_owned(), Value::Word(7))]);
        assert!(m.in_range(&base, 2));
        assert!(!m.in_range(&base, 3));
        m.set_bit("M10", true);
        assert!(m.bit("M10"));
        assert_eq!(m.values()[2], Value::Bit(true));
    }

    #[test]
    fn operands_read_their_words_found_at_load() {
        let v = Vector::from_request(&serde_json::json!({
            "id": "t", "family": "f", "instruction": "I",
            "initial": {"devices": {"D100": 1, "D101": 2, "D99": 9}, "operands": {"s1": {"device": "D100"}, "s2": {"device": "D98"}, "s3": {"constant": 7}}},
            "steps": [{}],
        }))
        .unwrap();
        let mut m = Memory::new(&v);
        let s1: Vec<u16> = (0..4).map(|k| m.operand_word("s1", k).unwrap()).collect();
        assert_eq!(s1, [1, 2, 0, 0]); // D102, D103: not listed, read as 0
        assert_eq!(
            (m.operand_word("s2", 0), m.operand_word("s2", 1), m.operand_word("s2", 2)),
            (Some(0), Some(9), Some(1))
        );
        assert_eq!((m.operand_word("s3", 0), m.operand_word("nope", 0)), (None, None));
        assert_eq!((m.operand_words::<4>("s1"), m.operand_words::<2>("s3")), (Some([1, 2, 0, 0]), None));
        m.set_word(&Address::parse("D100"), 2, 5); // outside the vector
        m.set_word(&Address::parse("D100"), 1, 6);
        assert_eq!((m.operand_word("s1", 2), m.operand_word("s1", 1)), (Some(5), Some(6)));
    }

    #[test]
    fn a_device_spelt_with_leading_zeros_is_found_by_address() {
        let v = Vector::from_request(&serde_json::json!({
            "id": "t", "family": "f", "instruction": "I",
            "initial": {"devices": {"D0100": 5, "D101": 6}, "operands": {}},
            "steps": [{}],
        }))
        .unwrap();
        let mut m = Memory::new(&v);
        let base = Address::parse("D99");
        assert_eq!((m.word(&base, 1), m.word(&base, 2)), (5, 6));
        m.set_word(&base, 1, 7);
        assert_eq!(m.get("D0100"), Some(Value::Word(7)));
        assert!(m.outside().is_empty());
    }
}
