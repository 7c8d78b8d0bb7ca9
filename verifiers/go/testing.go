package plcvec

import (
	"os"
	"regexp"
	"strconv"
	"strings"
	"testing"
	"unicode"
)

// Run verifies impl inside a Go test: one subtest per selected vector, named by the vector's
// id, so that `go test -run`, `-json`, `-v`, `-failfast` and CI's test reports work per vector.
// It is meant for the implementer's own _test.go:
//
//	func TestPlcvec(t *testing.T) {
//		plcvec.Run(t, myemu.Implementation(), plcvec.Options{})
//	}
//
// A failing vector's subtest fails with the field-level diff (Verdict.Text); a vector the
// implementation skips, or a known failure of the expectations file, is skipped with its reason.
// Run fails the test itself when the run cannot start (a bad selection, an unknown
// interpretation, a bad expectations file), when a listed known failure names no vector, and
// when every vector that ran was skipped: a gate never passes by accident.
//
// Subtest names: Go's testing package writes a subtest name with each space as '_' (and an
// unprintable character as its escape), and matches -run level by level at each '/'. An id
// such as "cp1e-time-compare/AND <=DT/logic/rlo-off/eq" is therefore the subtest
// "TestPlcvec/cp1e-time-compare/AND_<=DT/logic/rlo-off/eq"; RunPattern gives the -run pattern
// that selects exactly one id, and -run 'TestPlcvec/fx5-time-add/TADDP/' one instruction.
// $PLCVEC_SHARD=K/N runs one shard of the selection (when Options give no shard).
func Run(t *testing.T, impl Implementation, opts Options) *Report {
	t.Helper()
	if text := os.Getenv(EnvShard); text != "" && opts.Selection.Shard == (Shard{}) {
		shard, err := ParseShard(text)
		if err != nil {
			t.Fatalf("plcvec: $%s: %v", EnvShard, err)
		}
		opts.Selection.Shard = shard
	}
	plan, err := Prepare(impl, opts)
	if err != nil {
		t.Fatalf("plcvec: %v", err)
	}
	t.Log(strings.TrimSuffix(plan.Header(), "\n"))
	report := &Report{Plan: plan, Verdicts: make([]Verdict, 0, len(plan.Cases))}
	for _, c := range plan.Cases {
		t.Run(c.Vector.ID, func(t *testing.T) {
			t.Helper() // the report names the vector; a line of this file would say nothing
			v := c.Judge(impl)
			if plan.Known != nil {
				plan.Known.apply(&v)
			}
			report.Verdicts = append(report.Verdicts, v)
			switch v.Status {
			case StatusPass:
			case StatusSkip, StatusXFail:
				t.Skip(strings.TrimSuffix(v.Text(), "\n"))
			default:
				t.Error("\n" + v.Text())
			}
		})
	}
	if plan.Known != nil {
		for _, v := range plan.Known.unknownIDs(plan.Suite) {
			report.Verdicts = append(report.Verdicts, v)
			t.Error(v.Text())
		}
	}
	c := report.Counts()
	if len(report.Verdicts) > 0 && c[StatusPass]+c[StatusXFail]+c[StatusFail]+c[StatusError] == 0 {
		t.Errorf("plcvec: every one of the %d vectors run was skipped; nothing was verified", len(report.Verdicts))
	}
	return report
}

// EnvShard names the environment variable that gives Run a shard K/N when Options do not, so a
// CI matrix splits the suite without changing the test: PLCVEC_SHARD=2/4 go test ./...
const EnvShard = "PLCVEC_SHARD"

// SubtestName is the name Go's testing package gives the subtest of a vector id: each space
// becomes '_' and each unprintable character its escape, as testing.T.Run writes it.
func SubtestName(id string) string {
	var b strings.Builder
	for _, r := range id {
		switch {
		case unicode.IsSpace(r):
			b.WriteByte('_')
		case !strconv.IsPrint(r):
			q := strconv.QuoteRune(r)
			b.WriteString(q[1 : len(q)-1])
		default:
			b.WriteRune(r)
		}
	}
	return b.String()
}

// RunPattern is the `go test -run` pattern that selects exactly the vector id under the test
// function test: each '/'-separated level quoted and anchored, as -run matches level by level.
//
//	go test -run "$(... RunPattern("TestPlcvec", "cp1e-time-compare/AND <=DT/logic/rlo-off/eq"))"
//	-> ^TestPlcvec$/^cp1e-time-compare$/^AND_<=DT$/^logic$/^rlo-off$/^eq$
func RunPattern(test, id string) string {
	levels := append([]string{test}, strings.Split(SubtestName(id), "/")...)
	for i, l := range levels {
		levels[i] = "^" + regexp.QuoteMeta(l) + "$"
	}
	return strings.Join(levels, "/")
}
