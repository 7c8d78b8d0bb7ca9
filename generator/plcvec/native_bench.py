"""`plcvec bench-native`: each native verifier's speed beside the Python verifier's, in one run.

Every language folder `verifiers/<lang>/` that has an executable `bench` is run; it builds what it
needs, judges the golden set with that language's reference implementation in process, after
loading, and prints as its last line one JSON object:

    {"lang": "rust", "vectors": 2899, "passes": 20, "load_seconds": 0.041,
     "seconds": 0.0021, "vectors_per_s": 1380000, "note": "median of 20 passes after 3 warm-up"}

(`seconds` is one pass). A bench may add `guarded_vectors_per_s`, the same vectors through the
per-vector bound (PLCVEC_TIMEOUT) a user's test run puts on each, and `guarded_ratio`, that figure
over the same judging without the bound; both are printed under its line. The Python figure is the same measurement with the Python reference
(plcvec_verify.bench.in_process_rate), taken in this run, so each ratio compares like with like
on the same machine at the same moment.

`--baseline REV` compares each language's bench with the same bench of git revision REV instead:
REV is checked out in a temporary `git worktree` (removed at the end, on an error or Ctrl-C too),
each side's bench is run once to build it (that run's figure is not counted), then the two are run
in turn for `--rounds` rounds (baseline first in odd rounds, this tree first in even ones), so that
both sides meet the same moments of a shared machine; besides the ratio of the medians it prints the
median of the round-by-round ratios and the fastest round's ratio (`summary`). Each side judges its own vectors: their counts may differ between revisions,
so vectors/s is the figure compared, and the table says how many vectors each side ran.

`--same-vectors` makes both sides judge the same vectors, the folder `--vectors` (this tree's golden
set by default), named to each bench by PLCVEC_VECTORS: two revisions' vector sets differ in size
and weight, and vectors/s of two different sets is not one measure. A language whose two sides
report different numbers of vectors is not compared (its bench does not read PLCVEC_VECTORS, or
one side's loader left vectors out), and a side whose loader refuses the folder fails as any bench
does, with its own words.

`--common-vectors` is the like-for-like measure across releases (plcvec/common_vectors.py): both
sides judge the vectors the two revisions judge alike, each side in its own revision's format, so
that an older reference that fails some of today's vectors can still be compared on the rest.
"""
from __future__ import annotations

import json
import os
import re
import shutil
import signal
import statistics
import subprocess
import sys
import tempfile
import threading
import time
from dataclasses import dataclass, field
from pathlib import Path

from plcvec.errors import PlcvecError

TIMEOUT_S = 900          # one language's benchmark; a hung one is reported, not waited on
BUILD_TIMEOUT_S = 1800   # its first run, which builds it from nothing in a fresh worktree
DEFAULT_ROUNDS = 3
SAMPLE_S = 0.1           # how often the benchmark process's peak memory is read


def register(sub, spec_parent):
    b = sub.add_parser("bench-native", help="vectors/s of each native verifier (verifiers/<lang>/bench) beside Python's, "
                                            "or beside the same bench at git revision REV (--baseline)")
    b.add_argument("--lang", action="append", metavar="L",
                   help="only this language (repeatable, or comma-separated: --lang go,rust)")
    from plcvec_verify.locate import checkout

    root = checkout()   # the checkout in use (plcvec_verify/locate.py): the native verifiers live only there
    b.add_argument("--vectors", default=str(root / "vectors") if root else None,
                   help="the vector folder for the Python figure, and with --same-vectors the one both sides judge")
    b.add_argument("--root", default=str(root) if root else None,
                   help="the repository holding verifiers/ (default: %(default)s)")
    b.add_argument("--baseline", metavar="REV",
                   help="compare each bench with the same bench of git revision REV (a temporary git worktree), "
                        "run in turn with this tree's in the same run; prints vectors/s of each (median and spread), "
                        "the ratio this tree / REV (of the medians, the median of the rounds' ratios, and of the fastest "
                        "rounds), seconds per pass, loading seconds and peak memory")
    b.add_argument("--same-vectors", action="store_true",
                   help="with --baseline: both sides judge the vectors of --vectors (PLCVEC_VECTORS to each bench) "
                        "instead of each its own revision's; a language whose sides report different counts is not compared")
    b.add_argument("--common-vectors", action="store_true",
                   help="with --baseline: both sides judge the vectors the two revisions judge alike (this tree's, cut "
                        "to those whose instruction, states, steps, outcome and alternatives are REV's too): a like-for-like "
                        "measure where REV's reference fails some of this tree's vectors")
    b.add_argument("--rounds", type=_positive_int, metavar="N",
                   help=f"with --baseline: how many times each side is measured, in turn (default: {DEFAULT_ROUNDS}), "
                        "after one run of each that builds it and is not counted")
    b.set_defaults(func=run)


