"""A mutation run: every mutant of the engine (or a deterministic sample of them), each judged in a
process of its own against the committed vectors, at most `jobs` at a time, each within a timeout.

Before any mutant, the unmutated engine is judged the same way: its vectors must be the committed
ones (else every mutant would seem to change them), and its time sets the default timeout.
"""
from __future__ import annotations

import sys
import time
from contextlib import closing
from dataclasses import dataclass, field
from pathlib import Path

from plcvec.errors import PlcvecError
from plcvec.mutation import mutants as mutants_module
from plcvec.mutation.oracle import FAILS, TIMEOUT, UNCHANGED, Committed, Outcome, judge
from plcvec.mutation.touch import places, touched, verdict

# The default timeout of a mutant, in CPU seconds (see oracle.judge): this many times the CPU time of
# the unmutated engine, and never below the floor.
TIMEOUT_FACTOR = 5
TIMEOUT_FLOOR_S = 10.0
# The last bound, by the clock, for a mutant's process that the CPU-time limit did not stop (one that
# waits rather than computes): this many times its CPU time, for a machine shared with other work.
CLOCK_FACTOR = 20
PROGRESS_EVERY_S = 15.0


@dataclass
class Judged:
    mutant: object
    outcome: Outcome
    touches: list
    verdict: str


@dataclass
class Run:
    total: int                  # mutants of the files run over (before sampling)
    judged: list = field(default_factory=list)
    sample: tuple = None        # (N, seed) of a sampled run
    files: tuple = ()
    timeout: float = 0.0
    seconds: float = 0.0
    unmutated_cpu_seconds: float = 0.0   # the CPU time of judging the engine as it is


class _Unmutated:
    """Stands in for a mutant to judge the engine as it is."""

    name = "the unmutated engine"
    file = None


def select(all_mutants, sample=None, seed=0):
    """The mutants to run: all, or `sample` of them drawn with the project's SplitMix64 from `seed`
    (the same draw under any Python), in the order of `all_mutants`."""
    if sample is None or sample >= len(all_mutants):
        return list(all_mutants)
    from plcvec.cases.prng import SplitMix64

    rng = SplitMix64(seed)
    pool = list(range(len(all_mutants)))
    for k in range(sample):   # a partial Fisher-Yates shuffle: the first `sample` places are the draw
        j = k + rng.below(len(pool) - k)
        pool[k], pool[j] = pool[j], pool[k]
    return [all_mutants[k] for k in sorted(pool[:sample])]


def enumerate_mutants(sources, files=None):
    """Every mutant of the engine files named (all by default), by file then position."""
    if files:
        unknown = sorted(set(files) - set(sources))
        if unknown:
            raise PlcvecError(f"no engine file {', '.join(unknown)}; the engine's files are {', '.join(sources)}")
    out = []
    for name in sorted(set(files or sources)):
        out += mutants_module.mutants_of(name, sources[name])
    return sorted(out, key=lambda m: (m.file, m.start, m.end, m.operator, m.occurrence))


def committed_vectors(vectors_dir, spec_dir, engine_dir, sources):
    """The Committed set every mutant is judged against, with the families each engine file reaches:
    a file that implements a rule kind (plcvec.engine.KINDS) reaches the families of that kind, any
    other (the package, the helpers every kind shares) every family."""
    from plcvec.engine import KINDS
    from plcvec.output.diff import load_set
    from plcvec.spec.loader import load_spec

    committed = load_set(str(vectors_dir))
    spec = load_spec(spec_dir)
    kinds = {fam.name: fam.kind for fam in spec}
    missing = sorted(set(kinds) - set(committed.families))
    if missing:
        raise PlcvecError(f"{vectors_dir}: no committed vectors of {', '.join(missing)}; run `plcvec generate`")
    kind_files = {kind: sys.modules[cls.__module__].__file__ for kind, cls in KINDS.items()}
    targets = {}
    for name in sources:
        implemented = [k for k, f in kind_files.items() if Path(f).name == name]
        targets[name] = sorted(f for f, k in kinds.items() if not implemented or k in implemented)
    return Committed(spec=spec, engine_dir=Path(engine_dir), sources=sources,
                     families={n: committed.families[n] for n in kinds},
                     merged=committed.merged, targets=targets)


def run_mutants(selected, committed, decisions, jobs, timeout=None, progress=None):
    """Judge the unmutated engine, then each selected mutant; a Run (its `judged` in mutant order)."""
    from plcvec.output.workers import can_fork, each_in_a_worker

    if not can_fork():
        raise PlcvecError("the mutation run forks a process per mutant, which needs Linux")
    decision_places = places(decisions, committed.sources)
    started = time.monotonic()
    if committed.unmutated is None:
        committed.unmutated = judge_in_workers([_Unmutated()], committed, 1, None)[0]
    baseline = committed.unmutated
    run = Run(total=0, unmutated_cpu_seconds=baseline.cpu_seconds)
    if baseline.status != UNCHANGED:
        raise PlcvecError("the unmutated engine does not give the committed vectors ("
                          + (baseline.error or f"{baseline.change}: {', '.join(baseline.ids)}")
                          + "); run `plcvec generate --check` and mend that first")
    run.timeout = timeout or max(TIMEOUT_FLOOR_S, TIMEOUT_FACTOR * baseline.cpu_seconds)
    outcomes = judge_in_workers(selected, committed, jobs, run.timeout, progress)
    for mutant, outcome in zip(selected, outcomes):
        touches = touched(mutant, decision_places)
        run.judged.append(Judged(mutant, outcome, touches, verdict(outcome, touches)))
    run.seconds = time.monotonic() - started
    return run


def judge_in_workers(items, committed, jobs, cpu_seconds, progress=None):
    """[Outcome of each item], each judged in a forked process within `cpu_seconds` of CPU time (None:
    unbounded but for the build's own deadline), `judge(None)` judging the engine as it is. An item is a
    Mutant, or anything with its `file`, `name` and `mutated(source)`."""
    from plcvec.output.workers import FAMILY_TIMEOUT_S, each_in_a_worker

    def work(item):
        return judge(None if item.file is None else item, committed, cpu_seconds)

    outcomes = [None] * len(items)
    last = time.monotonic()
    clock = CLOCK_FACTOR * cpu_seconds if cpu_seconds else FAMILY_TIMEOUT_S
    with closing(each_in_a_worker(work, items, jobs, range(len(items)), clock)) as ended:
        for worker, finished in ended:
            outcomes[worker.index] = _result(worker) if finished else Outcome(
                TIMEOUT, error=f"more than {clock:g} s by the clock")
            if progress and time.monotonic() - last >= PROGRESS_EVERY_S:
                last = time.monotonic()
                progress(sum(o is not None for o in outcomes), len(items))
    return outcomes


def _result(worker):
    try:
        return worker.result()
    except PlcvecError as exc:   # the process died (the memory limit, a signal) or sent back nonsense
        return Outcome(FAILS, error=str(exc))
