package plcvec_test

import (
	"encoding/json"
	"errors"
	"os"
	"path/filepath"
	"regexp"
	"strings"
	"testing"

	"github.com/plcvec/plcvec/verifiers/go"
)

// textCases is verifiers/parity/text/: vectors, the answers of an implementation, and the text
// every plcvec runner prints for that run, byte for byte.
const textCases = "../parity/text"

// answered is the implementation of the shared cases: it declares answers.json's hello and
// answers each vector as answers.json says.
type answered struct {
	hello   plcvec.Hello
	answers map[string]json.RawMessage
}

func (a answered) Hello() plcvec.Hello { return a.hello }

func (a answered) Run(req *plcvec.Request) ([]plcvec.StepResult, error) {
	var answer struct {
		Steps []struct {
			Devices map[string]plcvec.Value `json:"devices"`
			Result  *bool                   `json:"result"`
		} `json:"steps"`
		Skip  *string `json:"skip"`
		Error *string `json:"error"`
	}
	if err := json.Unmarshal(a.answers[req.ID], &answer); err != nil {
		return nil, err
	}
	switch {
	case answer.Skip != nil:
		return nil, plcvec.Skip(*answer.Skip)
	case answer.Error != nil:
		return nil, errors.New(*answer.Error)
	}
	steps := make([]plcvec.StepResult, len(answer.Steps))
	for i, s := range answer.Steps {
		for name, v := range s.Devices {
			steps[i].Devices = append(steps[i].Devices, plcvec.Device{Name: name, Value: v})
		}
		if s.Result != nil {
			steps[i].Result = plcvec.Contact(*s.Result)
		}
	}
	return steps, nil
}

// TestSharedText: the run of the shared cases, judged and described by this runner's own code,
// is the expected text byte for byte (the machine's header line and the run's time left out).
func TestSharedText(t *testing.T) {
	raw, err := os.ReadFile(filepath.Join(textCases, "answers.json"))
	if err != nil {
		t.Fatal(err)
	}
	var cases struct {
		Hello struct {
			Adapter struct {
				Name    string `json:"name"`
				Version string `json:"version"`
			} `json:"adapter"`
			Instructions    []string          `json:"instructions"`
			Interpretations map[string]string `json:"interpretations"`
			CPUWrites       []string          `json:"cpu_writes"`
		} `json:"hello"`
		Answers map[string]json.RawMessage `json:"answers"`
	}
	if err := json.Unmarshal(raw, &cases); err != nil {
		t.Fatal(err)
	}
	suite, err := plcvec.Load(filepath.Join(textCases, "vectors"))
	if err != nil {
		t.Fatal(err)
	}
	h := cases.Hello
	impl := answered{plcvec.Hello{Name: h.Adapter.Name, Version: h.Adapter.Version, Instructions: h.Instructions,
		Interpretations: h.Interpretations, CPUWrites: h.CPUWrites}, cases.Answers}
	for _, c := range []struct{ known, expected string }{{"", "expected.txt"}, {"known.toml", "expected-known.txt"}} {
		t.Run(c.expected, func(t *testing.T) {
			compareText(t, impl, plcvec.Options{Suite: suite, Expectations: c.known}, c.expected)
		})
	}
}

// compareText runs the shared cases and compares the run's text with the expected file.
func compareText(t *testing.T, impl plcvec.Implementation, opts plcvec.Options, expected string) {
	t.Helper()
	folder, err := filepath.Abs(textCases)
	if err != nil {
		t.Fatal(err)
	}
	if opts.Expectations != "" {
		// The file is given as the shared cases name it: `known.toml`, from its own folder.
		here, err := os.Getwd()
		if err != nil {
			t.Fatal(err)
		}
		if err := os.Chdir(folder); err != nil {
			t.Fatal(err)
		}
		defer os.Chdir(here)
	}
	report, err := plcvec.Verify(impl, opts)
	if err != nil {
		t.Fatal(err)
	}
	plcvec.InVerifySyntax(report) // the expected text holds plcvec verify's --choose
	got := report.Summary()
	got = regexp.MustCompile(`(?m)^plcvec: .* against .*\n`).ReplaceAllString(got, "")
	got = regexp.MustCompile(` in [0-9.]+ s\n$`).ReplaceAllString(got, "\n")
	want, err := os.ReadFile(filepath.Join(folder, expected))
	if err != nil {
		t.Fatal(err)
	}
	if got != string(want) {
		gl, wl := strings.Split(got, "\n"), strings.Split(string(want), "\n")
		for i := 0; i < len(gl) || i < len(wl); i++ {
			var g, w string
			if i < len(gl) {
				g = gl[i]
			}
			if i < len(wl) {
				w = wl[i]
			}
			if g != w {
				t.Errorf("line %d differs:\n got: %q\nwant: %q", i+1, g, w)
				break
			}
		}
		t.Logf("the whole text:\n%s", got)
	}
}

// TestDeclarationInTextMD: the roll-up writes a declaration as TEXT.md's table gives it for Go
// ("The declaration in each runner"), from the generated names.
func TestDeclarationInTextMD(t *testing.T) {
	raw, err := os.ReadFile(filepath.Join(textCases, "..", "TEXT.md"))
	if err != nil {
		t.Fatal(err)
	}
	row := regexp.MustCompile("(?m)^\\| Go \\| `([^`]+)` \\|$").FindStringSubmatch(string(raw))
	if row == nil {
		t.Fatal("TEXT.md has no Go row in its table of declarations")
	}
	got := plcvec.Declaration(map[string]string{"TADD-FLAGS-OFF": "set-only", "FX5-SM709-SCOPE": "all-words"})
	if got != row[1] {
		t.Errorf("got  %s\nwant %s", got, row[1])
	}
}
