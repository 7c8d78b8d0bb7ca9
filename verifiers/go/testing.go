package plcvec

import (
	"fmt"
	"os"
	"runtime"
	"strconv"
	"strings"
	"sync/atomic"
	"testing"
	"time"
)

// Run verifies impl inside a Go test: one subtest per selected vector, named by the vector's
// id, so that `-json`, `-v`, `-failfast` and CI's test reports work per vector. It is meant for
// the implementer's own _test.go:
//
//	func TestPlcvec(t *testing.T) {
//		plcvec.Run(t, plcvec.Emulate(myEmulator{}), plcvec.Options{})
//	}
//
// A failing vector's subtest fails with the field-level diff (Verdict.Text); a vector the
// implementation skips, or a known failure of the known-failures file, is skipped with its
// reason. Run fails the test itself when the run cannot start (a bad selection, an unknown
// interpretation, a bad known-failures file or PLCVEC_* variable), when a listed known failure
// names no vector, when every vector that ran was skipped, and when `go test -run` leaves no
// vector to run: a gate never passes by accident.
//
// The PLCVEC_* variables (PLCVEC_ID, PLCVEC_FAMILY, PLCVEC_INSTRUCTION, PLCVEC_TAG,
// PLCVEC_INTERPRETATION, PLCVEC_SHARD, PLCVEC_VECTORS, PLCVEC_KNOWN_FAILURES,
// PLCVEC_WRITE_EXPECTATIONS, PLCVEC_TIMEOUT) narrow and steer the run as they do every plcvec
// runner's. PLCVEC_ID=<id> runs one vector by its exact id, with no quoting.
//
// The vectors are judged in a second run of the test binary (isolate.go), so that an
// implementation that hangs (PLCVEC_TIMEOUT, default 10 s per vector), exits or crashes is
// reported against the vector it was running, and the run ends there; Options.InProcess judges
// them in this process instead (for a debugger, or coverage of the implementation).
func Run(t *testing.T, impl Implementation, opts Options) *Report {
	t.Helper()
	ordinal := nextRunCall(t.Name())
	if spec, inChild := os.LookupEnv(envChild); inChild {
		if spec != t.Name()+"\n"+strconv.Itoa(ordinal) {
			return &Report{} // another Run call: its own child judges it
		}
		plan, _, err := prepareRun(impl, opts)
		childServe(plan, impl, err) // does not return
	}
	plan, env, err := prepareRun(impl, opts)
	if err != nil {
		t.Fatalf("plcvec: %v", err)
	}
	start := time.Now()
	report := &Report{Plan: plan, Verdicts: make([]Verdict, 0, len(plan.Cases))}
	wanted := wantedCases(t, plan)
	if wanted == nil {
		return report
	}
	src := openSource(t, plan, impl, opts, env, ordinal, wanted)
	defer src.close()
	judgeCases(t, report, src, wanted)
	finishRun(t, report, env, start)
	return report
}

// wantedCases are the cases the test runner's own filter (-run, -skip) lets through; nil, and the
// test failed, when it lets none through: nothing would be verified.
func wantedCases(t *testing.T, plan *Plan) []bool {
	t.Helper()
	filter, err := testFilter()
	if err != nil {
		t.Fatalf("plcvec: -run: %v", err)
	}
	wanted, count := make([]bool, len(plan.Cases)), 0
	prefix := t.Name() + "/"
	for i, c := range plan.Cases {
		if wanted[i] = filter.takes(prefix + SubtestName(c.id)); wanted[i] {
			count++
		}
	}
	if count == 0 {
		t.Errorf("plcvec: the test runner's filter (-run %q) matches none of the %d selected vectors: nothing was verified. "+
			"Choose vectors with PLCVEC_ID=<id or glob>[,...] (exact ids, no quoting) rather than -run", runFlag(), len(plan.Cases))
		return nil
	}
	return wanted
}

// openSource starts what judges the wanted cases: the second process (isolate.go), or this one.
func openSource(t *testing.T, plan *Plan, impl Implementation, opts Options, env environment, ordinal int, wanted []bool) source {
	t.Helper()
	var src source
	if opts.InProcess || !canIsolate() {
		src = newInProcess(plan, impl, env.timeout)
	} else {
		c, err := startChild(t.Name(), ordinal, wanted)
		if err != nil {
			t.Fatalf("plcvec: cannot start the test binary again to judge the vectors in it (%v); Options.InProcess judges them in this process", err)
		}
		src = newIsolated(plan, c, wanted, env.timeout)
	}
	if err := src.start(); err != nil {
		src.close()
		t.Fatalf("plcvec: %v", err)
	}
	return src
}

