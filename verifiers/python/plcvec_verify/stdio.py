"""Driving an adapter process over JSON lines on its stdin/stdout (PROTOCOL.md).

One long-lived process: a handshake, then batches of vectors, each answered by one result line
per vector, matched by id. Two batches are kept in flight so the process never waits for the
runner between batches. One single-threaded loop on non-blocking pipes does the writing, the
reading of stdout and stderr, and the timeouts, so a stuck adapter can never block the runner
(a blocking write into a full pipe while the adapter blocks writing to us would deadlock).

Faults (the process crashing or exiting, closing its stdout, hanging past the per-batch timeout,
a line that is not JSON or that never ends, an id that was not sent or answered twice) are blamed on the vector being run: the first one
sent and not yet answered, which is exact for adapters that answer in order and flush each line
(serve.py does). The process is then killed and restarted, and the rest of the batch is sent again,
so one crash costs one vector, not the run. A result of the wrong shape is blamed on its own id and
needs no restart. Anything written to stderr is kept as a note on the vector being run.

Every wait here has a bound: the per-batch timeout while vectors are out, EXIT_GRACE_S after
`bye`, KILL_WAIT_S for a killed process to be reaped. The adapter runs in its own process group
(its own session), so killing the group ends the children it started too; every adapter process
still running when the runner's interpreter exits is killed then (atexit), and `plcvec verify`
turns SIGTERM and SIGINT into a normal exit through that path (command.py).
"""
from __future__ import annotations

import atexit
import json
import os
import selectors
import shlex
import signal
import subprocess
import time
from collections import deque

from .adapters import AdapterAbort, Answer, check_hello
from .errors import VerifyError
from .protocol import encode
from .stopping import deferred

READ_CHUNK = 1 << 16
STDERR_KEEP = 2000          # characters of stderr kept per note
EXIT_GRACE_S = 2.0          # after `bye`, how long the adapter has to exit before it is killed
EOF_GRACE_S = 1.0           # after its stdout closes, how long the adapter has to exit before it is killed
KILL_WAIT_S = 5.0           # after SIGKILL, how long to wait for the process to be reaped
MAX_LINE_BYTES = 64 << 20   # a stdout line longer than this is a fault, not something to keep buffering
STDERR_BUF_MAX = 1 << 20    # stderr kept while waiting for a newline (notes keep STDERR_KEEP of it)

# Adapter processes started and not yet ended, for the exit path (atexit, signals). Strong
# references: an adapter object dropped without close() still has its process ended at exit.
_LIVE: "set[StdioAdapter]" = set()


def end_all() -> None:
    """Kill every adapter process group this interpreter started and has not ended.

    Called at interpreter exit and when `plcvec verify` is stopped by a signal: an adapter runs in
    its own session, so a Ctrl-C in the terminal or a CI job's SIGTERM to the runner's process
    group does not reach it, and nothing else would end it.
    """
    for adapter in list(_LIVE):
        adapter.terminate()


atexit.register(end_all)


class _Fault(Exception):
    """The stream is broken: kill, blame the vector being run, restart."""


class _InFlight:
    """The vectors sent to the adapter process and not yet answered, by batch, and the deadline of the
    oldest batch: each batch has the whole timeout from when the one before it is answered."""

    def __init__(self, adapter: "StdioAdapter", wire: dict):
        self.adapter, self.wire = adapter, wire
        self.sent: dict[str, dict] = {}   # id -> request, sent and not answered (in sending order)
        self.batches: deque = deque()     # [batch number, unanswered count] in flight, oldest first
        self.batch_of: dict[str, list] = {}   # id -> its entry in `batches`
        self.batch_no = 0
        self.deadline = None

    def send(self, chunk: list) -> None:
        entry = [self.batch_no, len(chunk)]
        self.batches.append(entry)
        sent, batch_of, wire = self.sent, self.batch_of, self.wire
        lines = []
        for r in chunk:
            vid = r["id"]
            sent[vid] = r
            batch_of[vid] = entry
            line = wire.get(vid)
            if line is None:
                line = wire[vid] = encode(r)[:-1]
            lines.append(line)
        self.adapter._queue(b'{"type":"run","batch":%d,"vectors":[' % self.batch_no + b",".join(lines) + b"]}\n")
        self.batch_no += 1

    def answered(self, vid: str) -> None:
        del self.sent[vid]
        self.batch_of.pop(vid)[1] -= 1
        while self.batches and self.batches[0][1] == 0:
            self.batches.popleft()
            self.deadline = time.monotonic() + self.adapter.timeout

    def clear(self) -> list:
        """Forget everything in flight (the process is being killed); return what was unanswered."""
        unanswered = list(self.sent.values())
        self.sent.clear()
        self.batches.clear()
        self.batch_of.clear()
        return unanswered


