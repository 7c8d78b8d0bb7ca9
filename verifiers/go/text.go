package plcvec

import (
	"fmt"
	"sort"
	"strconv"
	"strings"
)

// The one failure text of every plcvec runner (verifiers/parity/TEXT.md): the failure block of a
// vector, the roll-up by reading, the skips by reason and the summary lines, byte for byte what
// `plcvec verify` prints. verifiers/parity/text/ holds the cases a test compares against.

const indent = "    "

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

// judgedBy lists the interpretations that decide a differing field of the verdict: those for
// which the vector offers a combination that differs from the followed one in that
// interpretation only and differs from it at a field that differs.
func (v *Verdict) judgedBy() []string {
	c := v.c
	if c == nil || c.plan == nil || c.expect == nil || len(v.Problems) == 0 {
		return nil
	}
	followed := c.followed()
	var out []string
	for _, id := range c.Vector.Outcome.Interpretations {
		decides := false
		for _, o := range c.offers() {
			if o.expect == nil || o.choices[id] == followed[id] {
				continue
			}
			only := true
			for other, alt := range o.choices {
				if other != id && alt != followed[other] {
					only = false
				}
			}
			if !only {
				continue
			}
			for _, p := range v.Problems {
				if p.Step >= 0 && p.Step < len(o.expect.results) && differsAt(o.expect, c.expect, p.Step, p.Field) {
					decides = true
				}
			}
		}
		if decides {
			out = append(out, id+"="+followed[id])
		}
	}
	sort.Strings(out)
	return out
}

// Text is the verdict's failure block (TEXT.md, "The failure block"): the id, what the vector
// is about, the interpretations that decide a differing field, each step's inputs and operand
// words before its differences, the differences, the message and the spec clauses.
func (v *Verdict) Text() string {
	var b strings.Builder
	fmt.Fprintf(&b, "%s %s\n", strings.ToUpper(string(v.Status)), v.ID)
	if v.Vector != nil && v.Vector.Description != "" {
		fmt.Fprintf(&b, "%s%s: %s\n", indent, v.Instruction, v.Vector.Description)
	}
	if judged := v.judgedBy(); len(judged) > 0 {
		fmt.Fprintf(&b, "%sjudged by: %s\n", indent, strings.Join(judged, ", "))
	}
	shown := -1
	for i, p := range v.Problems {
		if i == maxProblems {
			fmt.Fprintf(&b, "%s... and %d more differences\n", indent, len(v.Problems)-maxProblems)
			break
		}
		if p.Step >= 0 && p.Step != shown && v.c != nil && v.c.expect != nil && p.Step < len(v.Vector.Steps) {
			shown = p.Step
			fmt.Fprintf(&b, "%sstep %d inputs: %s\n", indent, p.Step, v.Vector.inputsText(p.Step))
			fmt.Fprintf(&b, "%sstep %d operands: %s\n", indent, p.Step, v.c.expect.operandsText(p.Step))
		}
		fmt.Fprintf(&b, "%s%s\n", indent, p)
	}
	if v.Message != "" {
		fmt.Fprintf(&b, "%s%s\n", indent, strings.ReplaceAll(v.Message, "\n", "\n"+indent))
	}
	if v.Vector != nil && len(v.Vector.Clauses) > 0 {
		fmt.Fprintf(&b, "%sspec clauses: %s\n", indent, strings.Join(v.Vector.Clauses, ", "))
	}
	return b.String()
}

