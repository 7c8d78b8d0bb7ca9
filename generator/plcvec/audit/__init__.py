"""Audit of the manual's own tables: every printed example and table cell recomputed from the rules.

`audit_families(families)` takes the families of `plcvec.spec.loader.load_spec` and returns an
AuditReport: `findings` (Finding, in the order of the families, their examples and cells) and
`checked` / `disagreeing`, the number of printed cells recomputed and of those the rules contradict.
Every value is computed by the spec engine (probe.py), under the default alternative of every
interpretation unless a prose claim names another.

Finding kinds:
- `cell-disagrees`: a printed cell (a table cell, a printed result or flag, a row of the processing
  table, the fields a worked mask compares) that the rules contradict; `printed` and `derived` hold
  both values as the manual writes them.
- `cell-agrees-count`: per example, how many of its printed cells agree (cell "all cells").
- `values-found`: values of the labels (A, B, C) that produce every printed cell of a result table
  exist; `values` holds one set and `orderings`, per field, every ordering that works.
- `no-values`: no values can produce the table as printed (proved by trying every ordering of the
  values, see search.py); `conflicting_cells` is a smallest set of cells that cannot all hold,
  `conflicts` every such set, `corrections` every smallest set of cells that must be misprinted.
- `prose-vs-table`: a sentence of the page (its own addends and result, or a rule read as worded)
  gives by the rules another value than the sentence or its example prints.
- `erratum-stale`: an erratum names a cell that agrees with the rules; the erratum is out of date.
- `not-audited`: a family whose examples the audit has no recomputation for.

`erratum` is the id of the spec erratum that records a disagreement (errata.py links it from the
erratum's `concerns`), or None when the spec does not record it.

Run `python3 -m plcvec.audit [--spec-dir DIR] [--json]` to print the report.
"""
from plcvec.audit import findings as kinds
from plcvec.audit.clock_examples import ClockAddAudit
from plcvec.audit.compare_tables import CompareAudit
from plcvec.audit.errata import link_errata
from plcvec.audit.findings import AuditReport, FamilyAudit, Finding

__all__ = ["audit_families", "AuditReport", "Finding"]

AUDITS = {"masked_compare": CompareAudit, "clock_add": ClockAddAudit}


def audit_family(fam):
    auditor = AUDITS.get(fam.kind)
    if auditor is not None:
        return auditor(fam).run()
    audit = FamilyAudit(fam)
    if fam.doc.get("examples"):
        audit.add(kinds.NOT_AUDITED, None, kinds.WHOLE_TABLE,
                  f"The examples of {fam.name} (kind {fam.kind}) are not recomputed: the audit has no recomputation for this kind.")
    return audit


def audit_families(families):
    findings, checked, disagreeing = [], 0, 0
    for fam in families:
        audit = audit_family(fam)
        findings += link_errata(audit)
        checked += audit.checked
        disagreeing += audit.disagreeing
    return AuditReport(findings=findings, checked=checked, disagreeing=disagreeing,
                       families=tuple(fam.name for fam in families))
