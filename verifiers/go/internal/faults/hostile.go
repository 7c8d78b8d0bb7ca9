// Package faults holds the hostile implementations of the shared table of faults
// (verifiers/parity/faults.toml): each is the Go reference with one misbehaviour, on the vector
// $PLCVEC_HOSTILE_ON (or on every vector, for those that say so). verifiers/go/faults-entry runs
// them through plcvec.Run under `go test`, the entry point the README documents, and
// verifiers/parity/run.py checks that each row gets the verdict `plcvec verify` gives.
package faults

import (
	"fmt"
	"os"
	"os/exec"
	"sort"
	"strings"

	"github.com/plcvec/plcvec/verifiers/go"
	"github.com/plcvec/plcvec/verifiers/go/reference"
)

// Names lists the hostile implementations, as the table names them.
var Names = []string{"reference", "wrong-result", "panic", "loop-forever", "empty-answer", "stray-write",
	"duplicate-write", "wrong-type", "out-of-range", "exit-zero", "exit-nonzero", "crash", "mutates-request",
	"supports-nothing", "skips-everything", "bad-choice", "cpu-writes", "word-65536", "closes-fds",
	"child-holds-stdout", "follows-alternative"}

// New is the hostile implementation name, misbehaving on the vector id on; choice is the
// `ID=alternative` that follows-alternative follows without declaring it.
func New(name, on, choice string) (plcvec.Implementation, error) {
	if name == "not-a-number" {
		// The row is exempt in the table (faults.toml, the README): there is nothing to build.
		return nil, fmt.Errorf("PLCVEC_HOSTILE=not-a-number: a plcvec.Value is an integer, which cannot hold NaN")
	}
	followed := map[string]string(nil)
	if name == "follows-alternative" {
		id, alt, ok := strings.Cut(choice, "=")
		if !ok {
			return nil, fmt.Errorf("PLCVEC_HOSTILE_CHOICE=%q: follows-alternative takes ID=alternative", choice)
		}
		followed = map[string]string{id: alt}
	}
	ref, err := reference.New(followed)
	if err != nil {
		return nil, err
	}
	if name == "" || name == "reference" {
		return ref.Implementation(), nil
	}
	known := false
	for _, n := range Names {
		known = known || n == name
	}
	if !known {
		return nil, fmt.Errorf("PLCVEC_HOSTILE=%q: no such hostile implementation (known: %s)", name, strings.Join(Names, ", "))
	}
	return &hostile{ref: ref.Implementation(), name: name, on: on}, nil
}

type hostile struct {
	ref      plcvec.Implementation
	name, on string
}

func (h *hostile) Hello() plcvec.Hello {
	hello := h.ref.Hello()
	switch h.name {
	case "supports-nothing":
		hello.Instructions = []string{}
	case "bad-choice":
		hello.Interpretations = map[string]string{"NO-SUCH-INTERPRETATION": "x"}
	case "cpu-writes":
		hello.CPUWrites = []string{"SM56", "SD1", "SD0"}
	case "follows-alternative":
		hello.Interpretations = nil // a reading followed but not declared
	}
	return hello
}

func (h *hostile) Run(req *plcvec.Request) ([]plcvec.StepResult, error) {
	if h.name == "skips-everything" {
		return nil, plcvec.Skip("this implementation skips every vector")
	}
	target := req.ID == h.on
	if target {
		if steps, answered, err := h.before(req); answered {
			return steps, err
		}
	}
	steps, err := h.ref.Run(req)
	if err != nil {
		return steps, err
	}
	// The answer is the implementation's own from here on: the reference's buffers are not
	// handed back to be reused.
	steps = own(req, steps)
	h.after(req, steps, target)
	return steps, nil
}

// before is the misbehaviour on the target before the reference runs: one that ends the run,
// the process, or the answer (answered), or one done on the way (closes-fds, child-holds-stdout).
func (h *hostile) before(req *plcvec.Request) (steps []plcvec.StepResult, answered bool, err error) {
	switch h.name {
	case "panic":
		panic("hostile: a panic on " + req.ID)
	case "loop-forever":
		//lint:ignore SA5002 the misbehaviour itself: an implementation that never returns
		for {
		}
	case "exit-zero":
		os.Exit(0)
	case "exit-nonzero":
		os.Exit(3)
	case "crash":
		done := make(chan struct{})
		go func() {
			var p *plcvec.Request
			_ = p.ID // a nil dereference in a goroutine of its own: the process dies
			close(done)
		}()
		<-done
	case "empty-answer":
		return []plcvec.StepResult{}, true, nil
	case "closes-fds":
		closeInherited()
	case "child-holds-stdout":
		if err := holdStdout(); err != nil {
			return nil, true, err
		}
	}
	return nil, false, nil
}

