package plcvec

import (
	"bufio"
	"encoding/hex"
	"encoding/json"
	"errors"
	"flag"
	"fmt"
	"hash/crc32"
	"io"
	"os"
	"os/exec"
	"regexp"
	"strconv"
	"strings"
	"sync"
	"sync/atomic"
	"testing"
	"time"
)

// Run judges the vectors in a second process, the same test binary started again on the same
// test: an implementation that ends the process (os.Exit, a crash in a goroutine of its own),
// or never returns, can then be reported against the vector it was running, and the run ends
// there. In one process none of that can be told: Go has no hook at exit, and a goroutine that
// never returns cannot be stopped. The child runs the test function up to the same Run call,
// judges the vectors it is given and writes one line per vector to a pipe (file descriptor 3);
// the parent reads them, one subtest per vector, and bounds each by PLCVEC_TIMEOUT.
//
// A system call per vector would cost more than judging it, so the child writes a line only for
// a vector that does not pass (at once, before the next starts), and keeps its position in
// memory it shares with the parent (a file both map, file descriptor 4; beat_unix.go): which
// vector it is judging, or has judged, and how many lines it has written by then. A vector the
// position has passed, with no line of its own once every line written by then has been read,
// passed. The parent watches the position for the bound, and when the child ends or is stopped
// it knows from it which vector was running.

const (
	envChild  = "PLCVEC_GO_CHILD"  // set in the child: "<test name>\n<ordinal of the Run call>"
	envWanted = "PLCVEC_GO_WANTED" // the cases the child judges: a bitmap in hex, or "all"
	// readyBound is how long the child may take to reach Run (load the suite, build the plan).
	readyBound = 120 * time.Second
	outputKept = 16 << 10 // bytes of the child's own output kept for a report
	// outputWait is how long the child's output is still read once it has exited.
	outputWait = 500 * time.Millisecond
	beatSize   = 16 // bytes of the shared position: the position, then the lines written
	// pollMin and pollMax bound how long the parent waits before it looks at the position again
	// when nothing has come on the pipe: the wait doubles each time, since the child does not
	// wait for the parent (a longer wait only delays the subtests' reports; a line, the end of
	// the pipe and the bound's tick each wake the parent at once).
	pollMin = 50 * time.Microsecond
	pollMax = 10 * time.Millisecond
)

// runCalls counts the Run calls of each test in this process, so that the child acts on the
// same call as its parent.
var runCalls sync.Map // test name -> *atomic.Int32

func nextRunCall(name string) int {
	n, _ := runCalls.LoadOrStore(name, new(atomic.Int32))
	return int(n.(*atomic.Int32).Add(1))
}

// wire is one verdict on the pipe: what the parent cannot work out itself.
type wire struct {
	Status   Status    `json:"s"`
	Problems []Problem `json:"p,omitempty"`
	Message  string    `json:"m,omitempty"`
	Passes   []bool    `json:"x,omitempty"` // a failed answer: whether it passes under each offer
}

// planDigest tells the parent the child built the same plan: the number of cases and a crc32 of
// their ids in order. Worked out once per plan: each side needs it, and the per-run setup should
// leave no garbage for the collector to chase while the vectors are judged.
func planDigest(p *Plan) string {
	if p.digest == "" {
		h := crc32.NewIEEE()
		for _, c := range p.Cases {
			io.WriteString(h, c.id)
			h.Write([]byte{0})
		}
		p.digest = fmt.Sprintf("%d:%08x", len(p.Cases), h.Sum32())
	}
	return p.digest
}

func encodeWanted(wanted []bool) string {
	all := true
	b := make([]byte, (len(wanted)+7)/8)
	for i, w := range wanted {
		if w {
			b[i/8] |= 1 << (i % 8)
		} else {
			all = false
		}
	}
	if all {
		return "all"
	}
	return hex.EncodeToString(b)
}

func decodeWanted(text string, n int) ([]bool, error) {
	wanted := make([]bool, n)
	if text == "all" {
		for i := range wanted {
			wanted[i] = true
		}
		return wanted, nil
	}
	b, err := hex.DecodeString(text)
	if err != nil || len(b) != (n+7)/8 {
		return nil, fmt.Errorf("$%s does not fit a plan of %d vectors", envWanted, n)
	}
	for i := range wanted {
		wanted[i] = b[i/8]&(1<<(i%8)) != 0
	}
	return wanted, nil
}

