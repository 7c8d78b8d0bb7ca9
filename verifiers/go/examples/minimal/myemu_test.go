package myemu

import (
	"testing"

	"github.com/plcvec/plcvec/verifiers/go"
	"github.com/plcvec/plcvec/verifiers/go/spec"
)

// TestPlcvec runs every TADD vector as a subtest named by its id:
//
//	go test -run 'TestPlcvec/fx5-time-add/TADD/manual-example/' -v
func TestPlcvec(t *testing.T) {
	plcvec.Run(t, plcvec.Emulate(Emulator{}), plcvec.Options{
		Selection: plcvec.Selection{Families: []string{spec.FamilyFx5TimeAdd}},
	})
}
