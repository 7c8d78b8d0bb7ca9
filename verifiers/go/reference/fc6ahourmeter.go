package reference

// IDEC FC6A MICROSmart: HOUR (hour meter), from fc6a-hour-meter-HOUR.txt.

import (
	"github.com/plcvec/plcvec/verifiers/go"
	"github.com/plcvec/plcvec/verifiers/go/spec"
)

var m8004 = plcvec.Address{Kind: "M", N: 8004} // "special internal relay M8004"

// "Special internal relays cannot be designated as destination device D2": the FC6A's special
// internal relays are M8000 onwards (M8004, the error relay, is one).
var firstSpecialRelay = plcvec.Address{Kind: "M", N: 8000}

// "the value returns to 0 hours 0 minutes 0 seconds" after "65,535 hours 59 minutes 59 seconds"
const hourCycle = 65536 * 3600

// fc6aHourMeter is an FC6A CPU executing one HOUR instruction per scan. The fraction of a second
// already measured lives here (on the CPU it is in the system work area D3, D3+1, whose
// contents vectors never compare).
type fc6aHourMeter struct {
	parts      *Parts
	s1         plcvec.Operand
	d1, d2, d3 plcvec.Address
	writeD2    bool // false: D2 is a special relay that HOUR-D2-SPECIAL=error never writes
	forbidden  bool // a program the page forbids, whose reading is `undefined`: nothing judged is done
	d2Error    bool // HOUR-D2-SPECIAL=error: D2 is a special relay, an execution error
	// The alternatives followed.
	recompared bool   // HOUR-OUTPUT-OFF
	inputOff   string // HOUR-INPUT-OFF
	zeroNever  bool   // HOUR-PRESET-ZERO
	firstScan  string // HOUR-FIRST-SCAN
	presetAll  bool   // HOUR-PRESET-CHECK: the preset checked at every execution
	m8004Off   bool   // HOUR-M8004-OFF: a valid preset turns M8004 off
	m8004Once  bool   // HOUR-M8004-REPEAT=once
	d1Reading  string // HOUR-D1-OUT-OF-RANGE: how a D1 with a minute or second above 59 is read
	wrapBefore bool   // HOUR-WRAP-REACH=before-wrap
	d2Special  string // HOUR-D2-SPECIAL
	s1Range    string // HOUR-S1-CONSTANT-RANGE
	// The CPU's state.
	fractionMS int64
	wrapped    bool // for "recompared": D2 stays on across a wrap
	inputWasOn bool // the input at the previous execution (off before the first)
	started    bool // an execution has run since the CPU started
	lastValid  bool // the previous check of S1 found it valid (none yet: true)
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
	special := h.d2.Kind == firstSpecialRelay.Kind && h.d2.N >= firstSpecialRelay.N
	outside := h.s1.Constant != nil && (*h.s1.Constant < 0 || *h.s1.Constant > 65535)
	h.forbidden = special && h.d2Special == spec.HourD2SpecialUndefined ||
		outside && h.s1Range == spec.HourS1ConstantRangeUndefined
	h.d2Error = special && h.d2Special == spec.HourD2SpecialError
	h.writeD2 = !h.d2Error
	return h, nil
}

// Release hands the CPU back for the next vector, which overwrites all of it.
func (h *fc6aHourMeter) Release() { h.cpus.put(h) }

