package plcvec

import (
	"fmt"
	"os"
	"runtime/debug"
	"strings"
	"time"
)

// Options tell a run what to verify.
type Options struct {
	// Suite to run; nil is Default(): $PLCVEC_VECTORS or the embedded copy.
	Suite *Suite
	// Selection of vectors; the zero value selects all. A selection that selects nothing is an
	// error: a gate never passes by accident.
	Selection Selection
	// Expectations is the path of a TOML file of known failures (CONTRACT.md); Run's default is
	// $PLCVEC_KNOWN_FAILURES. A listed vector that fails is xfail, one that passes is stale and
	// fails the run.
	Expectations string
	// InProcess makes Run judge the vectors in the test's own process rather than in a second
	// run of the test binary: for a debugger, or for the coverage of the implementation. Then a
	// vector that hangs still ends the run (reported on stderr), but an implementation that
	// ends the process is named only by `go test -v`'s `=== RUN` line.
	InProcess bool
	// env: the PLCVEC_* selection, which narrows Selection (Run sets it).
	env *environment
}

// Plan is a run prepared once: the selected vectors with their requests and their expectations
// under the implementation's alternatives. Verify prepares one; a benchmark keeps it and judges
// the same vectors again and again.
type Plan struct {
	Suite   *Suite
	Hello   Hello
	Choices Followed // every interpretation of the suite
	Cases   []*Case
	Known   *KnownFailures // nil without an expectations file
	// offered: the combinations each case's vector offers, worked out for the text on demand
	offered map[*Case][]offer
	byID    map[string]*Case // the cases by id, made on demand
	digest  string           // planDigest's, made on demand
}

// Case is one selected vector with its request and expectation.
type Case struct {
	Vector  *Vector
	Request *Request
	expect  *expected // nil when the implementation does not run the instruction
	// The vector's names as a verdict gives them, beside the rest of the case: a run reads
	// nothing else of the vector unless it fails.
	id, family, instruction string
	plan                    *Plan
	about                   *about // {c: this case}: what its verdicts but a failed answer point to (a pointer: Case stays comparable)
}

// Prepare builds the plan of a run of impl: handshake, selection, expectations.
func Prepare(impl Implementation, opts Options) (*Plan, error) {
	warnSettings(os.Stderr)
	suite := opts.Suite
	if suite == nil {
		var err error
		if suite, err = Default(); err != nil {
			return nil, err
		}
	}
	vectors, err := suite.Select(opts.Selection)
	if err != nil {
		return nil, err
	}
	if opts.env != nil {
		if vectors, err = suite.narrow(vectors, *opts.env); err != nil {
			return nil, err
		}
	}
	if len(vectors) == 0 {
		return nil, fmt.Errorf("the selection selects no vector of %s (%d vectors): nothing would be verified", suite.Source, len(suite.Vectors))
	}
	hello := impl.Hello()
	choices, err := suite.resolveChoices(hello.Interpretations)
	if err != nil {
		return nil, err
	}
	var cpuWrites map[string]bool
	if len(hello.CPUWrites) > 0 {
		cpuWrites = make(map[string]bool, len(hello.CPUWrites))
		for _, name := range hello.CPUWrites {
			cpuWrites[name] = true
		}
	}
	p := &Plan{Suite: suite, Hello: hello, Choices: choices, Cases: make([]*Case, len(vectors))}
	a := runArena()
	for i, v := range vectors {
		c := a.cases.one(a.chunk)
		*c = Case{Vector: v, Request: requestOf(a, v), id: v.ID, family: a.intern(v.Family), instruction: a.intern(v.Instruction), plan: p}
		c.about = &about{c: c}
		if hello.supports(v.Instruction) {
			names := a.names.take(len(c.Request.Devices), a.chunk) // kept as the expectation's requested
			for i, d := range c.Request.Devices {
				names[i] = d.Name
			}
			if c.expect, err = expectedOf(a, v, choices, names, cpuWrites); err != nil {
				return nil, fmt.Errorf("%s: %w", suite.Source, err)
			}
		}
		p.Cases[i] = c
	}
	if opts.Expectations != "" {
		if p.Known, err = LoadKnownFailures(opts.Expectations); err != nil {
			return nil, err
		}
	}
	return p, nil
}

// Judge runs one case through impl and judges it (before known failures are applied).
func (c *Case) Judge(impl Implementation) Verdict {
	var verdict Verdict
	c.judge(impl, &verdict)
	if verdict.about == nil {
		verdict.about = c.about
	}
	return verdict
}

