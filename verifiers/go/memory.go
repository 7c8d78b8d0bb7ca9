package plcvec

import (
	"math"
)

// Memory is a vector's device image for the Emulator helper: the devices the vector lists,
// each by name and address, and the writes to any device it does not list (which the runner
// reports: an instruction must not write outside the vector).
//
// A device the vector does not list reads as 0 (false): CONTRACT.md leaves its value to the
// implementation, and an instruction that depends on it is wrong whatever it reads.
type Memory struct {
	req          *Request
	vals         []Value   // parallel to req.Devices
	small        [16]Value // vals' storage for a vector of up to 16 devices: one allocation, not two
	outside      []Device  // devices written that the vector does not list, in the order first written
	outsideAddrs []Addr    // parallel to outside: looked up without building names
}

// NewMemory is the initial device image of req.
func NewMemory(req *Request) *Memory {
	m := &Memory{}
	m.reset(req)
	return m
}

// reset makes m the initial device image of req: a copy of the image worked out when the
// request was built.
func (m *Memory) reset(req *Request) {
	if req.keys == nil && len(req.Devices) > 0 {
		req.prepareAddrs(&arena{})
	}
	m.req, m.outside, m.outsideAddrs = req, m.outside[:0], m.outsideAddrs[:0]
	if len(req.Devices) <= len(m.small) {
		m.vals = m.small[:len(req.Devices)]
	} else {
		m.vals = make([]Value, len(req.Devices))
	}
	copy(m.vals, req.initial)
}

// prepareAddrs works out once, for the whole run, what every memory of the request starts
// from: each device's address, its lookup key, and the initial image as a flat list of values.
func (r *Request) prepareAddrs(a *arena) {
	n := len(r.Devices)
	if cap(a.parsed) < n {
		a.parsed = make([]Addr, n)
	}
	addrs := a.parsed[:n]
	r.keys = a.keys.take(n, a.chunk)
	r.initial = a.values.take(n, a.chunk)
	r.addrs = nil
	for i, d := range r.Devices {
		addrs[i] = ParseAddr(d.Name)
		var exact bool
		r.keys[i], exact = addrKey(addrs[i])
		r.initial[i] = d.Value
		if !exact && r.addrs == nil {
			r.addrs = a.addrs.take(n, a.chunk)
		}
	}
	// The addresses are kept only for a request with a name whose key is not exact: an exact
	// key never equals an inexact one, so a look-up compares addresses only in such a request.
	if r.addrs != nil {
		copy(r.addrs, addrs)
		for i := range r.addrs {
			r.addrs[i].Kind = a.intern(r.addrs[i].Kind)
		}
	}
	r.prepareTable(a)
	r.prepareRuns(a)
}

// prepareRuns counts, for each device, the devices after it that continue it word by word
// (D100, D101, D102 sort together): a multi-word operand is read or written in one go. Only
// exact keys with a number (not P_EQ) continue: the next word's key is the key plus 1 << 32.
func (r *Request) prepareRuns(a *arena) {
	r.runs = a.runs.take(len(r.keys), a.chunk)
	for i := len(r.keys) - 1; i >= 0; i-- {
		r.runs[i] = 1
		key := r.keys[i]
		numbered := key&(1<<31) == 0 && key>>32 < math.MaxInt32
		if numbered && i+1 < len(r.keys) && r.keys[i+1] == key+1<<32 && r.runs[i+1] < math.MaxUint16 {
			r.runs[i] = r.runs[i+1] + 1
		}
	}
}

// addrKey folds an address into one integer, its number above its kind, so that a lookup
// compares integers, not strings. For the device names of PLCs (a kind of 1 to 4 ASCII
// characters, D, SM, P_EQ, and a number that fits 31 bits, or none) the kind's bytes are the
// key's low half and the key is exact: equal keys are equal addresses. Any other address gets a
// hash of its kind with the top bit of the low half set, which no exact key has, and a lookup
// compares the addresses themselves on a match.
func addrKey(a Addr) (key uint64, exact bool) {
	k := a.Kind
	if uint(a.N+1) > math.MaxInt32+1 {
		return inexactKey(a), false
	}
	var packed, pad uint64 // pad: 0x01 in each byte past the kind, so that none reads as NUL
	switch len(k) {
	case 1:
		packed, pad = uint64(k[0]), 0x01010100
	case 2:
		packed, pad = uint64(k[0])|uint64(k[1])<<8, 0x01010000
	case 3:
		packed, pad = uint64(k[0])|uint64(k[1])<<8|uint64(k[2])<<16, 0x01000000
	case 4:
		packed = uint64(k[0]) | uint64(k[1])<<8 | uint64(k[2])<<16 | uint64(k[3])<<24
	default:
		return inexactKey(a), false
	}
	// Every byte of the kind ASCII and none NUL (the zero-byte test of "Bit Twiddling Hacks").
	if v := packed | pad; packed&0x80808080 != 0 || (v-0x01010101)&^v&0x80808080 != 0 {
		return inexactKey(a), false
	}
	return uint64(uint32(a.N))<<32 | packed, true
}

