//! Choosing which vectors to run: by family, instruction, tag, id glob, interpretation and shard.
//!
//! Each filter is OR within itself and the filters are AND together, as in the Python runner.
//! Shards use the CRC-32 of the id, `crc32(id) % N + 1`, so a vector lands in the same shard in
//! every language, and adding vectors moves no other vector to another shard.

use crate::error::{Error, Result};
use crate::vector::Vector;

/// A selection of vectors. The empty selection selects everything.
#[derive(Clone, Debug, Default)]
pub struct Selection {
    families: Vec<String>,
    instructions: Vec<String>,
    tags: Vec<String>,
    ids: Vec<glob::Pattern>,
    interpretations: Vec<String>,
    shard: Option<(u32, u32)>,
}

impl Selection {
    /// Everything.
    pub fn all() -> Selection {
        Selection::default()
    }
    /// Also select this family (`fx5-time-add`).
    pub fn family(mut self, family: impl Into<String>) -> Selection {
        self.families.push(family.into());
        self
    }
    /// Also select this instruction (`TADDP`, `LD <=DT`).
    pub fn instruction(mut self, instruction: impl Into<String>) -> Selection {
        self.instructions.push(instruction.into());
        self
    }
    /// Also select vectors with this tag (`boundary`).
    pub fn tag(mut self, tag: impl Into<String>) -> Selection {
        self.tags.push(tag.into());
        self
    }
    /// Also select ids matching this glob (`*`, `?`, `[...]`, like Python's fnmatch).
    pub fn id_glob(mut self, pattern: &str) -> Result<Selection> {
        let p = glob::Pattern::new(pattern).map_err(|e| Error::new(format!("id pattern {pattern:?}: {e}")))?;
        self.ids.push(p);
        Ok(self)
    }
    /// Also select vectors whose outcome depends on this interpretation.
    pub fn interpretation(mut self, id: impl Into<String>) -> Selection {
        self.interpretations.push(id.into());
        self
    }
    /// Only shard `k` of `n` (1 <= k <= n).
    pub fn shard(mut self, k: u32, n: u32) -> Result<Selection> {
        if n == 0 || k == 0 || k > n {
            return Err(Error::new(format!("shard {k}/{n}: K must be between 1 and N")));
        }
        self.shard = Some((k, n));
        Ok(self)
    }
    /// Parse `K/N` (`2/4`) as a shard.
    pub fn shard_text(self, text: &str) -> Result<Selection> {
        let parsed = text.split_once('/').and_then(|(k, n)| Some((k.trim().parse().ok()?, n.trim().parse().ok()?)));
        match parsed {
            Some((k, n)) => self.shard(k, n),
            None => Err(Error::new(format!("shard takes K/N (e.g. 2/4), got {text:?}"))),
        }
    }

    /// Whether no filter is set.
    pub fn is_all(&self) -> bool {
        self.families.is_empty()
            && self.instructions.is_empty()
            && self.tags.is_empty()
            && self.ids.is_empty()
            && self.interpretations.is_empty()
            && self.shard.is_none()
    }

    /// Whether the selection keeps `v`.
    pub fn matches(&self, v: &Vector) -> bool {
        (self.families.is_empty() || self.families.iter().any(|f| f == v.family()))
            && (self.instructions.is_empty() || self.instructions.iter().any(|i| i == v.instruction()))
            && (self.tags.is_empty() || v.tags().iter().any(|t| self.tags.contains(t)))
            && (self.ids.is_empty() || self.ids.iter().any(|p| p.matches(v.id())))
            && (self.interpretations.is_empty() || v.interpretations().iter().any(|i| self.interpretations.contains(i)))
            && self.shard.is_none_or(|(k, n)| shard_of(v.id(), n) == k)
    }

    /// The vectors the selection keeps, in order.
    pub fn apply<'a>(&self, vectors: &'a [Vector]) -> Vec<&'a Vector> {
        vectors.iter().filter(|v| self.matches(v)).collect()
    }

    /// The vectors of `suite` the selection keeps, refusing a selection that names a family,
    /// instruction, tag or interpretation the suite lacks, or that keeps nothing: a gate never
    /// passes by accident.
    pub fn select<'s>(&self, suite: &'s crate::Suite) -> Result<Vec<&'s Vector>> {
        let unknown = self.unknown_names(suite);
        if !unknown.is_empty() {
            return Err(Error::new(format!(
                "the selection names what the suite does not have: {}",
                unknown.join(", ")
            )));
        }
        let vectors = self.apply(suite.vectors());
        if vectors.is_empty() {
            return Err(Error::new(format!(
                "the selection keeps none of the {} vectors of {}",
                suite.vectors().len(),
                suite.source()
            )));
        }
        Ok(vectors)
    }

    /// Names in the selection that the suite does not have (a misspelt family selects nothing,
    /// which must not read as a passing run), each with the names the suite has.
    pub fn unknown_names(&self, suite: &crate::Suite) -> Vec<String> {
        let mut out = Vec::new();
        for (kind, given) in [
            (Kind::Family, &self.families),
            (Kind::Instruction, &self.instructions),
            (Kind::Tag, &self.tags),
            (Kind::Interpretation, &self.interpretations),
        ] {
            let known = known_names(suite, kind);
            for name in given.iter().filter(|n| !known.contains(n)) {
                out.push(format!("{} {name:?} (known: {})", kind.as_str(), known.join(", ")));
            }
        }
        out
    }
}

/// What a selection names.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// A family (`fx5-time-add`).
    Family,
    /// An instruction (`TADDP`).
    Instruction,
    /// A tag (`boundary`).
    Tag,
    /// An interpretation (`TADD-FLAGS-OFF`).
    Interpretation,
}

impl Kind {
    /// The word (`family`).
    pub fn as_str(self) -> &'static str {
        match self {
            Kind::Family => "family",
            Kind::Instruction => "instruction",
            Kind::Tag => "tag",
            Kind::Interpretation => "interpretation",
        }
    }
}

/// Every name of `kind` the suite has, sorted: what an error about an unknown name lists.
pub fn known_names(suite: &crate::Suite, kind: Kind) -> Vec<String> {
    let mut names: Vec<String> = suite
        .families()
        .iter()
        .flat_map(|f| -> Vec<String> {
            match kind {
                Kind::Family => vec![f.family.clone()],
                Kind::Instruction => f.instructions.clone(),
                Kind::Tag => f.tags.keys().cloned().collect(),
                Kind::Interpretation => f.interpretations.iter().map(|i| i.id.clone()).collect(),
            }
        })
        .collect();
    names.sort();
    names.dedup();
    names
}

/// The shard (1..=n) a vector id belongs to: `crc32(id) % n + 1`, the Python runner's rule.
pub fn shard_of(id: &str, n: u32) -> u32 {
    crc32fast::hash(id.as_bytes()) % n + 1
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shard_is_the_crc32_of_the_id() {
        // zlib.crc32(b"123456789") is 0xCBF43926, the CRC-32 check value.
        assert_eq!(crc32fast::hash(b"123456789"), 0xCBF4_3926);
        assert_eq!(shard_of("123456789", 7), 0xCBF4_3926 % 7 + 1);
    }

    #[test]
    fn bad_shards_are_refused() {
        assert!(Selection::all().shard_text("0/4").is_err());
        assert!(Selection::all().shard_text("5/4").is_err());
        assert!(Selection::all().shard_text("two").is_err());
        assert!(Selection::all().shard_text("2/4").is_ok());
    }
}
