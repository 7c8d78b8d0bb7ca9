"""The decision inventory (decisions.yaml beside this file): every point in the engine where an
observable outcome is decided, with the clauses, interpretations or assumptions it follows and a way
to flip it.

A decision cites a clause as `family#clause`, an interpretation by its id, and an assumption of a
family's spec (`assumptions:`, a convention the pages do not state, such as what the vector format
takes before a vector's first step) as `family#assumptions.name`. `plcvec review` lists the inventory
beside each cited clause's quote, each interpretation's question and each assumption's why; `--check`
fails on a decision that cites nothing, cites what the spec does not hold, or whose engine text
(`old`) is not found exactly once in its engine file (the inventory went stale). tests/test_decisions.py flips each decision (`old` -> `new` in the engine's
source, built as a module of its own) and requires that the family's vectors change.
"""
from __future__ import annotations

import re
from pathlib import Path

import yaml

from plcvec.errors import PlcvecError

INVENTORY = Path(__file__).resolve().parent / "decisions.yaml"
ENGINE = Path(__file__).resolve().parents[1] / "engine"
# How a decision names an assumption of a family's spec: family#assumptions.<name>.
ASSUMPTION = "assumptions."


def load_inventory(path: Path = INVENTORY) -> list[dict]:
    try:
        doc = yaml.safe_load(path.read_text(encoding="utf-8"))
    except (OSError, yaml.YAMLError) as exc:
        raise PlcvecError(f"{path}: cannot read the decision inventory ({exc})") from None
    decisions = doc.get("decisions") if isinstance(doc, dict) else None
    if not isinstance(decisions, list):
        raise PlcvecError(f"{path}: needs a `decisions` list")
    return decisions


def _line_of(text: str, snippet: str) -> int | None:
    at = text.find(snippet)
    return None if at < 0 else text.count("\n", 0, at) + 1


def inventory(families, path: Path = INVENTORY, engine: Path = ENGINE):
    """(rows for the review, problems) of the decision inventory against the spec and the engine; a
    problem is (line of the inventory file, message)."""
    clauses, interpretations, assumptions = {}, {}, {}
    for fam in families:
        for cid, c in fam.clauses.items():
            clauses[f"{fam.name}#{cid}"] = (fam, c)
        for iid, i in fam.interpretations.items():
            interpretations[iid] = (fam, i)
        for name, a in (fam.doc.get("assumptions") or {}).items():
            assumptions[f"{fam.name}#{ASSUMPTION}{name}"] = (fam, a)
    rows, problems = [], []
    seen = set()
    listing = path.read_text(encoding="utf-8")
    decisions = load_inventory(path)
    # A spec folder of some families only (a review of one family) holds only their clauses and
    # interpretations: what the others' would answer is not asked of it.
    loaded = {fam.name for fam in families}
    complete = {d.get("family") for d in decisions} <= loaded
    for n, d in enumerate(decisions):
        ident = d.get("id", f"#{n + 1}")
        found = re.search(rf"\bid: {re.escape(str(ident))}[,}}\s]", listing)
        at = listing.count("\n", 0, found.start()) + 1 if found else None
        where = f"decision {ident}"
        problems_before = len(problems)
        if ident in seen:
            problems.append(f"{where}: the id is used twice")
        seen.add(ident)
        source = engine / str(d.get("engine", ""))
        text = source.read_text(encoding="utf-8") if source.is_file() else None
        line = None
        if text is None:
            problems.append(f"{where}: no engine file {d.get('engine')!r} in {engine}")
        else:
            count = text.count(d.get("old") or "\0")
            line = _line_of(text, d.get("old") or "\0")
            if count != 1:
                problems.append(f"{where}: its engine text is found {count} times in {source.name}, not once "
                                f"(the engine changed: update the inventory): {d.get('old')!r}")
        cites = d.get("cites") or []
        if not cites:
            problems.append(f"{where}: cites neither a clause nor an interpretation")
        cited = []
        for ref in cites:
            if ref in clauses:
                fam, c = clauses[ref]
                cited.append({"ref": ref, "kind": "clause", "text": c["source"].get("quote") or c["source"].get("states", ""),
                              "derived": bool(c.get("derived"))})
            elif ref in interpretations:
                fam, i = interpretations[ref]
                cited.append({"ref": ref, "kind": "interpretation", "text": i["question"], "derived": False})
            elif ref in assumptions:
                fam, a = assumptions[ref]
                cited.append({"ref": ref, "kind": "assumption", "text": a["why"], "derived": False})
            elif complete or ("#" in ref and ref.split("#", 1)[0] in loaded):
                problems.append(f"{where}: cites {ref!r}, which is no clause (family#id), interpretation or "
                                f"assumption (family#{ASSUMPTION}name) of the spec")
        problems[problems_before:] = [(at, message) for message in problems[problems_before:]]
        rows.append({"id": ident, "family": d.get("family", ""), "engine": d.get("engine", ""), "line": line,
                     "decides": d.get("decides", ""), "cites": cited})
    return rows, problems