// judgeCases runs one subtest per case, each failing with its vector's block; once the run has
// ended early (a vector that hung or ended the process), the cases after it are not-run.
func judgeCases(t *testing.T, report *Report, src source, wanted []bool) {
	t.Helper()
	plan, ended := report.Plan, ""
	for i, c := range plan.Cases {
		if ended != "" {
			if wanted[i] {
				report.Verdicts = append(report.Verdicts, verdictOf(c, wire{Status: StatusNotRun, Message: "not run: " + ended}))
			}
			continue
		}
		t.Run(c.id, func(t *testing.T) {
			t.Helper() // the report names the vector; a line of this file would say nothing
			if !wanted[i] {
				t.Errorf("plcvec: -run %q selects this vector, which plcvec did not foresee; choose vectors with PLCVEC_ID instead", runFlag())
				return
			}
			var w wire
			end := src.verdict(i, &w)
			v := verdictOf(c, w)
			if plan.Known != nil {
				plan.Known.apply(&v)
			}
			report.Verdicts = append(report.Verdicts, v)
			if end {
				ended = "the run ended at " + c.id
			}
			switch v.Status {
			case StatusPass:
			case StatusSkip, StatusXFail:
				t.Skip(strings.TrimSuffix(v.Text(), "\n"))
			default:
				t.Error("\n" + strings.TrimSuffix(v.Text(), "\n"))
			}
		})
	}
	if ended != "" {
		t.Errorf("plcvec: %s (%d vectors after it not run)", ended, report.Counts()[StatusNotRun])
	}
}

// finishRun reports the known failures the suite has no vector for, writes the expectations file
// asked for, and ends the test with the run's closing text: the roll-up, the skips and the totals,
// each failure having been reported by its own subtest. A run that proves nothing (NOT PASSED, in
// the text) fails the test.
func finishRun(t *testing.T, report *Report, env environment, start time.Time) {
	t.Helper()
	plan := report.Plan
	if plan.Known != nil {
		for _, v := range plan.Known.unknownIDs(plan.Suite) {
			report.Verdicts = append(report.Verdicts, v)
			t.Error(strings.TrimSuffix(v.Text(), "\n"))
		}
	}
	if env.write != "" {
		n, err := report.WriteExpectations(env.write, "not yet triaged")
		if err != nil {
			t.Errorf("plcvec: $%s: %v", EnvWriteExpectations, err)
		} else {
			t.Logf("plcvec: %d known failures written to %s", n, env.write)
		}
	}
	report.Seconds = time.Since(start).Seconds()
	closing := "\n" + strings.TrimSuffix(report.Closing(), "\n")
	if len(report.Failed()) == 0 && report.shortfall() != "" {
		t.Error(closing)
	} else {
		t.Log(closing)
	}
}

// prepareRun is the plan of a Run: Options, narrowed and completed by the PLCVEC_* variables.
func prepareRun(impl Implementation, opts Options) (*Plan, environment, error) {
	env, err := readEnvironment()
	if err != nil {
		return nil, env, err
	}
	if opts.Expectations == "" {
		opts.Expectations = env.known
	}
	if env.narrowed {
		opts.env = &env
	}
	plan, err := Prepare(impl, opts)
	return plan, env, err
}

// verdictOf is the verdict of case c from what the judging said.
func verdictOf(c *Case, w wire) Verdict {
	v := Verdict{ID: c.id, Family: c.family, Instruction: c.instruction, Vector: c.Vector,
		Status: w.Status, Problems: w.Problems, Message: w.Message, about: c.about}
	if w.Status == StatusFail {
		v.about = &about{c: c, failed: true, passes: w.Passes}
	}
	if c.expect != nil {
		v.Choices = c.expect.choices
	}
	return v
}

// canIsolate reports whether the test binary can be started again with a pipe of its own.
func canIsolate() bool {
	switch runtime.GOOS {
	case "windows", "js", "wasip1", "plan9", "ios", "android":
		return false
	}
	return true
}

