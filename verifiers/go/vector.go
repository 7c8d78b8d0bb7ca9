package plcvec

import (
	"encoding/json"
	"sort"
)

// Vector is one test vector as the vector files hold it (vectors/schema/vector-file.schema.json).
// A key the schema does not have is refused on load, at any level (validate.go).
type Vector struct {
	ID           string          `json:"id"`
	Family       string          `json:"family"`
	Instruction  string          `json:"instruction"`
	ST           string          `json:"st"`
	Description  string          `json:"description"`
	Tags         []string        `json:"tags"`
	Clauses      []string        `json:"clauses"`
	Assumes      Assumes         `json:"assumes"`
	Initial      *Initial        `json:"initial"`
	Steps        []VectorStep    `json:"steps"`
	Final        *State          `json:"final"`
	Outcome      *Outcome        `json:"outcome"`
	Alternatives []Alternative   `json:"alternatives"`
	Printed      json.RawMessage `json:"printed,omitempty"`
}

// Assumes holds what the vector assumes of the CPU: the number of points of each device type.
type Assumes struct {
	DeviceSizes map[string]int `json:"device_sizes"`
}

// Initial is the state a vector starts from.
type Initial struct {
	Devices  map[string]Value   `json:"devices"`
	Operands map[string]Operand `json:"operands"`
	// Scratch words are the implementation's own work area: never compared.
	Scratch []string `json:"scratch"`
}

// Operand is {"device": "D100"} or {"constant": 7}.
type Operand struct {
	Device   string `json:"device,omitempty"`
	Constant *int   `json:"constant,omitempty"`
	addr     *Addr  // Device parsed, when the operand comes from Request.Operand
}

// IsConstant reports whether the operand is a K/H constant rather than a device.
func (o Operand) IsConstant() bool { return o.Constant != nil }

// Addr is the operand's device address (its first word for a multi-word operand).
func (o Operand) Addr() Addr {
	if o.addr != nil {
		return *o.addr
	}
	return ParseAddr(o.Device)
}

// Inputs are the inputs of one execution (one scan); which ones a step holds depends on the
// family (CONTRACT.md, "Executing"). Absent inputs are zero.
type Inputs struct {
	Set       map[string]Value `json:"set,omitempty"`
	RLOIn     bool             `json:"rlo_in"`
	Clock     map[string]int   `json:"clock,omitempty"`
	EN        bool             `json:"en"`
	Input     bool             `json:"input"`
	ElapsedMS int64            `json:"elapsed_ms"`
	clock     []clockField     // Clock as a list, made once by NewRequest: a scan reads it, no map
	sets      []setDevice      // Set with each address parsed, made once by NewRequest
}

type clockField struct {
	name  string
	value int
}

type setDevice struct {
	addr  Addr
	value Value
}

// ClockField is one field of the step's current clock ("hour", "year", as `clock` names them)
// and whether the step gives it.
func (in *Inputs) ClockField(name string) (int, bool) {
	if in.clock == nil {
		v, ok := in.Clock[name]
		return v, ok
	}
	for _, f := range in.clock {
		if f.name == name {
			return f.value, true
		}
	}
	return 0, false
}

// prepare makes the lists a scan reads in place of the maps.
func (in *Inputs) prepare(a *arena) {
	in.clock, in.sets = nil, nil
	if len(in.Clock) > 0 {
		in.clock = make([]clockField, 0, len(in.Clock))
		for name, v := range in.Clock {
			in.clock = append(in.clock, clockField{a.intern(name), v})
		}
		sort.Slice(in.clock, func(i, j int) bool { return in.clock[i].name < in.clock[j].name })
	}
	if len(in.Set) > 0 {
		in.sets = make([]setDevice, 0, len(in.Set))
		for name, v := range in.Set {
			d := setDevice{ParseAddr(name), v}
			d.addr.Kind = a.intern(d.addr.Kind)
			in.sets = append(in.sets, d)
		}
		// The order a map gives is random; writes to distinct devices commute, but the same
		// order every run keeps a run repeatable.
		sort.Slice(in.sets, func(a, b int) bool { return in.sets[a].addr.String() < in.sets[b].addr.String() })
	}
}

