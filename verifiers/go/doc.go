// Package plcvec runs the plcvec conformance vectors for PLC clock and calendar instructions
// against an implementation, inside `go test`: one subtest per vector, named by its id.
//
//	func TestPlcvec(t *testing.T) {
//		plcvec.Run(t, plcvec.Emulate(myEmulator{}), plcvec.Options{})
//	}
//
// The golden vectors are embedded (the compact copy `plcvec export --lang go` writes into
// vectors/); $PLCVEC_VECTORS names another copy. An implementation is judged as
// verifiers/CONTRACT.md says: after every step, the contact result and every device the
// vector lists, with its JSON type (a bit is never the word 1), devices that must stay unchanged,
// and no write outside the vector, under the interpretation alternatives it declares.
//
// Implementation is the contract's level; Emulator, through Emulate, is the "execute this
// instruction on my memory" level. Verify and Prepare run the suite outside a test. The spec's
// names are constants in package github.com/plcvec/plcvec/verifiers/go/spec.
package plcvec
