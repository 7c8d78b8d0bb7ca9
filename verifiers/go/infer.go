package plcvec

import (
	"sort"
	"strings"
)

// The inference (verifiers/parity/TEXT.md, "The inference"): the combinations of alternatives
// each vector offers, where each judged answer passes, the choice of alternatives that explains
// the most, and the smallest change that explains each failure. It uses nothing but the vectors
// and the answers of one run.

// offer is one combination of alternatives a vector offers an expectation for: its defaults
// (the vector's own steps), then each entry of its `alternatives`.
type offer struct {
	choices map[string]string // the interpretations the vector touches -> alternative
	expect  *expected
}

// offers are the combinations case c offers, worked out once, on demand (a failing vector, or
// the inference over a run).
func (c *Case) offers() []offer {
	if c.plan == nil {
		return nil
	}
	if o, ok := c.plan.offered[c]; ok {
		return o
	}
	v := c.Vector
	touched := v.Outcome.Interpretations
	build := func(alts map[string]string) *expected {
		choices := make(map[string]Choice, len(touched))
		for _, id := range touched {
			def := c.plan.Choices[id].Default
			choices[id] = Choice{Alternative: alts[id], Default: def}
		}
		e, err := expectationOf(&arena{}, v, choices, c.expect.requested, c.expect.cpuWrites)
		if err != nil {
			return nil
		}
		return e
	}
	defaults := map[string]string{}
	for _, id := range touched {
		defaults[id] = c.plan.Choices[id].Default
	}
	out := []offer{{defaults, build(defaults)}}
	for _, alt := range v.Alternatives {
		choices, complete := map[string]string{}, true
		for _, id := range touched {
			a, ok := alt.Choices[id]
			complete = complete && ok
			choices[id] = a
		}
		if complete {
			out = append(out, offer{choices, build(choices)})
		}
	}
	if c.plan.offered == nil {
		c.plan.offered = map[*Case][]offer{}
	}
	c.plan.offered[c] = out
	return out
}

// followed is the combination the run followed, restricted to the interpretations c touches.
func (c *Case) followed() map[string]string {
	out := map[string]string{}
	for _, id := range c.Vector.Outcome.Interpretations {
		out[id] = c.plan.Choices[id].Alternative
	}
	return out
}

// offerIndex is the index of the offer with exactly these choices (restricted to the
// interpretations c touches), or -1.
func (c *Case) offerIndex(choices map[string]string) int {
	for i, o := range c.offers() {
		same := true
		for id, alt := range o.choices {
			if choices[id] != alt {
				same = false
				break
			}
		}
		if same {
			return i
		}
	}
	return -1
}

// passesUnder says, for a failing answer, under which offers it would pass.
func (c *Case) passesUnder(steps []StepResult) []bool {
	if len(c.Vector.Outcome.Interpretations) == 0 {
		return nil
	}
	offers := c.offers()
	out := make([]bool, len(offers))
	for i, o := range offers {
		out[i] = o.expect != nil && o.expect.compare(steps) == nil
	}
	return out
}

// differsAt reports whether two expectations of one vector differ at step k in field.
func differsAt(a, b *expected, k int, field string) bool {
	if field == "result" {
		return a.results[k] != b.results[k]
	}
	return a.valueAt(k, field) != b.valueAt(k, field)
}

func (e *expected) valueAt(k int, name string) Value {
	i := sort.SearchStrings(e.names, name)
	if i < len(e.names) && e.names[i] == name {
		return e.state(k)[i]
	}
	return absent
}

// sameExpectation reports whether two expectations of one vector expect the same of every step.
func sameExpectation(a, b *expected) bool {
	if a == nil || b == nil || len(a.results) != len(b.results) {
		return false
	}
	for k := range a.results {
		if a.results[k] != b.results[k] {
			return false
		}
		for _, n := range a.names {
			if a.valueAt(k, n) != b.valueAt(k, n) {
				return false
			}
		}
		for _, n := range b.names {
			if a.valueAt(k, n) != b.valueAt(k, n) {
				return false
			}
		}
	}
	return true
}

// readings is the inference of a run (TEXT.md, "The inference").
type readings struct {
	choice      map[string]string
	explained   map[int]string // verdict index -> its smallest change
	failing     []int
	broken      int
	unexplained []int
}

