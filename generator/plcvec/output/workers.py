"""A function of each family, worked out in forked worker processes: the golden set's families are
independent of each other, so on a machine with several cores they are built side by side.

The result is the list of each family's result in the families' order, whichever worker made it and
whenever it finished, so the output is the same bytes as one process gives. Workers are forked (they
start with the spec already loaded and the code already imported, and nothing but the family's index
is sent to them); where the platform does not fork safely (anything but Linux), the work is done in
this process, one family after another. A worker runs only the build and the executor's own loop, so
it is forked even from a process with other threads (a pytest-xdist worker): it takes none of the
locks those threads could hold at the fork.
"""
import gc
import os
import sys

from plcvec.errors import PlcvecError

# The longest a worker may take over one family before the build gives up on it: the golden set's
# largest family takes under a second here, so only a worker that hangs meets it.
FAMILY_TIMEOUT_S = 600

_work = None   # (function, families) of the map in progress, inherited by the forked workers


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

    `cost(family)`, a rough estimate of a family's work, only orders the submissions (the costliest
    first, so that no large family is left to the end while the other workers stand idle).
    """
    jobs = min(jobs, len(families))
    if jobs <= 1 or not can_fork():
        return [function(fam) for fam in families]
    global _work
    if _work is not None:
        raise RuntimeError("map_families is not reentrant")
    # Imported only when there are workers to start: the command line's other uses do without them.
    import multiprocessing
    from concurrent.futures import ProcessPoolExecutor
    from concurrent.futures import TimeoutError as WorkerTimeout   # not the built-in TimeoutError before 3.11
    from concurrent.futures.process import BrokenProcessPool

    order = sorted(range(len(families)), key=lambda k: -cost(families[k])) if cost else range(len(families))
    _work = (function, families)
    executor = ProcessPoolExecutor(max_workers=jobs, mp_context=multiprocessing.get_context("fork"))
    processes = []
    try:
        futures = {k: executor.submit(_run, k) for k in order}
        # The workers are all started by the first submit (forked before the executor starts a thread).
        processes = list(executor._processes.values())
        results = []
        for k, fam in enumerate(families):
            try:
                results.append(futures[k].result(timeout=FAMILY_TIMEOUT_S))
            except BrokenProcessPool:
                raise PlcvecError(f"a worker process building {fam.name} died (out of memory? killed?); "
                                  "try again with --jobs 1") from None
            except WorkerTimeout:
                raise PlcvecError(f"a worker process took more than {FAMILY_TIMEOUT_S} s over {fam.name}; "
                                  "try again with --jobs 1") from None
        executor.shutdown(wait=True)   # the workers reaped, so their CPU time is this process's children's
        return results
    finally:
        _work = None
        executor.shutdown(wait=False, cancel_futures=True)
        for process in processes:
            process.terminate()   # after a failure, a worker still busy: nothing will wait for its result
        for process in processes:
            process.join(timeout=5)


def _run(index):
    """In a worker: the function of the family at `index`, the collector held off as in the parent."""
    function, families = _work
    gc.disable()
    return function(families[index])
