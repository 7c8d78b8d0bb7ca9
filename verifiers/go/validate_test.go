package plcvec

import "testing"

// TestDeviceTypeConflictFound: the pass that only looks for a device typed two ways finds one
// wherever the pass that names the first finds one, and nowhere else: on golden vectors, and on
// the same with each device of each place turned the other type in turn.
func TestDeviceTypeConflictFound(t *testing.T) {
	data, err := embedded.ReadFile("vectors/fx5-time-add.jsonl")
	if err != nil {
		t.Fatal(err)
	}
	_, vectors, err := parseJSONL(data, "fx5-time-add.jsonl")
	if err != nil {
		t.Fatal(err)
	}
	found := 0
	agree := func(v *Vector) {
		t.Helper()
		named := v.firstDeviceTypeConflict()
		if v.deviceTypeConflict() != (named != "") {
			t.Fatalf("vector %s: a conflict found is %v, the first named %q", v.ID, v.deviceTypeConflict(), named)
		}
		if named != "" {
			found++
		}
	}
	for _, v := range vectors[:min(len(vectors), 40)] {
		agree(v)
		places := []map[string]Value{v.Initial.Devices, v.Final.Devices}
		for i := range v.Steps {
			places = append(places, v.Steps[i].Set, v.Steps[i].Expect.Devices)
		}
		for a := range v.Alternatives {
			for i := range v.Alternatives[a].Expect {
				places = append(places, v.Alternatives[a].Expect[i].Devices)
			}
			places = append(places, v.Alternatives[a].Final.Devices)
		}
		for _, place := range places {
			for name, value := range place {
				if value.IsBit() {
					place[name] = Word(1)
				} else {
					place[name] = Bit(true)
				}
				agree(v)
				place[name] = value
			}
		}
	}
	// A device `initial` does not name, in two other places.
	for _, final := range []Value{Word(2), Bit(true)} {
		agree(&Vector{ID: "outside-initial", Initial: &Initial{Devices: map[string]Value{}},
			Steps: []Step{{Inputs: Inputs{Set: map[string]Value{"D9": Word(1)}}}}, Final: &State{Devices: map[string]Value{"D9": final}}})
	}
	if found == 0 {
		t.Fatal("no vector turned had a conflict: the test tests nothing")
	}
}
