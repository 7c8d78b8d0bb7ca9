package reference

// Mitsubishi MELSEC iQ-F FX5: LDTM□/ANDTM□/ORTM□ (time) and LDDT□/ANDDT□/ORDT□ (date), from the
// manual pages fx5-time-compare-LDTM.txt and fx5-date-compare-LDDT.txt. The two pages are the
// same text with hour/minute/second replaced by year/month/day, so one CPU serves both.

import (
	"fmt"

	"github.com/plcvec/plcvec/verifiers/go"
	"github.com/plcvec/plcvec/verifiers/go/spec"
)

var sm709 = plcvec.Address{Kind: "SM", N: 709}

// field is one word of (s1)/(s2): its name (as in a step's `clock`), range, and (s3) bit.
type field struct {
	name   string
	lo, hi int
	bit    uint
}

// Time: 'Set the "hour" data ... within the range 0 to 23.' '"minute" ... (s1)+1 ... 0 to 59.'
// '"second" ... (s1)+2 ... 0 to 59.' '(1) Set "second" as comparison target. (2) ... "minute"
// ... (3) ... "hour"'. Most significant first, at word offsets 0, 1, 2.
var timeFields = [3]field{{"hour", 0, 23, 2}, {"minute", 0, 59, 1}, {"second", 0, 59, 0}}

// Date: 'Set the 4 digit "year" data ... within the range 1980 to 2079.' '"month" ... 1 to 12.'
// '"date" data in ... (s1)+2 ... 1 to 31.' '(1) Set "day" ... (2) ... "month" ... (3) ... "year"'
var dateFields = [3]field{{"year", 1980, 2079, 2}, {"month", 1, 12, 1}, {"day", 1, 31, 0}}

// fx5Config is what the alternatives decide, shared by every vector's CPU.
type fx5Config struct {
	parts        *Parts
	scope        string // FX5-SM709-SCOPE
	andOrWhenOff string // FX5-AND-OR-WHEN-OFF
	checkClockS2 bool   // FX5-CLOCK-S2-DEVICE-RANGE
	orErrorOff   bool   // FX5-OR-ON-ERROR: an error in an OR form turns the result off
	s3First      bool   // FX5-INVALID-S3-DEVICE-RANGE: an (s3) that compares nothing is judged first
	cpus         *spare[fx5Compare]
}

type fx5Compare struct {
	*fx5Config
	fields    *[3]field
	date      bool
	form      form
	condition condition
	s1, s2    plcvec.Address
	s3        plcvec.Operand
	failed    bool // the last evaluation found invalid data (SM709 on)
}

func newFX5Compare(r *Reference, req *plcvec.Request, fields *[3]field) (plcvec.CPU, error) {
	date := fields == &dateFields
	cfg, err := r.fx5.get(func() (fx5Config, error) { return configureFX5(r) })
	if err != nil {
		return nil, err
	}
	in, ok := fx5Contact(req.Instruction)
	if !ok || in.date != date {
		what := "time"
		if date {
			what = "date"
		}
		return nil, fmt.Errorf("not an FX5 %s comparison: %s", what, req.Instruction)
	}
	c := cfg.cpus.get()
	*c = fx5Compare{fx5Config: cfg, fields: fields, date: date, form: in.form, condition: in.condition}
	if err := deviceOperands(req, []string{"s1", "s2"}, &c.s1, &c.s2); err != nil {
		return nil, err
	}
	if c.s3, err = operand(req, "s3"); err != nil {
		return nil, err
	}
	return c, nil
}

// Release hands the CPU back for the next vector, which overwrites all of it.
func (c *fx5Compare) Release() { c.cpus.put(c) }

