"""`plcvec bench`: how fast the golden set and the exhaustive tier are made, in how much memory, and
how fast the verifier judges the golden set.

Each measurement runs in a child process, so that its peak resident memory is its own and so that
another tree can be measured the same way: `--baseline REV` exports a git revision into a temporary
folder and measures its code (on its own spec and vectors) in the same run, each measurement of this
tree followed at once by the same measurement of the revision, and prints the two side by side with
the ratio of their speeds. A speed-up is then a ratio from one moment of the machine, not two
figures from two moments.
"""
import io
import json
import os
import shutil
import subprocess
import sys
import tarfile
import tempfile
import time
from pathlib import Path

from plcvec.errors import PlcvecError
from plcvec.output.workers import usable_cores

GOLDEN_TARGET_S = 10.0
GOLDEN_TARGET_RATIO = 10
EXHAUSTIVE_TARGET_PER_S = 300_000
VERIFY_TARGET_PER_S = 200_000
GOLDEN_PROCESSES = 3
VERIFY_PASSES = 5
VERIFY_PROCESSES = 5

# Run in a child with the tree's own code; the APIs they use are those of every revision since the
# verifier's Plan (build_golden, load_spec, Suite, Plan, run, InProcess, ReferenceAdapter). A revision
# whose build_golden takes no `jobs` builds in one process whatever it is asked. The CPU time counts
# the worker processes' (reaped before build_golden returns).
_GOLDEN_IN_PROCESS = """
import inspect, json, os, sys, time
from plcvec.output.golden import build_golden
from plcvec.spec.loader import load_spec
families = load_spec(sys.argv[1])
jobs = {"jobs": int(sys.argv[2])} if "jobs" in inspect.signature(build_golden).parameters else {}
start, cpu, before = time.perf_counter(), time.process_time(), os.times()
_, by_family = build_golden(families, **jobs)
seconds, after = time.perf_counter() - start, os.times()
children = after.children_user - before.children_user + after.children_system - before.children_system
print(json.dumps({"vectors": sum(len(v) for v in by_family.values()), "seconds": seconds,
                  "cpu": time.process_time() - cpu + children, "jobs": jobs.get("jobs", 1)}))
"""

# The verifier in process, steady state: requests and expectations prepared once, one pass to warm
# up, the median of the passes after it. "harness" answers from memory (the runner's own cost);
# "reference" runs the Python reference implementation (its time included).
_VERIFY_IN_PROCESS = """
import gc, json, statistics, sys, time
from plcvec_reference.adapter import ReferenceAdapter
from plcvec_verify.adapters import InProcess
from plcvec_verify.runner import Plan, run
from plcvec_verify.suite import Suite
suite = Suite.load(sys.argv[1])
plan = Plan(suite, suite.vectors, {})
gc.freeze()
reference = ReferenceAdapter()
answers = {v["id"]: reference.run(plan.requests[v["id"]]) for v in suite.vectors}

class Replay:
    def hello(self, request):
        return reference.hello(request)

    def run(self, request):
        return answers[request["id"]]

def seconds(adapter):
    # (wall, CPU) seconds of a pass over the golden set: the medians of the passes after the first.
    walls, cpus = [], []
    for i in range(int(sys.argv[2]) + 1):
        start, cpu = time.perf_counter(), time.process_time()
        report = run(suite, adapter, plan=plan)
        wall, cpu = time.perf_counter() - start, time.process_time() - cpu
        if report.exit_code != 0:
            raise SystemExit(f"the reference did not pass the golden set: {report.counts}")
        if i:
            walls.append(wall)
            cpus.append(cpu)
    return statistics.median(walls), statistics.median(cpus)

print(json.dumps({"vectors": len(suite.vectors), "harness": seconds(InProcess(Replay())),
                  "reference": seconds(InProcess(reference))}))
"""


