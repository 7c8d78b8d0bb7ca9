package plcvec

import "time"

// Guarded judges the cases of a plan through the per-vector bound Run puts on each vector, for
// BenchmarkJudgeGoldenGuarded: in a second run of this test binary on the named test (Run's
// default), or in this process under the watchdog (Options.InProcess).
type Guarded struct {
	plan *Plan
	src  source
}

// StartGuarded starts the source Run would use (the child has loaded its plan and said ready).
func StartGuarded(plan *Plan, impl Implementation, test string, inChild bool, timeout time.Duration) (*Guarded, error) {
	g := &Guarded{plan: plan}
	if !inChild {
		g.src = newInProcess(plan, impl, timeout)
	} else {
		wanted := make([]bool, len(plan.Cases))
		for i := range wanted {
			wanted[i] = true
		}
		c, err := startChild(test, 1, wanted)
		if err != nil {
			return nil, err
		}
		g.src = newIsolated(plan, c, wanted, timeout)
	}
	if err := g.src.start(); err != nil {
		g.src.close()
		return nil, err
	}
	return g, nil
}

// JudgeAll takes each case's verdict in turn, as Run does: the number that did not pass.
func (g *Guarded) JudgeAll() (notPassed int) {
	for i := range g.plan.Cases {
		if w, _ := g.src.verdict(i); w.Status != StatusPass {
			notPassed++
		}
	}
	return notPassed
}

func (g *Guarded) Close() { g.src.close() }

// PrepareRun is the plan Run makes of opts and the PLCVEC_* variables, as its child makes it.
func PrepareRun(impl Implementation, opts Options) (*Plan, error) {
	plan, _, err := prepareRun(impl, opts)
	return plan, err
}
