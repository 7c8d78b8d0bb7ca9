package plcvec

import (
	"fmt"
	"sort"
	"strings"
)

// The roll-up by reading (verifiers/parity/TEXT.md, "The roll-up by reading"), built on the
// inference (infer.go): the failing vectors another reading explains, grouped by the smallest
// change, each group marked partial when failures of its families stay unexplained; those no
// reading explains, by the clauses they cite; the known failures another reading explains, with
// the declaration that replaces them.

// showIDs is the number of vector ids a NOT EXPLAINED group shows.
const showIDs = 5

type group struct {
	n     int
	text  string
	items []int // verdict indexes
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

// RollUp is the roll-up by reading (TEXT.md): empty when no vector failed and none is a known
// failure.
func (r *Report) RollUp() string {
	rd := r.infer()
	if len(rd.failing) == 0 && len(rd.known) == 0 {
		return ""
	}
	var b strings.Builder
	if len(rd.explained) > 0 {
		fmt.Fprintf(&b, "READINGS: %d of %d failing vectors pass under other alternatives:\n", len(rd.explained), len(rd.failing))
		r.writeGroups(&b, rd.explained, rd.unexplained, "failing vectors")
		changes := map[string]string{}
		for id, alt := range rd.choice {
			if r.Plan.Choices[id].Alternative != alt {
				changes[id] = alt
			}
		}
		fmt.Fprintf(&b, "%sdeclare: %s\n", indent, r.declaration(changes))
		if rd.broken > 0 {
			fmt.Fprintf(&b, "%s(so declared, %d vectors that pass now would fail)\n", indent, rd.broken)
		}
		if p := r.nearUnexplained(rd.explained, rd.unexplained); len(p) > 0 {
			fmt.Fprintf(&b, "%spartial: %d failing vectors that no reading explains are of the same families; "+
				"a declaration may hide part of a bug there\n", indent, len(p))
		}
	}
	if len(rd.unexplained) > 0 {
		r.writeUnexplained(&b, rd.unexplained)
	}
	if len(rd.knownExplained) > 0 {
		fmt.Fprintf(&b, "KNOWN FAILURES: %d of %d known failures pass under other alternatives:\n", len(rd.knownExplained), len(rd.known))
		others := append(append([]int(nil), rd.unexplained...), rd.knownUnexplained...)
		r.writeGroups(&b, rd.knownExplained, others, "failing vectors and known failures")
		changes := map[string]string{}
		for _, items := range rd.knownExplained {
			for _, item := range items {
				id, alt, _ := strings.Cut(item, "=")
				changes[id] = alt
			}
		}
		fmt.Fprintf(&b, "%sdeclare: %s\n", indent, r.declaration(changes))
		fmt.Fprintf(&b, "%sthen remove those %d known failures from %s\n", indent, len(rd.knownExplained), r.Plan.Known.Path)
	}
	return b.String()
}

// writeGroups writes one line per smallest change of explained, largest group first, each
// marked partial when a vector of others (unexplained) is of a family one of its vectors is of.
func (r *Report) writeGroups(b *strings.Builder, explained map[int][]string, others []int, what string) {
	groups := map[string]*group{}
	for i, items := range explained {
		text := strings.Join(items, ", ")
		if groups[text] == nil {
			groups[text] = &group{text: text}
		}
		groups[text].n++
		groups[text].items = append(groups[text].items, i)
	}
	for _, g := range sortGroups(groups) {
		mark := ""
		families := map[string]bool{}
		for _, i := range g.items {
			families[r.Verdicts[i].Family] = true
		}
		var near []int
		named := map[string]bool{}
		for _, i := range others {
			if f := r.Verdicts[i].Family; families[f] {
				near, named[f] = append(near, i), true
			}
		}
		if len(near) > 0 {
			mark = fmt.Sprintf(" (partial: %d %s of %s not explained)", len(near), what, strings.Join(sortedKeysOf(named), ", "))
		}
		fmt.Fprintf(b, "%s%6d  %s%s\n", indent, g.n, g.text, mark)
	}
}

// nearUnexplained are the vectors of unexplained whose family some explained vector is of.
func (r *Report) nearUnexplained(explained map[int][]string, unexplained []int) []int {
	families := map[string]bool{}
	for i := range explained {
		families[r.Verdicts[i].Family] = true
	}
	var out []int
	for _, i := range unexplained {
		if families[r.Verdicts[i].Family] {
			out = append(out, i)
		}
	}
	return out
}

// writeUnexplained writes the failing vectors no reading explains, grouped by the clauses they
// cite, each group's ids sorted, at most showIDs of them.
func (r *Report) writeUnexplained(b *strings.Builder, unexplained []int) {
	fmt.Fprintf(b, "NOT EXPLAINED by any reading: %d failing vectors, by the clauses they cite:\n", len(unexplained))
	groups := map[string]*group{}
	for _, i := range unexplained {
		v := &r.Verdicts[i]
		text := "(no clauses)"
		if v.Vector != nil && len(v.Vector.Clauses) > 0 {
			text = strings.Join(v.Vector.Clauses, ", ")
		}
		if groups[text] == nil {
			groups[text] = &group{text: text}
		}
		groups[text].n++
		groups[text].items = append(groups[text].items, i)
	}
	for _, g := range sortGroups(groups) {
		fmt.Fprintf(b, "%s%6d  %s\n", indent, g.n, g.text)
		ids := make([]string, len(g.items))
		for k, i := range g.items {
			ids[k] = r.Verdicts[i].ID
		}
		sort.Strings(ids)
		for k, id := range ids {
			if k == showIDs {
				fmt.Fprintf(b, "%s        ... and %d more\n", indent, len(ids)-showIDs)
				break
			}
			fmt.Fprintf(b, "%s        %s\n", indent, id)
		}
	}
}
