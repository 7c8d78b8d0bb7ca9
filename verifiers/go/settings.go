package plcvec

import (
	"fmt"
	"io"
	"os"
	"regexp"
	"sort"
	"strconv"
	"strings"
	"time"
)

// The PLCVEC_* variables of a run (CONTRACT.md, "The environment"): `plcvec verify` takes them as
// the defaults of its flags, and Run reads them so that a CI job changes what a gate runs without
// changing the test. Their names, old names and the names plcvec's own tools use come from the
// one table of them (settings_gen.go, generated from verifiers/python/plcvec_verify/settings.py).

// DefaultTimeout bounds one vector when $PLCVEC_TIMEOUT does not: an implementation that never
// answers is reported against that vector, and the run ends there rather than hang.
const DefaultTimeout = timeoutDefaultSeconds * time.Second

// CONTRACT.md's one rule for PLCVEC_TIMEOUT: digits with an optional fraction (no sign, no
// exponent), above 0 and at most a day (timeoutMaxSeconds, generated), so that a value one runner
// takes no runner refuses and none overflows a clock.

var timeoutPattern = regexp.MustCompile(`^[0-9]+(\.[0-9]+)?$`)

// environment is what the PLCVEC_* variables ask of a run.
type environment struct {
	narrow   Selection // narrows the selection the code gives (both must take a vector)
	narrowed bool
	known    string
	write    string
	timeout  time.Duration
}

// readEnvironment reads the PLCVEC_* variables. A malformed value is an error naming its
// variable; an empty item of a list (PLCVEC_FAMILY=,) is an error too, never "no filter".
func readEnvironment() (environment, error) {
	known, _ := lookupSetting(EnvKnownFailures)
	env := environment{known: known, write: os.Getenv(EnvWriteExpectations)}
	lists := []struct {
		name string
		into *[]string
	}{{EnvID, &env.narrow.IDs}, {EnvFamily, &env.narrow.Families}, {EnvInstruction, &env.narrow.Instructions},
		{EnvTag, &env.narrow.Tags}, {EnvInterpretation, &env.narrow.Interpretations}}
	for _, l := range lists {
		text, ok := os.LookupEnv(l.name)
		if !ok || text == "" {
			continue
		}
		items := strings.Split(text, ",")
		for i := range items {
			items[i] = strings.TrimSpace(items[i])
			if items[i] == "" {
				return env, fmt.Errorf("%s=%q: an empty name in the list (names are separated by commas)", l.name, text)
			}
		}
		*l.into, env.narrowed = items, true
	}
	if text := os.Getenv(EnvShard); text != "" {
		shard, err := ParseShard(text)
		if err != nil {
			return env, fmt.Errorf("%s=%q: %v", EnvShard, text, err)
		}
		env.narrow.Shard, env.narrowed = shard, true
	}
	var err error
	text, set := os.LookupEnv(EnvTimeout)
	env.timeout, err = parseTimeout(text, set)
	return env, err
}

// lookupSetting is the value of a setting: its variable, else, while the old name is still read,
// the variable it was renamed from (when only that one is set).
func lookupSetting(name string) (string, bool) {
	if text, ok := os.LookupEnv(name); ok {
		return text, true
	}
	for _, d := range deprecatedSettings {
		if d.replacement == name {
			if text, ok := os.LookupEnv(d.name); ok {
				return text, true
			}
		}
	}
	return "", false
}

// parseTimeout reads $PLCVEC_TIMEOUT (CONTRACT.md's one rule); unset is the default.
func parseTimeout(text string, set bool) (time.Duration, error) {
	if !set {
		return DefaultTimeout, nil
	}
	s, err := strconv.ParseFloat(text, 64)
	if !timeoutPattern.MatchString(text) || err != nil || !(s > 0) || s > timeoutMaxSeconds {
		return 0, fmt.Errorf("%s=%s: the bound must be a number of seconds above 0 and at most %d, "+
			"written as digits with an optional fraction (2, 0.5)", EnvTimeout, text, timeoutMaxSeconds)
	}
	return time.Duration(s * float64(time.Second)), nil
}

