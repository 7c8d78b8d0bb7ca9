"""Does a mutant change the committed vectors? Asked in a process of its own, forked for the mutant.

The process imports the mutated engine file in place of the real one, then the generator afresh
(so everything that imports the engine, the cases and the coverage model too, sees the mutant, as
`plcvec generate` would with the file changed on disk), builds the vectors of the families that file
can reach, and compares them, with what `plcvec generate` merged, with the committed ones. Nothing is
written anywhere: the mutated source lives in this process only.

The spec is the one the parent loaded with the engine as it is: a Family holds only what its YAML
files say, and the spec's checks, which use the engine's field codec, only accept or refuse a spec,
they make no vector. (Loading it again in each process would double a mutant's time.)

The answer is plain data (pickled back to the parent): the status, and for a change the first family
found changed, how many of its vectors changed in each of `plcvec diff`'s classes (expectation,
inputs, metadata, added, removed) and a few of their ids; for a generator that fails, its error.
"""
from __future__ import annotations

import importlib.abc
import importlib.util
import json
import math
import sys
import time
import warnings
from dataclasses import dataclass, field
from pathlib import Path

# What a mutant does to the committed vectors.
UNCHANGED = "unchanged"     # every vector the same: an equivalent mutant, or code no vector reaches
CHANGED = "changed"         # some vector added, removed or different
FAILS = "fails"             # the spec or the generator raised (or its process died)
TIMEOUT = "timeout"         # stopped after the run's timeout
STATUSES = (UNCHANGED, CHANGED, FAILS, TIMEOUT)

# plcvec.output.diff's classes of a changed vector, and the two of a vector present on one side only.
CHANGE_CLASSES = ("expectation", "inputs", "metadata", "added", "removed")
SHOWN_IDS = 3   # vector ids kept per mutant for the report
MODEL_TAG = "model"   # the tag of the vectors the coverage model adds (plcvec.cases.model_cases)

# The most a mutant's process may map: a mutant that allocates without end (a table of 2**32 entries)
# fails with MemoryError instead of taking the machine's memory from everything else on it.
MEMORY_LIMIT_BYTES = 4 << 30

# Modules kept when the generator is imported afresh: the error types (the same classes on both
# sides of the pipe) and this package itself (the code now running).
_KEPT = ("plcvec", "plcvec.errors", "plcvec.mutation")


@dataclass
class Outcome:
    status: str
    family: str = ""                             # the family where a change was found (the first built)
    counts: dict = field(default_factory=dict)   # change class -> vectors of that family
    ids: list = field(default_factory=list)      # a few changed vector ids, the most telling class first
    error: str = ""
    cpu_seconds: float = 0.0                     # the CPU time the judging took
    # A change of the engine's record alone: the clauses, tags or descriptions of vectors (metadata) or
    # which rows of the coverage model get a vector (model vectors added or removed), never what any
    # vector sets up or expects. The engine's trace and its record for the coverage model make these;
    # no observable outcome is decided there.
    record_only: bool = False

    @property
    def change(self):
        """The most telling class of change (expectation first), or None."""
        return next((c for c in CHANGE_CLASSES if self.counts.get(c)), None)


@dataclass
class Committed:
    """What a mutant is judged against: the committed vectors and the merged ids of each family."""

    spec: list             # the loaded families (plcvec.spec.loader.load_spec)
    engine_dir: Path
    sources: dict           # engine file name -> source
    families: dict          # family -> plcvec.output.diff's {"header": ..., "vectors": {id: vector}}
    merged: dict            # family -> {merged id: kept id}
    targets: dict           # engine file name -> the families whose vectors it can change
    # The unmutated engine's Outcome against these vectors, once judged: the same for every run over
    # them in one process (a caller running several selections pays for it once).
    unmutated: Outcome | None = field(default=None, compare=False, repr=False)


class _OutOfTime(BaseException):
    """The mutant's process has used the CPU time it was given."""


def _out_of_time(signum, frame):
    raise _OutOfTime


