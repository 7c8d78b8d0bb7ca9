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

// An exact key (a PLC name) never equals the key of an address that needs comparing.
func TestAddrKeys(t *testing.T) {
	exact := []Addr{{"D", 0}, {"D", 100}, {"SM", 709}, {"P_EQ", -1}, {"ABCD", 1<<31 - 1}}
	inexact := []Addr{{"D", 1 << 32}, {"D", -2}, {"LONGKIND", 7}, {"Dé", 5}, {"D\x00", 5}, {"", 3}}
	seen := map[uint64]Addr{}
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
