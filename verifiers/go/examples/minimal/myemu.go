// Package myemu is the smallest emulator that gates on plcvec: it runs TADD (Mitsubishi FX5
// clock data addition) on plcvec's Memory through the "execute on my memory" helper.
package myemu

import (
	"github.com/plcvec/plcvec/verifiers/go"
	"github.com/plcvec/plcvec/verifiers/go/spec"
)

// Emulator is the whole emulator: it runs TADD and follows the default alternatives.
type Emulator struct{}

func (Emulator) Hello() plcvec.Hello {
	return plcvec.Hello{Name: "myemu", Version: "0.1", Instructions: []string{spec.InstrTadd}}
}

func (Emulator) NewCPU(req *plcvec.Request) (plcvec.CPU, error) {
	s1, _ := req.Operand("s1")
	s2, _ := req.Operand("s2")
	d, _ := req.Operand("d")
	return &cpu{s1: s1.Addr(), s2: s2.Addr(), d: d.Addr()}, nil
}

type cpu struct{ s1, s2, d plcvec.Addr }

var (
	carry1, zero, carry2 = plcvec.ParseAddr("SM700"), plcvec.ParseAddr("SM8020"), plcvec.ParseAddr("SM8022")
	errorCode            = []plcvec.Addr{plcvec.ParseAddr("SD0"), plcvec.ParseAddr("SD8067")}
)

func (c *cpu) Execute(mem *plcvec.Memory, step *plcvec.Inputs) (plcvec.Result, error) {
	if !step.EN {
		return plcvec.NoResult, nil
	}
	for _, a := range []plcvec.Addr{c.s1, c.s2, c.d} {
		if !mem.InRange(a, 3) { // 2820H: an operand runs past its device
			c.fail(mem, 0x2820)
			return plcvec.NoResult, nil
		}
	}
	a, b := mem.Words(c.s1, 3), mem.Words(c.s2, 3)
	for i, max := range []int16{23, 59, 59} {
		if int16(a[i]) < 0 || int16(a[i]) > max || int16(b[i]) < 0 || int16(b[i]) > max {
			c.fail(mem, 0x3405) // 3405H: a time out of range; nothing else is written
			return plcvec.NoResult, nil
		}
	}
	sum := int(a[0]+b[0])*3600 + int(a[1]+b[1])*60 + int(a[2]+b[2])
	over := sum >= 24*3600
	sum %= 24 * 3600
	mem.SetWords(c.d, uint16(sum/3600), uint16(sum/60%60), uint16(sum%60))
	mem.SetBit(carry1, over)
	mem.SetBit(carry2, over)
	mem.SetBit(zero, sum == 0)
	return plcvec.NoResult, nil
}

func (c *cpu) fail(mem *plcvec.Memory, code uint16) {
	for _, r := range errorCode {
		mem.SetWord(r, code)
	}
}
