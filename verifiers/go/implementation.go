package plcvec

import (
	"errors"
	"sort"
)

// Implementation is what the suite verifies, at the level of the contract (CONTRACT.md): it gets
// one vector's initial state and its steps' inputs, and reports after each step the device
// image and, for contact instructions, the result. An emulator that would rather only "execute
// this instruction on my memory" implements Emulator and passes Emulate(e) instead.
type Implementation interface {
	// Hello says what the implementation is, which instructions it runs and which
	// interpretation alternatives it follows (the handshake of PROTOCOL.md).
	Hello() Hello
	// Run runs every step of req from req's initial state, which it must not carry over from
	// any earlier vector. It returns one StepResult per step, or Skip(reason) when it cannot run
	// this vector (reported as skipped), or another error (reported as an error: the run fails).
	Run(req *Request) ([]StepResult, error)
}

// Hello is an implementation's answer to the handshake.
type Hello struct {
	Name    string
	Version string
	// Instructions it runs, as in a vector's `instruction` (spec.Instr...). Vectors of other
	// instructions are skipped. Nil means every instruction of the suite.
	Instructions []string
	// Interpretations: interpretation id -> the alternative followed (spec.Interp... ->
	// spec.<Interp><Alternative>). Undeclared interpretations take their default.
	Interpretations map[string]string
	// CPUWrites are devices the implementation's CPU writes on its own account (diagnostic
	// relays and registers such as SM0, SM1, SM56, SD0): a write to one of them that a vector
	// does not list is not a stray write. A declared device the vector lists is compared as usual.
	CPUWrites []string
}

func (h Hello) supports(instruction string) bool {
	return h.Instructions == nil || contains(h.Instructions, instruction)
}

// Result is the logic state after a contact instruction (LD/AND/OR forms). Instructions that
// are not contacts (TADD, HOUR) report NoResult.
type Result int8

const (
	NoResult Result = iota
	ResultOff
	ResultOn
)

// Contact is the Result of a contact whose logic state is on.
func Contact(on bool) Result {
	if on {
		return ResultOn
	}
	return ResultOff
}

func (r Result) String() string {
	switch r {
	case ResultOn:
		return "true"
	case ResultOff:
		return "false"
	}
	return "<not reported>"
}

// StepResult is the state after one step, in either of two forms:
//
//   - Devices alone: every device of the request (scratch words may be left out), plus any
//     other device the step wrote, in any order;
//   - Values, the value of every device of the request in the order of Request.Devices, with
//     Devices listing only the devices outside the request that the step wrote (usually none).
//     This is the fast form, which the Emulator helper gives.
type StepResult struct {
	Result  Result
	Values  []Value
	Devices []Device
	buf     *resultBuffer // Emulate's buffer that holds the results, to reuse once judged
}

// Image is the whole device image of a step result of req, as Devices alone.
func (s StepResult) Image(req *Request) []Device {
	names := make([]string, len(req.Devices))
	for i, d := range req.Devices {
		names[i] = d.Name
	}
	return s.image(names)
}

func (s StepResult) image(names []string) []Device {
	if s.Values == nil {
		return s.Devices
	}
	out := make([]Device, 0, len(s.Values)+len(s.Devices))
	for i, v := range s.Values {
		out = append(out, Device{names[i], v})
	}
	return append(out, s.Devices...)
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
	addrs    []Addr         // parallel to Devices
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
	for _, s := range r.sizes {
		if s.kind == kind {
			return s.size, true
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

type skipError string

func (e skipError) Error() string { return string(e) }

// Skip is the error an implementation returns from Run for a vector it cannot run, saying why
// ("no R devices"). It is reported as skipped, not failed.
func Skip(reason string) error { return skipError(reason) }

// IsSkip reports whether err is a Skip, and its reason.
func IsSkip(err error) (string, bool) {
	var s skipError
	if errors.As(err, &s) {
		return string(s), true
	}
	return "", false
}
