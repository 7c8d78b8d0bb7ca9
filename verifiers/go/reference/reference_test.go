package reference_test

import (
	"sort"
	"strings"
	"testing"

	"github.com/plcvec/plcvec/verifiers/go"
	"github.com/plcvec/plcvec/verifiers/go/reference"
)

func mustNew(t testing.TB, choices map[string]string) plcvec.Implementation {
	t.Helper()
	r, err := reference.New(choices)
	if err != nil {
		t.Fatal(err)
	}
	return r.Implementation()
}

// TestReference runs every vector under the default alternatives, one subtest per vector id.
func TestReference(t *testing.T) {
	report := plcvec.Run(t, mustNew(t, nil), plcvec.Options{})
	suite, err := plcvec.Default()
	if err != nil {
		t.Fatal(err)
	}
	if !t.Failed() && !testing.Short() && len(report.Verdicts) == len(suite.Vectors) {
		if c := report.Counts(); c[plcvec.StatusPass] != len(suite.Vectors) {
			t.Errorf("%d of %d vectors passed: %v", c[plcvec.StatusPass], len(suite.Vectors), c)
		}
	}
}

// TestEveryCombination: the reference passes every vector of every family under every
// combination of that family's interpretation alternatives, as the Python reference does: every
// one up to productBound of them, past that a pairwise covering set and each combination a vector
// offers (combinations_test.go).
func TestEveryCombination(t *testing.T) {
	suite, err := plcvec.Default()
	if err != nil {
		t.Fatal(err)
	}
	for _, family := range suite.Families {
		var interps []plcvec.InterpretationInfo
		for _, i := range suite.Interpretations() {
			for _, f := range i.Families {
				if f == family {
					interps = append(interps, i)
				}
			}
		}
		combos := combinationsToRun(suite, family, interps)
		if len(combos) < 2 {
			t.Errorf("%s: %d combinations of alternatives; expected the family to have interpretations", family, len(combos))
		}
		for _, choices := range combos {
			keys := make([]string, 0, len(choices))
			for k, v := range choices {
				keys = append(keys, k+"="+v)
			}
			sort.Strings(keys)
			name := family + "/" + strings.Join(keys, ",")
			t.Run(name, func(t *testing.T) {
				report, err := plcvec.Verify(mustNew(t, choices), plcvec.Options{
					Suite: suite, Selection: plcvec.Selection{Families: []string{family}}})
				if err != nil {
					t.Fatal(err)
				}
				for _, v := range report.Failed() {
					t.Error("\n" + v.Text())
				}
				c := report.Counts()
				if c[plcvec.StatusPass] != len(report.Verdicts) || c[plcvec.StatusPass] == 0 {
					t.Errorf("%v", c)
				}
			})
		}
	}
}
