"""Which values of A, B, C (the labels of a comparison table) can produce every printed cell?

A masked comparison looks at its values only through <, = and > field by field, so what decides a
cell is, for each field, the relative ordering (with ties) of the labels' values. There are finitely
many of those (13 for three labels), so trying every combination over the compared fields answers
the question exactly: either some combination reproduces every printed cell, and the table has
values, or none does, and that is a proof that no values can reproduce it.

The search works on bit masks: for each combination, the set of cells whose outcome matches print.
A set of cells can all hold iff it lies inside one of those masks. From them come the smallest sets
of cells that cannot all hold, and the smallest sets of cells that must be misprinted.
"""
import itertools
from dataclasses import dataclass
from functools import cached_property
from math import comb

from plcvec.audit.probe import AuditError

# Above this many combinations the exhaustive search would take too long; a spec that needs more
# needs a smarter search, and the audit says so rather than guess.
MAX_COMBINATIONS = 500_000
# Above this many candidate subsets of one size, the smallest conflicts are found by deletion instead.
MAX_SUBSETS = 200_000


@dataclass(frozen=True)
class Cell:
    name: str
    selector: int
    x: int          # index of the left label (A in "A<B")
    y: int          # index of the right label
    printed: bool


@dataclass(frozen=True)
class SearchField:
    name: str
    room: int       # how many distinct values the field can hold: an ordering needs no more


def weak_orderings(count, room):
    """Every ordering with ties of `count` labels, as a rank per label, that fits in `room` values."""
    out = []
    for ranks in itertools.product(range(count), repeat=count):
        distinct = max(ranks) + 1
        if set(ranks) == set(range(distinct)) and distinct <= room:
            out.append(ranks)
    return out


def ordering_text(ranks, labels):
    """"B < A = C" for ranks (1, 0, 1) of labels A, B, C."""
    groups = [" = ".join(labels[i] for i, r in enumerate(ranks) if r == rank) for rank in range(max(ranks) + 1)]
    return " < ".join(groups)


@dataclass
class SearchResult:
    cells: list
    fields: list
    orderings: list          # per field, its candidate orderings
    solutions: list          # combinations (an ordering index per field) that reproduce every cell
    masks: dict              # agreement mask -> how many combinations give it
    tried: int

    @property
    def full(self):
        return (1 << len(self.cells)) - 1

    def satisfiable(self, cells_mask):
        return any(m & cells_mask == cells_mask for m in self.maximal)

    @cached_property
    def maximal(self):
        """The agreement masks no other mask contains: enough to decide whether a set of cells can hold."""
        keep = []
        for m in sorted(self.masks, key=lambda m: (-bin(m).count("1"), m)):
            if not any(m | k == k for k in keep):
                keep.append(m)
        return keep

    def smallest_conflicts(self):
        """Every smallest set of cells (as index tuples) that no combination satisfies together."""
        n = len(self.cells)
        for size in range(1, n + 1):
            if comb(n, size) > MAX_SUBSETS:
                return [self._conflict_by_deletion()]
            found = [c for c in itertools.combinations(range(n), size) if not self.satisfiable(_mask(c))]
            if found:
                return found
        return []

    def _conflict_by_deletion(self):
        keep = set(range(len(self.cells)))
        for i in range(len(self.cells)):
            if not self.satisfiable(_mask(keep - {i})):
                keep.discard(i)
        return tuple(sorted(keep))

    def smallest_corrections(self):
        """Every smallest set of cells (index tuples) outside which the remaining cells can all hold."""
        best = max(bin(m).count("1") for m in self.masks)
        out = {tuple(i for i in range(len(self.cells)) if not m >> i & 1) for m in self.masks if bin(m).count("1") == best}
        return sorted(out)


def _mask(indices):
    m = 0
    for i in indices:
        m |= 1 << i
    return m


def search(cells, labels, fields, outcome):
    """Try every combination of orderings of the labels' values, one ordering per field.

    `outcome(selector, relations)` is the contact state of the table's condition for one cell whose
    left value stands in `relations` (a -1/0/1 per field of `fields`) to its right value.
    """
    orderings = [weak_orderings(len(labels), f.room) for f in fields]
    total = 1
    for o in orderings:
        total *= len(o)
    if total > MAX_COMBINATIONS:
        raise AuditError(f"{total} combinations of orderings over {[f.name for f in fields]}: too many for the exhaustive search")
    # relation[f][o][cell]: -1, 0, 1 for the cell's left label against its right one under ordering o of field f.
    relation = [[[(r[c.x] > r[c.y]) - (r[c.x] < r[c.y]) for c in cells] for r in field_orderings]
                for field_orderings in orderings]
    memo = {}
    solutions, masks = [], {}
    full = (1 << len(cells)) - 1
    for combo in itertools.product(*[range(len(o)) for o in orderings]):
        mask = 0
        for i, cell in enumerate(cells):
            rel = tuple(relation[f][o][i] for f, o in enumerate(combo))
            key = (cell.selector, rel)
            if key not in memo:
                memo[key] = outcome(cell.selector, rel)
            if memo[key] == cell.printed:
                mask |= 1 << i
        masks[mask] = masks.get(mask, 0) + 1
        if mask == full:
            solutions.append(combo)
    return SearchResult(cells, fields, orderings, solutions, masks, total)
