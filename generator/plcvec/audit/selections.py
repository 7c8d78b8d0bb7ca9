"""Audit of what the manual says a selector value compares: the table of processing details (which
words of (s1) each (s3) value compares) and worked examples of one mask (CP1E's C = 39H).

What a selector value compares is found by asking the engine, not by reading the bit layout here:
a field is compared when changing it alone makes "=" false.
"""
from plcvec.audit import findings as kinds
from plcvec.audit import wording
from plcvec.audit.findings import WHOLE_TABLE
from plcvec.cases.common import hexw


def audit_processing(audit, ex):
    operand = audit.probe.c.first
    rows = ex["processing"]
    audit.cells[(ex["id"], "table")] = [row["target"] for row in rows]
    agree = total = 0
    for row in rows:
        printed = sorted(set(row["words"]))
        wrong = []
        for selector in row["s3"]:
            names = audit.probe.compared_fields(selector) or []
            derived = sorted({audit.by_name[n]["word"] for n in names})
            total += 1
            if audit.tally(derived == printed):
                agree += 1
            else:
                wrong.append((selector, names, derived))
        if not wrong:
            continue
        selectors = wording.listing(hexw(s) for s, _, _ in wrong)
        derived_text = "; ".join(f"{hexw(s)} compares {wording.words(operand, d)} ({wording.listing(n) or 'nothing'})"
                                 for s, n, d in wrong)
        audit.add(kinds.CELL_DISAGREES, ex["id"], row["target"],
                  f"Table '{ex['id']}', row '{row['target']}': the manual says \"{row['quote']}\", that is "
                  f"{wording.words(operand, row['words'])}; by the bit layout of {audit.selop}, {derived_text}. "
                  f"Its values {selectors} compare other words than the text names.",
                  printed=wording.words(operand, row["words"]), derived=wording.words(operand, wrong[0][2]))
    audit.add(kinds.CELL_AGREES_COUNT, ex["id"], WHOLE_TABLE,
              f"{agree} of {total} {audit.selop} values of table '{ex['id']}' compare the words its text names.")


def audit_selector_example(audit, ex):
    selector = ex["selector"]
    cell = f"{audit.selop} = {hexw(selector)}"
    audit.cells[(ex["id"], "table")] = [cell]
    derived = audit.probe.compared_fields(selector) or []
    printed = ex["compared"]
    order = [f["name"] for f in audit.fields]
    printed_text = wording.listing(sorted(printed, key=order.index)) or "nothing"
    derived_text = wording.listing(derived) or "nothing"
    if audit.tally(set(derived) == set(printed)):
        audit.add(kinds.CELL_AGREES_COUNT, ex["id"], WHOLE_TABLE,
                  f"Example '{ex['id']}': {cell} compares {derived_text}, as the manual says.")
    else:
        audit.add(kinds.CELL_DISAGREES, ex["id"], cell,
                  f"Example '{ex['id']}': the manual says {cell} compares {printed_text}, but by the rules it compares {derived_text}.",
                  printed=printed_text, derived=derived_text)