// inputsText is step k's inputs as a failure shows them: clock, rlo_in, en, input, elapsed_ms,
// then `set`.
func (v *Vector) inputsText(k int) string {
	st := &v.Steps[k]
	var parts []string
	if len(st.Clock) > 0 {
		parts = append(parts, "clock="+clockText(st.Clock))
	}
	if st.given&givesRLOIn != 0 {
		parts = append(parts, "rlo_in="+strconv.FormatBool(st.RLOIn))
	}
	if st.given&givesEN != 0 {
		parts = append(parts, "en="+strconv.FormatBool(st.EN))
	}
	if st.given&givesInput != 0 {
		parts = append(parts, "input="+strconv.FormatBool(st.Input))
	}
	if st.given&givesElapsed != 0 {
		parts = append(parts, "elapsed_ms="+strconv.FormatInt(st.ElapsedMS, 10))
	}
	text := strings.Join(parts, ", ")
	if len(st.Set) > 0 {
		names := make([]string, 0, len(st.Set))
		for n := range st.Set {
			names = append(names, n)
		}
		sort.Strings(names)
		for i, n := range names {
			names[i] = n + "=" + st.Set[n].String()
		}
		if text != "" {
			text += ", "
		}
		text += "set " + strings.Join(names, " ")
	}
	if text == "" {
		return "(none)"
	}
	return text
}

// clockText is a clock as a date, a time, or both: 2029/6/17 14:51:39.
func clockText(clock map[string]int) string {
	var date, tm, rest []string
	for _, f := range []string{"year", "month", "day"} {
		if n, ok := clock[f]; ok {
			date = append(date, strconv.Itoa(n))
		}
	}
	for _, f := range []string{"hour", "minute", "second"} {
		if n, ok := clock[f]; ok && len(tm) > 0 { // every field after the first: two digits
			tm = append(tm, fmt.Sprintf("%02d", n))
		} else if ok {
			tm = append(tm, strconv.Itoa(n))
		}
	}
	var others []string
	for f := range clock {
		switch f {
		case "year", "month", "day", "hour", "minute", "second":
		default:
			others = append(others, f)
		}
	}
	sort.Strings(others)
	for _, f := range others {
		rest = append(rest, " "+f+"="+strconv.Itoa(clock[f]))
	}
	text := strings.Join(date, "/")
	if len(tm) > 0 {
		if text != "" {
			text += " "
		}
		text += strings.Join(tm, ":")
	}
	return text + strings.Join(rest, "")
}

// operandsText is every operand with its words in the vector's state before step k.
func (e *expected) operandsText(k int) string {
	v := e.vector
	names := make([]string, 0, len(v.Initial.Operands))
	devices := map[string]bool{}
	for n, op := range v.Initial.Operands {
		names = append(names, n)
		if op.Device != "" {
			devices[op.Device] = true
		}
	}
	sort.Strings(names)
	scratch := map[string]bool{}
	for _, s := range v.Initial.Scratch {
		scratch[s] = true
	}
	before := e.before(k)
	at := func(name string) (Value, bool) {
		i := sort.SearchStrings(e.names, name)
		if i < len(e.names) && e.names[i] == name && before[i] != absent && !scratch[name] {
			return before[i], true
		}
		return 0, false
	}
	parts := make([]string, len(names))
	for i, n := range names {
		op := v.Initial.Operands[n]
		switch val, ok := at(op.Device); {
		case op.Constant != nil:
			parts[i] = n + " constant " + strconv.Itoa(*op.Constant)
		case scratch[op.Device]:
			parts[i] = n + " " + op.Device + " (scratch)"
		case !ok:
			parts[i] = n + " " + op.Device + " (not in the vector)"
		case val.IsBit():
			parts[i] = n + " " + op.Device + "=" + val.String()
		default:
			words := []string{val.String()}
			for next := nextAddress(op.Device); next != ""; next = nextAddress(next) {
				w, ok := at(next)
				if !ok || w.IsBit() || devices[next] {
					break
				}
				words = append(words, w.String())
			}
			parts[i] = n + " " + op.Device + "=" + strings.Join(words, " ")
		}
	}
	return strings.Join(parts, ", ")
}

