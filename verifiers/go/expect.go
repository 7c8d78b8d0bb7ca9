package plcvec

import (
	"fmt"
	"sort"
	"strings"
)

// absent marks a device that is not (yet) in the expected state.
const absent Value = 1 << 31

// expected is what one vector expects of an implementation that follows given alternatives.
// A vector stores per step only the devices that changed, and the full state at the end;
// implementations report the full image after every step, which is simpler for any emulator.
// So the full expected state after each step is worked out here once, and checked against the
// vector's own `final`, so that an inconsistent vector file is caught, not trusted.
type expected struct {
	names    []string // every device of the vector, sorted (usually just the initial ones)
	compared []bool   // parallel to names: false for scratch words
	scratch  bool     // whether any device is a scratch word (not compared)
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
	sets      []map[string]Value // each step's `set` (the vector's own maps)
	vector    *Vector
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

func expectationOf(a *arena, v *Vector, choices map[string]Choice, devices []string, cpuWrites map[string]bool) (*expected, error) {
	touched := v.Outcome.Interpretations
	applied := make(map[string]string, len(touched))
	isDefault := true
	for _, id := range touched {
		c, ok := choices[id]
		if !ok {
			return nil, fmt.Errorf("vector %s: depends on interpretation %s, which its file does not declare", v.ID, id)
		}
		applied[id] = c.Alternative
		if c.Alternative != c.Default {
			isDefault = false
		}
	}
	stepExpects := make([]*Expect, len(v.Steps))
	for i := range v.Steps {
		stepExpects[i] = v.Steps[i].Expect
	}
	final := v.Final.Devices
	category := v.Outcome.Category
	if len(touched) > 0 && v.Outcome.Default != nil {
		category = v.Outcome.Default.Category
	}
	if !isDefault {
		found := false
		for ai := range v.Alternatives {
			alt := &v.Alternatives[ai]
			match := true
			for id, a := range applied {
				if alt.Choices[id] != a {
					match = false
					break
				}
			}
			if match {
				for i := range alt.Expect {
					stepExpects[i] = &alt.Expect[i]
				}
				final, category, found = alt.Final.Devices, alt.Outcome.Category, true
				break
			}
		}
		if !found {
			keys := make([]string, 0, len(applied))
			for id, a := range applied {
				keys = append(keys, id+"="+a)
			}
			sort.Strings(keys)
			return nil, fmt.Errorf("vector %s: no expectation for %s (the vector file lists no such alternative)",
				v.ID, strings.Join(keys, ", "))
		}
	}

	scratch := map[string]bool{}
	for _, s := range v.Initial.Scratch {
		scratch[s] = true
	}
	// The devices: the request's (sorted), then any other a step sets or expects.
	names := make([]string, len(devices))
	index := make(map[string]int, len(devices))
	for i, d := range devices {
		names[i] = d
		index[d] = i
	}
	requested := a.names.take(len(names), a.chunk)
	copy(requested, names)
	extra := []string{}
	note := func(name string) {
		if _, ok := index[name]; !ok {
			index[name] = -1
			extra = append(extra, name)
		}
	}
	for i, st := range v.Steps {
		for name := range st.Set {
			note(name)
		}
		for name := range stepExpects[i].Devices {
			note(name)
		}
	}
	for name := range final {
		note(name)
	}
	if len(extra) > 0 {
		names = append(names, extra...)
		sort.Strings(names)
		for i, n := range names {
			index[n] = i
		}
	}
	e := a.expects.one(a.chunk)
	*e = expected{names: names, compared: a.flags.take(len(names), a.chunk), choices: applied, category: category,
		requested: requested, cpuWrites: cpuWrites, sets: make([]map[string]Value, len(v.Steps)), vector: v}
	for i := range v.Steps {
		e.sets[i] = v.Steps[i].Set
	}
	n, steps := len(names), len(v.Steps)
	e.states, e.befores = a.values.take(n*steps, a.chunk), a.befores.take(n*steps, a.chunk)
	e.results = a.results.take(steps, a.chunk)
	state := make([]Value, n)
	for i := range state {
		state[i] = absent
	}
	for i, name := range names {
		e.compared[i] = !scratch[name]
		e.scratch = e.scratch || scratch[name]
		if val, ok := v.Initial.Devices[name]; ok {
			state[i] = val
		}
	}
	for i, st := range v.Steps {
		for name, val := range st.Set {
			state[index[name]] = val
		}
		copy(e.before(i), state)
		for name, val := range stepExpects[i].Devices {
			state[index[name]] = val
		}
		copy(e.state(i), state)
		e.results[i] = NoResult
		if stepExpects[i].Result != nil {
			e.results[i] = Contact(*stepExpects[i].Result)
		}
	}
	last := e.state(steps - 1)
	for i, n := range names {
		if scratch[n] {
			continue
		}
		want, ok := final[n]
		if (ok && last[i] != want) || (!ok && last[i] != absent) {
			return nil, fmt.Errorf("vector %s: the per-step changes do not add up to `final` at %s "+
				"(the vector file is inconsistent; regenerate it)", v.ID, n)
		}
	}
	return e, nil
}
