package reference

// Mitsubishi MELSEC iQ-F FX5: TADD / TADDP (adding clock data), from fx5-time-add-TADD.txt.

import (
	"fmt"

	"github.com/plcvec/plcvec/verifiers/go"
	"github.com/plcvec/plcvec/verifiers/go/spec"
)

const day = 24 * 3600

var (
	// "SM700 Carry ... SM8020 Zero ... SM8022 Carry"
	sm700, sm8020, sm8022 = plcvec.Address{Kind: "SM", N: 700}, plcvec.Address{Kind: "SM", N: 8020}, plcvec.Address{Kind: "SM", N: 8022}
	// "Error code (SD0/SD8067)"
	errorRegisters = []plcvec.Address{{Kind: "SD", N: 0}, {Kind: "SD", N: 8067}}
	// "(s1) hour (0 to 23) ... minute (0 to 59) ... second (0 to 59)"
	taddRanges = [3][2]int{{0, 23}, {0, 59}, {0, 59}}
	// Seconds in one hour, minute and second, and what each word counts up to before it carries.
	taddWeights = [3]int{3600, 60, 1}
	taddRadix   = [3]int{24, 60, 60}
)

const (
	errDeviceRange = 0x2820 // "The device range specified by (s1), (s2), and (d) exceeds ..."
	errValueRange  = 0x3405 // "Any of values specified by (s1) and (s2) is outside the following range."
)

type fx5TimeAdd struct {
	parts        *Parts
	pulse        bool
	s1, s2, d    plcvec.Address
	flagsEach    bool   // TADD-FLAGS-OFF: written-each-execution
	carryAt24    bool   // TADD-EXACT-24
	computeOnErr bool   // TADD-ON-ERROR: computed
	fieldFirst   bool   // TADD-ERROR-ORDER: 3405H stored when both conditions meet
	overlap      string // TADD-OVERLAP: when (d) is written, relative to the reads of (s1) and (s2)
	previousEN   bool   // TADDP: the state before the first scan is off
	cpus         *spare[fx5TimeAdd]
}

func newTADD(r *Reference, req *plcvec.Request) (plcvec.CPU, error) {
	base, err := r.tadd.get(func() (fx5TimeAdd, error) { return configureTADD(r) })
	if err != nil {
		return nil, err
	}
	t := base.cpus.get()
	*t = *base
	switch req.Instruction {
	case spec.InstrTadd:
	case spec.InstrTaddp:
		t.pulse = true
	default:
		return nil, fmt.Errorf("not TADD/TADDP: %s", req.Instruction)
	}
	if err := deviceOperands(req, []string{"s1", "s2", "d"}, &t.s1, &t.s2, &t.d); err != nil {
		return nil, err
	}
	return t, nil
}

// Release hands the CPU back for the next vector, which overwrites all of it.
func (t *fx5TimeAdd) Release() { t.cpus.put(t) }

// configureTADD: the CPU as the alternatives of TADD configure it.
func configureTADD(r *Reference) (t fx5TimeAdd, err error) {
	t.parts, t.cpus = &r.parts, &r.taddCPUs
	flags, err := r.choice(spec.InterpTaddFlagsOff, spec.TaddFlagsOffWrittenEachExecution, spec.TaddFlagsOffSetOnly)
	if err != nil {
		return t, err
	}
	exact, err := r.choice(spec.InterpTaddExact24, spec.TaddExact24CarryAt24, spec.TaddExact24CarryAbove24)
	if err != nil {
		return t, err
	}
	onError, err := r.choice(spec.InterpTaddOnError, spec.TaddOnErrorNotExecuted, spec.TaddOnErrorComputed)
	if err != nil {
		return t, err
	}
	if r.parts.TADDOnError != "" {
		onError = r.parts.TADDOnError
	}
	t.flagsEach = flags == spec.TaddFlagsOffWrittenEachExecution
	t.carryAt24 = exact == spec.TaddExact24CarryAt24
	t.computeOnErr = onError == spec.TaddOnErrorComputed
	order, err := r.choice(spec.InterpTaddErrorOrder, spec.TaddErrorOrderDeviceRangeFirst, spec.TaddErrorOrderFieldRangeFirst)
	if err != nil {
		return t, err
	}
	t.fieldFirst = order == spec.TaddErrorOrderFieldRangeFirst
	t.overlap, err = r.choice(spec.InterpTaddOverlap, spec.TaddOverlapSourcesFirst, spec.TaddOverlapSecondFirst,
		spec.TaddOverlapHourFirst)
	return t, err
}

// taddRuns: TADD executes every scan while EN is on; TADDP on the rising edge of EN only.
func taddRuns(pulse, en, previous bool) bool {
	if pulse {
		return en && !previous
	}
	return en
}

func (t *fx5TimeAdd) Execute(mem *plcvec.Memory, step *plcvec.Inputs) (plcvec.Result, error) {
	run := t.parts.TADDRuns(t.pulse, step.EN, t.previousEN)
	t.previousEN = step.EN
	if run {
		t.add(mem)
	}
	return plcvec.NoResult, nil
}

