package plcvec

import (
	"errors"
	"testing"
)

// A memory finds every device by its address, whatever its name looks like: the lookup keys
// are exact for PLC names (D100, SM709, P_EQ) and fall back to comparing addresses for any
// other, so two addresses never share a slot.
func TestMemoryFindsEveryDevice(t *testing.T) {
	devices := map[string]Value{
		"D100": Word(1), "D101": Word(2), "D102": Word(3), "D1000": Word(4), // D1000 sorts between D100 and D101
		"D200": Word(12), "D201": Word(13), "D202": Word(14), "SM201": Bit(false), // a run of words, then another kind
		"D0": Word(5), "D4294967296": Word(6), "D8589934592": Word(7), // numbers past 32 bits
		"SM709": Bit(true), "P_EQ": Bit(false), "P_NE": Bit(true), // names without a number
		"LONGKIND7": Word(8), "LONGKINE7": Word(9), "Dé5": Word(10), "D\x005": Word(11), // kinds past 4 bytes, not ASCII, a NUL
	}
	req := NewRequest("t", "f", "I", nil, devices, map[string]Operand{}, nil, []Inputs{{}})
	if req.table == nil {
		t.Fatal("no lookup table")
	}
	t.Run("table", func(t *testing.T) { checkMemory(t, req, devices) })
	// A request too large for a table is scanned instead.
	req = NewRequest("t", "f", "I", nil, devices, map[string]Operand{}, nil, []Inputs{{}})
	req.table = nil
	t.Run("scan", func(t *testing.T) { checkMemory(t, req, devices) })
}

func checkMemory(t *testing.T, req *Request, devices map[string]Value) {
	mem := NewMemory(req)
	for name, want := range devices {
		if got, ok := mem.Get(ParseAddr(name)); !ok || got != want {
			t.Errorf("Get(%s) = %v, %v; want %v", name, got, ok, want)
		}
	}
	words := make([]uint16, 3)
	mem.ReadWords(ParseAddr("D100"), words)
	if words[0] != 1 || words[1] != 2 || words[2] != 3 {
		t.Errorf("ReadWords(D100, 3) = %v; want [1 2 3]", words)
	}
	mem.SetWords(ParseAddr("D100"), 7, 8, 9)
	for name, want := range map[string]uint16{"D100": 7, "D101": 8, "D102": 9, "D1000": 4} {
		if got := mem.Word(ParseAddr(name)); got != want {
			t.Errorf("after SetWords(D100, 7, 8, 9): %s = %d; want %d", name, got, want)
		}
	}
	mem.ReadWords(ParseAddr("D200"), words)
	if words[0] != 12 || words[1] != 13 || words[2] != 14 {
		t.Errorf("ReadWords(D200, 3) = %v; want [12 13 14]", words)
	}
	mem.SetWords(ParseAddr("D201"), 30, 31)
	mem.ReadWords(ParseAddr("D200"), words)
	if words[0] != 12 || words[1] != 30 || words[2] != 31 || mem.Bit(ParseAddr("SM201")) {
		t.Errorf("after SetWords(D201, 30, 31): D200.. = %v, SM201 = %v; want [12 30 31], false", words, mem.Bit(ParseAddr("SM201")))
	}
	// Words past the vector's devices are writes outside it, kept apart.
	mem.SetWords(ParseAddr("D101"), 20, 21, 22)
	if mem.Word(ParseAddr("D102")) != 21 || mem.Word(ParseAddr("D103")) != 22 {
		t.Errorf("SetWords(D101, 20, 21, 22): D102 = %d, D103 = %d; want 21, 22",
			mem.Word(ParseAddr("D102")), mem.Word(ParseAddr("D103")))
	}
	if len(mem.outside) != 1 || mem.outside[0] != (Device{"D103", Word(22)}) {
		t.Errorf("writes outside the vector = %v; want [{D103 22}]", mem.outside)
	}
	mem.SetBit(ParseAddr("P_LT"), true)
	if v, ok := mem.Get(ParseAddr("P_LT")); !ok || v != Bit(true) {
		t.Errorf("P_LT written outside the vector reads %v, %v", v, ok)
	}
	// A fresh memory of the same request starts from the initial image again.
	if again := NewMemory(req); again.Word(ParseAddr("D100")) != 1 || len(again.outside) != 0 {
		t.Errorf("a new memory kept the last one's writes")
	}
}

