//! JSON objects that hold no key twice (CONTRACT.md, "Loading"): parsers disagree on which of two
//! values wins, so a file with a repeated key is refused, whatever the key.
//!
//! The check is part of the one parse of each file: the structs the files are read into refuse a
//! repeated field themselves (serde's derive does), the maps keyed by names are read as
//! [`Unique`], and the parts the runner does not keep as [`NoRepeats`]. Nothing is parsed twice.

use std::collections::BTreeMap;
use std::fmt;
use std::marker::PhantomData;
use std::ops::Deref;

use serde::de::{Deserialize, Deserializer, MapAccess, SeqAccess, Visitor};

/// The message of a repeated key, as every runner words it.
pub(crate) fn repeated(key: &str) -> String {
    format!("repeated key {}", serde_json::Value::from(key))
}

/// serde's own message for a struct field given twice, reworded as [`repeated`]; any other
/// message as it is. The position serde_json adds (`at line 1 column 9`) is left out.
pub(crate) fn message(e: &serde_json::Error) -> String {
    let text = e.to_string();
    let text = text.strip_suffix(&format!(" at line {} column {}", e.line(), e.column())).unwrap_or(&text).to_owned();
    match text.strip_prefix("duplicate field `").and_then(|rest| rest.strip_suffix('`')) {
        Some(field) => repeated(field),
        None => text,
    }
}

/// Whether an error is a repeated key (to be worded by file, line and vector id).
pub(crate) fn is_repeated(e: &serde_json::Error) -> bool {
    message(e).starts_with("repeated key ")
}

/// A map of names read from a JSON object that holds no key twice.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct Unique<V>(pub BTreeMap<String, V>);

impl<V> Default for Unique<V> {
    fn default() -> Self {
        Unique(BTreeMap::new())
    }
}

impl<V> Deref for Unique<V> {
    type Target = BTreeMap<String, V>;
    fn deref(&self) -> &BTreeMap<String, V> {
        &self.0
    }
}

impl<'a, V> IntoIterator for &'a Unique<V> {
    type Item = (&'a String, &'a V);
    type IntoIter = std::collections::btree_map::Iter<'a, String, V>;
    fn into_iter(self) -> Self::IntoIter {
        self.0.iter()
    }
}

impl<V> IntoIterator for Unique<V> {
    type Item = (String, V);
    type IntoIter = std::collections::btree_map::IntoIter<String, V>;
    fn into_iter(self) -> Self::IntoIter {
        self.0.into_iter()
    }
}

impl<'de, V: Deserialize<'de>> Deserialize<'de> for Unique<V> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct Keys<V>(PhantomData<V>);
        impl<'de, V: Deserialize<'de>> Visitor<'de> for Keys<V> {
            type Value = Unique<V>;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str("an object")
            }
            fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Unique<V>, A::Error> {
                let mut out = BTreeMap::new();
                while let Some(key) = map.next_key::<String>()? {
                    if out.contains_key(&key) {
                        return Err(serde::de::Error::custom(repeated(&key)));
                    }
                    let value = map.next_value()?;
                    out.insert(key, value);
                }
                Ok(Unique(out))
            }
        }
        d.deserialize_map(Keys(PhantomData))
    }
}

/// Any JSON value, not kept, refused if some object in it holds a key twice (serde's
/// `IgnoredAny` with that one check).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) struct NoRepeats;

impl<'de> Deserialize<'de> for NoRepeats {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        d.deserialize_any(NoRepeats)
    }
}

impl<'de> Visitor<'de> for NoRepeats {
    type Value = NoRepeats;
    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("any JSON value")
    }
    fn visit_bool<E>(self, _: bool) -> Result<NoRepeats, E> {
        Ok(NoRepeats)
    }
    fn visit_i64<E>(self, _: i64) -> Result<NoRepeats, E> {
        Ok(NoRepeats)
    }
    fn visit_u64<E>(self, _: u64) -> Result<NoRepeats, E> {
        Ok(NoRepeats)
    }
    fn visit_f64<E>(self, _: f64) -> Result<NoRepeats, E> {
        Ok(NoRepeats)
    }
    fn visit_str<E>(self, _: &str) -> Result<NoRepeats, E> {
        Ok(NoRepeats)
    }
    fn visit_unit<E>(self) -> Result<NoRepeats, E> {
        Ok(NoRepeats)
    }
    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<NoRepeats, A::Error> {
        while seq.next_element::<NoRepeats>()?.is_some() {}
        Ok(NoRepeats)
    }
    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<NoRepeats, A::Error> {
        let mut keys: Vec<String> = Vec::new();
        while let Some(key) = map.next_key::<String>()? {
            if keys.contains(&key) {
                return Err(serde::de::Error::custom(repeated(&key)));
            }
            map.next_value::<NoRepeats>()?;
            keys.push(key);
        }
        Ok(NoRepeats)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[derive(serde::Deserialize, Debug)]
    #[serde(deny_unknown_fields)]
    struct Shape {
        #[allow(dead_code)]
        devices: Unique<u16>,
        #[serde(default)]
        #[allow(dead_code)]
        rest: Option<NoRepeats>,
    }

    fn refused(text: &str) -> String {
        message(&serde_json::from_str::<Shape>(text).unwrap_err())
    }

    #[test]
    fn a_key_twice_is_refused_wherever_it_is() {
        assert_eq!(refused(r#"{"devices": {"D1": 1, "D1": 2}}"#), r#"repeated key "D1""#);
        assert_eq!(refused(r#"{"devices": {}, "devices": {}}"#), r#"repeated key "devices""#);
        assert_eq!(refused(r#"{"devices": {}, "rest": [{"a": 1}, {"b": {"c": 1, "c": 1}}]}"#), r#"repeated key "c""#);
        let ok: Shape = serde_json::from_str(r#"{"devices": {"D1": 1, "D2": 2}, "rest": [{"a": {"a": 1}}]}"#).unwrap();
        assert_eq!(ok.devices.len(), 2);
        assert!(!is_repeated(&serde_json::from_str::<Shape>(r#"{"devices": 1}"#).unwrap_err()));
    }
}
