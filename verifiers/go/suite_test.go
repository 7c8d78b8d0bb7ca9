package plcvec

import (
	"reflect"
	"testing"
)

// TestMergedIDsFollowed: a vector merged into one that was merged again is named by the vector
// it is now; a loop of merges (a damaged index) ends where it started rather than running on.
func TestMergedIDsFollowed(t *testing.T) {
	got := mergedIDs(map[string]map[string]string{"f": {"a": "b", "b": "c"}, "g": {"x": "y", "y": "x"}})
	want := map[string]string{"a": "c", "b": "c", "x": "x", "y": "y"}
	if !reflect.DeepEqual(got, want) {
		t.Errorf("got %v; want %v", got, want)
	}
}
