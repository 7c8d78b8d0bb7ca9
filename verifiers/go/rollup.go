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
		r.writeGroups(&b, rd.explained, rd.unexplained, rd.broken)
		changes := map[string]string{}
		for id, alt := range rd.choice {
			if r.Plan.Choices[id].Alternative != alt {
				changes[id] = alt
			}
		}
		fmt.Fprintf(&b, "%sdeclare: %s\n", indent, r.declaration(changes))
		if len(rd.broken) > 0 {
			fmt.Fprintf(&b, "%s(so declared, %d vectors that pass now would fail)\n", indent, len(rd.broken))
		}
		families := map[string]bool{}
		for i := range rd.explained {
			families[r.Verdicts[i].Family] = true
		}
		if near, lost := r.near(families, rd.unexplained, rd.broken); len(near)+len(lost) > 0 {
			fmt.Fprintf(&b, "%spartial: %d vectors no reading explains and %d vectors that pass now are of the same "+
				"families; the declaration may hide part of a bug there\n", indent, len(near), len(lost))
		}
	}
	if len(rd.unexplained) > 0 {
		r.writeUnexplained(&b, rd.unexplained)
	}
	if len(rd.knownExplained) > 0 {
		fmt.Fprintf(&b, "KNOWN FAILURES: %d of %d known failures pass under other alternatives:\n", len(rd.knownExplained), len(rd.known))
		others := append(append([]int(nil), rd.unexplained...), rd.knownUnexplained...)
		r.writeGroups(&b, rd.knownExplained, others, rd.broken)
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
// marked partial when a vector of others (not explained) or of broken (passes now, would fail
// under the choice; by family) is of a family one of its vectors is of: the reading does not
// account for everything the implementation does there.
func (r *Report) writeGroups(b *strings.Builder, explained map[int][]string, others []int, broken []string) {
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
		families := map[string]bool{}
		for _, i := range g.items {
			families[r.Verdicts[i].Family] = true
		}
		mark := ""
		if near, lost := r.near(families, others, broken); len(near)+len(lost) > 0 {
			named := map[string]bool{}
			for _, i := range near {
				named[r.Verdicts[i].Family] = true
			}
			for _, f := range lost {
				named[f] = true
			}
			mark = fmt.Sprintf(" (partial: %d not explained, %d would fail, in %s)", len(near), len(lost),
				strings.Join(sortedKeysOf(named), ", "))
		}
		fmt.Fprintf(b, "%s%6d  %s%s\n", indent, g.n, g.text, mark)
	}
}

// near are the vectors of others (verdict indexes) and of broken (families) that are of families.
func (r *Report) near(families map[string]bool, others []int, broken []string) (near []int, lost []string) {
	for _, i := range others {
		if families[r.Verdicts[i].Family] {
			near = append(near, i)
		}
	}
	for _, f := range broken {
		if families[f] {
			lost = append(lost, f)
		}
	}
	return near, lost
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
