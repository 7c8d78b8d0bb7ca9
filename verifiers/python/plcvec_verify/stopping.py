"""Being stopped: SIGTERM (a CI job cancelled) and SIGINT (Ctrl-C) end the run like a fault.

The adapter runs in its own session, so neither signal reaches it: the runner has to end it. The
signals are turned into `Stopped`, an exception that unwinds to the runner, which ends the
adapter at once and keeps the results gathered so far; `plcvec verify` then writes its reports
and exits 128 + the signal number (143, 130), as a shell reports a process killed by it.
"""
from __future__ import annotations

import signal
import threading
from contextlib import contextmanager

STOP_SIGNALS = (signal.SIGTERM, signal.SIGINT)

# Sections that must not be cut in half (starting the adapter and registering it, killing it and
# reaping it): a stop signal arriving inside one is raised when the outermost one ends.
_deferring = 0
_pending: list[int] = []


class Stopped(BaseException):
    """The runner received a stop signal.

    A BaseException, like KeyboardInterrupt: the `except Exception` that turns an in-process
    adapter's exception into a vector's error must not swallow it.
    """

    def __init__(self, signum: int):
        super().__init__(signum)
        self.signum = signum

    @property
    def exit_code(self) -> int:
        return 128 + self.signum

    def __str__(self):
        return f"stopped by {signal.Signals(self.signum).name}; the adapter was ended"


@contextmanager
def stop_on_signals(signals=STOP_SIGNALS):
    """Within the block, each of `signals` raises Stopped (once; later ones are ignored).

    One Stopped is enough: everything that follows it (ending the adapter, writing the reports)
    has a bounded wait, and a second signal arriving in the middle would only lose the reports.
    Handlers can be set only from the main thread; elsewhere the block runs unguarded.
    """
    if threading.current_thread() is not threading.main_thread():
        yield
        return

    def handler(signum, frame):
        for s in signals:
            signal.signal(s, signal.SIG_IGN)
        if _deferring:
            _pending.append(signum)
            return
        raise Stopped(signum)

    previous = {s: signal.signal(s, handler) for s in signals}
    try:
        yield
    finally:
        for s, h in previous.items():
            signal.signal(s, h)


@contextmanager
def deferred():
    """Hold a stop signal until the block ends, so the block is never cut in half.

    Without it, a SIGTERM arriving between the fork of the adapter and the line that records it
    would leave a process that nothing knows to end.
    """
    global _deferring
    _deferring += 1
    try:
        yield
    finally:
        _deferring -= 1
        if not _deferring and _pending:
            signum = _pending.pop()
            _pending.clear()
            raise Stopped(signum)
