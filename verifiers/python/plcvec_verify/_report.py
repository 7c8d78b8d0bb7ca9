"""The report of one run (VOCABULARY.md: `Report`, named by `runner`, where users import it).

A module of its own so that `runner` can name the class under its 0.1.0 name too (`RunReport`) as an
import of this one, which the API check sees as the same class, not as a class turned attribute.
"""
from __future__ import annotations

from dataclasses import dataclass, field

from .gate import NOTHING_TESTED, Gate
from .selection import Selection
from .suite import Suite
from .verdict import FAILING, STATUSES


@dataclass
class Report:
    """What a run found: every verdict (`results`), the adapter's name and the interpretations it was
    judged by, and what ended it early, if anything did; `exit_code` is the gate's answer.

    `RunReport`, its name until 0.3.0, still works until 0.4.0, with a DeprecationWarning.
    """

    suite: Suite
    adapter: dict
    interpretations: dict          # id -> {"alternative", "declared": bool, "family"}
    results: list
    seconds: float = 0.0
    aborted: str = ""
    notes: list = field(default_factory=list)   # adapter notes not tied to a vector
    selection: Selection = field(default_factory=Selection)
    stopped: int = 0                            # the signal that stopped the run, if one did
    gate: Gate = field(default_factory=Gate)    # what the run must show beyond "no failures"
    cpu_writes: tuple = ()                      # devices the implementation's CPU writes on its own
    known_file: str = ""                        # the known-failures file as given, when there was one

    def count(self, status):
        return sum(1 for r in self.results if r.status == status)

    @property
    def counts(self):
        return {s: self.count(s) for s in STATUSES}

    @property
    def failed(self):
        return [r for r in self.results if r.status in FAILING]

    @property
    def selected(self):
        """The vectors the run was given (not the stale ids an expectations file adds)."""
        return sum(1 for r in self.results if r.family)

    @property
    def shortfall(self) -> str:
        """Why the run proves too little to pass, though nothing failed ("" when it is enough)."""
        return self.gate.shortfall(self.counts, self.selected)

    @property
    def exit_code(self):
        """128+N stopped by signal N; 2 harness error; 1 failures; 5 nothing (or too little) tested; 0 passed."""
        if self.stopped:
            return 128 + self.stopped
        if self.aborted:
            return 2
        if self.failed:
            return 1
        return NOTHING_TESTED if self.shortfall else 0
