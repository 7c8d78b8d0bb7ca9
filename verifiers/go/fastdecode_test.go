package plcvec

import (
	"bytes"
	"reflect"
	"regexp"
	"strings"
	"testing"
)

// The hand-written decoder of the vector lines (fastdecode.go) is a shortcut: whatever it takes,
// encoding/json (streamJSONL, the way every file was read before it) takes too, decodes to the
// same values, and finds no repeated key in; whatever else, it declines. These tests hold it to
// that on the whole embedded set and on damaged lines of every kind.

// jsonlLines splits an exported family file into its lines as parseJSONL does.
func jsonlLines(data []byte) [][]byte {
	lines := bytes.Split(data, []byte("\n"))
	if len(lines) > 0 && len(lines[len(lines)-1]) == 0 {
		lines = lines[:len(lines)-1]
	}
	return lines
}

// fastAgrees checks the one rule on one file: declined, or what encoding/json gives with no
// repeated key on any vector line. It reports whether the fast path took the file.
func fastAgrees(t *testing.T, data []byte) bool {
	t.Helper()
	lines := jsonlLines(data)
	if len(lines) == 0 {
		return false
	}
	fastHeader, fastVectors, ok := fastJSONL(data, lines)
	if !ok {
		return false
	}
	header, vectors, slowOK := streamJSONL(data, lines)
	if !slowOK {
		t.Fatalf("the fast path took what encoding/json refuses:\n%q", data)
	}
	if !reflect.DeepEqual(fastHeader, header) {
		t.Fatalf("the header decodes otherwise:\nfast %+v\njson %+v\n%q", fastHeader, header, data)
	}
	if !reflect.DeepEqual(fastVectors, vectors) {
		for i := range vectors {
			if i < len(fastVectors) && !reflect.DeepEqual(fastVectors[i], vectors[i]) {
				t.Fatalf("line %d decodes otherwise:\nfast %#v\njson %#v\n%q", i+2, fastVectors[i], vectors[i], lines[i+1])
			}
		}
		t.Fatalf("%d vectors decoded; encoding/json decodes %d", len(fastVectors), len(vectors))
	}
	var keys keyScanner
	for i, line := range lines[1:] {
		if at, key := keys.scan(line); at >= 0 {
			t.Fatalf("the fast path took line %d, which repeats key %q:\n%q", i+2, key, line)
		}
	}
	return true
}

// TestFastDecodeOfTheEmbeddedSet: every embedded family decodes by hand, to the very values
// encoding/json gives (a golden set the fast path declined would leave its time unsaved).
func TestFastDecodeOfTheEmbeddedSet(t *testing.T) {
	entries, err := embedded.ReadDir("vectors")
	if err != nil {
		t.Fatal(err)
	}
	families := 0
	for _, e := range entries {
		if !strings.HasSuffix(e.Name(), ".jsonl") {
			continue
		}
		data, err := embedded.ReadFile("vectors/" + e.Name())
		if err != nil {
			t.Fatal(err)
		}
		if !fastAgrees(t, data) {
			t.Errorf("%s: the fast path declined a golden family", e.Name())
		}
		families++
	}
	if families == 0 {
		t.Fatal("no embedded family")
	}
}

// fastSample is a header naming a family, and a golden vector line holding every kind of member
// the schema gives one: strings, lists, device values of both types, an operand, steps, an
// alternative with its outcome, `printed`.
func fastSample(t testing.TB) (header, line []byte) {
	t.Helper()
	data, err := embedded.ReadFile("vectors/fx5-time-add.jsonl")
	if err != nil {
		t.Fatal(err)
	}
	lines := jsonlLines(data)
	for _, l := range lines[1:] {
		if bytes.Contains(l, []byte(`"alternatives":[{`)) && bytes.Contains(l, []byte(`"printed":`)) &&
			bytes.Contains(l, []byte(`true`)) && (line == nil || len(l) < len(line)) {
			line = l
		}
	}
	if line == nil {
		t.Fatal("fx5-time-add holds no vector with alternatives and `printed`")
	}
	// A header of the family's name alone: what the fast path does with a header (encoding/json
	// decodes it) the embedded set's test covers, and the family's own, decoded for every
	// damaged line, was most of this test's time.
	return []byte(`{"family":"fx5-time-add"}`), line
}

// fileOf is an exported family file of a header and vector lines.
func fileOf(header []byte, lines ...[]byte) []byte {
	return append(bytes.Join(append([][]byte{header}, lines...), []byte("\n")), '\n')
}

