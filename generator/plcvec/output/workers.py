"""A function of each family, worked out in forked worker processes: the golden set's families are
independent of each other, so on a machine with several cores they are built side by side.

The result is the list of each family's result in the families' order, whichever worker made it and
whenever it finished, so the output is the same bytes as one process gives. Each family is built by a
process forked for it (it starts with the spec loaded and the code imported; nothing is sent to it),
at most `jobs` at a time, the costliest first, and sends its result back pickled through a pipe of its
own. The parent waits on those pipes alone, with a deadline, and uses no thread: a worker that dies
is seen at once (its pipe closes early) and one that hangs is killed at the deadline. Workers ignore
^C; the parent, interrupted, kills them and waits for them before it goes on. each_in_a_worker is
the same loop for any items with a name (the mutation run's mutants) and a timeout of the caller's,
reporting each item that passes it instead of giving up on the whole map.

Where the platform does not fork safely (anything but Linux) the work is done in this process, one
family after another. A worker runs only the build and writes to its own pipe, so it is forked even
from a process with other threads (a pytest-xdist worker): it takes none of the locks they may hold.
"""
import gc
import os
import pickle
import select
import signal
import sys
import time
from contextlib import closing

from plcvec.errors import PlcvecError

# The longest a worker may take over one family before the build gives up on it: the golden set's
# largest family takes under a second here, so only a worker that hangs meets it.
FAMILY_TIMEOUT_S = 600


def usable_cores():
    """The cores this process may run on (its CPU affinity where the platform tells it)."""
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:
        return os.cpu_count() or 1


def add_jobs_option(parser):
    """--jobs N / -j N on a command that builds the families (default: the usable cores)."""
    parser.add_argument("--jobs", "-j", type=_jobs, default=usable_cores(), metavar="N",
                        help=f"build the families in N worker processes (default: {usable_cores()}, the cores usable "
                             "here; 1: in this process); the output is the same bytes whatever N is")


def _jobs(text):
    """--jobs N: a whole number of worker processes, at least 1."""
    import argparse

    try:
        jobs = int(text)
    except ValueError:
        jobs = 0
    if jobs < 1:
        raise argparse.ArgumentTypeError(f"{text!r} is not a number of processes (a whole number, 1 or more)")
    return jobs


def can_fork():
    return sys.platform.startswith("linux")


def map_families(function, families, jobs, cost=None):
    """[function(family) for family in families], in up to `jobs` worker processes.

    `cost(family)`, a rough estimate of a family's work, only orders the work (the costliest first, so
    that no large family is left to the end while the other workers stand idle).
    """
    jobs = min(jobs, len(families))
    if jobs <= 1 or not can_fork():
        return [function(fam) for fam in families]
    order = sorted(range(len(families)), key=lambda k: -cost(families[k])) if cost else range(len(families))
    results = {}
    with closing(each_in_a_worker(function, families, jobs, order, FAMILY_TIMEOUT_S)) as ended:
        for worker, finished in ended:
            if not finished:
                raise PlcvecError(f"a worker process took more than {FAMILY_TIMEOUT_S} s over "
                                  f"{worker.name}; try again with --jobs 1")
            results[worker.index] = worker.result()
    return [results[k] for k in range(len(families))]


def each_in_a_worker(function, items, jobs, order, timeout):
    """(worker, finished) as the worker of each item (by `order`, a list of indices) ends, up to `jobs`
    at a time: finished (its result() is then ready), or not within `timeout` seconds (then already
    killed and reaped). Closed early (the caller raised, or ^C here), it kills and reaps the workers still
    at work: close it explicitly (contextlib.closing), since a traceback keeps an open generator alive.
    """
    waiting = list(order)
    waiting.reverse()   # popped from the end
    running = {}        # read end of a worker's pipe -> _Worker
    try:
        while waiting or running:
            while waiting and len(running) < jobs:
                worker = _Worker.start(function, items, waiting.pop(), timeout)
                running[worker.fd] = worker
            deadline = min(w.deadline for w in running.values())
            ready, _, _ = select.select(list(running), [], [], max(0.0, deadline - time.monotonic()))
            for fd in ready:
                if running[fd].read():
                    yield running.pop(fd), True
            for worker in [w for w in running.values() if time.monotonic() >= w.deadline]:
                del running[worker.fd]
                worker.stop()
                yield worker, False
    finally:
        for worker in running.values():
            worker.stop()


class _Worker:
    """One forked process building one family, and what it has sent back so far."""

    def __init__(self, index, name, pid, fd, timeout):
        self.index, self.name, self.pid, self.fd = index, name, pid, fd
        self.chunks = []
        self.deadline = time.monotonic() + timeout

    @classmethod
    def start(cls, function, families, index, timeout):
        read_end, write_end = os.pipe()
        pid = os.fork()
        if pid == 0:   # the worker: never returns
            os.close(read_end)
            _work_and_exit(function, families[index], write_end)
        os.close(write_end)
        return cls(index, families[index].name, pid, read_end, timeout)

    def read(self):
        """Take what the pipe holds; True once the worker has closed it."""
        chunk = os.read(self.fd, 1 << 20)
        if chunk:
            self.chunks.append(chunk)
            return False
        os.close(self.fd)
        return True

    def result(self):
        """The family's result, or the worker's exception raised here as it was raised there."""
        _, status = os.waitpid(self.pid, 0)   # reaped, so its CPU time is this process's children's
        data = b"".join(self.chunks)
        try:
            ok, value = pickle.loads(data)
        except Exception as exc:
            code = os.waitstatus_to_exitcode(status)
            if code == 0:   # it finished, but what it sent does not read back
                raise PlcvecError(f"the worker process building {self.name} sent back what cannot be read "
                                  f"({exc}); try again with --jobs 1") from None
            raise PlcvecError(f"a worker process building {self.name} died ("
                              + (f"signal {-code}" if code < 0 else f"exit {code}")
                              + "; out of memory? killed?); try again with --jobs 1") from None
        if not ok:
            raise value
        return value

    def stop(self):
        """Kill a worker whose result nobody will wait for, and reap it."""
        try:
            os.kill(self.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
        os.waitpid(self.pid, 0)
        os.close(self.fd)


def _work_and_exit(function, fam, fd):
    """In a worker: the family's result (or its exception) pickled into `fd`, then out, without
    running anything of the parent's at exit (its atexit handlers, its buffered output)."""
    code = 0
    try:
        signal.signal(signal.SIGINT, signal.SIG_IGN)   # ^C is the parent's to handle
        gc.disable()   # as in the parent: the build keeps nearly everything it makes
        try:
            message = (True, function(fam))
        except BaseException as exc:   # sent back whole, to be raised in the parent
            message = (False, exc)
        try:
            data = pickle.dumps(message, protocol=pickle.HIGHEST_PROTOCOL)
        except Exception as exc:   # an exception that does not pickle: its text at least
            data = pickle.dumps((False, PlcvecError(f"building {fam.name}: {message[1]!r} ({exc})")))
        with os.fdopen(fd, "wb") as out:
            out.write(data)
    except BaseException:
        code = 1
    finally:
        os._exit(code)
