"""Which vectors catch each mutant: the run behind MUTANTS.md and tests/test_mutants.py."""
from __future__ import annotations

from plcvec_verify import InProcess, Selection, Suite, run

from ..adapter import ReferenceAdapter
from .registry import MUTANTS

EXAMPLES = 3   # vector ids shown per mutant in MUTANTS.md


def run_mutant(suite: Suite, name: str, selection: Selection = Selection()):
    """The verifier's report on mutant `name`, run in process."""
    return run(suite, InProcess(ReferenceAdapter(mutant=name)), selection)


def examples(failed_ids, families, n: int = EXAMPLES) -> list[str]:
    """A few catching ids: one per family first, hand-made cases before random draws."""
    ranked = sorted(failed_ids, key=lambda vid: ("/random/" in vid, vid))
    picked = [next(v for v in ranked if v.startswith(f + "/")) for f in families
              if any(v.startswith(f + "/") for v in ranked)]
    picked += [v for v in ranked if v not in picked]
    return picked[:n]


def dimensions(m) -> str:
    """The coverage-model dimensions a mutant's bug lives in, with the classes its catchers exercise."""
    return "<br>".join(f"{dim}: {', '.join(f'`{p}`' for p in patterns)}" for dim, patterns in m.exercises) or "—"


def table(suite: Suite) -> str:
    lines = ["| mutant | family | the bug | model dimension (classes every catching vector exercises) | caught by (examples) |",
             "|---|---|---|---|---|"]
    for name, m in MUTANTS.items():
        failed = [r.id for r in run_mutant(suite, name).failed]
        ids = "<br>".join(f"`{vid}`" for vid in examples(failed, m.families)) or "**nothing: it survives**"
        lines.append(f"| `{name}` | {', '.join(m.families)} | {m.description} | {dimensions(m)} | {ids} |")
    return "\n".join(lines) + "\n"
