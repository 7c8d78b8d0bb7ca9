package plcvec

import (
	"bytes"
	"encoding/json"
	"unicode/utf8"
)

// Every run loads the whole vector set before it judges, and encoding/json, which finds each
// key's field and each value's type by reflection, was some two thirds of a load; the check of
// repeated keys, a second pass over every line, a tenth more. fastJSONL decodes an exported family
// file's vectors by hand instead, over exactly the shapes the schema gives a vector, in the one
// pass that also rules out repeated keys. It is a shortcut and never a judge: it takes only text
// that encoding/json takes too and decodes to the very same values (fastdecode_test.go decodes
// every embedded family both ways and compares them, and damaged lines with a fuzz target), and
// on anything else (an unknown key, a key written in another case or with an escape, a value of
// another type, a repeated key, null, a number out of range or written with a fraction or an
// exponent, a \u escape, text after a line's value, bytes that are not UTF-8) it declines, and
// the file is decoded the way it always was, which finds the fault and words it.

// fastJSONL decodes an exported family file's header (line 1, by encoding/json, as streamJSONL
// reads it) and its vectors (by hand). ok is true only when every line decoded so and no object
// of a vector line repeats a key: the caller then need not look for repeated keys in them.
func fastJSONL(data []byte, lines [][]byte) (header *FamilyHeader, vectors []*Vector, ok bool) {
	if !utf8.Valid(data) {
		return nil, nil, false
	}
	// The header: one line a file, decoded as streamJSONL decodes it (a value of line 1 alone,
	// nothing but blanks after it).
	dec := json.NewDecoder(bytes.NewReader(lines[0]))
	dec.DisallowUnknownFields()
	header = &FamilyHeader{}
	if dec.Decode(header) != nil || len(bytes.Trim(lines[0][dec.InputOffset():], " \t\r")) > 0 {
		return nil, nil, false
	}
	d := fastDecoder{names: map[string]string{}}
	vectors = make([]*Vector, 0, len(lines)-1)
	for _, line := range lines[1:] {
		d.data, d.i, d.failed = line, 0, false
		v := &Vector{}
		d.vector(v)
		d.space()
		if d.failed || d.i != len(line) {
			return nil, nil, false
		}
		vectors = append(vectors, v)
	}
	return header, vectors, true
}

// fastDecoder reads one line's JSON. A method that meets anything it does not take sets failed
// and returns a zero value; once failed, every method does nothing, and the line is declined.
type fastDecoder struct {
	data   []byte
	i      int
	failed bool
	key    []byte            // the key member read, as written (never with an escape)
	names  map[string]string // a string value read before, to give the same name one copy
	// The number of devices of the last full image read (`initial`, `final`): the next is
	// made that size, the size a vector's images mostly share, rather than grown to it.
	image int
	keys  keyScanner // for `printed`, the one value read as it is written
}

func (d *fastDecoder) fail() { d.failed = true }

// space skips JSON's blanks.
func (d *fastDecoder) space() {
	for d.i < len(d.data) {
		switch d.data[d.i] {
		case ' ', '\t', '\r', '\n':
			d.i++
		default:
			return
		}
	}
}

// peek is the next byte after blanks, or 0 at the end.
func (d *fastDecoder) peek() byte {
	d.space()
	if d.failed || d.i >= len(d.data) {
		return 0
	}
	return d.data[d.i]
}

// open reads the byte that opens an object or an array ('{' or '[').
func (d *fastDecoder) open(c byte) {
	if d.peek() != c {
		d.fail()
		return
	}
	d.i++
}

// next moves to the next member or element of the object or array open at d, which close
// ends: false at its end (close read) or on failure. first is true before the first.
func (d *fastDecoder) next(first *bool, close byte) bool {
	c := d.peek()
	switch {
	case d.failed:
		return false
	case c == close:
		d.i++
		return false
	case !*first:
		if c != ',' {
			d.fail()
			return false
		}
		d.i++
	}
	*first = false
	return true
}

// member reads the next member of the object open at d up to its value: its key into d.key and
// the colon. It is false at the object's end or on failure.
func (d *fastDecoder) member(first *bool) bool {
	if !d.next(first, '}') {
		return false
	}
	if d.peek() != '"' {
		d.fail()
		return false
	}
	d.key = d.rawString()
	if d.peek() != ':' {
		d.fail()
		return false
	}
	d.i++
	return !d.failed
}

