package plcvec

import "sync"

// Memory is a vector's device image for the Emulator helper: the devices the vector lists,
// each by name and address, and the writes to any device it does not list (which the runner
// reports: an instruction must not write outside the vector).
//
// A device the vector does not list reads as 0 (false): CONTRACT.md leaves its value to the
// implementation, and an instruction that depends on it is wrong whatever it reads.
type Memory struct {
	req     *Request
	vals    []Value   // parallel to req.Devices
	small   [16]Value // vals' storage for a vector of up to 16 devices: one allocation, not two
	outside []Device  // devices written that the vector does not list, in the order first written
}

// NewMemory is the initial device image of req.
func NewMemory(req *Request) *Memory {
	m := &Memory{}
	m.reset(req)
	return m
}

// reset makes m the initial device image of req.
func (m *Memory) reset(req *Request) {
	m.req, m.outside = req, m.outside[:0]
	if len(req.Devices) <= len(m.small) {
		m.vals = m.small[:len(req.Devices)]
	} else {
		m.vals = make([]Value, len(req.Devices))
	}
	for i, d := range req.Devices {
		m.vals[i] = d.Value
	}
	if req.addrs == nil {
		req.prepareAddrs()
	}
}

func (r *Request) prepareAddrs() {
	r.addrs = make([]Addr, len(r.Devices))
	r.keys = make([]uint64, len(r.Devices))
	for i, d := range r.Devices {
		r.addrs[i] = ParseAddr(d.Name)
		r.keys[i] = addrKey(r.addrs[i])
	}
}

// addrKey folds an address into one integer (its number, and an FNV-1a hash of its kind), so a
// lookup compares integers and compares strings only on a match: names without a number
// (P_EQ, P_NE, ...) all have N = -1 and would otherwise each cost a string comparison.
func addrKey(a Addr) uint64 {
	h := uint32(2166136261)
	for i := 0; i < len(a.Kind); i++ {
		h = (h ^ uint32(a.Kind[i])) * 16777619
	}
	return uint64(uint32(a.N))<<32 | uint64(h)
}

// resultBuffer is what Emulate needs for one vector: its memory and its results. It is reused
// for the next vector once the runner has judged the results (recycle); a caller that keeps
// the results (the stdio adapter) simply never hands it back.
type resultBuffer struct {
	mem    Memory
	values []Value
	steps  []StepResult
}

var results = sync.Pool{New: func() any { return new(resultBuffer) }}

func grow(v []Value, n int) []Value {
	if cap(v) < n {
		return make([]Value, n)
	}
	return v[:n]
}

func (emulated) recycle(steps []StepResult) {
	if len(steps) > 0 && steps[0].buf != nil {
		results.Put(steps[0].buf)
	}
}

func (m *Memory) index(a Addr) int {
	key, keys := addrKey(a), m.req.keys
	for i := range keys {
		if keys[i] == key && m.req.addrs[i] == a {
			return i
		}
	}
	return -1
}

// Get returns a device's value and whether the image holds the device.
func (m *Memory) Get(a Addr) (Value, bool) {
	if i := m.index(a); i >= 0 {
		return m.vals[i], true
	}
	name := a.String()
	for _, d := range m.outside {
		if d.Name == name {
			return d.Value, true
		}
	}
	return 0, false
}

// Word is the 16 bits of a word device (0 when the image does not hold it).
func (m *Memory) Word(a Addr) uint16 {
	v, _ := m.Get(a)
	return v.Word()
}

// Words reads n consecutive words from a: D100, D101, ... (a multi-word operand).
func (m *Memory) Words(a Addr, n int) []uint16 {
	out := make([]uint16, n)
	m.ReadWords(a, out)
	return out
}

// ReadWords fills dst with len(dst) consecutive words from a, without allocating.
func (m *Memory) ReadWords(a Addr, dst []uint16) {
	for k := range dst {
		dst[k] = m.Word(a.Offset(k))
	}
}

// Bit is a bit device's state (false when the image does not hold it).
func (m *Memory) Bit(a Addr) bool {
	v, _ := m.Get(a)
	return v.Bit()
}