class Tree:
    """Where a measured version of plcvec lives: its import roots, spec and vectors."""

    def __init__(self, label, root, spec_dir=None):
        self.label, self.root = label, root
        self.spec_dir = Path(spec_dir) if spec_dir else root / "spec"
        self.vectors_dir = root / "vectors"

    def env(self):
        """The environment that imports this tree's plcvec and plcvec_verify first."""
        return dict(os.environ, PYTHONPATH=os.pathsep.join([str(self.root / "generator"),
                                                              str(self.root / "verifiers" / "python")]))

    def child(self, args, what):
        """(seconds, CPU seconds, peak RSS MiB, stdout) of `python3 ARGS` run with this tree's code, from its root."""
        env = self.env()
        with tempfile.TemporaryFile("w+") as out, tempfile.TemporaryFile("w+") as err:
            start = time.perf_counter()
            proc = subprocess.Popen([sys.executable, *args], stdout=out, stderr=err, text=True, env=env, cwd=self.root)
            _, status, usage = os.wait4(proc.pid, 0)   # this child's own peak memory
            seconds = time.perf_counter() - start
            proc.returncode = os.waitstatus_to_exitcode(status)
            out.seek(0)
            err.seek(0)
            if proc.returncode:
                raise PlcvecError(f"bench: {what} failed for {self.label} ({proc.returncode}):\n{err.read().strip()}")
            return seconds, usage.ru_utime + usage.ru_stime, usage.ru_maxrss / 1024, out.read()


def current_tree(spec_dir):
    """The tree this plcvec is imported from (a checkout: the root above generator/plcvec)."""
    root = Path(__file__).resolve().parents[2]
    if not (root / "generator" / "plcvec").is_dir() or not (root / "verifiers" / "python").is_dir():
        raise PlcvecError(f"bench: the code is not in a source tree ({root}); run it from a checkout")
    return Tree("this tree", root, spec_dir)