// nextAddress is the device after name (D199 -> D200), or "" for a name of another form.
func nextAddress(name string) string {
	i := len(name)
	for i > 0 && name[i-1] >= '0' && name[i-1] <= '9' {
		i--
	}
	if i == len(name) || i == 0 {
		return ""
	}
	for _, r := range name[:i] {
		if !(r >= 'A' && r <= 'Z' || r >= 'a' && r <= 'z' || r == '_') {
			return ""
		}
	}
	n, err := strconv.Atoi(name[i:])
	if err != nil {
		return ""
	}
	return name[:i] + strconv.Itoa(n+1)
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

type group struct {
	n     int
	text  string
	items []string
}

func sortGroups(groups map[string]*group) []*group {
	out := make([]*group, 0, len(groups))
	for _, g := range groups {
		out = append(out, g)
	}
	sort.Slice(out, func(a, b int) bool {
		if out[a].n != out[b].n {
			return out[a].n > out[b].n
		}
		return out[a].text < out[b].text
	})
	return out
}

// RollUp is the roll-up by reading (TEXT.md): the failing vectors another reading explains,
// grouped by the declaration that does it, then those no reading explains, by the clauses they
// cite. Empty when nothing failed.
func (r *Report) RollUp() string {
	rd := r.infer()
	if len(rd.failing) == 0 {
		return ""
	}
	var b strings.Builder
	if len(rd.explained) > 0 {
		fmt.Fprintf(&b, "READINGS: %d of %d failing vectors pass under other alternatives:\n", len(rd.explained), len(rd.failing))
		groups := map[string]*group{}
		for _, change := range rd.explained {
			if groups[change] == nil {
				groups[change] = &group{text: change}
			}
			groups[change].n++
		}
		for _, g := range sortGroups(groups) {
			fmt.Fprintf(&b, "%s%6d  %s\n", indent, g.n, g.text)
		}
		var declare []string
		for id, alt := range rd.choice {
			if r.Plan.Choices[id].Alternative != alt {
				declare = append(declare, "--choose "+id+"="+alt)
			}
		}
		sort.Strings(declare)
		fmt.Fprintf(&b, "%sdeclare: %s\n", indent, strings.Join(declare, " "))
		if rd.broken > 0 {
			fmt.Fprintf(&b, "%s(so declared, %d vectors that pass now would fail)\n", indent, rd.broken)
		}
	}
	if len(rd.unexplained) > 0 {
		fmt.Fprintf(&b, "NOT EXPLAINED by any reading: %d failing vectors, by the clauses they cite:\n", len(rd.unexplained))
		groups := map[string]*group{}
		for _, i := range rd.unexplained {
			v := &r.Verdicts[i]
			text := "(no clauses)"
			if v.Vector != nil && len(v.Vector.Clauses) > 0 {
				text = strings.Join(v.Vector.Clauses, ", ")
			}
			if groups[text] == nil {
				groups[text] = &group{text: text}
			}
			groups[text].n++
			groups[text].items = append(groups[text].items, v.ID)
		}
		for _, g := range sortGroups(groups) {
			fmt.Fprintf(&b, "%s%6d  %s\n", indent, g.n, g.text)
			sort.Strings(g.items)
			for k, id := range g.items {
				if k == 5 {
					fmt.Fprintf(&b, "%s      %s... and %d more\n", indent, "  ", len(g.items)-5)
					break
				}
				fmt.Fprintf(&b, "%s        %s\n", indent, id)
			}
		}
	}
	return b.String()
}

// Skips is the skips by reason (TEXT.md), empty when nothing was skipped.
func (r *Report) Skips() string {
	groups := map[string]*group{}
	n, s := 0, 0
	for i := range r.Verdicts {
		v := &r.Verdicts[i]
		if v.Vector != nil {
			n++
		}
		if v.Status != StatusSkip {
			continue
		}
		s++
		reason := v.Message
		if reason == "" {
			reason = "(no reason given)"
		}
		if groups[reason] == nil {
			groups[reason] = &group{text: reason}
		}
		groups[reason].n++
	}
	if s == 0 {
		return ""
	}
	t := (2000*s + n) / (2 * n)
	var b strings.Builder
	fmt.Fprintf(&b, "SKIPPED %d of %d vectors (%d.%d%%):\n", s, n, t/10, t%10)
	sorted := sortGroups(groups)
	for k, g := range sorted {
		if k == maxProblems {
			fmt.Fprintf(&b, "%s... and %d more reasons (--jsonl lists each vector)\n", indent, len(sorted)-maxProblems)
			break
		}
		fmt.Fprintf(&b, "%s%6d  %s\n", indent, g.n, g.text)
	}
	return b.String()
}
