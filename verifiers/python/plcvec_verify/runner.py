"""Running a selection of vectors through an adapter and judging every answer.

The run is: handshake (which instructions the adapter supports, which interpretation alternatives
it follows), the expectation of each vector under those alternatives, the answers streamed back
and compared field by field, and last the expectations file (known failures) applied. Whatever
happens to the adapter, the results gathered so far are kept, so the reports can always be written.
"""
from __future__ import annotations

import time
from contextlib import contextmanager
from operator import itemgetter
from typing import TYPE_CHECKING

from ._renamed import old_names
from ._report import Report
from .adapters import AdapterAbort
from .choices import defaults_of, followed_alternatives, resolve_choices
from .collector import collector_paused
from .compare import judge, passes_at_once
from .gate import Gate
from .known import KnownFailures
from .protocol import hello_request
from .selection import Selection, select
from .stopping import Stopped
from .suite import Suite
# The statuses, the verdict type and its problems live in the leaf verdict.py (known.py needs them
# too); they are named here as well, where 0.1.0's users import them from.
from .verdict import (ERROR, FAIL, FAILING, NOT_RUN, PASS, SKIP, STALE, STATUSES, XFAIL,  # noqa: F401
                      Problem, Verdict)

# 0.1.0's names of Report and Verdict, deprecated until 0.4.0: static tools see them here as imports of
# the one class each; at run time __getattr__ gives them with a DeprecationWarning.
if TYPE_CHECKING:
    from ._report import Report as RunReport  # noqa: F401
    from .verdict import Verdict as VectorResult  # noqa: F401
__getattr__ = old_names(__name__, {"RunReport": "Report", "VectorResult": "Verdict"})

# The per-vector bookkeeping of a run is done with map() over these where it can: a run over the
# golden set is a few microseconds a vector, and a Python-level loop is a good part of that.
_ID, _FAMILY, _INSTRUCTION = itemgetter("id"), itemgetter("family"), itemgetter("instruction")


class Plan:
    """The vectors of one run with their requests and expectations, built once.

    Kept apart from the run so that repeated runs (the benchmark, the pytest plugin) and the
    selection of vectors do not pay for it again.
    """

    def __init__(self, suite: Suite, vectors: list, choices: dict):
        defaults = defaults_of(suite)
        self.vectors = vectors
        made = suite.expectations
        with collector_paused():   # kept for the whole run: the collector would only walk them again
            self.requests = {v["id"]: made.request(v) for v in vectors}
            self.expected = {v["id"]: made.expected(v, choices, defaults) for v in vectors}
            # Per vector, the result it gets when an answer passes, and its expectation, made once here:
            # a passing result holds nothing of the answer, and making it again for every vector of every
            # run was a good part of a run's time. Each answer is still judged in full (_judge_answers).
            self.judging = {vid: (Verdict(vid, exp.family, exp.instruction, PASS, choices=exp.choices), exp)
                            for vid, exp in self.expected.items()}
        self.wire: dict[str, bytes] = {}   # encoded requests, filled by a process adapter
        # For a run of exactly `vectors` (the same list): the requests in order, the families and
        # instructions, worked out once rather than by a pass over the vectors in every run.
        self.ids = list(self.requests)
        self.request_list = list(self.requests.values())
        self.families = sorted(set(map(_FAMILY, vectors)))
        self.instructions = frozenset(map(_INSTRUCTION, vectors))


def run(suite: Suite, adapter, selection: Selection = Selection(), *, choose: dict | None = None,
        known: KnownFailures | None = None, progress=None, plan: Plan | None = None,
        vectors: list | None = None, keep_open: bool = False, gate: Gate | None = None) -> Report:
    """Run the selected vectors through `adapter` (adapters.InProcess or stdio.StdioAdapter).

    `vectors`, when given, is the list to run instead of `selection` (the pytest plugin passes the
    items pytest kept after -k and friends). `keep_open` leaves the adapter running for another run.
    `gate` says what the run must show beyond "no failures" (gate.py); by default, at least one pass.
    A selection naming a family, instruction, tag or interpretation the suite does not have, or an
    id glob that matches no vector, is a VerifyError: a typo must not turn a gate off.
    """
    started = time.perf_counter()
    if vectors is None:
        vectors = select(suite, selection)
    planned = plan is not None and vectors is plan.vectors
    families = (plan.families if planned else sorted(set(map(_FAMILY, vectors)))) or sorted(suite.headers)
    hello = adapter.hello(hello_request(suite, families))
    interpretations = resolve_choices(suite, families, hello.get("interpretations", {}), choose or {})
    cpu_writes = frozenset(hello.get("cpu_writes", ()))
    runnable, results = _supported(vectors, set(hello["instructions"]), plan.instructions if planned else None)
    if plan is None:
        plan = Plan(suite, runnable, followed_alternatives(interpretations))
    report = Report(suite, hello["adapter"], interpretations, [], selection=selection, gate=gate or Gate(),
                    cpu_writes=tuple(sorted(cpu_writes)))
    with _ended_by_the_adapter(report, adapter):
        _judge_answers(adapter, plan, runnable, results, cpu_writes, progress)
    _close(report, adapter, keep_open)
    if len(results) < len(vectors):
        _not_run(results, runnable)
    _attach_notes(report, results, getattr(adapter, "notes", ()))
    report.results = list(map(results.__getitem__, plan.ids if vectors is plan.vectors else map(_ID, vectors)))
    if known is not None:
        known.apply(report.results, suite)
        report.known_file = known.path
    report.seconds = time.perf_counter() - started
    return report


