package plcvec

import "testing"

// TestRunFilter: the filter worked out from -run and -skip lets through what `go test` runs:
// level by level at each '/', each level a regexp that may match part of a name, '|' between
// whole patterns, spaces of an id written as '_'.
func TestRunFilter(t *testing.T) {
	const tadd, taddp = "TestPlcvec/fx5-time-add/TADD/manual-example/program", "TestPlcvec/fx5-time-add/TADDP/manual-example/program"
	const cp1e = "TestPlcvec/" + "cp1e-time-compare/AND_<=DT/logic/rlo-off/eq"
	for _, c := range []struct {
		run, skip string
		name      string
		want      bool
	}{
		{"TestPlcvec/fx5-time-add/TADD/", "", taddp, true}, // unanchored: TADD matches TADDP too
		{"^TestPlcvec$/^fx5-time-add$/^TADD$/", "", taddp, false},
		{"^TestPlcvec$/^fx5-time-add$/^TADD$/", "", tadd, true},
		{"TestPlcvec/cp1e-time-compare/AND <=DT/", "", cp1e, true}, // a space in the pattern is '_'
		{"TestPlcvec/no-such", "", tadd, false},
		{"TestOther|TestPlcvec/fx5-time-add", "", tadd, true},
		{"TestPlcvec", "TestPlcvec/fx5-time-add/TADDP", taddp, false},
		{"TestPlcvec", "TestPlcvec/fx5-time-add/TADDP", tadd, true},
		{"TestPlcvec", "fx5-time-add", tadd, true}, // -skip matches whole names level by level
		{"TestPlcvec/[a-z0-9]+-time-add/(TADD|X)/", "", tadd, true},
		{RunPattern("TestPlcvec", "cp1e-time-compare/AND <=DT/logic/rlo-off/eq"), "", cp1e, true},
	} {
		var f runFilter
		var err error
		if c.run != "" {
			if f.run, err = splitPattern(c.run); err != nil {
				t.Fatal(err)
			}
		}
		if c.skip != "" {
			if f.skip, err = splitPattern(c.skip); err != nil {
				t.Fatal(err)
			}
		}
		if got := f.takes(c.name); got != c.want {
			t.Errorf("-run %q -skip %q on %s: %v, want %v", c.run, c.skip, c.name, got, c.want)
		}
	}
}