// configureFX5: the CPU as the alternatives of the FX5 comparisons configure it.
func configureFX5(r *Reference) (c fx5Config, err error) {
	c.parts, c.cpus = &r.parts, &r.fx5CPUs
	if c.scope, err = r.choice(spec.InterpFx5Sm709Scope, spec.Fx5Sm709ScopeSelectedFields,
		spec.Fx5Sm709ScopeAllWords, spec.Fx5Sm709ScopeComparedOperands); err != nil {
		return c, err
	}
	if c.andOrWhenOff, err = r.choice(spec.InterpFx5AndOrWhenOff, spec.Fx5AndOrWhenOffAndSkipped,
		spec.Fx5AndOrWhenOffAlwaysExecuted, spec.Fx5AndOrWhenOffShortCircuit); err != nil {
		return c, err
	}
	s2range, err := r.choice(spec.InterpFx5ClockS2DeviceRange, spec.Fx5ClockS2DeviceRangeIgnored, spec.Fx5ClockS2DeviceRangeChecked)
	if err != nil {
		return c, err
	}
	c.checkClockS2 = s2range == spec.Fx5ClockS2DeviceRangeChecked
	orError, err := r.choice(spec.InterpFx5OrOnError, spec.Fx5OrOnErrorContactOff, spec.Fx5OrOnErrorResultOff)
	if err != nil {
		return c, err
	}
	c.orErrorOff = orError == spec.Fx5OrOnErrorResultOff
	order, err := r.choice(spec.InterpFx5InvalidS3DeviceRange, spec.Fx5InvalidS3DeviceRangeDeviceRangeFirst,
		spec.Fx5InvalidS3DeviceRangeS3First)
	if err != nil {
		return c, err
	}
	c.s3First = order == spec.Fx5InvalidS3DeviceRangeS3First
	return c, nil
}

// Execute is one scan of one LD/AND/OR contact. "(Devices are used as a normally open
// contact.)" The MELSEC iQ-R Programming Manual (CPU Module Instructions), processing-time
// tables: an AND/OR comparison is not executed while the preceding logic decides it
// (FX5-AND-OR-WHEN-OFF).
func (c *fx5Compare) Execute(mem *plcvec.Memory, step *plcvec.Inputs) (plcvec.Result, error) {
	switch c.form {
	case formLD:
		return plcvec.Contact(c.evaluate(mem, step)), nil
	case formAND:
		if !step.RLOIn && c.andOrWhenOff != spec.Fx5AndOrWhenOffAlwaysExecuted {
			return plcvec.Contact(false), nil
		}
		contact := c.evaluate(mem, step) // executed: may set SM709
		return plcvec.Contact(step.RLOIn && contact), nil
	}
	if step.RLOIn && c.andOrWhenOff == spec.Fx5AndOrWhenOffShortCircuit {
		return plcvec.Contact(true), nil
	}
	c.failed = false
	contact := c.evaluate(mem, step)
	// "SM709 turns on ... and the operation result will be non-continuity": a non-conductive
	// contact in parallel (contact-off), or the rung's result itself off (FX5-OR-ON-ERROR=result-off).
	if c.failed && c.orErrorOff {
		return plcvec.Contact(false), nil
	}
	return plcvec.Contact(step.RLOIn || contact), nil
}

