// Package mutants holds single-bug variants of the reference implementation: each is the
// reference with one plausible misreading of the manual, made by replacing one of its Parts.
// The verifier must reject every one of them (mutants_test.go): a verifier that cannot fail is
// a defect. Serve one over the stdio protocol with
//
//	verifiers/go/reference-adapter --mutant NAME
package mutants

import (
	"fmt"
	"sort"
	"strings"
	"time"

	"github.com/plcvec/plcvec/verifiers/go"
	"github.com/plcvec/plcvec/verifiers/go/reference"
	"github.com/plcvec/plcvec/verifiers/go/spec"
)

// Mutant is one single-bug variant.
type Mutant struct {
	Name     string
	Families []string // the families its bug is in
	Aspect   string   // what of a vector it breaks: the comparison aspect that must catch it
	Bug      string
	change   func(*reference.Parts)
}

// New is the mutant as an implementation following the given alternatives.
func (m Mutant) New(choices map[string]string) (plcvec.Implementation, error) {
	parts := reference.Correct()
	m.change(&parts)
	r, err := reference.NewVariant(reference.Name+" (mutant "+m.Name+")", choices, parts)
	if err != nil {
		return nil, err
	}
	return r.Implementation(), nil
}

var (
	sm709 = plcvec.Address{Kind: "SM", N: 709}
	sm700 = plcvec.Address{Kind: "SM", N: 700}
)

const day = 24 * 3600

