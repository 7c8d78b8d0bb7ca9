package plcvec

import (
	"math"
	"sort"
)

// Request is one vector without its expectations, and what a run works out of it once: each
// device's lookup key, a small hash table of them, the runs of consecutive words, the initial
// image as a flat list, the operands and device sizes as lists. Memory reads them for every step.

// prepareAddrs works out once, for the whole run, what every memory of the request starts
// from: each device's address, its lookup key, and the initial image as a flat list of values.
func (r *Request) prepareAddrs(a *arena) {
	n := len(r.Devices)
	if cap(a.parsed) < n {
		a.parsed = make([]Address, n)
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
func addrKey(a Address) (key uint64, exact bool) {
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

func inexactKey(a Address) uint64 { return uint64(uint32(a.N))<<32 | kindHash(a.Kind) }

// kindHash is an FNV-1a hash of a device kind, with bit 31 set: never an exact key's low half.
func kindHash(kind string) uint64 {
	h := uint32(2166136261)
	for i := 0; i < len(kind); i++ {
		h = (h ^ uint32(kind[i])) * 16777619
	}
	return uint64(h | 1<<31)
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

// Request is one vector without its expectations: what an implementation needs to run it.
type Request struct {
	ID          string
	Family      string
	Instruction string
	DeviceSizes map[string]int     // points of each device type: {"D": 8000} is D0..D7999
	Devices     []Device           // the initial device image, sorted by name
	Operands    map[string]Operand // s1, s2, d, S1, D1, C, ...
	Scratch     []string           // work-area words: start at 0, never compared
	Steps       []Inputs
	// What a run reads of every vector, together: keys, table and initial for its memory,
	// operands and sizes for its CPU. addrs only when a name's key is not exact.
	keys     []uint64       // parallel to Devices: addrKey of each
	table    []uint16       // keys hashed: index + 1 of each device, 0 empty (Memory.slot)
	shift    uint           // 64 - log2(len(table))
	runs     []uint16       // parallel to Devices: how many devices from this one are consecutive words
	initial  []Value        // parallel to Devices: the initial image every memory copies
	operands []namedOperand // Operands by name, their addresses parsed once
	sizes    []kindSize     // DeviceSizes as a list: a few entries, read on every range check
	addrs    []Address      // parallel to Devices
}

type kindSize struct {
	kind string
	size int
}

// DeviceSize is the number of points of a device type the vector assumes, and whether it says.
func (r *Request) DeviceSize(kind string) (int, bool) {
	if r.sizes == nil && len(r.DeviceSizes) > 0 {
		r.prepareSizes()
	}
	return r.size(kind)
}

// size is DeviceSize once the sizes are worked out: a loop over a few entries, small enough to
// be inlined where it is asked at every execution (Memory.InRange).
func (r *Request) size(kind string) (int, bool) {
	for i := range r.sizes {
		if sameShort(r.sizes[i].kind, kind) { // a kind is a few bytes: compared in place, not by a call
			return r.sizes[i].size, true
		}
	}
	return 0, false
}

func (r *Request) prepareSizes() { r.prepareSizesIn(&arena{}) }

func (r *Request) prepareSizesIn(a *arena) {
	r.sizes = a.sizes.take(len(r.DeviceSizes), a.chunk)[:0]
	for k, n := range r.DeviceSizes {
		r.sizes = append(r.sizes, kindSize{a.intern(k), n})
	}
	sort.Slice(r.sizes, func(i, j int) bool { return r.sizes[i].kind < r.sizes[j].kind })
}

type namedOperand struct {
	name string
	op   Operand
}

// Operand is the named operand (s1, d, C, ...) and whether the vector has it. It is what
// Operands[name] holds, with the device address parsed once for the whole run.
func (r *Request) Operand(name string) (Operand, bool) {
	if r.operands == nil && len(r.Operands) > 0 {
		r.prepareOperands(&arena{})
	}
	for i := range r.operands {
		if sameShort(r.operands[i].name, name) {
			return r.operands[i].op, true
		}
	}
	return Operand{}, false
}

// sameShort is a == b for short strings such as operand names, compared in place: most
// differ in their last character (s1, s2, s3), and most that match are a few bytes long.
func sameShort(a, b string) bool {
	if len(a) != len(b) {
		return false
	}
	for i := len(a) - 1; i >= 0; i-- {
		if a[i] != b[i] {
			return false
		}
	}
	return true
}

func (r *Request) prepareOperands(a *arena) {
	r.operands = a.operands.take(len(r.Operands), a.chunk)[:0]
	for name, op := range r.Operands {
		if op.Device != "" {
			op.addr = a.operandAddrs.one(a.chunk)
			*op.addr = ParseAddr(op.Device)
			op.addr.Kind = a.intern(op.addr.Kind)
		}
		if op.Constant != nil { // a copy beside the others, not the decoder's own
			c := a.ints.one(a.chunk)
			*c = *op.Constant
			op.Constant = c
		}
		r.operands = append(r.operands, namedOperand{a.intern(name), op})
	}
	sort.Slice(r.operands, func(i, j int) bool { return r.operands[i].name < r.operands[j].name })
}

// NewRequest builds the request of a vector (or of a run message received over stdio).
func NewRequest(id, family, instruction string, sizes map[string]int, devices map[string]Value,
	operands map[string]Operand, scratch []string, steps []Inputs) *Request {
	return newRequest(&arena{}, id, family, instruction, sizes, devices, operands, scratch, steps)
}

// newRequest builds a request in the arena, with everything a run reads worked out once.
func newRequest(a *arena, id, family, instruction string, sizes map[string]int, devices map[string]Value,
	operands map[string]Operand, scratch []string, steps []Inputs) *Request {
	r := a.requests.one(a.chunk)
	*r = Request{ID: id, Family: a.intern(family), Instruction: a.intern(instruction), DeviceSizes: sizes,
		Operands: operands, Scratch: scratch, Steps: steps}
	for i := range steps {
		steps[i].prepare(a)
	}
	r.Devices = a.devices.take(len(devices), a.chunk)[:0]
	for name, v := range devices {
		r.Devices = append(r.Devices, Device{name, v})
	}
	sort.Slice(r.Devices, func(i, j int) bool { return r.Devices[i].Name < r.Devices[j].Name })
	r.prepareAddrs(a)
	r.prepareOperands(a)
	r.prepareSizesIn(a)
	return r
}

func requestOf(a *arena, v *Vector) *Request {
	steps := a.inputs.take(len(v.Steps), a.chunk)
	for i, st := range v.Steps {
		steps[i] = st.Inputs
	}
	return newRequest(a, v.ID, v.Family, v.Instruction, v.Assumes.DeviceSizes, v.Initial.Devices,
		v.Initial.Operands, v.Initial.Scratch, steps)
}