// infer finds the alternatives the implementation's answers match.
func (r *Report) infer() readings {
	p := r.Plan
	type judged struct {
		c      *Case
		passed bool
		passes []bool // per offer, for a failed vector
	}
	var js []judged
	var failing []int
	touched := map[string]bool{}
	for i := range r.Verdicts {
		v := &r.Verdicts[i]
		if v.c == nil {
			v.c = r.caseOf(v.ID)
		}
		if v.c == nil {
			continue
		}
		if v.Status == StatusFail || v.Status == StatusError || v.Status == StatusNotRun {
			failing = append(failing, i)
		}
		failed := v.Status == StatusFail || v.Status == StatusXFail && v.failed != nil
		if v.Status != StatusPass && !failed {
			continue
		}
		js = append(js, judged{v.c, v.Status == StatusPass, v.passes()})
		for _, id := range v.c.Vector.Outcome.Interpretations {
			touched[id] = true
		}
	}
	choice := map[string]string{}
	for id, c := range p.Choices {
		choice[id] = c.Alternative
	}
	passUnder := func(j judged, choice map[string]string) bool {
		if len(j.c.Vector.Outcome.Interpretations) == 0 {
			return j.passed
		}
		idx := j.c.offerIndex(choice)
		if idx < 0 {
			return false
		}
		if j.passed {
			return sameExpectation(j.c.offers()[idx].expect, j.c.expect)
		}
		return idx < len(j.passes) && j.passes[idx]
	}
	score := func(id string) int {
		n := 0
		for _, j := range js {
			if contains(j.c.Vector.Outcome.Interpretations, id) && passUnder(j, choice) {
				n++
			}
		}
		return n
	}
	ids := make([]string, 0, len(touched))
	for id := range touched {
		ids = append(ids, id)
	}
	sort.Strings(ids)
	alternatives := map[string][]string{}
	for _, i := range p.Suite.Interpretations() {
		alternatives[i.ID] = i.Alternatives
	}
	for changed := true; changed; {
		changed = false
		for _, id := range ids {
			current := choice[id]
			best, bestAlt := score(id), current
			for _, alt := range alternatives[id] {
				if alt == current {
					continue
				}
				choice[id] = alt
				if s := score(id); s > best {
					best, bestAlt = s, alt
				}
			}
			choice[id] = bestAlt
			changed = changed || bestAlt != current
		}
	}
	out := readings{choice: choice, explained: map[int]string{}, failing: failing}
	byCase := map[*Case]judged{}
	for _, j := range js {
		byCase[j.c] = j
		if j.passed && !passUnder(j, choice) {
			out.broken++
		}
	}
	for _, i := range failing {
		v := &r.Verdicts[i]
		j, ok := byCase[v.c]
		if !ok || !passUnder(j, choice) {
			out.unexplained = append(out.unexplained, i)
			continue
		}
		out.explained[i] = smallestChange(j.c, choice, func(m map[string]string) bool { return passUnder(j, m) })
	}
	return out
}

// caseOf is the case of a vector id in the report's plan (nil for a stale id).
func (r *Report) caseOf(id string) *Case {
	if r.Plan == nil {
		return nil
	}
	if r.Plan.byID == nil {
		r.Plan.byID = make(map[string]*Case, len(r.Plan.Cases))
		for _, c := range r.Plan.Cases {
			r.Plan.byID[c.id] = c
		}
	}
	return r.Plan.byID[id]
}

// smallestChange is the first set of changes, by size then in order, under which the vector
// passes: "ID=alt, ID=alt".
func smallestChange(c *Case, choice map[string]string, passes func(map[string]string) bool) string {
	followed := c.followed()
	var differ []string
	for _, id := range c.Vector.Outcome.Interpretations {
		if choice[id] != followed[id] {
			differ = append(differ, id)
		}
	}
	sort.Strings(differ)
	for size := 1; size <= len(differ); size++ {
		idx := make([]int, size)
		for i := range idx {
			idx[i] = i
		}
		for {
			trial := map[string]string{}
			for k, v := range followed {
				trial[k] = v
			}
			var parts []string
			for _, i := range idx {
				trial[differ[i]] = choice[differ[i]]
				parts = append(parts, differ[i]+"="+choice[differ[i]])
			}
			if passes(trial) {
				return strings.Join(parts, ", ")
			}
			// the next combination in lexicographic order
			i := size - 1
			for i >= 0 && idx[i] == len(differ)-size+i {
				i--
			}
			if i < 0 {
				break
			}
			idx[i]++
			for j := i + 1; j < size; j++ {
				idx[j] = idx[j-1] + 1
			}
		}
	}
	var parts []string
	for _, id := range differ {
		parts = append(parts, id+"="+choice[id])
	}
	return strings.Join(parts, ", ")
}
