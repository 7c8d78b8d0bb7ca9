//! IDEC FC6A MICROSmart: HOUR (hour meter).
//!
//! Written from the manual page fc6a-hour-meter-HOUR.txt.

use plcvec::names::{
    HourD1OutOfRange, HourD2Special, HourFirstScan, HourInputOff, HourM8004Off, HourM8004Repeat, HourOutputOff,
    HourPresetCheck, HourPresetZero, HourS1ConstantRange, HourWrapReach,
};
use plcvec::{Address, Choices, Memory, Operand, Refusal, Step, Vector};

use super::{device, read3, Mutant};

const ERROR_FLAG: &str = "M8004";
// "the value returns to 0 hours 0 minutes 0 seconds" after "65,535 hours 59 minutes 59 seconds"
const CYCLE: u64 = 65536 * 3600;
// "Special internal relays cannot be designated as destination device D2": the FC6A's special
// internal relays are M8000 onwards (M8004, the error relay, is one).
const SPECIAL_RELAYS: (&str, u32) = ("M", 8000);

/// The readings of the page's open questions this execution follows.
#[derive(Clone, Debug)]
struct Readings {
    output_off: HourOutputOff,
    input_off: HourInputOff,
    preset_zero: HourPresetZero,
    first_scan: HourFirstScan,
    preset_check: HourPresetCheck,
    m8004_off: HourM8004Off,
    d1_out_of_range: HourD1OutOfRange,
    wrap_reach: HourWrapReach,
    m8004_repeat: HourM8004Repeat,
    d2_special: HourD2Special,
    s1_constant_range: HourS1ConstantRange,
}

/// The fraction of a second already measured lives here; on the CPU it is in the system work
/// area (D3, D3+1), whose contents vectors never compare.
#[derive(Clone, Debug)]
pub(super) struct Fc6aHourMeter {
    readings: Readings,
    mutant: Option<Mutant>,
    fraction_ms: u64,
    /// For "recompared": D2 stays on across a wrap.
    wrapped: bool,
    /// The input at the previous execution (off before the first).
    input_was_on: bool,
    /// No execution yet since the CPU started (HOUR-FIRST-SCAN=after-cpu-start).
    first_scan: bool,
    /// Whether the last check of S1 found it valid (HOUR-M8004-REPEAT=once); no check yet counts.
    last_check_valid: bool,
}

fn seconds(hms: [u64; 3]) -> u64 {
    hms[0] * 3600 + hms[1] * 60 + hms[2]
}

fn words(hms: [u16; 3]) -> [u64; 3] {
    hms.map(u64::from)
}

fn is_special_relay(d2: &Address) -> bool {
    d2.kind() == SPECIAL_RELAYS.0 && d2.number().is_some_and(|n| n >= SPECIAL_RELAYS.1)
}

/// One second more on a D1 whose words count each on their own (HOUR-D1-OUT-OF-RANGE=by-field):
/// the words after it, and whether the hour went from 65535 to 0.
fn tick(hms: [u16; 3]) -> ([u16; 3], bool) {
    let [h, m, s] = hms;
    let s = s.wrapping_add(1);
    if s != 60 {
        return ([h, m, s], false);
    }
    let m = m.wrapping_add(1);
    if m != 60 {
        return ([h, m, 0], false);
    }
    let h = h.wrapping_add(1);
    ([h, 0, 0], h == 0)
}

impl Fc6aHourMeter {
    pub(super) fn new(choices: &Choices, mutant: Option<Mutant>) -> Fc6aHourMeter {
        let readings = Readings {
            output_off: choices.get(),
            input_off: choices.get(),
            preset_zero: choices.get(),
            first_scan: choices.get(),
            preset_check: choices.get(),
            m8004_off: choices.get(),
            d1_out_of_range: choices.get(),
            wrap_reach: choices.get(),
            m8004_repeat: choices.get(),
            d2_special: choices.get(),
            s1_constant_range: choices.get(),
        };
        Fc6aHourMeter {
            readings,
            mutant,
            fraction_ms: 0,
            wrapped: false,
            input_was_on: false,
            first_scan: true,
            last_check_valid: true,
        }
    }

    pub(super) fn reset(&mut self) {
        self.fraction_ms = 0;
        self.wrapped = false;
        self.input_was_on = false;
        self.first_scan = true;
        self.last_check_valid = true;
    }

    fn bug(&self, m: Mutant) -> bool {
        self.mutant == Some(m)
    }

    pub(super) fn execute(&mut self, vector: &Vector, step: &Step, mem: &mut Memory<'_>) -> Result<(), Refusal> {
        let result = self.measure(vector, step, mem);
        if self.bug(Mutant::HourDropsFraction) {
            self.fraction_ms = 0;
        }
        result
    }

