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
	Steps        []Step          `json:"steps"`
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
	Device   string   `json:"device,omitempty"`
	Constant *int     `json:"constant,omitempty"`
	addr     *Address // Device parsed, when the operand comes from Request.Operand
}

// IsConstant reports whether the operand is a K/H constant rather than a device.
func (o Operand) IsConstant() bool { return o.Constant != nil }

// Addr is the operand's device address (its first word for a multi-word operand).
func (o Operand) Addr() Address {
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
	addr  Address
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

// Step is one step of a vector: its inputs and what it expects.
type Step struct {
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
func (s *Step) UnmarshalJSON(b []byte) error {
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
	*s = Step{Inputs: Inputs{Set: raw.Set, Clock: raw.Clock}, Expect: raw.Expect}
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
	// Unjudged (schema 1.1): the devices this combination leaves unjudged, by the interpretation
	// whose alternative leaves them: listed in `initial`, absent from Expect and Final, never
	// compared (a write to one is no stray write: the vector lists it).
	Unjudged map[string][]string `json:"unjudged,omitempty"`
}

// FamilyHeader is a family file's header: everything but the vectors.
type FamilyHeader struct {
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
