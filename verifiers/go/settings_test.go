package plcvec

import (
	"strings"
	"testing"
)

// TestSettingWarnings: the lines of CONTRACT.md, "Old names and misspellings", for an old name
// alone or beside its setting, a misspelling near a setting, and a name near none; nothing for a
// setting or a name plcvec's own tools use; in variable order.
func TestSettingWarnings(t *testing.T) {
	all := "the settings are PLCVEC_VECTORS, PLCVEC_ID, PLCVEC_FAMILY, PLCVEC_INSTRUCTION, PLCVEC_TAG, " +
		"PLCVEC_INTERPRETATION, PLCVEC_SHARD, PLCVEC_KNOWN_FAILURES, PLCVEC_WRITE_EXPECTATIONS, PLCVEC_TIMEOUT"
	for _, c := range []struct {
		environ []string
		want    []string
	}{
		{[]string{"PLCVEC_EXPECTATIONS=k.toml"}, []string{"warning: PLCVEC_EXPECTATIONS is the old name of PLCVEC_KNOWN_FAILURES, read as it until plcvec 0.3.0; set PLCVEC_KNOWN_FAILURES instead"}},
		{[]string{"PLCVEC_KNOWN_FAILURES=a", "PLCVEC_EXPECTATIONS=b"}, []string{"warning: PLCVEC_EXPECTATIONS is ignored: it is the old name of PLCVEC_KNOWN_FAILURES, which is set too"}},
		{[]string{"PLCVEC_TAGG=boundary"}, []string{"warning: PLCVEC_TAGG is not a plcvec setting; did you mean PLCVEC_TAG?"}},
		{[]string{"PLCVEC_COLOUR=red"}, []string{"warning: PLCVEC_COLOUR is not a plcvec setting; " + all}},
		// An old name counts as the setting it was renamed to.
		{[]string{"PLCVEC_EXPECTATION=x"}, []string{"warning: PLCVEC_EXPECTATION is not a plcvec setting; did you mean PLCVEC_KNOWN_FAILURES?"}},
		// Lower case is compared in upper case; the first by name among equals (ID before TAG at 2).
		{[]string{"PLCVEC_tag=x"}, []string{"warning: PLCVEC_tag is not a plcvec setting; did you mean PLCVEC_TAG?"}},
		{[]string{"PLCVEC_IG=x"}, []string{"warning: PLCVEC_IG is not a plcvec setting; did you mean PLCVEC_ID?"}},
		{[]string{"PLCVEC_TAG=x", "PLCVEC_HOSTILE=panic", "PLCVEC_TEST_LOOP=1", "PLCVEC_GO_CHILD=x", "HOME=/"}, nil},
		{[]string{"PLCVEC_ZZZ=1", "PLCVEC_FAMILLY=x"}, []string{
			"warning: PLCVEC_FAMILLY is not a plcvec setting; did you mean PLCVEC_FAMILY?",
			"warning: PLCVEC_ZZZ is not a plcvec setting; did you mean PLCVEC_ID?"}},
	} {
		got := settingWarnings(c.environ)
		if strings.Join(got, "\n") != strings.Join(c.want, "\n") {
			t.Errorf("%v:\n got %q\nwant %q", c.environ, got, c.want)
		}
	}
}

// TestTimeoutRule: CONTRACT.md's one rule for PLCVEC_TIMEOUT, and its one message.
func TestTimeoutRule(t *testing.T) {
	for text, seconds := range map[string]float64{"10": 10, "2.5": 2.5, "0.5": 0.5, "86400": 86400, "007": 7} {
		if d, err := parseTimeout(text, true); err != nil || d.Seconds() != seconds {
			t.Errorf("PLCVEC_TIMEOUT=%s: %v, %v; want %g s", text, d, err, seconds)
		}
	}
	for _, text := range []string{"1e9", "1e12", "86401", "86400.5", "0", "0.0", "-1", "+2", "2.", ".5", " 2", "inf", "NaN", "", "1_0"} {
		_, err := parseTimeout(text, true)
		want := "PLCVEC_TIMEOUT=" + text + ": the bound must be a number of seconds above 0 and at most 86400, " +
			"written as digits with an optional fraction (2, 0.5)"
		if err == nil || err.Error() != want {
			t.Errorf("PLCVEC_TIMEOUT=%q: %v; want %q", text, err, want)
		}
	}
	if d, err := parseTimeout("", false); err != nil || d != DefaultTimeout {
		t.Errorf("unset: %v, %v", d, err)
	}
}
