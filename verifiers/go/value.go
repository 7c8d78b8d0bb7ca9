package plcvec

import (
	"fmt"
	"strconv"
)

// Value is the value of one device: a word (the raw 16 bits, 0..65535) or a bit (true/false).
// The two are different values even when they read alike: the contract compares the JSON type,
// so Bit(true) is never Word(1). A Value is comparable with ==, which compares the type too.
type Value uint32

// bitTag marks a bit; a word is its 16 bits alone.
const bitTag Value = 1 << 16

// Word is a word device's value.
func Word(w uint16) Value { return Value(w) }

// Bit is a bit device's value.
func Bit(b bool) Value {
	if b {
		return bitTag | 1
	}
	return bitTag
}

// IsBit reports whether v is a bit (true/false) rather than a word.
func (v Value) IsBit() bool { return v&bitTag != 0 }

// Word returns the 16 bits of a word (a bit reads as 0 or 1).
func (v Value) Word() uint16 { return uint16(v) }

// Bit returns a bit's state (a word reads as true when it is not 0).
func (v Value) Bit() bool { return uint16(v) != 0 }

// Valid reports whether v is a word (0..65535) or a bit: a Value built from a number out of
// range (Value(70000)) is neither, and never equals an expected value.
func (v Value) Valid() bool { return v <= 0xFFFF || v == Bit(false) || v == Bit(true) }

// String shows v as the vector files write it: 13, 65535, true, false.
func (v Value) String() string {
	if !v.Valid() {
		return strconv.FormatUint(uint64(v), 10) + " (neither a word 0..65535 nor a bit)"
	}
	if v.IsBit() {
		return strconv.FormatBool(v.Bit())
	}
	return strconv.Itoa(int(v.Word()))
}

// MarshalJSON writes a bit as true/false and a word as an integer.
func (v Value) MarshalJSON() ([]byte, error) { return []byte(v.String()), nil }

// UnmarshalJSON reads true/false as a bit and an integer 0..65535 as a word; anything else
// (1.5, -1, 70000, "7", null) is refused, so a damaged vector file is not half-read.
func (v *Value) UnmarshalJSON(b []byte) error {
	switch s := string(b); s {
	case "true":
		*v = Bit(true)
	case "false":
		*v = Bit(false)
	default:
		n, err := strconv.ParseUint(s, 10, 16)
		if err != nil {
			return fmt.Errorf("a device value is true, false or an integer 0..65535, not %s", s)
		}
		*v = Word(uint16(n))
	}
	return nil
}

// Device is one named device and its value.
type Device struct {
	Name  string
	Value Value
}
