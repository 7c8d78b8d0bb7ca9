package plcvec

import (
	"fmt"
	"hash/crc32"
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
// tag or interpretation names are an error, not an empty selection: a misspelt filter must not
// pass a gate by selecting nothing.
func (s *Suite) Select(sel Selection) ([]*Vector, error) {
	if err := sel.check(); err != nil {
		return nil, err
	}
	if err := s.checkNames(sel); err != nil {
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

func (s *Suite) checkNames(sel Selection) error {
	families, instructions, tags := map[string]bool{}, map[string]bool{}, map[string]bool{}
	for _, f := range s.Families {
		families[f] = true
		for _, i := range s.Headers[f].Instructions {
			instructions[i] = true
		}
		for t := range s.Headers[f].Tags {
			tags[t] = true
		}
	}
	interps := map[string]bool{}
	for _, i := range s.Interpretations() {
		interps[i.ID] = true
	}
	for _, c := range []struct {
		what  string
		names []string
		known map[string]bool
	}{{"family", sel.Families, families}, {"instruction", sel.Instructions, instructions},
		{"tag", sel.Tags, tags}, {"interpretation", sel.Interpretations, interps}} {
		for _, n := range c.names {
			if !c.known[n] {
				return fmt.Errorf("no %s %q in %s", c.what, n, s.Source)
			}
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
