package main

import (
	"bytes"
	"encoding/json"
	"fmt"
	"strings"
	"testing"

	"github.com/plcvec/plcvec/verifiers/go"
)

func answers(t *testing.T, input string) ([]map[string]any, int) {
	t.Helper()
	impl, err := build("", choices{})
	if err != nil {
		t.Fatal(err)
	}
	var out bytes.Buffer
	code := serve(impl, strings.NewReader(input), &out)
	var msgs []map[string]any
	for _, line := range strings.Split(strings.TrimSpace(out.String()), "\n") {
		if line == "" {
			continue
		}
		var m map[string]any
		if err := json.Unmarshal([]byte(line), &m); err != nil {
			t.Fatalf("the adapter wrote a line that is not JSON: %q", line)
		}
		msgs = append(msgs, m)
	}
	return msgs, code
}

// The manual's TADD example as the runner sends it (PROTOCOL.md's transcript).
const helloLine = `{"type": "hello", "protocol": 1, "families": {"fx5-time-add": {"instructions": ["TADD", "TADDP"], "interpretations": {"TADD-EXACT-24": {"default": "carry-at-24", "alternatives": ["carry-at-24", "carry-above-24"]}}}}}`
const runLine = `{"type": "run", "batch": 0, "vectors": [{"id": "fx5-time-add/TADD/manual-example/program", "family": "fx5-time-add", "instruction": "TADD", "assumes": {"device_sizes": {"D": 8000, "R": 32768, "SD": 12000}}, "initial": {"devices": {"D10": 10, "D11": 30, "D12": 10, "D20": 3, "D21": 10, "D22": 5, "D30": 65535, "D31": 65535, "D32": 65535, "SD0": 0, "SD8067": 0, "SM700": false, "SM8020": false, "SM8022": false}, "operands": {"d": {"device": "D30"}, "s1": {"device": "D10"}, "s2": {"device": "D20"}}}, "steps": [{"en": true}]}]}`

func TestTranscript(t *testing.T) {
	msgs, code := answers(t, helloLine+"\n"+runLine+"\n"+`{"type": "bye"}`+"\n")
	if code != 0 || len(msgs) != 2 {
		t.Fatalf("exit %d, %d answers: %v", code, len(msgs), msgs)
	}
	if msgs[0]["type"] != "hello" || msgs[0]["protocol"] != float64(1) {
		t.Errorf("hello answer: %v", msgs[0])
	}
	if got := msgs[0]["interpretations"].(map[string]any); len(got) != 1 || got["TADD-EXACT-24"] != "carry-at-24" {
		t.Errorf("declares %v; only the runner's interpretations, with their alternatives", got)
	}
	// 10:30:10 + 3:10:05 = 13:40:15 in D30..D32, no carry, no zero.
	devices := msgs[1]["steps"].([]any)[0].(map[string]any)["devices"].(map[string]any)
	for name, want := range map[string]any{"D30": float64(13), "D31": float64(40), "D32": float64(15), "SM700": false, "SM8020": false} {
		if devices[name] != want {
			t.Errorf("%s = %v, want %v", name, devices[name], want)
		}
	}
	if _, has := msgs[1]["steps"].([]any)[0].(map[string]any)["result"]; has {
		t.Error("TADD is not a contact: no result")
	}
}

func TestMalformedInput(t *testing.T) {
	for _, c := range []struct {
		name, input string
		code        int
		want        string
	}{
		{"not JSON", "not json\n", 2, "stdin line 1 is not a protocol message"},
		{"another protocol", `{"type": "hello", "protocol": 2}` + "\n", 2, "speaks protocol 1, not 2"},
		{"unknown type", `{"type": "dance"}` + "\n", 2, `unknown message type "dance"`},
		{"a vector of the wrong shape", `{"type": "run", "batch": 0, "vectors": [{"id": "v", "steps": 5}]}` + "\n", 0, "the request is not a valid vector"},
		{"a vector without steps", `{"type": "run", "batch": 0, "vectors": [{"id": "v", "family": "fx5-time-add", "instruction": "TADD", "initial": {"devices": {}, "operands": {}}, "steps": []}]}` + "\n", 0, "needs initial.devices, initial.operands and steps"},
		{"an unknown family", `{"type": "run", "batch": 0, "vectors": [{"id": "v", "family": "x", "instruction": "X", "initial": {"devices": {}, "operands": {}}, "steps": [{}]}]}` + "\n", 0, "the reference has no family x"},
		{"an operand missing", `{"type": "run", "batch": 0, "vectors": [{"id": "v", "family": "fx5-time-add", "instruction": "TADD", "initial": {"devices": {"D0": 1}, "operands": {}}, "steps": [{"en": true}]}]}` + "\n", 0, "TADD: no operand s1"},
	} {
		t.Run(c.name, func(t *testing.T) {
			msgs, code := answers(t, c.input)
			if code != c.code || len(msgs) != 1 {
				t.Fatalf("exit %d, answers %v", code, msgs)
			}
			text := fmt.Sprint(msgs[0]["message"], msgs[0]["error"], msgs[0]["skip"])
			if !strings.Contains(text, c.want) {
				t.Errorf("want %q in %v", c.want, msgs[0])
			}
		})
	}
	// End of input without bye is a clean exit.
	if msgs, code := answers(t, ""); code != 0 || len(msgs) != 0 {
		t.Errorf("empty input: exit %d, %v", code, msgs)
	}
}

func TestBuild(t *testing.T) {
	if _, err := build("no-such-mutant", choices{}); err == nil {
		t.Error("an unknown mutant was served")
	}
	if _, err := build("", choices{"TADD-EXACT-24": "carry-at-99"}); err == nil {
		t.Error("an unknown alternative was accepted")
	}
	c := choices{}
	if err := c.Set("no-equals"); err == nil {
		t.Error("--choose without = accepted")
	}
	var _ plcvec.Implementation = mustImpl(t)
}

func mustImpl(t *testing.T) plcvec.Implementation {
	impl, err := build("cp1e-and-as-or", choices{})
	if err != nil {
		t.Fatal(err)
	}
	return impl
}
