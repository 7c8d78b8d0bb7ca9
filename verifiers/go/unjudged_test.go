package plcvec_test

import (
	"bufio"
	"encoding/json"
	"os"
	"path/filepath"
	"strings"
	"testing"

	"github.com/plcvec/plcvec/verifiers/go"
	"github.com/plcvec/plcvec/verifiers/go/reference"
	"github.com/plcvec/plcvec/verifiers/go/spec"
)

// Devices an alternative leaves unjudged (schema 1.1, verifiers/parity/unjudged rule), on a
// hand-made vector until the golden set has some: the HOUR vector whose D1 holds a minute of
// 65535, its alternative HOUR-D1-OUT-OF-RANGE=error (with HOUR-FIRST-SCAN=counts) made to leave
// D1's three words unjudged. Under that combination the vector expects M8004 on, D2 (M10) and
// S1 as they were, and nothing of D200..D202.
const unjudgedID = "fc6a-hour-meter/HOUR/measured-out-of-range/minute=65535/1000ms"

var unjudgedD1 = []string{"D200", "D201", "D202"}

// unjudgedSuite writes the one-vector folder, the vector's error entry edited by edit (nil: as
// described above), the header at schema version schema.
func unjudgedSuite(t *testing.T, schema string, edit func(entry map[string]any)) string {
	t.Helper()
	f, err := os.Open(filepath.Join("vectors", "fc6a-hour-meter.jsonl"))
	if err != nil {
		t.Fatal(err)
	}
	defer f.Close()
	sc := bufio.NewScanner(f)
	sc.Buffer(nil, 1<<20)
	var header, vector map[string]any
	for sc.Scan() {
		var obj map[string]any
		if err := json.Unmarshal(sc.Bytes(), &obj); err != nil {
			t.Fatal(err)
		}
		if header == nil {
			header = obj
		} else if obj["id"] == unjudgedID {
			vector = obj
		}
	}
	if vector == nil {
		t.Fatalf("no vector %s in the golden set", unjudgedID)
	}
	header["schema_version"], header["count"] = schema, 1
	for _, a := range vector["alternatives"].([]any) {
		entry := a.(map[string]any)
		choices := entry["choices"].(map[string]any)
		if choices[spec.InterpHourD1OutOfRange] != spec.HourD1OutOfRangeError || choices[spec.InterpHourFirstScan] != spec.HourFirstScanCounts {
			continue
		}
		final := entry["final"].(map[string]any)["devices"].(map[string]any)
		for _, d := range unjudgedD1 {
			delete(final, d)
		}
		entry["unjudged"] = map[string]any{spec.InterpHourD1OutOfRange: unjudgedD1}
		if edit != nil {
			edit(entry)
		}
	}
	dir := t.TempDir()
	var lines []string
	for _, obj := range []map[string]any{header, vector} {
		b, _ := json.Marshal(obj)
		lines = append(lines, string(b))
	}
	write := func(name, text string) {
		if err := os.WriteFile(filepath.Join(dir, name), []byte(text), 0o644); err != nil {
			t.Fatal(err)
		}
	}
	write("fc6a-hour-meter.jsonl", strings.Join(lines, "\n")+"\n")
	write("index.json", `{"families": {"fc6a-hour-meter": {"count": 1, "file": "fc6a-hour-meter.jsonl"}}, "suite_version": "test"}`)
	return dir
}

// answering is the reference following choices, declaring declared, with change applied to its
// answer (device -> value) after the first step.
type answering struct {
	ref      plcvec.Implementation
	declared map[string]string
	change   map[string]plcvec.Value
}

func newAnswering(t *testing.T, choices, declared map[string]string, change map[string]plcvec.Value) answering {
	r, err := reference.New(choices)
	if err != nil {
		t.Fatal(err)
	}
	return answering{r.Implementation(), declared, change}
}

func (a answering) Hello() plcvec.Hello {
	h := a.ref.Hello()
	h.Interpretations = a.declared
	return h
}

func (a answering) Run(req *plcvec.Request) ([]plcvec.StepResult, error) {
	steps, err := a.ref.Run(req)
	if err != nil {
		return nil, err
	}
	image := steps[0].Image(req)
	for i := range image {
		if v, ok := a.change[image[i].Name]; ok {
			image[i].Value = v
		}
	}
	return []plcvec.StepResult{{Result: steps[0].Result, Devices: image}}, nil
}

var errorCounts = map[string]string{spec.InterpHourD1OutOfRange: spec.HourD1OutOfRangeError, spec.InterpHourFirstScan: spec.HourFirstScanCounts}

func verifyOne(t *testing.T, dir string, impl plcvec.Implementation) *plcvec.Report {
	t.Helper()
	suite, err := plcvec.Load(dir)
	if err != nil {
		t.Fatal(err)
	}
	report, err := plcvec.Verify(impl, plcvec.Options{Suite: suite})
	if err != nil {
		t.Fatal(err)
	}
	return report
}

