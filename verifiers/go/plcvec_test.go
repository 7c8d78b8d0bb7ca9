package plcvec_test

import (
	"os"
	"os/exec"
	"path/filepath"
	"regexp"
	"strings"
	"testing"
	"time"

	"github.com/plcvec/plcvec/verifiers/go"
	"github.com/plcvec/plcvec/verifiers/go/reference"
	"github.com/plcvec/plcvec/verifiers/go/spec"
)

// The manual's TADD example (fx5-time-add-TADD.txt): 10:30:10 + 3:10:05 = 13:40:15, in D30..D32.
const manualTADD = "fx5-time-add/TADD/manual-example/program"

// manualAnswer answers that vector as the manual prints it, with one change applied.
type manualAnswer struct {
	change func(devices []plcvec.Device) []plcvec.Device
}

func (manualAnswer) Hello() plcvec.Hello {
	return plcvec.Hello{Name: "manual", Instructions: []string{spec.InstrTadd}}
}

func (m manualAnswer) Run(req *plcvec.Request) ([]plcvec.StepResult, error) {
	if req.ID != manualTADD {
		return nil, plcvec.Skip("only the manual's example")
	}
	out := append([]plcvec.Device(nil), req.Devices...)
	for i := range out {
		switch out[i].Name {
		case "D30":
			out[i].Value = plcvec.Word(13)
		case "D31":
			out[i].Value = plcvec.Word(40)
		case "D32":
			out[i].Value = plcvec.Word(15)
		}
	}
	if m.change != nil {
		out = m.change(out)
	}
	return []plcvec.StepResult{{Devices: out}}, nil
}

func set(name string, v plcvec.Value) func([]plcvec.Device) []plcvec.Device {
	return func(ds []plcvec.Device) []plcvec.Device {
		for i := range ds {
			if ds[i].Name == name {
				ds[i].Value = v
				return ds
			}
		}
		return append(ds, plcvec.Device{Name: name, Value: v})
	}
}

func judge(t *testing.T, impl plcvec.Implementation) plcvec.Verdict {
	t.Helper()
	report, err := plcvec.Verify(impl, plcvec.Options{Selection: plcvec.Selection{IDs: []string{manualTADD}}})
	if err != nil {
		t.Fatal(err)
	}
	if len(report.Verdicts) != 1 {
		t.Fatalf("%d verdicts for one id", len(report.Verdicts))
	}
	return report.Verdicts[0]
}

func TestComparison(t *testing.T) {
	if v := judge(t, manualAnswer{}); v.Status != plcvec.StatusPass {
		t.Fatalf("the manual's own answer does not pass:\n%s", v.Text())
	}
	cases := []struct {
		name   string
		change func([]plcvec.Device) []plcvec.Device
		want   string
	}{
		{"changed word", set("D31", plcvec.Word(41)), "step 0 D31: expected 40, got 41"},
		{"bit reported as a word", set("SM700", plcvec.Word(0)), "step 0 SM700: expected false, got 0 (the step must leave it unchanged)"},
		{"device that must stay unchanged", set("D10", plcvec.Word(0)), "step 0 D10: expected 10, got 0 (the step must leave it unchanged)"},
		{"write outside the vector", set("D33", plcvec.Word(0)), "step 0 D33: expected <not in the vector>, got 0"},
		{"device not reported", func(ds []plcvec.Device) []plcvec.Device { return ds[1:] }, "step 0 D10: expected 10, got <not reported>"},
		{"device reported twice", func(ds []plcvec.Device) []plcvec.Device { return append(ds, ds[0]) }, "step 0 D10: expected one value, got the device reported twice"},
	}
	for _, c := range cases {
		t.Run(c.name, func(t *testing.T) {
			v := judge(t, manualAnswer{change: c.change})
			if v.Status != plcvec.StatusFail || len(v.Problems) != 1 || !strings.HasPrefix(v.Problems[0].String(), c.want) {
				t.Errorf("want one problem %q, got %s:\n%s", c.want, v.Status, v.Text())
			}
			if !strings.Contains(v.Text(), "spec clauses: fx5-time-add#") {
				t.Errorf("the report does not name the clauses:\n%s", v.Text())
			}
		})
	}
}

