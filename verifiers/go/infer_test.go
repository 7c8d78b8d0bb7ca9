package plcvec

import "testing"

// TestSameJudged: a passing answer passes under an offered combination when every device that
// combination judges is expected alike under it and under the followed one; a device the
// offered one judges and the followed one leaves unjudged is not known to match, even when both
// states hold the same value (the followed expectation never looked at the answer's).
func TestSameJudged(t *testing.T) {
	names := []string{"D1", "D2"}
	judgesAll := &expected{names: names, states: []Value{Word(0), Word(5)}, results: []Result{NoResult}}
	leavesD1 := &expected{names: names, states: []Value{Word(0), Word(5)}, results: []Result{NoResult},
		notJudged: map[string]bool{"D1": true}}
	otherD1 := &expected{names: names, states: []Value{Word(9), Word(5)}, results: []Result{NoResult},
		notJudged: map[string]bool{"D1": true}}
	otherD2 := &expected{names: names, states: []Value{Word(0), Word(6)}, results: []Result{NoResult}}
	for _, c := range []struct {
		name              string
		offered, followed *expected
		want              bool
	}{
		{"the same", judgesAll, judgesAll, true},
		{"judged under the offer, unjudged under the followed", judgesAll, leavesD1, false},
		{"unjudged under the offer", leavesD1, judgesAll, true},
		{"unjudged under both, other values", otherD1, leavesD1, true},
		{"a judged device differs", otherD2, judgesAll, false},
	} {
		if got := sameJudged(c.offered, c.followed); got != c.want {
			t.Errorf("%s: %v; want %v", c.name, got, c.want)
		}
	}
}
