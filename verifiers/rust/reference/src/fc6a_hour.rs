//! IDEC FC6A MICROSmart: HOUR (hour meter).
//!
//! Written from the manual page fc6a-hour-meter-HOUR.txt.

use plcvec::names::{
    HourD1OutOfRange, HourFirstScan, HourInputOff, HourM8004Off, HourOutputOff, HourPresetCheck, HourPresetZero,
};
use plcvec::{Choices, Memory, Operand, Refusal, Step, Vector};

use super::{device, read3, Mutant};

const ERROR_FLAG: &str = "M8004";
// "the value returns to 0 hours 0 minutes 0 seconds" after "65,535 hours 59 minutes 59 seconds"
const CYCLE: u64 = 65536 * 3600;

/// The fraction of a second already measured lives here; on the CPU it is in the system work
/// area (D3, D3+1), whose contents vectors never compare.
#[derive(Clone, Debug)]
pub(super) struct Fc6aHourMeter {
    output_off: HourOutputOff,
    input_off: HourInputOff,
    preset_zero: HourPresetZero,
    first_scan: HourFirstScan,
    preset_check: HourPresetCheck,
    m8004_off: HourM8004Off,
    d1_out_of_range: HourD1OutOfRange,
    mutant: Option<Mutant>,
    fraction_ms: u64,
    /// For "recompared": D2 stays on across a wrap.
    wrapped: bool,
    /// The input at the previous execution (off before the first).
    input_was_on: bool,
}

fn seconds(hms: [u16; 3]) -> u64 {
    u64::from(hms[0]) * 3600 + u64::from(hms[1]) * 60 + u64::from(hms[2])
}

impl Fc6aHourMeter {
    pub(super) fn new(choices: &Choices, mutant: Option<Mutant>) -> Fc6aHourMeter {
        Fc6aHourMeter {
            output_off: choices.get(),
            input_off: choices.get(),
            preset_zero: choices.get(),
            first_scan: choices.get(),
            preset_check: choices.get(),
            m8004_off: choices.get(),
            d1_out_of_range: choices.get(),
            mutant,
            fraction_ms: 0,
            wrapped: false,
            input_was_on: false,
        }
    }

    pub(super) fn reset(&mut self) {
        self.fraction_ms = 0;
        self.wrapped = false;
        self.input_was_on = false;
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

    // Over 80 lines, kept whole: one execution of HOUR read top to bottom in the order the page
    // and its interpretations take its steps (input off, the preset, D1, the ON time, D2).
    fn measure(&mut self, vector: &Vector, step: &Step, mem: &mut Memory<'_>) -> Result<(), Refusal> {
        let d1 = device(vector, "D1")?;
        let d2 = device(vector, "D2")?;
        let on = step.input.ok_or_else(|| Refusal::Error("HOUR needs the step's input".to_owned()))?;
        let turned_on = on && !self.input_was_on;
        self.input_was_on = on;
        if !on {
            // "While input is on, the ON duration of the input is measured." Off: HOUR-INPUT-OFF.
            match self.input_off {
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
            if self.preset_check == HourPresetCheck::EveryExecution {
                self.check_preset(vector, mem, d2)?;
            }
            return Ok(());
        }
        // D1 holding a minute or second above 59 (the page gives D1 no range): counted as
        // seconds and carried back into range (HOUR-D1-OUT-OF-RANGE=as-seconds), or an error
        // that stops this execution (error).
        let held = read3(vector, mem, "D1")?;
        if (held[1] > 59 || held[2] > 59) && self.d1_out_of_range == HourD1OutOfRange::Error {
            mem.set_bit(ERROR_FLAG, true);
            return Ok(());
        }
        // The elapsed time since the previous execution is ON time; at the execution at which
        // the input turns on, only under HOUR-FIRST-SCAN=counts.
        let elapsed = step.elapsed_ms.ok_or_else(|| Refusal::Error("HOUR needs the step's elapsed_ms".to_owned()))?;
        if !(turned_on && self.first_scan == HourFirstScan::FromNextScan) {
            self.fraction_ms += elapsed;
        }
        let whole = self.fraction_ms / 1000;
        self.fraction_ms %= 1000;
        let mut total = seconds(read3(vector, mem, "D1")?) + whole;
        // "When the measured input ON duration value exceeds 65,535 hours 59 minutes 59 seconds,
        // the value returns to 0 hours 0 minutes 0 seconds to repeat another measuring cycle,
        // with the comparison output remaining on."
        let wrapped_now = total >= CYCLE;
        total %= CYCLE;
        for (offset, v) in [total / 3600, total % 3600 / 60, total % 60].into_iter().enumerate() {
            mem.set_word(d1, offset as u32, v as u16);
        }
        if wrapped_now && self.bug(Mutant::HourWrapClearsD2) {
            mem.set_at(d2, 0, false.into());
        }

        let Some(preset) = self.check_preset(vector, mem, d2)? else { return Ok(()) };
        let preset = seconds(preset);
        // "When the measured input ON duration value in destination device D1 reaches the preset
        // value designated by source device S1, the comparison output ... turns on."
        let mut reached = if self.bug(Mutant::HourOutputAbovePreset) { total > preset } else { total >= preset };
        if preset == 0 && self.preset_zero == HourPresetZero::Never {
            reached = false;
        }
        let d2_on = mem.get_at(d2, 0) == Some(true.into());
        match self.output_off {
            HourOutputOff::Latched => {
                if reached {
                    mem.set_at(d2, 0, true.into());
                }
            }
            // D2 = D1 >= S1, except that it stays on across a wrap.
            HourOutputOff::Recompared => {
                if wrapped_now && d2_on {
                    self.wrapped = true;
                }
                if reached {
                    self.wrapped = false;
                }
                mem.set_at(d2, 0, (reached || (self.wrapped && d2_on)).into());
            }
        }
        Ok(())
    }

    /// Read and check S1: the preset, or `None` when it is invalid (M8004 on, D2 off).
    fn check_preset(
        &self,
        vector: &Vector,
        mem: &mut Memory<'_>,
        d2: &plcvec::Address,
    ) -> Result<Option<[u16; 3]>, Refusal> {
        // "When source device S1 is designated by a constant, the preset value can be 0 through
        // 65,535 in hours, then minutes and seconds are set to 0." A data register: "3
        // consecutive data registers ... hour, minute, and second data."
        let preset = match vector.operand("S1") {
            Some(Operand::Constant(c)) => [*c as u16, 0, 0],
            Some(Operand::Device(_)) => read3(vector, mem, "S1")?,
            None => return Err(Refusal::Error("HOUR: no operand S1".to_owned())),
        };
        // "Hour data can be 0 through 65,535. Minute and second data can be 0 through 59."
        if preset[1] > 59 || preset[2] > 59 {
            // "... a user program execution error will result, turning on special internal relay
            // M8004 ... but the input ON duration is measured." "... is changed to an invalid
            // value after the comparison output has turned on, the comparison output is turned off."
            mem.set_bit(ERROR_FLAG, true);
            mem.set_at(d2, 0, false.into());
            return Ok(None);
        }
        // The page never says M8004 turns off; HOUR-M8004-OFF=valid-preset does.
        if self.m8004_off == HourM8004Off::ValidPreset {
            mem.set_bit(ERROR_FLAG, false);
        }
        Ok(Some(preset))
    }
}