def golden_in_process(tree, work, processes=GOLDEN_PROCESSES):
    """The golden set built in one process, then in as many as there are usable cores: each the run of
    median time of `processes` runs, since one process's figure can be a third off the next one's."""
    rows = []
    for jobs in sorted({1, usable_cores()}):
        runs = [json.loads(tree.child(["-c", _GOLDEN_IN_PROCESS, str(tree.spec_dir), str(jobs)],
                                      "the golden set in process")[3]) for _ in range(processes)]
        golden = sorted(runs, key=lambda run: run["seconds"])[len(runs) // 2]
        label = "1 process" if jobs == 1 else f"{jobs} processes"
        rows.append((f"golden set, in process, {label}", golden["vectors"], golden["seconds"], golden["cpu"], None))
    return rows


def golden_generate(tree, work):
    seconds, cpu, rss, _ = tree.child(["-m", "plcvec", "generate", "--spec-dir", str(tree.spec_dir), "--out",
                                  str(work / "golden")], "plcvec generate")
    count = json.loads((work / "golden" / "manifest.json").read_text("utf-8"))["total"]
    return [("golden set, `plcvec generate`", count, seconds, cpu, rss)]


def exhaustive(tree, work):
    """All families, then the first alone: memory must not grow with the number of lines written."""
    def one_run(families):
        args = ["-m", "plcvec", "exhaustive", "--spec-dir", str(tree.spec_dir), "--out", str(work / "exhaustive")]
        for name in families:
            args += ["--family", name]
        seconds, cpu, rss, out = tree.child(args, "plcvec exhaustive")
        names = sorted(p.name[:-len(".exhaustive.jsonl")] for p in (work / "exhaustive").glob("*.exhaustive.jsonl"))
        shutil.rmtree(work / "exhaustive")   # about a gigabyte for the families: do not keep it
        return (int(out.split()[2]), seconds, cpu, rss), names

    every, names = one_run(())
    one, _ = one_run(names[:1])
    return [("exhaustive tier, 1 family", *one), (f"exhaustive tier, {len(names)} families", *every)]


def verifier_in_process(tree, work):
    """The verifier's figures in VERIFY_PROCESSES processes, the median of each: a pass over the golden
    set takes tens of milliseconds, steady within a process, but one process's passes can be half as
    fast again as the next one's on this kind of machine."""
    runs = [json.loads(tree.child(["-c", _VERIFY_IN_PROCESS, str(tree.vectors_dir), str(VERIFY_PASSES)],
                                  "the verifier in process")[3]) for _ in range(VERIFY_PROCESSES)]
    rows = []
    for key, label in (("harness", "verify in process (harness only)"), ("reference", "verify in process (reference)")):
        wall, cpu = sorted(run[key] for run in runs)[len(runs) // 2]
        rows.append((label, runs[0]["vectors"], wall, cpu, None))
    return rows


MEASUREMENTS = (golden_in_process, golden_generate, exhaustive, verifier_in_process)


def export_revision(rev, dest):
    """The files of git revision `rev` (of the repository of the current folder) written into `dest`."""
    found = subprocess.run(["git", "rev-parse", "--verify", "--quiet", f"{rev}^{{commit}}"],
                           capture_output=True, text=True, timeout=60)
    if found.returncode:
        raise PlcvecError(f"bench --baseline: {rev!r} is not a commit of the git repository here "
                          f"({Path.cwd()})")
    commit = found.stdout.strip()
    archive = subprocess.run(["git", "archive", "--format=tar", commit], capture_output=True, timeout=300)
    if archive.returncode:
        raise PlcvecError(f"bench --baseline: git archive {rev} failed: {archive.stderr.decode().strip()}")
    with tarfile.open(fileobj=io.BytesIO(archive.stdout)) as tar:
        if hasattr(tarfile, "data_filter"):
            tar.extractall(dest, filter="data")
        else:  # Python without extraction filters; git archive writes plain files and folders
            tar.extractall(dest)
    return commit


def _cells(n, seconds, cpu, rss):
    return f"{n:>9,} {seconds:>8.2f} {n / seconds:>10,.0f} {n / cpu:>10,.0f} {('%.1f' % rss) if rss else '-':>6}"


_HEAD = f"{'vectors':>9} {'seconds':>8} {'vectors/s':>10} {'per CPU-s':>10} {'MiB':>6}"


def print_single(rows):
    print(f"{'measurement':36} {_HEAD}")
    for label, *cells in rows:
        print(f"{label:36} {_cells(*cells)}")


def print_side_by_side(rows, base_rows, base_label):
    """Each measurement of this tree beside the baseline's, with the ratio of their speeds: by the
    clock, and by the CPU time used (steadier on a machine other work shares)."""
    print(f"{'':36} {'this tree':^47}   {base_label:^47}   {'speed-up':^15}")
    print(f"{'measurement':36} {_HEAD}   {_HEAD}   {'wall':>7} {'CPU':>7}")
    for (label, *cells), (_, *base) in zip(rows, base_rows):
        wall = (cells[0] / cells[1]) / (base[0] / base[1])
        cpu = (cells[0] / cells[2]) / (base[0] / base[2])
        print(f"{label:36} {_cells(*cells)}   {_cells(*base)}   {wall:>6.1f}x {cpu:>6.1f}x")


def run_benchmark(spec_dir, out_dir=None, verify=True, baseline=None):
    tree = current_tree(spec_dir)
    with tempfile.TemporaryDirectory(prefix="plcvec-bench-") as tmp:
        work = Path(out_dir or tmp)
        base = None
        if baseline:
            commit = export_revision(baseline, Path(tmp) / "baseline")
            base = Tree(baseline if commit.startswith(baseline) else f"{baseline} ({commit[:7]})", Path(tmp) / "baseline")
        rows, base_rows = [], []
        for measurement in MEASUREMENTS:   # each on this tree, then at once on the baseline
            rows += measurement(tree, work / "this")
            if base:
                base_rows += measurement(base, work / "baseline")
    figures = {label: n / seconds for label, n, seconds, _, _ in rows}
    cpu_figures = {label: n / cpu for label, n, _, cpu, _ in rows}
    seconds_of = {label: seconds for label, _, seconds, _, _ in rows}
    rss = {label: r for label, _, _, _, r in rows}
    if base_rows:
        print_side_by_side(rows, base_rows, base.label)
    else:
        print_single(rows)
    in_process = [label for label in figures if label.startswith("golden set, in process")]
    golden_s = seconds_of["golden set, `plcvec generate`"]
    one_label, ex_label = [label for label in figures if label.startswith("exhaustive tier")]
    ex_rate, flat = figures[ex_label], rss[ex_label] / rss[one_label]
    harness = figures["verify in process (harness only)"]
    verdicts = [f"golden set <= {GOLDEN_TARGET_S:.0f} s: {_met(golden_s <= GOLDEN_TARGET_S)} ({golden_s:.2f} s)"]
    summary = {"golden_seconds": round(golden_s, 3),
               "golden_in_process_seconds": {label[len("golden set, in process, "):]: round(seconds_of[label], 3)
                                             for label in in_process},
               "exhaustive_vectors_per_s": round(ex_rate), "exhaustive_vectors_per_cpu_s": round(cpu_figures[ex_label]),
               "exhaustive_peak_rss_mib": round(rss[ex_label], 1), "memory_ratio_all_vs_1_family": round(flat, 3),
               "verify_in_process_harness_per_s": round(harness),
               "verify_in_process_harness_per_cpu_s": round(cpu_figures["verify in process (harness only)"])}
    if base_rows:
        # Each golden row against the baseline's row of the same name (the baseline builds in one
        # process in both when its build_golden takes no `jobs`): by the clock, and in CPU time.
        base_of = {label: (n / seconds, n / cpu) for label, n, seconds, cpu, _ in base_rows}
        ratios = {label[len("golden set, in process, "):]: (figures[label] / base_of[label][0],
                                                             cpu_figures[label] / base_of[label][1])
                  for label in in_process}
        best = max(wall for wall, _ in ratios.values())
        verdicts.append(f"golden set in process >= {GOLDEN_TARGET_RATIO}x {base.label}: {_met(best >= GOLDEN_TARGET_RATIO)} ("
                        + ", ".join(f"{how}: {wall:.1f}x by the clock, {cpu:.1f}x in CPU time"
                                    for how, (wall, cpu) in ratios.items()) + ")")
        summary.update(golden_in_process_speedup={how: round(wall, 2) for how, (wall, _) in ratios.items()},
                       golden_in_process_cpu_speedup={how: round(cpu, 2) for how, (_, cpu) in ratios.items()},
                       baseline=base.label)
    verdicts += [f"exhaustive >= {EXHAUSTIVE_TARGET_PER_S:,}/s: {_met(ex_rate >= EXHAUSTIVE_TARGET_PER_S)} ({ex_rate:,.0f}/s, "
                 f"{cpu_figures[ex_label]:,.0f} per CPU-second), peak RSS {rss[ex_label]:.1f} MiB for all families, "
                 f"{flat:.2f}x that of one",
                 f"verify in process, harness only >= {VERIFY_TARGET_PER_S:,}/s: "
                 f"{_met(harness >= VERIFY_TARGET_PER_S)} ({harness:,.0f}/s, "
                 f"{cpu_figures['verify in process (harness only)']:,.0f} per CPU-second)"]
    print("targets: " + "; ".join(verdicts))
    print(json.dumps(summary))
    if verify:
        # The verifier's full figures (batched stdio, a process per vector) for this tree.
        from plcvec_verify.bench import print_verify_benchmark
        from plcvec_verify.locate import default_vectors

        print()
        print_verify_benchmark(default_vectors().path)
    return 0


def _met(ok):
    return "met" if ok else "MISSED"