def _positive_int(text):
    import argparse

    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"not a whole number: {text!r}") from None
    if value < 1:
        raise argparse.ArgumentTypeError(f"must be 1 or more, got {value}")
    return value


# ---------------------------------------------------------------------------------------------------
# Running one bench


def _child_env(vectors=None):
    """This environment without the PLCVEC_* variables: each bench judges its own tree's golden set,
    which a PLCVEC_VECTORS or selection left in the shell would change (and change alike for both
    sides of a comparison, hiding the difference between their vector sets). With `vectors`, the
    bench is told to judge that folder instead (PLCVEC_VECTORS), and nothing else of the shell's."""
    env = {k: v for k, v in os.environ.items() if not k.startswith("PLCVEC_")}
    if vectors is not None:
        env["PLCVEC_VECTORS"] = str(vectors)
    return env


def _children(pid):
    """The child processes of every thread of `pid` (a multi-threaded parent such as the go command
    starts its children from any of its threads, and each thread lists only its own)."""
    found = []
    for task in Path(f"/proc/{pid}/task").glob("*"):
        try:
            found += [int(p) for p in (task / "children").read_text().split()]
        except OSError:
            pass
    return found


def _status(pid):
    """(executable, VmHWM in KiB or None, command line) of a live process, or None. The executable,
    not the name: a script's process is named after the script until it execs."""
    try:
        exe = os.readlink(f"/proc/{pid}/exe")
        status = Path(f"/proc/{pid}/status").read_text()
        cmdline = Path(f"/proc/{pid}/cmdline").read_bytes().split(b"\0")
    except OSError:
        return None
    hwm = re.search(r"^VmHWM:\s*(\d+) kB", status, re.M)
    return (exe, int(hwm.group(1)) if hwm else None, [part.decode(errors="replace") for part in cmdline if part])


# What a bench script runs as before its `exec`: `#!/usr/bin/env bash` is env, then bash.
_LAUNCHERS = {"env", "bash", "sh", "dash", "zsh"}


def _sample_peak(root_pid, peak):
    """The benchmark program's peak resident memory so far, in KiB, in `peak` (a dict, kept between
    samples). The program measured is the bench script's own process once it has exec'd into
    something other than env or a shell (C, Java, Rust, TypeScript), or a Go test binary it runs
    (`-test.bench` among its arguments) -- not the compilers and build tools the script runs first,
    whose memory is no part of judging vectors. VmHWM is the high-water mark since the exec, so
    sampling misses at most what the last SAMPLE_S before exit added."""
    todo, seen = [root_pid], set()
    while todo:
        pid = todo.pop()
        if pid in seen:
            continue
        seen.add(pid)
        todo += _children(pid)
        status = _status(pid)
        if status is None:
            continue
        exe, hwm, cmdline = status
        measured = (pid == root_pid and Path(exe).name not in _LAUNCHERS) or any(arg.startswith("-test.bench") for arg in cmdline)
        if measured and hwm is not None:
            peak[pid, exe] = max(hwm, peak.get((pid, exe), 0))


