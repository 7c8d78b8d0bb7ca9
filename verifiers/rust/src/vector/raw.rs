//! The vector file's shapes (vectors/schema/vector-file.schema.json), as serde reads them.

use serde::Deserialize;

use crate::unique::{NoRepeats, Unique};

type Json = serde_json::Value;

// The file shapes (vectors/schema/vector-file.schema.json). Every key must be one the schema
// defines (CONTRACT.md, "Loading"): an unknown key means a damaged or hand-edited file, or one
// of a schema this crate does not read, and is refused rather than silently dropped. Keys the
// runner does not use are read as `NoRepeats` (checked for presence and for repeated keys, not
// kept); a key given twice anywhere is refused (`unique`).

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawVector {
    pub id: String,
    pub family: String,
    pub instruction: String,
    #[serde(default, rename = "st")]
    pub(crate) _st: Option<NoRepeats>,
    #[serde(default, rename = "printed")]
    pub(crate) _printed: Option<NoRepeats>,
    #[serde(default)]
    pub(crate) description: String,
    #[serde(default)]
    pub(crate) tags: Vec<String>,
    #[serde(default)]
    pub(crate) clauses: Vec<String>,
    #[serde(default)]
    pub(crate) assumes: RawAssumes,
    pub(crate) initial: RawInitial,
    pub(crate) steps: Vec<RawStep>,
    #[serde(rename = "final")]
    pub(crate) final_: Option<RawFinal>,
    pub(crate) outcome: Option<RawOutcome>,
    #[serde(default)]
    pub(crate) alternatives: Vec<RawAlternative>,
}

#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawAssumes {
    #[serde(default)]
    pub(crate) device_sizes: Unique<u64>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawInitial {
    pub(crate) devices: Unique<Json>,
    pub(crate) operands: Unique<RawOperand>,
    #[serde(default)]
    pub(crate) scratch: Vec<String>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawOperand {
    pub(crate) device: Option<String>,
    pub(crate) constant: Option<i64>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawStep {
    #[serde(default)]
    pub(crate) set: Unique<Json>,
    pub(crate) rlo_in: Option<bool>,
    pub(crate) en: Option<bool>,
    pub(crate) input: Option<bool>,
    pub(crate) elapsed_ms: Option<u64>,
    pub(crate) clock: Option<Unique<i64>>,
    pub(crate) expect: Option<RawExpect>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawExpect {
    pub(crate) result: Option<bool>,
    #[serde(default)]
    pub(crate) devices: Unique<Json>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawFinal {
    pub(crate) devices: Unique<Json>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawCategory {
    pub(crate) category: String,
    #[serde(default, rename = "errors")]
    pub(crate) _errors: Option<NoRepeats>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawOutcome {
    pub(crate) category: String,
    #[serde(default)]
    pub(crate) interpretations: Vec<String>,
    pub(crate) default: Option<RawCategory>,
    #[serde(default, rename = "errors")]
    pub(crate) _errors: Option<NoRepeats>,
    #[serde(default, rename = "reason")]
    pub(crate) _reason: Option<NoRepeats>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawAlternative {
    pub(crate) choices: Unique<String>,
    /// interpretation id -> the devices its alternative leaves unjudged (schema 1.1): read as
    /// JSON, so that a malformed map is refused by the vector's id and the path.
    #[serde(default)]
    pub(crate) unjudged: Option<Unique<Json>>,
    pub(crate) expect: Vec<RawExpect>,
    #[serde(rename = "final")]
    pub(crate) final_: RawFinal,
    pub(crate) outcome: RawCategory,
}
