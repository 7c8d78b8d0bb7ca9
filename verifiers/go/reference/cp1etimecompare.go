package reference

// Omron SYSMAC CP1E: LD/AND/OR =DT, <>DT, <DT, <=DT, >DT, >=DT (time comparison), from
// cp1e-time-compare-DT.txt (W483 p. 2-93).

import (
	"fmt"

	"github.com/plcvec/plcvec/verifiers/go"
	"github.com/plcvec/plcvec/verifiers/go/spec"
)

var pER = plcvec.Address{Kind: "P_ER", N: -1}

// The arithmetic flags: "the result of a time comparison instruction is reflected in the
// arithmetic flags (=, <>, <, <=, >, >=)."
var cp1eFlags = []struct {
	condition condition
	addr      plcvec.Address
}{{condEQ, plcvec.Address{Kind: "P_EQ", N: -1}}, {condNE, plcvec.Address{Kind: "P_NE", N: -1}},
	{condLT, plcvec.Address{Kind: "P_LT", N: -1}}, {condLE, plcvec.Address{Kind: "P_LE", N: -1}},
	{condGT, plcvec.Address{Kind: "P_GT", N: -1}}, {condGE, plcvec.Address{Kind: "P_GE", N: -1}}}

// cp1eField is one byte of the Calendar/Clock Area layout, most significant first:
// "A351.00 to A351.07 Second (00 to 59, BCD)  A351.08 to A351.15 Minute (00 to 59, BCD)
// A352.00 to A352.07 Hour (00 to 23, BCD)  A352.08 to A352.15 Day of month (01 to 31, BCD)
// A353.00 to A353.07 Month (01 to 12, BCD)  A353.08 to A353.15 Year (00 to 99, BCD)"
// "Bits 00 to 05 of C mask the seconds, minutes, hours, day, month, and year, respectively."
type cp1eField struct {
	word, shift uint
	lo, hi      int
	bit         uint
}

var cp1eFields = [6]cp1eField{
	{2, 8, 0, 99, 5}, // year
	{2, 0, 1, 12, 4}, // month
	{1, 8, 1, 31, 3}, // day
	{1, 0, 0, 23, 2}, // hour
	{0, 8, 0, 59, 1}, // minute
	{0, 0, 0, 59, 0}, // second
}

// cp1eConfig is what the alternatives decide, shared by every vector's CPU.
type cp1eConfig struct {
	parts                   *Parts
	nonBCDError, rangeError bool   // CP1E-NON-BCD, CP1E-OUT-OF-RANGE
	highBitsErr, erEach     bool   // CP1E-C-HIGH-BITS, CP1E-ER-FLAG
	errorFlagsOff           bool   // CP1E-ERROR-FLAGS
	pastEndNotExecuted      bool   // CP1E-PAST-AREA-END: a program error, not an error
	allMasked, andOrWhenOff string // CP1E-ALL-MASKED, CP1E-AND-OR-WHEN-OFF
	cpus                    *spare[cp1eTimeCompare]
}

type cp1eTimeCompare struct {
	*cp1eConfig
	form      form
	condition condition
	s1, s2    plcvec.Address
	c         plcvec.Operand
}

func newCP1E(r *Reference, req *plcvec.Request) (plcvec.CPU, error) {
	cfg, err := r.cp1e.get(func() (cp1eConfig, error) { return configureCP1E(r) })
	if err != nil {
		return nil, err
	}
	in, ok := cp1eContact(req.Instruction)
	if !ok {
		return nil, fmt.Errorf("not a CP1E time comparison: %s", req.Instruction)
	}
	c := cfg.cpus.get()
	*c = cp1eTimeCompare{cp1eConfig: cfg, form: in.form, condition: in.condition}
	if err := deviceOperands(req, []string{"S1", "S2"}, &c.s1, &c.s2); err != nil {
		return nil, err
	}
	if c.c, err = operand(req, "C"); err != nil {
		return nil, err
	}
	return c, nil
}

// Release hands the CPU back for the next vector, which overwrites all of it.
func (c *cp1eTimeCompare) Release() { c.cpus.put(c) }

// configureCP1E: the CPU as the alternatives of the CP1E comparisons configure it.
func configureCP1E(r *Reference) (c cp1eConfig, err error) {
	c.parts, c.cpus = &r.parts, &r.cp1eCPUs
	for _, q := range []struct {
		id, when, other string
		flag            *bool
	}{
		{spec.InterpCp1eNonBcd, spec.Cp1eNonBcdError, spec.Cp1eNonBcdRawBytes, &c.nonBCDError},
		{spec.InterpCp1eOutOfRange, spec.Cp1eOutOfRangeError, spec.Cp1eOutOfRangeCompared, &c.rangeError},
		{spec.InterpCp1eCHighBits, spec.Cp1eCHighBitsError, spec.Cp1eCHighBitsIgnored, &c.highBitsErr},
		{spec.InterpCp1eErFlag, spec.Cp1eErFlagReflectsEachExecution, spec.Cp1eErFlagHeld, &c.erEach},
		{spec.InterpCp1eErrorFlags, spec.Cp1eErrorFlagsOff, spec.Cp1eErrorFlagsKept, &c.errorFlagsOff},
		{spec.InterpCp1ePastAreaEnd, spec.Cp1ePastAreaEndProgramError, spec.Cp1ePastAreaEndError, &c.pastEndNotExecuted},
	} {
		alt, err := r.choice(q.id, q.when, q.other)
		if err != nil {
			return c, err
		}
		*q.flag = alt == q.when
	}
	if c.allMasked, err = r.choice(spec.InterpCp1eAllMasked, spec.Cp1eAllMaskedError, spec.Cp1eAllMaskedEqual,
		spec.Cp1eAllMaskedNotCompared); err != nil {
		return c, err
	}
	if c.andOrWhenOff, err = r.choice(spec.InterpCp1eAndOrWhenOff, spec.Cp1eAndOrWhenOffAlwaysExecuted,
		spec.Cp1eAndOrWhenOffAndSkipped, spec.Cp1eAndOrWhenOffShortCircuit); err != nil {
		return c, err
	}
	return c, nil
}