// damaged are edits of a sound vector line, each something the fast path must decline or decode
// as encoding/json does: (old, new) replaced once, at its first place.
var damaged = []struct{ old, new string }{
	{`"id":`, `"id":"x","id":`},                                                     // a repeated field
	{`"id":`, `"ID":`},                                                              // another case (encoding/json takes it)
	{`"id":`, `"i\u0064":`},                                                         // a key with an escape
	{`"id":`, `"idx":`},                                                             // an unknown key
	{`"devices":{`, `"devices":{"D1":1,"D1":2,`},                                    // a repeated device
	{`"devices":{`, `"devices":{"D1":1,"D\u0031":2,`},                               // the same device, escaped
	{`"devices":{`, `"devices":{"D1":65536,`},                                       // a word out of range
	{`"devices":{`, `"devices":{"D1":-1,`},                                          // a negative word
	{`"devices":{`, `"devices":{"D1":1.0,`},                                         // a fraction
	{`"devices":{`, `"devices":{"D1":1e2,`},                                         // an exponent
	{`"devices":{`, `"devices":{"D1":0012,`},                                        // leading zeros
	{`"devices":{`, `"devices":{"D1":"1",`},                                         // a string for a value
	{`"devices":{`, `"devices":{"D1":null,`},                                        // null
	{`"devices":{`, `"devices":{"D1":truex,`},                                       // a longer word
	{`"devices":{`, `"devices":{"D1":65535,"D2":0,"D3":true,"D4":false,`},           // the bounds
	{`"devices":{`, `"devices" : { "D1" : 7 ,`},                                     // blanks
	{`"devices":{`, "\"devices\":{\"D1\"\t:\r7,"},                                   // other blanks
	{`"steps":[{`, `"steps":[{"elapsed_ms":99999999999999999999,`},                  // overflows int64
	{`"steps":[{`, `"steps":[{"elapsed_ms":999999999999999999,`},                    // 18 digits
	{`"steps":[{`, `"steps":[{"elapsed_ms":-5,`},                                    // negative
	{`"steps":[{`, `"steps":[{"elapsed_ms":-0,`},                                    // minus zero
	{`"steps":[{`, `"steps":[{"rlo_in":1,`},                                         // a number for a bool
	{`"steps":[{`, `"steps":[{"input":false,"en":true,"rlo_in":true,`},              // every input given
	{`"steps":[{`, `"steps":[{"clock":{"hour":25,"hour":1},`},                       // a repeated clock field
	{`"steps":[{`, `"steps":[{"clock":{"hour":2147483648},`},                        // past int32
	{`"steps":[{`, `"steps":[{"clock":{},"set":{},`},                                // empty objects
	{`"tags":[`, `"tags":["a\"b\\c\/d\n\t\b\f\r",`},                                 // escapes
	{`"tags":[`, `"tags":["\u00e9",`},                                               // a \u escape
	{`"tags":[`, `"tags":["\ud800",`},                                               // a lone surrogate
	{`"tags":[`, `"tags":["a` + "\x01" + `",`},                                      // a control byte
	{`"tags":[`, `"tags":["` + "\xff" + `",`},                                       // not UTF-8
	{`"tags":[`, `"tags":["é€😀",`},                                                  // UTF-8
	{`"tags":[`, `"tags":[,`},                                                       // an empty element
	{`"tags":[`, `"tags":[1,`},                                                      // a number for a string
	{`"tags":[`, `"tags":[],"x":[`},                                                 // an unknown key after
	{`"printed":{`, `"printed":{"z":1,"z":2,`},                                      // a repeated key in `printed`
	{`"printed":{`, `"printed":{"z":[1,{"b":"}"}],`},                                // brackets in a string
	{`"printed":{`, `"printed":{"z":tru,`},                                          // not JSON in `printed`
	{`"operands":{`, `"operands":{"n":{"constant":-7},`},                            // a constant
	{`"operands":{`, `"operands":{"n":{"constant":7,"device":"D1"},`},               // both
	{`"operands":{`, `"operands":{"n":{"constant":7.5},`},                           // a fractional constant
	{`"operands":{`, `"operands":{"n":{},`},                                         // neither
	{`"outcome":{`, `"outcome":{"errors":[{"step":0,"code":1,"device":"SD0"},{}],`}, // errors
	{`"outcome":{`, `"outcome":{"default":{"category":"x","default":{}},`},          // nested default
	{`"choices":{`, `"choices":{"A":"x","A":"y",`},                                  // a repeated choice
	{`"choices":{`, `"choices":{"A":1,`},                                            // a number for a choice
	{`"final":{`, `"final":{"devices":{},"devices":{},`},                            // a repeated map
	{`"alternatives":[`, `"alternatives":[{"unjudged":{"X":["D1"],"Y":[]}},`},       // unjudged
	{`"alternatives":[`, `"alternatives":[{"unjudged":{"X":["D1"],"X":[]}},`},       // a repeated one
	{`{`, ` {`},   // a blank before the value
	{`{`, `[{`},   // an array
	{`{`, `{}{`},  // two values
	{`{`, `{},{`}, // two values, a comma between
}