// A request of PLC names alone keeps no addresses: its keys say it all, and a look-up of any
// other name finds nothing.
func TestMemoryOfExactNames(t *testing.T) {
	devices := map[string]Value{"D100": Word(1), "D101": Word(2), "SM709": Bit(true), "P_EQ": Bit(false)}
	req := NewRequest("t", "f", "I", nil, devices, map[string]Operand{}, nil, []Inputs{{}})
	if req.addrs != nil {
		t.Errorf("addresses kept for exact names: %v", req.addrs)
	}
	mem := NewMemory(req)
	for name, want := range devices {
		if got, ok := mem.Get(ParseAddr(name)); !ok || got != want {
			t.Errorf("Get(%s) = %v, %v; want %v", name, got, ok, want)
		}
	}
	for _, name := range []string{"LONGKIND100", "D4294967396", "P_EQX", "D102"} {
		if got, ok := mem.Get(ParseAddr(name)); ok {
			t.Errorf("Get(%s) = %v; want nothing", name, got)
		}
	}
}

// An exact key (a PLC name) never equals the key of an address that needs comparing.
func TestAddrKeys(t *testing.T) {
	exact := []Address{{"D", 0}, {"D", 100}, {"SM", 709}, {"P_EQ", -1}, {"ABCD", 1<<31 - 1}, {"D\x7F", 1}, {"D\x01", 1}}
	inexact := []Address{{"D", 1 << 32}, {"D", -2}, {"LONGKIND", 7}, {"Dé", 5}, {"D\x00", 5}, {"", 3}, {"ABC\x80", 1}, {"\x00", 0}, {"SMALL", 1}}
	seen := map[uint64]Address{}
	for _, a := range exact {
		key, ok := addrKey(a)
		if !ok {
			t.Errorf("addrKey(%v) is not exact", a)
		}
		if b, dup := seen[key]; dup {
			t.Errorf("addrKey(%v) = addrKey(%v)", a, b)
		}
		seen[key] = a
	}
	for _, a := range inexact {
		key, ok := addrKey(a)
		if ok {
			t.Errorf("addrKey(%v) claims to be exact", a)
		}
		if b, dup := seen[key]; dup {
			t.Errorf("addrKey(%v) = addrKey(%v), an exact key", a, b)
		}
	}
}

func TestClockField(t *testing.T) {
	req := NewRequest("t", "f", "I", nil, map[string]Value{}, map[string]Operand{}, nil,
		[]Inputs{{Clock: map[string]int{"hour": 23, "minute": 59}}})
	unprepared := Inputs{Clock: map[string]int{"hour": 23, "minute": 59}}
	for _, in := range []*Inputs{&req.Steps[0], &unprepared} {
		if v, ok := in.ClockField("hour"); !ok || v != 23 {
			t.Errorf("ClockField(hour) = %d, %v; want 23", v, ok)
		}
		if v, ok := in.ClockField("second"); ok || v != 0 {
			t.Errorf("ClockField(second) = %d, %v; want absent", v, ok)
		}
	}
}

// releasing counts the CPUs Emulate hands back.
type releasing struct{ made, released int }

func (e *releasing) Hello() Hello { return Hello{Name: "releasing"} }

func (e *releasing) NewCPU(*Request) (CPU, error) {
	e.made++
	return &releasingCPU{e}, nil
}

type releasingCPU struct{ e *releasing }

func (c *releasingCPU) Execute(_ *Memory, step *Inputs) (Result, error) {
	if step.RLOIn {
		return NoResult, errors.New("refused")
	}
	return NoResult, nil
}

func (c *releasingCPU) Release() { c.e.released++ }

