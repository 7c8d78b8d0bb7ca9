package plcvec

import (
	"fmt"
	"sort"
	"strings"
)

// What a vector expects of an implementation that follows given alternatives, in two concerns:
// which of the vector's expectations applies (its own steps and final, or the entry of its
// alternatives that matches: entryOf, the vector model), and that expectation laid out flat for
// judging (expectedOf: the full state after every step, one list of values per step, parallel to
// the names of the vector's devices), which is what a run reads for every vector.

// absent marks a device that is not (yet) in the expected state.
const absent Value = 1 << 31

// entry is the vector's expectation under one combination of alternatives.
type entry struct {
	choices  map[string]string // the interpretations the vector touches -> the alternative
	steps    []*Expect
	final    map[string]Value
	category string
	// unjudged: the devices the entry leaves unjudged, by the interpretation whose alternative
	// leaves them (an entry of `alternatives` only; the vector's defaults judge every device).
	unjudged map[string][]string
}

// entryOf is the entry of v under the alternatives of choices: v's own steps and final when
// every interpretation v touches is at its default, else the entry of v's alternatives whose
// choices match.
func entryOf(v *Vector, choices Followed) (entry, error) {
	touched := v.Outcome.Interpretations
	en := entry{choices: make(map[string]string, len(touched)), steps: make([]*Expect, len(v.Steps)),
		final: v.Final.Devices, category: v.Outcome.Category}
	isDefault := true
	for _, id := range touched {
		c, ok := choices[id]
		if !ok {
			return en, fmt.Errorf("vector %s: depends on interpretation %s, which its file does not declare", v.ID, id)
		}
		en.choices[id] = c.Alternative
		isDefault = isDefault && c.Alternative == c.Default
	}
	for i := range v.Steps {
		en.steps[i] = v.Steps[i].Expect
	}
	if len(touched) > 0 && v.Outcome.Default != nil {
		en.category = v.Outcome.Default.Category
	}
	if isDefault {
		return en, nil
	}
	alt := v.alternative(en.choices)
	if alt == nil {
		keys := make([]string, 0, len(en.choices))
		for id, a := range en.choices {
			keys = append(keys, id+"="+a)
		}
		sort.Strings(keys)
		return en, fmt.Errorf("vector %s: no expectation for %s (the vector file lists no such alternative)",
			v.ID, strings.Join(keys, ", "))
	}
	for i := range alt.Expect {
		en.steps[i] = &alt.Expect[i]
	}
	en.final, en.category, en.unjudged = alt.Final.Devices, alt.Outcome.Category, alt.Unjudged
	return en, nil
}

// alternative is the entry of v's alternatives whose choices name each of these alternatives,
// or nil.
func (v *Vector) alternative(choices map[string]string) *Alternative {
	for i := range v.Alternatives {
		alt := &v.Alternatives[i]
		match := true
		for id, a := range choices {
			if alt.Choices[id] != a {
				match = false
				break
			}
		}
		if match {
			return alt
		}
	}
	return nil
}

// expected is one vector's entry laid out for judging. A vector stores per step only the
// devices that changed, and the full state at the end; implementations report the full image
// after every step, which is simpler for any emulator. So the full expected state after each
// step is worked out here once, and checked against the entry's own `final`, so that an
// inconsistent vector file is caught, not trusted.
type expected struct {
	names    []string // every device of the vector, sorted (usually just the initial ones)
	compared []bool   // parallel to names: false for scratch words and devices left unjudged
	skips    bool     // whether some device is not compared
	states   []Value  // step after step, each parallel to names; absent where the state has no such device
	befores  []Value  // likewise: the state each step started from (after `set`), for messages
	results  []Result // per step: the contact result expected, NoResult when none
	choices  map[string]string
	category string
	// requested are the names of the request's devices, the order of StepResult.Values.
	requested []string
	// cpuWrites are the devices the implementation declares its CPU writes on its own account:
	// written outside the vector, they are not stray writes.
	cpuWrites map[string]bool
	sets      []map[string]Value // each step's `set` (the vector's own maps), for what was held before it
	// unjudged is the entry's: the devices left unjudged, by interpretation; notJudged the same
	// devices as a set (nil when the entry judges every device).
	unjudged  map[string][]string
	notJudged map[string]bool
}

// state is the full state expected after step i; before, the state the step started from.
func (e *expected) state(i int) []Value {
	n := len(e.names)
	return e.states[i*n : (i+1)*n : (i+1)*n]
}

func (e *expected) before(i int) []Value {
	n := len(e.names)
	return e.befores[i*n : (i+1)*n : (i+1)*n]
}