// contactTamper runs the reference and then changes the contact result of step 0.
type contactTamper struct {
	plcvec.Implementation
	result plcvec.Result
}

func (c contactTamper) Run(req *plcvec.Request) ([]plcvec.StepResult, error) {
	steps, err := c.Implementation.Run(req)
	if err == nil {
		steps[0].Result = c.result
	}
	return steps, err
}

func TestContactResult(t *testing.T) {
	ref, err := reference.New(nil)
	if err != nil {
		t.Fatal(err)
	}
	// "AND gives rlo_in AND the comparison": with rlo_in off the result is off.
	id := "cp1e-time-compare/AND <=DT/logic/rlo-off/eq"
	for _, c := range []struct {
		result plcvec.Result
		want   string
	}{{plcvec.ResultOn, "step 0 result: expected false, got true"}, {plcvec.NoResult, "step 0 result: expected false, got <not reported>"}} {
		report, err := plcvec.Verify(contactTamper{ref.Implementation(), c.result},
			plcvec.Options{Selection: plcvec.Selection{IDs: []string{id}}})
		if err != nil {
			t.Fatal(err)
		}
		v := report.Verdicts[0]
		if v.Status != plcvec.StatusFail || v.Problems[0].String() != c.want {
			t.Errorf("want %q, got:\n%s", c.want, v.Text())
		}
	}
}

func TestShard(t *testing.T) {
	// crc32 (IEEE) of the UTF-8 id, % N + 1, the rule of every plcvec runner; the values are
	// Python's zlib.crc32 of the same ids.
	for _, c := range []struct {
		id      string
		n, want int
	}{{"123456789", 4, 3}, {"123456789", 7, 6}, {manualTADD, 4, 3}, {"cp1e-time-compare/AND <=DT/logic/rlo-off/eq", 7, 5}} {
		if got := plcvec.ShardOf(c.id, c.n); got != c.want {
			t.Errorf("ShardOf(%q, %d) = %d, want %d", c.id, c.n, got, c.want)
		}
	}
	suite, err := plcvec.Default()
	if err != nil {
		t.Fatal(err)
	}
	total := 0
	for k := 1; k <= 3; k++ {
		vs, err := suite.Select(plcvec.Selection{Shard: plcvec.Shard{K: k, N: 3}})
		if err != nil {
			t.Fatal(err)
		}
		total += len(vs)
	}
	if total != len(suite.Vectors) {
		t.Errorf("shards 1..3 of 3 hold %d vectors, the suite %d", total, len(suite.Vectors))
	}
	for _, bad := range []string{"0/3", "4/3", "x", "1/"} {
		if _, err := plcvec.ParseShard(bad); err == nil {
			t.Errorf("ParseShard(%q) accepted", bad)
		}
	}
}

func TestSelection(t *testing.T) {
	suite, err := plcvec.Default()
	if err != nil {
		t.Fatal(err)
	}
	vs, err := suite.Select(plcvec.Selection{IDs: []string{"fx5-time-add/TADD*/manual-example/*"}})
	if err != nil || len(vs) == 0 {
		t.Fatalf("glob across '/' selected %d (%v)", len(vs), err)
	}
	for _, v := range vs {
		if !strings.HasPrefix(v.ID, "fx5-time-add/TADD") || !strings.Contains(v.ID, "/manual-example/") {
			t.Errorf("glob selected %s", v.ID)
		}
	}
	vs, _ = suite.Select(plcvec.Selection{Families: []string{spec.FamilyFx5TimeAdd}, Instructions: []string{spec.InstrTaddp}, Tags: []string{spec.TagPulse}})
	for _, v := range vs {
		if v.Instruction != spec.InstrTaddp {
			t.Errorf("instruction filter let %s through", v.ID)
		}
	}
	if len(vs) == 0 {
		t.Error("no TADDP pulse vector selected")
	}
	for _, sel := range []plcvec.Selection{{Families: []string{"fx5-time-ad"}}, {Tags: []string{"no-such-tag"}}} {
		if _, err := suite.Select(sel); err == nil {
			t.Errorf("%+v: a misspelt name selected silently", sel)
		}
	}
	// An empty selection never passes a gate.
	sel := plcvec.Selection{Families: []string{spec.FamilyFx5TimeAdd}, IDs: []string{"fx5-time-compare/*"}}
	if _, err := plcvec.Verify(manualAnswer{}, plcvec.Options{Selection: sel}); err == nil ||
		!strings.Contains(err.Error(), "selects no vector") {
		t.Errorf("an empty selection was not refused: %v", err)
	}
	// A glob that matches no id of the suite is a mistake of its own, named.
	if _, err := plcvec.Verify(manualAnswer{}, plcvec.Options{Selection: plcvec.Selection{IDs: []string{"nothing/*"}}}); err == nil ||
		!strings.Contains(err.Error(), `"nothing/*" matches no vector id`) {
		t.Errorf("a glob matching nothing was not refused: %v", err)
	}
}

