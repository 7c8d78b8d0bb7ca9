package plcvec_test

import (
	"encoding/json"
	"os"
	"path/filepath"
	"regexp"
	"runtime"
	"strconv"
	"strings"
	"syscall"
	"testing"
	"time"

	"github.com/plcvec/plcvec/verifiers/go"
)

// copyVectors copies the exported vectors of the families named into a new folder, with an index
// of them alone (each file's sha256 and count as the exported index gives them), each file
// through edit (name -> bytes; nil keeps them). One small family is enough for what a test of
// loading asks, and loads in a tenth of the time of the whole set.
func copyVectors(t *testing.T, edit func(name string, data []byte) []byte, families ...string) string {
	t.Helper()
	if len(families) == 0 {
		families = []string{"fx5-time-add"}
	}
	var index struct {
		Families map[string]json.RawMessage `json:"families"`
		Rest     map[string]json.RawMessage `json:"-"`
	}
	raw, err := os.ReadFile(filepath.Join("vectors", "index.json"))
	if err != nil {
		t.Fatal(err)
	}
	if err := json.Unmarshal(raw, &index); err != nil {
		t.Fatal(err)
	}
	dir := t.TempDir()
	kept := map[string]json.RawMessage{}
	write := func(name string, data []byte) {
		if edit != nil {
			data = edit(name, data)
		}
		if err := os.WriteFile(filepath.Join(dir, name), data, 0o644); err != nil {
			t.Fatal(err)
		}
	}
	for _, f := range families {
		kept[f] = index.Families[f]
		data, err := os.ReadFile(filepath.Join("vectors", f+".jsonl"))
		if err != nil {
			t.Fatal(err)
		}
		write(f+".jsonl", data)
	}
	listing, _ := json.MarshalIndent(map[string]any{"families": kept, "suite_version": "test"}, "", " ")
	write("index.json", append(listing, '\n'))
	return dir
}

// loadWithin loads dir, failing the test when the load takes more than a few seconds (a load
// that opens a named pipe waits for ever).
func loadWithin(t *testing.T, dir string) error {
	t.Helper()
	done := make(chan error, 1)
	go func() {
		_, err := plcvec.Load(dir)
		done <- err
	}()
	select {
	case err := <-done:
		return err
	case <-time.After(20 * time.Second):
		t.Fatalf("loading %s did not end", dir)
		return nil
	}
}

// TestLoadRefusesWhatIsNotARegularFile: a named pipe, a device, a folder or a loop of symbolic
// links where the index or a family file belongs is refused by its path, before it is opened.
func TestLoadRefusesWhatIsNotARegularFile(t *testing.T) {
	for _, c := range []struct {
		name, file string
		put        func(path string) error
		want       string
	}{
		{"named pipe", "fx5-time-add.jsonl", func(p string) error { return syscall.Mkfifo(p, 0o644) }, "fx5-time-add.jsonl: not a regular file (a named pipe)"},
		{"index a named pipe", "index.json", func(p string) error { return syscall.Mkfifo(p, 0o644) }, "index.json: not a regular file (a named pipe)"},
		{"device", "fx5-time-add.jsonl", func(p string) error { return os.Symlink("/dev/zero", p) }, "fx5-time-add.jsonl: not a regular file (a character device)"},
		{"folder", "fx5-time-add.jsonl", func(p string) error { return os.Mkdir(p, 0o755) }, "fx5-time-add.jsonl: not a regular file (a folder)"},
		{"loop", "fx5-time-add.jsonl", func(p string) error { return os.Symlink(filepath.Base(p), p) }, "fx5-time-add.jsonl: a loop of symbolic links"},
	} {
		t.Run(c.name, func(t *testing.T) {
			dir := copyVectors(t, nil)
			path := filepath.Join(dir, c.file)
			if err := os.Remove(path); err != nil {
				t.Fatal(err)
			}
			if err := c.put(path); err != nil {
				t.Skipf("cannot make one here: %v", err)
			}
			if err := loadWithin(t, dir); err == nil || err.Error() != path+strings.TrimPrefix(c.want, c.file) {
				t.Errorf("got %v; want %s", err, path+strings.TrimPrefix(c.want, c.file))
			}
		})
	}
}

