package plcvec

import (
	"fmt"
	"hash/crc32"
	"os"
	"sort"
	"strconv"
	"strings"
)

// Selection chooses vectors. Each list is OR within itself; the filters are AND together. The
// zero Selection selects every vector.
type Selection struct {
	Families        []string
	Instructions    []string
	Tags            []string
	IDs             []string // glob patterns on the id (*, ?, [...] as in fnmatch: * crosses '/')
	Interpretations []string // vectors whose outcome depends on one of these
	Shard           Shard    // the zero Shard is "all"
}

// Shard is shard K of N (1 <= K <= N): the vectors with crc32(id) % N + 1 == K, the rule of every
// plcvec runner, so shards agree across languages. A hash of the id rather than a position:
// adding a vector moves no other vector to another shard.
type Shard struct{ K, N int }

// ParseShard reads "K/N".
func ParseShard(text string) (Shard, error) {
	k, n, ok := strings.Cut(text, "/")
	ki, err1 := strconv.Atoi(k)
	ni, err2 := strconv.Atoi(n)
	if !ok || err1 != nil || err2 != nil {
		return Shard{}, fmt.Errorf("a shard is K/N (e.g. 2/4), not %q", text)
	}
	if ki < 1 || ki > ni {
		return Shard{}, fmt.Errorf("shard %s: K must be between 1 and N", text)
	}
	return Shard{ki, ni}, nil
}

// ShardOf is the shard (1..n) a vector id belongs to: crc32(id) % n + 1 (CRC-32/IEEE of the UTF-8 id).
func ShardOf(id string, n int) int {
	return int(crc32.ChecksumIEEE([]byte(id))%uint32(n)) + 1
}

func (sel *Selection) check() error {
	if sel.Shard != (Shard{}) && (sel.Shard.K < 1 || sel.Shard.K > sel.Shard.N) {
		return fmt.Errorf("shard %d/%d: K must be between 1 and N", sel.Shard.K, sel.Shard.N)
	}
	for _, p := range sel.IDs {
		if _, err := compileGlob(p); err != nil {
			return err
		}
	}
	return nil
}

// Matches reports whether the selection takes vector v.
func (sel *Selection) Matches(v *Vector) bool {
	if len(sel.Families) > 0 && !contains(sel.Families, v.Family) {
		return false
	}
	if len(sel.Instructions) > 0 && !contains(sel.Instructions, v.Instruction) {
		return false
	}
	if len(sel.Tags) > 0 && !anyIn(sel.Tags, v.Tags) {
		return false
	}
	if len(sel.IDs) > 0 {
		hit := false
		for _, p := range sel.IDs {
			if g, err := compileGlob(p); err == nil && g.MatchString(v.ID) {
				hit = true
				break
			}
		}
		if !hit {
			return false
		}
	}
	if len(sel.Interpretations) > 0 && !anyIn(sel.Interpretations, v.Outcome.Interpretations) {
		return false
	}
	if sel.Shard.N > 0 && ShardOf(v.ID, sel.Shard.N) != sel.Shard.K {
		return false
	}
	return true
}

// Select returns the vectors the selection takes, in suite order. Unknown family, instruction,
// tag or interpretation names, and an id glob that matches no vector of the suite, are an error,
// not an empty selection: a misspelt filter must not pass a gate by selecting nothing.
func (s *Suite) Select(sel Selection) ([]*Vector, error) {
	if err := s.checkSelection(sel); err != nil {
		return nil, err
	}
	var out []*Vector
	for _, v := range s.Vectors {
		if sel.Matches(v) {
			out = append(out, v)
		}
	}
	return out, nil
}

// checkSelection names the first thing in sel the suite does not have, with what it has.
func (s *Suite) checkSelection(sel Selection) error {
	if err := sel.check(); err != nil {
		return err
	}
	known := map[string][]string{}
	seen := map[string]bool{}
	add := func(what, name string) {
		if !seen[what+"\x00"+name] {
			seen[what+"\x00"+name] = true
			known[what] = append(known[what], name)
		}
	}
	for _, f := range s.Families {
		add("family", f)
		for _, i := range s.Headers[f].Instructions {
			add("instruction", i)
		}
		for t := range s.Headers[f].Tags {
			add("tag", t)
		}
	}
	for _, i := range s.Interpretations() {
		add("interpretation", i.ID)
	}
	for _, c := range []struct {
		what  string
		names []string
	}{{"family", sel.Families}, {"instruction", sel.Instructions}, {"tag", sel.Tags}, {"interpretation", sel.Interpretations}} {
		for _, n := range c.names {
			if !seen[c.what+"\x00"+n] {
				names := known[c.what]
				sort.Strings(names)
				return fmt.Errorf("%s has no such %s %q; known: %s", s.Source, c.what, n, strings.Join(names, ", "))
			}
		}
	}
	for _, p := range sel.IDs {
		g, _ := compileGlob(p)
		hit := false
		for _, v := range s.Vectors {
			if g.MatchString(v.ID) {
				hit = true
				break
			}
		}
		if !hit {
			example := "cp1e-time-compare/AND <=DT/logic/rlo-off/eq"
			if len(s.Vectors) > 0 {
				example = s.Vectors[0].ID
			}
			return fmt.Errorf("%q matches no vector id in %s (ids look like %s; a glob matches the whole id)", p, s.Source, example)
		}
	}
	return nil
}

func anyIn(want, have []string) bool {
	for _, w := range want {
		if contains(have, w) {
			return true
		}
	}
	return false
}

// narrow keeps the vectors the PLCVEC_* selection also takes.
func (s *Suite) narrow(vectors []*Vector, env environment) ([]*Vector, error) {
	if err := s.checkEnvironment(env); err != nil {
		return nil, err
	}
	out := vectors[:0:0]
	for _, v := range vectors {
		if env.narrow.Matches(v) {
			out = append(out, v)
		}
	}
	return out, nil
}

// checkEnvironment checks each variable's names against the suite apart, so that an error names
// the variable that holds the unknown name.
func (s *Suite) checkEnvironment(env environment) error {
	for _, c := range []struct {
		name string
		sel  Selection
	}{{EnvID, Selection{IDs: env.narrow.IDs}}, {EnvFamily, Selection{Families: env.narrow.Families}},
		{EnvInstruction, Selection{Instructions: env.narrow.Instructions}}, {EnvTag, Selection{Tags: env.narrow.Tags}},
		{EnvInterpretation, Selection{Interpretations: env.narrow.Interpretations}}} {
		if err := s.checkSelection(c.sel); err != nil {
			return fmt.Errorf("%s=%q: %v", c.name, os.Getenv(c.name), err)
		}
	}
	return nil
}