// evaluate is the comparison itself, with its error handling: the contact's state.
func (c *fx5Compare) evaluate(mem *plcvec.Memory, step *plcvec.Inputs) bool {
	s3 := c.operandS3(mem)
	// "(5) When 1 is set to the 15 bit, the data in the device specified by (s1) is compared
	// with the current time ... The time data in the device specified by (s2) is regarded as
	// dummy data and ignored."
	useClock := c.parts.FX5UsesClock(s3)
	// "(4) Set 0. If a value other than 0 is set, the operation result will be non-continuity."
	// (bits 3 to 14); "When 0 is set to the 0 to 2 bits, the time data ... are not compared."
	s3Valid := s3&0x7FF8 == 0 && s3&0x0007 != 0
	// "If the device areas specified by (s1) to (s1)+2 or (s2) to (s2)+2 exceed the
	// corresponding device range, SM709 turns on ... and the operation result will be
	// non-continuity as well."
	if !mem.InRange(c.s1, 3) || ((!useClock || c.checkClockS2) && !mem.InRange(c.s2, 3)) {
		// With an (s3) that compares nothing as well, FX5-INVALID-S3-DEVICE-RANGE says which
		// rule decides: non-continuity both ways, SM709 on only when the device range does.
		if !s3Valid && c.s3First {
			return false
		}
		return c.invalid(mem)
	}
	var s1, s2 [3]int
	var raw [3]uint16
	mem.ReadWords(c.s1, raw[:])
	for k := range raw {
		s1[k] = signed16(raw[k]) // (s1), (s2): "16-bit signed binary"
	}
	if useClock {
		for k, f := range c.fields {
			s2[k], _ = step.ClockField(f.name) // the current time or date
		}
	} else {
		mem.ReadWords(c.s2, raw[:])
		for k := range raw {
			s2[k] = signed16(raw[k])
		}
	}
	// "If the comparison target data in the device are not recognized as time data, SM709 turns
	// on after the instruction is executed and the operation result will be non-continuity."
	// Which words are "comparison target data" is interpretation FX5-SM709-SCOPE.
	switch c.scope {
	case spec.Fx5Sm709ScopeAllWords: // every word, whether or not the comparison is made
		if c.outOfRange(s1, 0xFFFF) || (!useClock && c.outOfRange(s2, 0xFFFF)) {
			return c.invalid(mem)
		}
		if !s3Valid {
			return false
		}
	case spec.Fx5Sm709ScopeComparedOperands:
		// The operands are "comparison target data" as a whole, but only when the table says
		// they "are compared": not for a selector that compares nothing.
		if !s3Valid {
			return false
		}
		if c.outOfRange(s1, 0xFFFF) || (!useClock && c.outOfRange(s2, 0xFFFF)) {
			return c.invalid(mem)
		}
	default: // selected-fields: a masked word is not comparison target data
		if !s3Valid {
			return false
		}
		if c.outOfRange(s1, s3) || (!useClock && c.outOfRange(s2, s3)) {
			return c.invalid(mem)
		}
	}
	// Date page: "Even if the data are not recognized as date data, SM709 does not turn on if
	// the data are within the setting range." -> 02/30 is compared as it is.
	if c.date && (!c.parts.FX5DateAccepted(s1[0], s1[1], s1[2]) ||
		(!useClock && !c.parts.FX5DateAccepted(s2[0], s2[1], s2[2]))) {
		return c.invalid(mem)
	}
	c.parts.FX5SetSM709(mem, false)
	return holds(c.condition, c.order(s1, s2, s3))
}

func (c *fx5Compare) operandS3(mem *plcvec.Memory) uint16 {
	if c.s3.Constant != nil {
		return uint16(*c.s3.Constant)
	}
	return mem.Word(c.s3.Addr())
}

// outOfRange: a field (selected by mask, or every field for 0xFFFF) outside its range.
func (c *fx5Compare) outOfRange(words [3]int, mask uint16) bool {
	for k, f := range c.fields {
		if mask>>f.bit&1 == 0 {
			continue
		}
		if words[k] < f.lo || words[k] > f.hi {
			return true
		}
	}
	return false
}

// order is -1/0/1: field by field, most significant selected field first.
func (c *fx5Compare) order(s1, s2 [3]int, s3 uint16) int {
	for _, k := range c.parts.FX5FieldOrder {
		if s3>>c.fields[k].bit&1 == 0 {
			continue
		}
		if s1[k] != s2[k] {
			if s1[k] < s2[k] {
				return -1
			}
			return 1
		}
	}
	return 0
}

func (c *fx5Compare) invalid(mem *plcvec.Memory) bool {
	c.failed = true
	c.parts.FX5SetSM709(mem, true)
	return false
}

// latchSM709: "SM709 turns on after the instruction is executed and the operation result will
// be non-continuity." "Once SM709 turns on, the on state is held until the CPU module is
// powered off or reset." -> only ever set, never cleared.
func latchSM709(mem *plcvec.Memory, invalid bool) {
	if invalid {
		mem.SetBit(sm709, true)
	}
}
