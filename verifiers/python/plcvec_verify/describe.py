"""The one failure text: what every runner prints for a failing vector, the roll-up by reading, the
skips by reason and the summary lines (verifiers/parity/TEXT.md is the rule, byte for byte).

Kept apart from the run and the reports so that the pytest plugin, the summary and the shared text
cases (verifiers/parity/text/) all print the same lines from the same code.
"""
from __future__ import annotations

import re
from collections import Counter

from ._report import Report
from .verdict import (ERROR, FAIL, FAILING, NOT_RUN, PASS, SKIP, STATUSES, UNLISTED, XFAIL, Problem, Verdict,
                      show)

SHOW_PROBLEMS = 12      # field lines shown per failing vector
SHOW_REASONS = 12       # skip reasons shown
SHOW_IDS = 5            # vector ids shown under each group of the roll-up
INDENT = "    "

# Step inputs in the order they are shown; any other input follows, by name.
INPUTS = ("clock", "rlo_in", "en", "input", "elapsed_ms")
_DATE, _TIME = ("year", "month", "day"), ("hour", "minute", "second")
_NUMBERED = re.compile(r"^([A-Za-z_]+)([0-9]+)$")


def percent(part: int, whole: int) -> str:
    """part/whole as a percentage with one decimal, rounded half up in integers (no float formatting,
    so that every language prints the same digits)."""
    whole = max(whole, 1)
    tenths = (2000 * part + whole) // (2 * whole)
    return f"{tenths // 10}.{tenths % 10}"


def clock_text(clock: dict) -> str:
    """`2024/2/29`, `10:05:00`, or both with a space; other fields as ` name=value`, by name."""
    date = "/".join(str(clock[f]) for f in _DATE if f in clock)
    time = [clock[f] for f in _TIME if f in clock]
    time_text = ":".join(str(v) if k == 0 else f"{v:02d}" if type(v) is int and v >= 0 else show(v)
                         for k, v in enumerate(time))
    parts = [p for p in (date, time_text) if p]
    parts += [f"{k}={show(v)}" for k, v in sorted(clock.items()) if k not in _DATE + _TIME]
    return " ".join(parts)


def inputs_text(step: dict) -> str:
    """A step's inputs: `clock=10:30:00, rlo_in=true, set D100=5 D101=0`, or `(none)`."""
    parts = []
    for key in INPUTS:
        if key in step:
            parts.append(f"{key}={clock_text(step[key]) if key == 'clock' and isinstance(step[key], dict) else show(step[key])}")
    for key in sorted(step):
        if key not in INPUTS and key not in ("expect", "set"):
            parts.append(f"{key}={show(step[key])}")
    if step.get("set"):
        parts.append("set " + " ".join(f"{d}={show(v)}" for d, v in sorted(step["set"].items())))
    return ", ".join(parts) or "(none)"


def _next_address(device: str) -> str | None:
    m = _NUMBERED.match(device)
    return f"{m.group(1)}{int(m.group(2)) + 1}" if m else None


def operands_text(vector: dict, state: dict) -> str:
    """Each operand with the words it reads in `state` (the vector's state before the step):
    `s1 D100=23 0 0`, `D2 M10=false`, `S1 constant 3600`, `D3 D300 (scratch)`."""
    operands = vector["initial"]["operands"]
    scratch = set(vector["initial"].get("scratch", ()))
    starts = {o["device"] for o in operands.values() if "device" in o}
    parts = []
    for name in sorted(operands):
        operand = operands[name]
        if "device" not in operand:
            parts.append(f"{name} constant {show(operand.get('constant'))}")
            continue
        first = operand["device"]
        if first in scratch:
            parts.append(f"{name} {first} (scratch)")
            continue
        if first not in state:
            parts.append(f"{name} {first} (not in the vector)")
            continue
        words = [state[first]]
        if type(words[0]) is not bool:
            device = _next_address(first)
            while device in state and type(state[device]) is not bool and device not in starts \
                    and device not in scratch:
                words.append(state[device])
                device = _next_address(device)
        parts.append(f"{name} {first}=" + " ".join(map(show, words)))
    return ", ".join(parts) or "(none)"


def deciding(vector: dict, problems, followed: dict, defaults: dict, expectations) -> list[str]:
    """The interpretations that decide the differing fields: those of which another alternative
    (every other interpretation as followed) expects something else of a field that differs."""
    touched = sorted(vector["outcome"].get("interpretations", ()))
    if not touched or not problems:
        return []
    from .infer import offered

    mine = expectations.expected(vector, followed, defaults)
    combos = offered(vector, defaults)
    out = []
    for interp in touched:
        for combo in combos:
            if combo[interp] == followed[interp] or any(combo[i] != followed[i] for i in touched if i != interp):
                continue
            other = expectations.expected(vector, combo, defaults)
            if any(_differs(mine, other, p) for p in problems):
                out.append(interp)
                break
    return out


