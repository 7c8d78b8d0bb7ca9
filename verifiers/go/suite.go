package plcvec

import (
	"bytes"
	"crypto/sha256"
	"encoding/hex"
	"encoding/json"
	"errors"
	"fmt"
	"io/fs"
	"os"
	"path"
	"path/filepath"
	"sort"
	"strconv"
	"strings"
	"sync"
	"syscall"
	"unicode/utf8"
)

// SchemaMajor is the major schema version this verifier reads (CONTRACT.md, "Versioning"): a 2.x
// file may mean something else by the same fields, so it is refused rather than misread.
const SchemaMajor = 1

// Suite is a loaded vector set: every family's header and vectors.
type Suite struct {
	Source        string // where it was read from ("embedded" or a path)
	SuiteVersion  string
	SchemaVersion string
	SpecSHA256    string
	Families      []string                 // in file order
	Headers       map[string]*FamilyHeader // family -> header
	Vectors       []*Vector                // family by family, each family sorted by id
	byID          map[string]*Vector
	merged        map[string]string // an id merged into another vector -> the id it is now
}

// Vector returns the vector with this id, or nil.
func (s *Suite) Vector(id string) *Vector { return s.byID[id] }

var (
	defaultOnce  sync.Once
	defaultSuite *Suite
	defaultErr   error
)

// Default is the suite a run uses unless told otherwise: the copy named by $PLCVEC_VECTORS if
// it is set, else the copy embedded in this package. It is loaded once per process.
func Default() (*Suite, error) {
	defaultOnce.Do(func() {
		if dir := os.Getenv(EnvVectors); dir != "" {
			defaultSuite, defaultErr = Load(dir)
			if defaultErr != nil {
				defaultErr = fmt.Errorf("$%s: %w", EnvVectors, defaultErr)
			}
			return
		}
		defaultSuite, defaultErr = Embedded()
	})
	return defaultSuite, defaultErr
}

// Embedded loads the copy of the vectors compiled into this package.
func Embedded() (*Suite, error) {
	sub, err := fs.Sub(embedded, "vectors")
	if err != nil {
		return nil, err
	}
	return loadFS(sub, "embedded vectors", "(embedded)/")
}

// Load reads a vector set from a folder: the exported compact copy (index.json and one
// <family>.jsonl each) or the repository's vectors/ folder (manifest.json and one <family>.json
// each).
func Load(dir string) (*Suite, error) {
	info, err := os.Stat(dir)
	if errors.Is(err, syscall.ELOOP) {
		return nil, fmt.Errorf("%s: a loop of symbolic links", dir)
	}
	if err != nil {
		return nil, fmt.Errorf("%s: no such vector folder", dir)
	}
	if !info.IsDir() {
		return nil, fmt.Errorf("%s: not a folder (give the folder holding index.json or manifest.json)", dir)
	}
	return loadFS(os.DirFS(dir), dir, strings.TrimSuffix(dir, string(filepath.Separator))+string(filepath.Separator))
}

// listing is what index.json (exported copy) and manifest.json (repository) have in common.
type listing struct {
	SuiteVersion     string                  `json:"suite_version"`
	GeneratorVersion string                  `json:"generator_version"`
	SchemaVersion    string                  `json:"schema_version"`
	SpecSHA256       string                  `json:"spec_sha256"`
	Total            *int                    `json:"total"`
	Families         map[string]listingEntry `json:"families"`
	// Merged: {family: {an id the generator merged into another vector: the id it went to}}.
	Merged map[string]map[string]string `json:"merged"`
}

// listingEntry is one family of an index.
type listingEntry struct {
	File   string `json:"file"`
	Count  *int   `json:"count"`
	SHA256 string `json:"sha256"`
}