    /// A program the page forbids, whose reading is `undefined`: the instruction does nothing
    /// anyone judges.
    fn forbidden(&self, vector: &Vector, d2: &Address) -> bool {
        let r = &self.readings;
        if is_special_relay(d2) && r.d2_special == HourD2Special::Undefined {
            return true;
        }
        let hours = match vector.operand("S1") {
            Some(Operand::Constant(c)) => *c,
            _ => 0,
        };
        !(0..=65535).contains(&hours) && r.s1_constant_range == HourS1ConstantRange::Undefined
    }

    fn measure(&mut self, vector: &Vector, step: &Step, mem: &mut Memory<'_>) -> Result<(), Refusal> {
        let d1 = device(vector, "D1")?;
        let d2 = device(vector, "D2")?;
        let on = step.input.ok_or_else(|| Refusal::Error("HOUR needs the step's input".to_owned()))?;
        let turned_on = on && !self.input_was_on;
        self.input_was_on = on;
        let first = std::mem::replace(&mut self.first_scan, false);
        if self.forbidden(vector, d2) {
            return Ok(());
        }
        // "Special internal relays cannot be designated as destination device D2":
        // HOUR-D2-SPECIAL=error never writes such a D2 and reports an error instead.
        let d2_error = is_special_relay(d2) && self.readings.d2_special == HourD2Special::Error;
        let d2 = (!d2_error).then_some(d2);
        if !on {
            // "While input is on, the ON duration of the input is measured." Off: HOUR-INPUT-OFF.
            match self.readings.input_off {
                HourInputOff::Hold => {}
                HourInputOff::Reset => {
                    for offset in 0..3 {
                        mem.set_word(d1, offset, 0);
                    }
                    self.fraction_ms = 0;
                }
                // D1 kept; the part of a second already counted is lost.
                HourInputOff::HoldDropFraction => self.fraction_ms = 0,
            }
            // HOUR-PRESET-CHECK=every-execution: the preset is checked with the input off too.
            if self.readings.preset_check == HourPresetCheck::EveryExecution {
                self.check_preset(vector, mem, d2)?;
            }
            return Ok(());
        }
        self.measure_and_compare(vector, step, mem, (d1, d2), turned_on, first)?;
        if d2_error {
            mem.set_bit(ERROR_FLAG, true);
        }
        Ok(())
    }

    /// An execution with the input on: the ON time added to D1, then D1 compared with S1.
    fn measure_and_compare(
        &mut self,
        vector: &Vector,
        step: &Step,
        mem: &mut Memory<'_>,
        (d1, d2): (&Address, Option<&Address>),
        turned_on: bool,
        first: bool,
    ) -> Result<(), Refusal> {
        // "Minute and second data can be 0 through 59." A D1 the program set outside that is read
        // as HOUR-D1-OUT-OF-RANGE says.
        let held = read3(vector, mem, "D1")?;
        let out_of_range = held[1] > 59 || held[2] > 59;
        let reading = if out_of_range { self.readings.d1_out_of_range } else { HourD1OutOfRange::AsSeconds };
        match reading {
            HourD1OutOfRange::Undefined => return Ok(()),
            HourD1OutOfRange::Error => {
                mem.set_bit(ERROR_FLAG, true);
                return Ok(());
            }
            _ => {}
        }
        // The elapsed time since the previous execution is ON time; at the execution at which
        // the input turns on, only under HOUR-FIRST-SCAN=counts (and after-cpu-start, but for
        // the first execution since the CPU started).
        let elapsed = step.elapsed_ms.ok_or_else(|| Refusal::Error("HOUR needs the step's elapsed_ms".to_owned()))?;
        let first_scan = self.readings.first_scan;
        let skip = (turned_on && first_scan == HourFirstScan::FromNextScan)
            || (first && first_scan == HourFirstScan::AfterCpuStart);
        if !skip {
            self.fraction_ms += elapsed;
        }
        let whole = self.fraction_ms / 1000;
        self.fraction_ms %= 1000;
        let (hms, wraps) = counted(held, whole, reading);
        if whole > 0 || reading != HourD1OutOfRange::AsSecondsIfAdded {
            for (offset, v) in hms.into_iter().enumerate() {
                mem.set_word(d1, offset as u32, v);
            }
        }
        if wraps > 0 && self.bug(Mutant::HourWrapClearsD2) {
            if let Some(d2) = d2 {
                mem.set_at(d2, 0, false.into());
            }
        }
        let Some(preset) = self.check_preset(vector, mem, d2)? else { return Ok(()) };
        // HOUR-WRAP-REACH=before-wrap compares the count as it was before it wrapped.
        let before_wrap = wraps > 0 && self.readings.wrap_reach == HourWrapReach::BeforeWrap;
        let mut count = words(hms);
        if before_wrap {
            count[0] += 65536 * wraps;
        }
        // "When the measured input ON duration value in destination device D1 reaches the preset
        // value designated by source device S1, the comparison output ... turns on." By field:
        // hour, then minute, then second.
        let mut reached = match reading {
            HourD1OutOfRange::ByField => count >= preset,
            _ if self.bug(Mutant::HourOutputAbovePreset) => seconds(count) > seconds(preset),
            _ => seconds(count) >= seconds(preset),
        };
        if seconds(preset) == 0 && self.readings.preset_zero == HourPresetZero::Never {
            reached = false;
        }
        if let Some(d2) = d2 {
            self.set_output(mem, d2, reached, wraps > 0, before_wrap);
        }
        Ok(())
    }

