package reference

import "testing"

// Each condition against Go's own comparison of two numbers below, equal to and above each other.
func TestHoldsIsTheComparisonItNames(t *testing.T) {
	compare := map[condition]func(a, b int) bool{
		condEQ: func(a, b int) bool { return a == b },
		condNE: func(a, b int) bool { return a != b },
		condGT: func(a, b int) bool { return a > b },
		condLE: func(a, b int) bool { return a <= b },
		condLT: func(a, b int) bool { return a < b },
		condGE: func(a, b int) bool { return a >= b },
	}
	for c, want := range compare {
		for _, pair := range [][2]int{{3, 7}, {7, 7}, {7, 3}} {
			order := 0
			if pair[0] < pair[1] {
				order = -1
			} else if pair[0] > pair[1] {
				order = 1
			}
			if got := holds(c, order); got != want(pair[0], pair[1]) {
				t.Errorf("holds(%d, %d) = %v for s1=%d s2=%d", c, order, got, pair[0], pair[1])
			}
		}
	}
}
