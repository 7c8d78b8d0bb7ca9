package plcvec_test

import (
	"sort"
	"testing"
	"time"

	"github.com/plcvec/plcvec/verifiers/go"
	"github.com/plcvec/plcvec/verifiers/go/reference"
)

// BenchmarkJudgeGoldenGuarded sets the per-vector bound (PLCVEC_TIMEOUT) that plcvec.Run puts on
// each vector against the same judging without it, paired: each op judges the golden set with
// the reference three ways, back to back, in an order that turns from one op to the next, and
// times each pass on its own:
//
//   - unguarded: the loop over the cases with no bound (Case.Judge);
//   - isolated: Run's default, the serving side of its second process (position in a mapped
//     file, a line on a pipe for each vector that does not pass) on a goroutine, so that the
//     clock starts with the judging (export_test.go), read by Run's parent side;
//   - in-process: Options.InProcess, under the watchdog.
//
// A machine shared with other work slows one pass and not the next, and a minute later all of
// them: separate benchmarks of each way, set side by side, measure that more than the bound. So
// the ratios are taken per op, of passes a millisecond apart: x-ratio is the median over the
// ops of (unguarded seconds / x seconds), x-ratio-fastest the fastest unguarded pass over the
// fastest x pass. A guarded pass also holds what a run pays once, not per vector (the isolated
// parent's last wake once the serving side is done, the watchdog's start): each op also times a
// guarded pass over one vector, x-fixed-µs is its median, and x-ratio-per-vector the median
// of (unguarded / (x − that op's one-vector pass)): the bound's cost per vector. The subtests Run
// makes of the vectors are not made: they are the test framework's cost, not the bound's.
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
	one := plcvec.PlanHead(plan, 1)
	unguarded := func() float64 {
		start := time.Now()
		for _, c := range plan.Cases {
			if v := c.Judge(impl); v.Status != plcvec.StatusPass {
				b.Fatalf("%s: %s", v.ID, v.Status)
			}
		}
		return time.Since(start).Seconds()
	}
	guarded := func(p *plcvec.Plan, isolated bool) float64 {
		g, err := plcvec.StartGuarded(p, impl, isolated, plcvec.DefaultTimeout)
		if err != nil {
			b.Fatal(err)
		}
		start := time.Now()
		notPassed := g.JudgeAll()
		seconds := time.Since(start).Seconds()
		if !g.Close() {
			b.Fatal("the serving side could not write its lines")
		}
		if notPassed != 0 {
			b.Fatalf("%d of %d vectors did not pass", notPassed, len(p.Cases))
		}
		return seconds
	}
	modes := []string{"unguarded", "isolated", "in-process"}
	pass := map[string]func() float64{
		"unguarded":  unguarded,
		"isolated":   func() float64 { return guarded(plan, true) },
		"in-process": func() float64 { return guarded(plan, false) },
	}
	seconds := map[string][]float64{}
	fixed := map[string][]float64{}
	ratio := map[string][]float64{}
	perVector := map[string][]float64{}
	b.ReportAllocs()
	for i := 0; i < b.N; i++ {
		took := map[string]float64{}
		for k := range modes {
			mode := modes[(i+k)%len(modes)]
			took[mode] = pass[mode]()
		}
		u := took["unguarded"]
		seconds["unguarded"] = append(seconds["unguarded"], u)
		for _, mode := range modes[1:] {
			f := guarded(one, mode == "isolated")
			seconds[mode] = append(seconds[mode], took[mode])
			fixed[mode] = append(fixed[mode], f)
			ratio[mode] = append(ratio[mode], u/took[mode])
			if took[mode] > f {
				perVector[mode] = append(perVector[mode], u/(took[mode]-f))
			}
		}
	}
	n := float64(len(plan.Cases))
	b.ReportMetric(n, "vectors")
	b.ReportMetric(n/median(seconds["unguarded"]), "unguarded-vectors/s")
	for _, mode := range modes[1:] {
		b.ReportMetric(n/median(seconds[mode]), mode+"-vectors/s")
		b.ReportMetric(median(ratio[mode]), mode+"-ratio")
		b.ReportMetric(fastest(seconds["unguarded"])/fastest(seconds[mode]), mode+"-ratio-fastest")
		b.ReportMetric(median(fixed[mode])*1e6, mode+"-fixed-µs")
		if len(perVector[mode]) > 0 {
			b.ReportMetric(median(perVector[mode]), mode+"-ratio-per-vector")
		}
	}
}

func median(xs []float64) float64 {
	s := append([]float64(nil), xs...)
	sort.Float64s(s)
	return s[len(s)/2]
}

func fastest(xs []float64) float64 {
	s := append([]float64(nil), xs...)
	sort.Float64s(s)
	return s[0]
}
