package plcvec

import "testing"

// TestValueShown: a value shows as the vector files write it, and a number an implementation
// reports outside the word range shows as the number it is (TEXT.md, "How values are shown"):
// never a bit, never clamped.
func TestValueShown(t *testing.T) {
	minusOne := -1
	for _, c := range []struct {
		v     Value
		shown string
		bit   bool
		valid bool
	}{
		{Word(0), "0", false, true},
		{Word(65535), "65535", false, true},
		{Bit(false), "false", true, true},
		{Bit(true), "true", true, true},
		{Value(65536), "65536", false, false}, // one above the range: not the bit false
		{Value(65537), "65537", false, false}, // not the bit true
		{Value(70000), "70000", false, false},
		{Value(uint32(minusOne)), "-1", false, false}, // the implementation's -1, wrapped
	} {
		if got := c.v.String(); got != c.shown {
			t.Errorf("Value(%d).String() = %q; want %q", uint32(c.v), got, c.shown)
		}
		if c.v.IsBit() != c.bit || c.v.Valid() != c.valid {
			t.Errorf("Value(%d): IsBit %v, Valid %v; want %v, %v", uint32(c.v), c.v.IsBit(), c.v.Valid(), c.bit, c.valid)
		}
	}
	// A bit read as a word is 0 or 1, a word read as a bit is true when not 0.
	if Bit(true).Word() != 1 || Bit(false).Word() != 0 || !Word(2).Bit() || Word(0).Bit() {
		t.Error("a bit does not read as 0/1, or a word not as a bit")
	}
	if Bit(true) == Word(1) || Value(65536) == Bit(false) {
		t.Error("values of two JSON types compare equal")
	}
}
