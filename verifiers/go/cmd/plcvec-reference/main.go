// Command plcvec-reference serves the Go reference implementation (or one of its mutants) over
// the plcvec stdio protocol (verifiers/PROTOCOL.md), so that the suite's own gate runs it:
//
//	python3 -m plcvec verify --adapter verifiers/go/reference-adapter
//	python3 -m plcvec verify --adapter "verifiers/go/reference-adapter --mutant cp1e-and-as-or"
//
// It reads one JSON object a line on stdin and writes one a line on stdout; logs go to stderr.
// A line it cannot read gets a `fatal` answer and exit status 2; a vector it cannot run gets an
// `error` result; it never panics on its input.
package main

import (
	"bufio"
	"encoding/json"
	"flag"
	"fmt"
	"io"
	"os"
	"sort"
	"strings"

	"github.com/plcvec/plcvec/verifiers/go"
	"github.com/plcvec/plcvec/verifiers/go/mutants"
	"github.com/plcvec/plcvec/verifiers/go/reference"
)

const protocol = 1

type choices map[string]string

func (c choices) String() string { return fmt.Sprint(map[string]string(c)) }
func (c choices) Set(s string) error {
	id, alt, ok := strings.Cut(s, "=")
	if !ok {
		return fmt.Errorf("--choose takes ID=ALTERNATIVE, not %q", s)
	}
	c[id] = alt
	return nil
}

func main() {
	chosen := choices{}
	mutant := flag.String("mutant", "", "serve this mutant of the reference instead (see package mutants)")
	flag.Var(chosen, "choose", "follow this interpretation alternative, ID=ALTERNATIVE (repeatable)")
	flag.Parse()
	impl, err := build(*mutant, chosen)
	if err != nil {
		fmt.Fprintf(os.Stderr, "plcvec-reference: %v\n", err)
		os.Exit(2)
	}
	os.Exit(serve(impl, os.Stdin, os.Stdout))
}

func build(mutant string, chosen choices) (plcvec.Implementation, error) {
	if mutant != "" {
		m, err := mutants.Find(mutant)
		if err != nil {
			return nil, err
		}
		return m.New(chosen)
	}
	r, err := reference.New(chosen)
	if err != nil {
		return nil, err
	}
	return r.Implementation(), nil
}

// message is any runner -> adapter message; only the fields of its type are set.
type message struct {
	Type     string            `json:"type"`
	Protocol *int              `json:"protocol"`
	Families map[string]family `json:"families"`
	Batch    *int              `json:"batch"`
	Vectors  []json.RawMessage `json:"vectors"`
}

type family struct {
	Instructions    []string                   `json:"instructions"`
	Interpretations map[string]json.RawMessage `json:"interpretations"`
}

// request is one vector of a run message (run-request.schema.json#/$defs/request).
type request struct {
	ID          string          `json:"id"`
	Family      string          `json:"family"`
	Instruction string          `json:"instruction"`
	Assumes     plcvec.Assumes  `json:"assumes"`
	Initial     plcvec.Initial  `json:"initial"`
	Steps       []plcvec.Inputs `json:"steps"`
}

type stepOut struct {
	Result  *bool                   `json:"result,omitempty"`
	Devices map[string]plcvec.Value `json:"devices"`
}

type result struct {
	Type  string    `json:"type"`
	ID    string    `json:"id"`
	Steps []stepOut `json:"steps,omitempty"`
	Skip  string    `json:"skip,omitempty"`
	Error string    `json:"error,omitempty"`
}