def _kill_group(proc):
    try:
        os.killpg(proc.pid, signal.SIGKILL)
    except (ProcessLookupError, PermissionError):
        pass
    proc.wait()


def invoke(script: Path, timeout=TIMEOUT_S, vectors=None) -> dict:
    """Run one bench script; its JSON figure, with `wall_seconds` (the whole run) and `peak_mib` (the
    benchmark program's, where it could be told apart) added, or {"error": message}. The script and
    everything it starts form a process group of their own, killed whole on a timeout, an error or
    Ctrl-C, so that no compiler goes on writing into a folder about to be removed. `vectors`: the
    folder the bench judges instead of its own golden set (PLCVEC_VECTORS)."""
    with tempfile.TemporaryFile("w+") as out, tempfile.TemporaryFile("w+") as err:
        start = time.monotonic()
        try:
            proc = subprocess.Popen([str(script)], cwd=script.parent, stdout=out, stderr=err, text=True,
                                    stdin=subprocess.DEVNULL, env=_child_env(vectors), start_new_session=True)
        except OSError as exc:
            return {"error": f"cannot run {script}: {exc.strerror or exc}"}
        peak = {}
        try:
            while True:
                _sample_peak(proc.pid, peak)
                try:
                    proc.wait(timeout=SAMPLE_S)
                    break
                except subprocess.TimeoutExpired:
                    if time.monotonic() - start > timeout:
                        _kill_group(proc)
                        return {"error": f"{script}: no result within {timeout} s (stopped)"}
        except BaseException:
            _kill_group(proc)
            raise
        wall = time.monotonic() - start
        out.seek(0)
        err.seek(0)
        stdout, stderr = out.read(), err.read()
    lines = [line for line in stdout.splitlines() if line.strip()]
    if proc.returncode != 0 or not lines:
        tail = (stderr.strip().splitlines() or stdout.strip().splitlines() or ["(no output)"])[-1]
        return {"error": f"{script} exited {proc.returncode}: {tail[:300]}"}
    try:
        figure = json.loads(lines[-1])
        float(figure["vectors_per_s"])
    except (ValueError, KeyError, TypeError):
        return {"error": f"{script}: the last line is not the benchmark's JSON object: {lines[-1][:200]!r}"}
    figure["wall_seconds"] = wall
    if peak:
        figure["peak_mib"] = max(peak.values()) / 1024
    return figure


# ---------------------------------------------------------------------------------------------------
# Selecting languages


def _scripts(root: Path) -> dict:
    return {p.parent.name: p for p in sorted((root / "verifiers").glob("*/bench")) if os.access(p, os.X_OK)}


def _select(requested, known) -> list:
    """The languages asked for (all known ones when none), in the order of `known`; an unknown or
    empty name is a usage error listing the known ones."""
    if not requested:
        return list(known)
    names = [name.strip() for item in requested for name in item.split(",")]
    unknown = sorted({name for name in names if name not in known})
    if unknown:
        shown = ", ".join(repr(name) if not name else name for name in unknown)
        raise PlcvecError(f"bench-native --lang {shown}: no verifiers/<lang>/bench of that name "
                          f"(known: {', '.join(known) or 'none'})")
    return [lang for lang in known if lang in names]


# ---------------------------------------------------------------------------------------------------
# The comparison: interleaving and arithmetic (the runner is a parameter, so that tests can give one)


@dataclass
class Comparison:
    lang: str
    baseline: list = field(default_factory=list)   # figures, one per round
    current: list = field(default_factory=list)
    error: str | None = None                       # why it could not be compared
    current_failed: bool = False                   # the error is this tree's (not the baseline's)