func TestDeclaredAlternatives(t *testing.T) {
	bad := []map[string]string{{"NO-SUCH": "x"}, {spec.InterpTaddExact24: "carry-at-25"}}
	for _, decl := range bad {
		impl := declaring{decl}
		if _, err := plcvec.Verify(impl, plcvec.Options{}); err == nil {
			t.Errorf("declaration %v accepted", decl)
		}
	}
}

type declaring struct{ interps map[string]string }

func (d declaring) Hello() plcvec.Hello { return plcvec.Hello{Name: "d", Interpretations: d.interps} }
func (declaring) Run(*plcvec.Request) ([]plcvec.StepResult, error) {
	return nil, plcvec.Skip("never runs")
}

func TestKnownFailures(t *testing.T) {
	dir := t.TempDir()
	path := filepath.Join(dir, "known.toml")
	write := func(text string) {
		if err := os.WriteFile(path, []byte(text), 0o644); err != nil {
			t.Fatal(err)
		}
	}
	opts := plcvec.Options{Selection: plcvec.Selection{IDs: []string{manualTADD}}, Expectations: path}
	write("[[known-failure]]\nid = \"" + manualTADD + "\"\nreason = \"our D31 is off by one\"\n")
	report, err := plcvec.Verify(manualAnswer{change: set("D31", plcvec.Word(41))}, opts)
	if err != nil {
		t.Fatal(err)
	}
	// (Not OK all the same: a run of known failures alone passes nothing; known_test.go.)
	if v := report.Verdicts[0]; v.Status != plcvec.StatusXFail || len(report.Failed()) != 0 {
		t.Errorf("a listed failure is not xfail: %s", v.Text())
	}
	report, _ = plcvec.Verify(manualAnswer{}, opts)
	if v := report.Verdicts[0]; v.Status != plcvec.StatusStale || report.OK() {
		t.Errorf("a listed pass is not stale: %s", v.Text())
	}
	write("[[known-failure]]\nid = \"no/such/vector\"\nreason = \"gone\"\n")
	report, _ = plcvec.Verify(manualAnswer{}, opts)
	if report.OK() || report.Verdicts[len(report.Verdicts)-1].Status != plcvec.StatusStale {
		t.Errorf("an unknown id is not stale: %+v", report.Verdicts)
	}
	for text, want := range map[string]string{
		"[[known-failure]]\nid = \"x\"\n":                          "known.toml:1: x: every known failure needs a `reason`",
		"[[known-failure]]\nid = \"x\"\nreason = \"r\"\nwhy = 1\n": "known.toml:1: unknown key \"why\"",
		"[[known-failure]\n":                                       "not valid TOML: expected end of table array name",
		"skip = [\"x\"]\n":                                         "known.toml:1: unknown key \"skip\"",
		"[[known-failure]]\nid = \"x\"\nreason = \"r\"\n\n[[known-failure]]\nid = \"x\"\nreason = \"r\"\n": "known.toml:5: x is listed twice (first at line 1)",
	} {
		write(text)
		_, err := plcvec.Verify(manualAnswer{}, opts)
		if err == nil || !strings.Contains(err.Error(), want) {
			t.Errorf("%q: want an error containing %q, got %v", text, want, err)
		}
	}
}

