"""What moving from one vector set to another changes for one implementation: the upgrade report.

`plcvec diff OLD NEW` lists every vector that changed. An implementer who pinned OLD wants less and
more: under the alternatives they declare, which vectors now expect something else of them; which
interpretations are new (each by id, question and default, since an undeclared one takes its
default); which declared alternative the new set no longer has; and what becomes of each id in
their known-failures file (kept, merged into another vector, or gone). The known failures another
reading explains are found by a run, not here: every runner's end-of-run text says so (TEXT.md,
"The roll-up by reading").
"""
from __future__ import annotations

from plcvec.errors import PlcvecError


def interpretations(vector_set) -> dict:
    """{id: {"question", "default", "alternatives": [ids], "families": [names]}} of a vector set's headers."""
    out = {}
    for name, fam in sorted(vector_set.families.items()):
        for interp in fam["header"].get("interpretations", ()):
            entry = out.setdefault(interp["id"], {"question": interp.get("question", ""), "default": interp["default"],
                                                  "alternatives": [a["id"] for a in interp["alternatives"]],
                                                  "families": []})
            entry["families"].append(name)
    return out


def interpretation_changes(old: dict, new: dict) -> list[dict]:
    """Interpretations added, removed, or whose default or alternatives changed, by id."""
    out = []
    for iid in sorted(set(old) | set(new)):
        a, b = old.get(iid), new.get(iid)
        if a is None:
            out.append({"id": iid, "change": "added", **b})
        elif b is None:
            out.append({"id": iid, "change": "removed", **a})
        else:
            entry = {"id": iid, "change": "changed", **b}
            if a["default"] != b["default"]:
                entry["old_default"] = a["default"]
            entry["alternatives_added"] = [x for x in b["alternatives"] if x not in a["alternatives"]]
            entry["alternatives_removed"] = [x for x in a["alternatives"] if x not in b["alternatives"]]
            if "old_default" in entry or entry["alternatives_added"] or entry["alternatives_removed"]:
                out.append(entry)
    return out


def interpretation_lines(changes: list[dict], indent: str = "  ") -> list[str]:
    lines = []
    for c in changes:
        if c["change"] == "added":
            lines.append(f"{indent}+ {c['id']} ({', '.join(c['families'])}): {c['question']} default {c['default']}; "
                         f"alternatives {', '.join(c['alternatives'])}")
        elif c["change"] == "removed":
            lines.append(f"{indent}- {c['id']} ({', '.join(c['families'])}): no longer an interpretation")
        else:
            parts = []
            if "old_default" in c:
                parts.append(f"default {c['old_default']} -> {c['default']}")
            if c["alternatives_added"]:
                parts.append("alternatives added: " + ", ".join(c["alternatives_added"]))
            if c["alternatives_removed"]:
                parts.append("alternatives removed: " + ", ".join(c["alternatives_removed"]))
            lines.append(f"{indent}~ {c['id']}: " + "; ".join(parts))
    return lines


def _expected(vector: dict, choices: dict, defaults: dict):
    """What `vector` expects of an implementation declaring `choices`: per step the result and the full
    state, and the outcome's category (None when the vector offers no expectation for them)."""
    from plcvec_verify.errors import VerifyError
    from plcvec_verify.expect import expected_of

    try:
        e = expected_of(vector, choices, defaults)
    except VerifyError:
        return None
    return e.results, tuple(sorted((k, type(v).__name__, v) for k, v in s.items()) for s in e.states), \
        e.outcome.get("category")