class StdioAdapter:
    def __init__(self, command, *, timeout: float = 30.0, batch_size: int = 256, max_restarts: int = 10,
                 cwd=None, env=None):
        self.argv = shlex.split(command) if isinstance(command, str) else list(command)
        if not self.argv:
            raise VerifyError("--adapter: empty command")
        self.label = self.argv[0].rsplit("/", 1)[-1]
        self.command = command if isinstance(command, str) else shlex.join(command)
        self.timeout = timeout
        self.batch_size = max(1, batch_size)
        self.max_restarts = max_restarts
        self.cwd, self.env = cwd, env
        self.notes: list[tuple[str | None, str]] = []
        self.restarts = 0
        self.proc = None
        self._hello_request = None
        self._stderr_buf = b""
        self._answered: set[str] = set()
        self._last_answered = None

    # -- process life ---------------------------------------------------------------------------

    def _spawn(self):
        with deferred():   # started and recorded in _LIVE, or not started: never in between
            try:
                self.proc = subprocess.Popen(self.argv, stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                                             stderr=subprocess.PIPE, bufsize=0, cwd=self.cwd, env=self.env,
                                             start_new_session=True)
            except OSError as exc:
                raise AdapterAbort(f"--adapter {self.command}: cannot start it: {exc.strerror or exc}")
            _LIVE.add(self)
        for f in (self.proc.stdin, self.proc.stdout, self.proc.stderr):
            os.set_blocking(f.fileno(), False)
        self._out = b""
        self._in = b""
        self._stderr_buf = b""
        self._sel = selectors.DefaultSelector()
        self._sel.register(self.proc.stdout, selectors.EVENT_READ, "out")
        self._sel.register(self.proc.stderr, selectors.EVENT_READ, "err")
        self._writing = False
        self._stdout_open = True

    def _kill(self, current=None):
        with deferred():   # a stop signal waits until the process is killed and reaped
            self._kill_now(current)

    def _kill_now(self, current):
        if self.proc is None:
            return
        # The whole group: the adapter and any children it started (a shell wrapper, an emulator).
        try:
            os.killpg(self.proc.pid, signal.SIGKILL)
        except (ProcessLookupError, PermissionError):
            pass
        try:
            self.proc.wait(timeout=KILL_WAIT_S)
        except subprocess.TimeoutExpired:   # stuck in the kernel; nothing more can be done from here
            self.notes.append((None, f"adapter process {self.proc.pid} did not end within "
                                     f"{KILL_WAIT_S:g} s of SIGKILL"))
        _LIVE.discard(self)
        self._drain_stderr_now()
        self._settle_stderr(current, everything=True)
        self._sel.close()
        for f in (self.proc.stdin, self.proc.stdout, self.proc.stderr):
            try:
                f.close()
            except OSError:
                pass
        self.proc = None

    def terminate(self):
        """End the adapter now, without `bye` (the runner is being stopped)."""
        self._kill()

    def hello(self, request: dict) -> dict:
        # A process still running from an earlier run with the same handshake is reused (the
        # benchmark and repeated runs in one session pay for the start-up once).
        if self.proc is not None and request == self._hello_request:
            return self._hello_answer
        self._kill()
        self._hello_request = request
        self._spawn()
        self._hello_answer = self._handshake()
        return self._hello_answer

    def _handshake(self):
        self._queue(encode(self._hello_request))
        deadline = time.monotonic() + self.timeout
        while True:
            try:
                lines = self._pump(deadline)
            except _Fault as fault:
                self._kill()
                raise AdapterAbort(f"--adapter {self.command}: no handshake: {fault}{self._stderr_hint(None)}")
            if lines:
                try:
                    answer = json.loads(lines[0])
                    if len(lines) > 1:
                        raise AdapterAbort(f"--adapter {self.command}: wrote {len(lines)} lines for the handshake, "
                                           f"expected one; the second: {_clip(lines[1])}")
                    hello = check_hello(answer, f"--adapter {self.command}")
                    self._settle_stderr(None)          # start-up chatter belongs to no vector
                    return hello
                except ValueError:
                    self._kill()
                    raise AdapterAbort(f"--adapter {self.command}: the handshake answer is not JSON: {_clip(lines[0])}")
                except AdapterAbort:
                    self._kill()
                    raise

    def close(self):
        if self.proc is None:
            return
        try:
            self._queue(encode({"type": "bye"}))
            deadline = time.monotonic() + EXIT_GRACE_S
            while self._out and time.monotonic() < deadline:
                self._pump(deadline)
            self.proc.stdin.close()
            while self._stdout_open and time.monotonic() < deadline:
                lines = self._pump(deadline)
                if lines:
                    self.notes.append((None, f"adapter wrote after the run: {_clip(lines[0])}"))
        except (_Fault, OSError):
            pass
        try:
            status = self.proc.wait(timeout=max(0.0, deadline - time.monotonic()))
            if status != 0:
                self.notes.append((None, f"adapter exited with status {status} after `bye`"))
        except subprocess.TimeoutExpired:
            self.notes.append((None, f"adapter did not exit within {EXIT_GRACE_S:.0f} s of `bye`; killed"))
        self._kill()

    # -- the loop -------------------------------------------------------------------------------

    def _queue(self, data: bytes):
        self._out += data
        if not self._writing:
            try:
                self._sel.register(self.proc.stdin, selectors.EVENT_WRITE, "in")
                self._writing = True
            except (ValueError, OSError):
                pass

    def _pump(self, deadline: float) -> list[bytes]:
        """Write what is queued and read what is there; return complete stdout lines.

        Raises _Fault when the process is gone or the deadline passes with no line read.
        """
        while True:
            wait = deadline - time.monotonic()
            if wait <= 0:
                raise _Fault(f"no answer within {self.timeout:g} s (timeout); the adapter was killed")
            lines = []
            for key, _ in self._sel.select(wait):
                if key.data == "in":
                    try:
                        n = os.write(key.fileobj.fileno(), self._out[:READ_CHUNK])
                    except BrokenPipeError:
                        self._sel.unregister(key.fileobj)
                        self._writing = False
                        self._out = b""
                        continue
                    except BlockingIOError:
                        continue
                    self._out = self._out[n:]
                    if not self._out:
                        self._sel.unregister(key.fileobj)
                        self._writing = False
                elif key.data == "err":
                    chunk = os.read(key.fileobj.fileno(), READ_CHUNK)
                    if not chunk:
                        self._sel.unregister(key.fileobj)
                    else:
                        self._stderr_buf += chunk
                        if len(self._stderr_buf) > STDERR_BUF_MAX and b"\n" not in chunk:
                            self._stderr_buf = self._stderr_buf[:STDERR_KEEP] + b"...\n"
                else:
                    chunk = os.read(key.fileobj.fileno(), READ_CHUNK)
                    if not chunk:
                        self._sel.unregister(key.fileobj)
                        self._stdout_open = False
                        raise _Fault(self._stdout_closed_text(deadline))
                    self._in += chunk
                    if b"\n" in chunk:
                        *lines, self._in = self._in.split(b"\n")
                    if len(self._in) > MAX_LINE_BYTES:
                        raise _Fault(f"the adapter wrote a line longer than {MAX_LINE_BYTES >> 20} MiB "
                                     f"without a newline: {_clip(self._in)}")
            lines = [line for line in lines if line.strip()]
            if lines:
                return lines

    def _stdout_closed_text(self, deadline: float) -> str:
        """Why stdout ended: the process exited (how), or it closed stdout and is still running.

        A process that exits closes its stdout a moment before it can be reaped, so it gets a
        short grace, never past the batch's deadline; one still running after that will not
        answer again and is killed like a crash.
        """
        try:
            status = self.proc.wait(timeout=max(0.0, min(EOF_GRACE_S, deadline - time.monotonic())))
        except subprocess.TimeoutExpired:
            return "the adapter closed its stdout but kept running; it was killed"
        return _exit_text(status)

    def _settle_stderr(self, current, everything=False):
        """Note the complete stderr lines read so far against `current`.

        Called after the stdout lines of the same read are processed: an adapter writes a
        vector's stderr after the previous vector's answer, so the vector running then is the
        first one still unanswered once those answers are counted.
        """
        if everything:
            text, self._stderr_buf = self._stderr_buf, b""
        elif b"\n" in self._stderr_buf:
            text, _, self._stderr_buf = self._stderr_buf.rpartition(b"\n")
        else:
            return
        self._note_stderr(text, current)

    def _drain_stderr_now(self):
        # Non-blocking reads until the pipe is empty; bounded in size, since a child that escaped
        # the process group could keep writing.
        try:
            while len(self._stderr_buf) < STDERR_BUF_MAX:
                chunk = os.read(self.proc.stderr.fileno(), READ_CHUNK)
                if not chunk:
                    break
                self._stderr_buf += chunk
        except (BlockingIOError, OSError, ValueError):
            pass

    def _note_stderr(self, data: bytes, current):
        text = data.decode("utf-8", "replace").strip()
        if not text:
            return
        if self.notes and self.notes[-1][0] == current and self.notes[-1][1].startswith("stderr"):
            vid, old = self.notes[-1]
            self.notes[-1] = (vid, (old + "\n" + text)[:STDERR_KEEP])
        else:
            # stderr and stdout are separate pipes, so which vector was running when a line was
            # written is known only to within the window between two answers; say so.
            window = f" (written after {self._last_answered} was answered)" if self._last_answered else ""
            self.notes.append((current, f"stderr{window}: " + text[:STDERR_KEEP]))

    def _stderr_hint(self, vid):
        texts = [t for v, t in self.notes if v == vid and t.startswith("stderr")]
        return f"; adapter {texts[-1]}" if texts else ""

    # -- running vectors ------------------------------------------------------------------------

    def answers(self, requests, wire: dict | None = None):
        """Yield an Answer for every request, in the order answers arrive.

        `wire` caches each request's encoded line by id, for runs that repeat (runner.Plan).
        """
        if self.proc is None:
            if self._hello_request is None:
                raise VerifyError("StdioAdapter.answers() before hello()")
            # A fault on the last vector of an earlier call left the process stopped.
            self._restart()
        pending = deque(requests)         # not yet sent
        isolate = deque()                 # to be re-run one at a time, after a fault
        flight = _InFlight(self, {} if wire is None else wire)
        while pending or flight.sent or isolate:
            self._send_next(flight, pending, isolate)
            current = next(iter(flight.sent))
            try:
                yield from self._read_answers(flight)
            except _Fault as fault:
                yield from self._after_fault(fault, flight, current, isolate)
                if pending or isolate:
                    self._restart()

    def _send_next(self, flight: "_InFlight", pending: deque, isolate: deque) -> None:
        """Keep two batches in flight, so the process never waits for the runner between batches; after a
        fault with several vectors unanswered, one vector at a time instead (`isolate`): an adapter that
        buffers its output (most do) may have died on any of them, and this finds which."""
        if isolate:
            if not flight.sent:
                flight.send([isolate.popleft()])
                flight.deadline = time.monotonic() + self.timeout
            return
        while pending and len(flight.batches) < 2:
            flight.send([pending.popleft() for _ in range(min(self.batch_size, len(pending)))])
            if len(flight.batches) == 1:
                flight.deadline = time.monotonic() + self.timeout

    def _read_answers(self, flight: "_InFlight"):
        """Yield an Answer for each result line read before the oldest batch's deadline; raise _Fault
        when the stream is broken (a line that answers nothing sent is one)."""
        for msg in self._messages(self._pump(flight.deadline)):
            vid = msg.get("id") if isinstance(msg, dict) else None
            if isinstance(msg, dict) and msg.get("type") == "fatal":
                # It says it cannot go on (PROTOCOL.md): restarting would only hear it again.
                blamed = next(iter(flight.sent))
                self._kill(blamed)
                raise AdapterAbort(f"--adapter {self.command}: the adapter gave up while running "
                                   f"{blamed}: {msg.get('message')}")
            if vid not in flight.sent:
                if vid in self._answered:
                    # The stream is still in step; the vector answered twice is the culprit.
                    yield Answer(vid, None, f"the adapter answered {vid} twice")
                    continue
                if not isinstance(vid, str):
                    raise _Fault(f"the adapter wrote a message with no vector id: {_clip(json.dumps(msg))}")
                raise _Fault(f"the adapter answered id {vid!r}, which was not sent")
            flight.answered(vid)
            self._answered.add(vid)
            self._last_answered = vid
            if type(msg) is Repeated:
                yield Answer(vid, None, msg.text)
            else:
                yield Answer(vid, msg)
        self._settle_stderr(next(iter(flight.sent)) if flight.sent else self._last_answered)

    def _after_fault(self, fault: "_Fault", flight: "_InFlight", current: str, isolate: deque):
        """Kill the process; blame the one vector unanswered (yielding its Answer), or, when there were
        several, queue them to be run again one at a time."""
        unanswered = flight.clear()
        self._kill(unanswered[0]["id"] if unanswered else current)
        if len(unanswered) == 1:
            blamed = unanswered[0]["id"]
            yield Answer(blamed, None, f"{fault} (while running {blamed}){self._stderr_hint(blamed)}")
        else:
            self.notes.append((None, f"{fault}, with {len(unanswered)} vectors of the batch unanswered "
                                     "(from " + unanswered[0]["id"] + "); restarted to run them one at a time"))
            isolate.extendleft(reversed(unanswered))

    def _messages(self, lines):
        """Parse complete lines; one json.loads for the lot when they are all JSON (the usual case)."""
        joined = b"[" + b",".join(lines) + b"]"
        try:
            parsed = json.loads(joined, parse_constant=_not_json)
            if len(parsed) == len(lines):   # else some line held more than one value
                # json.loads keeps the last of a repeated key; every key is followed by `":` in
                # compact JSON, so equal counts prove no key was repeated (else look line by line).
                if joined.count(b'":') == _key_count(parsed):
                    return parsed
                return [_unrepeated(line, msg) for line, msg in zip(lines, parsed)]
        except ValueError:
            pass
        out = []
        for line in lines:
            try:
                out.append(_unrepeated(line, json.loads(line, parse_constant=_not_json)))
            except _NotFinite as exc:
                raise _Fault(f"the adapter wrote {exc.args[0]}, which is not a JSON number (a word is an integer "
                             f"0 to 65535): {_clip(line)}")
            except ValueError:
                raise _Fault(f"the adapter wrote a line that is not JSON: {_clip(line)}")
        return out

    def _restart(self):
        self.restarts += 1
        if self.restarts > self.max_restarts:
            raise AdapterAbort(f"--adapter {self.command}: gave up after {self.max_restarts} restarts")
        self._spawn()
        self._handshake()