def _differs(mine, other, p: Problem) -> bool:
    if p.step is None:
        return False
    if p.field == "result":
        return mine.results[p.step] is not other.results[p.step]
    if p.field in other.left_out:    # the other reading does not judge it at all
        return True
    a = mine.states[p.step].get(p.field, UNLISTED)
    b = other.states[p.step].get(p.field, UNLISTED)
    return a != b or type(a) is not type(b)


def block(r: Verdict, vector: dict | None, followed: dict, defaults: dict, expectations) -> list[str]:
    """The lines of one vector's verdict (TEXT.md, "The failure block")."""
    lines = [f"{r.status.upper()} {r.id}"]
    vector = vector or {}
    if vector.get("description"):
        lines.append(f"{INDENT}{vector['instruction']}: {vector['description']}")
    if r.problems and vector:
        judged = deciding(vector, r.problems, followed, defaults, expectations)
        if judged:
            lines.append(f"{INDENT}judged by: " + ", ".join(f"{i}={followed[i]}" for i in judged))
    if vector:
        for interp, devices in expectations.expected(vector, followed, defaults).unjudged.items():
            lines.append(f"{INDENT}not judged under {interp}={followed[interp]}: " + ", ".join(devices))
    shown = r.problems[:SHOW_PROBLEMS]
    step_shown = None
    for p in shown:
        if p.step is not None and p.step != step_shown and vector:
            step_shown = p.step
            step = vector["steps"][p.step]
            lines.append(f"{INDENT}step {p.step} inputs: {inputs_text(step)}")
            state = expectations.expected(vector, followed, defaults).before(p.step)
            lines.append(f"{INDENT}step {p.step} operands: {operands_text(vector, state)}")
        lines.append(f"{INDENT}{p.line()}")
    if len(r.problems) > SHOW_PROBLEMS:
        lines.append(f"{INDENT}... and {len(r.problems) - SHOW_PROBLEMS} more differences")
    if r.message:
        lines.append(f"{INDENT}{r.message}")
    for note in r.notes:
        lines.append(f"{INDENT}note: {note}")
    if vector.get("clauses"):
        lines.append(f"{INDENT}spec clauses: " + ", ".join(vector["clauses"]))
    return lines


def describe(verdict: Verdict, vector: dict | None, followed: dict, defaults: dict, expectations) -> str:
    """One vector's verdict as the failure text prints it (VOCABULARY.md: `describe(verdict)`): the
    lines of `block`, one string. `followed` and `defaults` map each interpretation to its alternative
    (what the run followed, the suite's defaults); `expectations` is the suite's (`Suite.expectations`).

    Here, not in `verdict` as the other runners have it: the text imports the verdict (and the
    inference, which imports it too), so `verdict`, a leaf, cannot import the text without a circle;
    nor in the package itself, where `plcvec_verify.describe` is this module.
    """
    return "\n".join(block(verdict, vector, followed, defaults, expectations))


def rollup_lines(report: Report, inferred, syntax: str = "verify") -> list[str]:
    """The failing vectors and known failures grouped by what would explain them (TEXT.md, "The
    roll-up by reading"); `syntax` the runner whose declaration is shown ("verify" or "pytest")."""
    by_id = report.suite.by_id
    failing = [r for r in report.results if r.status in (FAIL, ERROR, NOT_RUN)]
    known = [r for r in report.results if r.status == XFAIL]
    if not failing and not known:
        return []

    def family(vid):
        return by_id.get(vid, {}).get("family", "")

    lines = []
    if inferred.explained:
        lines.append(f"READINGS: {len(inferred.explained)} of {len(failing)} failing vectors pass "
                     "under other alternatives:")
        others = list(inferred.unexplained)
        lines += _groups(inferred.explained, others, inferred.broken, family)
        lines.append(f"{INDENT}declare: " + declaration(inferred.changes, syntax))
        if inferred.broken:
            lines.append(f"{INDENT}(so declared, {len(inferred.broken)} vectors that pass now would fail)")
        lines += _partial_line(inferred.explained, others, inferred.broken, family)
    if inferred.unexplained:
        lines.append(f"NOT EXPLAINED by any reading: {len(inferred.unexplained)} failing vectors, "
                     "by the clauses they cite:")
        groups: dict[str, list[str]] = {}
        for vid in inferred.unexplained:
            clauses = by_id.get(vid, {}).get("clauses") or ()
            groups.setdefault(", ".join(clauses) or "(no clauses)", []).append(vid)
        for key, ids in sorted(groups.items(), key=lambda kv: (-len(kv[1]), kv[0])):
            lines.append(f"{INDENT}{len(ids):>6}  {key}")
            for vid in sorted(ids)[:SHOW_IDS]:
                lines.append(f"{INDENT}{'':>6}  {vid}")
            if len(ids) > SHOW_IDS:
                lines.append(f"{INDENT}{'':>6}  ... and {len(ids) - SHOW_IDS} more")
    if inferred.known_explained:
        lines.append(f"KNOWN FAILURES: {len(inferred.known_explained)} of {len(known)} known failures pass under "
                     "other alternatives:")
        others = [*inferred.unexplained, *inferred.known_unexplained]
        lines += _groups(inferred.known_explained, others, inferred.broken, family)
        changes = dict(sorted({i: a for key in inferred.known_explained.values() for i, a in key}.items()))
        lines.append(f"{INDENT}declare: " + declaration(changes, syntax))
        lines.append(f"{INDENT}then remove those {len(inferred.known_explained)} known failures from "
                     f"{report.known_file}")
    return lines