// childServe is Run in the child: judge the wanted cases, one line each, then end the process.
func childServe(plan *Plan, impl Implementation, setupErr error) {
	pipe := os.NewFile(3, "plcvec-pipe")
	w := bufio.NewWriter(pipe)
	if setupErr == nil {
		var b *beat
		if b, setupErr = mapBeat(os.NewFile(4, "plcvec-beat")); setupErr == nil {
			childJudge(plan, impl, w, b) // does not return
		}
	}
	fmt.Fprintf(w, "error %s\n", strconv.Quote(setupErr.Error()))
	w.Flush()
	os.Exit(0)
}

// childJudge judges the cases $PLCVEC_GO_WANTED names (serveCases); it ends the process.
func childJudge(plan *Plan, impl Implementation, w *bufio.Writer, b *beat) {
	wanted, err := decodeWanted(os.Getenv(envWanted), len(plan.Cases))
	if err != nil {
		fmt.Fprintf(w, "error %s\n", strconv.Quote(err.Error()))
		w.Flush()
		os.Exit(0)
	}
	fmt.Fprintf(w, "ready %s\n", planDigest(plan))
	if w.Flush() != nil || !serveCases(plan, impl, wanted, w, b) {
		os.Exit(1) // the parent has gone
	}
	os.Exit(0)
}

// serveCases judges the wanted cases, once the ready line is written, keeping its position in b
// and writing a line for each case that does not pass; false when the pipe is gone.
func serveCases(plan *Plan, impl Implementation, wanted []bool, w *bufio.Writer, b *beat) bool {
	written := uint64(1) // lines, the ready line included
	b.storeWritten(written)
	var v Verdict
	for i, c := range plan.Cases {
		if !wanted[i] {
			continue
		}
		b.store(2 * uint64(i+1))
		v = Verdict{}
		c.judge(impl, &v)
		if v.Status != StatusPass {
			// Written, and counted, before the position says judged.
			line, _ := json.Marshal(wire{v.Status, v.Problems, v.Message, v.passes()})
			fmt.Fprintf(w, "%d %s\n", i, line)
			if w.Flush() != nil {
				return false
			}
			written++
			b.storeWritten(written)
		}
		b.store(2*uint64(i+1) + 1)
	}
	return true
}

// child is the parent's view of the second process.
type child struct {
	cmd      *exec.Cmd
	lines    chan []string // the lines read at once; closed at the end of the pipe
	pending  []string      // lines received and not yet taken
	received uint64        // lines received
	beat     *beat         // the child's position (isolate.go's top)
	output   *tail
	exited   chan struct{}
	err      error // the process's end, once exited is closed
}

// tail keeps the last bytes written to it: the child's own output, for a report.
type tail struct {
	mu  sync.Mutex
	buf []byte
}

func (t *tail) Write(p []byte) (int, error) {
	t.mu.Lock()
	defer t.mu.Unlock()
	t.buf = append(t.buf, p...)
	if len(t.buf) > outputKept {
		t.buf = append(t.buf[:0], t.buf[len(t.buf)-outputKept:]...)
	}
	return len(p), nil
}

func (t *tail) String() string {
	t.mu.Lock()
	defer t.mu.Unlock()
	return strings.TrimSpace(string(t.buf))
}

// startChild starts the test binary again on the test name, for the Run call ordinal.
func startChild(name string, ordinal int, wanted []bool) (*child, error) {
	self, err := os.Executable()
	if err != nil {
		return nil, err
	}
	levels := strings.Split(name, "/")
	for i, l := range levels {
		levels[i] = "^" + regexp.QuoteMeta(l) + "$"
	}
	args := []string{"-test.run=" + strings.Join(levels, "/"), "-test.count=1"}
	if fl := flag.Lookup("test.timeout"); fl != nil {
		// The child lives no longer than the parent may.
		args = append(args, "-test.timeout="+fl.Value.String())
	}
	if testing.Short() {
		// A test may choose its vectors by testing.Short(): the child must choose the same.
		args = append(args, "-test.short")
	}
	b, shared, err := newBeat()
	if err != nil {
		return nil, err
	}
	defer shared.Close()
	r, w, err := os.Pipe()
	if err != nil {
		b.unmap()
		return nil, err
	}
	c := &child{cmd: exec.Command(self, args...), lines: make(chan []string, 16), beat: b, output: &tail{}, exited: make(chan struct{})}
	c.cmd.Env = append(os.Environ(), envChild+"="+name+"\n"+strconv.Itoa(ordinal), envWanted+"="+encodeWanted(wanted))
	c.cmd.Stdout, c.cmd.Stderr = c.output, c.output
	// A process the implementation started may keep the child's output open long after the child
	// ended: its end is the child's exit, not the end of that output.
	c.cmd.WaitDelay = outputWait
	c.cmd.ExtraFiles = []*os.File{w, shared}
	if err := c.cmd.Start(); err != nil {
		r.Close()
		w.Close()
		b.unmap()
		return nil, err
	}
	w.Close() // the child holds the write end now: the pipe ends when the child does
	c.read(r)
	go func() {
		c.err = c.cmd.Wait()
		close(c.exited)
	}()
	return c, nil
}