// after changes the reference's answer as the implementation misbehaves: on every vector
// (cpu-writes), or on the target only.
func (h *hostile) after(req *plcvec.Request, steps []plcvec.StepResult, target bool) {
	switch {
	case h.name == "cpu-writes":
		for i := range steps {
			write(req, &steps[i], "SM56", plcvec.Bit(true))
			write(req, &steps[i], "SD1", plcvec.Word(1))
			if target {
				write(req, &steps[i], "SD0", plcvec.Word(1))
			}
		}
	case h.name == "mutates-request":
		if target {
			for i := range req.Devices {
				req.Devices[i] = plcvec.Device{}
			}
			req.Devices, req.Steps = nil, nil
		}
	case !target:
	case h.name == "wrong-result" || h.name == "closes-fds":
		if r := steps[0].Result; r != plcvec.NoResult {
			steps[0].Result = plcvec.Contact(r != plcvec.ResultOn)
		} else {
			changeWord(req, &steps[0], func(w uint16) plcvec.Value { return plcvec.Word(w + 1) })
		}
	case h.name == "stray-write":
		steps[0].Devices = append(steps[0].Devices, plcvec.Device{Name: "D7777", Value: plcvec.Word(1)})
	case h.name == "duplicate-write":
		d := req.Devices[0]
		other := plcvec.Word(steps[0].Values[0].Word() + 1)
		if steps[0].Values[0].IsBit() {
			other = plcvec.Bit(!steps[0].Values[0].Bit())
		}
		steps[0].Devices = append(steps[0].Devices, plcvec.Device{Name: d.Name, Value: other})
	case h.name == "wrong-type":
		for j, v := range steps[0].Values {
			if v.IsBit() {
				steps[0].Values[j] = plcvec.Word(1)
				break
			}
		}
	case h.name == "out-of-range":
		changeWord(req, &steps[0], func(uint16) plcvec.Value { return plcvec.Value(70000) })
	case h.name == "word-65536":
		changeWord(req, &steps[0], func(uint16) plcvec.Value { return plcvec.Value(65536) })
	}
}

// holdStdout starts a process that inherits stdout and stderr and sleeps 300 s, left running:
// a runner that waits for the end of its output would wait for it.
func holdStdout() error {
	cmd := exec.Command("sleep", "300")
	cmd.Stdout, cmd.Stderr = os.Stdout, os.Stderr
	if err := cmd.Start(); err != nil {
		return err
	}
	return cmd.Process.Release()
}

// own copies the reference's answer into slices of its own.
func own(req *plcvec.Request, steps []plcvec.StepResult) []plcvec.StepResult {
	out := make([]plcvec.StepResult, len(steps))
	for i, s := range steps {
		out[i] = plcvec.StepResult{Result: s.Result, Values: append([]plcvec.Value(nil), s.Values...),
			Devices: append([]plcvec.Device(nil), s.Devices...)}
	}
	return out
}

// write sets a device in a step's answer: its value if the request lists it, else a write
// outside the vector.
func write(req *plcvec.Request, s *plcvec.StepResult, name string, v plcvec.Value) {
	for j, d := range req.Devices {
		if d.Name == name {
			s.Values[j] = v
			return
		}
	}
	s.Devices = append(s.Devices, plcvec.Device{Name: name, Value: v})
}

// changeWord changes the word the step wrote (the first, by name), else the first word.
func changeWord(req *plcvec.Request, s *plcvec.StepResult, change func(uint16) plcvec.Value) {
	words := []int{}
	for j, v := range s.Values {
		if !v.IsBit() {
			words = append(words, j)
		}
	}
	sort.SliceStable(words, func(a, b int) bool {
		return s.Values[words[a]] != req.Devices[words[a]].Value && s.Values[words[b]] == req.Devices[words[b]].Value
	})
	if len(words) > 0 {
		j := words[0]
		s.Values[j] = change(s.Values[j].Word())
	}
}