// Set writes a device.
func (m *Memory) Set(a Addr, v Value) {
	if i := m.index(a); i >= 0 {
		m.vals[i] = v
		return
	}
	name := a.String()
	for k := range m.outside {
		if m.outside[k].Name == name {
			m.outside[k].Value = v
			return
		}
	}
	m.outside = append(m.outside, Device{name, v})
}

// SetWord writes a word device.
func (m *Memory) SetWord(a Addr, w uint16) { m.Set(a, Word(w)) }

// SetWords writes consecutive words from a.
func (m *Memory) SetWords(a Addr, words ...uint16) {
	for k, w := range words {
		m.Set(a.Offset(k), Word(w))
	}
}

// SetBit writes a bit device.
func (m *Memory) SetBit(a Addr, b bool) { m.Set(a, Bit(b)) }

// InRange reports whether a .. a+words-1 all exist on the CPU the vector assumes
// (assumes.device_sizes). A device type whose size the vector does not state is taken to exist.
func (m *Memory) InRange(a Addr, words int) bool {
	size, ok := m.req.DeviceSize(a.Kind)
	if !ok {
		return true
	}
	return a.N >= 0 && a.N+words <= size
}

// Operand is the word value of a one-word operand: its constant (K/H) or its device's word.
func (m *Memory) Operand(name string) uint16 {
	op, _ := m.req.Operand(name)
	if op.Constant != nil {
		return uint16(*op.Constant)
	}
	return m.Word(op.Addr())
}

// Request is the vector being run.
func (m *Memory) Request() *Request { return m.req }

// apply writes a step's `set` (values written by the outside world before the step).
func (m *Memory) apply(set map[string]Value) {
	for name, v := range set {
		m.Set(ParseAddr(name), v)
	}
}

// Emulator is the thin helper's interface, for an emulator that only wants to "execute this
// instruction on my memory": Emulate turns it into an Implementation that sets up each
// vector's memory, applies each step's `set`, and records the image after every step.
type Emulator interface {
	Hello() Hello
	// NewCPU is a CPU in its power-on state for one vector: nothing carries over from another
	// vector (not TADDP's previous execution condition, not HOUR's work area).
	NewCPU(req *Request) (CPU, error)
}

// CPU executes one vector's instruction, once per step.
type CPU interface {
	// Execute runs the instruction once (one scan) with the step's inputs on mem and returns
	// the contact result, or NoResult for an instruction that is not a contact. mem is the
	// vector's memory only until the vector ends: a CPU must not keep it.
	Execute(mem *Memory, step *Inputs) (Result, error)
}

// Emulate is the Implementation that runs an Emulator.
func Emulate(e Emulator) Implementation { return emulated{e} }

type emulated struct{ e Emulator }

func (em emulated) Hello() Hello { return em.e.Hello() }

func (em emulated) Run(req *Request) ([]StepResult, error) {
	cpu, err := em.e.NewCPU(req)
	if err != nil {
		return nil, err
	}
	buf := results.Get().(*resultBuffer)
	mem := &buf.mem
	mem.reset(req)
	n := len(req.Devices)
	// Every step's values in one buffer without pointers: the collector never scans it.
	buf.values = grow(buf.values, n*len(req.Steps))
	if cap(buf.steps) < len(req.Steps) {
		buf.steps = make([]StepResult, len(req.Steps))
	}
	values, out := buf.values, buf.steps[:len(req.Steps)]
	clear(out)
	for i := range req.Steps {
		step := &req.Steps[i]
		if step.Set != nil {
			mem.apply(step.Set)
		}
		r, err := cpu.Execute(mem, step)
		if err != nil {
			return nil, err
		}
		vals := values[i*n : (i+1)*n : (i+1)*n]
		copy(vals, mem.vals)
		out[i] = StepResult{Result: r, Values: vals}
		if len(mem.outside) > 0 {
			out[i].Devices = append([]Device(nil), mem.outside...)
		}
	}
	out[0].buf = buf
	return out, nil
}
