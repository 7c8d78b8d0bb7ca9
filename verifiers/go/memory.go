package plcvec

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
	outsideAddrs []Address // parallel to outside: looked up without building names
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

// slot is a's index in the vector's devices, or -1: its key looked up in the request's table,
// or a scan for a request too large for one.
func (m *Memory) slot(a Address) int {
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

// outsideIndex is a's index among the writes outside the vector, or -1.
func (m *Memory) outsideIndex(a Address) int {
	for k := range m.outsideAddrs {
		if m.outsideAddrs[k] == a {
			return k
		}
	}
	return -1
}

// Get returns a device's value and whether the image holds the device.
func (m *Memory) Get(a Address) (Value, bool) {
	if i := m.slot(a); i >= 0 {
		return m.vals[i], true
	}
	return m.getOutside(a)
}

func (m *Memory) getOutside(a Address) (Value, bool) {
	if k := m.outsideIndex(a); k >= 0 {
		return m.outside[k].Value, true
	}
	return 0, false
}

// Word is the 16 bits of a word device (0 when the image does not hold it).
func (m *Memory) Word(a Address) uint16 {
	v, _ := m.Get(a)
	return v.Word()
}

// Words reads n consecutive words from a: D100, D101, ... (a multi-word operand).
func (m *Memory) Words(a Address, n int) []uint16 {
	out := make([]uint16, n)
	m.ReadWords(a, out)
	return out
}

// ReadWords fills dst with len(dst) consecutive words from a, without allocating.
func (m *Memory) ReadWords(a Address, dst []uint16) {
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
func (m *Memory) Bit(a Address) bool {
	v, _ := m.Get(a)
	return v.Bit()
}

// Set writes a device.
func (m *Memory) Set(a Address, v Value) {
	if i := m.slot(a); i >= 0 {
		m.vals[i] = v
		return
	}
	m.setOutside(a, v)
}

func (m *Memory) setOutside(a Address, v Value) {
	if k := m.outsideIndex(a); k >= 0 {
		m.outside[k].Value = v
		return
	}
	m.outside = append(m.outside, Device{a.String(), v})
	m.outsideAddrs = append(m.outsideAddrs, a)
}

// SetWord writes a word device.
func (m *Memory) SetWord(a Address, w uint16) { m.Set(a, Word(w)) }

// SetWords writes consecutive words from a.
func (m *Memory) SetWords(a Address, words ...uint16) {
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
func (m *Memory) SetBit(a Address, b bool) { m.Set(a, Bit(b)) }

// InRange reports whether a .. a+words-1 all exist on the CPU the vector assumes
// (assumes.device_sizes). A device type whose size the vector does not state is taken to exist.
func (m *Memory) InRange(a Address, words int) bool {
	r := m.req
	if r.sizes == nil && len(r.DeviceSizes) > 0 { // a Request not made by NewRequest
		r.prepareSizes()
	}
	size, ok := r.size(a.Kind)
	return !ok || a.N >= 0 && a.N+words <= size
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