// newBeat maps a new shared position; its file is for the child to map (closed by the caller).
func newBeat() (*beat, *os.File, error) {
	shared, err := os.CreateTemp("", "plcvec-beat-")
	if err != nil {
		return nil, nil, err
	}
	// The file is only a name for the memory: gone from the folder at once, mapped by both.
	os.Remove(shared.Name())
	if err := shared.Truncate(beatSize); err != nil {
		shared.Close()
		return nil, nil, err
	}
	b, err := mapBeat(shared)
	if err != nil {
		shared.Close()
		return nil, nil, err
	}
	return b, shared, nil
}

// read passes the lines of r on to c.lines until r ends.
func (c *child) read(r *os.File) {
	go func() {
		// The lines that have arrived go on together: a handoff per batch, not per line.
		rd := bufio.NewReaderSize(r, 64<<10)
		var batch []string
		for {
			line, err := rd.ReadString('\n')
			if line = strings.TrimSuffix(line, "\n"); line != "" || err == nil {
				batch = append(batch, line)
			}
			if err != nil || rd.Buffered() == 0 || len(batch) >= 1024 {
				if len(batch) > 0 {
					c.lines <- batch
					batch = nil
				}
			}
			if err != nil {
				break
			}
		}
		close(c.lines)
		r.Close()
	}()
}

// errEnded is a child that ended before its answer; errHung one that gave none within the bound.
var (
	errEnded = errors.New("ended")
	errHung  = errors.New("hung")
)

// next is the child's next line within bound.
func (c *child) next(bound time.Duration, timer *time.Timer) (string, error) {
	if len(c.pending) == 0 {
		timer.Reset(bound)
		select {
		case batch, ok := <-c.lines:
			if !timer.Stop() {
				<-timer.C
			}
			if !ok {
				return "", errEnded
			}
			c.pending = batch
			c.received += uint64(len(batch))
		case <-timer.C:
			return "", errHung
		}
	}
	line := c.pending[0]
	c.pending = c.pending[1:]
	return line, nil
}

// watch is what the parent last saw of the child's position, and since when.
type watch struct {
	seen  uint64
	since time.Time
}

// drain takes the lines still on their way once the child has been stopped.
func (c *child) drain() {
	for {
		select {
		case batch, ok := <-c.lines:
			if !ok {
				return
			}
			c.pending = append(c.pending, batch...)
			c.received += uint64(len(batch))
		case <-time.After(10 * time.Second):
			return
		}
	}
}

// stop kills the child (a hung one) and waits for it.
func (c *child) stop() {
	c.cmd.Process.Kill()
	select {
	case <-c.exited:
	case <-time.After(10 * time.Second):
	}
}

// ending says how the child ended, with the end of its own output.
func (c *child) ending() string {
	select {
	case <-c.exited:
	case <-time.After(10 * time.Second):
		c.stop()
	}
	how := "ended"
	var exit *exec.ExitError
	if errors.As(c.err, &exit) {
		if exit.Exited() {
			how = fmt.Sprintf("ended the test process with exit status %d", exit.ExitCode())
		} else {
			how = "ended the test process: " + exit.String()
		}
	} else if c.err == nil || errors.Is(c.err, exec.ErrWaitDelay) {
		how = "ended the test process with exit status 0"
	}
	if out := c.output.String(); out != "" {
		lines := strings.Split(out, "\n")
		if len(lines) > 40 {
			lines = append([]string{"..."}, lines[len(lines)-40:]...)
		}
		how += "; the process's last output:\n" + strings.Join(lines, "\n")
	}
	return how
}

// parseVerdict reads one verdict line: "<index>" for a pass, "<index> <json>" otherwise.
func parseVerdict(line string) (int, wire, error) {
	head, rest, _ := strings.Cut(line, " ")
	i, err := strconv.Atoi(head)
	if err != nil {
		return 0, wire{}, fmt.Errorf("not a verdict: %.80q", line)
	}
	if rest == "" {
		return i, wire{Status: StatusPass}, nil
	}
	var w wire
	if err := json.Unmarshal([]byte(rest), &w); err != nil {
		return 0, wire{}, fmt.Errorf("not a verdict: %.80q", line)
	}
	return i, w, nil
}