// configureHour: the CPU as the alternatives of HOUR configure it.
func configureHour(r *Reference) (h fc6aHourMeter, err error) {
	h.parts, h.cpus, h.lastValid = &r.parts, &r.hourCPUs, true
	var output, zero, check, off, repeat, reach string
	for _, q := range []struct {
		id   string
		into *string
		alts []string
	}{
		{spec.InterpHourOutputOff, &output, []string{spec.HourOutputOffLatched, spec.HourOutputOffRecompared}},
		{spec.InterpHourInputOff, &h.inputOff, []string{spec.HourInputOffHold, spec.HourInputOffReset, spec.HourInputOffHoldDropFraction}},
		{spec.InterpHourPresetZero, &zero, []string{spec.HourPresetZeroImmediate, spec.HourPresetZeroNever}},
		{spec.InterpHourFirstScan, &h.firstScan, []string{spec.HourFirstScanCounts, spec.HourFirstScanFromNextScan, spec.HourFirstScanAfterCpuStart}},
		{spec.InterpHourPresetCheck, &check, []string{spec.HourPresetCheckInputOn, spec.HourPresetCheckEveryExecution}},
		{spec.InterpHourM8004Off, &off, []string{spec.HourM8004OffNever, spec.HourM8004OffValidPreset}},
		{spec.InterpHourM8004Repeat, &repeat, []string{spec.HourM8004RepeatEveryCheck, spec.HourM8004RepeatOnce}},
		{spec.InterpHourD1OutOfRange, &h.d1Reading, []string{spec.HourD1OutOfRangeAsSeconds, spec.HourD1OutOfRangeError,
			spec.HourD1OutOfRangeAsSecondsIfAdded, spec.HourD1OutOfRangeByField, spec.HourD1OutOfRangeUndefined}},
		{spec.InterpHourWrapReach, &reach, []string{spec.HourWrapReachAfterWrap, spec.HourWrapReachBeforeWrap}},
		{spec.InterpHourD2Special, &h.d2Special, []string{spec.HourD2SpecialAccepted, spec.HourD2SpecialError, spec.HourD2SpecialUndefined}},
		{spec.InterpHourS1ConstantRange, &h.s1Range, []string{spec.HourS1ConstantRangeError, spec.HourS1ConstantRangeAsIs,
			spec.HourS1ConstantRangeLow16Bits, spec.HourS1ConstantRangeUndefined}},
	} {
		if *q.into, err = r.choice(q.id, q.alts...); err != nil {
			return h, err
		}
	}
	h.recompared = output == spec.HourOutputOffRecompared
	h.zeroNever = zero == spec.HourPresetZeroNever
	h.presetAll = check == spec.HourPresetCheckEveryExecution
	h.m8004Off = off == spec.HourM8004OffValidPreset
	h.m8004Once = repeat == spec.HourM8004RepeatOnce
	h.wrapBefore = reach == spec.HourWrapReachBeforeWrap
	return h, nil
}

// preset is S1: "When source device S1 is designated by a constant, the preset value can be 0
// through 65,535 in hours, then minutes and seconds are set to 0." A data register: "3
// consecutive data registers ... to store hour, minute, and second data." A constant past 65,535
// is read as HOUR-S1-CONSTANT-RANGE says.
func (h *fc6aHourMeter) preset(mem *plcvec.Memory) [3]int64 {
	if h.s1.Constant != nil {
		hours := int64(*h.s1.Constant)
		if (hours < 0 || hours > 65535) && h.s1Range == spec.HourS1ConstantRangeLow16Bits {
			hours &= 0xFFFF
		}
		return [3]int64{hours, 0, 0}
	}
	var p [3]uint16
	mem.ReadWords(h.s1.Addr(), p[:])
	return [3]int64{int64(p[0]), int64(p[1]), int64(p[2])}
}

// checkPreset reads S1 and checks it: the preset, or false when it is invalid (M8004 on, D2
// off).
func (h *fc6aHourMeter) checkPreset(mem *plcvec.Memory) ([3]int64, bool) {
	p := h.preset(mem)
	// "Hour data can be 0 through 65,535. Minute and second data can be 0 through 59." Only a
	// constant holds an hour past that: HOUR-S1-CONSTANT-RANGE=as-is takes it.
	hourOK := p[0] >= 0 && p[0] <= 65535 || h.s1Range == spec.HourS1ConstantRangeAsIs
	if !hourOK || p[1] > 59 || p[2] > 59 {
		// "... a user program execution error will result, turning on special internal relay
		// M8004 ... but the input ON duration is measured." HOUR-M8004-REPEAT=once: only when
		// the check before found S1 valid.
		if !h.m8004Once || h.lastValid {
			mem.SetBit(m8004, true)
		}
		h.lastValid = false
		// "... is changed to an invalid value after the comparison output has turned on, the
		// comparison output is turned off."
		if h.writeD2 {
			mem.SetBit(h.d2, false)
		}
		return p, false
	}
	h.lastValid = true
	if h.m8004Off { // the page never says M8004 turns off; HOUR-M8004-OFF=valid-preset does
		mem.SetBit(m8004, false)
	}
	return p, true
}

// measureKeepingFraction: "While input is on, the ON duration of the input is measured": all
// the elapsed time counts, and the part of a second not yet whole is kept for the next scan.
func measureKeepingFraction(fractionMS, elapsedMS int64) (int64, int64) {
	total := fractionMS + elapsedMS
	return total / 1000, total % 1000
}

func (h *fc6aHourMeter) Execute(mem *plcvec.Memory, step *plcvec.Inputs) (plcvec.Result, error) {
	turnedOn := step.Input && !h.inputWasOn
	first := !h.started
	h.inputWasOn, h.started = step.Input, true
	if h.forbidden {
		return plcvec.NoResult, nil
	}
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
	h.measureAndCompare(mem, step, turnedOn, first)
	if h.d2Error { // HOUR-D2-SPECIAL=error: the special relay D2 is an execution error
		mem.SetBit(m8004, true)
	}
	return plcvec.NoResult, nil
}

