"""Which decisions of the inventory a mutant touches, and what a mutant's outcome says of the inventory.

A decision's place is the line(s) of its `old` text in its engine file (review/decisions.yaml: found
there exactly once): from the line its first character is on to the line its last character is on.
A mutant's place is the line(s) of the node cosmic-ray changes, from its start to its end position.

**A mutant touches a decision when both are in the same engine file and their lines share at least
one line.** A mutant that changes the committed vectors and touches no decision is a missing
decision: the engine decides something observable on a line the inventory does not list. Except when
it changes only the engine's record (oracle.Outcome.record_only): the clauses a vector cites, or which
rows of the coverage model get a vector of their own. The trace and the coverage record decide no
outcome of the instruction; such a mutant is counted apart (RECORD), not as a missing decision.

Lines, not characters: a decision's `old` is the text its flip replaces, often a part of a condition,
and the rest of that line (the other operand of an `and`, the value compared with) belongs to the same
decision point. A line holding two decisions is two entries of the inventory, each touched by a mutant
of that line.
"""
from __future__ import annotations

from dataclasses import dataclass

from plcvec.errors import PlcvecError
from plcvec.mutation.oracle import CHANGED, FAILS, TIMEOUT, UNCHANGED

# A mutant's verdict: what its outcome says of the inventory.
COVERED = "covered"     # changes vectors, on a decision's line
MISSING = "missing"     # changes what vectors set up or expect, on no decision's line
RECORD = "record"       # changes only the engine's record (clauses, model rows), on no decision's line
VERDICTS = (COVERED, MISSING, RECORD, UNCHANGED, FAILS, TIMEOUT)


@dataclass(frozen=True)
class Place:
    """Where a decision of the inventory is: its engine file and first and last line there."""

    decision: str
    file: str
    first: int
    last: int


def places(decisions, sources):
    """The Place of every decision; `sources` maps an engine file name to its text. A decision whose
    `old` is not found exactly once is an error: the inventory is stale (`plcvec review --check` says
    which), and a mapping built on it would prove nothing."""
    out = []
    for d in decisions:
        source, old = sources.get(d.get("engine")), d.get("old") or ""
        found = source.count(old) if source is not None and old else 0
        if found != 1:
            raise PlcvecError(f"decision {d.get('id')}: its engine text is found {found} times in "
                              f"{d.get('engine')}, not once; the inventory is stale (see plcvec review --check)")
        first = source.count("\n", 0, source.index(old)) + 1
        out.append(Place(d["id"], d["engine"], first, first + old.rstrip("\n").count("\n")))
    return out


def touched(mutant, decision_places):
    """The ids of the decisions `mutant` touches (see the module docstring)."""
    first, last = mutant.lines
    return [p.decision for p in decision_places if p.file == mutant.file and first <= p.last and p.first <= last]


def verdict(outcome, touches):
    """COVERED, MISSING, RECORD, or the outcome's own status when it changed no vector."""
    if outcome.status != CHANGED:
        return outcome.status
    if touches:
        return COVERED
    return RECORD if outcome.record_only else MISSING