// element is member for an array.
func (d *fastDecoder) element(first *bool) bool { return d.next(first, ']') }

// rawString reads a string with no escape and returns its bytes (in d.data). A control byte is
// not JSON; an escape is declined, as in a key it would make another key read alike.
func (d *fastDecoder) rawString() []byte {
	start := d.i + 1
	for j := start; j < len(d.data); j++ {
		switch c := d.data[j]; {
		case c == '"':
			d.i = j + 1
			return d.data[start:j]
		case c == '\\' || c < 0x20:
			d.fail()
			return nil
		}
	}
	d.fail()
	return nil
}

// string reads a string value. The escapes JSON writes with one letter are decoded; \u is
// declined (a lone surrogate is decoded by rules of encoding/json's own).
func (d *fastDecoder) string() string {
	if d.peek() != '"' {
		d.fail()
		return ""
	}
	start := d.i + 1
	for j := start; j < len(d.data); j++ {
		switch c := d.data[j]; {
		case c == '"':
			d.i = j + 1
			return d.name(d.data[start:j])
		case c == '\\':
			return d.escapedString(start)
		case c < 0x20:
			d.fail()
			return ""
		}
	}
	d.fail()
	return ""
}

// escapedString reads the string that opens before start and holds an escape.
func (d *fastDecoder) escapedString(start int) string {
	var out []byte
	for j := start; j < len(d.data); j++ {
		c := d.data[j]
		switch {
		case c == '"':
			d.i = j + 1
			return string(out)
		case c < 0x20:
			d.fail()
			return ""
		case c != '\\':
			out = append(out, c)
			continue
		}
		if j++; j >= len(d.data) {
			break
		}
		switch d.data[j] {
		case '"', '\\', '/':
			out = append(out, d.data[j])
		case 'b':
			out = append(out, '\b')
		case 'f':
			out = append(out, '\f')
		case 'n':
			out = append(out, '\n')
		case 'r':
			out = append(out, '\r')
		case 't':
			out = append(out, '\t')
		default:
			d.fail()
			return ""
		}
	}
	d.fail()
	return ""
}

// name is the string b as one copy for every time the line set holds it: device names, keys,
// categories and tags repeat by the thousand.
func (d *fastDecoder) name(b []byte) string {
	if s, ok := d.names[string(b)]; ok {
		return s
	}
	s := string(b)
	d.names[s] = s
	return s
}

// digits reads a JSON number that is an integer of at most max digits, with a minus sign when
// signed, and returns it; a fraction, an exponent, more digits or a leading 0 is declined.
func (d *fastDecoder) digits(max int, signed bool) (n int64) {
	d.space()
	negative := false
	if signed && d.i < len(d.data) && d.data[d.i] == '-' {
		negative = true
		d.i++
	}
	start := d.i
	for d.i < len(d.data) && d.data[d.i] >= '0' && d.data[d.i] <= '9' {
		n = n*10 + int64(d.data[d.i]-'0')
		d.i++
	}
	count := d.i - start
	switch {
	case count == 0 || count > max || count > 1 && d.data[start] == '0':
		d.fail()
	case d.i < len(d.data):
		if c := d.data[d.i]; c == '.' || c == 'e' || c == 'E' {
			d.fail()
		}
	}
	if negative {
		n = -n
	}
	return n
}

// int reads an int: at most 9 digits, so that it fits the narrowest int Go has.
func (d *fastDecoder) int() int {
	return int(d.digits(9, true))
}

// int64 reads an int64: at most 18 digits.
func (d *fastDecoder) int64() int64 {
	return d.digits(18, true)
}

// literal reads the word w (true or false).
func (d *fastDecoder) literal(w string) bool {
	if !bytes.HasPrefix(d.data[d.i:], []byte(w)) {
		return false
	}
	end := d.i + len(w)
	if end < len(d.data) && (d.data[end] >= 'a' && d.data[end] <= 'z' || d.data[end] >= '0' && d.data[end] <= '9') {
		return false // trues, false0: a longer word, not JSON
	}
	d.i = end
	return true
}