def _supported(vectors: list, supported: set, instructions: frozenset | None) -> tuple[list, dict]:
    """(the vectors the adapter runs, {id: a skip verdict} for those of an instruction it does not
    support). `instructions`: the vectors' instructions when a plan already knows them."""
    if supported.issuperset(map(_INSTRUCTION, vectors) if instructions is None else instructions):
        return vectors, {}
    runnable, skipped = [], {}
    for v in vectors:
        if v["instruction"] in supported:
            runnable.append(v)
        else:
            skipped[v["id"]] = Verdict(v["id"], v["family"], v["instruction"], SKIP,
                                       message=f"the adapter does not support {v['instruction']}")
    return runnable, skipped


def _judge_answers(adapter, plan: Plan, runnable: list, results: dict, cpu_writes: frozenset, progress) -> None:
    """Send `runnable` to the adapter and put the verdict on each answer into `results` as it comes.

    The usual answer passes at once (compare.passes_at_once) and gets the plan's passing verdict,
    made once; any other is judged the long way (compare.judge).
    """
    judging = plan.judging
    to_send = plan.request_list if runnable is plan.vectors else list(map(plan.requests.__getitem__,
                                                                          map(_ID, runnable)))
    total, done, failed = len(runnable), 0, 0
    for answer in adapter.answers(to_send, plan.wire):
        vid = answer[0]
        passed, exp = judging[vid]
        if passes_at_once(answer, exp):
            results[vid] = passed
        else:
            r = results[vid] = judge(answer, exp, cpu_writes)
            failed += r.status in FAILING
        done += 1
        if progress:
            progress(done, total, failed)


@contextmanager
def _ended_by_the_adapter(report: Report, adapter):
    """An adapter that cannot go on, or a signal, ends the run with the verdicts it has (the report says
    why). Anything else ends the adapter before it goes on up."""
    try:
        yield
    except AdapterAbort as exc:
        report.aborted = str(exc)
    except Stopped as exc:
        report.aborted, report.stopped = str(exc), exc.signum
    except BaseException:
        # KeyboardInterrupt in a library caller, or a bug: the adapter must not outlive the run.
        _end(adapter)
        raise


def _close(report: Report, adapter, keep_open: bool) -> None:
    """End the adapter after the run: at once after a signal, left running when the caller keeps it
    for another run (unless the run was aborted), else closed. Closing must never lose the results."""
    if report.stopped:
        _end(adapter)
    elif not keep_open or report.aborted:
        try:
            adapter.close()
        except Stopped as exc:
            report.aborted, report.stopped = str(exc), exc.signum
            _end(adapter)
        except Exception as exc:
            report.notes.append(f"closing the adapter: {type(exc).__name__}: {exc}")


def _not_run(results: dict, runnable: list) -> None:
    """Every vector the adapter stopped before is NOT_RUN: it counts against the run."""
    for v in runnable:
        if v["id"] not in results:
            results[v["id"]] = Verdict(v["id"], v["family"], v["instruction"], NOT_RUN,
                                       message="not run: the adapter stopped before it")


def _attach_notes(report: Report, results: dict, notes) -> None:
    """The adapter's notes (e.g. what it wrote to stderr), each on its vector's verdict when it names
    one, else on the report."""
    for vid, text in notes:
        if vid in results:
            results[vid] = results[vid]._replace(notes=(*results[vid].notes, text))
        else:
            report.notes.append(text)


def _end(adapter):
    """End the adapter at once: a process is killed with its children, an object is closed."""
    end = getattr(adapter, "terminate", None) or adapter.close
    try:
        end()
    except Exception:   # ending is best effort; the exception being handled matters more
        pass


__all__ = ["run", "Plan", "Report", "Verdict", "RunReport", "VectorResult", "Problem", "STATUSES", "FAILING",
           "PASS", "FAIL", "ERROR", "SKIP", "XFAIL", "STALE", "NOT_RUN"]
