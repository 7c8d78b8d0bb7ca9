package plcvec

import (
	"bytes"
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

// BenchmarkLoadEmbedded loads the embedded golden set: what every run pays before it judges
// (go test -bench LoadEmbedded; the report gives the load time before and after the check of
// repeated keys).
func BenchmarkLoadEmbedded(b *testing.B) {
	for range b.N {
		if _, err := Embedded(); err != nil {
			b.Fatal(err)
		}
	}
}

// BenchmarkRepeatedKeys is the check of repeated keys alone over the embedded golden set's
// lines, as a load makes it.
func BenchmarkRepeatedKeys(b *testing.B) {
	var lines [][]byte
	for _, name := range []string{"cp1e-time-compare", "fc6a-hour-meter", "fx5-date-compare", "fx5-time-add", "fx5-time-compare"} {
		data, err := embedded.ReadFile("vectors/" + name + ".jsonl")
		if err != nil {
			b.Fatal(err)
		}
		lines = append(lines, bytes.Split(data, []byte("\n"))...)
	}
	var keys keyScanner
	b.ResetTimer()
	for range b.N {
		for _, line := range lines {
			if err := keys.repeatedKeyError(line, "x", 1, nil); err != nil {
				b.Fatal(err)
			}
		}
	}
}
