package reference_test

import (
	"os"
	"syscall"
	"testing"
	"time"

	"github.com/plcvec/plcvec/verifiers/go"
)

// BenchmarkJudgeGolden judges the whole golden set with the Go reference in process, after
// loading (loading and preparing the expectations are timed apart, as load_s and prepare_s):
// one op is one pass over every vector. verifiers/go/bench runs it and prints the figure
// beside Python's (python3 -m plcvec bench-native --lang go).
func BenchmarkJudgeGolden(b *testing.B) {
	start := time.Now()
	suite, err := benchSuite()
	if err != nil {
		b.Fatal(err)
	}
	load := time.Since(start)
	impl := mustNew(b, nil)
	start = time.Now()
	plan, err := plcvec.Prepare(impl, plcvec.Options{Suite: suite})
	if err != nil {
		b.Fatal(err)
	}
	prepare := time.Since(start)
	if report := plan.Verify(impl); !report.OK() || len(report.Failed()) > 0 {
		b.Fatalf("the reference does not pass the golden set: %v", report.Counts())
	}
	b.ReportAllocs()
	cpu0 := cpuSeconds()
	b.ResetTimer()
	for i := 0; i < b.N; i++ {
		plan.Verify(impl)
	}
	b.StopTimer()
	cpu := cpuSeconds() - cpu0
	n := float64(len(plan.Cases))
	b.ReportMetric(n, "vectors")
	b.ReportMetric(n*float64(b.N)/b.Elapsed().Seconds(), "vectors/s")
	// On a shared machine the wall clock counts the time other processes held the cores; the
	// process's own CPU time (user + system, the collector's threads included) does not.
	b.ReportMetric(n*float64(b.N)/cpu, "cpu-vectors/s")
	b.ReportMetric(load.Seconds(), "load_s")
	b.ReportMetric(prepare.Seconds(), "prepare_s")
}

// cpuSeconds is the CPU time this process has used, user and system.
func cpuSeconds() float64 {
	var u syscall.Rusage
	if err := syscall.Getrusage(syscall.RUSAGE_SELF, &u); err != nil {
		return 0
	}
	return float64(u.Utime.Sec+u.Stime.Sec) + float64(u.Utime.Usec+u.Stime.Usec)/1e6
}

// replay answers every vector with the answers recorded from the reference, so that
// BenchmarkHarnessOnly measures the runner alone (preparing nothing, judging everything).
type replay struct {
	hello   plcvec.Hello
	answers map[*plcvec.Request][]plcvec.StepResult
}

func (r replay) Hello() plcvec.Hello { return r.hello }

func (r replay) Run(req *plcvec.Request) ([]plcvec.StepResult, error) { return r.answers[req], nil }

// BenchmarkHarnessOnly judges the golden set with answers recorded from the reference: what the
// verifier itself costs, apart from the implementation's run time.
func BenchmarkHarnessOnly(b *testing.B) {
	impl := mustNew(b, nil)
	plan, err := plcvec.Prepare(impl, plcvec.Options{})
	if err != nil {
		b.Fatal(err)
	}
	rp := replay{hello: impl.Hello(), answers: map[*plcvec.Request][]plcvec.StepResult{}}
	for _, c := range plan.Cases {
		steps, err := impl.Run(c.Request)
		if err != nil {
			b.Fatal(err)
		}
		rp.answers[c.Request] = steps
	}
	if report := plan.Verify(rp); !report.OK() || len(report.Failed()) > 0 {
		b.Fatalf("the recorded answers do not pass: %v", report.Counts())
	}
	cpu0 := cpuSeconds()
	b.ResetTimer()
	for i := 0; i < b.N; i++ {
		plan.Verify(rp)
	}
	b.StopTimer()
	n := float64(len(plan.Cases))
	b.ReportMetric(n*float64(b.N)/b.Elapsed().Seconds(), "vectors/s")
	b.ReportMetric(n*float64(b.N)/(cpuSeconds()-cpu0), "cpu-vectors/s")
}

// benchSuite is the set a bench judges: the folder PLCVEC_VECTORS names, as plcvec.Run reads it
// (plcvec bench-native --same-vectors and --common-vectors give both revisions one set that way),
// or else the embedded golden set.
func benchSuite() (*plcvec.Suite, error) {
	if dir := os.Getenv("PLCVEC_VECTORS"); dir != "" {
		return plcvec.Load(dir)
	}
	return plcvec.Embedded()
}

// TestVerifyAllocatesOnlyItsReport: a pass over the golden set with every vector passing makes
// two allocations, the report and its verdicts, however many vectors it judges: a passing vector
// allocates nothing (its memory, results and CPU are reused from the vector before), so that the
// cost BenchmarkJudgeGolden measures is judging, not the collector's.
func TestVerifyAllocatesOnlyItsReport(t *testing.T) {
	impl := mustNew(t, nil)
	plan, err := plcvec.Prepare(impl, plcvec.Options{})
	if err != nil {
		t.Fatal(err)
	}
	if report := plan.Verify(impl); !report.OK() || len(report.Failed()) > 0 {
		t.Fatalf("the reference does not pass the golden set: %v", report.Counts())
	}
	if allocs := testing.AllocsPerRun(3, func() { plan.Verify(impl) }); allocs > 2 {
		t.Errorf("a pass over %d passing vectors made %.0f allocations; want 2 (the report and its verdicts)", len(plan.Cases), allocs)
	}
}
