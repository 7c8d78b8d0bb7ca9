//! Mitsubishi MELSEC iQ-F FX5: LDTM□/ANDTM□/ORTM□ (time) and LDDT□/ANDDT□/ORDT□ (date).
//!
//! Written from the manual pages fx5-time-compare-LDTM.txt and fx5-date-compare-LDDT.txt. The
//! two pages are the same text with hour/minute/second replaced by year/month/day, so one
//! machine serves both.

use std::cmp::Ordering;

use plcvec::names::{
    Condition, Form, Fx5AndOrWhenOff, Fx5ClockS2DeviceRange, Fx5InvalidS3DeviceRange, Fx5OrOnError, Fx5Sm709Scope,
};
use plcvec::{Choices, Memory, Refusal, Step, Vector};

use super::{device, holds, read3, rlo_in, signed, word_operand, Mutant};

const SM709: &str = "SM709";

/// Time or date comparison.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Kind {
    Time,
    Date,
}

/// One field of the three words, most significant first.
struct Field {
    offset: usize,
    name: &'static str,
    min: i64,
    max: i64,
    /// The (s3) bit that selects it.
    bit: u16,
}

// Time: 'Set the "hour" data ... within the range 0 to 23.' '"minute" ... (s1)+1 ... 0 to 59.'
// '"second" ... (s1)+2 ... 0 to 59.' '(1) Set "second" as comparison target. (2) ... "minute"
// ... (3) ... "hour"'
const TIME_FIELDS: [Field; 3] = [
    Field { offset: 0, name: "hour", min: 0, max: 23, bit: 2 },
    Field { offset: 1, name: "minute", min: 0, max: 59, bit: 1 },
    Field { offset: 2, name: "second", min: 0, max: 59, bit: 0 },
];
// Date: 'Set the 4 digit "year" data ... within the range 1980 to 2079.' '"month" ... 1 to 12.'
// '"date" data in ... (s1)+2 ... 1 to 31.'
const DATE_FIELDS: [Field; 3] = [
    Field { offset: 0, name: "year", min: 1980, max: 2079, bit: 2 },
    Field { offset: 1, name: "month", min: 1, max: 12, bit: 1 },
    Field { offset: 2, name: "day", min: 1, max: 31, bit: 0 },
];

#[derive(Clone, Debug)]
pub(super) struct Fx5Compare {
    scope: Fx5Sm709Scope,
    logic: Fx5AndOrWhenOff,
    clock_s2: Fx5ClockS2DeviceRange,
    or_on_error: Fx5OrOnError,
    invalid_s3: Fx5InvalidS3DeviceRange,
    mutant: Option<Mutant>,
}

/// The contact's verdict before the AND/OR logic: the comparison, or an error (SM709).
enum Contact {
    Compared(bool),
    Error,
}

impl Fx5Compare {
    pub(super) fn new(choices: &Choices, mutant: Option<Mutant>) -> Fx5Compare {
        let logic = choices.get::<Fx5AndOrWhenOff>();
        Fx5Compare {
            scope: choices.get(),
            logic,
            clock_s2: choices.get(),
            or_on_error: choices.get(),
            invalid_s3: choices.get(),
            mutant,
        }
    }

    fn bug(&self, m: Mutant) -> bool {
        self.mutant == Some(m)
    }

    /// One scan of one LD/AND/OR contact; returns the logic state after it.
    pub(super) fn execute(
        &self,
        kind: Kind,
        form: Form,
        condition: Condition,
        vector: &Vector,
        step: &Step,
        mem: &mut Memory<'_>,
    ) -> Result<bool, Refusal> {
        let logic = self.logic;
        // "(Devices are used as a normally open contact.)" The MELSEC iQ-R Programming Manual
        // (CPU Module Instructions), processing-time tables: "an AND/OR comparison is not
        // executed while the preceding logic is off".
        match form {
            Form::Ld => self.contact(kind, condition, vector, step, mem),
            Form::And => {
                let rlo = rlo_in(step)?;
                if !rlo && self.bug(Mutant::Fx5AndAsLdWhenOff) {
                    return self.contact(kind, condition, vector, step, mem);
                }
                if !rlo && matches!(logic, Fx5AndOrWhenOff::AndSkipped | Fx5AndOrWhenOff::ShortCircuit) {
                    return Ok(false);
                }
                let contact = self.contact(kind, condition, vector, step, mem)?; // executed: may set SM709
                Ok(rlo && contact)
            }
            Form::Or => {
                let rlo = rlo_in(step)?;
                if rlo && logic == Fx5AndOrWhenOff::ShortCircuit {
                    return Ok(true);
                }
                let (contact, failed) = self.contact_checked(kind, condition, vector, step, mem)?;
                // "SM709 turns on ... and the operation result will be non-continuity": a
                // non-conductive contact in parallel (contact-off), or the rung's result itself
                // off (FX5-OR-ON-ERROR=result-off).
                if failed && self.or_on_error == Fx5OrOnError::ResultOff {
                    return Ok(false);
                }
                Ok(rlo || contact)
            }
        }
    }

    fn contact(
        &self,
        kind: Kind,
        condition: Condition,
        vector: &Vector,
        step: &Step,
        mem: &mut Memory<'_>,
    ) -> Result<bool, Refusal> {
        Ok(self.contact_checked(kind, condition, vector, step, mem)?.0)
    }

