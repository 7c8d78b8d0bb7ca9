"""Running a selection of vectors through an adapter and judging every answer.

The run is: handshake (which instructions the adapter supports, which interpretation alternatives
it follows), the expectation of each vector under those alternatives, the answers streamed back
and compared field by field, and last the expectations file (known failures) applied. Whatever
happens to the adapter, the results gathered so far are kept, so the reports can always be written.
"""
from __future__ import annotations

import time
from dataclasses import dataclass, field
from marshal import dumps
from operator import itemgetter

from .adapters import AdapterAbort, result_message
from .compare import Problem, compare, passes, steps_pass_by_value
from .errors import VerifyError
from .expect import PACKED_FORMAT
from .gate import NOTHING_TESTED, Gate
from .known import KnownFailures
from .protocol import hello_request, result_errors, result_shape_ok
from .stopping import Stopped
from .suite import Selection, Suite
# The statuses and the verdict type live in the leaf verdict.py (known.py needs them too); they are
# named here as well, where 0.1.0's users import them from.
from .verdict import (ERROR, FAIL, FAILING, NOT_RUN, PASS, SKIP, STALE, STATUSES, XFAIL,  # noqa: F401
                      VectorResult)

# The per-vector bookkeeping of a run is done with map() over these where it can: a run over the
# golden set is a few microseconds a vector, and a Python-level loop is a good part of that.
_ID, _FAMILY, _INSTRUCTION = itemgetter("id"), itemgetter("family"), itemgetter("instruction")


@dataclass
class RunReport:
    suite: Suite
    adapter: dict
    interpretations: dict          # id -> {"alternative", "declared": bool, "family"}
    results: list
    seconds: float = 0.0
    aborted: str = ""
    notes: list = field(default_factory=list)   # adapter notes not tied to a vector
    selection: Selection = field(default_factory=Selection)
    stopped: int = 0                            # the signal that stopped the run, if one did
    gate: Gate = field(default_factory=Gate)    # what the run must show beyond "no failures"
    cpu_writes: tuple = ()                      # devices the implementation's CPU writes on its own
    known_file: str = ""                        # the known-failures file as given, when there was one

    def count(self, status):
        return sum(1 for r in self.results if r.status == status)

    @property
    def counts(self):
        return {s: self.count(s) for s in STATUSES}

    @property
    def failed(self):
        return [r for r in self.results if r.status in FAILING]

    @property
    def selected(self):
        """The vectors the run was given (not the stale ids an expectations file adds)."""
        return sum(1 for r in self.results if r.family)

    @property
    def shortfall(self) -> str:
        """Why the run proves too little to pass, though nothing failed ("" when it is enough)."""
        return self.gate.shortfall(self.counts, self.selected)

    @property
    def exit_code(self):
        """128+N stopped by signal N; 2 harness error; 1 failures; 5 nothing (or too little) tested; 0 passed."""
        if self.stopped:
            return 128 + self.stopped
        if self.aborted:
            return 2
        if self.failed:
            return 1
        return NOTHING_TESTED if self.shortfall else 0


class Plan:
    """The vectors of one run with their requests and expectations, built once.

    Kept apart from the run so that repeated runs (the benchmark, the pytest plugin) and the
    selection of vectors do not pay for it again.
    """

    def __init__(self, suite: Suite, vectors: list, choices: dict):
        defaults = {i: d["default"] for i, d in suite.interpretations().items()}
        self.vectors = vectors
        made = suite.expectations
        self.requests = {v["id"]: made.request(v) for v in vectors}
        self.expected = {v["id"]: made.expected(v, choices, defaults) for v in vectors}
        # Per vector, its expectation and the result it gets when an answer passes, made once here:
        # a passing result holds nothing of the answer, and making it again for every vector of every
        # run was a good part of a run's time. Each answer is still judged in full (runner.run).
        # The first item is what an in-process adapter's passing answer packs to (see runner.run).
        self.judging = {vid: (exp.packed_answer, VectorResult(vid, exp.family, exp.instruction, PASS,
                                                              choices=exp.choices), exp)
                        for vid, exp in self.expected.items()}
        self.wire: dict[str, bytes] = {}   # encoded requests, filled by a process adapter
        # For a run of exactly `vectors` (the same list): the requests in order, the families and
        # instructions, worked out once rather than by a pass over the vectors in every run.
        self.ids = list(self.requests)
        self.request_list = list(self.requests.values())
        self.families = sorted(set(map(_FAMILY, vectors)))
        self.instructions = frozenset(map(_INSTRUCTION, vectors))


