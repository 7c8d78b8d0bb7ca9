package plcvec

import (
	"bufio"
	"fmt"
	"os"
	"time"
)

// Guarded judges the cases of a plan through the per-vector bound Run puts on each vector, for
// BenchmarkJudgeGoldenGuarded: as Run's second process does (serveCases, writing to a pipe and
// keeping its position in a mapped file) with this process reading them as Run's parent does
// (isolated.verdict), but with the serving side on a goroutine of this process, so that the
// clock starts when the judging does, not when a process started a moment before is found to
// be ready; or in this process under the watchdog (Options.InProcess).
type Guarded struct {
	plan   *Plan
	src    source
	served chan bool
	beat   *beat
}

// StartGuarded makes the source; Judge starts the judging.
func StartGuarded(plan *Plan, impl Implementation, piped bool, timeout time.Duration) (*Guarded, error) {
	g := &Guarded{plan: plan}
	if !piped {
		g.src = newInProcess(plan, impl, timeout)
		return g, g.src.start()
	}
	b, shared, err := newBeat()
	if err != nil {
		return nil, err
	}
	shared.Close() // one mapping serves both sides here
	g.beat = b
	r, w, err := os.Pipe()
	if err != nil {
		return nil, err
	}
	wanted := make([]bool, len(plan.Cases))
	for i := range wanted {
		wanted[i] = true
	}
	c := &child{lines: make(chan []string, 16), beat: g.beat, output: &tail{}, exited: make(chan struct{})}
	c.read(r)
	g.src = newIsolated(plan, c, wanted, timeout)
	g.served = make(chan bool, 1)
	go func() {
		bw := bufio.NewWriter(w)
		fmt.Fprintf(bw, "ready %s\n", planDigest(plan))
		ok := bw.Flush() == nil
		<-g.served // the go of JudgeAll
		ok = ok && serveCases(plan, impl, wanted, bw, g.beat)
		w.Close()
		g.served <- ok
	}()
	return g, g.src.start()
}

// JudgeAll judges every case and takes each one's verdict in turn, as Run does: the number that
// did not pass.
func (g *Guarded) JudgeAll() (notPassed int) {
	if g.served != nil {
		g.served <- true
	}
	var w wire
	for i := range g.plan.Cases {
		if g.src.verdict(i, &w); w.Status != StatusPass {
			notPassed++
		}
	}
	return notPassed
}

// Close ends the source; false if the serving side failed.
func (g *Guarded) Close() bool {
	if g.served == nil {
		g.src.close()
		return true
	}
	ok := <-g.served
	s := g.src.(*isolated)
	s.tick.Stop()
	g.beat.unmap()
	return ok
}

// PrepareRun is the plan Run makes of opts and the PLCVEC_* variables, as its child makes it.
func PrepareRun(impl Implementation, opts Options) (*Plan, error) {
	plan, _, err := prepareRun(impl, opts)
	return plan, err
}

// PlanHead is a plan of the first n cases of p, for the guard's cost per run (a pass over one
// vector) beside its cost per vector.
func PlanHead(p *Plan, n int) *Plan {
	return &Plan{Suite: p.Suite, Hello: p.Hello, Choices: p.Choices, Cases: p.Cases[:n], Known: p.Known}
}

// InVerifySyntax makes r's roll-up write a declaration as `plcvec verify` does (--choose ...),
// the form the shared cases' expected text holds.
func InVerifySyntax(r *Report) { r.syntax = declareVerify }

// Declaration is changes (interpretation -> alternative) as this runner's roll-up writes them.
func Declaration(changes map[string]string) string { return (&Report{}).declaration(changes) }