// damagedValues are edits of a value of a sound vector line: the first match of the pattern
// replaced.
var damagedValues = []struct{ pattern, new string }{
	{`"instruction":"[^"]*"`, `"instruction":null`},                        // null for a string
	{`"printed":\{[^{}]*(\{[^{}]*\}[^{}]*)*\}`, `"printed":null`},          // null for `printed`
	{`"printed":\{[^{}]*(\{[^{}]*\}[^{}]*)*\}`, `"printed":[1,"x",{}]`},    // an array
	{`"printed":\{[^{}]*(\{[^{}]*\}[^{}]*)*\}`, `"printed":{ "a" : [ ] }`}, // blanks kept
	{`"printed":\{[^{}]*(\{[^{}]*\}[^{}]*)*\}`, `"printed":7`},             // a number
	{`"en":true`, `"en":"true"`},                                           // a string for a bool
	{`"category":"[^"]*"`, `"category":["value"]`},                         // a list for a string
}

// TestFastDecodeOfDamagedLines: every damaged line of the table, every prefix of a sound line,
// and the line with each byte replaced by a few that change its structure: the fast path
// declines each or decodes it as encoding/json does.
func TestFastDecodeOfDamagedLines(t *testing.T) {
	header, line := fastSample(t)
	if !fastAgrees(t, fileOf(header, line)) {
		t.Fatal("the fast path declined a sound line")
	}
	took := 0
	for _, c := range damaged {
		if !bytes.Contains(line, []byte(c.old)) {
			t.Fatalf("the sample line holds no %s", c.old)
		}
		edited := bytes.Replace(line, []byte(c.old), []byte(c.new), 1)
		if fastAgrees(t, fileOf(header, edited)) {
			took++
		}
		for _, trailing := range []string{" ", "\t\r", "x", "}", "\n", "\n\n", "\n{}"} {
			fastAgrees(t, fileOf(header, append(append([]byte(nil), edited...), trailing...)))
		}
	}
	for _, c := range damagedValues {
		at := regexp.MustCompile(c.pattern).FindIndex(line)
		if at == nil {
			t.Fatalf("the sample line holds no %s", c.pattern)
		}
		edited := append(append(append([]byte(nil), line[:at[0]]...), c.new...), line[at[1]:]...)
		if fastAgrees(t, fileOf(header, edited)) {
			took++
		}
	}
	if took == 0 || took == len(damaged)+len(damagedValues) {
		t.Errorf("the fast path took %d of %d damaged lines: the table tests one way only", took, len(damaged)+len(damagedValues))
	}
	for end := range line {
		fastAgrees(t, fileOf(header, line[:end]))
	}
	for i := range line {
		for _, b := range []byte{'"', '}', ',', ':', '\\', 0xff} {
			edited := append([]byte(nil), line...)
			edited[i] = b
			fastAgrees(t, fileOf(header, edited))
		}
	}
	fastAgrees(t, fileOf(header, line, line))
	fastAgrees(t, fileOf(header))
	fastAgrees(t, fileOf(append(append([]byte(nil), header...), ' '), line))
	fastAgrees(t, fileOf(append(append([]byte(nil), header...), '}'), line))
}

// FuzzFastDecode: any vector line (go test -fuzz FuzzFastDecode); the damaged table is its seed.
func FuzzFastDecode(f *testing.F) {
	header, line := fastSample(f)
	f.Add(line)
	for _, c := range damaged {
		f.Add(bytes.Replace(line, []byte(c.old), []byte(c.new), 1))
	}
	f.Fuzz(func(t *testing.T, line []byte) {
		fastAgrees(t, fileOf(header, line))
	})
}
