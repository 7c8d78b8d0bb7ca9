package reference

// The comparison contacts of both makers: an instruction name such as LDTM<=, ANDDT<> or
// "OR >=DT" is a form (LD, AND, OR) and a condition, decoded once for a vector's CPU so that a
// scan switches on small integers, not on names.

import (
	"strings"
)

// form is where a contact stands in the rung: LD starts it, AND and OR combine its comparison
// with the logic before it (the step's rlo_in).
type form uint8

const (
	formLD form = iota
	formAND
	formOR
)

var forms = [...]string{formLD: "LD", formAND: "AND", formOR: "OR"}

// condition is the comparison a contact makes.
type condition uint8

const (
	condEQ condition = iota // =
	condNE                  // <>
	condGT                  // >
	condLE                  // <=
	condLT                  // <
	condGE                  // >=
)

// conditionOf decodes a condition symbol.
func conditionOf(symbol string) (condition, bool) {
	switch symbol {
	case "=":
		return condEQ, true
	case "<>":
		return condNE, true
	case ">":
		return condGT, true
	case "<=":
		return condLE, true
	case "<":
		return condLT, true
	case ">=":
		return condGE, true
	}
	return 0, false
}

// "The following table lists the comparison operation results of each instruction."
// TM=/DT= (s1)=(s2), <> (s1)≠(s2), > (s1)>(s2), <= (s1)≤(s2), < (s1)<(s2), >= (s1)≥(s2).
// holdsFor[c] has bit order+1 set (order -1, 0, +1: s1 below, equal to, above s2) for each order
// under which c holds.
var holdsFor = [...]uint8{
	condEQ: 0b010,
	condNE: 0b101,
	condGT: 0b100,
	condLE: 0b011,
	condLT: 0b001,
	condGE: 0b110,
}

// holds reports whether condition c holds for order (-1, 0 or +1): a load and a shift, with no
// branch on the condition, which changes from one vector to the next and so was mispredicted
// about as often as it was taken.
func holds(c condition, order int) bool {
	return holdsFor[c]>>uint(order+1)&1 != 0
}

// contact is a decoded comparison instruction.
type contact struct {
	form      form
	condition condition
	date      bool // FX5: DT (date) rather than TM (time); CP1E: always DT
}

// fx5Contact decodes an FX5 name: form, then TM or DT, then the condition (LDTM<=, ORDT<>).
func fx5Contact(instruction string) (contact, bool) {
	for f, name := range forms {
		rest, ok := strings.CutPrefix(instruction, name)
		if !ok || len(rest) < 2 || (rest[:2] != "TM" && rest[:2] != "DT") {
			continue
		}
		c, ok := conditionOf(rest[2:])
		return contact{form(f), c, rest[:2] == "DT"}, ok
	}
	return contact{}, false
}

// cp1eContact decodes a CP1E name: form, a space, the condition, then DT ("AND <=DT").
func cp1eContact(instruction string) (contact, bool) {
	name, symbol, _ := strings.Cut(instruction, " ")
	symbol, isDT := strings.CutSuffix(symbol, "DT")
	c, ok := conditionOf(symbol)
	for f := range forms {
		if forms[f] == name && isDT && ok {
			return contact{form(f), c, true}, true
		}
	}
	return contact{}, false
}