// VectorStep is one step of a vector: its inputs and what it expects.
type VectorStep struct {
	Inputs
	Expect *Expect `json:"expect"`
	given  uint8   // which of the inputs the step gives (a failure shows those)
}

// The inputs a step may give, in the order a failure shows them.
const (
	givesRLOIn uint8 = 1 << iota
	givesEN
	givesInput
	givesElapsed
)

// UnmarshalJSON reads a step, refusing keys the schema does not have, and notes which inputs
// it gives.
func (s *VectorStep) UnmarshalJSON(b []byte) error {
	var raw struct {
		Set       map[string]Value `json:"set"`
		RLOIn     *bool            `json:"rlo_in"`
		Clock     map[string]int   `json:"clock"`
		EN        *bool            `json:"en"`
		Input     *bool            `json:"input"`
		ElapsedMS *int64           `json:"elapsed_ms"`
		Expect    *Expect          `json:"expect"`
	}
	if err := decodeStrict(b, &raw); err != nil {
		return err
	}
	*s = VectorStep{Inputs: Inputs{Set: raw.Set, Clock: raw.Clock}, Expect: raw.Expect}
	if raw.RLOIn != nil {
		s.RLOIn, s.given = *raw.RLOIn, s.given|givesRLOIn
	}
	if raw.EN != nil {
		s.EN, s.given = *raw.EN, s.given|givesEN
	}
	if raw.Input != nil {
		s.Input, s.given = *raw.Input, s.given|givesInput
	}
	if raw.ElapsedMS != nil {
		s.ElapsedMS, s.given = *raw.ElapsedMS, s.given|givesElapsed
	}
	return nil
}

// Expect is what one step expects: the contact result (LD/AND/OR forms) and the devices whose
// value changed in the step.
type Expect struct {
	Result  *bool            `json:"result,omitempty"`
	Devices map[string]Value `json:"devices"`
}

// State is a full device image.
type State struct {
	Devices map[string]Value `json:"devices"`
}

// Outcome is the vector's outcome category; for `implementation-defined`, the interpretations
// it depends on and the outcome under their defaults.
type Outcome struct {
	Category        string         `json:"category"`
	Interpretations []string       `json:"interpretations,omitempty"`
	Reason          string         `json:"reason,omitempty"`
	Default         *Outcome       `json:"default,omitempty"`
	Errors          []OutcomeError `json:"errors,omitempty"`
}

// OutcomeError is one error an execution reports: the step, the error code and the device
// that holds it.
type OutcomeError struct {
	Step   int    `json:"step"`
	Code   int    `json:"code"`
	Device string `json:"device,omitempty"`
}

// Alternative is the expectation under one combination of interpretation alternatives.
type Alternative struct {
	Choices map[string]string `json:"choices"`
	Expect  []Expect          `json:"expect"`
	Final   State             `json:"final"`
	Outcome Outcome           `json:"outcome"`
}

// Header is a family file's header: everything but the vectors.
type Header struct {
	Family          string                 `json:"family"`
	Kind            string                 `json:"kind"`
	Title           string                 `json:"title"`
	SchemaVersion   string                 `json:"schema_version"`
	SpecSHA256      string                 `json:"spec_sha256"`
	Instructions    []string               `json:"instructions"`
	Tags            map[string]string      `json:"tags"`
	Interpretations []HeaderInterpretation `json:"interpretations"`
	Count           int                    `json:"count"`
	Generated       string                 `json:"generated"`
	SpecFile        string                 `json:"spec_file"`
}

// HeaderInterpretation is one interpretation as a family file declares it.
type HeaderInterpretation struct {
	ID           string `json:"id"`
	Question     string `json:"question"`
	Default      string `json:"default"`
	Alternatives []struct {
		ID   string `json:"id"`
		Says string `json:"says"`
	} `json:"alternatives"`
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
