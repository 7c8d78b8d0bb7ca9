package plcvec

import (
	"bytes"
	"encoding/json"
	"errors"
	"fmt"
	"io/fs"
	"os"
	"strings"
	"syscall"
)

// Reading the files a run trusts (CONTRACT.md, "Loading"): only regular files, and JSON with no
// key given twice. A named pipe nobody writes, a device that never ends (/dev/zero) or a loop of
// symbolic links where a vector file belongs would hang a loader that opens it without looking,
// so a path is looked at first and refused by name. A JSON object holding one key twice is
// refused too: parsers disagree on which value wins (encoding/json keeps the last), so the
// runners could judge one file several ways.

// notRegular says why the file name of fsys is not a regular file ("" when it is one, or when
// nothing is there: reading it then says so): the message of CONTRACT.md without the path.
func notRegular(fsys fs.FS, name string) string {
	info, err := fs.Stat(fsys, name)
	if errors.Is(err, syscall.ELOOP) {
		return "a loop of symbolic links"
	}
	if err != nil {
		return ""
	}
	return modeProblem(info.Mode())
}

// notRegularPath is notRegular for a path of the operating system.
func notRegularPath(path string) string {
	info, err := os.Stat(path)
	if errors.Is(err, syscall.ELOOP) {
		return "a loop of symbolic links"
	}
	if err != nil {
		return ""
	}
	return modeProblem(info.Mode())
}

func modeProblem(mode fs.FileMode) string {
	switch {
	case mode.IsRegular():
		return ""
	case mode&fs.ModeNamedPipe != 0:
		return "not a regular file (a named pipe)"
	case mode&fs.ModeCharDevice != 0:
		return "not a regular file (a character device)"
	case mode&fs.ModeDevice != 0:
		return "not a regular file (a block device)"
	case mode&fs.ModeSocket != 0:
		return "not a regular file (a socket)"
	case mode.IsDir():
		return "not a regular file (a folder)"
	}
	return "not a regular file"
}

// keyScanner finds the first key, in text order, that repeats an earlier key of its own object
// in the JSON values of some data (one value, or one per line). The data are valid JSON (the
// decoder has read them): the scan only tells strings, objects and arrays apart. Keys are
// compared as written, and decoded only when one holds an escape, so that "a" and "\u0061" are
// one key. It holds, for each object open at the scan's position, the keys read so far: one list
// for all of them, each object's from the mark it was opened at; reused from one line to the next.
type keyScanner struct {
	keys  []span
	marks []int // per open container: the start of its keys in keys, -1 for an array
}

type span struct{ start, end int } // a key's bytes, quotes excluded

// scan is the offset of the first repeated key's opening quote and the key, or -1.
func (sc *keyScanner) scan(data []byte) (int, string) {
	sc.keys, sc.marks = sc.keys[:0], sc.marks[:0]
	wantKey := false
	for i := 0; i < len(data); i++ {
		switch data[i] {
		case '{':
			sc.marks = append(sc.marks, len(sc.keys))
			wantKey = true
		case '[':
			sc.marks = append(sc.marks, -1)
		case '}', ']':
			if mark := sc.marks[len(sc.marks)-1]; mark >= 0 {
				sc.keys = sc.keys[:mark]
			}
			sc.marks = sc.marks[:len(sc.marks)-1]
			wantKey = false
		case ',':
			wantKey = len(sc.marks) > 0 && sc.marks[len(sc.marks)-1] >= 0
		case '"':
			end := stringEnd(data, i)
			if wantKey {
				key := span{i + 1, end}
				if sc.seen(data, key) {
					return i, keyText(data[key.start:key.end])
				}
				sc.keys = append(sc.keys, key)
				wantKey = false
			}
			i = end
		}
	}
	return -1, ""
}

// stringEnd is the offset of the closing quote of the string that opens at i.
func stringEnd(data []byte, i int) int {
	for j := i + 1; j < len(data); j++ {
		switch data[j] {
		case '\\':
			j++
		case '"':
			return j
		}
	}
	return len(data)
}

// seen reports whether the innermost object already holds key.
func (sc *keyScanner) seen(data []byte, key span) bool {
	k := data[key.start:key.end]
	escaped := bytes.IndexByte(k, '\\') >= 0
	for _, other := range sc.keys[sc.marks[len(sc.marks)-1]:] {
		o := data[other.start:other.end]
		if bytes.Equal(o, k) || (escaped || bytes.IndexByte(o, '\\') >= 0) && keyText(o) == keyText(k) {
			return true
		}
	}
	return false
}

// keyText is a key's text, its escapes decoded.
func keyText(raw []byte) string {
	var s string
	if err := json.Unmarshal(append(append([]byte{'"'}, raw...), '"'), &s); err != nil {
		return string(raw)
	}
	return s
}

// repeatedKeyError names the first repeated key of data: "<where>:<line>: [vector <id>: ]repeated
// key "<key>"", the line that of the repeat (data's first line is firstLine), the vector the one
// vectorAt gives for the offset (nil, or "" for none), or nil when no key repeats.
func (sc *keyScanner) repeatedKeyError(data []byte, where string, firstLine int, vectorAt func(offset int) string) error {
	at, key := sc.scan(data)
	if at < 0 {
		return nil
	}
	line := firstLine + bytes.Count(data[:at], []byte("\n"))
	if vectorAt != nil {
		if id := vectorAt(at); id != "" {
			return fmt.Errorf("%s:%d: vector %s: repeated key %s", where, line, id, quoteJSON(key))
		}
	}
	return fmt.Errorf("%s:%d: repeated key %s", where, line, quoteJSON(key))
}

// quoteJSON is s as a JSON string, as `plcvec verify` writes it (no HTML escapes, non-ASCII kept).
func quoteJSON(s string) string {
	var b bytes.Buffer
	enc := json.NewEncoder(&b)
	enc.SetEscapeHTML(false)
	_ = enc.Encode(s)
	return strings.TrimSuffix(b.String(), "\n")
}
