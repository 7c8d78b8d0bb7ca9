package reference

import "github.com/plcvec/plcvec/verifiers/go"

// Parts are the small pieces of the reference that a single-bug variant replaces (package
// mutants); Correct gives the reference's own. Each is one decision the manual states, so a
// mutant is the reference with one plausible misreading.
type Parts struct {
	// FX5Fields orders the FX5 comparison fields as they are compared: most significant first.
	FX5FieldOrder []int
	// FX5UsesClock: whether (s3) asks for the current time/date ("(5) When 1 is set to the 15 bit").
	FX5UsesClock func(s3 uint16) bool
	// FX5SetSM709 writes SM709 after an execution; invalid says whether the data were invalid.
	FX5SetSM709 func(mem *plcvec.Memory, invalid bool)
	// FX5DateAccepted: whether a date within the setting range is compared (the manual: yes,
	// even when it does not exist).
	FX5DateAccepted func(year, month, day int) bool
	// TADDWrap: the sum in seconds -> the result in seconds and the carry.
	TADDWrap func(total int, carryAt24 bool) (int, bool)
	// TADDCarryFlags: the carry relays written by an execution.
	TADDCarryFlags []plcvec.Address
	// TADDRuns: whether this scan executes the addition (TADD: while EN; TADDP: its rising edge).
	TADDRuns func(pulse, en, previous bool) bool
	// TADDOnError overrides TADD-ON-ERROR's declared alternative when not "" (a variant that
	// follows another alternative than it declares).
	TADDOnError string
	// TADDFlagsOnError: whether an execution that computes the sum on error 3405H
	// (TADD-ON-ERROR=computed) writes the flags too ("flags updated"; the reference: yes).
	TADDFlagsOnError bool
	// TADDS1CopiedIntoD: whether the addition first copies (s1) into (d) and then adds (s2) to
	// (d) in place (the reference: no, it adds (s2) to (s1) as TADD-OVERLAP says).
	TADDS1CopiedIntoD bool
	// HourMeasure: whole seconds measured and the fraction kept, from the kept fraction and
	// this scan's elapsed milliseconds.
	HourMeasure func(fractionMS, elapsedMS int64) (whole, keptMS int64)
	// HourOnWrap: what a wrap of D1 does to D2.
	HourOnWrap func(mem *plcvec.Memory, d2 plcvec.Address)
	// HourWorkArea: what the CPU keeps in the system work area D3 (the reference: nothing
	// that the vectors compare; scratch words are never compared).
	HourWorkArea func(mem *plcvec.Memory, d3 plcvec.Address, fractionMS int64)
	// CP1EMasked: whether bit `bit` of C masks its field.
	CP1EMasked func(c uint16, bit uint) bool
	// CP1EReflectFlags writes the arithmetic flags after a comparison of the given order.
	CP1EReflectFlags func(mem *plcvec.Memory, order int)
	// CP1EAnd combines an AND form's comparison with the preceding logic.
	CP1EAnd func(rlo, contact bool) bool
	// CP1EInArea: whether the three words of S1 or S2 from a lie in their data area.
	CP1EInArea func(mem *plcvec.Memory, a plcvec.Address) bool
}

// Correct is the reference's own parts.
func Correct() Parts {
	return Parts{
		FX5FieldOrder:    []int{0, 1, 2},
		FX5UsesClock:     func(s3 uint16) bool { return s3&0x8000 != 0 },
		FX5SetSM709:      latchSM709,
		FX5DateAccepted:  func(int, int, int) bool { return true },
		TADDWrap:         wrapDay,
		TADDCarryFlags:   []plcvec.Address{sm700, sm8022},
		TADDRuns:         taddRuns,
		TADDFlagsOnError: true,
		HourMeasure:      measureKeepingFraction,
		HourOnWrap:       func(*plcvec.Memory, plcvec.Address) {},
		HourWorkArea:     func(*plcvec.Memory, plcvec.Address, int64) {},
		CP1EMasked:       func(c uint16, bit uint) bool { return c>>bit&1 == 1 },
		CP1EReflectFlags: reflectFlags,
		CP1EAnd:          func(rlo, contact bool) bool { return rlo && contact },
		CP1EInArea:       func(mem *plcvec.Memory, a plcvec.Address) bool { return mem.InRange(a, 3) },
	}
}