// judges reports whether the expectation compares device name (every device but those its entry
// leaves unjudged; a scratch word's value is never compared, but it is expected all the same).
func (e *expected) judges(name string) bool { return !e.notJudged[name] }

// expectedOf is v's expectation under choices, laid out for judging: devices are the names of the
// request's devices (sorted), the order in which a fast answer gives their values, kept as they
// are (requested), not copied: no one writes to them afterwards.
func expectedOf(a *arena, v *Vector, choices Followed, devices []string, cpuWrites map[string]bool) (*expected, error) {
	en, err := entryOf(v, choices)
	if err != nil {
		return nil, err
	}
	names := deviceNames(v, en, devices)
	e := a.expects.one(a.chunk)
	*e = expected{names: names, compared: a.flags.take(len(names), a.chunk), choices: en.choices, category: en.category,
		requested: devices, cpuWrites: cpuWrites, sets: make([]map[string]Value, len(v.Steps)),
		unjudged: en.unjudged}
	for i := range v.Steps {
		e.sets[i] = v.Steps[i].Set
	}
	e.markCompared(v, en)
	e.layOut(a, v, en)
	if err := e.checkFinal(v, en); err != nil {
		return nil, err
	}
	return e, nil
}

// deviceNames are the vector's devices, sorted: the request's (sorted already), then any other a
// step sets or expects (seldom any: a vector lists in `initial` what it reads or writes).
func deviceNames(v *Vector, en entry, devices []string) []string {
	names := devices
	note := func(name string) {
		if !hasName(names, name) {
			if len(names) == len(devices) { // the first extra: a list of the vector's own
				names = append(make([]string, 0, len(devices)+4), devices...)
			}
			names = append(names, name)
			sort.Strings(names)
		}
	}
	for i, st := range v.Steps {
		for name := range st.Set {
			note(name)
		}
		for name := range en.steps[i].Devices {
			note(name)
		}
	}
	for name := range en.final {
		note(name)
	}
	return names
}

// hasName reports whether the sorted names hold name.
func hasName(names []string, name string) bool {
	i := sort.SearchStrings(names, name)
	return i < len(names) && names[i] == name
}

// indexOf is name's index in the sorted names (which hold it).
func indexOf(names []string, name string) int { return sort.SearchStrings(names, name) }

// markCompared leaves scratch words and the devices the entry leaves unjudged out of the
// comparison.
func (e *expected) markCompared(v *Vector, en entry) {
	scratch := make(map[string]bool, len(v.Initial.Scratch))
	for _, s := range v.Initial.Scratch {
		scratch[s] = true
	}
	for _, devices := range en.unjudged {
		if e.notJudged == nil {
			e.notJudged = map[string]bool{}
		}
		for _, d := range devices {
			e.notJudged[d] = true
		}
	}
	for i, name := range e.names {
		e.compared[i] = !scratch[name] && !e.notJudged[name]
		e.skips = e.skips || !e.compared[i]
	}
}

// layOut works out the state before and after every step, and each step's contact result.
func (e *expected) layOut(a *arena, v *Vector, en entry) {
	n, steps := len(e.names), len(v.Steps)
	e.states, e.befores = a.values.take(n*steps, a.chunk), a.befores.take(n*steps, a.chunk)
	e.results = a.results.take(steps, a.chunk)
	state := make([]Value, n)
	for i, name := range e.names {
		state[i] = absent
		if val, ok := v.Initial.Devices[name]; ok {
			state[i] = val
		}
	}
	for i, st := range v.Steps {
		for name, val := range st.Set {
			state[indexOf(e.names, name)] = val
		}
		copy(e.before(i), state)
		for name, val := range en.steps[i].Devices {
			state[indexOf(e.names, name)] = val
		}
		copy(e.state(i), state)
		e.results[i] = NoResult
		if r := en.steps[i].Result; r != nil {
			e.results[i] = Contact(*r)
		}
	}
}

// checkFinal checks that the per-step changes add up to the entry's `final` on every device it
// judges (scratch words and devices left unjudged are in no `final`).
func (e *expected) checkFinal(v *Vector, en entry) error {
	last := e.state(len(v.Steps) - 1)
	for i, name := range e.names {
		if !e.compared[i] {
			continue
		}
		want, ok := en.final[name]
		if (ok && last[i] != want) || (!ok && last[i] != absent) {
			return fmt.Errorf("vector %s: the per-step changes do not add up to `final` at %s "+
				"(the vector file is inconsistent; regenerate it)", v.ID, name)
		}
	}
	return nil
}
