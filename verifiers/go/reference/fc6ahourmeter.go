package reference

// IDEC FC6A MICROSmart: HOUR (hour meter), from fc6a-hour-meter-HOUR.txt.

import (
	"github.com/plcvec/plcvec/verifiers/go"
	"github.com/plcvec/plcvec/verifiers/go/spec"
)

var m8004 = plcvec.Addr{Kind: "M", N: 8004} // "special internal relay M8004"

// "the value returns to 0 hours 0 minutes 0 seconds" after "65,535 hours 59 minutes 59 seconds"
const hourCycle = 65536 * 3600

// hourMeter is an FC6A CPU executing one HOUR instruction per scan. The fraction of a second
// already measured lives here (on the CPU it is in the system work area D3, D3+1, whose
// contents vectors never compare).
type fc6aHourMeter struct {
	parts      *Parts
	s1         plcvec.Operand
	d1, d2, d3 plcvec.Addr
	recompared bool   // HOUR-OUTPUT-OFF
	inputOff   string // HOUR-INPUT-OFF
	zeroNever  bool   // HOUR-PRESET-ZERO
	fromNext   bool   // HOUR-FIRST-SCAN: the scan the input turns on does not count
	presetAll  bool   // HOUR-PRESET-CHECK: the preset checked at every execution
	m8004Off   bool   // HOUR-M8004-OFF: a valid preset turns M8004 off
	d1Error    bool   // HOUR-D1-OUT-OF-RANGE: a D1 minute or second above 59 is an error
	fractionMS int64
	wrapped    bool // for "recompared": D2 stays on across a wrap
	inputWasOn bool // the input at the previous execution (off before the first)
	cpus       *spare[fc6aHourMeter]
}

func newHourMeter(r *Reference, req *plcvec.Request) (plcvec.CPU, error) {
	if req.Instruction != spec.InstrHour {
		return nil, plcvec.Skip("not HOUR: " + req.Instruction)
	}
	base, err := r.hour.get(func() (fc6aHourMeter, error) { return configureHour(r) })
	if err != nil {
		return nil, err
	}
	h := base.cpus.get()
	*h = *base
	if h.s1, err = operand(req, "S1"); err != nil {
		return nil, err
	}
	if err := deviceOperands(req, []string{"D1", "D2"}, &h.d1, &h.d2); err != nil {
		return nil, err
	}
	// D3, the work area, is the CPU's own: a vector need not name it.
	if d3, ok := req.Operand("D3"); ok {
		h.d3 = d3.Addr()
	}
	return h, nil
}

// Release hands the CPU back for the next vector, which overwrites all of it.
func (h *fc6aHourMeter) Release() { h.cpus.put(h) }

// configureHour: the CPU as the alternatives of HOUR configure it.
func configureHour(r *Reference) (h fc6aHourMeter, err error) {
	h.parts, h.cpus = &r.parts, &r.hourCPUs
	output, err := r.choice(spec.InterpHourOutputOff, spec.HourOutputOffLatched, spec.HourOutputOffRecompared)
	if err != nil {
		return h, err
	}
	if h.inputOff, err = r.choice(spec.InterpHourInputOff, spec.HourInputOffHold, spec.HourInputOffReset,
		spec.HourInputOffHoldDropFraction); err != nil {
		return h, err
	}
	zero, err := r.choice(spec.InterpHourPresetZero, spec.HourPresetZeroImmediate, spec.HourPresetZeroNever)
	if err != nil {
		return h, err
	}
	h.recompared = output == spec.HourOutputOffRecompared
	h.zeroNever = zero == spec.HourPresetZeroNever
	for _, q := range []struct {
		id, when, other string
		flag            *bool
	}{
		{spec.InterpHourFirstScan, spec.HourFirstScanFromNextScan, spec.HourFirstScanCounts, &h.fromNext},
		{spec.InterpHourPresetCheck, spec.HourPresetCheckEveryExecution, spec.HourPresetCheckInputOn, &h.presetAll},
		{spec.InterpHourM8004Off, spec.HourM8004OffValidPreset, spec.HourM8004OffNever, &h.m8004Off},
		{spec.InterpHourD1OutOfRange, spec.HourD1OutOfRangeError, spec.HourD1OutOfRangeAsSeconds, &h.d1Error},
	} {
		alt, err := r.choice(q.id, q.when, q.other)
		if err != nil {
			return h, err
		}
		*q.flag = alt == q.when
	}
	return h, nil
}

