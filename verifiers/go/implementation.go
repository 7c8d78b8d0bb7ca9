package plcvec

import (
	"errors"
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
