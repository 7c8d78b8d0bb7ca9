"""How fast the verifier judges the golden set, three ways side by side.

- in process: the reference implementation as a Python adapter object;
- over stdio, batched: one long-lived adapter process (the protocol of PROTOCOL.md);
- over stdio, one process per vector: the way some suites drive implementations (a sample of the
  set, since a process start costs tens of milliseconds).

The first two are steady-state figures: the vectors' requests and expectations are prepared once
(`Plan`, timed on its own line), the adapter is warmed by one pass, and the figure is the median of
several passes over the whole golden set. The third includes each process start, which is the point.
A row "harness only" answers from memory, to show what the runner itself costs.
"""
from __future__ import annotations

import gc
import statistics
import sys
import time

from .adapters import InProcess
from .runner import Plan, run
from .stdio import StdioAdapter
from .suite import Suite

PASSES = 5
PER_PROCESS_SAMPLE = 40
TARGET_IN_PROCESS = 100_000
TARGET_BATCHED = 50_000
TARGET_RATIO = 100


class _Replay:
    """Answers every vector with answers recorded from the reference: the runner's cost alone."""

    def __init__(self, reference, answers):
        self.reference, self.answers = reference, answers

    def hello(self, request):
        return self.reference.hello(request)

    def run(self, request):
        return self.answers[request["id"]]


def _passes(suite, adapter, plan, keep_open):
    rates = []
    for i in range(PASSES + 1):
        start = time.perf_counter()
        report = run(suite, adapter, plan=plan, keep_open=keep_open)
        seconds = time.perf_counter() - start
        if report.exit_code != 0:
            raise SystemExit(f"plcvec bench: the reference did not pass the golden set: {report.counts}")
        if i:                       # the first pass warms caches and the adapter process
            rates.append(len(suite.vectors) / seconds)
    return statistics.median(rates)


def in_process_rate(vectors_dir) -> tuple[int, float]:
    """(vectors, vectors/s) judging the golden set in process with the Python reference: the
    figure the native verifiers' benchmarks are set beside (`plcvec bench-native`)."""
    from plcvec_reference.adapter import ReferenceAdapter

    suite = Suite.load(vectors_dir)
    plan = Plan(suite, suite.vectors, {})
    return len(suite.vectors), _passes(suite, InProcess(ReferenceAdapter()), plan, keep_open=False)


def run_verify_benchmark(vectors_dir) -> list[tuple[str, int, float, float]]:
    """Rows of (label, vectors, seconds, vectors/s)."""
    from plcvec_reference.adapter import ReferenceAdapter

    suite = Suite.load(vectors_dir)
    n = len(suite.vectors)
    start = time.perf_counter()
    plan = Plan(suite, suite.vectors, {})
    prepare = time.perf_counter() - start
    # The loaded suite lives as long as the run: keep the collector from walking it again and again.
    gc.freeze()
    rows = [("prepare requests and expectations", n, prepare, n / prepare)]

    reference = ReferenceAdapter()
    rate = _passes(suite, InProcess(reference), plan, keep_open=False)
    rows.append(("verify in process (reference)", n, n / rate, rate))
    recorded = {v["id"]: reference.run(plan.requests[v["id"]]) for v in suite.vectors}
    rate = _passes(suite, InProcess(_Replay(reference, recorded)), plan, keep_open=False)
    rows.append(("verify in process (harness only)", n, n / rate, rate))

    command = [sys.executable, "-m", "plcvec_reference.adapter"]
    adapter = StdioAdapter(command)
    try:
        rate = _passes(suite, adapter, plan, keep_open=True)
    finally:
        adapter.close()
    rows.append(("verify over stdio, batched", n, n / rate, rate))

    sample = suite.vectors[:: max(1, n // PER_PROCESS_SAMPLE)][:PER_PROCESS_SAMPLE]
    start = time.perf_counter()
    for v in sample:
        report = run(suite, StdioAdapter(command, batch_size=1), vectors=[v], plan=plan)
        if report.exit_code != 0:
            raise SystemExit(f"plcvec bench: {v['id']} failed when run alone: {report.counts}")
    seconds = time.perf_counter() - start
    rows.append((f"verify over stdio, process per vector ({len(sample)} sampled)", len(sample), seconds,
                 len(sample) / seconds))
    gc.unfreeze()
    return rows


def print_verify_benchmark(vectors_dir) -> bool:
    rows = run_verify_benchmark(vectors_dir)
    print(f"{'verification of the golden set':52} {'vectors':>8} {'seconds':>9} {'vectors/s':>12}")
    for label, n, seconds, rate in rows:
        print(f"{label:52} {n:>8,} {seconds:>9.3f} {rate:>12,.0f}")
    rate = {label: r for label, _, _, r in rows}
    harness = rate["verify in process (harness only)"]
    inproc = rate["verify in process (reference)"]
    batched = rate["verify over stdio, batched"]
    per_process = rows[-1][3]
    # The in-process target is the verifier's own speed; the reference implementation's run time
    # (about 8 us a vector) is the implementation's, and is shown beside it.
    met = (harness >= TARGET_IN_PROCESS, batched >= TARGET_BATCHED, batched >= TARGET_RATIO * per_process)
    print(f"targets: in process >= {TARGET_IN_PROCESS:,}/s: {'met' if met[0] else 'MISSED'} ({harness:,.0f} for the "
          f"verifier alone, {inproc:,.0f} with the reference implementation's own time); "
          f"batched stdio >= {TARGET_BATCHED:,}/s: {'met' if met[1] else 'MISSED'} ({batched:,.0f}); "
          f"batched >= {TARGET_RATIO}x process per vector: {'met' if met[2] else 'MISSED'} "
          f"({batched / per_process:,.0f}x)")
    return all(met)


if __name__ == "__main__":
    from .locate import default_vectors

    print_verify_benchmark(sys.argv[1] if len(sys.argv) > 1 else default_vectors().path)