class Repeated(dict):
    """A message in which a JSON object repeats a key (`{"D100": 1, "D100": 2}`): which value was meant
    cannot be told, so it is a fault against its vector, never silently the last one."""

    text = ""


def _key_count(value) -> int:
    if type(value) is dict:
        return len(value) + sum(_key_count(v) for v in value.values() if type(v) in (dict, list))
    if type(value) is list:
        return sum(_key_count(v) for v in value if type(v) in (dict, list))
    return 0


def _refuse_repeats(pairs):
    seen = set()
    for key, _ in pairs:
        if key in seen:
            raise _RepeatedKey(key)
        seen.add(key)
    return dict(pairs)


class _RepeatedKey(ValueError):
    pass


class _NotFinite(ValueError):
    """NaN, Infinity or -Infinity: Python's json reads them, JSON has no such numbers."""


def _not_json(name: str):
    raise _NotFinite(name)


def _unrepeated(line: bytes, msg):
    """`msg` (parsed from `line`), or a Repeated copy naming the first key `line` repeats."""
    if line.count(b'":') == _key_count(msg):
        return msg
    try:
        json.loads(line, object_pairs_hook=_refuse_repeats)
    except _RepeatedKey as exc:
        out = Repeated(msg) if isinstance(msg, dict) else Repeated()
        out.text = f"the answer reports {exc.args[0]} twice (a JSON object with a repeated key)"
        return out
    return msg


def _clip(line: bytes, limit: int = 120) -> str:
    text = line.decode("utf-8", "replace") if isinstance(line, bytes) else str(line)
    return repr(text if len(text) <= limit else text[:limit] + "...")


def _exit_text(status: int) -> str:
    if status < 0:
        try:
            name = signal.Signals(-status).name
        except ValueError:
            name = f"signal {-status}"
        return f"the adapter was killed by {name}"
    return f"the adapter exited with status {status} before answering"