func loadFS(fsys fs.FS, source, prefix string) (*Suite, error) {
	name, raw, err := readIndex(fsys, source, prefix)
	if err != nil {
		return nil, err
	}
	var list listing
	if err := json.Unmarshal(raw, &list); err != nil {
		return nil, fmt.Errorf("%s%s:%d: not valid JSON (%v)", prefix, name, jsonErrorLine(raw, err), err)
	}
	var keys keyScanner
	if err := keys.repeatedKeyError(raw, prefix+name, 1, nil); err != nil {
		return nil, err
	}
	if len(list.Families) == 0 {
		return nil, fmt.Errorf("%s%s: no `families`; is this a plcvec vector folder?", prefix, name)
	}
	s := &Suite{Source: source, SuiteVersion: list.SuiteVersion, SpecSHA256: list.SpecSHA256,
		Headers: map[string]*FamilyHeader{}, byID: map[string]*Vector{}, merged: mergedIDs(list.Merged)}
	if s.SuiteVersion == "" {
		s.SuiteVersion = list.GeneratorVersion
	}
	// The family files are read and parsed side by side (parsing is most of a load, and every run
	// loads the set), then added in the index's order, so that an error is the same every time.
	families := sortedKeysOf(list.Families)
	loaded := make([]familyFile, len(families))
	var wg sync.WaitGroup
	for i, family := range families {
		wg.Add(1)
		go func() {
			defer wg.Done()
			loaded[i] = readFamily(fsys, prefix, name, family, list.Families[family])
		}()
	}
	wg.Wait()
	versions := map[string]bool{}
	for i, f := range loaded {
		if f.err != nil {
			return nil, f.err
		}
		if err := s.add(families[i], f); err != nil {
			return nil, err
		}
		versions[f.header.SchemaVersion] = true
	}
	if list.Total != nil && *list.Total != len(s.Vectors) {
		return nil, fmt.Errorf("%s%s: total %d, but the files hold %d vectors", prefix, name, *list.Total, len(s.Vectors))
	}
	s.SchemaVersion = strings.Join(sortedKeysOf(versions), ", ")
	if s.SchemaVersion == "" {
		s.SchemaVersion = list.SchemaVersion
	}
	if _, err := s.interpretations(); err != nil {
		return nil, err
	}
	return s, nil
}

// familyFile is one family file as read and checked against its index, or what is wrong with it.
type familyFile struct {
	header  *FamilyHeader
	vectors []*Vector
	where   string
	err     error
}

// readFamily reads one family file the index (name) lists and checks it against the index.
func readFamily(fsys fs.FS, prefix, name, family string, entry listingEntry) familyFile {
	fail := func(format string, args ...any) familyFile { return familyFile{err: fmt.Errorf(format, args...)} }
	if entry.File == "" || strings.Contains(entry.File, "..") {
		return fail("%s%s: family %s has no usable `file`", prefix, name, family)
	}
	if why := notRegular(fsys, entry.File); why != "" {
		return fail("%s%s: %s", prefix, entry.File, why)
	}
	data, err := fs.ReadFile(fsys, entry.File)
	if err != nil {
		return fail("%s%s: cannot read it (listed in %s)", prefix, entry.File, name)
	}
	f := familyFile{where: prefix + entry.File}
	if path.Ext(entry.File) == ".jsonl" {
		f.header, f.vectors, f.err = parseJSONL(data, f.where)
	} else {
		f.header, f.vectors, f.err = parseFamilyJSON(data, f.where)
	}
	if f.err != nil {
		return f
	}
	// After parsing, so that a line that does not parse is named by its line.
	if entry.SHA256 != "" {
		if sum := sha256.Sum256(data); hex.EncodeToString(sum[:]) != entry.SHA256 {
			return fail("%s: its sha256 is not the one %s gives: the file is damaged or edited; export it again (plcvec export --lang go)", f.where, name)
		}
	}
	if f.header.Family != family {
		return fail("%s: holds family %q, but %s lists it as %q", f.where, f.header.Family, name, family)
	}
	if entry.Count != nil && *entry.Count != len(f.vectors) {
		return fail("%s: %d vectors, but %s says %d (a truncated file?)", f.where, len(f.vectors), name, *entry.Count)
	}
	return f
}

// add adds a family's header and vectors to s; an id s holds already is an error.
func (s *Suite) add(family string, f familyFile) error {
	s.Families = append(s.Families, family)
	s.Headers[family] = f.header
	for _, v := range f.vectors {
		if s.byID[v.ID] != nil {
			return fmt.Errorf("%s: vector id %s appears twice", f.where, v.ID)
		}
		s.byID[v.ID] = v
	}
	s.Vectors = append(s.Vectors, f.vectors...)
	return nil
}