func serve(impl plcvec.Implementation, in io.Reader, out io.Writer) int {
	r := bufio.NewReaderSize(in, 1<<20)
	w := bufio.NewWriterSize(out, 1<<16)
	defer w.Flush()
	enc := json.NewEncoder(w)
	fatal := func(format string, args ...any) int {
		_ = enc.Encode(map[string]string{"type": "fatal", "message": fmt.Sprintf(format, args...)})
		return 2
	}
	for lineNo := 1; ; lineNo++ {
		line, err := r.ReadBytes('\n')
		if len(strings.TrimSpace(string(line))) == 0 {
			if err != nil {
				return 0 // end of input means bye
			}
			continue
		}
		var msg message
		if jerr := json.Unmarshal(line, &msg); jerr != nil {
			return fatal("stdin line %d is not a protocol message: %v", lineNo, jerr)
		}
		switch msg.Type {
		case "hello":
			if msg.Protocol == nil || *msg.Protocol != protocol {
				got := "none"
				if msg.Protocol != nil {
					got = fmt.Sprint(*msg.Protocol)
				}
				return fatal("this adapter speaks protocol %d, not %s", protocol, got)
			}
			if err := enc.Encode(hello(impl, msg.Families)); err != nil {
				return 1
			}
		case "run":
			for _, raw := range msg.Vectors {
				if err := enc.Encode(run(impl, raw)); err != nil {
					return 1
				}
			}
		case "bye":
			return 0
		default:
			return fatal("stdin line %d: unknown message type %q (expected hello, run or bye)", lineNo, msg.Type)
		}
		if err := w.Flush(); err != nil {
			return 1
		}
	}
}

// hello answers with the instructions of the runner's families that the reference runs, the
// alternative it follows for each of their interpretations, and any devices its CPU writes on
// its own account.
func hello(impl plcvec.Implementation, families map[string]family) map[string]any {
	h := impl.Hello()
	instructions := []string{}
	interps := map[string]string{}
	for _, f := range families {
		for _, i := range f.Instructions {
			if h.Instructions == nil || contains(h.Instructions, i) {
				instructions = append(instructions, i)
			}
		}
		for id := range f.Interpretations {
			if alt, ok := h.Interpretations[id]; ok {
				interps[id] = alt
			}
		}
	}
	sort.Strings(instructions)
	answer := map[string]any{"type": "hello", "protocol": protocol,
		"adapter":      map[string]string{"name": h.Name, "version": h.Version},
		"instructions": instructions, "interpretations": interps}
	if len(h.CPUWrites) > 0 { // PROTOCOL.md: the devices the CPU writes on its own account
		answer["cpu_writes"] = h.CPUWrites
	}
	return answer
}

func contains(list []string, s string) bool {
	for _, x := range list {
		if x == s {
			return true
		}
	}
	return false
}

// run runs one vector; whatever goes wrong is that vector's `error`, never the loop's.
func run(impl plcvec.Implementation, raw json.RawMessage) (res result) {
	res.Type = "result"
	var req request
	if err := json.Unmarshal(raw, &req); err != nil {
		var probe struct {
			ID string `json:"id"`
		}
		_ = json.Unmarshal(raw, &probe)
		res.ID, res.Error = probe.ID, "the request is not a valid vector: "+err.Error()
		return res
	}
	res.ID = req.ID
	if req.Initial.Devices == nil || req.Initial.Operands == nil || len(req.Steps) == 0 {
		res.Error = "the request needs initial.devices, initial.operands and steps"
		return res
	}
	defer func() {
		if p := recover(); p != nil {
			res.Steps, res.Error = nil, fmt.Sprintf("the implementation panicked: %v", p)
		}
	}()
	request := plcvec.NewRequest(req.ID, req.Family, req.Instruction, req.Assumes.DeviceSizes,
		req.Initial.Devices, req.Initial.Operands, req.Initial.Scratch, req.Steps)
	steps, err := impl.Run(request)
	if err != nil {
		if reason, ok := plcvec.IsSkip(err); ok {
			res.Skip = reason
		} else {
			res.Error = err.Error()
		}
		return res
	}
	res.Steps = make([]stepOut, len(steps))
	for i, st := range steps {
		image := st.Image(request)
		devices := make(map[string]plcvec.Value, len(image))
		for _, d := range image {
			devices[d.Name] = d.Value
		}
		res.Steps[i].Devices = devices
		if st.Result != plcvec.NoResult {
			on := st.Result == plcvec.ResultOn
			res.Steps[i].Result = &on
		}
	}
	return res
}
