package reference_test

import (
	"testing"

	"github.com/plcvec/plcvec/verifiers/go"
	"github.com/plcvec/plcvec/verifiers/go/reference"
	"github.com/plcvec/plcvec/verifiers/go/spec"
)

// run executes one step of instruction on a CPU of the reference following choices, over the
// given devices and operands, and returns the memory after it and the contact result.
func run(t *testing.T, choices map[string]string, family, instruction string, sizes map[string]int,
	devices map[string]plcvec.Value, operands map[string]plcvec.Operand, step plcvec.Inputs) (*plcvec.Memory, plcvec.Result) {
	t.Helper()
	r, err := reference.New(choices)
	if err != nil {
		t.Fatal(err)
	}
	req := plcvec.NewRequest("readings_test", family, instruction, sizes, devices, operands, nil, []plcvec.Inputs{step})
	cpu, err := r.NewCPU(req)
	if err != nil {
		t.Fatal(err)
	}
	mem := plcvec.NewMemory(req)
	result, err := cpu.Execute(mem, &req.Steps[0])
	if err != nil {
		t.Fatal(err)
	}
	return mem, result
}

func words(values map[string]uint16) map[string]plcvec.Value {
	out := map[string]plcvec.Value{}
	for name, w := range values {
		out[name] = plcvec.Word(w)
	}
	return out
}

// TestTADDOverlap: (s1) = 10:25:50 in D100-D102 plus (s2) = 1:50:30 in D200-D202, with (d) one
// word below (s1) (D99) or one above (D101), under each alternative of TADD-OVERLAP. The
// expected times are worked by hand from the alternatives' text:
//   - sources-first: 10:25:50 + 1:50:30 = 12:16:20 wherever (d) lies.
//   - second-first, (d) = D99: 50+30 = 80 -> D101 = 20, carry 1; D101 (now 20) + 50 + 1 = 71 ->
//     D100 = 11, carry 1; D100 (now 11) + 1 + 1 = 13 -> D99 = 13. The words read sum to
//     12*3600 + 70*60 + 80 = 47480 s = 13:11:20. (d) = D101 writes each word after it is read:
//     12:16:20.
//   - hour-first, (d) = D101: 10+1 = 11 -> D101; D101 (now 11) + 50 = 61 -> D102; D102 (now 61) +
//     30 = 91 -> D103; 11*3600 + 61*60 + 91 = 43351 s = 12:02:31. (d) = D99 writes each word after
//     it is read: 12:16:20.
func TestTADDOverlap(t *testing.T) {
	type hms [3]uint16
	for _, c := range []struct {
		alternative, d string
		want           hms
	}{
		{spec.TaddOverlapSourcesFirst, "D99", hms{12, 16, 20}},
		{spec.TaddOverlapSourcesFirst, "D101", hms{12, 16, 20}},
		{spec.TaddOverlapSecondFirst, "D99", hms{13, 11, 20}},
		{spec.TaddOverlapSecondFirst, "D101", hms{12, 16, 20}},
		{spec.TaddOverlapHourFirst, "D99", hms{12, 16, 20}},
		{spec.TaddOverlapHourFirst, "D101", hms{12, 2, 31}},
	} {
		devices := words(map[string]uint16{"D99": 0xFFFF, "D100": 10, "D101": 25, "D102": 50, "D103": 0xFFFF,
			"D200": 1, "D201": 50, "D202": 30})
		mem, _ := run(t, map[string]string{spec.InterpTaddOverlap: c.alternative}, spec.FamilyFx5TimeAdd,
			spec.InstrTadd, map[string]int{"D": 8000}, devices,
			map[string]plcvec.Operand{"s1": {Device: "D100"}, "s2": {Device: "D200"}, "d": {Device: c.d}},
			plcvec.Inputs{EN: true})
		var got hms
		mem.ReadWords(plcvec.ParseAddr(c.d), got[:])
		if got != c.want {
			t.Errorf("TADD-OVERLAP=%s, (d) = %s: %d:%d:%d, want %d:%d:%d", c.alternative, c.d,
				got[0], got[1], got[2], c.want[0], c.want[1], c.want[2])
		}
		for _, f := range []string{"SM700", "SM8022", "SM8020"} {
			if mem.Bit(plcvec.ParseAddr(f)) {
				t.Errorf("TADD-OVERLAP=%s, (d) = %s: %s on, the sum is neither past 24:00:00 nor 0", c.alternative, c.d, f)
			}
		}
	}
}

