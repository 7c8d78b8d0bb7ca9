package faults_test

import (
	"os"
	"testing"

	"github.com/plcvec/plcvec/verifiers/go"
	"github.com/plcvec/plcvec/verifiers/go/internal/faults"
)

// TestFaults is plcvec.Run as an implementer's test calls it, on the implementation
// $PLCVEC_HOSTILE names (the reference by default); verifiers/go/faults-entry runs it.
func TestFaults(t *testing.T) {
	if os.Getenv("PLCVEC_HOSTILE") == "" {
		t.Skip("a row of the table of faults sets PLCVEC_HOSTILE (faults-entry); the reference's whole-set run is reference.TestReference")
	}
	impl, err := faults.New(os.Getenv("PLCVEC_HOSTILE"), os.Getenv("PLCVEC_HOSTILE_ON"), os.Getenv("PLCVEC_HOSTILE_CHOICE"))
	if err != nil {
		t.Fatal(err)
	}
	plcvec.Run(t, impl, plcvec.Options{})
}
