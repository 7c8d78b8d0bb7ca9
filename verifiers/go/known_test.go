package plcvec_test

import (
	"os"
	"path/filepath"
	"strings"
	"syscall"
	"testing"

	"github.com/plcvec/plcvec/verifiers/go"
)

func writeKnown(t *testing.T, text string) string {
	t.Helper()
	path := filepath.Join(t.TempDir(), "known.toml")
	if err := os.WriteFile(path, []byte(text), 0o644); err != nil {
		t.Fatal(err)
	}
	return path
}

// TestKnownFailuresAloneProveNothing: a run whose every vector is a known failure of an
// implementation that fails it passes nothing, and is not green (CONTRACT.md, "Exit status").
func TestKnownFailuresAloneProveNothing(t *testing.T) {
	path := writeKnown(t, "[[known-failure]]\nid = \""+manualTADD+"\"\nreason = \"our D31 is off by one\"\n")
	report, err := plcvec.Verify(manualAnswer{change: set("D31", plcvec.Word(41))}, plcvec.Options{
		Selection: plcvec.Selection{IDs: []string{manualTADD}}, Expectations: path})
	if err != nil {
		t.Fatal(err)
	}
	if report.OK() || report.Verdicts[0].Status != plcvec.StatusXFail {
		t.Errorf("a run of one known failure is green: %v", report.Counts())
	}
	if text := report.Summary(); !strings.Contains(text, "NOT PASSED: nothing passed (1 known failures): the run proves nothing\n") {
		t.Errorf("the text does not say nothing passed:\n%s", text)
	}
}

// TestKnownFailureMerged: a listed id that the suite merged into another vector is stale, and
// its message names the vector it became; an id the suite never had is told to be removed.
func TestKnownFailureMerged(t *testing.T) {
	const old, now = "cp1e-time-compare/AND <=DT/ordering/eq", "cp1e-time-compare/AND <=DT/logic/rlo-on/eq"
	path := writeKnown(t, "[[known-failure]]\nid = \""+old+"\"\nreason = \"listed before the merge\"\n\n"+
		"[[known-failure]]\nid = \"no/such/vector\"\nreason = \"gone\"\n")
	report, err := plcvec.Verify(manualAnswer{}, plcvec.Options{
		Selection: plcvec.Selection{IDs: []string{manualTADD}}, Expectations: path})
	if err != nil {
		t.Fatal(err)
	}
	want := map[string]string{
		old:              "listed as a known failure (" + path + ":1) but the suite has no such vector: it was merged into " + now + "; list that id instead",
		"no/such/vector": "listed as a known failure (" + path + ":5) but the suite has no such vector; remove it from the expectations file",
	}
	for _, v := range report.Verdicts[1:] {
		if v.Status != plcvec.StatusStale || v.Message != want[v.ID] {
			t.Errorf("%s: %s %q; want stale %q", v.ID, v.Status, v.Message, want[v.ID])
		}
	}
	if len(report.Verdicts) != 3 || report.OK() {
		t.Errorf("%d verdicts, OK %v", len(report.Verdicts), report.OK())
	}
}

// TestKnownFailuresFileNotRegular: a known-failures file that is a named pipe is refused by name
// (reading it would wait for a writer for ever); so is a folder given to WriteExpectations.
func TestKnownFailuresFileNotRegular(t *testing.T) {
	pipe := filepath.Join(t.TempDir(), "known.toml")
	if err := syscall.Mkfifo(pipe, 0o644); err != nil {
		t.Skipf("no named pipes here: %v", err)
	}
	if _, err := plcvec.LoadKnownFailures(pipe); err == nil || err.Error() != pipe+": not a regular file (a named pipe)" {
		t.Errorf("got %v", err)
	}
	report, err := plcvec.Verify(manualAnswer{}, plcvec.Options{Selection: plcvec.Selection{IDs: []string{manualTADD}}})
	if err != nil {
		t.Fatal(err)
	}
	folder := t.TempDir()
	if _, err := report.WriteExpectations(folder, "r"); err == nil || err.Error() != folder+": not a regular file (a folder)" {
		t.Errorf("writing over a folder: %v", err)
	}
}
