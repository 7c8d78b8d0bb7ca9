"""`plcvec bench`: how fast the golden set and the exhaustive tier are made, and in how much memory.

Each measurement runs in a child process so that its peak resident memory is its own.
"""
import json
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

GOLDEN_TARGET_S = 10.0
EXHAUSTIVE_TARGET_PER_S = 100_000


def _child(args):
    start = time.perf_counter()
    proc = subprocess.Popen([sys.executable, "-m", "plcvec", *args], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    _, status, usage = os.wait4(proc.pid, 0)
    seconds = time.perf_counter() - start
    out, err = proc.stdout.read(), proc.stderr.read()
    proc.returncode = os.waitstatus_to_exitcode(status)
    if proc.returncode:
        raise SystemExit(f"plcvec bench: `plcvec {' '.join(args)}` failed ({proc.returncode}):\n{err}")
    return seconds, usage.ru_maxrss / 1024, out


def run_benchmark(spec_dir, out_dir=None, verify=True):
    from plcvec.output.golden import build_golden
    from plcvec.spec.loader import load_spec

    with tempfile.TemporaryDirectory(prefix="plcvec-bench-") as tmp:
        work = Path(out_dir or tmp)
        rows = []
        # Golden set, in process (generation alone) and as a user runs it (interpreter start included).
        families = load_spec(spec_dir)
        start = time.perf_counter()
        _, by_family = build_golden(families)
        inproc = time.perf_counter() - start
        count = sum(len(v) for v in by_family.values())
        seconds, rss, _ = _child(["generate", "--spec-dir", str(spec_dir), "--out", str(work / "golden")])
        rows.append(("golden set, in process", count, inproc, None))
        rows.append(("golden set, `plcvec generate`", count, seconds, rss))
        # Exhaustive tier: one family, then all, to show memory does not grow with the number written.
        names = [f.name for f in families if f.kind == "masked_compare"]
        for label, only in (("exhaustive tier, 1 family", names[:1]), (f"exhaustive tier, {len(names)} families", names)):
            args = ["exhaustive", "--spec-dir", str(spec_dir), "--out", str(work / "exhaustive")]
            for name in only:
                args += ["--family", name]
            seconds, rss, out = _child(args)
            n = int(out.split()[2])
            rows.append((label, n, seconds, rss))
    print(f"{'measurement':34} {'vectors':>10} {'seconds':>9} {'vectors/s':>12} {'peak RSS MiB':>13}")
    for label, n, seconds, rss in rows:
        print(f"{label:34} {n:>10,} {seconds:>9.2f} {n / seconds:>12,.0f} {('%.1f' % rss) if rss else '-':>13}")
    golden_s = rows[1][2]
    ex_rate = rows[3][1] / rows[3][2]
    flat = rows[3][3] / rows[2][3]
    print(f"targets: golden set <= {GOLDEN_TARGET_S:.0f} s: {'met' if golden_s <= GOLDEN_TARGET_S else 'MISSED'} ({golden_s:.2f} s); "
          f"exhaustive >= {EXHAUSTIVE_TARGET_PER_S:,}/s: {'met' if ex_rate >= EXHAUSTIVE_TARGET_PER_S else 'MISSED'} ({ex_rate:,.0f}/s); "
          f"memory {rows[3][1] / rows[2][1]:.0f}x the vectors in {flat:.2f}x the peak RSS")
    print(json.dumps({"golden_seconds": round(golden_s, 3), "exhaustive_vectors_per_s": round(ex_rate),
                      "exhaustive_peak_rss_mib": round(rows[3][3], 1), "memory_ratio_3_vs_1_family": round(flat, 3)}))
    if verify:
        # The verifier's own figures, on the committed vectors it ships with (plcvec_verify/bench.py).
        from plcvec_verify.bench import print_verify_benchmark
        from plcvec_verify.locate import default_vectors

        print()
        print_verify_benchmark(default_vectors().path)
    return 0