// measureAndCompare is an execution with the input on: D1 measured, S1 checked, D2 written.
func (h *fc6aHourMeter) measureAndCompare(mem *plcvec.Memory, step *plcvec.Inputs, turnedOn, first bool) {
	var d1 [3]uint16
	mem.ReadWords(h.d1, d1[:])
	// "Minute and second data can be 0 through 59." A D1 the program set outside that is read
	// as HOUR-D1-OUT-OF-RANGE says.
	reading := spec.HourD1OutOfRangeAsSeconds
	if d1[1] > 59 || d1[2] > 59 {
		reading = h.d1Reading
	}
	switch reading {
	case spec.HourD1OutOfRangeUndefined:
		return
	case spec.HourD1OutOfRangeError:
		mem.SetBit(m8004, true)
		return
	}
	// The elapsed time since the previous execution is ON time; HOUR-FIRST-SCAN says whether the
	// execution the input turns on at, or the first since the CPU started, counts it.
	elapsed := step.ElapsedMS
	if turnedOn && h.firstScan == spec.HourFirstScanFromNextScan || first && h.firstScan == spec.HourFirstScanAfterCpuStart {
		elapsed = 0
	}
	var whole int64
	whole, h.fractionMS = h.parts.HourMeasure(h.fractionMS, elapsed)
	h.parts.HourWorkArea(mem, h.d3, h.fractionMS)
	hms, wraps := advance(d1, whole, reading == spec.HourD1OutOfRangeByField)
	if whole > 0 || reading != spec.HourD1OutOfRangeAsSecondsIfAdded {
		mem.SetWords(h.d1, uint16(hms[0]), uint16(hms[1]), uint16(hms[2]))
	}
	if wraps > 0 {
		h.parts.HourOnWrap(mem, h.d2)
	}
	p, valid := h.checkPreset(mem)
	if !valid {
		return
	}
	// HOUR-WRAP-REACH=before-wrap compares the count as it was before it wrapped.
	beforeWrap := wraps > 0 && h.wrapBefore
	if beforeWrap {
		hms[0] += 65536 * wraps
	}
	// "When the measured input ON duration value in destination device D1 reaches the preset
	// value designated by source device S1, the comparison output ... turns on."
	reached := seconds(hms) >= seconds(p)
	if reading == spec.HourD1OutOfRangeByField { // word by word: the hours, then minutes, seconds
		reached = hms[0] > p[0] || hms[0] == p[0] && (hms[1] > p[1] || hms[1] == p[1] && hms[2] >= p[2])
	}
	if seconds(p) == 0 && h.zeroNever {
		reached = false
	}
	if h.writeD2 {
		h.setOutput(mem, reached, wraps > 0, beforeWrap)
	}
}

func seconds(hms [3]int64) int64 { return hms[0]*3600 + hms[1]*60 + hms[2] }

// advance is D1 after whole more seconds, and how many times it passed 65535:59:59. "When the
// measured input ON duration value exceeds 65,535 hours 59 minutes 59 seconds, the value returns
// to 0 hours 0 minutes 0 seconds to repeat another measuring cycle." By field
// (HOUR-D1-OUT-OF-RANGE=by-field), each word counts on its own, one second at a time.
func advance(d1 [3]uint16, whole int64, byField bool) ([3]int64, int64) {
	if !byField {
		total := int64(d1[0])*3600 + int64(d1[1])*60 + int64(d1[2]) + whole
		wraps := total / hourCycle
		total %= hourCycle
		return [3]int64{total / 3600, total % 3600 / 60, total % 60}, wraps
	}
	h, m, s, wraps := d1[0], d1[1], d1[2], int64(0)
	for range whole {
		if s++; s == 60 {
			s = 0
			if m++; m == 60 {
				m = 0
				if h++; h == 0 {
					wraps++
				}
			}
		}
	}
	return [3]int64{int64(h), int64(m), int64(s)}, wraps
}

// setOutput writes D2: "When the D1 value reaches the S1 value, an output or internal relay
// assigned by destination device D2 is turned on" ("with the comparison output remaining on"
// across a wrap). compared before the wrap: HOUR-WRAP-REACH=before-wrap.
func (h *fc6aHourMeter) setOutput(mem *plcvec.Memory, reached, wrappedNow, comparedFirst bool) {
	if !h.recompared {
		if reached {
			mem.SetBit(h.d2, true)
		}
		return
	}
	// recompared: D2 = D1 >= S1, except that it stays on across a wrap
	if wrappedNow && !comparedFirst && mem.Bit(h.d2) {
		h.wrapped = true
	}
	if reached {
		h.wrapped = false
	}
	mem.SetBit(h.d2, reached || (h.wrapped && mem.Bit(h.d2)))
	if wrappedNow && comparedFirst && mem.Bit(h.d2) {
		h.wrapped = true // on when D1 wrapped, after the comparison
	}
}
