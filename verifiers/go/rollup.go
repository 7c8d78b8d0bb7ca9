package plcvec

import (
	"fmt"
	"sort"
	"strings"
)

// The roll-up by reading (verifiers/parity/TEXT.md, "The roll-up by reading"), built on the
// inference (infer.go).

type group struct {
	n     int
	text  string
	items []string
}

func sortGroups(groups map[string]*group) []*group {
	out := make([]*group, 0, len(groups))
	for _, g := range groups {
		out = append(out, g)
	}
	sort.Slice(out, func(a, b int) bool {
		if out[a].n != out[b].n {
			return out[a].n > out[b].n
		}
		return out[a].text < out[b].text
	})
	return out
}

// RollUp is the roll-up by reading (TEXT.md): the failing vectors another reading explains,
// grouped by the declaration that does it, then those no reading explains, by the clauses they
// cite. Empty when nothing failed.
func (r *Report) RollUp() string {
	rd := r.infer()
	if len(rd.failing) == 0 {
		return ""
	}
	var b strings.Builder
	if len(rd.explained) > 0 {
		fmt.Fprintf(&b, "READINGS: %d of %d failing vectors pass under other alternatives:\n", len(rd.explained), len(rd.failing))
		groups := map[string]*group{}
		for _, change := range rd.explained {
			if groups[change] == nil {
				groups[change] = &group{text: change}
			}
			groups[change].n++
		}
		for _, g := range sortGroups(groups) {
			fmt.Fprintf(&b, "%s%6d  %s\n", indent, g.n, g.text)
		}
		var declare []string
		for id, alt := range rd.choice {
			if r.Plan.Choices[id].Alternative != alt {
				declare = append(declare, "--choose "+id+"="+alt)
			}
		}
		sort.Strings(declare)
		fmt.Fprintf(&b, "%sdeclare: %s\n", indent, strings.Join(declare, " "))
		if rd.broken > 0 {
			fmt.Fprintf(&b, "%s(so declared, %d vectors that pass now would fail)\n", indent, rd.broken)
		}
	}
	if len(rd.unexplained) > 0 {
		fmt.Fprintf(&b, "NOT EXPLAINED by any reading: %d failing vectors, by the clauses they cite:\n", len(rd.unexplained))
		groups := map[string]*group{}
		for _, i := range rd.unexplained {
			v := &r.Verdicts[i]
			text := "(no clauses)"
			if v.Vector != nil && len(v.Vector.Clauses) > 0 {
				text = strings.Join(v.Vector.Clauses, ", ")
			}
			if groups[text] == nil {
				groups[text] = &group{text: text}
			}
			groups[text].n++
			groups[text].items = append(groups[text].items, v.ID)
		}
		for _, g := range sortGroups(groups) {
			fmt.Fprintf(&b, "%s%6d  %s\n", indent, g.n, g.text)
			sort.Strings(g.items)
			for k, id := range g.items {
				if k == 5 {
					fmt.Fprintf(&b, "%s      %s... and %d more\n", indent, "  ", len(g.items)-5)
					break
				}
				fmt.Fprintf(&b, "%s        %s\n", indent, id)
			}
		}
	}
	return b.String()
}