// TestLoadRefusesDamage: a damaged copy is refused by file, line and vector id; a 2.x schema
// is refused rather than misread.
func TestLoadRefusesDamage(t *testing.T) {
	for _, c := range []struct {
		name string
		edit func(lines []string) []string
		want string
	}{
		{"a vector without steps", func(ls []string) []string {
			ls[2] = regexp.MustCompile(`"steps":\[.*\],"tags"`).ReplaceAllString(ls[2], `"steps":[],"tags"`)
			return ls
		}, "fx5-time-add.jsonl:3: vector fx5-time-add/"},
		{"a bit written as 1", func(ls []string) []string {
			ls[1] = regexp.MustCompile(`"SM700":(true|false)`).ReplaceAllString(ls[1], `"SM700":1.5`)
			return ls
		}, "fx5-time-add.jsonl:2: vector fx5-time-add/"},
		{"a key the schema does not have", func(ls []string) []string {
			ls[1] = strings.Replace(ls[1], `{`, `{"surprise":1,`, 1)
			return ls
		}, `fx5-time-add.jsonl:2: vector fx5-time-add/`},
		{"a bit holding 2", func(ls []string) []string {
			// In the first vector's `initial` (which lists SM700 as a bit), SM700 holds 2.
			initial := regexp.MustCompile(`"initial":\{"devices":\{[^}]*\}`)
			ls[1] = initial.ReplaceAllStringFunc(ls[1], func(m string) string {
				return regexp.MustCompile(`"SM700":(true|false)`).ReplaceAllString(m, `"SM700":2`)
			})
			return ls
		}, "a word in `initial`"},
		{"a byte that is not UTF-8", func(ls []string) []string {
			ls[3] = strings.Replace(ls[3], `"description":"`, "\"description\":\"\xff", 1)
			return ls
		}, "fx5-time-add.jsonl:4: byte 0xff at column"},
		// Each line one value, all of it: what the lines hold is read line by line, whatever a
		// decoder reading the file as one stream of values would make of it.
		{"a vector over two lines", func(ls []string) []string {
			ls[2] = "{\n" + ls[2][1:]
			return ls
		}, "fx5-time-add.jsonl:3: the line is not a valid vector (unexpected EOF)"},
		{"a blank line", func(ls []string) []string {
			return append(ls[:2], append([]string{" "}, ls[2:]...)...)
		}, "fx5-time-add.jsonl:3: the line is not a valid vector (EOF)"},
		{"two vectors on a line", func(ls []string) []string {
			ls[1] += " " + ls[2]
			return ls
		}, "not a valid vector (more than one JSON value)"},
		{"schema 2", func(ls []string) []string {
			ls[0] = strings.Replace(ls[0], `"schema_version":"1.`, `"schema_version":"2.`, 1)
			return ls
		}, "schema_version 2."},
	} {
		t.Run(c.name, func(t *testing.T) {
			dir := copyVectors(t, func(name string, data []byte) []byte {
				switch name {
				case "fx5-time-add.jsonl":
					return []byte(strings.Join(c.edit(strings.Split(string(data), "\n")), "\n"))
				case "index.json": // an edited copy fails its hash first: drop the hashes
					return regexp.MustCompile(`"sha256": "[0-9a-f]+"`).ReplaceAll(data, []byte(`"sha256": ""`))
				}
				return data
			})
			_, err := plcvec.Load(dir)
			if err == nil || !strings.Contains(err.Error(), c.want) {
				t.Errorf("want an error containing %q, got %v", c.want, err)
			}
		})
	}
	// Untouched except for one byte, the index's hash names the damaged file.
	dir := copyVectors(t, func(name string, data []byte) []byte {
		if name == "fc6a-hour-meter.jsonl" { // still a valid file, but not the one exported
			return []byte(strings.Replace(string(data), `"description":"`, `"description":"x`, 1))
		}
		return data
	}, "fx5-time-add", "fc6a-hour-meter")
	if _, err := plcvec.Load(dir); err == nil || !strings.Contains(err.Error(), "fc6a-hour-meter.jsonl: its sha256") {
		t.Errorf("a damaged file was not named: %v", err)
	}
}

