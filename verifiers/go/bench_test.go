package plcvec_test

import (
	"testing"

	"github.com/plcvec/plcvec/verifiers/go"
	"github.com/plcvec/plcvec/verifiers/go/reference"
)

// BenchmarkJudgeGoldenGuarded judges the golden set with the reference through the per-vector
// bound (PLCVEC_TIMEOUT) that plcvec.Run puts on each vector. isolated: Run's default, the
// serving side of its second process (position in a mapped file, a line on a pipe for each
// vector that does not pass) read by its parent's side, with the serving side on a goroutine so
// that the clock starts with the judging (export_test.go); in-process: Options.InProcess, under
// the watchdog; unguarded: the same loop over the cases with no bound (Case.Judge), which the
// guarded figures are set against. One op is one pass. The subtests Run makes of the vectors are not made: what is
// timed is the bound's own cost beside reference/BenchmarkJudgeGolden, which judges the same
// vectors with no bound (verifiers/go/bench prints both).
func BenchmarkJudgeGoldenGuarded(b *testing.B) {
	ref, err := reference.New(nil)
	if err != nil {
		b.Fatal(err)
	}
	impl := ref.Implementation()
	// The plan plcvec.Run makes (PLCVEC_VECTORS, if set, too).
	plan, err := plcvec.PrepareRun(impl, plcvec.Options{})
	if err != nil {
		b.Fatal(err)
	}
	b.Run("unguarded", func(b *testing.B) {
		b.ReportAllocs()
		for i := 0; i < b.N; i++ {
			for _, c := range plan.Cases {
				if v := c.Judge(impl); v.Status != plcvec.StatusPass {
					b.Fatalf("%s: %s", v.ID, v.Status)
				}
			}
		}
		n := float64(len(plan.Cases))
		b.ReportMetric(n, "vectors")
		b.ReportMetric(n*float64(b.N)/b.Elapsed().Seconds(), "vectors/s")
	})
	for _, mode := range []string{"isolated", "in-process"} {
		b.Run(mode, func(b *testing.B) {
			b.ReportAllocs()
			b.ResetTimer()
			for i := 0; i < b.N; i++ {
				b.StopTimer()
				g, err := plcvec.StartGuarded(plan, impl, mode == "isolated", plcvec.DefaultTimeout)
				if err != nil {
					b.Fatal(err)
				}
				b.StartTimer()
				notPassed := g.JudgeAll()
				b.StopTimer()
				if !g.Close() {
					b.Fatal("the serving side could not write its lines")
				}
				if notPassed != 0 {
					b.Fatalf("%d of %d vectors did not pass", notPassed, len(plan.Cases))
				}
				b.StartTimer()
			}
			n := float64(len(plan.Cases))
			b.ReportMetric(n, "vectors")
			b.ReportMetric(n*float64(b.N)/b.Elapsed().Seconds(), "vectors/s")
		})
	}
}