// judge writes the verdict in place: a run fills its report's verdicts without copying each.
// Every verdict but a pass keeps its case, for the text (a pass needs none, and a pointer more
// written per vector is measurable in a pass over the whole set; Report.caseOf finds it).
func (c *Case) judge(impl Implementation, verdict *Verdict) {
	verdict.ID, verdict.Family, verdict.Instruction, verdict.Vector = c.id, c.family, c.instruction, c.Vector
	if c.expect == nil {
		verdict.Status, verdict.Message, verdict.about = StatusSkip, "the implementation does not run "+c.instruction, c.about
		return
	}
	verdict.Choices = c.expect.choices
	defer func() {
		// An implementation that panics on one vector fails that vector, not the run.
		if r := recover(); r != nil {
			verdict.Status, verdict.about = StatusError, c.about
			verdict.Message = fmt.Sprintf("the implementation panicked: %v\n%s", r, trimStack(debug.Stack()))
		}
	}()
	steps, err := impl.Run(c.Request)
	if err != nil {
		verdict.about = c.about
		if reason, ok := IsSkip(err); ok {
			verdict.Status, verdict.Message = StatusSkip, reason
		} else {
			verdict.Status, verdict.Message = StatusError, "the implementation reported an error: "+err.Error()
		}
		return
	}
	if verdict.Problems = c.expect.compare(steps); verdict.Problems != nil {
		verdict.Status, verdict.about = StatusFail, &about{c: c, failed: true, passes: c.passesUnder(steps)}
	} else {
		verdict.Status = StatusPass
	}
	if r, ok := impl.(recycler); ok {
		r.recycle(steps)
	}
}

// recycler is an implementation of this package (Emulate's) whose step results the runner
// hands back once judged, to be reused for the next vector.
type recycler interface{ recycle([]StepResult) }

// trimStack keeps the frames below the panic, not the runner's own.
func trimStack(stack []byte) string {
	lines := strings.Split(string(stack), "\n")
	for i, l := range lines {
		if strings.HasPrefix(l, "panic(") && i+2 < len(lines) {
			lines = lines[i+2:]
			break
		}
	}
	if len(lines) > 12 {
		lines = lines[:12]
	}
	return strings.Join(lines, "\n")
}

// Report is a whole run's verdicts with what they were judged against.
type Report struct {
	Plan     *Plan
	Verdicts []Verdict
	Seconds  float64 // the run's wall-clock time
	// syntax: how the roll-up writes a declaration (this runner's, unless a test asks for the
	// shared cases' --choose form).
	syntax declarationSyntax
}

// Verify runs the selected vectors through impl outside `go test` (a command, a benchmark, a
// CI tool); Run is the same inside a test, one subtest per vector.
func Verify(impl Implementation, opts Options) (*Report, error) {
	plan, err := Prepare(impl, opts)
	if err != nil {
		return nil, err
	}
	return plan.Verify(impl), nil
}

// Verify judges every case of the plan with impl, then applies the expectations file.
func (p *Plan) Verify(impl Implementation) *Report {
	start := time.Now()
	r := &Report{Plan: p, Verdicts: make([]Verdict, len(p.Cases))}
	defer func() { r.Seconds = time.Since(start).Seconds() }()
	for i, c := range p.Cases {
		c.judge(impl, &r.Verdicts[i])
	}
	if p.Known != nil {
		for i := range r.Verdicts {
			p.Known.apply(&r.Verdicts[i])
			if r.Verdicts[i].about == nil { // a pass made stale is described too
				r.Verdicts[i].about = p.Cases[i].about
			}
		}
		r.Verdicts = append(r.Verdicts, p.Known.unknownIDs(p.Suite)...)
	}
	return r
}

// Counts is the number of verdicts of each status.
func (r *Report) Counts() map[Status]int {
	out := map[Status]int{}
	for _, v := range r.Verdicts {
		out[v.Status]++
	}
	return out
}

// Failed lists the verdicts that fail the run.
func (r *Report) Failed() []Verdict {
	var out []Verdict
	for _, v := range r.Verdicts {
		if v.Status.Failing() {
			out = append(out, v)
		}
	}
	return out
}

// OK reports whether the run passes: nothing failed, and at least one vector passed (a run of
// skips and known failures alone proves nothing: CONTRACT.md, "Exit status").
func (r *Report) OK() bool {
	return len(r.Failed()) == 0 && r.shortfall() == ""
}

// shortfall says why the run proves nothing, "" when some vector passed: no vector was run, or
// every one was skipped or a known failure (an implementation that skips everything, or a list
// of known failures on an implementation that fails them all).
func (r *Report) shortfall() string {
	c := r.Counts()
	switch {
	case len(r.Verdicts) == 0:
		return "no vector was run; choose vectors with PLCVEC_ID=<id or glob>[,...]"
	case c[StatusPass] > 0:
		return ""
	}
	var parts []string
	for _, s := range statusOrder {
		if c[s] > 0 {
			word := string(s)
			switch s {
			case StatusSkip:
				word = "skipped"
			case StatusXFail:
				word = "known failures"
			}
			parts = append(parts, fmt.Sprintf("%d %s", c[s], word))
		}
	}
	return "nothing passed (" + strings.Join(parts, ", ") + "): the run proves nothing"
}
