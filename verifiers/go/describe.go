package plcvec

import (
	"fmt"
	"sort"
	"strconv"
	"strings"
)

// The failure block of a vector (verifiers/parity/TEXT.md, "The failure block"), byte for byte what
// `plcvec verify` prints: the id, what the vector is about, the interpretations that decide a
// differing field, the devices the followed alternatives leave unjudged, each step's inputs and
// operand words before its differences, the differences, the message and the spec clauses.
// verifiers/parity/text/ holds the cases a test compares against.

const indent = "    "

// judgedBy lists the interpretations that decide a differing field of the verdict: those for
// which the vector offers a combination that differs from the followed one in that
// interpretation only and differs from it at a field that differs.
func (v *Verdict) judgedBy() []string {
	c := v.judgedCase()
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
// is about, the interpretations that decide a differing field, the devices the followed
// alternatives leave unjudged, each step's inputs and operand words before its differences, the
// differences, the message and the spec clauses.
func (v *Verdict) Text() string {
	var b strings.Builder
	fmt.Fprintf(&b, "%s %s\n", strings.ToUpper(string(v.Status)), v.ID)
	if v.Vector != nil && v.Vector.Description != "" {
		fmt.Fprintf(&b, "%s%s: %s\n", indent, v.Instruction, v.Vector.Description)
	}
	if judged := v.judgedBy(); len(judged) > 0 {
		fmt.Fprintf(&b, "%sjudged by: %s\n", indent, strings.Join(judged, ", "))
	}
	c := v.judgedCase()
	if c != nil {
		for _, line := range c.notJudgedLines() {
			fmt.Fprintf(&b, "%s%s\n", indent, line)
		}
	}
	shown := -1
	for i, p := range v.Problems {
		if i == maxProblems {
			fmt.Fprintf(&b, "%s... and %d more differences\n", indent, len(v.Problems)-maxProblems)
			break
		}
		if p.Step >= 0 && p.Step != shown && c != nil && c.expect != nil && p.Step < len(v.Vector.Steps) {
			shown = p.Step
			fmt.Fprintf(&b, "%sstep %d inputs: %s\n", indent, p.Step, v.Vector.inputsText(p.Step))
			fmt.Fprintf(&b, "%sstep %d operands: %s\n", indent, p.Step, operandsText(v.Vector, c.expect, p.Step))
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

// notJudgedLines are the block's `not judged under` lines (verifiers/parity/unjudged rule, TEXT.md):
// one per interpretation whose followed alternative leaves devices of the vector unjudged, sorted
// by id, each with its devices sorted. A vector whose instruction the implementation does not run
// has no expectation built, so its entry is looked up here.
func (c *Case) notJudgedLines() []string {
	var unjudged map[string][]string
	var choices map[string]string
	switch {
	case c.expect != nil:
		unjudged, choices = c.expect.unjudged, c.expect.choices
	case c.plan != nil && len(c.Vector.Alternatives) > 0:
		en, err := entryOf(c.Vector, c.plan.Choices)
		if err != nil {
			return nil
		}
		unjudged, choices = en.unjudged, en.choices
	}
	ids := sortedKeysOf(unjudged)
	lines := make([]string, len(ids))
	for i, id := range ids {
		devices := append([]string(nil), unjudged[id]...)
		sort.Strings(devices)
		lines[i] = "not judged under " + id + "=" + choices[id] + ": " + strings.Join(devices, ", ")
	}
	return lines
}

// operandsText is every operand of v with its words in the state before step k under e.
func operandsText(v *Vector, e *expected, k int) string {
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