// source gives the verdict of each wanted case, in order; end says the run ends with it.
type source interface {
	start() error
	verdict(i int, w *wire) (end bool)
	close()
}

// isolated judges in the child process.
type isolated struct {
	plan    *Plan
	child   *child
	wanted  []bool
	timeout time.Duration
	last    int // the index of the last verdict read
	timer   *time.Timer
	tick    *time.Ticker
	watch   watch
	poll    *time.Timer
	wait    time.Duration // the next wait for the position to move: it only grows (pollMin to pollMax)
	known   int           // every wanted case up to this index is judged, its line (if any) read
	done    bool
	// Once the child has ended or been stopped: its last position, and what ended it.
	ended   bool
	pos     uint64
	endedBy error
}

func newIsolated(plan *Plan, c *child, wanted []bool, timeout time.Duration) *isolated {
	return &isolated{plan: plan, child: c, wanted: wanted, timeout: timeout, last: -1, known: -1,
		timer: time.NewTimer(time.Hour), poll: time.NewTimer(time.Hour), wait: pollMin}
}

func (s *isolated) start() error {
	line, err := s.child.next(readyBound, s.timer)
	switch {
	case err == errHung:
		s.child.stop()
		return fmt.Errorf("the test binary, started again to judge the vectors, did not reach plcvec.Run within %s", readyBound)
	case err != nil:
		return fmt.Errorf("the test binary, started again to judge the vectors, %s", s.child.ending())
	case strings.HasPrefix(line, "error "):
		msg, _ := strconv.Unquote(strings.TrimPrefix(line, "error "))
		return fmt.Errorf("%s (in the test binary started again to judge the vectors)", msg)
	case line != "ready "+planDigest(s.plan):
		return fmt.Errorf("the test binary, started again, prepared other vectors than this run (%s, not %s): does the test choose them at random?",
			strings.TrimPrefix(line, "ready "), planDigest(s.plan))
	}
	// The child's position, watched every eighth of the bound (10 ms to 1 s).
	tick := s.timeout / 8
	tick = max(10*time.Millisecond, min(time.Second, tick))
	s.tick = time.NewTicker(tick)
	s.watch = watch{seen: s.child.beat.load(), since: time.Now()}
	return nil
}

func (s *isolated) verdict(i int, out *wire) bool {
	for {
		if len(s.child.pending) > 0 {
			line := s.child.pending[0]
			j, w, perr := parseVerdict(line)
			if perr != nil || j <= s.last || j >= len(s.plan.Cases) {
				s.child.stop()
				s.done, s.ended, s.endedBy = true, true, errEnded
				s.child.pending = nil
				*out = wire{Status: StatusError, Message: fmt.Sprintf("the test binary judging the vectors wrote something else on its pipe: %.80q", line)}
				return true
			}
			if j > i {
				*out = wire{Status: StatusPass} // judged before j, with no line: passed
				return false
			}
			s.child.pending, s.last = s.child.pending[1:], j
			if j == i {
				*out = w
				return false
			}
			continue // a verdict of a case this process did not run (-failfast): read past it
		}
		if i <= s.known {
			*out = wire{Status: StatusPass}
			return false
		}
		if s.ended {
			return s.endVerdict(i, out)
		}
		// The position, then the lines written by then: if every one has been read, each case
		// the position has passed and no line named passed.
		pos := s.child.beat.load()
		judged := int(pos/2) - 1
		if pos%2 == 0 {
			judged--
		}
		if s.child.received >= s.child.beat.loadWritten() && judged > s.known {
			s.known = judged
			continue
		}
		s.poll.Reset(s.wait)
		select {
		case batch, ok := <-s.child.lines:
			if !s.poll.Stop() {
				<-s.poll.C
			}
			if !ok {
				s.end(errEnded)
				continue
			}
			s.child.pending = batch
			s.child.received += uint64(len(batch))
		case now := <-s.tick.C:
			if !s.poll.Stop() {
				<-s.poll.C
			}
			if pos := s.child.beat.load(); pos != s.watch.seen {
				s.watch.seen, s.watch.since = pos, now
			} else if now.Sub(s.watch.since) >= s.timeout {
				s.end(errHung)
			}
		case <-s.poll.C:
			s.wait = min(2*s.wait, pollMax)
		}
	}
}