def compare(langs, baseline_runners, current_runners, rounds, progress=lambda message: None):
    """Each language measured on both sides: one run of each that builds it (not counted), then
    `rounds` rounds, baseline then current in the odd rounds and current then baseline in the even
    ones, so that a machine slowing down (or speeding up) over the run weighs on both sides alike
    rather than on whichever always runs second. `baseline_runners[lang](build=...)` and
    `current_runners[lang](build=...)` return a bench's figure or {"error": ...}; a language whose
    baseline bench is absent has None.
    A failure on either side ends that language's comparison (its other rounds are not run)."""
    results = []
    for lang in langs:
        result = Comparison(lang)
        results.append(result)
        if baseline_runners.get(lang) is None:
            result.error = f"the baseline revision has no executable verifiers/{lang}/bench"
            continue
        sides = (("baseline", baseline_runners[lang], result.baseline),
                 ("current", current_runners[lang], result.current))
        stages = [("building and a first run", "", True)] + [
            (f"round {i} of {rounds}", f", round {i}", False) for i in range(1, rounds + 1)]
        for n, (stage, where, build) in enumerate(stages):
            for side, runner, figures in (sides if n % 2 == 1 or build else sides[::-1]):
                progress(f"{lang}: {stage} ({side})")
                figure = runner(build=build)
                if "error" in figure:
                    result.error, result.current_failed = f"{side}{where}: {figure['error']}", side == "current"
                    progress(f"{lang}: {side}{where} failed")
                    break
                progress(f"{lang}: {stage} ({side}): {float(figure['vectors_per_s']):,.0f} vectors/s"
                         + (f" in {figure['wall_seconds']:.0f} s" if "wall_seconds" in figure else ""))
                if not build:
                    figures.append(figure)
            if result.error:
                break
    return results


def spread(values):
    """(max - min) / median: how far apart the rounds of one side are, as a fraction of their median."""
    return (max(values) - min(values)) / statistics.median(values)


def summary(result: Comparison) -> dict:
    """The figures of one compared language: per side the median vectors/s and its spread, the vector
    counts, the medians of seconds per pass, loading seconds and peak memory where given; the ratio
    current / baseline of the medians, the range of the round-by-round ratios, and the same ratio by
    CPU time where both benches give cpu_vectors_per_s in every round.

    Two more ratios, for a machine shared with other work, whose load comes and goes over seconds:
    `paired_ratio`, the median of the round-by-round ratios (each of two runs a moment apart, so a
    slow minute weighs on both), and `best_ratio`, the fastest round of this tree over the fastest
    round of the baseline (work from other programs only ever slows a run down, so the fastest round
    of each side is the one least disturbed: timeit's reading of repeated timings)."""
    out = {"lang": result.lang}
    for side in ("baseline", "current"):
        figures = getattr(result, side)
        rates = [float(f["vectors_per_s"]) for f in figures]
        one = {"vectors": sorted({int(f.get("vectors", 0)) for f in figures}),
               "vectors_per_s": statistics.median(rates), "spread": spread(rates), "rounds": rates}
        for key in ("seconds", "load_seconds", "peak_mib", "cpu_vectors_per_s"):
            values = [float(f[key]) for f in figures if key in f]
            one[key] = statistics.median(values) if len(values) == len(figures) else None
        out[side] = one
    base, cur = out["baseline"], out["current"]
    out["ratio"] = cur["vectors_per_s"] / base["vectors_per_s"]
    per_round = [c / b for b, c in zip(base["rounds"], cur["rounds"])]
    out["round_ratios"] = (min(per_round), max(per_round))
    out["paired_ratio"] = statistics.median(per_round)
    out["best_ratio"] = max(cur["rounds"]) / max(base["rounds"])
    out["cpu_ratio"] = (cur["cpu_vectors_per_s"] / base["cpu_vectors_per_s"]
                        if cur["cpu_vectors_per_s"] and base["cpu_vectors_per_s"] else None)
    return out


def _num(value, fmt, width):
    return f"{'-' if value is None else format(value, fmt):>{width}}"