// bool reads true or false.
func (d *fastDecoder) bool() bool {
	switch d.peek() {
	case 't':
		if d.literal("true") {
			return true
		}
	case 'f':
		if d.literal("false") {
			return false
		}
	}
	d.fail()
	return false
}

// value reads a device value as Value.UnmarshalJSON does: true, false or an integer 0..65535.
func (d *fastDecoder) value() Value {
	switch d.peek() {
	case 't', 'f':
		return Bit(d.bool())
	}
	n := d.digits(5, false)
	if n > 0xFFFF {
		d.fail()
	}
	return Word(uint16(n))
}

// list reads an array, each element by read (never nil, as encoding/json makes [] an empty
// slice).
func list[T any](d *fastDecoder, read func(*fastDecoder, *T)) []T {
	out := []T{}
	d.open('[')
	for first := true; d.element(&first); {
		out = append(out, *new(T))
		read(d, &out[len(out)-1])
	}
	return out
}

// object reads an object into a map made for size members, each value by read; a key given
// twice is declined (encoding/json would keep the last; the check of repeated keys refuses it).
func object[T any](d *fastDecoder, size int, read func(*fastDecoder) T) map[string]T {
	out := make(map[string]T, size)
	d.open('{')
	for first := true; d.member(&first); {
		name := d.name(d.key)
		if _, repeated := out[name]; repeated {
			d.fail()
		}
		out[name] = read(d)
	}
	return out
}

// strings reads an array of strings.
func (d *fastDecoder) strings() []string {
	return list(d, func(d *fastDecoder, s *string) { *s = d.string() })
}

// values reads an object of device values, into a map made for size of them.
func (d *fastDecoder) values(size int) map[string]Value {
	return object(d, size, (*fastDecoder).value)
}

// fields reads an object into a struct: field reads the value of the member d.key names and
// returns the field's bit (one bit a field), or 0, reading nothing, for a key the struct does
// not have. A field given twice is declined.
func (d *fastDecoder) fields(field func() uint32) {
	var seen uint32
	d.open('{')
	for first := true; d.member(&first); {
		bit := field()
		if bit == 0 || seen&bit != 0 {
			d.fail()
		}
		seen |= bit
	}
}

// vector reads a Vector.
func (d *fastDecoder) vector(v *Vector) {
	d.fields(func() uint32 {
		switch string(d.key) {
		case "id":
			v.ID = d.string()
			return 1 << 0
		case "family":
			v.Family = d.string()
			return 1 << 1
		case "instruction":
			v.Instruction = d.string()
			return 1 << 2
		case "st":
			v.ST = d.string()
			return 1 << 3
		case "description":
			v.Description = d.string()
			return 1 << 4
		case "tags":
			v.Tags = d.strings()
			return 1 << 5
		case "clauses":
			v.Clauses = d.strings()
			return 1 << 6
		case "assumes":
			d.fields(func() uint32 {
				if string(d.key) != "device_sizes" {
					return 0
				}
				v.Assumes.DeviceSizes = object(d, 0, (*fastDecoder).int)
				return 1
			})
			return 1 << 7
		case "initial":
			v.Initial = &Initial{}
			d.initial(v.Initial)
			return 1 << 8
		case "steps":
			v.Steps = list(d, (*fastDecoder).step)
			return 1 << 9
		case "final":
			v.Final = &State{}
			d.state(v.Final)
			return 1 << 10
		case "outcome":
			v.Outcome = &Outcome{}
			d.outcome(v.Outcome)
			return 1 << 11
		case "alternatives":
			v.Alternatives = list(d, (*fastDecoder).alternative)
			return 1 << 12
		case "printed":
			v.Printed = d.raw()
			return 1 << 13
		}
		return 0
	})
}

func (d *fastDecoder) initial(in *Initial) {
	d.fields(func() uint32 {
		switch string(d.key) {
		case "devices":
			in.Devices = d.values(d.image)
			d.image = len(in.Devices)
			return 1 << 0
		case "operands":
			in.Operands = object(d, 0, (*fastDecoder).operand)
			return 1 << 1
		case "scratch":
			in.Scratch = d.strings()
			return 1 << 2
		}
		return 0
	})
}

func (d *fastDecoder) operand() (o Operand) {
	d.fields(func() uint32 {
		switch string(d.key) {
		case "device":
			o.Device = d.string()
			return 1 << 0
		case "constant":
			n := d.int()
			o.Constant = &n
			return 1 << 1
		}
		return 0
	})
	return o
}

