//! One vector: its initial state, its steps' inputs, and (in a suite) its expectations.
//!
//! A vector's devices are numbered once at load: `devices()` is the slot table (sorted by name, as
//! in the files), and every value list of the crate (the initial image, an expected state, a
//! [`Memory`](crate::Memory)) is aligned with it. Running and judging a vector then needs no
//! string lookups and no allocation beyond the one device image.

use std::collections::BTreeMap;

use serde::Deserialize;

use crate::error::{Error, Result};
use crate::generated::names::{Family, Instruction};
use crate::keys::{SlotKeys, INLINE_SLOTS};
use crate::small::Small;
use crate::value::{pack, Address, Value};

mod build;
mod raw;

pub(crate) use raw::RawVector;

/// How many words of each device operand have their slots found at load (the instructions of
/// the suite read at most three consecutive words of an operand).
const OPERAND_WORDS: usize = 3;
/// In `Vector::operand_slots`: the word is not a listed device (or the operand is a constant).
pub(crate) const NO_SLOT: u8 = u8::MAX;

type Json = serde_json::Value;

/// An operand: a device (the first of its words for a multi-word operand) or a K/H constant.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Operand {
    /// `{"device": "D100"}`: D100, D101, ... in the order the manual gives.
    Device(Address),
    /// `{"constant": 7}`.
    Constant(i64),
}

impl Operand {
    /// The device, if the operand is one.
    #[inline]
    pub fn device(&self) -> Option<&Address> {
        match self {
            Operand::Device(a) => Some(a),
            Operand::Constant(_) => None,
        }
    }
}

/// The current clock a current-time comparison reads (only the fields the family compares).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Clock {
    /// The fields by packed name (`value::pack`; 0 for a name longer than 8 bytes), inline for
    /// the three an FX5 comparison reads.
    keys: Small<(u64, i64), 3>,
    named: Vec<(String, i64)>,
}

impl Clock {
    fn new(named: Vec<(String, i64)>) -> Clock {
        let keys = named.iter().map(|(n, v)| (pack(n), *v)).collect();
        Clock { keys, named }
    }

    /// The field (`hour`, `year`), if the step gives it.
    #[inline]
    pub fn get(&self, field: &str) -> Option<i64> {
        match pack(field) {
            0 => self.named.iter().find(|(name, _)| name == field).map(|&(_, v)| v),
            key => self.keys.iter().find(|&&(k, _)| k == key).map(|&(_, v)| v),
        }
    }

    /// Every field as given, sorted by name.
    pub fn fields(&self) -> impl Iterator<Item = (&str, i64)> {
        self.named.iter().map(|(n, v)| (n.as_str(), *v))
    }
}

/// One execution of the instruction (one scan): what the outside world sets, then the inputs.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Step {
    set: Vec<(usize, Value)>,
    /// The logic state before an AND/OR form (absent for LD forms).
    pub rlo_in: Option<bool>,
    /// The execution condition of TADD/TADDP.
    pub en: Option<bool>,
    /// The HOUR input this scan.
    pub input: Option<bool>,
    /// Milliseconds since the previous execution (HOUR).
    pub elapsed_ms: Option<u64>,
    /// The current clock (current-time comparisons).
    pub clock: Option<Clock>,
}

impl Step {
    /// `(slot, value)` of each device the outside world writes before the execution.
    #[inline]
    pub fn set(&self) -> &[(usize, Value)] {
        &self.set
    }
}

/// What one step must produce: the contact result, and the devices that changed.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct StepExpect {
    pub result: Option<bool>,
    pub devices: Vec<(usize, Value)>,
}

/// One set of expectations: the vector's own, or one of its alternatives.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct Expectation {
    pub choices: Vec<(String, String)>,
    pub steps: Vec<StepExpect>,
    pub final_devices: BTreeMap<String, Value>,
    pub category: String,
    /// Per interpretation whose alternative leaves devices unjudged (an alternative's
    /// `unjudged`, schema 1.1), those devices' slots; empty for the vector's own expectation.
    pub unjudged: Vec<(String, Vec<usize>)>,
}

/// The expectations of a suite vector (a request sent over the protocol has none).
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct Expectations {
    /// The interpretations the outcome depends on.
    pub touched: Vec<String>,
    pub own: Expectation,
    pub alternatives: Vec<Expectation>,
}