def same_counts(results, mode="--same-vectors"):
    """Under --same-vectors or --common-vectors (`mode`, named in the message): a compared language whose sides reported different numbers of vectors
    is not compared after all (they did not judge the same vectors). The languages it was so for."""
    differed = []
    for result in results:
        if result.error:
            continue
        counts = {side: sorted({int(f.get("vectors", 0)) for f in getattr(result, side)}) for side in ("baseline", "current")}
        if counts["baseline"] != counts["current"] or len(counts["current"]) != 1:
            shown = " and ".join(f"{'/'.join(map(str, n))} ({side})" for side, n in counts.items())
            result.error = (f"{mode}: the two sides judged different numbers of vectors, {shown}: a bench that "
                            "does not read PLCVEC_VECTORS, or a loader that left vectors out")
            differed.append(result.lang)
    return differed


def print_comparison(results, base_label, rounds, file=None, vectors=None):
    file = file or sys.stdout
    print(f"bench-native: this tree against {base_label}, {rounds} round(s) of the two in turn (baseline first in odd "
          "rounds, this tree first in even ones), after one run of each that builds it (not counted); vectors/s is the "
          "median of the rounds, spread (max - min) / median", file=file)
    if vectors is not None:
        print(f"both sides judged the same vectors: {vectors}", file=file)
    head = (f"{'language':10} {'side':16} {'vectors':>8} {'vectors/s':>12} {'spread':>7} {'s/pass':>10} "
            f"{'load s':>7} {'peak MiB':>8} {'CPU vectors/s':>13}")
    print(head, file=file)
    summaries = []
    for result in results:
        if result.error:
            print(f"{result.lang:10} not compared: {result.error}", file=file)
            continue
        s = summary(result)
        summaries.append(s)
        for side, label in (("baseline", base_label), ("current", "this tree")):
            one = s[side]
            print(f"{result.lang if side == 'baseline' else '':10} {label[:16]:16} "
                  f"{'/'.join(f'{n:,}' for n in one['vectors']):>8} {one['vectors_per_s']:>12,.0f} "
                  f"{one['spread'] * 100:>6.1f}% {_num(one['seconds'], '.6f', 10)} {_num(one['load_seconds'], '.3f', 7)} "
                  f"{_num(one['peak_mib'], '.1f', 8)} {_num(one['cpu_vectors_per_s'], ',.0f', 13)}", file=file)
        low, high = s["round_ratios"]
        print(f"{'':10} {'this / baseline':16} {s['ratio']:>20.3f}x by the clock (rounds {low:.3f}x to {high:.3f}x, "
              f"median of the rounds {s['paired_ratio']:.3f}x, fastest round over fastest {s['best_ratio']:.3f}x)"
              + (f", {s['cpu_ratio']:.3f}x by CPU time" if s["cpu_ratio"] else ""), file=file)
    print("peak MiB: the benchmark program's own peak resident memory (not its build's); "
          "CPU vectors/s: where the bench reports it", file=file)
    print(json.dumps({"baseline": base_label, "rounds": rounds, "same_vectors": None if vectors is None else str(vectors),
                      "compared": {s["lang"]: {"ratio": round(s["ratio"], 4),
                                               "paired_ratio": round(s["paired_ratio"], 4),
                                               "best_ratio": round(s["best_ratio"], 4),
                                               "cpu_ratio": round(s["cpu_ratio"], 4) if s["cpu_ratio"] else None,
                                               "baseline_vectors_per_s": round(s["baseline"]["vectors_per_s"]),
                                               "current_vectors_per_s": round(s["current"]["vectors_per_s"]),
                                               "baseline_vectors": s["baseline"]["vectors"],
                                               "current_vectors": s["current"]["vectors"]} for s in summaries},
                      "not_compared": {r.lang: r.error for r in results if r.error}}), file=file)
    return summaries


# ---------------------------------------------------------------------------------------------------
# The baseline's worktree


def _git(root, *args, timeout=300):
    try:
        return subprocess.run(["git", "-C", str(root), *args], capture_output=True, text=True, timeout=timeout,
                              stdin=subprocess.DEVNULL)
    except (OSError, subprocess.TimeoutExpired) as exc:
        raise PlcvecError(f"bench-native --baseline: git {args[0]} failed: {exc}") from None