// Emulate hands back every CPU once its vector is done, after an error too.
func TestEmulateReleasesCPUs(t *testing.T) {
	e := &releasing{}
	impl := Emulate(e)
	ok := NewRequest("ok", "f", "I", nil, map[string]Value{}, map[string]Operand{}, nil, []Inputs{{}, {}})
	failing := NewRequest("failing", "f", "I", nil, map[string]Value{}, map[string]Operand{}, nil, []Inputs{{RLOIn: true}})
	if _, err := impl.Run(ok); err != nil {
		t.Fatal(err)
	}
	if _, err := impl.Run(failing); err == nil {
		t.Fatal("the failing step did not fail")
	}
	if e.made != 2 || e.released != 2 {
		t.Errorf("%d CPUs made, %d released; want 2 and 2", e.made, e.released)
	}
}

// BenchmarkMemory is what a CP1E comparison does to its memory in one scan: read two
// three-word operands and the control word, write the seven flags.
func BenchmarkMemory(b *testing.B) {
	devices := map[string]Value{"D100": Word(1), "D101": Word(2), "D102": Word(3),
		"D200": Word(1), "D201": Word(2), "D202": Word(3), "D300": Word(0)}
	flags := []Address{{"P_EQ", -1}, {"P_NE", -1}, {"P_LT", -1}, {"P_LE", -1}, {"P_GT", -1}, {"P_GE", -1}, {"P_ER", -1}}
	for _, f := range flags {
		devices[f.Kind] = Bit(false)
	}
	req := NewRequest("t", "f", "I", map[string]int{"D": 8000}, devices, map[string]Operand{}, nil, []Inputs{{}})
	mem := NewMemory(req)
	s1, s2, c := Address{"D", 100}, Address{"D", 200}, Address{"D", 300}
	var w [3]uint16
	for range b.N {
		mem.ReadWords(s1, w[:])
		mem.ReadWords(s2, w[:])
		_ = mem.Word(c)
		_ = mem.InRange(s1, 3)
		for _, f := range flags {
			mem.SetBit(f, true)
		}
	}
}

// TestInRange: assumes.device_sizes {"D": 8000} is D0 to D7999, so three words from D7997 exist
// and from D7998 do not; a kind the vector gives no size for is taken to exist; a request built
// as a struct, whose sizes no constructor worked out, answers the same.
func TestInRange(t *testing.T) {
	sizes := map[string]int{"D": 8000, "SD": 12000}
	made := NewRequest("t", "f", "I", sizes, map[string]Value{"D0": Word(0)}, map[string]Operand{}, nil, []Inputs{{}})
	literal := &Request{ID: "t", DeviceSizes: sizes}
	for _, c := range []struct {
		a     Address
		words int
		want  bool
	}{
		{Address{"D", 0}, 3, true},
		{Address{"D", 7997}, 3, true},
		{Address{"D", 7998}, 3, false},
		{Address{"D", 7999}, 1, true},
		{Address{"D", 8000}, 1, false},
		{Address{"D", -1}, 1, false},
		{Address{"SD", 11997}, 3, true},
		{Address{"SD", 11998}, 3, false},
		{Address{"R", 40000}, 3, true}, // no size given for R
		{Address{"DX", 9000}, 3, true}, // a kind that only starts like a sized one
	} {
		for name, req := range map[string]*Request{"NewRequest": made, "a struct": literal} {
			if got := NewMemory(req).InRange(c.a, c.words); got != c.want {
				t.Errorf("%s: InRange(%v, %d) = %v; want %v", name, c.a, c.words, got, c.want)
			}
		}
	}
}

// TestBitsReadAsWords: a bit device read as a word is 0 or 1, alone and inside a run of words
// ReadWords reads in one go (Value.Word takes a value's low 16 bits, with no test).
func TestBitsReadAsWords(t *testing.T) {
	devices := map[string]Value{"D100": Word(7), "D101": Bit(true), "D102": Bit(false), "D103": Word(65535)}
	mem := NewMemory(NewRequest("t", "f", "I", nil, devices, map[string]Operand{}, nil, []Inputs{{}}))
	var got [4]uint16
	mem.ReadWords(Address{"D", 100}, got[:])
	if want := [4]uint16{7, 1, 0, 65535}; got != want {
		t.Errorf("ReadWords(D100, 4) = %v; want %v", got, want)
	}
	if mem.Word(Address{"D", 101}) != 1 || mem.Word(Address{"D", 102}) != 0 {
		t.Error("a bit device does not read as the word 0 or 1")
	}
}
