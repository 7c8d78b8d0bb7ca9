"""Tie each disagreement to the erratum of the spec that records it, and find errata that no longer hold.

An erratum says where its disagreement is with `concerns: {example: ID, table: [cells]}` (cells of a
printed table) or `concerns: {example: ID, prose: [cells]}` (cells on which a sentence of the page
disagrees with its example). The link is made from that data only.
"""
from dataclasses import replace

from plcvec.audit import findings as kinds

# Which finding kind answers to each part of an erratum's `concerns`.
PART_KIND = {"table": kinds.CELL_DISAGREES, "prose": kinds.PROSE_VS_TABLE}


def pointers(audit):
    """(erratum id, example id, part, cell) for every cell an erratum names; unknown cells are spec errors."""
    fam, out = audit.fam, []
    for i, erratum in enumerate(fam.doc["errata"]):
        concerns = erratum.get("concerns")
        if not concerns:
            continue
        for part in PART_KIND:
            for j, cell in enumerate(concerns.get(part, [])):
                known = audit.cells.get((concerns["example"], part))
                if known is None:
                    raise fam.error(("errata", i, "concerns", "example"),
                                    f"erratum {erratum['id']!r}: example {concerns['example']!r} has no {part} cells the audit recomputes")
                if cell not in known:
                    raise fam.error(("errata", i, "concerns", part, j),
                                    f"erratum {erratum['id']!r}: example {concerns['example']!r} has no {part} cell {cell!r} "
                                    f"(its cells: {', '.join(known) or 'none'})")
                out.append((erratum["id"], concerns["example"], part, cell))
    return out


def link_errata(audit):
    """The family's findings with `erratum` filled in, then one erratum-stale finding per cell no finding answers."""
    named = pointers(audit)
    linked = []
    for f in audit.findings:
        if f.kind in PART_KIND.values():
            ids = [e for e, ex, part, cell in named if ex == f.example and PART_KIND[part] == f.kind and cell == f.cell]
            f = replace(f, erratum=ids[0] if ids else None)
        elif f.kind == kinds.NO_VALUES:
            f = replace(f, erratum=_explaining(audit, f.example, named))
        linked.append(f)
    for erratum, example, part, cell in named:
        if not any(f.example == example and f.kind == PART_KIND[part] and f.cell == cell for f in linked):
            linked.append(kinds.Finding(
                family=audit.fam.name, example=example, kind=kinds.ERRATUM_STALE, cell=cell, printed=None, derived=None,
                erratum=erratum,
                message=f"Erratum {erratum} says {part} cell '{cell}' of example '{example}' disagrees with the rules, "
                        f"but recomputed it agrees: the erratum no longer holds."))
    return linked


def _explaining(audit, example, named):
    """The erratum whose table cells, set aside, leave a table that values can produce (errata together if need be)."""
    consistent_without = audit.consistent_without[example]
    ids = list(dict.fromkeys(e for e, ex, part, _ in named if ex == example and part == "table"))
    cells = {e: [c for e2, ex, part, c in named if e2 == e and ex == example and part == "table"] for e in ids}
    for e in ids:
        if consistent_without(cells[e]):
            return e
    if ids and consistent_without([c for e in ids for c in cells[e]]):
        return ids[0]
    return None
