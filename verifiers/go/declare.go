package plcvec

import (
	"strconv"
	"strings"
)

// The declaration a roll-up proposes, written as the implementer of this runner declares it
// (verifiers/parity/TEXT.md, "The declaration in each runner"): Hello().Interpretations with
// package spec's names (declaration_gen.go, generated), e.g.
//
//	map[string]string{spec.InterpFx5Sm709Scope: spec.Fx5Sm709ScopeAllWords}

// declarationSyntax is the runner whose declaration a report writes.
type declarationSyntax int

const (
	declareGo     declarationSyntax = iota // Hello().Interpretations, this runner's
	declareVerify                          // plcvec verify's --choose (the shared cases' text)
)

// declaration is changes (interpretation -> alternative) as r's syntax writes it, sorted by id.
func (r *Report) declaration(changes map[string]string) string {
	ids := sortedKeysOf(changes)
	parts := make([]string, len(ids))
	for i, id := range ids {
		if r.syntax == declareVerify {
			parts[i] = "--choose " + id + "=" + changes[id]
		} else {
			parts[i] = goName(id) + ": " + goName(id+"="+changes[id])
		}
	}
	if r.syntax == declareVerify {
		return strings.Join(parts, " ")
	}
	return "map[string]string{" + strings.Join(parts, ", ") + "}"
}

// goName is package spec's constant for an interpretation id or an "ID=alternative"; a name the
// generated table lacks (a vector set newer than this package) is written as a string.
func goName(spec string) string {
	for _, n := range goNames {
		if n.spec == spec {
			return n.name
		}
	}
	if _, alt, ok := strings.Cut(spec, "="); ok {
		spec = alt
	}
	return strconv.Quote(spec)
}
