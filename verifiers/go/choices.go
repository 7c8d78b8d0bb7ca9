package plcvec

import (
	"fmt"
	"sort"
	"strings"
)

// Choice is the alternative a run judges one interpretation by, and whether the implementation
// declared it or it is the default.
type Choice struct {
	Alternative string
	Declared    bool
	Default     string
}

// Followed is, by interpretation id, the alternative followed for it: a run's Plan.Choices holds
// one for every interpretation of the suite, the implementation's declared alternatives and the
// defaults of the rest. An alias rather than a type of its own, so that code which spells out
// map[string]Choice, as it had to before the name existed, still compiles and assigns.
type Followed = map[string]Choice

// resolveChoices checks the declared alternatives against the suite and fills in the defaults.
func (s *Suite) resolveChoices(declared map[string]string) (Followed, error) {
	known := map[string]InterpretationInfo{}
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
	out := make(Followed, len(known))
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
