package plcvec_test

import (
	"testing"

	"github.com/plcvec/plcvec/verifiers/go"
	"github.com/plcvec/plcvec/verifiers/go/reference"
)

// BenchmarkJudgeGoldenGuarded judges the golden set with the reference through the per-vector
// bound (PLCVEC_TIMEOUT) that plcvec.Run puts on each vector: isolated, Run's default, in a
// second run of this test binary on TestPlcvecReference (the same plan, checked by its digest),
// its verdicts read one by one under the bound; in-process (Options.InProcess), under the
// watchdog. One op is one pass. Starting the child (loading, preparing) is not timed; the
// subtests Run makes of the vectors are not made: what is timed is the bound's own cost beside
// reference/BenchmarkJudgeGolden, which judges the same vectors with no bound (verifiers/go/bench
// prints both).
func BenchmarkJudgeGoldenGuarded(b *testing.B) {
	ref, err := reference.New(nil)
	if err != nil {
		b.Fatal(err)
	}
	impl := ref.Implementation()
	// The plan TestPlcvecReference's plcvec.Run makes in the child (PLCVEC_VECTORS, if set, too).
	plan, err := plcvec.PrepareRun(impl, plcvec.Options{})
	if err != nil {
		b.Fatal(err)
	}
	for _, mode := range []string{"isolated", "in-process"} {
		b.Run(mode, func(b *testing.B) {
			b.ReportAllocs()
			b.ResetTimer()
			for i := 0; i < b.N; i++ {
				b.StopTimer()
				g, err := plcvec.StartGuarded(plan, impl, "TestPlcvecReference", mode == "isolated", plcvec.DefaultTimeout)
				if err != nil {
					b.Fatal(err)
				}
				b.StartTimer()
				notPassed := g.JudgeAll()
				b.StopTimer()
				g.Close()
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