// warnSettings writes the warnings the environment earns to w, once per run: Prepare calls it,
// except in the second process of a Run (isolate.go), whose parent has warned already.
func warnSettings(w io.Writer) {
	if _, inChild := os.LookupEnv(envChild); inChild {
		return
	}
	for _, line := range settingWarnings(os.Environ()) {
		fmt.Fprintln(w, "plcvec: "+line)
	}
}

// settingWarnings are the warnings of CONTRACT.md, "Old names and misspellings", for the
// variables of environ (NAME=value entries), in variable order: an old name read as the setting it
// was renamed to, or ignored when that one is set too; a PLCVEC_* variable that is neither a
// setting, an old name nor a name plcvec's own tools use, named with the nearest setting.
func settingWarnings(environ []string) []string {
	set := map[string]bool{}
	var names []string
	for _, kv := range environ {
		name, _, _ := strings.Cut(kv, "=")
		if strings.HasPrefix(name, "PLCVEC_") && !set[name] {
			set[name] = true
			names = append(names, name)
		}
	}
	sort.Strings(names)
	var out []string
	for _, name := range names {
		if line := settingWarning(name, set); line != "" {
			out = append(out, line)
		}
	}
	return out
}

// settingWarning is the warning variable name earns, or "" (set: every PLCVEC_* variable set).
func settingWarning(name string, set map[string]bool) string {
	if isSetting(name) || isReserved(name) {
		return ""
	}
	for _, d := range deprecatedSettings {
		if d.name != name {
			continue
		}
		if set[d.replacement] {
			return fmt.Sprintf("warning: %s is ignored: it is the old name of %s, which is set too", name, d.replacement)
		}
		return fmt.Sprintf("warning: %s is the old name of %s, read as it until plcvec %s; set %s instead",
			name, d.replacement, d.until, d.replacement)
	}
	if guess := nearestSetting(name); guess != "" {
		return fmt.Sprintf("warning: %s is not a plcvec setting; did you mean %s?", name, guess)
	}
	all := make([]string, len(settings))
	for i, s := range settings {
		all[i] = s.name
	}
	return fmt.Sprintf("warning: %s is not a plcvec setting; the settings are %s", name, strings.Join(all, ", "))
}

func isSetting(name string) bool {
	for _, s := range settings {
		if s.name == name {
			return true
		}
	}
	return false
}

func isReserved(name string) bool {
	for _, r := range reservedSettings {
		if r == name {
			return true
		}
	}
	for _, p := range reservedSettingPrefixes {
		if strings.HasPrefix(name, p) {
			return true
		}
	}
	return false
}

// nearestSetting is the setting name is most likely a misspelling of: the first by name among
// the settings and old names at the smallest edit distance, if that is at most nearestDistance,
// an old name counting as the setting it was renamed to; "" when none is that near.
func nearestSetting(name string) string {
	candidates := make([]string, 0, len(settings)+len(deprecatedSettings))
	for _, s := range settings {
		candidates = append(candidates, s.name)
	}
	for _, d := range deprecatedSettings {
		candidates = append(candidates, d.name)
	}
	sort.Strings(candidates)
	upper := strings.ToUpper(name)
	best, distance := "", nearestDistance+1
	for _, c := range candidates {
		if d := editDistance(upper, c); d < distance {
			best, distance = c, d
		}
	}
	for _, d := range deprecatedSettings {
		if d.name == best {
			return d.replacement
		}
	}
	return best
}

// editDistance is the Levenshtein distance of a and b (insert, delete, replace: each 1), by byte:
// the names are ASCII.
func editDistance(a, b string) int {
	previous := make([]int, len(b)+1)
	for j := range previous {
		previous[j] = j
	}
	for i := 1; i <= len(a); i++ {
		current := make([]int, len(b)+1)
		current[0] = i
		for j := 1; j <= len(b); j++ {
			cost := 1
			if a[i-1] == b[j-1] {
				cost = 0
			}
			current[j] = min(previous[j]+1, current[j-1]+1, previous[j-1]+cost)
		}
		previous = current
	}
	return previous[len(b)]
}
