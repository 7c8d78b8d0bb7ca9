package mutants_test

import (
	"os"
	"regexp"
	"strings"
	"testing"

	"github.com/plcvec/plcvec/verifiers/go"
	"github.com/plcvec/plcvec/verifiers/go/mutants"
	"github.com/plcvec/plcvec/verifiers/go/reference"
)

// TestMutantsRejected: the verifier rejects every mutant, by name, in each family its bug is in.
// The vectors that catch it are logged (go test -v), so a mutant that survives says which cases
// the generator lacks.
func TestMutantsRejected(t *testing.T) {
	suite, err := plcvec.Default()
	if err != nil {
		t.Fatal(err)
	}
	if len(mutants.All) < 10 {
		t.Fatalf("%d mutants; the suite promises at least 10", len(mutants.All))
	}
	families, aspects := map[string]bool{}, map[string]bool{}
	for _, m := range mutants.All {
		aspects[m.Aspect] = true
		t.Run(m.Name, func(t *testing.T) {
			impl, err := m.New(nil)
			if err != nil {
				t.Fatal(err)
			}
			for _, family := range m.Families {
				families[family] = true
				report, err := plcvec.Verify(impl, plcvec.Options{Suite: suite,
					Selection: plcvec.Selection{Families: []string{family}}})
				if err != nil {
					t.Fatal(err)
				}
				failed := report.Failed()
				if len(failed) == 0 {
					t.Errorf("%s survives every %s vector: %s", m.Name, family, m.Bug)
					continue
				}
				for _, v := range failed {
					if v.Status != plcvec.StatusFail {
						t.Errorf("%s: %s is %s, not a field-level failure: %s", m.Name, v.ID, v.Status, v.Message)
					}
				}
				ids := make([]string, 0, 3)
				for _, v := range failed[:min(3, len(failed))] {
					ids = append(ids, v.ID)
				}
				t.Logf("%s: %d %s vectors fail, e.g. %s", m.Name, len(failed), family, strings.Join(ids, ", "))
			}
		})
	}
	for _, f := range suite.Families {
		if !families[f] {
			t.Errorf("no mutant in family %s", f)
		}
	}
	for _, a := range []string{"contact result", "a changed word", "a flag", "a device that must stay unchanged",
		"a write outside the vector", "an interpretation alternative", "a flag (its JSON type)"} {
		if !aspects[a] {
			t.Errorf("no mutant breaks %q", a)
		}
	}
}

// TestMutantFailureReadsAsDiff: how a failure reads, on a mutant whose bug is known exactly:
// the write outside the vector is named with its device and value.
func TestMutantFailureReadsAsDiff(t *testing.T) {
	m, err := mutants.Find("hour-work-area-overrun")
	if err != nil {
		t.Fatal(err)
	}
	impl, err := m.New(nil)
	if err != nil {
		t.Fatal(err)
	}
	report, err := plcvec.Verify(impl, plcvec.Options{Selection: plcvec.Selection{
		IDs: []string{"fc6a-hour-meter/HOUR/subsecond/remainder-kept"}}})
	if err != nil {
		t.Fatal(err)
	}
	if len(report.Verdicts) != 1 || report.Verdicts[0].Status != plcvec.StatusFail {
		t.Fatalf("expected one failing vector, got %+v", report.Verdicts)
	}
	text := report.Verdicts[0].Text()
	for _, want := range []string{"FAIL fc6a-hour-meter/HOUR/subsecond/remainder-kept", "D302: expected <not in the vector>",
		"step 0 inputs: input=true", "step 0 operands: D1 D200=", "spec clauses: fc6a-hour-meter#"} {
		if !strings.Contains(text, want) {
			t.Errorf("the report lacks %q:\n%s", want, text)
		}
	}
}

// TestUnknownMutant: a misspelt mutant is an error naming the known ones.
func TestUnknownMutant(t *testing.T) {
	if _, err := mutants.Find("no-such-bug"); err == nil || !strings.Contains(err.Error(), "cp1e-and-as-or") {
		t.Errorf("expected an error listing the mutants, got %v", err)
	}
	if _, err := reference.New(map[string]string{"NO-SUCH-INTERPRETATION": "x"}); err == nil {
		t.Error("the reference accepted an unknown interpretation")
	}
}

// TestTableInMutantsMD: MUTANTS.md lists exactly the mutants of All.
func TestTableInMutantsMD(t *testing.T) {
	text, err := os.ReadFile("MUTANTS.md")
	if err != nil {
		t.Fatal(err)
	}
	if !strings.Contains(string(text), mutants.Table()) {
		t.Errorf("MUTANTS.md does not hold the table of mutants.All; put this in it:\n%s", mutants.Table())
	}
}

// TestNoMutantExplainedAway: no mutant's run ends with a proposal that is not marked partial
// (TEXT.md, "The roll-up by reading"): a reading is proposed unmarked only when it explains every
// failure of the families it touches, and a mutant is a bug, never only a reading, so some
// failure of its family must stay unexplained.
func TestNoMutantExplainedAway(t *testing.T) {
	suite, err := plcvec.Default()
	if err != nil {
		t.Fatal(err)
	}
	for _, m := range mutants.All {
		t.Run(m.Name, func(t *testing.T) {
			impl, err := m.New(nil)
			if err != nil {
				t.Fatal(err)
			}
			report, err := plcvec.Verify(impl, plcvec.Options{Suite: suite,
				Selection: plcvec.Selection{Families: m.Families}})
			if err != nil {
				t.Fatal(err)
			}
			rollUp := report.RollUp()
			if !strings.Contains(rollUp, "NOT EXPLAINED by any reading") {
				t.Errorf("%s: every failure is explained by a reading:\n%s", m.Name, rollUp)
			}
			inReadings := false
			for _, line := range strings.Split(rollUp, "\n") {
				switch {
				case strings.HasPrefix(line, "READINGS:"):
					inReadings = true
				case !strings.HasPrefix(line, "    "):
					inReadings = false
				case inReadings && regexp.MustCompile(`^ {4} {0,5}\d+  `).MatchString(line) && !strings.Contains(line, "(partial: "):
					t.Errorf("%s: a reading proposed unmarked: %q\n%s", m.Name, line, rollUp)
				}
			}
		})
	}
}
