package plcvec

import (
	"sort"
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
		choices := make(Followed, len(touched))
		for _, id := range touched {
			def := c.plan.Choices[id].Default
			choices[id] = Choice{Alternative: alts[id], Default: def}
		}
		e, err := expectedOf(&arena{}, v, choices, c.expect.requested, c.expect.cpuWrites)
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

// differsAt reports whether the offered expectation o differs from the followed one at step k in
// field: another contact result, another value or JSON type, or the field left unjudged.
func differsAt(o, followed *expected, k int, field string) bool {
	if field == "result" {
		return o.results[k] != followed.results[k]
	}
	return !o.judges(field) || o.valueAt(k, field) != followed.valueAt(k, field)
}

func (e *expected) valueAt(k int, name string) Value {
	i := sort.SearchStrings(e.names, name)
	if i < len(e.names) && e.names[i] == name {
		return e.state(k)[i]
	}
	return absent
}

// sameJudged reports whether a passing answer passes under the offered expectation o: at every
// step the same contact result, and every device o judges expected alike (value and JSON type)
// under o and under the followed expectation, which must judge it too: an answer the followed
// expectation did not judge is not known to match (the unjudged rule).
func sameJudged(o, followed *expected) bool {
	if o == nil || followed == nil || len(o.results) != len(followed.results) {
		return false
	}
	for k := range o.results {
		if o.results[k] != followed.results[k] {
			return false
		}
		for _, names := range [2][]string{o.names, followed.names} {
			for _, n := range names {
				if o.judges(n) && (!followed.judges(n) || o.valueAt(k, n) != followed.valueAt(k, n)) {
					return false
				}
			}
		}
	}
	return true
}

// judged is a vector whose answer the inference judges: one that passed, or one that failed
// (a known failure that failed too), with whether its answer passes under each offer.
type judged struct {
	c      *Case
	passed bool
	passes []bool
}

// passesUnder reports whether j's answer passes under choice (restricted to what j touches).
func (j judged) passesUnder(choice map[string]string) bool {
	if len(j.c.Vector.Outcome.Interpretations) == 0 {
		return j.passed
	}
	idx := j.c.offerIndex(choice)
	if idx < 0 {
		return false
	}
	if j.passed {
		return sameJudged(j.c.offers()[idx].expect, j.c.expect)
	}
	return idx < len(j.passes) && j.passes[idx]
}

// readings is the inference of a run (TEXT.md, "The inference"): the choice, and which failing
// vectors (fail, error, not-run) and known failures (xfail) it explains, each by its smallest
// change ("ID=alternative" items in ID order), by verdict index.
type readings struct {
	choice           map[string]string
	failing, known   []int
	explained        map[int][]string
	unexplained      []int
	knownExplained   map[int][]string
	knownUnexplained []int
	broken           []string // the family of each vector that passes now and would fail under the choice
}

// infer finds the alternatives the implementation's answers match.
func (r *Report) infer() readings {
	js, rd := r.judgedVectors()
	if len(rd.failing) == 0 && len(rd.known) == 0 {
		return rd
	}
	rd.choice = r.Plan.choose(js)
	byCase := make(map[*Case]judged, len(js))
	for _, j := range js {
		byCase[j.c] = j
		if j.passed && !j.passesUnder(rd.choice) {
			rd.broken = append(rd.broken, j.c.family)
		}
	}
	explain := func(i int, explained map[int][]string, unexplained *[]int) {
		j, ok := byCase[r.Verdicts[i].judgedCase()]
		if !ok || !j.passesUnder(rd.choice) {
			*unexplained = append(*unexplained, i)
			return
		}
		explained[i] = smallestChange(j.c, rd.choice, j.passesUnder)
	}
	rd.explained, rd.knownExplained = map[int][]string{}, map[int][]string{}
	for _, i := range rd.failing {
		explain(i, rd.explained, &rd.unexplained)
	}
	for _, i := range rd.known {
		explain(i, rd.knownExplained, &rd.knownUnexplained)
	}
	return rd
}

// judgedVectors are the run's judged vectors (steps 2 and 3), with its failing vectors and
// known failures by verdict index.
func (r *Report) judgedVectors() ([]judged, readings) {
	var js []judged
	var rd readings
	for i := range r.Verdicts {
		v := &r.Verdicts[i]
		if v.about == nil {
			if c := r.caseOf(v.ID); c != nil {
				v.about = c.about
			}
		}
		c := v.judgedCase()
		if c == nil {
			continue
		}
		switch v.Status {
		case StatusFail, StatusError, StatusNotRun:
			rd.failing = append(rd.failing, i)
		case StatusXFail:
			rd.known = append(rd.known, i)
		}
		// A known failure is judged when its answer failed (not when its vector errored).
		if v.Status == StatusPass || v.Status == StatusFail || v.Status == StatusXFail && v.answerFailed() {
			js = append(js, judged{c, v.Status == StatusPass, v.passes()})
		}
	}
	return js, rd
}

// choose is the choice of step 4: from the followed alternatives, each interpretation in ID
// order moved to the first alternative (in the files' order) that makes strictly more of the
// judged vectors that touch it pass, round after round until none moves. The rounds run twice:
// first without the alternatives that leave devices unjudged, then, from where the first run
// ended, with every alternative: a reading that judges nothing of a device explains any answer
// there, so it is taken only for what no reading that judges explains.
func (p *Plan) choose(js []judged) map[string]string {
	choice := make(map[string]string, len(p.Choices))
	for id, c := range p.Choices {
		choice[id] = c.Alternative
	}
	unjudging := p.Suite.unjudgingAlternatives()
	judging := func(id, alt string) bool { return !unjudging[id+"="+alt] }
	p.search(js, choice, judging)
	if len(unjudging) > 0 {
		p.search(js, choice, func(string, string) bool { return true })
	}
	return choice
}

// search moves choice as step 4 says, trying only the alternatives allowed. Only an
// interpretation some failed answer touches can move (a passing answer passes under the followed
// alternatives), so only those are tried.
func (p *Plan) search(js []judged, choice map[string]string, allowed func(id, alt string) bool) {
	touched := map[string]bool{}
	for _, j := range js {
		for _, id := range j.c.Vector.Outcome.Interpretations {
			touched[id] = touched[id] || !j.passed
		}
	}
	var ids []string
	for id, failed := range touched {
		if failed {
			ids = append(ids, id)
		}
	}
	sort.Strings(ids)
	score := func(id string) int {
		n := 0
		for _, j := range js {
			if contains(j.c.Vector.Outcome.Interpretations, id) && j.passesUnder(choice) {
				n++
			}
		}
		return n
	}
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
				if alt == current || !allowed(id, alt) {
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

// smallestChange is step 6: the first set of the interpretations whose chosen alternative
// differs from the followed one, by size then in lexicographic order (as itertools.combinations
// gives them), under which the vector passes, as "ID=alternative" items.
func smallestChange(c *Case, choice map[string]string, passes func(map[string]string) bool) []string {
	followed := c.followed()
	var differ []string
	for _, id := range c.Vector.Outcome.Interpretations {
		if choice[id] != followed[id] {
			differ = append(differ, id)
		}
	}
	sort.Strings(differ)
	for size := 1; size <= len(differ); size++ {
		for idx := firstCombination(size); idx != nil; idx = nextCombination(idx, len(differ)) {
			trial := make(map[string]string, len(followed))
			for k, v := range followed {
				trial[k] = v
			}
			parts := make([]string, len(idx))
			for n, i := range idx {
				trial[differ[i]] = choice[differ[i]]
				parts[n] = differ[i] + "=" + choice[differ[i]]
			}
			if passes(trial) {
				return parts
			}
		}
	}
	parts := make([]string, len(differ))
	for n, id := range differ {
		parts[n] = id + "=" + choice[id]
	}
	return parts
}

// firstCombination is the first choice of size indexes: 0, 1, ..., size-1.
func firstCombination(size int) []int {
	idx := make([]int, size)
	for i := range idx {
		idx[i] = i
	}
	return idx
}

// nextCombination is the choice of len(idx) indexes out of n after idx in lexicographic order,
// or nil after the last.
func nextCombination(idx []int, n int) []int {
	size := len(idx)
	i := size - 1
	for i >= 0 && idx[i] == n-size+i {
		i--
	}
	if i < 0 {
		return nil
	}
	idx[i]++
	for j := i + 1; j < size; j++ {
		idx[j] = idx[j-1] + 1
	}
	return idx
}