// readIndex reads the folder's index: index.json (an exported copy), else manifest.json (a vector
// folder). Whatever is there under an index's name is read as the index: a named pipe is refused
// by name, not taken for "no index".
func readIndex(fsys fs.FS, source, prefix string) (string, []byte, error) {
	for _, name := range []string{"index.json", "manifest.json"} {
		if _, err := fs.Stat(fsys, name); errors.Is(err, fs.ErrNotExist) {
			continue
		}
		if why := notRegular(fsys, name); why != "" {
			return "", nil, fmt.Errorf("%s%s: %s", prefix, name, why)
		}
		raw, err := fs.ReadFile(fsys, name)
		if err != nil {
			return "", nil, fmt.Errorf("%s%s: cannot read it (%v)", prefix, name, errors.Unwrap(err))
		}
		return name, raw, nil
	}
	return "", nil, fmt.Errorf("%s: no index.json (an exported copy) or manifest.json (a vector folder)", source)
}

// mergedIDs flattens an index's {family: {old id: the id it went to}} into {old id: the id it is
// now}, each chain of merges followed to its end (a vector merged into one merged again later).
func mergedIDs(merged map[string]map[string]string) map[string]string {
	flat := map[string]string{}
	for _, ids := range merged {
		for old, id := range ids {
			flat[old] = id
		}
	}
	out := make(map[string]string, len(flat))
	for old, id := range flat {
		seen := map[string]bool{old: true}
		for next, ok := flat[id]; ok && !seen[id]; next, ok = flat[id] {
			seen[id] = true
			id = next
		}
		out[old] = id
	}
	return out
}

func checkHeader(h *FamilyHeader, where string) error {
	if h.Family == "" {
		return fmt.Errorf("%s: not a plcvec vector file (no `family`)", where)
	}
	major := strings.SplitN(h.SchemaVersion, ".", 2)[0]
	if major != strconv.Itoa(SchemaMajor) {
		v := h.SchemaVersion
		if v == "" {
			v = "(none)"
		}
		return fmt.Errorf("%s: schema_version %s is not %d.x; this verifier reads %d.x files only (see CONTRACT.md, Versioning)", where, v, SchemaMajor, SchemaMajor)
	}
	return nil
}

// parseJSONL reads an exported family file: line 1 the header, then one vector per line. A
// sound file is decoded by hand (fastJSONL); one that the hand-written decoder declines, in one
// pass by encoding/json (streamJSONL); one that does not decode so is read again line by line
// (jsonlByLine), which names the line at fault.
func parseJSONL(data []byte, where string) (*FamilyHeader, []*Vector, error) {
	lines := bytes.Split(data, []byte("\n"))
	if len(lines) > 0 && len(lines[len(lines)-1]) == 0 {
		lines = lines[:len(lines)-1]
	}
	if len(lines) == 0 {
		return nil, nil, fmt.Errorf("%s: empty; not a plcvec vector file", where)
	}
	// The hand-written decoder first (fastdecode.go); what it declines, encoding/json.
	header, vectors, noRepeats := fastJSONL(data, lines)
	if !noRepeats {
		var ok bool
		if header, vectors, ok = streamJSONL(data, lines); !ok {
			return jsonlByLine(lines, where)
		}
	}
	var keys keyScanner
	if err := keys.repeatedKeyError(lines[0], where, 1, nil); err != nil {
		return nil, nil, err
	}
	if err := checkHeader(header, where); err != nil {
		return nil, nil, err
	}
	for i, v := range vectors {
		lineNo := i + 2
		// fastJSONL read every object of the vector lines and found no key twice.
		if !noRepeats {
			if err := keys.repeatedKeyError(lines[i+1], where, lineNo, func(int) string { return v.ID }); err != nil {
				return nil, nil, err
			}
		}
		if p := v.shapeProblem(header); p != "" {
			return nil, nil, fmt.Errorf("%s:%d: vector %s: %s (is the file a plcvec vector file, unedited?)", where, lineNo, nameOr(v.ID, lineNo), p)
		}
	}
	return header, vectors, nil
}

