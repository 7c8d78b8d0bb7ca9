package plcvec

import (
	"fmt"
	"sort"
	"strings"
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
}

// Problem is one field that differs: where, what the vector expects, what was reported.
type Problem struct {
	Step     int    // -1: about the vector as a whole (the number of steps)
	Field    string // "result", a device name, or "steps"
	Expected string // as the vector files write values: 13, true; or <not in the vector>
	Actual   string // likewise; <not reported> when the implementation left it out
	Before   string // a device's value before the step ("" when unknown or not a device)
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
	text := fmt.Sprintf("%s%s: expected %s, got %s", where, p.Field, p.Expected, p.Actual)
	switch {
	case p.Expected == notListed:
		text += " (a write outside the vector: the instruction must not write it)"
	case p.Before != "" && p.Before == p.Expected:
		text += " (the step must leave it unchanged)"
	case p.Before != "":
		text += fmt.Sprintf(" (before the step: %s)", p.Before)
	}
	return text
}

func show(v Value) string {
	if v == absent {
		return notListed
	}
	return v.String()
}

func showBefore(v Value) string {
	if v == absent {
		return ""
	}
	return v.String()
}

// maxProblems is the number of field lines shown per failing vector.
const maxProblems = 12

// Text is the verdict as a person reads it: the id, what the vector is about, the alternatives
// it was judged by, the field-level diff (step, device, expected, actual) and the spec clauses
// it exercises.
func (v *Verdict) Text() string {
	var b strings.Builder
	fmt.Fprintf(&b, "%s %s\n", strings.ToUpper(string(v.Status)), v.ID)
	if v.Vector != nil && v.Vector.Description != "" {
		fmt.Fprintf(&b, "    %s: %s\n", v.Instruction, v.Vector.Description)
	}
	if len(v.Choices) > 0 {
		keys := make([]string, 0, len(v.Choices))
		for id, alt := range v.Choices {
			keys = append(keys, id+"="+alt)
		}
		sort.Strings(keys)
		fmt.Fprintf(&b, "    judged by: %s\n", strings.Join(keys, ", "))
	}
	for i, p := range v.Problems {
		if i == maxProblems {
			fmt.Fprintf(&b, "    ... and %d more differences\n", len(v.Problems)-maxProblems)
			break
		}
		fmt.Fprintf(&b, "    %s\n", p)
	}
	if v.Message != "" {
		fmt.Fprintf(&b, "    %s\n", strings.ReplaceAll(v.Message, "\n", "\n    "))
	}
	if v.Vector != nil && len(v.Vector.Clauses) > 0 {
		fmt.Fprintf(&b, "    spec clauses: %s\n", strings.Join(v.Vector.Clauses, ", "))
	}
	return b.String()
}