    /// The contact, and whether the execution found invalid data (turned SM709 on).
    fn contact_checked(
        &self,
        kind: Kind,
        condition: Condition,
        vector: &Vector,
        step: &Step,
        mem: &mut Memory<'_>,
    ) -> Result<(bool, bool), Refusal> {
        match self.evaluate(kind, condition, vector, step, mem)? {
            Contact::Compared(result) => {
                if self.bug(Mutant::Fx5Sm709NotLatched) {
                    mem.set_bit(SM709, false);
                }
                Ok((result, false))
            }
            // "SM709 turns on after the instruction is executed and the operation result will
            // be non-continuity." "Once SM709 turns on, the on state is held until the CPU
            // module is powered off or reset." -> only ever set here, never cleared.
            Contact::Error => {
                mem.set_bit(SM709, true);
                Ok((false, true))
            }
        }
    }

    // Over 80 lines, kept whole: the checks of one comparison in the order the page makes them
    // ((s3)'s reserved bits, the device range, the data, then the fields), each beside its quote.
    fn evaluate(
        &self,
        kind: Kind,
        condition: Condition,
        vector: &Vector,
        step: &Step,
        mem: &Memory<'_>,
    ) -> Result<Contact, Refusal> {
        let fields = match kind {
            Kind::Time => &TIME_FIELDS,
            Kind::Date => &DATE_FIELDS,
        };
        let s1_dev = device(vector, "s1")?;
        let s2_dev = device(vector, "s2")?;
        let s3 = word_operand(vector, mem, "s3")?;

        // "(5) When 1 is set to the 15 bit, the data in the device specified by (s1) is compared
        // with the current time ... (s2) is regarded as dummy data and ignored."
        let use_clock = s3 & 0x8000 != 0;

        // "(4) Set 0. If a value other than 0 is set, the operation result will be
        // non-continuity." (bits 3 to 14) "When 0 is set to the 0 to 2 bits, the time data ...
        // are not compared." Table: "Other than 0001H to 0007H, 8001H to 8007H  None ... (The
        // operation result will be non-continuity.)"
        let reserved = if self.bug(Mutant::Fx5ReservedBitsIgnored) { 0 } else { s3 & 0x7FF8 };
        let s3_valid = reserved == 0 && s3 & 0x0007 != 0;

        // "If the device areas specified by (s1) to (s1)+2 or (s2) to (s2)+2 exceed the
        // corresponding device range, SM709 turns on ... and the operation result will be
        // non-continuity as well." With an invalid (s3) too, FX5-INVALID-S3-DEVICE-RANGE says
        // which rule decides: the device range (SM709 on), or (s3) (non-continuity alone).
        let s2_checked = !use_clock || self.clock_s2 == Fx5ClockS2DeviceRange::Checked;
        let past = !mem.in_range(s1_dev, 3) || (s2_checked && !mem.in_range(s2_dev, 3));
        if past && !self.bug(Mutant::Fx5DeviceRangeUnchecked) {
            if !s3_valid && self.invalid_s3 == Fx5InvalidS3DeviceRange::S3First {
                return Ok(Contact::Compared(false));
            }
            return Ok(Contact::Error);
        }

        let s1 = read3(vector, mem, "s1")?;
        let s2 = if use_clock {
            let clock = step
                .clock
                .as_ref()
                .ok_or_else(|| Refusal::Error("(s3) bit 15 is on but the step gives no clock".to_owned()))?;
            let mut words = [0u16; 3];
            for f in fields {
                let v =
                    clock.get(f.name).ok_or_else(|| Refusal::Error(format!("the step's clock has no {}", f.name)))?;
                words[f.offset] = v as u16; // the current time as the CPU holds it, a word
            }
            words
        } else {
            read3(vector, mem, "s2")?
        };

        // "If the comparison target data in the device are not recognized as time data, SM709
        // turns on ... and the operation result will be non-continuity." Which words are
        // "comparison target data" is interpretation FX5-SM709-SCOPE.
        let out_of_range = |words: &[u16; 3], selected: Option<u16>| {
            fields.iter().any(|f| {
                selected.is_none_or(|s3| s3 >> f.bit & 1 == 1) && !(f.min..=f.max).contains(&signed(words[f.offset]))
            })
        };
        match self.scope {
            Fx5Sm709Scope::AllWords => {
                if out_of_range(&s1, None) || (!use_clock && out_of_range(&s2, None)) {
                    return Ok(Contact::Error);
                }
                if !s3_valid {
                    return Ok(Contact::Compared(false));
                }
            }
            // The operands are "comparison target data" as a whole, but only when the table says
            // they "are compared": not for a selector that compares nothing.
            Fx5Sm709Scope::ComparedOperands => {
                if !s3_valid {
                    return Ok(Contact::Compared(false));
                }
                if out_of_range(&s1, None) || (!use_clock && out_of_range(&s2, None)) {
                    return Ok(Contact::Error);
                }
            }
            Fx5Sm709Scope::SelectedFields => {
                // A masked word is not comparison target data.
                if !s3_valid {
                    return Ok(Contact::Compared(false));
                }
                if out_of_range(&s1, Some(s3)) || (!use_clock && out_of_range(&s2, Some(s3))) {
                    return Ok(Contact::Error);
                }
            }
        }
        // Date page: "Even if the data are not recognized as date data, SM709 does not turn on if
        // the data are within the setting range." -> 02/30 is compared as it is.
        let order = self.compare(fields, &s1, &s2, s3);
        Ok(Contact::Compared(holds(condition, order)))
    }

    /// Field by field, the most significant selected field first.
    fn compare(&self, fields: &[Field; 3], s1: &[u16; 3], s2: &[u16; 3], s3: u16) -> Ordering {
        let order = if self.bug(Mutant::Fx5LowFieldFirst) { [2, 1, 0] } else { [0, 1, 2] };
        order
            .iter()
            .map(|&i| &fields[i])
            .filter(|f| s3 >> f.bit & 1 == 1)
            .map(|f| signed(s1[f.offset]).cmp(&signed(s2[f.offset])))
            .find(|o| o.is_ne())
            .unwrap_or(Ordering::Equal)
    }
}