def resolve_revision(root, rev) -> str:
    found = _git(root, "rev-parse", "--verify", "--quiet", "--end-of-options", f"{rev}^{{commit}}", timeout=60)
    if found.returncode:
        raise PlcvecError(f"bench-native --baseline: {rev!r} is not a commit of the git repository at {root}")
    return found.stdout.strip()


class BaselineWorktree:
    """Revision `commit` checked out (detached) in a temporary `git worktree` of the repository at
    `root`; on leaving, the worktree is removed (and git's record of it), whatever ended the block."""

    def __init__(self, root, commit):
        self.root, self.commit = Path(root), commit
        self.tmp = self.path = None

    def __enter__(self):
        self.tmp = Path(tempfile.mkdtemp(prefix="plcvec-bench-native-"))
        self.path = self.tmp / "baseline"
        try:
            added = _git(self.root, "worktree", "add", "--detach", str(self.path), self.commit)
            if added.returncode:
                raise PlcvecError(f"bench-native --baseline: git worktree add {self.commit[:12]} failed: "
                                  f"{added.stderr.strip()}")
        except BaseException:
            self.remove()
            raise
        return self

    def __exit__(self, *exc):
        self.remove()
        return False

    def remove(self):
        if self.path is not None:
            try:
                removed = _git(self.root, "worktree", "remove", "--force", "--force", str(self.path)).returncode == 0
            except PlcvecError:
                removed = False
            if not removed:
                shutil.rmtree(self.path, ignore_errors=True)
                # Git's record of the worktree whose folder is now gone (or of an `add` that failed
                # half way); prune touches no worktree whose folder is still there.
                try:
                    _git(self.root, "worktree", "prune")
                except PlcvecError as exc:
                    print(f"plcvec: {exc}; `git worktree prune` removes the record of {self.path}", file=sys.stderr)
        if self.tmp is not None:
            shutil.rmtree(self.tmp, ignore_errors=True)


def _terminate_as_interrupt(signum, frame):
    raise KeyboardInterrupt


def run_baseline(args, root: Path, progress=None, invoke_bench=invoke):
    rounds = args.rounds or DEFAULT_ROUNDS
    vectors = None
    if getattr(args, "same_vectors", False):
        if not getattr(args, "vectors", None):
            raise PlcvecError("bench-native --same-vectors: name the vector folder both sides judge with --vectors")
        vectors = Path(args.vectors).resolve()
        if not vectors.exists():
            raise PlcvecError(f"bench-native --same-vectors: {vectors}: no such vector folder or file")
    common = getattr(args, "common_vectors", False)
    if common and vectors is not None:
        raise PlcvecError("bench-native: --same-vectors and --common-vectors each choose the vectors both sides judge; give one")
    here = _scripts(root)
    langs = _select(args.lang, list(here))
    if not langs:
        raise PlcvecError(f"{root / 'verifiers'}: no native verifier has a `bench` script")
    commit = resolve_revision(root, args.baseline)
    label = args.baseline if commit.startswith(args.baseline) else f"{args.baseline} ({commit[:7]})"
    progress = progress or (lambda message: print(f"bench-native: {message}", file=sys.stderr, flush=True))
    # A run ended by SIGTERM removes its worktree too (only the main thread may set a handler).
    main_thread = threading.current_thread() is threading.main_thread()
    previous = signal.signal(signal.SIGTERM, _terminate_as_interrupt) if main_thread else None
    try:
        with BaselineWorktree(root, commit) as tree:
            there = _scripts(tree.path)
            theirs = shown = vectors
            if common:
                from plcvec.common_vectors import COMPILED_IN, compiled_in_copy, describe, export_into, write_common

                vectors, theirs = tree.tmp / "common", tree.tmp / "common-baseline"
                shown = describe(write_common(tree.path, Path(args.vectors or root / "vectors"), vectors, theirs))
                progress(shown)
                export_into(tree.path, theirs)
                here = {lang: compiled_in_copy(root, lang, vectors, tree.tmp / "current") if lang in COMPILED_IN
                        else script for lang, script in here.items()}

            def runner(script, folder):
                return lambda build: invoke_bench(script, timeout=BUILD_TIMEOUT_S if build else TIMEOUT_S, vectors=folder)

            results = compare(langs, {lang: runner(there[lang], theirs) if lang in there else None for lang in langs},
                              {lang: runner(here[lang], vectors) for lang in langs}, rounds, progress)
            mode = "--common-vectors" if common else "--same-vectors"
            differed = same_counts(results, mode) if vectors is not None else []
    finally:
        if main_thread:
            signal.signal(signal.SIGTERM, previous)
    summaries = print_comparison(results, label, rounds, vectors=shown)
    sys.stdout.flush()
    if not summaries:
        print("plcvec: bench-native --baseline: no language could be compared", file=sys.stderr)
        return 1
    # Asked for the same vectors and not given them: not a measurement to pass on.
    return 1 if differed or any(r.current_failed for r in results) else 0


