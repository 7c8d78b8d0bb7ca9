"""The vectors two revisions judge alike: `plcvec bench-native --baseline REV --common-vectors`.

Two releases' golden sets differ (vectors merged, added, their expectations refined), and an older
reference fails some of today's vectors, so neither side's set can be judged by both. What both can
judge is the part they agree on: the vectors whose every field that takes part in judging (the
instruction, the initial state, the steps, the outcome, the final state, the alternatives, `st` and
`assumes`) is the same in this tree and at REV under the same id. Their descriptions, tags and
clause citations may differ: those are read by people, not by a judge.

Each side gets that set in its own revision's format: this tree's family files cut to those ids
(named to its benches by PLCVEC_VECTORS), and REV's own family files cut to the same ids, which
REV's `plcvec export` then writes into REV's worktree, so that a bench of REV that judges the copy
embedded in its verifier (rather than reading PLCVEC_VECTORS) judges the same vectors too.
"""
from __future__ import annotations

import hashlib
import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

from plcvec.errors import PlcvecError

# The fields a judge reads; the rest of a vector (id, family, description, tags, clauses) is prose
# or bookkeeping, which two releases may word differently for the same judgement.
JUDGED = ("instruction", "initial", "steps", "outcome", "final", "alternatives", "st", "assumes")
EXPORT_TIMEOUT_S = 600
# Runners whose vectors are compiled in and that refuse PLCVEC_VECTORS (verifiers/c/src/settings.c):
# this tree's side of such a runner is a copy of its folder with the common set exported into it.
COMPILED_IN = ("c",)


def judged(vector: dict) -> dict:
    return {key: vector.get(key) for key in JUDGED}


def _fail(message):
    raise PlcvecError(f"bench-native --common-vectors: {message}")


def _load(path: Path):
    try:
        return json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError) as exc:
        _fail(f"{path}: {exc}")


def _dump(data) -> bytes:
    return (json.dumps(data, indent=2, ensure_ascii=False) + "\n").encode("utf-8")


def _write_folder(manifest: dict, families: dict, out: Path):
    """A vector folder of `families` ({family: family file data}) under `manifest` (a copy of the
    revision's own, its counts, hashes and total set to what is written)."""
    out.mkdir(parents=True, exist_ok=True)
    manifest = json.loads(json.dumps(manifest))
    for family, entry in manifest.get("families", {}).items():
        data = _dump(families[family])
        (out / entry["file"]).write_bytes(data)
        entry["count"], entry["sha256"] = len(families[family]["vectors"]), hashlib.sha256(data).hexdigest()
        # The per-outcome and per-tag counts describe the whole set; left out rather than wrong.
        entry.pop("outcomes", None)
        entry.pop("tags", None)
    manifest.pop("csv", None)   # vectors.csv is not written: no bench reads it
    if "total" in manifest:
        manifest["total"] = sum(len(f["vectors"]) for f in families.values())
    (out / "manifest.json").write_bytes(_dump(manifest))


def write_common(baseline_tree: Path, vectors: Path, current_out: Path, baseline_out: Path) -> dict:
    """Write the vectors this tree's folder `vectors` and the worktree `baseline_tree` (its
    `vectors/`) judge alike, each in its own format, into `current_out` and `baseline_out`;
    returns {family: (kept, this tree's count, the baseline's count)}. Refuses a set with nothing in
    common: a benchmark of no vectors measures nothing."""
    mine, theirs = _load(vectors / "manifest.json"), _load(baseline_tree / "vectors" / "manifest.json")
    current, baseline, kept = {}, {}, {}
    for family, entry in sorted(mine.get("families", {}).items()):
        if not isinstance(entry, dict) or not isinstance(entry.get("file"), str):
            _fail(f"{vectors / 'manifest.json'}: family {family} names no `file`; is this a plcvec vector folder?")
        new = _load(vectors / entry["file"])
        old_entry = theirs.get("families", {}).get(family)
        old = _load(baseline_tree / "vectors" / old_entry["file"]) if old_entry else {"vectors": []}
        before = {v["id"]: v for v in old["vectors"]}
        same = [v["id"] for v in new["vectors"] if v["id"] in before and judged(before[v["id"]]) == judged(v)]
        kept[family] = (len(same), len(new["vectors"]), len(old["vectors"]))
        ids = set(same)
        current[family] = {**new, "count": len(same), "vectors": [v for v in new["vectors"] if v["id"] in ids]}
        if old_entry:
            baseline[family] = {**old, "count": len(same), "vectors": [v for v in old["vectors"] if v["id"] in ids]}
    if not sum(n for n, _, _ in kept.values()):
        _fail(f"no vector of {vectors} judges alike at the baseline")
    _write_folder(mine, current, current_out)
    theirs["families"] = {f: e for f, e in theirs.get("families", {}).items() if f in baseline}
    _write_folder(theirs, baseline, baseline_out)
    return kept


def _export(which: list, vectors: Path, root: Path, pythonpath: str | None, whose: str):
    env = {k: v for k, v in os.environ.items() if not k.startswith("PLCVEC_")}
    if pythonpath is not None:
        env["PYTHONPATH"] = pythonpath
    try:
        done = subprocess.run([sys.executable, "-m", "plcvec", "export", *which, "--vectors", str(vectors),
                               "--root", str(root)], cwd=root, env=env, capture_output=True,
                              text=True, timeout=EXPORT_TIMEOUT_S, stdin=subprocess.DEVNULL)
    except (OSError, subprocess.TimeoutExpired) as exc:
        _fail(f"{whose} plcvec export failed: {exc}")
    if done.returncode:
        _fail(f"{whose} plcvec export exited {done.returncode}: {(done.stderr or done.stdout).strip()[-800:]}")


def export_into(baseline_tree: Path, vectors: Path):
    """The baseline's own `plcvec export --all` of `vectors` into its worktree (its code, not this
    tree's: the copies embedded in its verifiers are written in its format)."""
    _export(["--all"], vectors, baseline_tree,
            os.pathsep.join(str(baseline_tree / p) for p in ("generator", "verifiers/python")), "the baseline's")


def compiled_in_copy(root: Path, lang: str, vectors: Path, dest: Path) -> Path:
    """This tree's `verifiers/<lang>` (its build folders left out) copied under `dest`, with this
    tree's export of `vectors` written into it; the copy's bench script."""
    (dest / "verifiers").mkdir(parents=True, exist_ok=True)
    shutil.copytree(root / "verifiers" / lang, dest / "verifiers" / lang,
                    ignore=shutil.ignore_patterns("build", "build-*", "target", "node_modules"))
    shutil.copy2(root / "verifiers" / "CONTRACT.md", dest / "verifiers" / "CONTRACT.md")   # its tables are written too
    _export(["--lang", lang], vectors, dest, None, "this tree's")
    return dest / "verifiers" / lang / "bench"


def describe(kept: dict) -> str:
    total = sum(n for n, _, _ in kept.values())
    parts = ", ".join(f"{family} {n} of {mine} (baseline {theirs})" for family, (n, mine, theirs) in kept.items())
    return f"{total:,} vectors judged alike by both revisions: {parts}"
