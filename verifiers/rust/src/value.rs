//! Device values and device addresses, as the contract defines them.

use std::fmt;

/// The value of one device: a word is the raw 16 bits (a "16-bit signed binary" -1 is 65535),
/// a bit is on or off. The two never compare equal: a bit reported as the word 1 is wrong.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Value {
    /// A bit device (`true`/`false` in JSON): M10, SM709, P_EQ.
    Bit(bool),
    /// A word device (an integer 0..=65535 in JSON): D100, SD0.
    Word(u16),
}

impl Value {
    /// The word, or `None` for a bit.
    pub fn word(self) -> Option<u16> {
        match self {
            Value::Word(w) => Some(w),
            Value::Bit(_) => None,
        }
    }

    /// The bit, or `None` for a word.
    pub fn bit(self) -> Option<bool> {
        match self {
            Value::Bit(b) => Some(b),
            Value::Word(_) => None,
        }
    }

    /// The value as JSON (`true`, `12`).
    pub fn to_json(self) -> serde_json::Value {
        match self {
            Value::Bit(b) => serde_json::Value::Bool(b),
            Value::Word(w) => serde_json::Value::from(w),
        }
    }

    /// A JSON value read as a device value: `true`/`false`, or an integer 0..=65535.
    pub fn from_json(value: &serde_json::Value) -> Option<Value> {
        match value {
            serde_json::Value::Bool(b) => Some(Value::Bit(*b)),
            serde_json::Value::Number(n) => n.as_u64().and_then(|w| u16::try_from(w).ok()).map(Value::Word),
            _ => None,
        }
    }
}

impl fmt::Display for Value {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Value::Bit(b) => write!(f, "{b}"),
            Value::Word(w) => write!(f, "{w}"),
        }
    }
}

impl From<bool> for Value {
    fn from(b: bool) -> Value {
        Value::Bit(b)
    }
}

impl From<u16> for Value {
    fn from(w: u16) -> Value {
        Value::Word(w)
    }
}

/// Up to 8 bytes of a name packed into an integer, so that names compare as integers on the hot
/// path of every device access; 0 (no key) for a longer name, which is compared as text.
/// Byte by byte, not through a copy of a slice of variable length (a call to `memcpy` and its
/// branches on every device access), and at compile time for a constant name.
#[inline(always)]
pub(crate) const fn pack(name: &str) -> u64 {
    let bytes = name.as_bytes();
    if bytes.is_empty() || bytes.len() > 8 {
        return 0;
    }
    let mut key = 0;
    let mut i = 0;
    while i < bytes.len() {
        key |= (bytes[i] as u64) << (8 * i);
        i += 1;
    }
    key
}

/// A device address split into its device type and number: `D100` is (`D`, 100). Names without
/// a number (Omron's `P_EQ`) have none.
#[derive(Clone, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Address {
    name: Box<str>,
    kind_len: usize,
    number: Option<u32>,
    kind_key: u64,
}

impl Address {
    /// Parse a device name: upper-case letters then decimal digits (`SD8067`), or any other name.
    pub fn parse(name: &str) -> Address {
        let kind_len = name.bytes().take_while(u8::is_ascii_uppercase).count();
        let digits = &name[kind_len..];
        let number = if kind_len > 0 && !digits.is_empty() && digits.bytes().all(|b| b.is_ascii_digit()) {
            digits.parse().ok()
        } else {
            None
        };
        let kind_len = if number.is_some() { kind_len } else { name.len() };
        Address { name: name.into(), kind_len, number, kind_key: pack(&name[..kind_len]) }
    }

    /// The address as written (`D100`).
    #[inline]
    pub fn name(&self) -> &str {
        &self.name
    }

    /// The device type (`D`, `SM`), or the whole name when it has no number.
    pub fn kind(&self) -> &str {
        &self.name[..self.kind_len]
    }

    /// The device number, if the name has one.
    #[inline]
    pub fn number(&self) -> Option<u32> {
        self.number
    }

    /// Whether this is `kind` `number` (no allocation: the hot path of every device read).
    pub fn is(&self, kind: &str, number: u32) -> bool {
        self.number == Some(number) && self.kind() == kind
    }

    /// The device type packed as an integer (0 when it is longer than 8 bytes).
    #[inline]
    pub(crate) fn kind_key(&self) -> u64 {
        self.kind_key
    }

    /// The packed name (`pack`) of the device `offset` further on, spelled as a name is (two on
    /// from `D100` is `D102`, no leading zeros), without building the text; 0 when there is no
    /// such device or its name is longer than 8 bytes.
    #[inline]
    pub(crate) fn key_at(&self, offset: u32) -> u64 {
        let Some(number) = self.number.and_then(|n| n.checked_add(offset)) else { return 0 };
        let digits = number.checked_ilog10().unwrap_or(0) as usize + 1;
        if self.kind_key == 0 || self.kind_len + digits > 8 {
            return 0;
        }
        let (mut key, mut n) = (self.kind_key, number);
        for i in (0..digits).rev() {
            key |= u64::from(b'0' + (n % 10) as u8) << (8 * (self.kind_len + i));
            n /= 10;
        }
        key
    }

    /// Whether `other` is of the same device type (`D100` and `D7999`).
    #[inline]
    pub fn same_kind(&self, other: &Address) -> bool {
        if self.kind_key != 0 && other.kind_key != 0 {
            self.kind_key == other.kind_key
        } else {
            self.kind() == other.kind()
        }
    }
}

impl fmt::Display for Address {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.name)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn addresses_split_into_type_and_number() {
        let a = Address::parse("SD8067");
        assert_eq!((a.kind(), a.number()), ("SD", Some(8067)));
        let p = Address::parse("P_EQ");
        assert_eq!((p.kind(), p.number()), ("P_EQ", None));
        assert!(Address::parse("D100").is("D", 100));
        assert!(!Address::parse("D100").is("SD", 100));
    }

    #[test]
    fn the_key_of_a_later_device_is_its_packed_name() {
        let d = Address::parse("D99");
        assert_eq!(d.key_at(0), pack("D99"));
        assert_eq!(d.key_at(1), pack("D100"));
        assert_eq!(Address::parse("SD8067").key_at(0), pack("SD8067"));
        assert_eq!(Address::parse("SM0").key_at(10), pack("SM10"));
        assert_eq!(Address::parse("D0100").key_at(0), pack("D100")); // as a name is spelled
        assert_eq!(Address::parse("D9999999").key_at(1), 0); // D10000000: 9 bytes
        assert_eq!(Address::parse("D4294967295").key_at(1), 0);
        assert_eq!(Address::parse("P_EQ").key_at(0), 0);
    }

    #[test]
    fn json_values_keep_their_type() {
        assert_eq!(Value::from_json(&serde_json::json!(true)), Some(Value::Bit(true)));
        assert_eq!(Value::from_json(&serde_json::json!(1)), Some(Value::Word(1)));
        assert_ne!(Value::Word(1), Value::Bit(true));
        assert_eq!(Value::from_json(&serde_json::json!(65536)), None);
        assert_eq!(Value::from_json(&serde_json::json!(-1)), None);
        assert_eq!(Value::from_json(&serde_json::json!(1.5)), None);
    }
}