// streamJSONL decodes the header and the vectors of an exported family file with one decoder,
// value after value, each of which must be the whole of its line (the lines of data, in
// order). A decoder per line, as jsonlByLine reads them, copies each line into a buffer it
// grows by doubling: some three times the file's size of garbage, made by every run that loads
// the set. ok is false for anything jsonlByLine would refuse before it looks at a vector's shape.
func streamJSONL(data []byte, lines [][]byte) (header *FamilyHeader, vectors []*Vector, ok bool) {
	if !utf8.Valid(data) {
		return nil, nil, false
	}
	dec := json.NewDecoder(bytes.NewReader(data))
	dec.DisallowUnknownFields()
	header, vectors = &FamilyHeader{}, make([]*Vector, 0, len(lines)-1)
	end := 0 // the offset of the end of the line being read
	for i, line := range lines {
		end += len(line)
		var into any = header
		if i > 0 {
			v := &Vector{}
			vectors, into = append(vectors, v), v
		}
		// A value that ends past its line's end, or leaves more than blanks after it on the
		// line, is not that line's alone (a line with no value, two values on a line).
		if dec.Decode(into) != nil || dec.InputOffset() > int64(end) ||
			len(bytes.Trim(data[dec.InputOffset():end], " \t\r")) > 0 {
			return nil, nil, false
		}
		end++ // the newline
	}
	return header, vectors, true
}

// jsonlByLine is parseJSONL for a file that does not decode in one pass: each line apart, so
// that a refusal names the first line at fault.
func jsonlByLine(lines [][]byte, where string) (*FamilyHeader, []*Vector, error) {
	if err := checkUTF8(lines[0], where, 1); err != nil {
		return nil, nil, err
	}
	header := &FamilyHeader{}
	if err := decodeStrict(lines[0], header); err != nil {
		return nil, nil, fmt.Errorf("%s:1: the header is not valid (%v)", where, err)
	}
	var keys keyScanner
	if err := keys.repeatedKeyError(lines[0], where, 1, nil); err != nil {
		return nil, nil, err
	}
	if err := checkHeader(header, where); err != nil {
		return nil, nil, err
	}
	vectors := make([]*Vector, 0, len(lines)-1)
	for i, line := range lines[1:] {
		lineNo := i + 2
		if err := checkUTF8(line, where, lineNo); err != nil {
			return nil, nil, err
		}
		v := &Vector{}
		if err := decodeStrict(line, v); err != nil {
			return nil, nil, fmt.Errorf("%s:%d: %s not a valid vector (%v)", where, lineNo, idOf(line), err)
		}
		if err := keys.repeatedKeyError(line, where, lineNo, func(int) string { return v.ID }); err != nil {
			return nil, nil, err
		}
		if p := v.shapeProblem(header); p != "" {
			return nil, nil, fmt.Errorf("%s:%d: vector %s: %s (is the file a plcvec vector file, unedited?)", where, lineNo, nameOr(v.ID, lineNo), p)
		}
		vectors = append(vectors, v)
	}
	return header, vectors, nil
}

// parseFamilyJSON reads a repository family file: one JSON object, the header and `vectors`.
// A sound file is read in one pass, vector after vector straight into its struct
// (streamFamilyJSON); a file that does not read so is read again vector by vector from copies of
// their text (familyJSONByVector), which names the vector at fault. The one pass spares a run
// two copies of every vector (json.RawMessage, then a decoder's buffer) and the decoder's buffer
// of the whole file: some 60 MB of garbage for the golden set, which the collector and the
// scavenger were still working off while the run judged.
func parseFamilyJSON(data []byte, where string) (*FamilyHeader, []*Vector, error) {
	if err := checkUTF8(data, where, 1); err != nil {
		return nil, nil, err
	}
	header, vectors, ok := streamFamilyJSON(data)
	if !ok {
		return familyJSONByVector(data, where)
	}
	if err := checkHeader(header, where); err != nil {
		return nil, nil, err
	}
	var keys keyScanner
	if err := keys.repeatedKeyError(data, where, 1, func(at int) string { return vectorAt(data, at) }); err != nil {
		return nil, nil, err
	}
	for i, v := range vectors {
		if p := v.shapeProblem(header); p != "" {
			return nil, nil, fmt.Errorf("%s: vector %s: %s (is the file a plcvec vector file, unedited?)", where, nameOr(v.ID, i), p)
		}
	}
	return header, vectors, nil
}