// TestFX5InvalidS3DeviceRange: LDTM= with (s1) at D7998 of 8000 D words ((s1)+2 past the range)
// and (s2) in range. "If the device areas specified by (s1) to (s1)+2 ... exceed the corresponding
// device range, SM709 turns on ... and the operation result will be non-continuity": the contact
// is off under both alternatives; an (s3) that compares nothing (a bit of 3 to 14 set, or none of
// bits 0 to 2) leaves SM709 off under s3-first only, and an (s3) that selects fields turns it on
// under both.
func TestFX5InvalidS3DeviceRange(t *testing.T) {
	for _, c := range []struct {
		alternative string
		s3          int
		sm709       bool
	}{
		{spec.Fx5InvalidS3DeviceRangeDeviceRangeFirst, 0x0008, true},
		{spec.Fx5InvalidS3DeviceRangeDeviceRangeFirst, 0x0000, true},
		{spec.Fx5InvalidS3DeviceRangeDeviceRangeFirst, 0x0007, true},
		{spec.Fx5InvalidS3DeviceRangeS3First, 0x0008, false},
		{spec.Fx5InvalidS3DeviceRangeS3First, 0x0000, false},
		{spec.Fx5InvalidS3DeviceRangeS3First, 0x8000, false},
		{spec.Fx5InvalidS3DeviceRangeS3First, 0x0007, true},
		{spec.Fx5InvalidS3DeviceRangeS3First, 0x8001, true},
	} {
		devices := words(map[string]uint16{"D7998": 12, "D7999": 0, "D100": 12, "D101": 0, "D102": 0})
		devices["SM709"] = plcvec.Bit(false)
		s3 := c.s3
		mem, result := run(t, map[string]string{spec.InterpFx5InvalidS3DeviceRange: c.alternative},
			spec.FamilyFx5TimeCompare, spec.InstrLdtmEq, map[string]int{"D": 8000}, devices,
			map[string]plcvec.Operand{"s1": {Device: "D7998"}, "s2": {Device: "D100"}, "s3": {Constant: &s3}},
			plcvec.Inputs{Clock: map[string]int{"hour": 12, "minute": 0, "second": 0}})
		if result != plcvec.ResultOff {
			t.Errorf("FX5-INVALID-S3-DEVICE-RANGE=%s, (s3) = %04XH: result %v, want non-continuity", c.alternative, c.s3, result)
		}
		if got := mem.Bit(plcvec.ParseAddr("SM709")); got != c.sm709 {
			t.Errorf("FX5-INVALID-S3-DEVICE-RANGE=%s, (s3) = %04XH: SM709 %v, want %v", c.alternative, c.s3, got, c.sm709)
		}
	}
}

// TestCP1EPastAreaEnd: LD =DT, AND =DT and OR =DT with S1 or S2 at D8190 or D8191 of 8192 D words,
// the other operand equal to it, and P_EQ on before the step. error: P_ER on and an OFF execution
// condition, P_EQ kept (CP1E-ERROR-FLAGS=kept). program-error: nothing written (P_ER stays off,
// P_EQ on) and an OFF execution condition. Under both, OR with the preceding logic on stays on,
// AND with it on is off.
func TestCP1EPastAreaEnd(t *testing.T) {
	for _, alternative := range []string{spec.Cp1ePastAreaEndError, spec.Cp1ePastAreaEndProgramError} {
		for _, past := range []string{"S1", "S2"} {
			for _, at := range []string{"D8190", "D8191"} {
				for instruction, want := range map[string]plcvec.Result{spec.InstrLdEqDt: plcvec.ResultOff,
					spec.InstrAndEqDt: plcvec.ResultOff, spec.InstrOrEqDt: plcvec.ResultOn} {
					operands := map[string]plcvec.Operand{"S1": {Device: "D100"}, "S2": {Device: "D100"}, "C": {Device: "D300"}}
					operands[past] = plcvec.Operand{Device: at}
					devices := words(map[string]uint16{"D100": 0x1000, "D101": 0x0112, "D102": 0x2601,
						"D8190": 0x1000, "D8191": 0x0112, "D300": 0})
					devices["P_ER"], devices["P_EQ"] = plcvec.Bit(false), plcvec.Bit(true)
					mem, result := run(t, map[string]string{spec.InterpCp1ePastAreaEnd: alternative},
						spec.FamilyCp1eTimeCompare, instruction, map[string]int{"D": 8192, "A": 754}, devices,
						operands, plcvec.Inputs{RLOIn: true})
					what := alternative + ", " + instruction + ", " + past + " = " + at
					if result != want {
						t.Errorf("%s: result %v, want %v", what, result, want)
					}
					if got := mem.Bit(plcvec.ParseAddr("P_ER")); got != (alternative == spec.Cp1ePastAreaEndError) {
						t.Errorf("%s: P_ER %v", what, got)
					}
					if !mem.Bit(plcvec.ParseAddr("P_EQ")) {
						t.Errorf("%s: P_EQ turned off, although nothing was compared", what)
					}
				}
			}
		}
	}
}
