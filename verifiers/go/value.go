package plcvec

import (
	"fmt"
	"strconv"
)

// Value is the value of one device: a word (the raw 16 bits, 0..65535) or a bit (true/false).
// The two are different values even when they read alike: the contract compares the JSON type,
// so Bit(true) is never Word(1). A Value is comparable with ==, which compares the type too.
//
// A Value made from a number outside the word range (Value(65536), Value(70000)) is that number,
// never a bit, and never equals an expected value: a failure shows it as the integer it is
// (verifiers/parity/TEXT.md, "How values are shown"). The two bits are kept at the top of the
// range a 31-bit count can reach, where no plausible arithmetic lands, with low 16 bits of 0 and 1:
// read as a word, a bit is 0 or 1 by its low 16 bits as a word is, with no test (Memory.ReadWords
// reads every word of a vector's operands so).
type Value uint32

const (
	bitFalse Value = 0x7FFF_0000
	bitTrue  Value = 0x7FFF_0001 // bitFalse | 1: IsBit tests both at once
)

// Word is a word device's value.
func Word(w uint16) Value { return Value(w) }

// Bit is a bit device's value.
func Bit(b bool) Value {
	if b {
		return bitTrue
	}
	return bitFalse
}

// IsBit reports whether v is a bit (true/false) rather than a word.
func (v Value) IsBit() bool { return v|1 == bitTrue }

// Word returns the 16 bits of a word (a bit reads as 0 or 1).
func (v Value) Word() uint16 { return uint16(v) }

// Bit returns a bit's state (a word reads as true when it is not 0).
func (v Value) Bit() bool {
	if v.IsBit() {
		return v == bitTrue
	}
	return v != 0
}

// Valid reports whether v is a word (0..65535) or a bit: a Value built from a number out of
// range (Value(70000)) is neither, and never equals an expected value.
func (v Value) Valid() bool { return v <= 0xFFFF || v.IsBit() }

// String shows v as the vector files write it: 13, 65535, true, false; a number outside the word
// range as its digits (70000), and one that wrapped below 0 in the implementation's arithmetic
// (a uint32 conversion of -1) as the negative number it was.
func (v Value) String() string {
	switch {
	case v.IsBit():
		return strconv.FormatBool(v == bitTrue)
	case v >= 1<<31:
		return strconv.Itoa(int(int32(v)))
	}
	return strconv.FormatUint(uint64(v), 10)
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