// step reads a Step as Step.UnmarshalJSON does, noting the inputs it gives.
func (d *fastDecoder) step(s *Step) {
	d.fields(func() uint32 {
		switch string(d.key) {
		case "set":
			s.Set = d.values(0)
			return 1 << 0
		case "rlo_in":
			s.RLOIn, s.given = d.bool(), s.given|givesRLOIn
			return 1 << 1
		case "clock":
			s.Clock = object(d, 0, (*fastDecoder).int)
			return 1 << 2
		case "en":
			s.EN, s.given = d.bool(), s.given|givesEN
			return 1 << 3
		case "input":
			s.Input, s.given = d.bool(), s.given|givesInput
			return 1 << 4
		case "elapsed_ms":
			s.ElapsedMS, s.given = d.int64(), s.given|givesElapsed
			return 1 << 5
		case "expect":
			s.Expect = &Expect{}
			d.expect(s.Expect)
			return 1 << 6
		}
		return 0
	})
}

func (d *fastDecoder) expect(e *Expect) {
	d.fields(func() uint32 {
		switch string(d.key) {
		case "result":
			b := d.bool()
			e.Result = &b
			return 1 << 0
		case "devices":
			e.Devices = d.values(0)
			return 1 << 1
		}
		return 0
	})
}

func (d *fastDecoder) state(s *State) {
	d.fields(func() uint32 {
		if string(d.key) != "devices" {
			return 0
		}
		s.Devices = d.values(d.image)
		d.image = len(s.Devices)
		return 1
	})
}

func (d *fastDecoder) outcome(o *Outcome) {
	d.fields(func() uint32 {
		switch string(d.key) {
		case "category":
			o.Category = d.string()
			return 1 << 0
		case "interpretations":
			o.Interpretations = d.strings()
			return 1 << 1
		case "reason":
			o.Reason = d.string()
			return 1 << 2
		case "default":
			o.Default = &Outcome{}
			d.outcome(o.Default)
			return 1 << 3
		case "errors":
			o.Errors = list(d, (*fastDecoder).outcomeError)
			return 1 << 4
		}
		return 0
	})
}

func (d *fastDecoder) outcomeError(e *OutcomeError) {
	d.fields(func() uint32 {
		switch string(d.key) {
		case "step":
			e.Step = d.int()
			return 1 << 0
		case "code":
			e.Code = d.int()
			return 1 << 1
		case "device":
			e.Device = d.string()
			return 1 << 2
		}
		return 0
	})
}

func (d *fastDecoder) alternative(a *Alternative) {
	d.fields(func() uint32 {
		switch string(d.key) {
		case "choices":
			a.Choices = object(d, 0, (*fastDecoder).string)
			return 1 << 0
		case "expect":
			a.Expect = list(d, (*fastDecoder).expect)
			return 1 << 1
		case "final":
			d.state(&a.Final)
			return 1 << 2
		case "outcome":
			d.outcome(&a.Outcome)
			return 1 << 3
		case "unjudged":
			a.Unjudged = object(d, 0, (*fastDecoder).strings)
			return 1 << 4
		}
		return 0
	})
}

// raw reads `printed`, which the runner keeps as written: an object or an array, its end found by
// its brackets, then checked by encoding/json's own validator and for repeated keys; a copy of
// its text, as json.RawMessage keeps it.
func (d *fastDecoder) raw() json.RawMessage {
	c := d.peek()
	if c != '{' && c != '[' {
		d.fail()
		return nil
	}
	start, depth := d.i, 0
	for ; d.i < len(d.data); d.i++ {
		switch d.data[d.i] {
		case '"':
			d.i = stringEnd(d.data, d.i)
		case '{', '[':
			depth++
		case '}', ']':
			if depth--; depth == 0 {
				d.i++
				text := d.data[start:d.i]
				if !json.Valid(text) || d.repeats(text) {
					d.fail()
					return nil
				}
				return append(json.RawMessage(nil), text...)
			}
		}
	}
	d.fail()
	return nil
}

// repeats reports whether an object of the valid JSON text repeats a key.
func (d *fastDecoder) repeats(text []byte) bool {
	at, _ := d.keys.scan(text)
	return at >= 0
}
