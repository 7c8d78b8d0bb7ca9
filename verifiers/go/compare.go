package plcvec

import (
	"fmt"
	"slices"
	"sort"
)

// compare judges reported steps against the expectation: nil when everything matches exactly.
// Most vectors pass, and the fast form (values in the request's order) is what Emulate gives,
// so that case is checked first, apart: the full comparison builds the differences.
//
// The request is not read: an implementation may have changed it while it ran (the names of its
// devices were copied when the expectation was built).
func (e *expected) compare(steps []StepResult) []Problem {
	if e.matches(steps) {
		return nil
	}
	return e.problems(steps)
}

// matches reports whether steps in the fast form match the expectation exactly.
func (e *expected) matches(steps []StepResult) bool {
	if len(steps) != len(e.results) {
		return false
	}
	for i := range steps {
		vals := steps[i].Values
		if r := e.results[i]; r != NoResult && steps[i].Result != r || len(steps[i].Devices) != 0 || len(vals) != len(e.names) {
			return false
		}
		if want := e.state(i); e.skips && !sameCompared(vals, want, e.compared) || !e.skips && !slices.Equal(vals, want) {
			return false
		}
	}
	return true
}

// problems compares every step field by field.
func (e *expected) problems(steps []StepResult) []Problem {
	if len(steps) != len(e.results) {
		return []Problem{{Step: -1, Field: "steps", Expected: fmt.Sprintf("%d steps", len(e.results)),
			Actual: fmt.Sprintf("%d steps", len(steps))}}
	}
	var problems []Problem
	for i := range steps {
		want := e.state(i)
		if r := e.results[i]; r != NoResult && steps[i].Result != r {
			problems = append(problems, Problem{Step: i, Field: "result", Expected: r.String(), Actual: steps[i].Result.String()})
		}
		if vals := steps[i].Values; vals != nil && len(steps[i].Devices) == 0 && len(vals) == len(e.names) {
			// The fast form, aligned with the request's devices, which are all the vector's.
			if e.skips && sameCompared(vals, want, e.compared) || !e.skips && slices.Equal(vals, want) {
				continue
			}
		}
		if vals := steps[i].Values; vals != nil && len(vals) != len(e.requested) {
			problems = append(problems, Problem{Step: i, Field: "values", Expected: fmt.Sprintf("%d values, one per device of the request", len(e.requested)),
				Actual: fmt.Sprintf("%d values", len(vals))})
			continue
		}
		got := steps[i].image(e.requested)
		// Fast path: the image in the request's order, every compared value equal (Value's ==
		// compares the JSON type too). Most vectors pass, and this is where a run spends its time.
		if len(got) == len(e.names) {
			same := true
			for j := range got {
				if got[j].Name != e.names[j] || (e.compared[j] && got[j].Value != want[j]) {
					same = false
					break
				}
			}
			if same {
				continue
			}
		}
		problems = append(problems, e.deviceProblems(i, got, steps)...)
	}
	return problems
}

// held is what the implementation held of device j before step k: for step 0 what the vector
// gave it, for a later step its own report of the step before, with this step's `set` over it.
func (e *expected) held(k, j int, steps []StepResult, prev map[string]Value) string {
	name := e.names[j]
	if _, set := e.sets[k][name]; k == 0 || set {
		return show(e.before(k)[j])
	}
	if v, ok := prev[name]; ok {
		return v.String()
	}
	return notReported
}

// sameCompared reports whether got and want hold the same value wherever compared says so.
func sameCompared(got, want []Value, compared []bool) bool {
	for j := range got {
		if compared[j] && got[j] != want[j] {
			return false
		}
	}
	return true
}

// deviceProblems compares one step's image device by device, in name order.
func (e *expected) deviceProblems(step int, got []Device, steps []StepResult) []Problem {
	want, before := e.state(step), e.before(step)
	var prev map[string]Value // the implementation's report of the step before, made on demand
	line := func(j int, actual string) Problem {
		if step > 0 && prev == nil {
			prev = map[string]Value{}
			for _, d := range steps[step-1].image(e.requested) {
				prev[d.Name] = d.Value
			}
		}
		w, b := show(want[j]), ""
		if before[j] != absent {
			b = before[j].String()
		}
		return Problem{Step: step, Field: e.names[j], Expected: w, Actual: actual, Before: b,
			Suffix: suffix(e.held(step, j, steps, prev), w, actual, want[j] == before[j])}
	}
	reported := make(map[string]Value, len(got))
	var problems []Problem
	for _, d := range got {
		if _, dup := reported[d.Name]; dup {
			problems = append(problems, Problem{Step: step, Field: d.Name, Expected: "one value",
				Actual: "the device reported twice"})
		}
		reported[d.Name] = d.Value
	}
	listed := make(map[string]bool, len(e.names))
	for j, name := range e.names {
		listed[name] = true
		if !e.compared[j] {
			continue
		}
		have, ok := reported[name]
		w := want[j]
		switch {
		case !ok && w == absent:
		case !ok:
			problems = append(problems, line(j, notReported))
		case have != w:
			problems = append(problems, line(j, have.String()))
		}
	}
	var outside []string
	for name := range reported {
		if !listed[name] && !e.cpuWrites[name] {
			outside = append(outside, name)
		}
	}
	sort.Strings(outside)
	for _, name := range outside {
		problems = append(problems, Problem{Step: step, Field: name, Expected: notListed, Actual: reported[name].String()})
	}
	sort.SliceStable(problems, func(a, b int) bool { return problems[a].Field < problems[b].Field })
	return problems
}