// end stops the child (a hung one; an ended one is gone already) and takes the lines it wrote
// before it ended, then its last position.
func (s *isolated) end(err error) {
	s.ended, s.endedBy, s.done = true, err, true
	if err == errHung {
		s.child.stop()
	}
	s.child.drain()
	s.pos = s.child.beat.load()
}

// endVerdict is case i's verdict once the child has ended, every line it wrote read.
func (s *isolated) endVerdict(i int, out *wire) bool {
	// The child had judged case i, and it passed: it wrote no line for it.
	if judged := int(s.pos/2) - 1; i < judged || (i == judged && s.pos%2 == 1) {
		*out = wire{Status: StatusPass}
		return false
	}
	// The child was on the case its position names, or, between cases, on the next wanted one.
	at := int(s.pos/2) - 1
	if s.pos%2 == 1 || at < 0 {
		at++
		for at < len(s.wanted) && !s.wanted[at] {
			at++
		}
	}
	w := wire{Status: StatusError}
	if s.endedBy == errHung {
		w.Message = fmt.Sprintf("no answer within %s s (%s); the implementation was stopped and the run ends here",
			strconv.FormatFloat(s.timeout.Seconds(), 'g', -1, 64), EnvTimeout)
	} else {
		w.Message = "the implementation " + s.child.ending() + "\n(while running this vector; the run ends here)"
	}
	if at != i && at < len(s.plan.Cases) {
		w.Message = "while vector " + s.plan.Cases[at].id + " ran: " + w.Message
	}
	*out = w
	return true
}

func (s *isolated) close() {
	if !s.done {
		// Every verdict read: the child ends on its own (a bound, in case it does not).
		select {
		case <-s.child.exited:
		case <-time.After(10 * time.Second):
		}
	}
	s.child.stop()
	if s.tick != nil {
		s.tick.Stop()
	}
	s.child.beat.unmap()
}

// inProcess judges in this process, with a watchdog: a vector that holds the run longer than
// the bound is reported on stderr and the process ends (a goroutine cannot be stopped). An
// implementation that ends the process itself is named only by `go test -v`'s `=== RUN` line.
type inProcess struct {
	plan    *Plan
	impl    Implementation
	timeout time.Duration
	// position is the child's in isolate.go, kept here: 2*(i+1) while case i is judged,
	// 2*(i+1)+1 once it is, 0 before any. Two atomic stores per case and no clock read: each
	// case moves it to a value it never had, which is the progress the watchdog looks for.
	position atomic.Uint64
	stop     chan struct{}
}

func newInProcess(plan *Plan, impl Implementation, timeout time.Duration) *inProcess {
	return &inProcess{plan: plan, impl: impl, timeout: timeout, stop: make(chan struct{})}
}

func (s *inProcess) start() error {
	go s.watch()
	return nil
}

func (s *inProcess) watch() {
	tick := s.timeout / 8
	if tick < 10*time.Millisecond {
		tick = 10 * time.Millisecond
	}
	ticker := time.NewTicker(tick)
	defer ticker.Stop()
	seen, since := s.position.Load(), time.Now()
	for {
		select {
		case <-s.stop:
			return
		case now := <-ticker.C:
			if pos := s.position.Load(); pos != seen {
				seen, since = pos, now
				continue
			}
			// Unmoved for the bound, and on a case (even), not between two.
			if seen%2 == 0 && seen > 0 && now.Sub(since) >= s.timeout {
				fmt.Fprintf(os.Stderr, "plcvec: vector %s: no answer within %s s (%s); the run ends here\n",
					s.plan.Cases[seen/2-1].id, strconv.FormatFloat(s.timeout.Seconds(), 'g', -1, 64), EnvTimeout)
				os.Exit(1)
			}
		}
	}
}

func (s *inProcess) verdict(i int, out *wire) bool {
	s.position.Store(2 * uint64(i+1))
	var v Verdict
	s.plan.Cases[i].judge(s.impl, &v)
	s.position.Store(2*uint64(i+1) + 1)
	*out = wire{v.Status, v.Problems, v.Message, v.passes()}
	return false
}

func (s *inProcess) close() { close(s.stop) }