// TestRepositoryFolder: PLCVEC_VECTORS may name the repository's vectors/ (manifest.json and
// <family>.json); it holds the same vectors as the embedded copy.
func TestRepositoryFolder(t *testing.T) {
	dir := filepath.Join("..", "..", "vectors")
	if _, err := os.Stat(filepath.Join(dir, "manifest.json")); err != nil {
		t.Skip("no repository vectors/ beside this module")
	}
	repo, err := plcvec.Load(dir)
	if err != nil {
		t.Fatal(err)
	}
	emb, err := plcvec.Embedded()
	if err != nil {
		t.Fatal(err)
	}
	if len(repo.Vectors) != len(emb.Vectors) || repo.SpecSHA256 != emb.SpecSHA256 {
		t.Errorf("repository %d vectors (%s), embedded %d (%s)", len(repo.Vectors), repo.SpecSHA256, len(emb.Vectors), emb.SpecSHA256)
	}
	if _, err := plcvec.Load(filepath.Join(dir, "no-such")); err == nil {
		t.Error("a missing folder loaded")
	}
}

// TestRunPatternSelectsID runs this test binary again with -run RunPattern(id): exactly that
// vector's subtest runs, although its id holds a space, '<', '=' and '/'.
func TestRunPatternSelectsID(t *testing.T) {
	id := "cp1e-time-compare/AND <=DT/logic/rlo-off/eq"
	if os.Getenv("PLCVEC_CHILD") == "1" {
		t.Skip("the child run")
	}
	cmd := exec.Command(os.Args[0], "-test.run", plcvec.RunPattern("TestPlcvecReference", id), "-test.v")
	cmd.Env = append(os.Environ(), "PLCVEC_CHILD=1")
	out, err := cmd.CombinedOutput()
	if err != nil {
		t.Fatalf("%v\n%s", err, out)
	}
	ran := regexp.MustCompile(`--- PASS: TestPlcvecReference/(\S+)`).FindAllStringSubmatch(string(out), -1)
	if len(ran) != 1 || ran[0][1] != plcvec.SubtestName(id) || plcvec.SubtestName(id) != "cp1e-time-compare/AND_<=DT/logic/rlo-off/eq" {
		t.Errorf("-run %s ran %v:\n%s", plcvec.RunPattern("TestPlcvecReference", id), ran, out)
	}
}

// TestPlcvecReference is plcvec.Run as an implementer writes it, on the reference.
// With -short (CI's run under the race detector, which makes it slow) it runs one family: the
// reference package's TestReference runs the whole set through Run.
func TestPlcvecReference(t *testing.T) {
	ref, err := reference.New(nil)
	if err != nil {
		t.Fatal(err)
	}
	var opts plcvec.Options
	if testing.Short() {
		opts.Selection.Families = []string{spec.FamilyFx5TimeAdd}
	}
	plcvec.Run(t, ref.Implementation(), opts)
}

// valuesAnswer reports its steps in the fast form, with the wrong number of values.
type valuesAnswer struct{ manualAnswer }

func (v valuesAnswer) Run(req *plcvec.Request) ([]plcvec.StepResult, error) {
	return []plcvec.StepResult{{Values: make([]plcvec.Value, len(req.Devices)+1)}}, nil
}

func TestValuesOfTheWrongLength(t *testing.T) {
	v := judge(t, valuesAnswer{})
	if v.Status != plcvec.StatusFail || !strings.Contains(v.Text(), "step 0 values: expected 14 values, one per device of the request, got 15 values") {
		t.Errorf("got:\n%s", v.Text())
	}
}

// TestEnvVectors: $PLCVEC_VECTORS replaces the embedded copy (checked in a child process, since
// Default loads once per process); a wrong path is an error naming the variable.
func TestEnvVectors(t *testing.T) {
	if want := os.Getenv("PLCVEC_CHILD_WANT"); want != "" {
		suite, err := plcvec.Default()
		got := ""
		if err != nil {
			got = err.Error()
		} else {
			got = suite.Source
		}
		if !strings.Contains(got, want) {
			t.Fatalf("Default(): %q, want %q", got, want)
		}
		return
	}
	repo := filepath.Join("..", "..", "vectors")
	for dir, want := range map[string]string{
		repo:              repo,
		"/no/such/folder": "$PLCVEC_VECTORS: /no/such/folder: no such vector folder",
	} {
		cmd := exec.Command(os.Args[0], "-test.run", "^TestEnvVectors$")
		cmd.Env = append(os.Environ(), "PLCVEC_VECTORS="+dir, "PLCVEC_CHILD_WANT="+want)
		if out, err := cmd.CombinedOutput(); err != nil {
			t.Errorf("PLCVEC_VECTORS=%s: %v\n%s", dir, err, out)
		}
	}
}

