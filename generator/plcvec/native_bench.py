"""`plcvec bench-native`: each native verifier's speed beside the Python verifier's, in one run.

Every language folder `verifiers/<lang>/` that has an executable `bench` is run; it builds what it
needs, judges the golden set with that language's reference implementation in process, after
loading, and prints as its last line one JSON object:

    {"lang": "rust", "vectors": 2899, "passes": 20, "load_seconds": 0.041,
     "seconds": 0.0021, "vectors_per_s": 1380000, "note": "median of 20 passes after 3 warm-up"}

(`seconds` is one pass). The Python figure is the same measurement with the Python reference
(plcvec_verify.bench.in_process_rate), taken in this run, so each ratio compares like with like
on the same machine at the same moment.
"""
from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

from plcvec.errors import PlcvecError

TIMEOUT_S = 900      # one language's build and benchmark; a hung one is reported, not waited on


def register(sub, spec_parent):
    b = sub.add_parser("bench-native", help="vectors/s of each native verifier (verifiers/<lang>/bench) beside Python's")
    b.add_argument("--lang", action="append", metavar="L", help="only this language (repeatable)")
    from plcvec_verify.locate import checkout

    root = checkout()   # the checkout in use (plcvec_verify/locate.py): the native verifiers live only there
    b.add_argument("--vectors", default=str(root / "vectors") if root else None, help="the vector folder for the Python figure")
    b.add_argument("--root", default=str(root) if root else None,
                   help="the repository holding verifiers/ (default: %(default)s)")
    b.set_defaults(func=run)


def _native(script: Path) -> dict:
    try:
        proc = subprocess.run([str(script)], cwd=script.parent, capture_output=True, text=True,
                              timeout=TIMEOUT_S, stdin=subprocess.DEVNULL)
    except subprocess.TimeoutExpired:
        return {"error": f"no result within {TIMEOUT_S} s"}
    except OSError as exc:
        return {"error": f"cannot run {script}: {exc.strerror or exc}"}
    lines = [line for line in proc.stdout.splitlines() if line.strip()]
    if proc.returncode != 0 or not lines:
        tail = (proc.stderr.strip().splitlines() or ["(no output)"])[-1]
        return {"error": f"{script} exited {proc.returncode}: {tail}"}
    try:
        figure = json.loads(lines[-1])
        float(figure["vectors_per_s"])
    except (ValueError, KeyError, TypeError):
        return {"error": f"{script}: the last line is not the benchmark's JSON object: {lines[-1][:200]!r}"}
    return figure


def run(args):
    from plcvec_verify.bench import in_process_rate

    if not args.root or not args.vectors:
        raise PlcvecError("bench-native: not in a plcvec checkout; name the repository with --root and the vectors with --vectors")
    root = Path(args.root)
    scripts = sorted(p for p in (root / "verifiers").glob("*/bench") if os.access(p, os.X_OK))
    if args.lang:
        known = {p.parent.name for p in scripts}
        unknown = sorted(set(args.lang) - known)
        if unknown:
            raise PlcvecError(f"--lang {', '.join(unknown)}: no verifiers/<lang>/bench (have: {', '.join(sorted(known)) or 'none'})")
        scripts = [p for p in scripts if p.parent.name in args.lang]
    if not scripts:
        raise PlcvecError(f"{root / 'verifiers'}: no native verifier has a `bench` script")
    n, python_rate = in_process_rate(args.vectors)
    print(f"{'judging the golden set in process, after loading':50} {'vectors':>8} {'vectors/s':>12} {'x Python':>9}")
    print(f"{'python (reference)':50} {n:>8,} {python_rate:>12,.0f} {1:>9.1f}")
    failed = False
    for script in scripts:
        lang = script.parent.name
        figure = _native(script)
        if "error" in figure:
            print(f"{lang:50} {'':>8} {'failed':>12}   {figure['error']}")
            failed = True
            continue
        rate = float(figure["vectors_per_s"])
        label = f"{lang} ({figure.get('note', '')})" if figure.get("note") else lang
        print(f"{label[:50]:50} {int(figure.get('vectors', 0)):>8,} {rate:>12,.0f} {rate / python_rate:>9.1f}"
              + (f"   load {float(figure['load_seconds']):.3f} s" if "load_seconds" in figure else ""))
    sys.stdout.flush()
    return 1 if failed else 0