def resolve_choices(suite: Suite, families, declared: dict, cli: dict) -> dict:
    """interpretation -> {"alternative", "declared", "family"} for every interpretation of `families`."""
    known = suite.interpretations()
    for source, choices in (("the adapter declares", declared), ("--choose gives", cli)):
        for interp, alt in choices.items():
            if interp not in known:
                raise VerifyError(f"{source} interpretation {interp!r}, which no vector file defines "
                                  f"(known: {', '.join(sorted(known))})")
            if alt not in known[interp]["alternatives"]:
                raise VerifyError(f"{source} {interp}={alt}, but {interp} has the alternatives "
                                  f"{', '.join(known[interp]['alternatives'])}")
    for interp, alt in cli.items():
        if interp in declared and declared[interp] != alt:
            raise VerifyError(f"--choose {interp}={alt}, but the adapter declares {interp}={declared[interp]}")
    out = {}
    for interp, d in sorted(known.items()):
        if not set(d["families"]) & set(families):
            continue
        chosen = declared.get(interp, cli.get(interp))
        out[interp] = {"alternative": chosen or d["default"], "declared": chosen is not None,
                       "families": d["families"]}
    return out


def run(suite: Suite, adapter, selection: Selection = Selection(), *, choose: dict | None = None,
        known: KnownFailures | None = None, progress=None, plan: Plan | None = None,
        vectors: list | None = None, keep_open: bool = False, gate: Gate | None = None) -> RunReport:
    """Run the selected vectors through `adapter` (adapters.InProcess or stdio.StdioAdapter).

    `vectors`, when given, is the list to run instead of `selection` (the pytest plugin passes the
    items pytest kept after -k and friends). `keep_open` leaves the adapter running for another run.
    `gate` says what the run must show beyond "no failures" (gate.py); by default, at least one pass.
    A selection naming a family, instruction, tag or interpretation the suite does not have, or an
    id glob that matches no vector, is a VerifyError: a typo must not turn a gate off.
    """
    started = time.perf_counter()
    if vectors is None:
        selection.check(suite)
        vectors = suite.vectors if selection.everything else selection.apply(suite.vectors)
    planned = plan is not None and vectors is plan.vectors
    families = (plan.families if planned else sorted(set(map(_FAMILY, vectors)))) or sorted(suite.headers)
    hello = adapter.hello(hello_request(suite, families))
    interpretations = resolve_choices(suite, families, hello.get("interpretations", {}), choose or {})
    choices = {i: d["alternative"] for i, d in interpretations.items()}
    supported = set(hello["instructions"])
    cpu_writes = frozenset(hello.get("cpu_writes", ()))

    results: dict[str, VectorResult] = {}
    if supported.issuperset(plan.instructions if planned else map(_INSTRUCTION, vectors)):
        runnable = vectors
    else:
        runnable = []
        for v in vectors:
            if v["instruction"] in supported:
                runnable.append(v)
            else:
                results[v["id"]] = VectorResult(v["id"], v["family"], v["instruction"], SKIP,
                                                message=f"the adapter does not support {v['instruction']}")
    if plan is None:
        plan = Plan(suite, runnable, choices)
    by_id, judging, requests = suite.by_id, plan.judging, plan.requests
    report = RunReport(suite, hello["adapter"], interpretations, [], selection=selection, gate=gate or Gate(),
                       cpu_writes=tuple(sorted(cpu_writes)))
    total, done, failed = len(runnable), 0, 0
    try:
        to_send = plan.request_list if runnable is plan.vectors else list(map(requests.__getitem__, map(_ID, runnable)))
        for answer in adapter.answers(to_send, plan.wire):
            vid, msg, fault, bare = answer
            packed, passed, exp = judging[vid]
            # The usual case, decided at one comparison. An in-process adapter's answer (`bare`: the
            # result message without `type` and `id`, never a fault) passes when its bytes in marshal's
            # format are the expectation's (compare.steps_pass says why that is exact, JSON types
            # included), else when its steps equal the expectation value for value and type for type;
            # a process's result message goes through compare.passes. Anything else, the long way.
            if bare:
                try:
                    usual = dumps(msg, PACKED_FORMAT) == packed
                except ValueError:      # marshal refuses it: not plain dicts, lists and numbers
                    usual = False
                usual = usual or len(msg) == 1 and steps_pass_by_value(exp, msg.get("steps"))
            else:
                usual = fault is None and passes(exp, msg)
            if usual:
                results[vid] = passed
                done += 1
                if progress:
                    progress(done, total, failed)
                continue
            msg = result_message(answer)
            v = by_id[vid]
            problems = None
            if not fault and result_shape_ok(msg):
                problems = compare(exp, msg["steps"], cpu_writes)     # shape fine: compare at once
            # A comparison that passes has seen every reported value equal to one of the vector's, which
            # are valid; the values of devices it does not compare (scratch, unjudged) it has not seen.
            errors = () if fault or (problems == [] and not exp.ignored) else result_errors(msg)
            if fault or errors:
                fault = fault or "the result does not match result.schema.json: " + "; ".join(errors)
                r = VectorResult(v["id"], v["family"], v["instruction"], ERROR, message=fault, choices=exp.choices)
            elif "steps" in msg:
                if problems is None:
                    problems = compare(exp, msg["steps"], cpu_writes)
                r = VectorResult(v["id"], v["family"], v["instruction"], FAIL if problems else PASS,
                                 tuple(problems), choices=exp.choices, answer=msg["steps"] if problems else None)
            elif "skip" in msg:
                r = VectorResult(v["id"], v["family"], v["instruction"], SKIP, message=msg["skip"], choices=exp.choices)
            else:
                r = VectorResult(v["id"], v["family"], v["instruction"], ERROR,
                                 message=f"the implementation reported an error: {msg['error']}", choices=exp.choices)
            results[vid] = r
            done += 1
            failed += r.status in FAILING
            if progress:
                progress(done, total, failed)
    except AdapterAbort as exc:
        report.aborted = str(exc)
    except Stopped as exc:
        report.aborted, report.stopped = str(exc), exc.signum
    except BaseException:
        # KeyboardInterrupt in a library caller, or a bug: the adapter must not outlive the run.
        _end(adapter)
        raise
    if report.stopped:
        _end(adapter)
    elif not keep_open or report.aborted:
        try:
            adapter.close()
        except Stopped as exc:
            report.aborted, report.stopped = str(exc), exc.signum
            _end(adapter)
        except Exception as exc:  # closing must never lose the results
            report.notes.append(f"closing the adapter: {type(exc).__name__}: {exc}")
    if len(results) < len(vectors):
        for v in runnable:
            if v["id"] not in results:
                results[v["id"]] = VectorResult(v["id"], v["family"], v["instruction"], NOT_RUN,
                                                message="not run: the adapter stopped before it")
    for vid, text in getattr(adapter, "notes", ()):
        if vid in results:
            results[vid] = results[vid]._replace(notes=(*results[vid].notes, text))
        else:
            report.notes.append(text)
    report.results = list(map(results.__getitem__, plan.ids if vectors is plan.vectors else map(_ID, vectors)))
    if known is not None:
        known.apply(report.results, suite)
        report.known_file = known.path
    report.seconds = time.perf_counter() - started
    return report


def _end(adapter):
    """End the adapter at once: a process is killed with its children, an object is closed."""
    end = getattr(adapter, "terminate", None) or adapter.close
    try:
        end()
    except Exception:   # ending is best effort; the exception being handled matters more
        pass


__all__ = ["run", "Plan", "RunReport", "VectorResult", "Problem", "STATUSES", "FAILING",
           "PASS", "FAIL", "ERROR", "SKIP", "XFAIL", "STALE", "NOT_RUN"]