// checkPreset reads S1 and checks it: the preset in seconds, or false when it is invalid
// (M8004 on, D2 off).
func (h *fc6aHourMeter) checkPreset(mem *plcvec.Memory) (int64, bool) {
	// "When source device S1 is designated by a constant, the preset value can be 0 through
	// 65,535 in hours, then minutes and seconds are set to 0." A data register: "3 consecutive
	// data registers ... to store hour, minute, and second data."
	var p [3]uint16
	if h.s1.Constant != nil {
		p[0] = uint16(*h.s1.Constant)
	} else {
		mem.ReadWords(h.s1.Addr(), p[:])
	}
	// "Hour data can be 0 through 65,535. Minute and second data can be 0 through 59."
	if p[1] > 59 || p[2] > 59 {
		// "... a user program execution error will result, turning on special internal relay
		// M8004 ... but the input ON duration is measured." "... is changed to an invalid value
		// after the comparison output has turned on, the comparison output is turned off."
		mem.SetBit(m8004, true)
		mem.SetBit(h.d2, false)
		return 0, false
	}
	if h.m8004Off { // the page never says M8004 turns off; HOUR-M8004-OFF=valid-preset does
		mem.SetBit(m8004, false)
	}
	return int64(p[0])*3600 + int64(p[1])*60 + int64(p[2]), true
}

// measureKeepingFraction: "While input is on, the ON duration of the input is measured": all
// the elapsed time counts, and the part of a second not yet whole is kept for the next scan.
func measureKeepingFraction(fractionMS, elapsedMS int64) (int64, int64) {
	total := fractionMS + elapsedMS
	return total / 1000, total % 1000
}

func (h *fc6aHourMeter) Execute(mem *plcvec.Memory, step *plcvec.Inputs) (plcvec.Result, error) {
	turnedOn := step.Input && !h.inputWasOn
	h.inputWasOn = step.Input
	if !step.Input {
		switch h.inputOff { // HOUR-INPUT-OFF
		case spec.HourInputOffReset:
			mem.SetWords(h.d1, 0, 0, 0)
			h.fractionMS = 0
		case spec.HourInputOffHoldDropFraction:
			h.fractionMS = 0 // D1 kept; the part of a second is lost
		}
		if h.presetAll { // HOUR-PRESET-CHECK=every-execution: checked with the input off too
			h.checkPreset(mem)
		}
		return plcvec.NoResult, nil
	}
	var d1 [3]uint16
	mem.ReadWords(h.d1, d1[:])
	// "Minute and second data can be 0 through 59." A D1 the program set outside that is
	// counted as seconds and carried back into range, or (HOUR-D1-OUT-OF-RANGE=error) is an
	// error that stops this execution.
	if h.d1Error && (d1[1] > 59 || d1[2] > 59) {
		mem.SetBit(m8004, true)
		return plcvec.NoResult, nil
	}
	// The elapsed time since the previous execution is ON time; at the execution the input
	// turns on, only under HOUR-FIRST-SCAN=counts.
	elapsed := step.ElapsedMS
	if turnedOn && h.fromNext {
		elapsed = 0
	}
	var whole int64
	whole, h.fractionMS = h.parts.HourMeasure(h.fractionMS, elapsed)
	h.parts.HourWorkArea(mem, h.d3, h.fractionMS)
	total := int64(d1[0])*3600 + int64(d1[1])*60 + int64(d1[2]) + whole
	// "When the measured input ON duration value exceeds 65,535 hours 59 minutes 59 seconds, the
	// value returns to 0 hours 0 minutes 0 seconds to repeat another measuring cycle, with the
	// comparison output remaining on."
	wrappedNow := total >= hourCycle
	total %= hourCycle
	mem.SetWords(h.d1, uint16(total/3600), uint16(total%3600/60), uint16(total%60))
	if wrappedNow {
		h.parts.HourOnWrap(mem, h.d2)
	}

	preset, valid := h.checkPreset(mem)
	if !valid {
		return plcvec.NoResult, nil
	}
	// "When the measured input ON duration value in destination device D1 reaches the preset
	// value designated by source device S1, the comparison output ... turns on."
	reached := total >= preset
	if preset == 0 && h.zeroNever {
		reached = false
	}
	if !h.recompared {
		if reached {
			mem.SetBit(h.d2, true)
		}
		return plcvec.NoResult, nil
	}
	// recompared: D2 = D1 >= S1, except that it stays on across a wrap
	if wrappedNow && mem.Bit(h.d2) {
		h.wrapped = true
	}
	if reached {
		h.wrapped = false
	}
	mem.SetBit(h.d2, reached || (h.wrapped && mem.Bit(h.d2)))
	return plcvec.NoResult, nil
}
