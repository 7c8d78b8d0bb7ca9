"""Audit of a masked comparison's result tables (A<B, B<C, A<C under each comparison target).

Each printed cell is recomputed with the example's values when the spec has them; then, whatever
the values, the ordering search (search.py) asks whether any values can produce the table at all.
"""
from plcvec.audit import findings as kinds
from plcvec.audit import wording
from plcvec.audit.findings import WHOLE_TABLE, FamilyAudit
from plcvec.audit.probe import AuditError, CompareProbe
from plcvec.audit.search import Cell, SearchField, ordering_text, search
from plcvec.audit.selections import audit_processing, audit_selector_example
from plcvec.cases.common import hexw

# A no-values finding lists the sets of conflicting cells up to this many, then only counts them.
MAX_LISTED = 6


class CompareAudit(FamilyAudit):
    def __init__(self, fam):
        super().__init__(fam)
        self.probe = CompareProbe(fam)
        self.fields = fam.doc["data"]["fields"]
        self.by_name = {f["name"]: f for f in self.fields}
        self.selop = self.probe.c.selop

    def run(self):
        for ex in self.fam.doc["examples"]:
            if "table" in ex:
                self.table(ex)
            if "processing" in ex:
                audit_processing(self, ex)
            if "selector" in ex:
                audit_selector_example(self, ex)
        return self

    # -- the table as printed -------------------------------------------------------------------------
    def table(self, ex):
        labels = list(dict.fromkeys(label for pair in ex["pairs"].values() for label in pair))
        cells = [Cell(f"{row['target']}, {pair}", row["s3"], labels.index(x), labels.index(y), printed)
                 for row in ex["table"]
                 for (pair, (x, y)), printed in zip(ex["pairs"].items(), row["printed"])]
        self.cells[(ex["id"], "table")] = [c.name for c in cells]
        if "values" in ex:
            self.recompute(ex, labels, cells)
        self.search_values(ex, labels, cells)

    def recompute(self, ex, labels, cells):
        legend, values = ex.get("legend"), ex["values"]
        agree = 0
        for cell in cells:
            x, y = labels[cell.x], labels[cell.y]
            derived, error = self.probe.contact(ex["condition"], cell.selector, values[x], values[y])
            if self.tally(derived == cell.printed and not error):
                agree += 1
                continue
            shown = "an error" if error else wording.contact(derived, legend)
            self.add(kinds.CELL_DISAGREES, ex["id"], cell.name,
                     f"Table '{ex['id']}', cell '{cell.name}': the manual prints {wording.contact(cell.printed, legend)}, "
                     f"but the rules give {shown} for {x} {ex['condition']} {y} with {x} = {wording.field_values(values[x], self.fields)}, "
                     f"{y} = {wording.field_values(values[y], self.fields)} and {self.selop} = {hexw(cell.selector)}: "
                     f"{self.decider(cell.selector, values[x], values[y])}.",
                     printed=wording.contact(cell.printed, legend), derived=shown)
        origin = "reconstructed values" if ex.get("reconstructed") else "the values the manual gives"
        self.add(kinds.CELL_AGREES_COUNT, ex["id"], WHOLE_TABLE,
                 f"{agree} of {len(cells)} printed cells of table '{ex['id']}' agree with the rules for {origin}: "
                 + "; ".join(f"{label} = {wording.field_values(values[label], self.fields)}" for label in labels) + ".")

    def decider(self, selector, x, y):
        compared = self.probe.compared_fields(selector)
        if not compared:
            return f"{self.selop} = {hexw(selector)} compares nothing"
        for name in compared:  # in the spec's order, which the comparison follows
            if x[name] != y[name]:
                return f"the first compared field that differs is {name}, {x[name]} against {y[name]}"
        return f"the compared fields ({wording.listing(compared)}) are equal"

    # -- can any values produce the table? ---------------------------------------------------------------
    def search_values(self, ex, labels, cells):
        compared = {c.selector: self.probe.compared_fields(c.selector) or [] for c in cells}
        relevant = [f for f in self.fields if any(f["name"] in names for names in compared.values())]
        fields = [SearchField(f["name"], f["max"] - f["min"] + 1) for f in relevant]
        result = search(cells, labels, fields, lambda selector, rel: self.outcome(ex["condition"], selector, relevant, rel))
        scope = (f"all {result.tried} orderings (ties included) of the values of {wording.listing(labels)} "
                 f"in {wording.listing(f.name for f in fields)}")
        if result.solutions:
            self.found(ex, labels, cells, relevant, result, scope)
        else:
            self.none_found(ex, cells, result, scope)

    def outcome(self, symbol, selector, relevant, relations):
        """The contact for a cell whose left value stands in `relations` to its right one, field by field.

        Asked twice, with the values near the bottom of each range and near the top, and with the
        fields no row compares equal the first time and unequal the second: a comparison that looks
        at its values only through their order answers the same both times. If it does not, the
        ordering search would not be a proof, and the audit says so.
        """
        answers = set()
        for near_top in (False, True):
            x, y = {}, {}
            for f in self.fields:
                x[f["name"]], y[f["name"]] = (f["min"], f["max"]) if near_top else (f["min"], f["min"])
            for f, rel in zip(relevant, relations):
                lo, hi = (f["max"] - 1, f["max"]) if near_top else (f["min"], f["min"] + 1)
                x[f["name"]], y[f["name"]] = {-1: (lo, hi), 0: (lo, lo), 1: (hi, lo)}[rel]
            contact, error = self.probe.contact(symbol, selector, x, y)
            if error:
                raise AuditError(f"{self.fam.path}: {self.selop} = {hexw(selector)} gives an error for in-range values {x}, {y}")
            answers.add(contact)
        if len(answers) != 1:
            raise AuditError(f"{self.fam.path}: with {self.selop} = {hexw(selector)} the result depends on more than the "
                             f"order of the values; the ordering search cannot decide the table")
        return answers.pop()

    def found(self, ex, labels, cells, relevant, result, scope):
        # The solution that keeps the most values apart reads best; the first of those, for determinism.
        best = max(result.solutions, key=lambda combo: sum(max(result.orderings[f][o]) for f, o in enumerate(combo)))
        values = {label: {} for label in labels}
        for f in self.fields:
            for label in labels:
                values[label][f["name"]] = (f["min"] + f["max"]) // 2
        for f, (k, o) in zip(relevant, enumerate(best)):
            ranks = result.orderings[k][o]
            for label, rank in zip(labels, ranks):
                values[label][f["name"]] = spread(f, rank, max(ranks) + 1)
        for cell in cells:  # the values themselves, put to the engine cell by cell
            got, error = self.probe.contact(ex["condition"], cell.selector, values[labels[cell.x]], values[labels[cell.y]])
            if error or got != cell.printed:
                raise AuditError(f"{self.fam.path}: values found for table '{ex['id']}' fail cell '{cell.name}' when run")
        per_field = {}
        for k, f in enumerate(relevant):
            used = sorted({combo[k] for combo in result.solutions})
            per_field[f["name"]] = tuple(ordering_text(result.orderings[k][o], labels) for o in used)
        product = 1
        for texts in per_field.values():
            product *= len(texts)
        constraints = "; ".join(f"{name}: {' or '.join(texts)}" for name, texts in per_field.items())
        shape = ("any combination of these" if product == len(result.solutions)
                 else f"{len(result.solutions)} of the {product} combinations of these")
        lost = " (the figure with the manual's own values was lost)" if ex.get("reconstructed") else ""
        self.add(kinds.VALUES_FOUND, ex["id"], WHOLE_TABLE,
                 f"Values that produce every one of the {len(cells)} printed cells of table '{ex['id']}'{lost} exist: "
                 f"of {scope}, {len(result.solutions)} do, namely {shape}: {constraints}. For example "
                 + "; ".join(f"{label} = {wording.field_values(values[label], self.fields)}" for label in labels) + ".",
                 values=values, orderings=per_field)

    def none_found(self, ex, cells, result, scope):
        def names(indices):
            return tuple(cells[i].name for i in indices)
        conflicts = tuple(names(c) for c in result.smallest_conflicts())
        corrections = tuple(names(c) for c in result.smallest_corrections())
        shown = conflicts if len(conflicts) <= MAX_LISTED else conflicts[:1]
        more = "" if len(conflicts) <= MAX_LISTED else f" (and {len(conflicts) - 1} other sets of {len(conflicts[0])} cells)"
        least = len(corrections[0])
        self.add(kinds.NO_VALUES, ex["id"], WHOLE_TABLE,
                 f"No values can produce table '{ex['id']}' as printed: none of {scope} satisfies every cell. "
                 f"Sets of cells that cannot all hold: {wording.cell_sets(shown)}{more}. "
                 f"At least {least} cell{'s' if least > 1 else ''} must be misprinted; each of these sets, taken as "
                 f"misprinted, leaves a table some values produce: {wording.cell_sets(corrections)}.",
                 conflicting_cells=conflicts[0], conflicts=conflicts, corrections=corrections)
        index = {c.name: i for i, c in enumerate(cells)}

        def consistent_without(cell_names):
            keep = result.full
            for name in cell_names:
                keep &= ~(1 << index[name])
            return result.satisfiable(keep)
        self.consistent_without[ex["id"]] = consistent_without


def spread(field, rank, distinct):
    """A value of `field` for the rank-th of `distinct` ordered values, spread over the range when it has room."""
    lo, hi = field["min"], field["max"]
    if hi - lo >= distinct + 1:
        return lo + (rank + 1) * (hi - lo) // (distinct + 1)
    return lo + rank
