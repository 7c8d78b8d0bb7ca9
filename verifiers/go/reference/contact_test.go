package reference

import (
	"testing"

	"github.com/plcvec/plcvec/verifiers/go/spec"
)

// TestInstructionMetadata: the form and condition the spec gives each instruction as values
// (spec.Instructions) are the ones the reference reads from its name, and TADDP alone executes
// on the rising edge.
func TestInstructionMetadata(t *testing.T) {
	if len(spec.Instructions) == 0 {
		t.Fatal("no instructions")
	}
	conditions := map[spec.Condition]condition{spec.ConditionEq: condEQ, spec.ConditionNe: condNE,
		spec.ConditionLt: condLT, spec.ConditionLe: condLE, spec.ConditionGt: condGT, spec.ConditionGe: condGE}
	for _, in := range spec.Instructions {
		c, fx5 := fx5Contact(in.Name)
		if !fx5 {
			c, _ = cp1eContact(in.Name)
		}
		isContact := in.Family != spec.FamilyFx5TimeAdd && in.Family != spec.FamilyFc6aHourMeter
		switch {
		case !isContact && (in.Form != "" || in.Condition != ""):
			t.Errorf("%s: not a contact, but form %q condition %q", in.Name, in.Form, in.Condition)
		case isContact && (forms[c.form] != string(in.Form) || conditions[in.Condition] != c.condition):
			t.Errorf("%s: the spec says %s %s, the name reads %s %d", in.Name, in.Form, in.Condition, forms[c.form], c.condition)
		}
		want := spec.ExecutionEveryScan
		if in.Name == spec.InstrTaddp {
			want = spec.ExecutionRisingEdge
		}
		if in.Execution != want {
			t.Errorf("%s: execution %s, want %s", in.Name, in.Execution, want)
		}
		if got, ok := spec.InstructionOf(in.Name); !ok || got != in {
			t.Errorf("InstructionOf(%q) = %+v, %v", in.Name, got, ok)
		}
	}
}
