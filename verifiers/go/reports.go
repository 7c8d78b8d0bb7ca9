package plcvec

import (
	"fmt"
	"strings"
)

// Summary is the report as a person reads it at the end of a run: each failing vector with its
// diff, then what was run against what, and the totals.
func (r *Report) Summary() string {
	var b strings.Builder
	for i := range r.Verdicts {
		if r.Verdicts[i].Status.Failing() {
			b.WriteString(r.Verdicts[i].Text())
		}
	}
	b.WriteString(r.Plan.Header())
	b.WriteString(r.Totals())
	return b.String()
}

// Totals is the line of counts that ends a run's report.
func (r *Report) Totals() string {
	c := r.Counts()
	var b strings.Builder
	fmt.Fprintf(&b, "%d vectors: %d pass, %d fail", len(r.Verdicts), c[StatusPass], c[StatusFail])
	for _, s := range []Status{StatusError, StatusSkip, StatusXFail, StatusStale, StatusNotRun} {
		if c[s] > 0 {
			fmt.Fprintf(&b, ", %d %s", c[s], s)
		}
	}
	b.WriteString("\n")
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
		text += "cpu writes: " + strings.Join(p.Hello.CPUWrites, ", ") + "\n"
	}
	return text
}