func (t *fx5TimeAdd) add(mem *plcvec.Memory) {
	// "2820H The device range specified by (s1), (s2), and (d) exceeds the corresponding device
	// range." Nothing is read or written. ("These instructions occupy three points for each of
	// three devices")
	for _, a := range []plcvec.Address{t.s1, t.s2, t.d} {
		if !mem.InRange(a, 3) {
			// Both conditions: TADD-ERROR-ORDER says which code; nothing else is written, since
			// an operand past its device cannot be read or written.
			code := uint16(errDeviceRange)
			if t.fieldFirst && (t.fieldOutOfRange(mem, t.s1) || t.fieldOutOfRange(mem, t.s2)) {
				code = errValueRange
			}
			t.error(mem, code)
			return
		}
	}
	// "3405H Any of values specified by (s1) and (s2) is outside the following range": judged on
	// the words as they were before the execution, whatever TADD-OVERLAP writes on the way. The
	// three words of each exist (above): read once, for the check and, unless an error code was
	// written in between, for the sum.
	var w1, w2 [3]uint16
	mem.ReadWords(t.s1, w1[:])
	mem.ReadWords(t.s2, w2[:])
	failed := fieldsOutOfRange(&w1) || fieldsOutOfRange(&w2)
	if failed {
		t.error(mem, errValueRange)
		if !t.computeOnErr {
			return
		}
	}
	total := t.sumSeconds(mem, &w1, &w2, !failed)
	result, carry := t.parts.TADDWrap(total, t.carryAt24)
	mem.SetWords(t.d, uint16(result/3600), uint16(result%3600/60), uint16(result%60))
	if failed && !t.parts.TADDFlagsOnError {
		return
	}
	// "If the result is 0 (0:00:00), the zero flag turns on."
	t.setFlags(mem, carry, result == 0)
}

// sumSeconds is (s1) + (s2) in seconds, the words read in the order TADD-OVERLAP says. "These
// instructions add the time data stored in the device numbers starting from (s2) to the clock data
// stored in the device numbers starting from (s1), and store the result to the device numbers
// starting from (d)." The order shows only when (d) shares words with (s1) or (s2) at another
// offset: a source word read after that word of (d) is written holds what was written. Every
// word of (d) is written again from the total afterwards (add). w1 and w2 are (s1) and (s2) as
// add read them; fresh says nothing has been written since, so that they are what a read now gives.
func (t *fx5TimeAdd) sumSeconds(mem *plcvec.Memory, w1, w2 *[3]uint16, fresh bool) int {
	word := func(a plcvec.Address, k int) int { return signed16(mem.Word(a.Offset(k))) }
	total, s1 := 0, t.s1
	if t.parts.TADDS1CopiedIntoD {
		var w [3]uint16
		mem.ReadWords(t.s1, w[:])
		mem.SetWords(t.d, w[:]...)
		s1, fresh = t.d, false
	}
	switch t.overlap {
	case spec.TaddOverlapSecondFirst:
		// Second, minute, hour, the carry's way: each word of (d) gets its digit once known.
		carry := 0
		for k := 2; k >= 0; k-- {
			a, b := word(s1, k), word(t.s2, k)
			total += (a + b) * taddWeights[k]
			var digit int
			carry, digit = floorDivMod(a+b+carry, taddRadix[k])
			mem.SetWord(t.d.Offset(k), uint16(digit))
		}
	case spec.TaddOverlapHourFirst:
		// Hour, minute, second: each word of (d) gets the plain sum of its pair, the carries
		// settled afterwards from the three sums.
		for k := 0; k < 3; k++ {
			a, b := word(s1, k), word(t.s2, k)
			total += (a + b) * taddWeights[k]
			mem.SetWord(t.d.Offset(k), uint16(a+b))
		}
	default: // sources-first: all six words read before (d) is written
		if !fresh {
			mem.ReadWords(s1, w1[:])
			mem.ReadWords(t.s2, w2[:])
		}
		for k := range w1 {
			total += (signed16(w1[k]) + signed16(w2[k])) * taddWeights[k]
		}
	}
	return total
}

// floorDivMod is n div m and n mod m rounded toward minus infinity, so that a negative word
// (invalid data computed under TADD-ON-ERROR=computed) borrows from the next word up.
func floorDivMod(n, m int) (int, int) {
	q, r := n/m, n%m
	if r < 0 {
		q, r = q-1, r+m
	}
	return q, r
}

// fieldOutOfRange: "3405H Any of values specified by (s1) and (s2) is outside the following
// range." Only an operand whose three words exist can be read and checked.
func (t *fx5TimeAdd) fieldOutOfRange(mem *plcvec.Memory, a plcvec.Address) bool {
	if !mem.InRange(a, 3) {
		return false
	}
	var raw [3]uint16
	mem.ReadWords(a, raw[:])
	return fieldsOutOfRange(&raw)
}

// fieldsOutOfRange: an operand's hour, minute or second, as read, outside its range.
func fieldsOutOfRange(raw *[3]uint16) bool {
	for k, r := range taddRanges {
		if v := signed16(raw[k]); v < r[0] || v > r[1] {
			return true
		}
	}
	return false
}

// wrapDay: "If the sum of two values exceeds 24:00:00, the carry flag turns on, and the result
// will be the sum minus 24:00:00." But: "If 1 second is added to 23:59:59, the result will be
// 0:00:00. This turns on both the carry flag and the zero flag." -> TADD-EXACT-24.
func wrapDay(total int, carryAt24 bool) (int, bool) {
	carry := total > day
	if carryAt24 {
		carry = total >= day
	}
	result := total % day
	if result < 0 { // a negative word (invalid data computed under TADD-ON-ERROR=computed)
		result += day
	}
	return result, carry
}

func (t *fx5TimeAdd) setFlags(mem *plcvec.Memory, carry, zero bool) {
	if t.flagsEach {
		for _, f := range t.parts.TADDCarryFlags {
			mem.SetBit(f, carry)
		}
		mem.SetBit(sm8020, zero)
		return
	}
	// set-only: an execution only ever turns a flag on
	if carry {
		for _, f := range t.parts.TADDCarryFlags {
			mem.SetBit(f, true)
		}
	}
	if zero {
		mem.SetBit(sm8020, true)
	}
}

func (t *fx5TimeAdd) error(mem *plcvec.Memory, code uint16) {
	for _, r := range errorRegisters {
		mem.SetWord(r, code)
	}
}