func inexactKey(a Addr) uint64 { return uint64(uint32(a.N))<<32 | kindHash(a.Kind) }

// kindHash is an FNV-1a hash of a device kind, with bit 31 set: never an exact key's low half.
func kindHash(kind string) uint64 {
	h := uint32(2166136261)
	for i := 0; i < len(kind); i++ {
		h = (h ^ uint32(kind[i])) * 16777619
	}
	return uint64(h | 1<<31)
}

// slot is a's index in the vector's devices, or -1: its key looked up in the request's table,
// or a scan for a request too large for one.
func (m *Memory) slot(a Addr) int {
	key, exact := addrKey(a)
	r := m.req
	if r.table == nil {
		for i := range r.keys {
			if r.keys[i] == key && (exact || r.addrs[i] == a) {
				return i
			}
		}
		return -1
	}
	mask := uint64(len(r.table) - 1)
	for h := key * fibonacci >> r.shift; ; h = (h + 1) & mask {
		i := int(r.table[h]) - 1
		if i < 0 {
			return -1
		}
		if r.keys[i] == key && (exact || r.addrs[i] == a) {
			return i
		}
	}
}

// fibonacci is 2^64 divided by the golden ratio: multiplying a key by it and keeping the top
// bits spreads keys that differ only in their number (D100, D101) over the table.
const fibonacci = 0x9E3779B97F4A7C15

// prepareTable makes the request's lookup table: open addressing, at most half full, each
// entry a device's index + 1 (0 is empty).
func (r *Request) prepareTable(a *arena) {
	r.table = nil
	if len(r.keys) >= math.MaxUint16 {
		return
	}
	bits := uint(3)
	for 1<<bits < 2*len(r.keys) {
		bits++
	}
	r.table, r.shift = a.slots.take(1<<bits, a.chunk), 64-bits
	mask := uint64(len(r.table) - 1)
	for i, key := range r.keys {
		h := key * fibonacci >> r.shift
		for r.table[h] != 0 {
			h = (h + 1) & mask
		}
		r.table[h] = uint16(i + 1)
	}
}

// outsideIndex is a's index among the writes outside the vector, or -1.
func (m *Memory) outsideIndex(a Addr) int {
	for k := range m.outsideAddrs {
		if m.outsideAddrs[k] == a {
			return k
		}
	}
	return -1
}

// Get returns a device's value and whether the image holds the device.
func (m *Memory) Get(a Addr) (Value, bool) {
	if i := m.slot(a); i >= 0 {
		return m.vals[i], true
	}
	return m.getOutside(a)
}

func (m *Memory) getOutside(a Addr) (Value, bool) {
	if k := m.outsideIndex(a); k >= 0 {
		return m.outside[k].Value, true
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
	if i := m.slot(a); i >= 0 && int(m.req.runs[i]) >= len(dst) {
		for k, v := range m.vals[i : i+len(dst)] {
			dst[k] = v.Word()
		}
		return
	}
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
	if i := m.slot(a); i >= 0 {
		m.vals[i] = v
		return
	}
	m.setOutside(a, v)
}

func (m *Memory) setOutside(a Addr, v Value) {
	if k := m.outsideIndex(a); k >= 0 {
		m.outside[k].Value = v
		return
	}
	m.outside = append(m.outside, Device{a.String(), v})
	m.outsideAddrs = append(m.outsideAddrs, a)
}

// SetWord writes a word device.
func (m *Memory) SetWord(a Addr, w uint16) { m.Set(a, Word(w)) }

// SetWords writes consecutive words from a.
func (m *Memory) SetWords(a Addr, words ...uint16) {
	if i := m.slot(a); i >= 0 && int(m.req.runs[i]) >= len(words) {
		for k, w := range words {
			m.vals[i+k] = Word(w)
		}
		return
	}
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
func (m *Memory) apply(step *Inputs) {
	if step.sets == nil { // a step NewRequest did not prepare
		for name, v := range step.Set {
			m.Set(ParseAddr(name), v)
		}
		return
	}
	for _, d := range step.sets {
		m.Set(d.addr, d.value)
	}
}