# ---------------------------------------------------------------------------------------------------


def run(args):
    if not args.root:
        raise PlcvecError("bench-native: not in a plcvec checkout; name the repository with --root"
                          + ("" if args.baseline else " and the vectors with --vectors"))
    root = Path(args.root)
    if args.baseline:
        return run_baseline(args, root)
    if args.rounds is not None:
        raise PlcvecError("bench-native: --rounds is for --baseline (without it each bench runs once)")
    if args.common_vectors:
        raise PlcvecError("bench-native: --common-vectors is for --baseline (it compares two revisions' vector sets)")
    if args.same_vectors:
        raise PlcvecError("bench-native: --same-vectors is for --baseline (without it each bench judges its own golden set)")
    if not args.vectors:
        raise PlcvecError("bench-native: not in a plcvec checkout; name the repository with --root and the vectors with --vectors")
    from plcvec_verify.bench import in_process_rate

    scripts = _scripts(root)
    langs = _select(args.lang, list(scripts))
    if not langs:
        raise PlcvecError(f"{root / 'verifiers'}: no native verifier has a `bench` script")
    n, python_rate = in_process_rate(args.vectors)
    print(f"{'judging the golden set in process, after loading':50} {'vectors':>8} {'vectors/s':>12} {'x Python':>9}")
    print(f"{'python (reference)':50} {n:>8,} {python_rate:>12,.0f} {1:>9.1f}")
    failed = False
    for lang in langs:
        figure = invoke(scripts[lang])
        if "error" in figure:
            print(f"{lang:50} {'':>8} {'failed':>12}   {figure['error']}")
            failed = True
            continue
        rate = float(figure["vectors_per_s"])
        label = f"{lang} ({figure.get('note', '')})" if figure.get("note") else lang
        print(f"{label[:50]:50} {int(figure.get('vectors', 0)):>8,} {rate:>12,.0f} {rate / python_rate:>9.1f}"
              + (f"   load {float(figure['load_seconds']):.3f} s" if "load_seconds" in figure else ""))
        if "guarded_vectors_per_s" in figure:
            # The same vectors through the per-vector bound a user's test run puts on each, and its
            # share of the speed of the same judging without it (guarded_ratio, the bench's own).
            # The unguarded judging it is set against is the bench's own loop, which need not be the
            # headline figure's (a bench's headline may judge by a faster path than a test run's):
            # shown where the bench gives it, so that the two figures on the line are the pair.
            guarded = float(figure["guarded_vectors_per_s"])
            unguarded = figure.get("unguarded_loop_vectors_per_s")
            print(f"{'  ' + lang + ', under the per-vector bound':50} {int(figure.get('vectors', 0)):>8,} {guarded:>12,.0f} "
                  f"{guarded / python_rate:>9.1f}   x {float(figure['guarded_ratio']):.2f} of unguarded"
                  + (f" ({float(unguarded):,.0f} vectors/s, the same judging without the bound)" if unguarded else ""))
    sys.stdout.flush()
    return 1 if failed else 0