// TestLoadRefusesRepeatedKeys: a JSON object holding one key twice, in a vector, a file's header
// or the index, is refused by file, line (of the second occurrence) and vector id.
func TestLoadRefusesRepeatedKeys(t *testing.T) {
	const family = "fx5-time-add.jsonl"
	sealed := func(edit func([]string) []string) func(string, []byte) []byte {
		return func(name string, data []byte) []byte {
			switch name {
			case family:
				return []byte(strings.Join(edit(strings.Split(string(data), "\n")), "\n"))
			case "index.json": // the edited file's hash is not the damage under test
				return regexp.MustCompile(`"sha256": "[0-9a-f]+"`).ReplaceAll(data, []byte(`"sha256": ""`))
			}
			return data
		}
	}
	idOnLine3 := func(lines []string) string {
		return regexp.MustCompile(`"id":"([^"]+)"`).FindStringSubmatch(lines[2])[1]
	}
	var id string
	for _, c := range []struct {
		name string
		edit func(string, []byte) []byte
		want func(dir string) string
	}{
		{"in a vector", sealed(func(ls []string) []string {
			id = idOnLine3(ls)
			ls[2] = strings.Replace(ls[2], `"description":"`, `"description":"twice","description":"`, 1)
			return ls
		}), func(dir string) string {
			return filepath.Join(dir, family) + ":3: vector " + id + `: repeated key "description"`
		}},
		{"deep in a vector, written with an escape", sealed(func(ls []string) []string {
			id = idOnLine3(ls)
			ls[2] = strings.Replace(ls[2], `"devices":{`, `"devices":{"D\u0031":1,"D1":1,`, 1)
			return ls
		}), func(dir string) string {
			return filepath.Join(dir, family) + ":3: vector " + id + `: repeated key "D1"`
		}},
		{"in the header", sealed(func(ls []string) []string {
			ls[0] = strings.Replace(ls[0], `{`, `{"family":"fx5-time-add",`, 1)
			return ls
		}), func(dir string) string { return filepath.Join(dir, family) + `:1: repeated key "family"` }},
		{"in the index (the line of the second occurrence)", func(name string, data []byte) []byte {
			if name == "index.json" {
				return []byte(strings.Replace(string(data), "{", `{"families": {}, `, 1))
			}
			return data
		}, func(dir string) string { return filepath.Join(dir, "index.json") + `:2: repeated key "families"` }},
	} {
		t.Run(c.name, func(t *testing.T) {
			dir := copyVectors(t, c.edit)
			if err := loadWithin(t, dir); err == nil || err.Error() != c.want(dir) {
				t.Errorf("got %v; want %s", err, c.want(dir))
			}
		})
	}
}

// familyJSONFolder is a repository folder (manifest.json and <family>.json) of one family of the
// repository's vectors/, its file's hash left out of the manifest (an edit is the damage under
// test); "" and a skip where there is no repository beside this module.
func familyJSONFolder(t *testing.T, family string) string {
	t.Helper()
	src := filepath.Join("..", "..", "vectors")
	if _, err := os.Stat(filepath.Join(src, "manifest.json")); err != nil {
		t.Skip("no repository vectors/ beside this module")
	}
	dir := t.TempDir()
	for _, name := range []string{"manifest.json", family + ".json"} {
		data, err := os.ReadFile(filepath.Join(src, name))
		if err != nil {
			t.Fatal(err)
		}
		os.WriteFile(filepath.Join(dir, name), data, 0o644)
	}
	var manifest map[string]any
	raw, _ := os.ReadFile(filepath.Join(dir, "manifest.json"))
	if err := json.Unmarshal(raw, &manifest); err != nil {
		t.Fatal(err)
	}
	entry := manifest["families"].(map[string]any)[family].(map[string]any)
	entry["sha256"] = ""
	manifest["families"] = map[string]any{family: entry}
	delete(manifest, "total")
	raw, _ = json.Marshal(manifest)
	os.WriteFile(filepath.Join(dir, "manifest.json"), raw, 0o644)
	return dir
}

// TestLoadRefusesRepeatedKeysInAFamilyJSON: in a repository folder (manifest.json and
// <family>.json), the repeat is named by its line and the vector that holds it.
func TestLoadRefusesRepeatedKeysInAFamilyJSON(t *testing.T) {
	dir := familyJSONFolder(t, "fx5-time-add")
	data, _ := os.ReadFile(filepath.Join(dir, "fx5-time-add.json"))
	lines := strings.Split(string(data), "\n")
	at, id := -1, ""
	for i, l := range lines {
		if m := regexp.MustCompile(`"id": "(fx5-time-add/TADD/manual-example/program)"`).FindStringSubmatch(l); m != nil {
			id = m[1]
		}
		if id != "" && strings.Contains(l, `"tags": [`) {
			lines[i] = strings.Replace(l, `"tags": [`, `"tags": [], "tags": [`, 1)
			at = i + 1
			break
		}
	}
	os.WriteFile(filepath.Join(dir, "fx5-time-add.json"), []byte(strings.Join(lines, "\n")), 0o644)
	want := filepath.Join(dir, "fx5-time-add.json") + ":" + strconv.Itoa(at) + ": vector " + id + `: repeated key "tags"`
	if err := loadWithin(t, dir); at < 0 || err == nil || err.Error() != want {
		t.Errorf("got %v; want %s", err, want)
	}
}