// TestUnjudgedDevicesAreNotCompared: under the combination that leaves D1 unjudged, any value of
// D1's words passes (a write to them is no stray write: the vector lists them), while a judged
// device still fails, and its block says which devices were not judged, after `judged by:` and
// before the step's lines.
func TestUnjudgedDevicesAreNotCompared(t *testing.T) {
	dir := unjudgedSuite(t, "1.1.0", nil)
	scrambled := map[string]plcvec.Value{"D200": plcvec.Word(7), "D201": plcvec.Word(8), "D202": plcvec.Word(9)}
	if r := verifyOne(t, dir, newAnswering(t, errorCounts, errorCounts, scrambled)); !r.OK() {
		t.Errorf("D1 left unjudged was judged:\n%s", r.Summary())
	}
	wrong := map[string]plcvec.Value{"D200": plcvec.Word(7), "M10": plcvec.Bit(true)}
	r := verifyOne(t, dir, newAnswering(t, errorCounts, errorCounts, wrong))
	v := r.Verdicts[0]
	if v.Status != plcvec.StatusFail || len(v.Problems) != 1 || v.Problems[0].Field != "M10" {
		t.Fatalf("want one problem, at M10:\n%s", v.Text())
	}
	lines := strings.Split(v.Text(), "\n")
	want := []string{
		"    judged by: HOUR-D1-OUT-OF-RANGE=error",
		"    not judged under HOUR-D1-OUT-OF-RANGE=error: D200, D201, D202",
		"    step 0 inputs: input=true, elapsed_ms=1000",
		"    step 0 operands: D1 D200=0 65535 0, D2 M10=false, D3 D300 (scratch), S1 D100=1 0 0",
		"    step 0 M10: expected false, got true (the step must leave it unchanged)",
	}
	if len(lines) < 7 || strings.Join(lines[2:7], "\n") != strings.Join(want, "\n") {
		t.Errorf("the block is not as the rule says:\n%s", v.Text())
	}
}

// TestUnjudgedInTheInference: `judged by:` names the interpretation whose other alternative
// leaves the differing device unjudged (D200: 1092 under both alternatives of HOUR-FIRST-SCAN, so
// that one does not decide it); an implementation that follows the alternative leaving D1
// unjudged without declaring it fails under the defaults, passes under that alternative whatever
// its D1, and the roll-up says so.
func TestUnjudgedInTheInference(t *testing.T) {
	dir := unjudgedSuite(t, "1.1.0", nil)
	scrambled := map[string]plcvec.Value{"D200": plcvec.Word(7)}
	v := verifyOne(t, dir, newAnswering(t, nil, nil, scrambled)).Verdicts[0]
	if lines := strings.Split(v.Text(), "\n"); len(v.Problems) != 1 || lines[2] != "    judged by: HOUR-D1-OUT-OF-RANGE=as-seconds" {
		t.Errorf("want one problem judged by HOUR-D1-OUT-OF-RANGE alone:\n%s", v.Text())
	}
	r := verifyOne(t, dir, newAnswering(t, errorCounts, nil, scrambled))
	text := r.Summary()
	for _, want := range []string{
		"READINGS: 1 of 1 failing vectors pass under other alternatives:\n         1  HOUR-D1-OUT-OF-RANGE=error\n",
		"    declare: map[string]string{spec.InterpHourD1OutOfRange: spec.HourD1OutOfRangeError}\n",
	} {
		if !strings.Contains(text, want) {
			t.Errorf("the text lacks %q:\n%s", want, text)
		}
	}
	if strings.Contains(text, "not judged under") {
		t.Errorf("the defaults leave nothing unjudged, yet the block says so:\n%s", text)
	}
}

// TestUnjudgedRefusedWhenMalformed: an `unjudged` map the rule does not allow is refused on load
// by vector id and JSON path.
func TestUnjudgedRefusedWhenMalformed(t *testing.T) {
	for _, c := range []struct {
		name, schema string
		edit         func(map[string]any)
		want         string
	}{
		{"schema 1.0", "1.0.0", nil, "at alternatives/0: `unjudged` is not a key of schema 1.0.0"},
		{"empty", "1.1.0", func(e map[string]any) { e["unjudged"] = map[string]any{spec.InterpHourD1OutOfRange: []string{}} },
			"at alternatives/0/unjudged/HOUR-D1-OUT-OF-RANGE: no device"},
		{"not a choice", "1.1.0", func(e map[string]any) { e["unjudged"] = map[string]any{spec.InterpHourPresetZero: unjudgedD1} },
			"at alternatives/0/unjudged: HOUR-PRESET-ZERO is not one of the entry's choices"},
		{"twice", "1.1.0", func(e map[string]any) {
			e["unjudged"] = map[string]any{spec.InterpHourD1OutOfRange: []string{"D200", "D200", "D201", "D202"}}
		}, "at alternatives/0/unjudged/HOUR-D1-OUT-OF-RANGE: D200 is listed twice"},
		{"not in initial", "1.1.0", func(e map[string]any) {
			e["unjudged"] = map[string]any{spec.InterpHourD1OutOfRange: []string{"D200", "D201", "D202", "D999"}}
		}, "at alternatives/0/unjudged/HOUR-D1-OUT-OF-RANGE: D999 is not in initial/devices"},
		{"still expected", "1.1.0", func(e map[string]any) { e["final"].(map[string]any)["devices"].(map[string]any)["D201"] = 65535 },
			"at alternatives/0/final/devices/D201: D201 is left unjudged by this entry"},
	} {
		t.Run(c.name, func(t *testing.T) {
			dir := unjudgedSuite(t, c.schema, c.edit)
			_, err := plcvec.Load(dir)
			want := "fc6a-hour-meter.jsonl:2: vector " + unjudgedID + ": " + c.want
			if err == nil || !strings.Contains(err.Error(), want) {
				t.Errorf("got %v\nwant %s", err, want)
			}
		})
	}
}
