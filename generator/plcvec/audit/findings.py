"""What the audit reports: one Finding per observation, and the report that holds them."""
import json
from dataclasses import asdict, dataclass, field

# A printed cell the rules contradict.
CELL_DISAGREES = "cell-disagrees"
# How many printed cells of one example were recomputed and agree.
CELL_AGREES_COUNT = "cell-agrees-count"
# Values exist that reproduce every printed cell of a table (its inputs lost, or given).
VALUES_FOUND = "values-found"
# No values can reproduce a table as printed; `conflicting_cells` cannot all hold.
NO_VALUES = "no-values"
# A sentence of the page states inputs, a result or a rule that its own example contradicts.
PROSE_VS_TABLE = "prose-vs-table"
# An erratum points at a cell the rules agree with: the erratum is out of date.
ERRATUM_STALE = "erratum-stale"
# The family holds examples of a kind the audit has no recomputation for.
NOT_AUDITED = "not-audited"

KINDS = (CELL_DISAGREES, CELL_AGREES_COUNT, VALUES_FOUND, NO_VALUES, PROSE_VS_TABLE, ERRATUM_STALE, NOT_AUDITED)

# The cell name of a finding about a whole table rather than one of its cells.
WHOLE_TABLE = "all cells"


@dataclass(frozen=True)
class Finding:
    family: str
    example: str | None
    kind: str
    cell: str
    printed: str | None
    derived: str | None
    message: str
    erratum: str | None = None
    # no-values: one smallest set of cells that cannot all hold together.
    conflicting_cells: tuple = ()
    # values-found: {label: {field: value}} that reproduce every printed cell.
    values: dict | None = None
    # no-values: every smallest set of cells that cannot all hold (conflicting_cells is the first).
    conflicts: tuple = ()
    # no-values: every smallest set of cells which, if misprinted, leaves a table that values can produce.
    corrections: tuple = ()
    # values-found: {field: (ordering, ...)}, the orderings of the labels' values that work, per field.
    orderings: dict | None = None

    def as_dict(self):
        return asdict(self)


@dataclass(frozen=True)
class AuditReport:
    findings: list
    # Printed cells (table cells, printed results, prose claims, processing rows) recomputed from the rules.
    checked: int
    # How many of those the rules contradict.
    disagreeing: int = 0
    families: tuple = field(default_factory=tuple)

    def by_kind(self, kind):
        return [f for f in self.findings if f.kind == kind]

    def headline(self):
        return f"{self.checked} printed cells recomputed from the rules, {self.disagreeing} disagree"

    def as_dict(self):
        return {"checked": self.checked, "disagreeing": self.disagreeing, "families": list(self.families),
                "findings": [f.as_dict() for f in self.findings]}

    def to_json(self):
        return json.dumps(self.as_dict(), indent=1, ensure_ascii=False) + "\n"

    def text(self):
        lines = [f"plcvec audit: {self.headline()}"]
        for f in self.findings:
            where = f"{f.family} {f.example or '-'} [{f.kind}] {f.cell}"
            if f.printed is not None or f.derived is not None:
                where += f": printed {f.printed}, derived {f.derived}"
            if f.erratum:
                where += f" (erratum {f.erratum})"
            lines.append(where)
            lines.append(f"    {f.message}")
        return "\n".join(lines) + "\n"


class FamilyAudit:
    """What the audit of one family gathers: its findings, its counts, and the cells errata may name."""

    def __init__(self, fam):
        self.fam = fam
        self.findings = []
        self.checked = 0
        self.disagreeing = 0
        # (example id, "table" or "prose") -> the cell names recomputed there, for errata pointers.
        self.cells = {}
        # example id -> f(cell names) telling whether the table's other cells can all hold: for the
        # tables no values can produce, so that an erratum naming misprinted cells can be checked.
        self.consistent_without = {}

    def add(self, kind, example, cell, message, printed=None, derived=None, **more):
        self.findings.append(Finding(family=self.fam.name, example=example, kind=kind, cell=cell,
                                     printed=printed, derived=derived, message=message, **more))

    def tally(self, agrees):
        """Count one printed cell recomputed; returns whether it agrees."""
        self.checked += 1
        self.disagreeing += not agrees
        return agrees
