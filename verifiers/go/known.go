package plcvec

import (
	"errors"
	"fmt"
	"os"
	"path/filepath"
	"sort"
	"strings"

	"github.com/BurntSushi/toml"
)

// KnownFailures is an expectations file: the vectors an implementation is known to fail, each
// with a reason (CONTRACT.md, "The expectations file"), the same file `plcvec verify
// --expectations` reads:
//
//	[[known-failure]]
//	id = "fx5-date-compare/LDDT</nonexistent/2024-2-30/s1/vs-previous"
//	reason = "our calendar check rejects 2008/02/31"
//
// A listed vector that fails is xfail and does not fail the run; a listed vector that passes
// is stale and fails the run, and so does an id the suite does not have: the list can only
// shrink. Ids are exact, never patterns: a pattern would hide tomorrow's new failures.
type KnownFailures struct {
	Path    string
	Entries map[string]KnownFailure
}

// KnownFailure is one entry, with the line it starts on.
type KnownFailure struct {
	ID     string
	Reason string
	Line   int
}

const knownSection = "known-failure"

// LoadKnownFailures reads an expectations file; every mistake is named by file and line.
func LoadKnownFailures(path string) (*KnownFailures, error) {
	// A named pipe nobody writes would hold the run before it starts.
	if why := notRegularPath(path); why != "" {
		return nil, fmt.Errorf("%s: %s", path, why)
	}
	raw, err := os.ReadFile(path)
	if err != nil {
		return nil, fmt.Errorf("%s: cannot read the expectations file: %v", path, errors.Unwrap(err))
	}
	text := string(raw)
	var data struct {
		Known []map[string]any `toml:"known-failure"`
	}
	md, err := toml.Decode(text, &data)
	if err != nil {
		var perr toml.ParseError
		if errors.As(err, &perr) {
			return nil, fmt.Errorf("%s:%d: not valid TOML: %s", path, perr.Position.Line, perr.Message)
		}
		return nil, fmt.Errorf("%s: not valid TOML for an expectations file: %v (it holds only [[%s]] entries)", path, err, knownSection)
	}
	for _, key := range md.Keys() {
		if key[0] != knownSection {
			return nil, fmt.Errorf("%s:%d: unknown key %q; an expectations file holds only [[%s]] entries",
				path, lineOf(text, key[0]), key[0], knownSection)
		}
	}
	headers := []int{}
	for i, line := range strings.Split(text, "\n") {
		if strings.HasPrefix(strings.TrimSpace(line), "[["+knownSection+"]]") {
			headers = append(headers, i+1)
		}
	}
	k := &KnownFailures{Path: path, Entries: map[string]KnownFailure{}}
	for n, entry := range data.Known {
		line := 0
		if n < len(headers) {
			line = headers[n]
		}
		keys := make([]string, 0, len(entry))
		for key := range entry {
			keys = append(keys, key)
		}
		sort.Strings(keys)
		for _, key := range keys {
			if key != "id" && key != "reason" {
				return nil, fmt.Errorf("%s:%d: unknown key %q (an entry has `id` and `reason`)", path, line, key)
			}
		}
		id, _ := entry["id"].(string)
		reason, _ := entry["reason"].(string)
		if id == "" {
			return nil, fmt.Errorf("%s:%d: entry without an `id` (a string)", path, line)
		}
		if strings.TrimSpace(reason) == "" {
			return nil, fmt.Errorf("%s:%d: %s: every known failure needs a `reason` (a string)", path, line, id)
		}
		if first, dup := k.Entries[id]; dup {
			return nil, fmt.Errorf("%s:%d: %s is listed twice (first at line %d)", path, line, id, first.Line)
		}
		k.Entries[id] = KnownFailure{ID: id, Reason: strings.TrimSpace(reason), Line: line}
	}
	return k, nil
}

func lineOf(text, key string) int {
	for i, line := range strings.Split(text, "\n") {
		t := strings.TrimSpace(line)
		if strings.HasPrefix(t, key) || strings.HasPrefix(t, "["+key) || strings.HasPrefix(t, "[["+key) {
			return i + 1
		}
	}
	return 1
}