// TestEnvShard: PLCVEC_SHARD=K/N runs that shard only; a bad value fails naming the variable.
func TestEnvShard(t *testing.T) {
	ref, err := reference.New(nil)
	if err != nil {
		t.Fatal(err)
	}
	t.Setenv("PLCVEC_SHARD", "2/5")
	sel := plcvec.Selection{Families: []string{spec.FamilyFx5TimeAdd}}
	report := plcvec.Run(t, ref.Implementation(), plcvec.Options{Selection: sel})
	all, _ := plcvec.Verify(ref.Implementation(), plcvec.Options{Selection: sel})
	want := 0
	for _, v := range all.Verdicts {
		if plcvec.ShardOf(v.ID, 5) == 2 {
			want++
		}
	}
	if len(report.Verdicts) != want || want == 0 || want == len(all.Verdicts) {
		t.Errorf("shard 2/5 ran %d vectors, want %d of %d", len(report.Verdicts), want, len(all.Verdicts))
	}
}

// TestWriteExpectations: the failures of a run become an expectations file that makes the same
// run pass (every entry an xfail), and that the loader reads back.
func TestWriteExpectations(t *testing.T) {
	path := filepath.Join(t.TempDir(), "known.toml")
	wrong := manualAnswer{change: set("D31", plcvec.Word(41))}
	opts := plcvec.Options{Selection: plcvec.Selection{IDs: []string{manualTADD}}}
	report, err := plcvec.Verify(wrong, opts)
	if err != nil {
		t.Fatal(err)
	}
	n, err := report.WriteExpectations(path, "D31 off by one (\"minute\")\tc:\\x")
	if err != nil || n != 1 {
		t.Fatalf("%d entries, %v", n, err)
	}
	opts.Expectations = path
	report, err = plcvec.Verify(wrong, opts)
	if err != nil {
		t.Fatal(err)
	}
	if len(report.Failed()) != 0 || report.Verdicts[0].Status != plcvec.StatusXFail || !strings.Contains(report.Verdicts[0].Message, "D31 off by one (\"minute\")\tc:\\x") {
		t.Errorf("the written file does not make the run pass: %+v", report.Verdicts)
	}
	if _, err := report.WriteExpectations(filepath.Join(t.TempDir(), "no", "such", "dir", "k.toml"), "r"); err == nil {
		t.Error("writing into a missing folder succeeded")
	}
}

// TestInProcess: Options.InProcess judges in the test's own process, with the same verdicts.
func TestInProcess(t *testing.T) {
	ref, err := reference.New(nil)
	if err != nil {
		t.Fatal(err)
	}
	report := plcvec.Run(t, ref.Implementation(), plcvec.Options{InProcess: true,
		Selection: plcvec.Selection{Families: []string{spec.FamilyFx5TimeAdd}}})
	if c := report.Counts(); c[plcvec.StatusPass] != len(report.Verdicts) || len(report.Verdicts) == 0 {
		t.Errorf("%v", c)
	}
}

// looping never answers on the manual's TADD example; in mode "exits" it ends the process there,
// in mode "wrong" it answers D30 = 99 there.
type looping struct {
	plcvec.Implementation
	mode string
}

func (l looping) Run(req *plcvec.Request) ([]plcvec.StepResult, error) {
	if req.ID == manualTADD {
		switch l.mode {
		case "exits":
			os.Exit(3)
		case "wrong":
			return manualAnswer{set("D30", plcvec.Word(99))}.Run(req)
		}
		//lint:ignore SA5002 the implementation under test never returns: the bound must end it
		for {
		}
	}
	return l.Implementation.Run(req)
}

