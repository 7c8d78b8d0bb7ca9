package plcvec

import (
	"bytes"
	"encoding/json"
	"fmt"
	"regexp"
	"sort"
	"strconv"
	"strings"
	"unicode/utf8"
)

// Loading refuses what `plcvec verify` refuses (CONTRACT.md, "Loading"): a key the schema
// (vectors/schema/vector-file.schema.json) does not have, at any level, since a key this runner
// does not know may carry a meaning it would silently ignore; a value that is neither a word
// nor a bit; a device that is a bit in one place of a vector and a word in another (a bit
// holding 2 is a damaged file, not an implementation's mistake); text that is not UTF-8.

// decodeStrict decodes one JSON value into v, refusing keys v's type does not have and
// anything after the value.
func decodeStrict(data []byte, v any) error {
	dec := json.NewDecoder(bytes.NewReader(data))
	dec.DisallowUnknownFields()
	if err := dec.Decode(v); err != nil {
		return err
	}
	if dec.More() {
		return fmt.Errorf("more than one JSON value")
	}
	return nil
}

// checkUTF8 names the first byte of data that is not UTF-8, by line and column (1-based).
func checkUTF8(data []byte, where string, firstLine int) error {
	if utf8.Valid(data) {
		return nil
	}
	line, col := firstLine, 1
	for i := 0; i < len(data); {
		r, size := utf8.DecodeRune(data[i:])
		if r == utf8.RuneError && size <= 1 {
			return fmt.Errorf("%s:%d: byte 0x%02x at column %d is not UTF-8 (the vector files are UTF-8 text; is the copy damaged?)", where, line, data[i], col)
		}
		if r == '\n' {
			line, col = line+1, 1
		} else {
			col++
		}
		i += size
	}
	return nil
}

// deviceTypes checks that each device of a vector holds one JSON type (a bit or a word) in
// `initial`, every step's `set` and `expect`, `final` and every alternative, and returns the
// first conflict in words.
func (v *Vector) deviceTypes() string {
	// Every load checks every vector, and naming each place and sorting each map's names, to
	// find the first conflict in a fixed order, was a third of a load with no conflict to name:
	// a pass that only looks for one comes first.
	if !v.deviceTypeConflict() {
		return ""
	}
	return v.firstDeviceTypeConflict()
}

// deviceTypeConflict reports whether a device of v is a bit in one place and a word in another.
// Each place is held against `initial`, which names nearly every device of a vector (a map of
// every device, built per vector, was most of the time); the others alone go into a map.
func (v *Vector) deviceTypeConflict() bool {
	var initial map[string]Value
	if v.Initial != nil {
		initial = v.Initial.Devices
	}
	var others map[string]bool
	conflict := false
	note := func(devices map[string]Value) {
		for name, value := range devices {
			bit := value.IsBit()
			if first, ok := initial[name]; ok {
				conflict = conflict || first.IsBit() != bit
				continue
			}
			if first, ok := others[name]; ok {
				conflict = conflict || first != bit
				continue
			}
			if others == nil {
				others = map[string]bool{}
			}
			others[name] = bit
		}
	}
	for i := range v.Steps {
		note(v.Steps[i].Set)
		if v.Steps[i].Expect != nil {
			note(v.Steps[i].Expect.Devices)
		}
	}
	if v.Final != nil {
		note(v.Final.Devices)
	}
	for a := range v.Alternatives {
		for i := range v.Alternatives[a].Expect {
			note(v.Alternatives[a].Expect[i].Devices)
		}
		note(v.Alternatives[a].Final.Devices)
	}
	return conflict
}

// firstDeviceTypeConflict names the first conflict deviceTypeConflict found, the places in the
// order deviceTypes gives, each place's devices by name.
func (v *Vector) firstDeviceTypeConflict() string {
	type seen struct {
		bit   bool
		where string
	}
	types := map[string]seen{}
	conflict := ""
	note := func(devices map[string]Value, where string) {
		names := make([]string, 0, len(devices))
		for name := range devices {
			names = append(names, name)
		}
		sort.Strings(names)
		for _, name := range names {
			bit := devices[name].IsBit()
			first, ok := types[name]
			if !ok {
				types[name] = seen{bit, where}
				continue
			}
			if conflict == "" && first.bit != bit {
				conflict = fmt.Sprintf("device %s is %s in %s but %s in %s", name, kindOf(first.bit), first.where, kindOf(bit), where)
			}
		}
	}
	if v.Initial != nil {
		note(v.Initial.Devices, "`initial`")
	}
	for i := range v.Steps {
		note(v.Steps[i].Set, fmt.Sprintf("step %d `set`", i))
		if v.Steps[i].Expect != nil {
			note(v.Steps[i].Expect.Devices, fmt.Sprintf("step %d `expect`", i))
		}
	}
	if v.Final != nil {
		note(v.Final.Devices, "`final`")
	}
	for a := range v.Alternatives {
		for i := range v.Alternatives[a].Expect {
			note(v.Alternatives[a].Expect[i].Devices, fmt.Sprintf("alternative %d step %d", a, i))
		}
		note(v.Alternatives[a].Final.Devices, fmt.Sprintf("alternative %d `final`", a))
	}
	return conflict
}