/// One test vector.
///
/// The fields every step reads come first, in the order a run reads them, and lie inline: the
/// hot part of a vector is a few adjacent cache lines, and the vectors of a suite follow each
/// other in one array (`#[repr(C)]` keeps that order).
#[derive(Clone, Debug, PartialEq, Eq)]
#[repr(C)]
pub struct Vector {
    known_instruction: Option<Instruction>,
    known_family: Option<Family>,
    /// Whether every numbered device is spelled as `Address::key_at` spells it (`D100`, not
    /// `D0100`); if not, look-ups by address compare the parsed addresses instead.
    keys_spell_addresses: bool,
    /// Inline when there is one step (most vectors).
    steps: Small<Step, 1>,
    initial: Small<Value, INLINE_SLOTS>,
    operand_keys: Small<u64, 4>,
    /// Per operand, the slots of its device's first words (`NO_SLOT` where there is none), found
    /// once at load: an instruction reads its operands without searching the slot keys.
    operand_slots: Small<[u8; OPERAND_WORDS], 4>,
    operands: Small<(String, Operand), 4>,
    /// Each slot's packed name (`value::pack`; 0 when longer than 8 bytes), and a small hash
    /// table of them: every device access of an implementation finds its slot here, by name or
    /// by address (`Address::key_at`).
    name_keys: SlotKeys,
    /// `device_sizes` by packed device type (0 for a type longer than 8 bytes).
    size_keys: Small<(u64, u32), 4>,
    // Read only to report, to serve the protocol, or on a failure.
    id: String,
    family: String,
    instruction: String,
    description: String,
    tags: Vec<String>,
    clauses: Vec<String>,
    device_sizes: Vec<(String, u32)>,
    devices: Vec<Address>,
    scratch: Vec<bool>,
    pub(crate) expectations: Option<Expectations>,
}

// The accessors an emulator calls on every step are `#[inline]`: a function of another crate
// (the emulator's) is otherwise never inlined without LTO, and each would be a call.
impl Vector {
    /// The stable id (`fx5-time-add/TADD/manual-example/program`): the test's name.
    #[inline]
    pub fn id(&self) -> &str {
        &self.id
    }
    /// The family (`fx5-time-add`).
    #[inline]
    pub fn family(&self) -> &str {
        &self.family
    }
    /// The instruction as the spec spells it (`LDTM<=`, `LD <=DT`).
    #[inline]
    pub fn instruction(&self) -> &str {
        &self.instruction
    }
    /// The family as a generated enum (`None` for a family this build does not know, from a
    /// newer copy named by `PLCVEC_VECTORS`).
    #[inline]
    pub fn known_family(&self) -> Option<Family> {
        self.known_family
    }
    /// The instruction as a generated enum (`None` for one this build does not know).
    #[inline]
    pub fn known_instruction(&self) -> Option<Instruction> {
        self.known_instruction
    }
    /// What the vector tests, in a sentence.
    pub fn description(&self) -> &str {
        &self.description
    }
    /// Why the vector exists (`boundary`, `manual-example`).
    pub fn tags(&self) -> &[String] {
        &self.tags
    }
    /// The spec clauses the vector exercises.
    pub fn clauses(&self) -> &[String] {
        &self.clauses
    }
    /// The interpretations the vector's outcome depends on.
    pub fn interpretations(&self) -> &[String] {
        self.expectations.as_ref().map_or(&[], |e| &e.touched)
    }
    /// `assumes.device_sizes`: the number of points of each device type (`D` -> 8000).
    pub fn device_sizes(&self) -> &[(String, u32)] {
        &self.device_sizes
    }
    /// The number of points of one device type, if the vector states it.
    pub fn device_size(&self, kind: &str) -> Option<u32> {
        self.device_sizes.iter().find(|(k, _)| k == kind).map(|&(_, n)| n)
    }

    /// The number of points of `address`'s device type, if the vector states it (no text
    /// compared: the hot path of every range check). Inlined into `Memory::in_range`, which an
    /// emulator's crate inlines: a call per range check otherwise.
    #[inline]
    pub(crate) fn size_of_kind(&self, address: &Address) -> Option<u32> {
        match address.kind_key() {
            0 => self.device_size(address.kind()),
            kind => self.size_keys.iter().find(|&&(k, _)| k == kind).map(|&(_, n)| n),
        }
    }
    /// Every device the vector lists (its slots), sorted by name.
    #[inline]
    pub fn devices(&self) -> &[Address] {
        &self.devices
    }
    /// The initial value of each slot.
    #[inline]
    pub fn initial(&self) -> &[Value] {
        &self.initial
    }
    #[inline]
    pub(crate) fn initial_image(&self) -> &Small<Value, INLINE_SLOTS> {
        &self.initial
    }
    /// Whether each slot is a scratch word (the implementation's own work area, never compared).
    #[inline]
    pub fn scratch(&self) -> &[bool] {
        &self.scratch
    }
    /// The slot of a listed device.
    #[inline(always)]
    pub fn slot(&self, name: &str) -> Option<usize> {
        match pack(name) {
            0 => self.devices.binary_search_by(|a| a.name().cmp(name)).ok(),
            key => self.name_keys.find(key),
        }
    }