// streamFamilyJSON reads a family file's header and vectors in one pass, each vector decoded
// from the file's text as the decoder reaches it (its buffer holds a vector or so, not the
// file). ok is false for anything familyJSONByVector would refuse before it looks at a vector's
// shape (text that is not JSON, a key the schema does not have, no `vectors`, a value of the
// wrong type), and for `vectors` given twice: that way names the fault.
func streamFamilyJSON(data []byte) (header *FamilyHeader, vectors []*Vector, ok bool) {
	dec := json.NewDecoder(bytes.NewReader(data))
	dec.DisallowUnknownFields()
	if t, err := dec.Token(); err != nil || t != json.Delim('{') {
		return nil, nil, false
	}
	// The header's members are gathered into an object of their own, decoded as the whole
	// file's object would decode them (the same strictness, the last of a repeated key winning).
	head := []byte{'{'}
	for dec.More() {
		t, err := dec.Token()
		key, isKey := t.(string)
		switch {
		case err != nil || !isKey:
			return nil, nil, false
		case strings.EqualFold(key, "vectors"): // encoding/json's match of a key to a field
			if vectors != nil { // given twice: the other way reads it as the whole file's decoding does
				return nil, nil, false
			}
			if vectors, ok = streamVectors(dec); !ok {
				return nil, nil, false
			}
		default:
			var value json.RawMessage
			if dec.Decode(&value) != nil {
				return nil, nil, false
			}
			quoted, _ := json.Marshal(key)
			head = append(append(append(append(head, quoted...), ':'), value...), ',')
		}
	}
	if t, err := dec.Token(); err != nil || t != json.Delim('}') || dec.More() || vectors == nil {
		return nil, nil, false
	}
	head[len(head)-1] = '}'
	if len(head) == 1 {
		head = append(head, '}')
	}
	header = &FamilyHeader{}
	if decodeStrict(head, header) != nil {
		return nil, nil, false
	}
	return header, vectors, true
}

// streamVectors decodes the array of vectors the decoder has reached, one vector at a time.
func streamVectors(dec *json.Decoder) ([]*Vector, bool) {
	if t, err := dec.Token(); err != nil || t != json.Delim('[') {
		return nil, false
	}
	vectors := []*Vector{}
	for dec.More() {
		v := &Vector{}
		if dec.Decode(v) != nil {
			return nil, false
		}
		vectors = append(vectors, v)
	}
	if t, err := dec.Token(); err != nil || t != json.Delim(']') {
		return nil, false
	}
	return vectors, true
}

// familyJSONByVector is parseFamilyJSON for a file that does not decode in one pass: each
// vector apart, so that a refusal names the first vector at fault, after what the file as a
// whole gets wrong.
func familyJSONByVector(data []byte, where string) (*FamilyHeader, []*Vector, error) {
	var file struct {
		FamilyHeader
		Vectors []json.RawMessage `json:"vectors"`
	}
	if err := decodeStrict(data, &file); err != nil {
		return nil, nil, fmt.Errorf("%s:%d: not valid JSON (%v)", where, jsonErrorLine(data, err), err)
	}
	if err := checkHeader(&file.FamilyHeader, where); err != nil {
		return nil, nil, err
	}
	var keys keyScanner
	if err := keys.repeatedKeyError(data, where, 1, func(at int) string { return vectorAt(data, at) }); err != nil {
		return nil, nil, err
	}
	if file.Vectors == nil {
		return nil, nil, fmt.Errorf("%s: not a plcvec vector file (no `vectors`)", where)
	}
	vectors := make([]*Vector, 0, len(file.Vectors))
	for i, raw := range file.Vectors {
		v := &Vector{}
		if err := decodeStrict(raw, v); err != nil {
			return nil, nil, fmt.Errorf("%s: vector %s: not a valid vector (%v)", where, nameOr(idOfString(raw), i), err)
		}
		if p := v.shapeProblem(&file.FamilyHeader); p != "" {
			return nil, nil, fmt.Errorf("%s: vector %s: %s (is the file a plcvec vector file, unedited?)", where, nameOr(v.ID, i), p)
		}
		vectors = append(vectors, v)
	}
	h := file.FamilyHeader
	return &h, vectors, nil
}