func kindOf(bit bool) string {
	if bit {
		return "a bit"
	}
	return "a word"
}

// shapeProblem names what a vector of a file with header h lacks that the runner needs, a
// device typed two ways, or a malformed `unjudged` map, or "" (the full schema is
// vectors/schema/; unknown keys are refused by the decoder).
func (v *Vector) shapeProblem(h *FamilyHeader) string {
	if p := v.basicShape(h.Family); p != "" {
		return p
	}
	if p := v.unjudgedProblem(h.SchemaVersion); p != "" {
		return p
	}
	return v.deviceTypes()
}

// basicShape names what a vector lacks that the runner needs.
func (v *Vector) basicShape(family string) string {
	switch {
	case v.ID == "":
		return "no `id`"
	case v.Family == "":
		return "no `family`"
	case v.Family != family:
		return "family " + v.Family + " in a " + family + " file"
	case v.Instruction == "":
		return "no `instruction`"
	case v.Initial == nil || v.Initial.Devices == nil || v.Initial.Operands == nil:
		return "`initial` needs `devices` and `operands`"
	case len(v.Steps) == 0:
		return "no `steps`"
	case v.Final == nil || v.Final.Devices == nil:
		return "`final` needs `devices`"
	case v.Outcome == nil || v.Outcome.Category == "":
		return "no `outcome`"
	}
	for i, st := range v.Steps {
		if st.Expect == nil {
			return "step " + itoa(i) + " has no `expect`"
		}
	}
	for i, a := range v.Alternatives {
		if len(a.Expect) != len(v.Steps) {
			return "alternative " + itoa(i) + " has " + itoa(len(a.Expect)) + " expectations for " + itoa(len(v.Steps)) + " steps"
		}
	}
	return ""
}

// deviceName is the schema's pattern of a device name.
var deviceName = regexp.MustCompile(`^[A-Za-z_]+[0-9]*$`)

// unjudgedProblem names the first fault of an `alternatives` entry's `unjudged` map by its JSON
// path (unjudged.md, schema 1.1): the key in a file of schema 1.0, an interpretation that is not
// one of the entry's choices, an empty list, a device named twice or not a device name, a device
// not in `initial`, or one the entry expects all the same (in a step's `expect` or its `final`).
func (v *Vector) unjudgedProblem(schema string) string {
	for i, a := range v.Alternatives {
		if a.Unjudged == nil {
			continue
		}
		at := "alternatives/" + itoa(i)
		if strings.HasPrefix(schema, "1.0.") {
			return "at " + at + ": `unjudged` is not a key of schema " + schema + " (it came with 1.1.0)"
		}
		for _, id := range sortedKeysOf(a.Unjudged) {
			if p := a.unjudgedDevices(v, at, id); p != "" {
				return p
			}
		}
	}
	return ""
}

// unjudgedDevices checks the devices an alternative leaves unjudged under interpretation id.
func (a *Alternative) unjudgedDevices(v *Vector, at, id string) string {
	path := at + "/unjudged/" + id
	devices := a.Unjudged[id]
	switch _, ok := a.Choices[id]; {
	case !ok:
		return "at " + at + "/unjudged: " + id + " is not one of the entry's choices"
	case len(devices) == 0:
		return "at " + path + ": no device (the list holds one or more)"
	}
	seen := map[string]bool{}
	for k, d := range devices {
		switch _, listed := v.Initial.Devices[d]; {
		case !deviceName.MatchString(d):
			return "at " + path + "/" + itoa(k) + ": " + strconv.Quote(d) + " is not a device name"
		case seen[d]:
			return "at " + path + ": " + d + " is listed twice"
		case !listed:
			return "at " + path + ": " + d + " is not in initial/devices"
		}
		seen[d] = true
		for s := range a.Expect {
			if _, ok := a.Expect[s].Devices[d]; ok {
				return "at " + at + "/expect/" + itoa(s) + "/devices/" + d + ": " + d + " is left unjudged by this entry (" + path + ")"
			}
		}
		if _, ok := a.Final.Devices[d]; ok {
			return "at " + at + "/final/devices/" + d + ": " + d + " is left unjudged by this entry (" + path + ")"
		}
	}
	return ""
}

func sortedKeysOf[V any](m map[string]V) []string {
	out := make([]string, 0, len(m))
	for k := range m {
		out = append(out, k)
	}
	sort.Strings(out)
	return out
}