    /// The slot of the device `base` + `offset` (D100 + 2 is D102), if the vector lists it.
    #[inline]
    pub fn slot_at(&self, base: &Address, offset: u32) -> Option<usize> {
        match base.key_at(offset) {
            key if key != 0 && self.keys_spell_addresses => self.name_keys.find(key),
            _ => {
                let number = base.number()?.checked_add(offset)?;
                self.devices.iter().position(|a| a.number() == Some(number) && a.same_kind(base))
            }
        }
    }
    /// The operands by name (`s1`, `d`, `S1`, `D2`), sorted.
    pub fn operands(&self) -> &[(String, Operand)] {
        &self.operands
    }
    /// One operand.
    #[inline]
    pub fn operand(&self, name: &str) -> Option<&Operand> {
        self.operand_index(name).map(|i| &self.operands[i].1)
    }

    // Always inlined for the reason of `Memory::set`: the operand's name is a constant (`s1`).
    #[inline(always)]
    fn operand_index(&self, name: &str) -> Option<usize> {
        match pack(name) {
            0 => self.operands.iter().position(|(n, _)| n == name),
            key => self.operand_keys.find(key),
        }
    }

    /// The device of operand `name` and the slots of its first words found at load (`NO_SLOT`
    /// where there is none).
    #[inline(always)]
    pub(crate) fn operand_device(&self, name: &str) -> Option<(&Address, &[u8; OPERAND_WORDS])> {
        let i = self.operand_index(name)?;
        Some((self.operands[i].1.device()?, &self.operand_slots[i]))
    }
    /// The executions, in order.
    #[inline]
    pub fn steps(&self) -> &[Step] {
        &self.steps
    }

    /// A vector as the runner sends it over the protocol (no expectations).
    pub fn from_request(request: &Json) -> Result<Vector> {
        let raw = RawVector::deserialize(request).map_err(|e| Error::new(format!("not a vector request: {e}")))?;
        Vector::from_raw(raw, false)
    }

    /// The request the runner sends for this vector (PROTOCOL.md, run-request).
    pub fn to_request(&self) -> Json {
        let devices: serde_json::Map<String, Json> =
            self.devices.iter().zip(self.initial.iter()).map(|(a, v)| (a.name().to_owned(), v.to_json())).collect();
        let operands: serde_json::Map<String, Json> = self
            .operands
            .iter()
            .map(|(n, o)| {
                let o = match o {
                    Operand::Device(a) => serde_json::json!({ "device": a.name() }),
                    Operand::Constant(c) => serde_json::json!({ "constant": c }),
                };
                (n.clone(), o)
            })
            .collect();
        let mut initial = serde_json::json!({ "devices": devices, "operands": operands });
        let scratch: Vec<&str> =
            self.devices.iter().zip(&self.scratch).filter(|(_, &s)| s).map(|(a, _)| a.name()).collect();
        if !scratch.is_empty() {
            initial["scratch"] = serde_json::json!(scratch);
        }
        let steps: Vec<Json> = self
            .steps
            .iter()
            .map(|s| {
                let mut m = serde_json::Map::new();
                if !s.set.is_empty() {
                    let set: serde_json::Map<String, Json> =
                        s.set.iter().map(|&(i, v)| (self.devices[i].name().to_owned(), v.to_json())).collect();
                    m.insert("set".into(), set.into());
                }
                for (key, v) in [("rlo_in", s.rlo_in), ("en", s.en), ("input", s.input)] {
                    if let Some(b) = v {
                        m.insert(key.into(), b.into());
                    }
                }
                if let Some(ms) = s.elapsed_ms {
                    m.insert("elapsed_ms".into(), ms.into());
                }
                if let Some(c) = &s.clock {
                    let c: serde_json::Map<String, Json> = c.fields().map(|(n, v)| (n.to_owned(), v.into())).collect();
                    m.insert("clock".into(), c.into());
                }
                Json::Object(m)
            })
            .collect();
        let sizes: serde_json::Map<String, Json> =
            self.device_sizes.iter().map(|(k, n)| (k.clone(), (*n).into())).collect();
        serde_json::json!({
            "id": self.id, "family": self.family, "instruction": self.instruction,
            "assumes": { "device_sizes": sizes }, "initial": initial, "steps": steps,
        })
    }
}