// TestLoadNamesTheVectorAtFaultInAFamilyJSON: a family file (<family>.json) is read in one pass
// when it is sound; one that is not is refused as reading it vector by vector refuses it, by the
// vector at fault (its id, or its place in the list when it has none), and one that spells
// `vectors` otherwise loads as encoding/json reads it, whatever the case of the key.
func TestLoadNamesTheVectorAtFaultInAFamilyJSON(t *testing.T) {
	const family = "fx5-time-add"
	cases := []struct {
		name string
		edit func(file map[string]any, vectors []any)
		want string // "": loads, with every vector of the file
	}{
		{"a key no vector has", func(_ map[string]any, vs []any) { vs[2].(map[string]any)["bogus"] = 1 },
			`: vector {id2}: not a valid vector (json: unknown field "bogus")`},
		{"a word out of range", func(_ map[string]any, vs []any) {
			vs[3].(map[string]any)["initial"].(map[string]any)["devices"].(map[string]any)["D0"] = 70000
		}, ": vector {id3}: not a valid vector (a device value is true, false or an integer 0..65535, not 70000)"},
		{"null for a vector", func(_ map[string]any, vs []any) { vs[1] = nil },
			": vector #1: no `id` (is the file a plcvec vector file, unedited?)"},
		{"a key the header does not have", func(f map[string]any, _ []any) { f["bogus"] = true },
			`:1: not valid JSON (json: unknown field "bogus")`},
		{"vectors spelt in capitals", func(f map[string]any, vs []any) { delete(f, "vectors"); f["VECTORS"] = vs }, ""},
	}
	for _, c := range cases {
		t.Run(c.name, func(t *testing.T) {
			dir := familyJSONFolder(t, family)
			path := filepath.Join(dir, family+".json")
			raw, _ := os.ReadFile(path)
			var file map[string]any
			if err := json.Unmarshal(raw, &file); err != nil {
				t.Fatal(err)
			}
			vectors := file["vectors"].([]any)
			ids := make([]string, len(vectors))
			for i, v := range vectors {
				ids[i] = v.(map[string]any)["id"].(string)
			}
			c.edit(file, vectors)
			raw, _ = json.Marshal(file)
			os.WriteFile(path, raw, 0o644)
			suite, err := plcvec.Load(dir)
			if c.want == "" {
				if err != nil || len(suite.Vectors) != len(ids) {
					t.Fatalf("got %v; want the %d vectors loaded", err, len(ids))
				}
				return
			}
			want := path + strings.NewReplacer("{id2}", ids[2], "{id3}", ids[3]).Replace(c.want)
			if err == nil || err.Error() != want {
				t.Errorf("got %v; want %s", err, want)
			}
		})
	}
}

// TestLoadingAFamilyAllocatesAboutItsVectors: a family file, a repository's <family>.json or an
// exported <family>.jsonl, is decoded in one pass, without a copy of the file or of each
// vector's text, so that a run does not start judging with a heap full of loading's garbage for
// the collector to work through. Read vector by vector (line by line), the JSON file allocated
// some seventeen times its (pretty-printed) size and the JSON-lines file some fourteen times its
// own; in one pass, each under seven times, most of it the vectors themselves.
func TestLoadingAFamilyAllocatesAboutItsVectors(t *testing.T) {
	const family = "cp1e-time-compare"
	for _, c := range []struct {
		file  string
		dir   func() string
		times uint64
	}{
		{family + ".json", func() string { return familyJSONFolder(t, family) }, 8},
		{family + ".jsonl", func() string { return copyVectors(t, nil, family) }, 8},
	} {
		dir := c.dir()
		info, err := os.Stat(filepath.Join(dir, c.file))
		if err != nil {
			t.Fatal(err)
		}
		if _, err := plcvec.Load(dir); err != nil { // warm: the first load's one-off allocations apart
			t.Fatal(err)
		}
		var before, after runtime.MemStats
		runtime.ReadMemStats(&before)
		if _, err := plcvec.Load(dir); err != nil {
			t.Fatal(err)
		}
		runtime.ReadMemStats(&after)
		if allocated, limit := after.TotalAlloc-before.TotalAlloc, c.times*uint64(info.Size()); allocated > limit {
			t.Errorf("loading %s (%d bytes) allocated %d bytes; want at most %d (%d times the file)", c.file, info.Size(), allocated, limit, c.times)
		} else {
			t.Logf("loading %s (%d bytes) allocated %d bytes (%.1f times)", c.file, info.Size(), allocated, float64(allocated)/float64(info.Size()))
		}
	}
}