// Execute: "The time comparison instructions are treated just like the LD, AND, and OR
// instructions to control the execution of subsequent instructions."
func (c *cp1eTimeCompare) Execute(mem *plcvec.Memory, step *plcvec.Inputs) (plcvec.Result, error) {
	switch c.form {
	case formLD:
		return plcvec.Contact(c.evaluate(mem)), nil
	case formAND:
		if !step.RLOIn && c.andOrWhenOff != spec.Cp1eAndOrWhenOffAlwaysExecuted {
			return plcvec.Contact(false), nil
		}
		return plcvec.Contact(c.parts.CP1EAnd(step.RLOIn, c.evaluate(mem))), nil
	}
	if step.RLOIn && c.andOrWhenOff == spec.Cp1eAndOrWhenOffShortCircuit {
		return plcvec.Contact(true), nil
	}
	contact := c.evaluate(mem)
	return plcvec.Contact(step.RLOIn || contact), nil
}

func isBCD(b int) bool   { return b>>4 <= 9 && b&0xF <= 9 }
func bcdValue(b int) int { return b>>4*10 + b&0xF }

func (c *cp1eTimeCompare) evaluate(mem *plcvec.Memory) bool {
	// "S 1 to S 1 +2", "S 2 to S 2 +2": three words each. One past the end of the data area (S1 or
	// S2 at one of its last two words) cannot be read: CP1E-PAST-AREA-END, found before C or the
	// data are looked at.
	if !c.parts.CP1EInArea(mem, c.s1) || !c.parts.CP1EInArea(mem, c.s2) {
		if c.pastEndNotExecuted {
			return false // not executed: nothing written, an OFF execution condition
		}
		return c.error(mem)
	}
	var s1, s2 [3]uint16
	mem.ReadWords(c.s1, s1[:])
	mem.ReadWords(c.s2, s2[:])
	var ctl uint16
	if c.c.Constant != nil {
		ctl = uint16(*c.c.Constant)
	} else {
		ctl = mem.Word(c.c.Addr())
	}
	// Bits 06 to 15 of C: not described by the manual (CP1E-C-HIGH-BITS).
	if ctl&0xFFC0 != 0 && c.highBitsErr {
		return c.error(mem)
	}
	// "To mask a time value, set the corresponding bit in the control word (C) to 1."
	// "compares the unmasked values (corresponding bit of C set to 0)"
	var masked [len(cp1eFields)]bool
	unmasked := 0
	for i, f := range cp1eFields {
		if masked[i] = c.parts.CP1EMasked(ctl, f.bit); !masked[i] {
			unmasked++
		}
	}
	switch {
	case unmasked > 0:
	case c.allMasked == spec.Cp1eAllMaskedError:
		return c.error(mem)
	case c.allMasked == spec.Cp1eAllMaskedNotCompared:
		// Nothing compared, no result: OFF, flags untouched, no error.
		if c.erEach {
			mem.SetBit(pER, false)
		}
		return false
	}
	order := 0
	for i, f := range cp1eFields {
		if masked[i] {
			continue
		}
		a, b := int(s1[f.word]>>f.shift&0xFF), int(s2[f.word]>>f.shift&0xFF)
		for _, raw := range [2]int{a, b} {
			if !isBCD(raw) {
				if c.nonBCDError { // "Second (00 to 59, BCD)" ... (CP1E-NON-BCD)
					return c.error(mem)
				}
			} else if v := bcdValue(raw); (v < f.lo || v > f.hi) && c.rangeError { // CP1E-OUT-OF-RANGE
				return c.error(mem)
			}
		}
		// "The time comparison instructions are limited to comparing 8-bit time values." For
		// valid BCD the byte order is the numeric order; with raw-bytes the bytes are compared
		// as unsigned 8-bit values.
		if order == 0 && a != b {
			order = 1
			if a < b {
				order = -1
			}
		}
	}
	c.parts.CP1EReflectFlags(mem, order)
	if c.erEach {
		mem.SetBit(pER, false) // executed without error
	}
	return holds(c.condition, order)
}

// error: P_ER on, execution condition OFF. The flag table has no row for an execution without a
// comparison result: the six arithmetic flags keep their values, or (CP1E-ERROR-FLAGS=off) are
// all written off.
func (c *cp1eTimeCompare) error(mem *plcvec.Memory) bool {
	mem.SetBit(pER, true)
	if c.errorFlagsOff {
		for _, f := range cp1eFlags {
			mem.SetBit(f.addr, false)
		}
	}
	return false
}

// reflectFlags: the flag table's rows S1 = S2, S1 > S2, S1 < S2.
func reflectFlags(mem *plcvec.Memory, order int) {
	for _, f := range cp1eFlags {
		mem.SetBit(f.addr, holds(f.condition, order))
	}
}