    /// D2 after a comparison (HOUR-OUTPUT-OFF).
    fn set_output(
        &mut self,
        mem: &mut Memory<'_>,
        d2: &Address,
        reached: bool,
        wrapped_now: bool,
        compared_first: bool,
    ) {
        // "When the D1 value reaches the S1 value, an output or internal relay assigned by
        // destination device D2 is turned on."
        let d2_on = |mem: &Memory<'_>| mem.get_at(d2, 0) == Some(true.into());
        match self.readings.output_off {
            HourOutputOff::Latched => {
                if reached {
                    mem.set_at(d2, 0, true.into());
                }
            }
            // D2 = D1 >= S1, except that it stays on across a wrap.
            HourOutputOff::Recompared => {
                if wrapped_now && !compared_first && d2_on(mem) {
                    self.wrapped = true;
                }
                if reached {
                    self.wrapped = false;
                }
                let on = reached || (self.wrapped && d2_on(mem));
                mem.set_at(d2, 0, on.into());
                if wrapped_now && compared_first && d2_on(mem) {
                    self.wrapped = true; // on when D1 wrapped, after the comparison
                }
            }
        }
    }

    /// Read and check S1: the preset, or `None` when it is invalid (M8004 on, D2 off).
    fn check_preset(
        &mut self,
        vector: &Vector,
        mem: &mut Memory<'_>,
        d2: Option<&Address>,
    ) -> Result<Option<[u64; 3]>, Refusal> {
        let r = &self.readings;
        // "When source device S1 is designated by a constant, the preset value can be 0 through
        // 65,535 in hours, then minutes and seconds are set to 0." A data register: "3
        // consecutive data registers ... hour, minute, and second data."
        let (hours, preset) = match vector.operand("S1") {
            Some(Operand::Constant(c)) => {
                let low = *c & 0xFFFF;
                let hours = if r.s1_constant_range == HourS1ConstantRange::Low16Bits { low } else { *c };
                (hours, [hours.max(0) as u64, 0, 0])
            }
            Some(Operand::Device(_)) => {
                let p = read3(vector, mem, "S1")?;
                (i64::from(p[0]), words(p))
            }
            None => return Err(Refusal::Error("HOUR: no operand S1".to_owned())),
        };
        // "Hour data can be 0 through 65,535. Minute and second data can be 0 through 59." Only a
        // constant can hold an hour outside 0..65535: HOUR-S1-CONSTANT-RANGE=as-is takes it.
        let hour_ok = (0..=65535).contains(&hours) || r.s1_constant_range == HourS1ConstantRange::AsIs;
        if !hour_ok || preset[1] > 59 || preset[2] > 59 {
            // "... a user program execution error will result, turning on special internal relay
            // M8004 ... but the input ON duration is measured." HOUR-M8004-REPEAT=once: only when
            // the check before found S1 valid. "... is changed to an invalid value after the
            // comparison output has turned on, the comparison output is turned off."
            if r.m8004_repeat == HourM8004Repeat::EveryCheck || self.last_check_valid {
                mem.set_bit(ERROR_FLAG, true);
            }
            self.last_check_valid = false;
            if let Some(d2) = d2 {
                mem.set_at(d2, 0, false.into());
            }
            return Ok(None);
        }
        self.last_check_valid = true;
        // The page never says M8004 turns off; HOUR-M8004-OFF=valid-preset does.
        if r.m8004_off == HourM8004Off::ValidPreset {
            mem.set_bit(ERROR_FLAG, false);
        }
        Ok(Some(preset))
    }
}

/// D1 after `whole` seconds more, and how many times it wrapped past 65535:59:59: counted in
/// seconds (and written back within range), or field by field (HOUR-D1-OUT-OF-RANGE=by-field).
fn counted(held: [u16; 3], whole: u64, reading: HourD1OutOfRange) -> ([u16; 3], u64) {
    if reading == HourD1OutOfRange::ByField {
        let mut hms = held;
        let mut wraps = 0;
        for _ in 0..whole {
            let (next, wrapped) = tick(hms);
            hms = next;
            wraps += u64::from(wrapped);
        }
        return (hms, wraps);
    }
    // "When the measured input ON duration value exceeds 65,535 hours 59 minutes 59 seconds,
    // the value returns to 0 hours 0 minutes 0 seconds to repeat another measuring cycle, with
    // the comparison output remaining on."
    let total = seconds(words(held)) + whole;
    let t = total % CYCLE;
    ([t / 3600, t % 3600 / 60, t % 60].map(|v| v as u16), total / CYCLE)
}