// apply turns a listed failure into xfail and a listed pass into stale.
func (k *KnownFailures) apply(v *Verdict) {
	entry, ok := k.Entries[v.ID]
	if !ok {
		return
	}
	where := fmt.Sprintf("%s:%d", k.Path, entry.Line)
	switch v.Status {
	case StatusFail, StatusError:
		v.Status = StatusXFail
		v.Message = strings.TrimSuffix(fmt.Sprintf("known failure (%s): %s; %s", where, entry.Reason, v.Message), "; ")
	case StatusPass:
		v.Status = StatusStale
		v.Message = fmt.Sprintf("listed as a known failure (%s: %s) but it passes; remove it from the expectations file", where, entry.Reason)
	}
}

// unknownIDs are stale verdicts for listed ids the suite does not have.
func (k *KnownFailures) unknownIDs(s *Suite) []Verdict {
	var out []Verdict
	ids := make([]string, 0, len(k.Entries))
	for id := range k.Entries {
		ids = append(ids, id)
	}
	sort.Strings(ids)
	for _, id := range ids {
		if s.Vector(id) != nil {
			continue
		}
		why := "; remove it from the expectations file"
		if now, ok := s.merged[id]; ok {
			why = ": it was merged into " + now + "; list that id instead"
		}
		out = append(out, Verdict{ID: id, Status: StatusStale, Message: fmt.Sprintf(
			"listed as a known failure (%s:%d) but the suite has no such vector%s", k.Path, k.Entries[id].Line, why)})
	}
	return out
}

// WriteExpectations writes the vectors that fail in r as a new expectations file, each with the
// given reason: the starting list for an implementation adopting the suite (the same file
// `plcvec verify --write-expectations` writes). The file is replaced atomically: a reader never
// sees half of it. It returns the number of entries.
func (r *Report) WriteExpectations(path, reason string) (int, error) {
	// Line for line what `plcvec verify --write-expectations` writes.
	lines := []string{"# Known failures: each passing entry fails the run as stale, so fix and delete.", ""}
	ids := []string{}
	for _, v := range r.Verdicts {
		if v.Vector != nil && (v.Status == StatusFail || v.Status == StatusError || v.Status == StatusXFail) {
			ids = append(ids, v.ID)
		}
	}
	sort.Strings(ids)
	for _, id := range ids {
		lines = append(lines, "[["+knownSection+"]]", "id = "+tomlString(id), "reason = "+tomlString(reason), "")
	}
	return len(ids), writeAtomic(path, []byte(strings.Join(lines, "\n")))
}

// tomlString quotes s as a TOML basic string: `\` and `"` escaped, control characters as \uXXXX
// (Go's own quoting writes \x and \a, which TOML does not read).
func tomlString(s string) string {
	var b strings.Builder
	b.WriteByte('"')
	for _, r := range s {
		switch {
		case r == '\\' || r == '"':
			b.WriteByte('\\')
			b.WriteRune(r)
		case r < 0x20 || r == 0x7f:
			fmt.Fprintf(&b, "\\u%04X", r)
		default:
			b.WriteRune(r)
		}
	}
	b.WriteByte('"')
	return b.String()
}

// writeAtomic replaces path with data through a temporary file in the same folder.
func writeAtomic(path string, data []byte) error {
	if why := notRegularPath(path); why != "" {
		return fmt.Errorf("%s: %s", path, why)
	}
	tmp, err := os.CreateTemp(filepath.Dir(path), "."+filepath.Base(path)+".*")
	if err != nil {
		return fmt.Errorf("%s: %v", path, err)
	}
	defer os.Remove(tmp.Name())
	if _, err := tmp.Write(data); err != nil {
		tmp.Close()
		return fmt.Errorf("%s: %v", path, err)
	}
	if err := tmp.Chmod(0o644); err != nil {
		tmp.Close()
		return fmt.Errorf("%s: %v", path, err)
	}
	if err := tmp.Close(); err != nil {
		return fmt.Errorf("%s: %v", path, err)
	}
	if err := os.Rename(tmp.Name(), path); err != nil {
		return fmt.Errorf("%s: %v", path, err)
	}
	return nil
}
