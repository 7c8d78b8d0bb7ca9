// Package reference is a plain implementation of the five instruction families, written from
// the manual pages the way an emulator author would write it, and verified by the suite: the
// Go verifier's own second oracle. It is an Emulator (plcvec's "execute on my memory" level):
// a CPU per vector executing one instruction per scan on the vector's memory.
package reference

import (
	"fmt"
	"sort"
	"strings"
	"sync"
	"sync/atomic"

	"github.com/plcvec/plcvec/verifiers/go"
	"github.com/plcvec/plcvec/verifiers/go/spec"
)

// Name and Version are what the reference says in the handshake.
const (
	Name    = "plcvec-reference-go"
	Version = "1.0"
)

// Reference is the reference emulator following one alternative of every interpretation.
type Reference struct {
	name    string
	choices map[string]string // every interpretation: declared or default
	parts   Parts
	// Each family's CPU as configured by the alternatives, worked out once: a vector's CPU is a
	// copy of it with the vector's operands.
	fx5  configured[fx5Config]
	tadd configured[fx5TimeAdd]
	hour configured[fc6aHourMeter]
	cp1e configured[cp1eConfig]
	// One CPU of each family handed back by Release, for the next vector to reuse.
	fx5CPUs  spare[fx5Compare]
	taddCPUs spare[fx5TimeAdd]
	hourCPUs spare[fc6aHourMeter]
	cp1eCPUs spare[cp1eTimeCompare]
}

type configured[T any] struct {
	once sync.Once
	cpu  T
	err  error
}

func (c *configured[T]) get(configure func() (T, error)) (*T, error) {
	c.once.Do(func() { c.cpu, c.err = configure() })
	return &c.cpu, c.err
}

// spare keeps one CPU that its vector is done with (Release) for the next vector of the same
// family, so that running a vector allocates nothing; NewCPU overwrites all of it, so nothing
// carries over. A swap, not a plain field: vectors run in parallel each get their own CPU.
type spare[T any] struct{ p atomic.Pointer[T] }

func (s *spare[T]) get() *T {
	if p := s.p.Swap(nil); p != nil {
		return p
	}
	return new(T)
}

func (s *spare[T]) put(p *T) { s.p.Store(p) }

// New is the reference following the given alternatives (interpretation id -> alternative);
// every other interpretation takes its default. An unknown interpretation or alternative is an
// error.
func New(choices map[string]string) (*Reference, error) {
	return NewVariant(Name, choices, Correct())
}

// NewVariant is the reference built from other parts: what package mutants does to make a
// single-bug variant.
func NewVariant(name string, choices map[string]string, parts Parts) (*Reference, error) {
	all := map[string]string{}
	known := map[string]spec.Interpretation{}
	for _, i := range spec.Interpretations {
		all[i.ID] = i.Default
		known[i.ID] = i
	}
	ids := make([]string, 0, len(choices))
	for id := range choices {
		ids = append(ids, id)
	}
	sort.Strings(ids)
	for _, id := range ids {
		i, ok := known[id]
		if !ok {
			return nil, fmt.Errorf("no interpretation %q", id)
		}
		alt := choices[id]
		found := false
		for _, a := range i.Alternatives {
			found = found || a == alt
		}
		if !found {
			return nil, fmt.Errorf("%s has no alternative %q (it has %s)", id, alt, strings.Join(i.Alternatives, ", "))
		}
		all[id] = alt
	}
	return &Reference{name: name, choices: all, parts: parts}, nil
}

// Implementation is the reference as a plcvec.Implementation.
func (r *Reference) Implementation() plcvec.Implementation { return plcvec.Emulate(r) }

// Hello: every instruction of the five families, and the alternative followed for every
// interpretation (declared explicitly, defaults included).
func (r *Reference) Hello() plcvec.Hello {
	var instructions []string
	for _, f := range spec.Families {
		instructions = append(instructions, f.Instructions...)
	}
	interps := make(map[string]string, len(r.choices))
	for id, alt := range r.choices {
		interps[id] = alt
	}
	return plcvec.Hello{Name: r.name, Version: Version, Instructions: instructions, Interpretations: interps}
}

// Choices is the alternative followed for every interpretation.
func (r *Reference) Choices() map[string]string { return r.choices }

// NewCPU is a CPU in its power-on state for the vector's family.
func (r *Reference) NewCPU(req *plcvec.Request) (plcvec.CPU, error) {
	switch req.Family {
	case spec.FamilyFx5TimeCompare:
		return newFX5Compare(r, req, &timeFields)
	case spec.FamilyFx5DateCompare:
		return newFX5Compare(r, req, &dateFields)
	case spec.FamilyFx5TimeAdd:
		return newTADD(r, req)
	case spec.FamilyFc6aHourMeter:
		return newHourMeter(r, req)
	case spec.FamilyCp1eTimeCompare:
		return newCP1E(r, req)
	}
	return nil, plcvec.Skip("the reference has no family " + req.Family)
}

// choice is the alternative followed for interpretation id, checked against those this code
// knows: an alternative the spec gains later is reported, not silently read as another.
func (r *Reference) choice(id string, known ...string) (string, error) {
	alt := r.choices[id]
	for _, k := range known {
		if alt == k {
			return alt, nil
		}
	}
	return "", fmt.Errorf("the reference does not implement %s=%s yet", id, alt)
}

// operand is a named operand of the request, or an error naming the vector.
func operand(req *plcvec.Request, name string) (plcvec.Operand, error) {
	op, ok := req.Operand(name)
	if !ok {
		return op, fmt.Errorf("%s: no operand %s", req.Instruction, name)
	}
	return op, nil
}

// deviceOperands sets addrs[i] to the device address of the operand names[i].
func deviceOperands(req *plcvec.Request, names []string, addrs ...*plcvec.Address) error {
	for i, name := range names {
		op, err := operand(req, name)
		if err != nil {
			return err
		}
		*addrs[i] = op.Addr()
	}
	return nil
}

// signed16 is a word read as "16-bit signed binary".
func signed16(w uint16) int { return int(int16(w)) }
