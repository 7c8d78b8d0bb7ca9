"""The report of a mutation run: the counts, then each missing decision by file:line (text), or every
mutant's record (JSON)."""
from __future__ import annotations

import json
from collections import Counter

from plcvec.mutation.oracle import CHANGE_CLASSES, FAILS, TIMEOUT, UNCHANGED
from plcvec.mutation.touch import COVERED, MISSING, RECORD, VERDICTS

COUNT_LINES = (
    ("changed vectors", (COVERED, MISSING, RECORD)),
    ("  covered by a decision", (COVERED,)),
    ("  missing decision", (MISSING,)),
    ("  clauses or model rows", (RECORD,)),
    ("no change", (UNCHANGED,)),
    ("generator fails", (FAILS,)),
    ("timeout", (TIMEOUT,)),
)
SHOWN_FAILURES = 5


def counts(run):
    """{verdict: mutants}, every verdict present (0 where none)."""
    found = Counter(j.verdict for j in run.judged)
    return {v: found.get(v, 0) for v in VERDICTS}


def text(run, sources):
    c = counts(run)
    what = (f"a sample of {len(run.judged)} of {run.total} mutants (--sample {run.sample[0]} --seed {run.sample[1]})"
            if run.sample else f"{len(run.judged)} mutants")
    lines = [f"plcvec mutation: {what} of the engine ({', '.join(run.files)}), judged against the committed "
             f"vectors in {run.seconds:.1f} s (timeout: {run.timeout:g} s of CPU time per mutant)"]
    lines += [f"  {label:<26}{sum(c[v] for v in verdicts):>6}" for label, verdicts in COUNT_LINES]
    missing = _by_line(j for j in run.judged if j.verdict == MISSING)
    if missing:
        lines.append(f"missing decisions: {len(missing)} line(s) where a mutant changes vectors and "
                     "review/decisions.yaml lists no decision:")
        for (file, line), judged in missing.items():
            lines.append(f"  {file}:{line}: {sources[file].splitlines()[line - 1].strip()}")
            for j in judged:
                lines.append(f"      {j.mutant.name}: {_mutated_line(j.mutant, sources)}; {_change(j.outcome)}")
    for verdict, label in ((TIMEOUT, "timed out"), (FAILS, "made the generator fail")):
        shown = [j for j in run.judged if j.verdict == verdict]
        if shown:
            lines.append(f"mutants that {label} ({len(shown)}" + (f", the first {SHOWN_FAILURES}" if len(shown) > SHOWN_FAILURES else "") + "):")
            lines += [f"  {j.mutant.name}" + (f": {j.outcome.error}" if j.outcome.error else "") for j in shown[:SHOWN_FAILURES]]
    lines.append("no missing decision" if not missing else
                 "add a decision for each line above (review/decisions.yaml), or report what the spec does not say")
    return "\n".join(lines) + "\n"


def as_json(run):
    """Every mutant's record, and the counts; the same for the same engine, spec and selection (times
    apart, under "seconds")."""
    return json.dumps({
        "total": run.total, "sample": list(run.sample) if run.sample else None, "files": list(run.files),
        "counts": counts(run), "timeout": run.timeout,
        "seconds": {"run": round(run.seconds, 1), "unmutated_cpu": round(run.unmutated_cpu_seconds, 2)},
        "mutants": [{"name": j.mutant.name, "file": j.mutant.file, "lines": list(j.mutant.lines),
                     "operator": j.mutant.operator, "occurrence": j.mutant.occurrence, "verdict": j.verdict,
                     "touches": j.touches, "family": j.outcome.family, "changes": j.outcome.counts, "ids": j.outcome.ids,
                     "error": j.outcome.error} for j in run.judged],
    }, indent=1) + "\n"


def _by_line(judged):
    out = {}
    for j in judged:
        out.setdefault((j.mutant.file, j.mutant.line), []).append(j)
    return out


def _mutated_line(mutant, sources):
    """The mutant's first changed line as it reads mutated."""
    mutated = mutant.mutated(sources[mutant.file])
    if mutated is None:
        return "(no change)"
    return "-> " + mutated.splitlines()[mutant.line - 1].strip()


def _change(outcome):
    parts = [f"{cls} {outcome.counts[cls]}" for cls in CHANGE_CLASSES if outcome.counts.get(cls)]
    return f"{outcome.family}: " + ", ".join(parts) + (f" ({', '.join(outcome.ids)})" if outcome.ids else "")