def report(old, new, choices: dict, known_file: str | None = None) -> dict:
    """The upgrade report for an implementation declaring `choices` with known failures in `known_file`."""
    old_i, new_i = interpretations(old), interpretations(new)
    unknown = {i: a for i, a in choices.items() if i not in new_i or a not in new_i[i]["alternatives"]}
    old_defaults = {i: d["default"] for i, d in old_i.items()}
    new_defaults = {i: d["default"] for i, d in new_i.items()}
    known_choices = {i: a for i, a in choices.items() if i not in unknown}
    changed = []
    for name in sorted(set(old.families) & set(new.families)):
        a, b = old.families[name]["vectors"], new.families[name]["vectors"]
        for vid in sorted(set(a) & set(b)):
            if _expected(a[vid], known_choices, old_defaults) != _expected(b[vid], known_choices, new_defaults):
                changed.append(vid)
    out = {"old": old.label, "new": new.label, "choices": dict(sorted(choices.items())),
           "undeclared_new": [c for c in interpretation_changes(old_i, new_i) if c["change"] == "added"
                              and c["id"] not in choices],
           "interpretations": interpretation_changes(old_i, new_i),
           "unknown_choices": dict(sorted(unknown.items())),
           "expectation_changed": changed, "known": None}
    if known_file:
        out["known"] = _known(known_file, new, set(changed))
    return out


def _known(path: str, new, changed: set) -> dict:
    from plcvec_verify.errors import VerifyError
    from plcvec_verify.known import KnownFailures

    try:
        known = KnownFailures.load(path)
    except VerifyError as exc:
        raise PlcvecError(str(exc)) from None
    ids = {vid for fam in new.families.values() for vid in fam["vectors"]}
    merged = {}
    for fam in new.merged.values():
        merged.update(fam)
    entries = []
    for vid, entry in sorted(known.entries.items(), key=lambda kv: kv[1].line):
        if vid in ids:
            entries.append({"id": vid, "line": entry.line,
                            "fate": "expectation-changed" if vid in changed else "kept"})
        elif vid in merged:
            went = merged[vid]
            while went in merged and went not in ids:
                went = merged[went]
            entries.append({"id": vid, "line": entry.line, "fate": "merged", "into": went})
        else:
            entries.append({"id": vid, "line": entry.line, "fate": "removed"})
    return {"file": path, "entries": entries}


def render(rep: dict) -> str:
    declared = " ".join(f"--choose {i}={a}" for i, a in rep["choices"].items()) or "(nothing declared)"
    lines = [f"plcvec diff: {rep['old']} -> {rep['new']}, for an implementation declaring {declared}"]
    if rep["unknown_choices"]:
        lines.append("declared alternatives the new set does not have (they would be refused):")
        lines += [f"  ! {i}={a}" for i, a in rep["unknown_choices"].items()]
    if rep["interpretations"]:
        lines.append("interpretations:")
        lines += interpretation_lines(rep["interpretations"])
    if rep["undeclared_new"]:
        lines.append(f"new interpretations you do not declare take their default: "
                     + ", ".join(f"{c['id']}={c['default']}" for c in rep["undeclared_new"])
                     + "; if your implementation follows another alternative, declare it")
    changed = rep["expectation_changed"]
    lines.append(f"vectors whose expectation changed for you: {len(changed)}")
    lines += [f"  ~ {vid}" for vid in changed]
    known = rep["known"]
    if known is not None:
        fates = [e["fate"] for e in known["entries"]]
        lines.append(f"known failures ({known['file']}): {len(fates)} listed, {fates.count('kept')} kept, "
                     f"{fates.count('expectation-changed')} with a changed expectation, {fates.count('merged')} merged, "
                     f"{fates.count('removed')} removed")
        for e in known["entries"]:
            where = f"{known['file']}:{e['line']}"
            if e["fate"] == "merged":
                lines.append(f"  > {e['id']} ({where}): merged into {e['into']}; list that id instead")
            elif e["fate"] == "removed":
                lines.append(f"  - {e['id']} ({where}): no such vector in the new set; remove it")
            elif e["fate"] == "expectation-changed":
                lines.append(f"  ~ {e['id']} ({where}): its expectation changed; run it again before you keep it")
        lines.append("  (which known failures another reading explains, a run says: its KNOWN FAILURES lines)")
    return "\n".join(lines) + "\n"


__all__ = ["interpretations", "interpretation_changes", "interpretation_lines", "report", "render"]