// vectorAt is the id of the vector of a family file (one JSON object, its `vectors` a list) that
// holds the byte at offset, or "". Only a refusal looks for it, so it decodes the file again.
func vectorAt(data []byte, offset int) string {
	dec := json.NewDecoder(bytes.NewReader(data))
	if t, err := dec.Token(); err != nil || t != json.Delim('{') {
		return ""
	}
	for dec.More() {
		key, err := dec.Token()
		if err != nil {
			return ""
		}
		if key != "vectors" {
			var skip json.RawMessage
			if dec.Decode(&skip) != nil {
				return ""
			}
			continue
		}
		if t, err := dec.Token(); err != nil || t != json.Delim('[') {
			return ""
		}
		for dec.More() {
			start := int(dec.InputOffset())
			var raw json.RawMessage
			if dec.Decode(&raw) != nil {
				return ""
			}
			if start <= offset && offset < int(dec.InputOffset()) {
				return idOfString(raw)
			}
		}
		return ""
	}
	return ""
}

func idOf(line []byte) string {
	if id := idOfString(line); id != "" {
		return "vector " + id + ":"
	}
	return "the line is"
}

// idOfString digs the id out of a vector that does not decode, so the error can name it.
func idOfString(raw []byte) string {
	var probe struct {
		ID string `json:"id"`
	}
	_ = json.Unmarshal(raw, &probe)
	if probe.ID == "" {
		// A value error deeper in the object still leaves a readable id before it.
		for _, key := range [][]byte{[]byte(`"id":"`), []byte(`"id": "`)} {
			if i := bytes.Index(raw, key); i >= 0 {
				rest := raw[i+len(key):]
				if j := bytes.IndexByte(rest, '"'); j > 0 {
					return string(rest[:j])
				}
			}
		}
	}
	return probe.ID
}

func nameOr(id string, index int) string {
	if id != "" {
		return id
	}
	return "#" + strconv.Itoa(index)
}

func jsonErrorLine(data []byte, err error) int {
	var syntax *json.SyntaxError
	var typ *json.UnmarshalTypeError
	offset := int64(-1)
	if errors.As(err, &syntax) {
		offset = syntax.Offset
	} else if errors.As(err, &typ) {
		offset = typ.Offset
	}
	if offset < 0 || offset > int64(len(data)) {
		return 1
	}
	return bytes.Count(data[:offset], []byte("\n")) + 1
}

func itoa(n int) string { return strconv.Itoa(n) }

// InterpretationInfo is an open question of the manual as the loaded suite declares it: its
// alternatives, its default, and the families whose vectors it decides. One interpretation may
// belong to several families (the FX5 time and date comparisons share theirs): an
// implementation declares it once, and it holds for all of them.
type InterpretationInfo struct {
	ID           string
	Default      string
	Alternatives []string
	Families     []string
}

// Interpretations lists the suite's interpretations, sorted by id.
func (s *Suite) Interpretations() []InterpretationInfo {
	out, _ := s.interpretations()
	return out
}

func (s *Suite) interpretations() ([]InterpretationInfo, error) {
	byID := map[string]*InterpretationInfo{}
	for _, family := range s.Families {
		for _, hi := range s.Headers[family].Interpretations {
			alts := make([]string, len(hi.Alternatives))
			for i, a := range hi.Alternatives {
				alts[i] = a.ID
			}
			seen := byID[hi.ID]
			if seen == nil {
				byID[hi.ID] = &InterpretationInfo{ID: hi.ID, Default: hi.Default, Alternatives: alts, Families: []string{family}}
				continue
			}
			if seen.Default != hi.Default || strings.Join(seen.Alternatives, "\x00") != strings.Join(alts, "\x00") {
				return nil, fmt.Errorf("%s: interpretation %s has other alternatives or another default in %s than in %s",
					s.Source, hi.ID, family, seen.Families[0])
			}
			seen.Families = append(seen.Families, family)
		}
	}
	out := make([]InterpretationInfo, 0, len(byID))
	for _, i := range byID {
		out = append(out, *i)
	}
	sort.Slice(out, func(a, b int) bool { return out[a].ID < out[b].ID })
	return out, nil
}

// unjudgingAlternatives are the alternatives ("ID=alternative") under which some vector's
// `alternatives` entry leaves devices unjudged.
func (s *Suite) unjudgingAlternatives() map[string]bool {
	out := map[string]bool{}
	for _, v := range s.Vectors {
		for _, alt := range v.Alternatives {
			for id := range alt.Unjudged {
				out[id+"="+alt.Choices[id]] = true
			}
		}
	}
	return out
}
