package plcvec

import (
	"bytes"
	"encoding/json"
	"fmt"
	"sort"
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

// shapeProblem names what a vector lacks that the runner needs, or a device typed two ways, or
// "" (the full schema is vectors/schema/; unknown keys are refused by the decoder).
func (v *Vector) shapeProblem(family string) string {
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
	return v.deviceTypes()
}