// TestTimeout: a vector that never answers is reported against its id within PLCVEC_TIMEOUT,
// and the run ends, in a second process (the default) and in this one (Options.InProcess); a
// vector that ends the process is reported against its id too. Every vector before it passed,
// and says so, although the second process writes no line for a vector that passes; a vector
// that fails among passing ones fails alone. Run in a child test binary, since the in-process
// watchdog ends its process.
func TestTimeout(t *testing.T) {
	selection := plcvec.Selection{Families: []string{spec.FamilyFx5TimeAdd}}
	if mode := os.Getenv("PLCVEC_TEST_LOOP"); mode != "" {
		ref, err := reference.New(nil)
		if err != nil {
			t.Fatal(err)
		}
		plcvec.Run(t, looping{ref.Implementation(), mode}, plcvec.Options{InProcess: mode == "in-process",
			Selection: selection})
		return
	}
	ref, err := reference.New(nil)
	if err != nil {
		t.Fatal(err)
	}
	plan, err := plcvec.Prepare(ref.Implementation(), plcvec.Options{Selection: selection})
	if err != nil {
		t.Fatal(err)
	}
	before := -1
	for i, c := range plan.Cases {
		if c.Vector.ID == manualTADD {
			before = i
		}
	}
	if before < 1 {
		t.Fatalf("%s is not after another vector of its family (at %d): the test would show nothing", manualTADD, before)
	}
	for _, mode := range []string{"isolated", "in-process", "exits", "wrong"} {
		t.Run(mode, func(t *testing.T) {
			cmd := exec.Command(os.Args[0], "-test.run", "^TestTimeout$", "-test.v")
			cmd.Env = append(os.Environ(), "PLCVEC_TEST_LOOP="+mode, "PLCVEC_TIMEOUT=0.5")
			start := time.Now()
			out, err := cmd.CombinedOutput()
			if err == nil {
				t.Fatalf("a vector that never answers passed:\n%s", out)
			}
			said, wantPassed := "no answer within 0.5 s (PLCVEC_TIMEOUT)", before
			switch mode {
			case "exits":
				said = "the implementation ended the test process with exit status 3"
			case "wrong":
				// A vector that does not pass has a line of its own, between passing vectors that have none.
				said, wantPassed = "--- FAIL: TestTimeout/"+plcvec.SubtestName(manualTADD), len(plan.Cases)-1
			}
			if !strings.Contains(string(out), manualTADD) || !strings.Contains(string(out), said) {
				t.Errorf("the vector is not named with %q:\n%s", said, out)
			}
			// (In process, the watchdog ends the process before go test prints its subtests' results.)
			if passed := strings.Count(string(out), "--- PASS: TestTimeout/"); mode != "in-process" && passed != wantPassed {
				t.Errorf("%d vectors passed beside %s, not %d:\n%s", passed, manualTADD, wantPassed, out)
			}
			if d := time.Since(start); d > 60*time.Second {
				t.Errorf("took %s", d)
			}
		})
	}
}

// TestSettingWarningsOncePerRun: a misspelt PLCVEC_* variable earns its warning once per run on
// stderr, through Run (its second process, whose last output a failure shows, does not repeat
// it) and through Verify alike. Run in a child test binary, whose stderr is read.
func TestSettingWarningsOncePerRun(t *testing.T) {
	selection := plcvec.Selection{Families: []string{spec.FamilyFx5TimeAdd}}
	if os.Getenv("PLCVEC_TEST_WARN") != "" {
		ref, err := reference.New(nil)
		if err != nil {
			t.Fatal(err)
		}
		if _, err := plcvec.Verify(ref.Implementation(), plcvec.Options{Selection: selection}); err != nil {
			t.Fatal(err)
		}
		// The second process ends the process on the manual's example: its output is shown.
		plcvec.Run(t, looping{ref.Implementation(), "exits"}, plcvec.Options{Selection: selection})
		return
	}
	cmd := exec.Command(os.Args[0], "-test.run", "^TestSettingWarningsOncePerRun$", "-test.v")
	cmd.Env = append(os.Environ(), "PLCVEC_TEST_WARN=1", "PLCVEC_TAGG=boundary")
	out, _ := cmd.CombinedOutput()
	line := "plcvec: warning: PLCVEC_TAGG is not a plcvec setting; did you mean PLCVEC_TAG?\n"
	if n := strings.Count(string(out), line); n != 2 || !strings.Contains(string(out), "ended the test process with exit status 3") {
		t.Errorf("the warning %d times in two runs, not twice (Verify's and Run's, none from Run's second process):\n%s", n, out)
	}
}
