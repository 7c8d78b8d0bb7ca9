package plcvec

import (
	"fmt"
)

// Status is a vector's verdict. Only pass, skip and xfail let a run pass.
type Status string

const (
	StatusPass  Status = "pass"
	StatusFail  Status = "fail"
	StatusError Status = "error"
	StatusSkip  Status = "skip"
	StatusXFail Status = "xfail"
	StatusStale Status = "stale"
	// StatusNotRun: the run ended before the vector (an implementation that hung or ended the
	// process on an earlier one).
	StatusNotRun Status = "not-run"
)

// statusOrder is the order the totals count the statuses in (TEXT.md, "The summary lines").
var statusOrder = []Status{StatusPass, StatusFail, StatusError, StatusSkip, StatusXFail, StatusStale, StatusNotRun}

// Failing reports whether the status fails a run.
func (s Status) Failing() bool {
	return s == StatusFail || s == StatusError || s == StatusStale || s == StatusNotRun
}

// Verdict is the judgement of one vector.
type Verdict struct {
	ID          string
	Family      string
	Instruction string
	Status      Status
	Problems    []Problem         // for Fail: the fields that differ
	Message     string            // for Error, Skip, XFail, Stale: why
	Choices     map[string]string // interpretation -> alternative the vector was judged by (those it depends on)
	Vector      *Vector           // nil for an expectations-file id the suite does not have
	// about: what the text and the readings need of a verdict other than the usual pass, its case
	// and, for an answer that differed, the combinations it passes under. One pointer, nil for the
	// usual pass: each byte of a verdict is some 2.8 kB more that every pass over the golden set
	// allocates, clears and leaves to the collector, a cost a benchmark of the runner sees.
	about *about
}

// about is a verdict's case and, for an answer that differed (kept when a known failure makes it
// xfail), whether it passes under each combination the vector offers. Every verdict but a
// failed answer shares its case's own (Case.about), so that only a failure allocates one.
type about struct {
	c      *Case // nil for a stale id
	failed bool
	passes []bool
}

// judgedCase is the case the verdict judged (nil for a pass from Plan.Verify and a stale id:
// Report.caseOf finds the former).
func (v *Verdict) judgedCase() *Case {
	if v.about == nil {
		return nil
	}
	return v.about.c
}

// answerFailed reports whether the implementation's answer differed from the expectation.
func (v *Verdict) answerFailed() bool { return v.about != nil && v.about.failed }

// passes is what a failed answer passes under (nil for any other verdict).
func (v *Verdict) passes() []bool {
	if v.about == nil {
		return nil
	}
	return v.about.passes
}

// Problem is one field that differs: where, what the vector expects, what was reported.
type Problem struct {
	Step     int    // -1: about the vector as a whole (the number of steps)
	Field    string // "result", a device name, or "steps"
	Expected string // as the vector files write values: 13, true; or <not in the vector>
	Actual   string // likewise; <not reported> when the implementation left it out
	// Suffix: for a device the vector lists, the value the implementation held before the step
	// and whether the step had to leave it unchanged (verifiers/parity/TEXT.md, "A field line").
	Suffix string
	// Before is the vector's value of the device before the step ("" when the state before the
	// step has no such device, or the problem is not about a device).
	//
	// Deprecated: the line (String) shows the value the implementation held before the step, in
	// Suffix; Before stays filled until plcvec 0.3.0.
	Before string
}

const (
	notReported = "<not reported>"
	notListed   = "<not in the vector>"
)

// String is the problem as a line of a failure report.
func (p Problem) String() string {
	where := ""
	if p.Step >= 0 {
		where = fmt.Sprintf("step %d ", p.Step)
	}
	return fmt.Sprintf("%s%s: expected %s, got %s%s", where, p.Field, p.Expected, p.Actual, p.Suffix)
}

// suffix is a listed device's suffix: held is the value the implementation held before the
// step, keep whether the vector's value after the step is its value before it.
func suffix(held, want, got string, keep bool) string {
	wrote := got != notReported && got != held
	switch {
	case keep && wrote && held == want:
		return " (the step must leave it unchanged)"
	case keep && wrote:
		return " (before the step: " + held + "; the step must leave it unchanged)"
	}
	return " (before the step: " + held + ")"
}

func show(v Value) string {
	if v == absent {
		return notListed
	}
	return v.String()
}

// maxProblems is the number of field lines shown per failing vector.
const maxProblems = 12