// All lists the mutants, by name.
var All = []Mutant{
	{"fx5-low-field-first", []string{spec.FamilyFx5TimeCompare, spec.FamilyFx5DateCompare}, "contact result",
		"The selected fields are compared from (s1)+2 up (second before minute before hour), so a later field decides before an earlier one.",
		func(p *reference.Parts) { p.FX5FieldOrder = []int{2, 1, 0} }},
	{"fx5-clock-bit-ignored", []string{spec.FamilyFx5TimeCompare, spec.FamilyFx5DateCompare}, "contact result",
		"Bit 15 of (s3) is ignored: (s1) is always compared with (s2), never with the current time or date.",
		func(p *reference.Parts) { p.FX5UsesClock = func(uint16) bool { return false } }},
	{"fx5-sm709-not-latched", []string{spec.FamilyFx5TimeCompare, spec.FamilyFx5DateCompare}, "a device that must stay unchanged",
		"SM709 is written on every execution, off when the data are good, although 'Once SM709 turns on, the on state is held'.",
		func(p *reference.Parts) {
			p.FX5SetSM709 = func(mem *plcvec.Memory, invalid bool) { mem.SetBit(sm709, invalid) }
		}},
	{"fx5-sm709-as-word", []string{spec.FamilyFx5TimeCompare, spec.FamilyFx5DateCompare}, "a flag (its JSON type)",
		"SM709 is stored as the word 1 instead of the bit true: the value reads alike, the type does not.",
		func(p *reference.Parts) {
			p.FX5SetSM709 = func(mem *plcvec.Memory, invalid bool) {
				if invalid {
					mem.SetWord(sm709, 1)
				}
			}
		}},
	{"fx5-date-calendar-check", []string{spec.FamilyFx5DateCompare}, "a flag",
		"A date that does not exist but is within the setting range (2006/02/30) turns SM709 on, although 'SM709 does not turn on if the data are within the setting range'.",
		func(p *reference.Parts) {
			p.FX5DateAccepted = func(y, m, d int) bool {
				return time.Date(y, time.Month(m), d, 0, 0, 0, 0, time.UTC).Day() == d
			}
		}},
	{"tadd-no-wrap-at-24", []string{spec.FamilyFx5TimeAdd}, "a changed word",
		"'If the sum of two values exceeds 24:00:00' read literally: a sum of exactly 24:00:00 is stored as 24:00:00 with neither flag.",
		func(p *reference.Parts) {
			p.TADDWrap = func(total int, _ bool) (int, bool) {
				if total > day {
					return total - day, true
				}
				return total, false
			}
		}},
	{"tadd-sm8022-not-written", []string{spec.FamilyFx5TimeAdd}, "a flag",
		"Only SM700 is written as the carry flag; SM8022, the table's second 'Carry' relay, is left alone.",
		func(p *reference.Parts) { p.TADDCarryFlags = []plcvec.Address{sm700} }},
	{"taddp-every-scan", []string{spec.FamilyFx5TimeAdd}, "a changed word",
		"TADDP adds on every scan while EN is on, like TADD, instead of once on its rising edge.",
		func(p *reference.Parts) { p.TADDRuns = func(_, en, _ bool) bool { return en } }},
	{"tadd-on-error-computed-flags-kept", []string{spec.FamilyFx5TimeAdd}, "an interpretation alternative",
		"On error 3405H the sum is still written to (d), as TADD-ON-ERROR=computed has it, while the implementation declares the default, not-executed; and the flags are left as they were, although that alternative updates them: half of a reading, undeclared.",
		func(p *reference.Parts) { p.TADDOnError, p.TADDFlagsOnError = spec.TaddOnErrorComputed, false }},
	{"tadd-s1-copied-into-d-first", []string{spec.FamilyFx5TimeAdd}, "a changed word",
		"(s1) is copied into (d) first and (s2) then added to (d) in place, so a (d) that shares words with (s2) at another offset adds a changed (s2), under every reading of TADD-OVERLAP.",
		func(p *reference.Parts) { p.TADDS1CopiedIntoD = true }},
	{"hour-drops-fraction", []string{spec.FamilyFc6aHourMeter}, "a changed word",
		"Each scan's ON time is cut to whole seconds and the remainder thrown away, so short scans never add up.",
		func(p *reference.Parts) {
			p.HourMeasure = func(_, elapsed int64) (int64, int64) { return elapsed / 1000, 0 }
		}},
	{"hour-wrap-clears-d2", []string{spec.FamilyFc6aHourMeter}, "a flag",
		"When D1 returns to 0 hours 0 minutes 0 seconds D2 is turned off with it, instead of 'with the comparison output remaining on'.",
		func(p *reference.Parts) {
			p.HourOnWrap = func(mem *plcvec.Memory, d2 plcvec.Address) { mem.SetBit(d2, false) }
		}},
	{"hour-work-area-overrun", []string{spec.FamilyFc6aHourMeter}, "a write outside the vector",
		"The kept fraction of a second is stored in a third work-area word, D3+2, which the manual does not give HOUR: a write outside the vector.",
		func(p *reference.Parts) {
			p.HourWorkArea = func(mem *plcvec.Memory, d3 plcvec.Address, fractionMS int64) {
				mem.SetWords(d3, 0, 0, uint16(fractionMS))
			}
		}},
	{"cp1e-mask-inverted", []string{spec.FamilyCp1eTimeCompare}, "contact result",
		"A C bit set to 1 selects its field for comparison, the opposite of 'To mask a time value, set the corresponding bit in the control word (C) to 1'.",
		func(p *reference.Parts) { p.CP1EMasked = func(c uint16, bit uint) bool { return c>>bit&1 == 0 } }},
	{"cp1e-flags-not-reflected", []string{spec.FamilyCp1eTimeCompare}, "a flag",
		"The arithmetic flags (=, <>, <, <=, >, >=) are left alone, although 'the result of a time comparison instruction is reflected in the arithmetic flags'.",
		func(p *reference.Parts) { p.CP1EReflectFlags = func(*plcvec.Memory, int) {} }},
	{"cp1e-and-as-or", []string{spec.FamilyCp1eTimeCompare}, "contact result",
		"AND =DT ... AND >=DT combine the comparison with the preceding logic as OR does.",
		func(p *reference.Parts) { p.CP1EAnd = func(rlo, contact bool) bool { return rlo || contact } }},
	{"cp1e-past-area-compared", []string{spec.FamilyCp1eTimeCompare}, "a flag",
		"S1 or S2 at the last one or two words of the data area is compared all the same, the words past the end read as 0, instead of the error or program error CP1E-PAST-AREA-END names.",
		func(p *reference.Parts) { p.CP1EInArea = func(*plcvec.Memory, plcvec.Address) bool { return true } }},
}

// Find returns the mutant of that name.
func Find(name string) (Mutant, error) {
	for _, m := range All {
		if m.Name == name {
			return m, nil
		}
	}
	names := make([]string, len(All))
	for i, m := range All {
		names[i] = m.Name
	}
	sort.Strings(names)
	return Mutant{}, fmt.Errorf("no mutant %q; known: %s", name, strings.Join(names, ", "))
}

// Table is the Markdown table of the mutants that MUTANTS.md holds (a test keeps them equal).
func Table() string {
	var b strings.Builder
	b.WriteString("| mutant | families | what it breaks | the bug |\n|---|---|---|---|\n")
	for _, m := range All {
		fmt.Fprintf(&b, "| `%s` | %s | %s | %s |\n", m.Name, strings.Join(m.Families, ", "), m.Aspect, m.Bug)
	}
	return b.String()
}