def judge(mutant, committed: Committed, cpu_seconds=None) -> Outcome:
    """In the mutant's own process: the Outcome of building its families with the mutant in place
    (with `mutant` None, of building every family with the engine as it is), stopped as a TIMEOUT once
    it has used `cpu_seconds` of CPU time.

    CPU time, not time by the clock: on a machine shared with other work a mutant's clock time varies
    many times over, its CPU time hardly (the generator neither waits nor sleeps, so a mutant that hangs
    is one that computes without end). The parent's deadline by the clock stays as the last bound.
    """
    _limit_resources(cpu_seconds)
    if mutant is None:
        wanted = set(committed.families)
    else:
        mutated = mutant.mutated(committed.sources[mutant.file])
        if mutated is None:
            return Outcome(FAILS, error="cosmic-ray made no change at this position")
        warnings.simplefilter("ignore")   # `x is 0` and the like: a mutant's SyntaxWarning is no news
        sys.dont_write_bytecode = True    # the mutant is never cached into __pycache__
        _import_with(mutant.file, mutated, committed.engine_dir)
        wanted = committed.targets[mutant.file]
    try:
        from plcvec.output.diff import VectorSet, compare
        from plcvec.output.golden import family_vectors

        # The smallest family first, and none after the first that changes: a mutant is judged by
        # whether it changes vectors, and most that change some change them in every family they reach.
        outcome = Outcome(UNCHANGED)
        for fam in sorted((f for f in committed.spec if f.name in wanted),
                          key=lambda f: (len(committed.families[f.name]["vectors"]), f.name)):
            merged = {}
            built = json.loads(json.dumps(family_vectors(fam, merged=merged)))
            old = VectorSet("committed", single=False, families={fam.name: committed.families[fam.name]},
                            merged={fam.name: committed.merged.get(fam.name, {})})
            new = VectorSet("mutant", single=False, merged={fam.name: merged}, families={
                fam.name: {"header": committed.families[fam.name]["header"], "vectors": {v["id"]: v for v in built}}})
            outcome = _outcome(fam.name, compare(old, new), merged != old.merged[fam.name], old, new)
            if outcome.status == CHANGED:
                break
        outcome.cpu_seconds = time.process_time()
        return outcome
    except _OutOfTime:
        return Outcome(TIMEOUT, error=f"more than {cpu_seconds:g} s of CPU time")
    except BaseException as exc:   # anything the mutant raises is its answer, not the run's
        return Outcome(FAILS, error=f"{type(exc).__name__}: {exc}"[:300])


def _outcome(family, report, merged_differs, old, new):
    """The Outcome of one family's comparison (plcvec.output.diff.compare of `old` and `new`)."""
    counts = {c: report["totals"][c] for c in CHANGE_CLASSES if report["totals"][c]}
    if merged_differs and not counts:
        counts["metadata"] = 1   # only which ids went into which vector: what a vector is called
    if not counts:
        return Outcome(UNCHANGED)
    fam = report["families"][family]
    ids = [vid for cls in CHANGE_CLASSES
           for vid in (fam[cls] if cls in ("added", "removed") else [v["id"] for v in fam["changed"] if v["class"] == cls])]
    rows = [new.families[family]["vectors"][vid] for vid in fam["added"]] + [
        old.families[family]["vectors"][vid] for vid in fam["removed"]]
    record_only = (not counts.get("expectation") and not counts.get("inputs")
                   and all(MODEL_TAG in v.get("tags", ()) for v in rows))
    return Outcome(CHANGED, family=family, counts=counts, ids=ids[:SHOWN_IDS], record_only=record_only)


def _limit_resources(cpu_seconds):
    """Bound this process: MEMORY_LIMIT_BYTES of address space, and `cpu_seconds` of CPU time (then
    SIGXCPU, turned into _OutOfTime; the hard limit, a little later, kills a process that ignores it)."""
    try:
        import resource
        import signal
    except ImportError:   # not on this platform: the parent's deadline still bounds it
        return
    limits = [(resource.RLIMIT_AS, MEMORY_LIMIT_BYTES, MEMORY_LIMIT_BYTES)]
    if cpu_seconds:
        signal.signal(signal.SIGXCPU, _out_of_time)
        used = int(time.process_time())   # the limit counts what the process used before it too
        limits.append((resource.RLIMIT_CPU, used + math.ceil(cpu_seconds), used + math.ceil(cpu_seconds) + 5))
    for which, soft, hard in limits:
        try:
            _, old_hard = resource.getrlimit(which)
            if old_hard != resource.RLIM_INFINITY:
                soft, hard = min(soft, old_hard), min(hard, old_hard)
            resource.setrlimit(which, (soft, hard))
        except (ValueError, OSError):   # a limit this platform does not set: the deadline still holds
            pass


class _MutantFinder(importlib.abc.MetaPathFinder, importlib.abc.Loader):
    """Serves one engine module from the mutated source; every other import goes on as usual."""

    def __init__(self, name, path, source):
        self.name, self.path, self.source = name, path, source

    def find_spec(self, fullname, path=None, target=None):
        if fullname != self.name:
            return None
        package = self.path.name == "__init__.py"
        return importlib.util.spec_from_file_location(
            fullname, self.path, loader=self, submodule_search_locations=[str(self.path.parent)] if package else None)

    def create_module(self, spec):
        return None

    def exec_module(self, module):
        from cosmic_ray.exceptions import CosmicRayTestingException

        # ExceptionReplacer's handler catches an exception nothing raises: the handler never runs.
        module.CosmicRayTestingException = CosmicRayTestingException
        exec(compile(self.source, str(self.path), "exec"), module.__dict__)


def _import_with(file_name, source, engine_dir):
    """Forget every generator module imported so far and serve `file_name` of the engine mutated."""
    root = sys.modules["plcvec"]
    for name in [m for m in sys.modules if m.startswith("plcvec.")]:
        if not (name in _KEPT or name.startswith("plcvec.mutation.")):
            del sys.modules[name]
            # `from plcvec import engine` reads the package's attribute before sys.modules.
            if name.count(".") == 1 and hasattr(root, name[len("plcvec."):]):
                delattr(root, name[len("plcvec."):])
    module = "plcvec.engine" if file_name == "__init__.py" else f"plcvec.engine.{file_name.removesuffix('.py')}"
    sys.meta_path.insert(0, _MutantFinder(module, Path(engine_dir) / file_name, source))
