package plcvec

import (
	"fmt"
	"sort"
	"strings"
)

// Interpretation is an open question of the manual as the loaded suite declares it: its
// alternatives, its default, and the families whose vectors it decides. One interpretation may
// belong to several families (the FX5 time and date comparisons share theirs): an
// implementation declares it once, and it holds for all of them.
type Interpretation struct {
	ID           string
	Default      string
	Alternatives []string
	Families     []string
}

// Interpretations lists the suite's interpretations, sorted by id.
func (s *Suite) Interpretations() []Interpretation {
	out, _ := s.interpretations()
	return out
}

func (s *Suite) interpretations() ([]Interpretation, error) {
	byID := map[string]*Interpretation{}
	for _, family := range s.Families {
		for _, hi := range s.Headers[family].Interpretations {
			alts := make([]string, len(hi.Alternatives))
			for i, a := range hi.Alternatives {
				alts[i] = a.ID
			}
			seen := byID[hi.ID]
			if seen == nil {
				byID[hi.ID] = &Interpretation{ID: hi.ID, Default: hi.Default, Alternatives: alts, Families: []string{family}}
				continue
			}
			if seen.Default != hi.Default || strings.Join(seen.Alternatives, "\x00") != strings.Join(alts, "\x00") {
				return nil, fmt.Errorf("%s: interpretation %s has other alternatives or another default in %s than in %s",
					s.Source, hi.ID, family, seen.Families[0])
			}
			seen.Families = append(seen.Families, family)
		}
	}
	out := make([]Interpretation, 0, len(byID))
	for _, i := range byID {
		out = append(out, *i)
	}
	sort.Slice(out, func(a, b int) bool { return out[a].ID < out[b].ID })
	return out, nil
}

// Choice is the alternative a run judges one interpretation by, and whether the implementation
// declared it or it is the default.
type Choice struct {
	Alternative string
	Declared    bool
	Default     string
}

// resolveChoices checks the declared alternatives against the suite and fills in the defaults.
func (s *Suite) resolveChoices(declared map[string]string) (map[string]Choice, error) {
	known := map[string]Interpretation{}
	for _, i := range s.Interpretations() {
		known[i.ID] = i
	}
	ids := make([]string, 0, len(declared))
	for id := range declared {
		ids = append(ids, id)
	}
	sort.Strings(ids)
	for _, id := range ids {
		i, ok := known[id]
		if !ok {
			names := make([]string, 0, len(known))
			for k := range known {
				names = append(names, k)
			}
			sort.Strings(names)
			return nil, fmt.Errorf("the implementation declares interpretation %q, which no vector file defines (known: %s)",
				id, strings.Join(names, ", "))
		}
		if !contains(i.Alternatives, declared[id]) {
			return nil, fmt.Errorf("the implementation declares %s=%s, but %s has the alternatives %s",
				id, declared[id], id, strings.Join(i.Alternatives, ", "))
		}
	}
	out := make(map[string]Choice, len(known))
	for id, i := range known {
		if alt, ok := declared[id]; ok {
			out[id] = Choice{Alternative: alt, Declared: true, Default: i.Default}
		} else {
			out[id] = Choice{Alternative: i.Default, Default: i.Default}
		}
	}
	return out, nil
}

func contains(list []string, s string) bool {
	for _, x := range list {
		if x == s {
			return true
		}
	}
	return false
}
