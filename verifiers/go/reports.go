package plcvec

import (
	"fmt"
	"sort"
	"strings"
)

// Summary is the run's text as every plcvec runner prints it (verifiers/parity/TEXT.md): the
// failure block of each failing vector, the roll-up by reading, the skips by reason, then what
// was run against what and the totals.
func (r *Report) Summary() string {
	var b strings.Builder
	for i := range r.Verdicts {
		if r.Verdicts[i].Status.Failing() {
			b.WriteString(r.Verdicts[i].Text())
		}
	}
	b.WriteString(r.Closing())
	return b.String()
}

// Closing is what follows the failure blocks: the roll-up by reading, the skips by reason, an
// empty line, the header and the totals. Run logs it at the end of the test, each failure
// having been reported by its own subtest.
func (r *Report) Closing() string {
	gate := ""
	if len(r.Failed()) == 0 && r.shortfall() != "" {
		gate = "NOT PASSED: " + r.shortfall() + "\n"
	}
	return r.RollUp() + r.Skips() + gate + "\n" + r.Plan.Header() + r.Totals()
}

// Totals is the line of counts that ends a run's report: pass, fail and skip always, the
// others when not 0, then the run's seconds.
func (r *Report) Totals() string {
	c := r.Counts()
	var b strings.Builder
	fmt.Fprintf(&b, "%d vectors: %d pass, %d fail", len(r.Verdicts), c[StatusPass], c[StatusFail])
	if c[StatusError] > 0 {
		fmt.Fprintf(&b, ", %d error", c[StatusError])
	}
	fmt.Fprintf(&b, ", %d skip", c[StatusSkip])
	for _, s := range []Status{StatusXFail, StatusStale, StatusNotRun} {
		if c[s] > 0 {
			fmt.Fprintf(&b, ", %d %s", c[s], s)
		}
	}
	fmt.Fprintf(&b, " in %.2f s\n", r.Seconds)
	return b.String()
}

// Header says what a run judged against: the implementation, the suite version, the spec
// hash and the alternative followed for every interpretation.
func (p *Plan) Header() string {
	name := p.Hello.Name
	if name == "" {
		name = "(unnamed implementation)"
	}
	if p.Hello.Version != "" {
		name += " " + p.Hello.Version
	}
	hash := p.Suite.SpecSHA256
	if len(hash) > 12 {
		hash = hash[:12]
	}
	text := fmt.Sprintf("plcvec: %s against %s (suite %s, schema %s, spec sha256 %s)\ninterpretations: %s\n",
		name, p.Suite.Source, p.Suite.SuiteVersion, p.Suite.SchemaVersion, hash, p.Interpretations())
	if len(p.Hello.CPUWrites) > 0 {
		devices := append([]string(nil), p.Hello.CPUWrites...)
		sort.Strings(devices)
		text += "cpu_writes: " + strings.Join(devices, ", ") + "\n"
	}
	return text
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

// Interpretations is a line naming the alternative followed for every interpretation of the
// families run, declared or default: a result means nothing without it.
func (p *Plan) Interpretations() string {
	families := map[string]bool{}
	for _, c := range p.Cases {
		families[c.family] = true
	}
	var parts []string
	for _, i := range p.Suite.Interpretations() {
		run := false
		for _, f := range i.Families {
			run = run || families[f]
		}
		if !run {
			continue
		}
		c := p.Choices[i.ID]
		how := " (default)"
		if c.Declared {
			how = " (declared)"
		}
		parts = append(parts, i.ID+"="+c.Alternative+how)
	}
	if len(parts) == 0 {
		return "(none)"
	}
	return strings.Join(parts, ", ")
}
