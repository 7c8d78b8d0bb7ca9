package plcvec

import (
	"testing"
	"unsafe"
)

// TestVerdictStaysSmall: a pass over the golden set allocates one Verdict per vector, so each
// byte of it is some 2.8 kB more per pass to clear and to collect (BenchmarkJudgeGolden). The
// exported fields take 15 words on a 64-bit machine (ID, Family, Instruction, Status and Message
// two each, Problems three, Choices and Vector one each); what the text and the readings need
// beside them (the case, a failed answer's combinations) is one pointer more, not one each.
func TestVerdictStaysSmall(t *testing.T) {
	word := unsafe.Sizeof(uintptr(0))
	if got, want := unsafe.Sizeof(Verdict{}), 16*word; got > want {
		t.Errorf("a Verdict is %d bytes, more than %d (%d words): keep what the text needs behind one pointer", got, want, want/word)
	}
}
