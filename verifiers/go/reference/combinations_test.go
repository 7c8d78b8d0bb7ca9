package reference_test

import (
	"sort"
	"strings"
	"testing"

	"github.com/plcvec/plcvec/verifiers/go"
)

// productBound is the number of a family's combinations of alternatives past which the tests
// run a pairwise covering set instead of every one (as the Python tests do: HOUR's eleven
// interpretations have 34,560 combinations). What the full product adds over it is an interaction
// of three or more readings at once; each combination some vector offers is run too, so that
// every vector is checked under each of its own.
const productBound = 1024

// combinationsToRun are the combinations (interpretation -> alternative) of family's
// interpretations to run the reference under, taken from the loaded suite (never a list typed
// here: an alternative the spec gains is run too).
func combinationsToRun(suite *plcvec.Suite, family string, interps []plcvec.InterpretationInfo) []map[string]string {
	product := 1
	for _, i := range interps {
		product *= len(i.Alternatives)
	}
	if product <= productBound {
		return everyCombination(interps)
	}
	out := pairwise(interps)
	seen := map[string]bool{}
	for _, c := range out {
		seen[comboKey(c)] = true
	}
	for _, v := range suite.Vectors {
		if v.Family != family {
			continue
		}
		for _, alt := range v.Alternatives {
			if !seen[comboKey(alt.Choices)] {
				seen[comboKey(alt.Choices)] = true
				out = append(out, alt.Choices) // the others at their defaults
			}
		}
	}
	return out
}

func comboKey(c map[string]string) string {
	keys := make([]string, 0, len(c))
	for k, v := range c {
		keys = append(keys, k+"="+v)
	}
	sort.Strings(keys)
	return strings.Join(keys, ",")
}

// everyCombination is every combination of the alternatives of interps.
func everyCombination(interps []plcvec.InterpretationInfo) []map[string]string {
	out := []map[string]string{{}}
	for _, i := range interps {
		var next []map[string]string
		for _, combo := range out {
			for _, alt := range i.Alternatives {
				c := map[string]string{i.ID: alt}
				for k, v := range combo {
					c[k] = v
				}
				next = append(next, c)
			}
		}
		out = next
	}
	return out
}

// pair is two alternatives of two interpretations (by index in interps, a < b).
type pair struct{ a, altA, b, altB int }

// pairwise is a covering set of interps' combinations: every alternative of each interpretation
// beside every alternative of each other in some combination. Greedy and deterministic: take the
// first pair not yet covered, then give every other interpretation, in order, the alternative that
// covers the most pairs not yet covered with those already given (the first on a tie).
func pairwise(interps []plcvec.InterpretationInfo) []map[string]string {
	uncovered := map[pair]bool{}
	var order []pair
	for a := range interps {
		for b := a + 1; b < len(interps); b++ {
			for x := range interps[a].Alternatives {
				for y := range interps[b].Alternatives {
					p := pair{a, x, b, y}
					uncovered[p], order = true, append(order, p)
				}
			}
		}
	}
	var out []map[string]string
	for _, seed := range order {
		if !uncovered[seed] {
			continue
		}
		row := make([]int, len(interps))
		for i := range row {
			row[i] = -1
		}
		row[seed.a], row[seed.b] = seed.altA, seed.altB
		for i := range interps {
			if row[i] < 0 {
				row[i] = bestAlternative(interps, row, i, uncovered)
			}
		}
		combo := map[string]string{}
		for i, alt := range row {
			combo[interps[i].ID] = interps[i].Alternatives[alt]
			for j := i + 1; j < len(row); j++ {
				delete(uncovered, pair{i, alt, j, row[j]})
			}
		}
		out = append(out, combo)
	}
	return out
}

// bestAlternative is the alternative of interpretation i that covers the most uncovered pairs
// with the alternatives row gives already (-1: none yet).
func bestAlternative(interps []plcvec.InterpretationInfo, row []int, i int, uncovered map[pair]bool) int {
	best, bestCount := 0, -1
	for x := range interps[i].Alternatives {
		n := 0
		for j, y := range row {
			switch {
			case y < 0 || j == i:
			case j < i && uncovered[pair{j, y, i, x}]:
				n++
			case j > i && uncovered[pair{i, x, j, y}]:
				n++
			}
		}
		if n > bestCount {
			best, bestCount = x, n
		}
	}
	return best
}

// TestPairwiseCoversEveryPair: the set past the bound holds every pair of alternatives of two
// interpretations, and is far smaller than the product.
func TestPairwiseCoversEveryPair(t *testing.T) {
	suite, err := plcvec.Default()
	if err != nil {
		t.Fatal(err)
	}
	interps := suite.Interpretations()
	rows := pairwise(interps)
	for a := range interps {
		for b := a + 1; b < len(interps); b++ {
			for _, x := range interps[a].Alternatives {
				for _, y := range interps[b].Alternatives {
					found := false
					for _, r := range rows {
						found = found || r[interps[a].ID] == x && r[interps[b].ID] == y
					}
					if !found {
						t.Errorf("no combination has %s=%s with %s=%s", interps[a].ID, x, interps[b].ID, y)
					}
				}
			}
		}
	}
	if len(rows) > 100 {
		t.Errorf("%d rows for every pair of %d interpretations", len(rows), len(interps))
	}
}
