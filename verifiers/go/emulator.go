package plcvec

import (
	"sync/atomic"
)

// resultBuffer is what Emulate needs for one vector: its memory and its results. It is reused
// for the next vector once the runner has judged the results (recycle); a caller that keeps
// the results (the stdio adapter) simply never hands it back.
type resultBuffer struct {
	mem    Memory
	values []Value
	steps  []StepResult
}

func grow(v []Value, n int) []Value {
	if cap(v) < n {
		return make([]Value, n)
	}
	return v[:n]
}

func (em *emulated) recycle(steps []StepResult) {
	if len(steps) > 0 && steps[0].buf != nil {
		em.spare.Store(steps[0].buf)
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

// Releaser is a CPU that Emulate hands back with Release once its vector is done (its last
// step run, or an error), so that the emulator can reuse it for the next vector instead of
// allocating one. Optional: an emulator whose NewCPU simply allocates needs nothing of it.
type Releaser interface {
	Release()
}

// Emulate is the Implementation that runs an Emulator.
func Emulate(e Emulator) Implementation { return &emulated{e: e} }

type emulated struct {
	e Emulator
	// spare is the buffer of the vector judged last, handed back (recycle) for the next one to
	// reuse; a swap, so vectors run in parallel each get their own.
	spare atomic.Pointer[resultBuffer]
}

func (em *emulated) Hello() Hello { return em.e.Hello() }

func (em *emulated) Run(req *Request) ([]StepResult, error) {
	cpu, err := em.e.NewCPU(req)
	if err != nil {
		return nil, err
	}
	if r, ok := cpu.(Releaser); ok {
		defer r.Release()
	}
	buf := em.spare.Swap(nil)
	if buf == nil {
		buf = new(resultBuffer)
	}
	mem := &buf.mem
	mem.reset(req)
	n := len(req.Devices)
	// Every step's values in one buffer without pointers: the collector never scans it.
	buf.values = grow(buf.values, n*len(req.Steps))
	if cap(buf.steps) < len(req.Steps) {
		buf.steps = make([]StepResult, len(req.Steps))
	}
	values, out := buf.values, buf.steps[:len(req.Steps)]
	for i := range req.Steps {
		step := &req.Steps[i]
		if step.Set != nil {
			mem.apply(step)
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