def _groups(explained: dict, others: list, broken: list, family) -> list[str]:
    """One line per smallest change, largest group first, each marked partial when a vector of
    `others` (not explained) or of `broken` (passes now, would fail so declared) is of a family one of
    its vectors is of: the reading does not account for everything the implementation does there."""
    groups: dict[tuple, list[str]] = {}
    for vid, key in explained.items():
        groups.setdefault(key, []).append(vid)
    lines = []
    for key, ids in sorted(groups.items(), key=lambda kv: (-len(kv[1]), _reading(kv[0]))):
        families = {family(vid) for vid in ids}
        near = [vid for vid in others if family(vid) in families]
        lost = [vid for vid in broken if family(vid) in families]
        mark = ""
        if near or lost:
            named = ", ".join(sorted({family(vid) for vid in near + lost}))
            mark = f" (partial: {len(near)} not explained, {len(lost)} would fail, in {named})"
        lines.append(f"{INDENT}{len(ids):>6}  {_reading(key)}{mark}")
    return lines


def _partial_line(explained: dict, others: list, broken: list, family) -> list[str]:
    """The `partial:` line: the vectors of the partial groups' families that no reading explains or that
    the declaration would break, each counted once."""
    families = {family(vid) for vid in explained}
    near = [vid for vid in others if family(vid) in families]
    lost = [vid for vid in broken if family(vid) in families]
    if not near and not lost:
        return []
    return [f"{INDENT}partial: {len(near)} vectors no reading explains and {len(lost)} vectors that pass now "
            "are of the same families; the declaration may hide part of a bug there"]


# How an implementer declares alternatives in each Python entry point (TEXT.md, "The declaration in
# each runner").
_OPTION = {"verify": "--choose", "pytest": "--plcvec-choose"}


def declaration(changes: dict, syntax: str = "verify") -> str:
    """`--choose ID=alt ...` (plcvec verify) or `--plcvec-choose ID=alt ...` (the pytest plugin)."""
    return " ".join(f"{_OPTION[syntax]} {i}={a}" for i, a in sorted(changes.items()))


def _reading(key) -> str:
    return ", ".join(f"{i}={a}" for i, a in key)


def skipped_lines(report: Report) -> list[str]:
    """How many vectors were skipped and why, most common reason first (ties by reason): a run that
    skips much proves little, so the number is said before the totals, not hidden among them."""
    skipped = [r.message for r in report.results if r.status == SKIP]
    if not skipped:
        return []
    lines = [f"SKIPPED {len(skipped)} of {report.selected} vectors ({percent(len(skipped), report.selected)}%):"]
    reasons = sorted(Counter(skipped).items(), key=lambda kv: (-kv[1], kv[0]))
    for reason, n in reasons[:SHOW_REASONS]:
        lines.append(f"{INDENT}{n:>6}  {reason or '(no reason given)'}")
    if len(reasons) > SHOW_REASONS:
        lines.append(f"{INDENT}... and {len(reasons) - SHOW_REASONS} more reasons (--jsonl lists each vector)")
    return lines


def interpretations_line(report: Report) -> str:
    """Every interpretation of the families run with the alternative followed, declared or default."""
    items = [f"{i}={d['alternative']} ({'declared' if d['declared'] else 'default'})"
             for i, d in sorted(report.interpretations.items())]
    return "interpretations: " + (", ".join(items) or "(none)")


def totals_line(report: Report) -> str:
    """`N vectors: a pass, b fail, c skip` (other statuses when not 0), without the time."""
    counts = report.counts
    parts = [f"{counts[s]} {s}" for s in STATUSES if counts[s] or s in (PASS, FAIL, SKIP)]
    return f"{len(report.results)} vectors: " + ", ".join(parts)


__all__ = ["describe", "block", "rollup_lines", "declaration", "skipped_lines", "interpretations_line", "totals_line",
           "inputs_text", "operands_text", "clock_text", "percent", "deciding", "FAILING"]
