"""The review as plain data: every fact of the spec, arranged the way a reviewer checks it.

Everything here is read from the loaded spec, the vectors generated from it in process, the quote
check and the audit; nothing about an instruction is written in this file. The templates only
arrange what this model holds, so the HTML and the Markdown say the same things.
"""
import importlib
import importlib.util
import re

from plcvec.spec.instructions import instruction_list
from plcvec.review import coverage as cov
from plcvec.review import accounting as acc
from plcvec.review import provenance as prov

# Spec sections drawn as their own tables, or shown in their own part of the report; every other
# top-level section is listed parameter by parameter under "Rule parameters".
_OWN_SECTIONS = {"spec_version", "family", "title", "manual", "kind", "clauses", "interpretations", "errata", "documents",
                 "assumptions", "examples", "generation", "coverage", "operands", "instructions", "accounting"}
# Roles of the operands whose words hold the data fields (the others are selectors, bits, work areas).
_DATA_ROLES = ("data", "addend", "result", "preset", "measured")
# Audit findings that a reviewer must act on unless an erratum of the spec records them.
AUDIT_PROBLEM_KINDS = ("cell-disagrees", "no-values", "prose-vs-table")
# An erratum the audit finds out of date is wrong whatever else the spec records.
AUDIT_STALE_KIND = "erratum-stale"
WORD_BITS = 16
# Element ids of the report, stable across runs so that links, tests and reviewers can find an item.
_ANCHOR_PREFIX = {"family": "family", "clause": "clause", "interpretation": "interp", "erratum": "erratum",
                  "example": "example", "coverage": "coverage", "audit": "audit", "layout": "layout",
                  "wording": "wording"}


def anchor(kind, family, ident=None):
    """The element id of an item: kind prefix, family, item id (e.g. clause-fx5-date-compare-sm709.in-range)."""
    return f"{_ANCHOR_PREFIX[kind]}-{family}" + ("" if ident is None else f"-{ident}")


def slug(text):
    return re.sub(r"[^A-Za-z0-9._-]+", "-", str(text)).strip("-") or "x"


class Problems:
    """What `--check` fails on, each with the place to fix it (file:line) and an anchor in the report."""

    def __init__(self):
        self.items = []

    def add(self, kind, fam, line, message, target):
        where = f"{fam.path}:{line}" if line else str(fam.path)
        self.items.append({"kind": kind, "where": where, "file": fam.path.name, "line": line,
                           "message": message, "anchor": target})

    def add_at(self, kind, where, file, line, message, target):
        """A problem located in another file than a spec file (a page of the manual: `page.txt:12`)."""
        self.items.append({"kind": kind, "where": where, "file": file, "line": line, "message": message,
                           "anchor": target})

    def lines(self):
        return [f"{p['where']}: {p['message']}" for p in self.items]


def run_audit(families):
    """The audit report, or None when the audit package is not installed beside this one."""
    if importlib.util.find_spec("plcvec.audit") is None:
        return None
    return importlib.import_module("plcvec.audit").audit_families(families)


def build_model(families, vectors_by_family, *, quotes=None, audit=None, cells=None, pages=None):
    """The whole review.

    quotes: None when no manual folder was given, else (checked quotes, missing quotes) from
    plcvec.review.quotes.check_quotes. audit: an AuditReport, or None when there is no audit.
    pages: None, or {page file name: (path, text)} of the manual folder, for the sentence accounting.
    """
    missing = {}
    problems = Problems()
    by_name = {fam.name: fam for fam in families}
    for m in quotes[1] if quotes is not None else ():
        q = m.quote
        missing[(q.family, q.line, q.quote)] = m.reason
        kind, _, ident = q.owner.partition(" ")
        problems.add("quote", by_name[q.family], q.line, m.message(),
                     anchor(kind, q.family, ident) if kind in _ANCHOR_PREFIX else anchor("family", q.family))
    manuals = {fam.doc["manual"] for fam in families}
    fams = [_FamilyView(fam, vectors_by_family[fam.name], quotes is not None, missing, problems).build(
                audit, (cells or {}).get(fam.name), manuals, pages) for fam in families]
    from plcvec.review.decisions import INVENTORY, inventory

    decisions, decision_problems = inventory(families)
    for line, message in decision_problems:
        problems.add_at("decision", f"{INVENTORY}:{line}" if line else str(INVENTORY), INVENTORY.name, line,
                        message, "decisions")
    all_vectors = [v for fam in families for v in vectors_by_family[fam.name]]
    audit_rows = [f for fm in fams for f in fm["audit"]]
    coverage_rows = [r for fm in fams for r in fm["coverage"]]
    summary = {
        "families": len(fams),
        "clauses": sum(len(fm["clauses"]) for fm in fams),
        "vectors": len(all_vectors),
        "vector_categories": cov.category_counts(all_vectors),
        "interpretations": sum(len(fm["interpretations"]) for fm in fams),
        "errata": sum(len(fm["errata"]) for fm in fams),
        "wording_notes": sum(len(fm["accounting"]["notes"]) for fm in fams),
        "quotes_checked": len(quotes[0]) if quotes is not None else None,
        "quotes_missing": len(quotes[1]) if quotes is not None else None,
        "covered": sum(r["status"] == "covered" for r in coverage_rows),
        "uncovered": sum(r["status"] == "uncovered" for r in coverage_rows),
        "no_vectors": sum(r["status"] == "no-vectors" for r in coverage_rows),
        "cited_despite_no_vectors": sum(r["status"] == "cited-despite-no-vectors" for r in coverage_rows),
        "audit_available": audit is not None,
        "audit_headline": audit.headline() if audit is not None else None,
        "audit_findings": len(audit_rows),
        "audit_unrecorded": sum(f["problem"] for f in audit_rows),
        "model_required": sum(fm["model"]["required"] for fm in fams if fm["model"]),
        "model_missing": sum(len(fm["model"]["missing"]) for fm in fams if fm["model"]),
        "sentences": sum(fm["accounting"]["units"] for fm in fams) if pages is not None else None,
        "sentences_unaccounted": sum(len(fm["accounting"]["left"]) for fm in fams),
        "accounting_entries": sum(len(fm["accounting"]["entries"]) for fm in fams),
        "decisions": len(decisions),
        "derived": sum(len(fm["provenance"]["derived"]) for fm in fams),
        "citations": sum(len(fm["provenance"]["citations"]) for fm in fams),
        "documents": sum(len(fm["provenance"]["documents"]) for fm in fams),
        "problems": len(problems.items),
    }
    return {"summary": summary, "problems": problems.items, "problem_lines": problems.lines(), "decisions": decisions,
            "coverage_definitions": cov.DEFINITIONS, "coverage_columns": list(cov.COLUMNS),
            "families": fams}


class _FamilyView:
    """One family's part of the review; each method builds one section of it."""

    def __init__(self, fam, vectors, quotes_checked, missing, problems):
        self.fam, self.doc, self.name, self.vectors = fam, fam.doc, fam.name, vectors
        self.quotes_checked, self.missing, self.problems = quotes_checked, missing, problems

    def link(self, kind, ident):
        return anchor(kind, self.name, ident)

    def source(self, where, node):
        """A quote with its source and whether the manual holds it (missing quotes are problems, see build_model);
        a citation of another document or a derivation is shown in the same shape, with what it states."""
        if "states" in node:
            documents = {d["id"]: d for d in self.doc.get("documents", ())}
            document = documents.get(node["document"])
            label = prov.document_label(document) if document else f"unknown document {node['document']}"
            return {"quote": node["states"], "file": label, "section": node.get("section", "") +
                    (f", p. {node['page']}" if node.get("page") else ""), "line": self.fam.line_of(*where, "document"),
                    "status": "stated by another document (not held by the project, not checked)", "reason": None,
                    "kind": "document"}
        if "derived" in node and "quote" not in node:
            return {"quote": node["derived"], "file": "derived", "section": node.get("section", ""),
                    "line": self.fam.line_of(*where, "derived"), "status": "derived (no document states it)",
                    "reason": None, "kind": "derived"}
        line = self.fam.line_of(*where, "quote")
        reason = self.missing.get((self.name, line, node["quote"]))
        status = "not checked" if not self.quotes_checked else ("missing" if reason else "found")
        return {"quote": node["quote"], "file": node.get("file") or self.doc["manual"], "section": node.get("section", ""),
                "line": line, "status": status, "reason": reason, "kind": "quote"}

    def build(self, audit, cells=None, manuals=(), pages=None):
        fam, doc = self.fam, self.doc
        page = None if pages is None else pages.get(doc["manual"])
        coverage = cov.family_coverage(fam, self.vectors)
        audit_rows = _audit_rows(fam, audit, self.problems, self.link)
        return {
            "name": self.name, "anchor": self.link("family", None), "title": doc["title"], "kind": fam.kind,
            "spec_file": fam.path.name, "manual": doc["manual"], "vector_count": len(self.vectors),
            "instructions": _instructions(fam),
            "operands": [{"name": op, "size": _size(o), "role": o["role"], "constant": "yes" if o.get("constant") else "no",
                          "clause": o["clause"], "clause_anchor": self.link("clause", o["clause"])}
                         for op, o in doc["operands"].items()],
            "layout": _layout(fam, self.link),
            "selector": _selector(fam, self.link),
            "parameters": _parameters(fam, self.link),
            "clauses": self.clauses(coverage),
            "interpretations": self.interpretations(),
            "errata": self.errata(audit_rows),
            "assumptions": [{"name": k, "settings": _text({x: y for x, y in v.items() if x != "why"}), "why": v["why"]}
                            for k, v in doc["assumptions"].items()],
            "examples": self.examples(),
            "audit": audit_rows,
            "audit_available": audit is not None,
            "coverage": self.coverage(coverage),
            "model": cov.model_coverage(fam, cells, self.problems, self.link) if cells is not None else None,
            "provenance": prov.family_provenance(fam, set(manuals) or {doc["manual"]}, self.problems, self.link),
            "accounting": self.accounting(page),
        }

    def accounting(self, page):
        """The sentence accounting of the page; each wording note's texts shown as the quotes they are."""
        found = acc.family_accounting(self.fam, page[1] if page else None, page[0] if page else None,
                                      self.problems, self.link)
        for note in found["notes"]:
            note["words"] = [self.source(("accounting", note["index"], "texts", j), {"quote": text})
                             for j, text in enumerate(note["texts"])]
        return found

    def clauses(self, coverage):
        return [{"id": c["id"], "anchor": self.link("clause", c["id"]), "says": c["says"],
                 "source": self.source(("clauses", i, "source"), c["source"]),
                 "derived": c.get("derived", ""),
                 "cites": [self.source(("clauses", i, "cites", j), x) for j, x in enumerate(c.get("cites", ()))],
                 "line": self.fam.line_of("clauses", i), "vectors": coverage[c["id"]].total,
                 "status": coverage[c["id"]].status}
                for i, c in enumerate(self.doc["clauses"])]

    def coverage(self, coverage):
        rows = []
        for i, c in enumerate(self.doc["clauses"]):
            row, where = coverage[c["id"]], self.link("coverage", c["id"])
            if row.problem:
                self.problems.add("coverage", self.fam, self.fam.line_of("clauses", i), row.problem, where)
            rows.append({"clause": c["id"], "anchor": where, "clause_anchor": self.link("clause", c["id"]),
                         "counts": row.counts, "samples": row.samples, "total": row.total,
                         "status": row.status, "why": row.no_vectors_why, "cited_by": row.cited_by})
        return rows

    def interpretations(self):
        return [{"id": it["id"], "anchor": self.link("interpretation", it["id"]),
                 "line": self.fam.line_of("interpretations", i), "question": it["question"],
                 "quotes": [self.source(("interpretations", i, "quotes", j), q) for j, q in enumerate(it["quotes"])],
                 "default": it["default"], "why": it["why"],
                 "alternatives": [{"id": a["id"], "says": a["says"], "default": a["id"] == it["default"],
                                   "sets": _text(a["sets"]),
                                   "unjudged": _text(a["unjudged"]) if "unjudged" in a else ""}
                                  for a in it["alternatives"]],
                 "decides": _decided_by(self.doc, it["id"]),
                 "vectors": sum(1 for v in self.vectors if _touches(v, it["id"]))}
                for i, it in enumerate(self.doc["interpretations"])]

    def errata(self, audit_rows):
        return [{"id": e["id"], "anchor": self.link("erratum", e["id"]), "line": self.fam.line_of("errata", i),
                 "clause": e["clause"], "clause_anchor": self.link("clause", e["clause"]),
                 "printed": e["printed"], "quote": self.source(("errata", i), e), "rule": e["rule"],
                 "vectors_follow": e["vectors_follow"],
                 "findings": [f["anchor"] for f in audit_rows if f["erratum"] == e["id"]]}
                for i, e in enumerate(self.doc["errata"])]

    def examples(self):
        shown_apart = ("id", "clause", "says", "reconstructed", "reconstruction")
        rows = []
        for i, ex in enumerate(self.doc.get("examples", [])):
            recon = ex.get("reconstruction")
            rows.append({"id": ex["id"], "anchor": self.link("example", ex["id"]), "clause": ex["clause"],
                         "clause_anchor": self.link("clause", ex["clause"]), "says": ex.get("says", ""),
                         "reconstructed": bool(ex.get("reconstructed")),
                         "reconstruction": self.source(("examples", i, "reconstruction"), recon) if recon else None,
                         # A table of printed rows reads best one row per line.
                         "given": [{"key": k, "lines": [_text(x) for x in v]
                                    if isinstance(v, list) and any(isinstance(x, dict) for x in v) else [_text(v)]}
                                   for k, v in ex.items() if k not in shown_apart]})
        return rows


def _touches(vector, iid):
    """A vector is affected by an interpretation when its outcome or one of its alternatives names it."""
    if iid in vector["outcome"].get("interpretations", []):
        return True
    return any(iid in alt["choices"] for alt in vector.get("alternatives", []))


def _decided_by(doc, iid):
    """The rule parameters (dotted paths) whose value the interpretation decides."""
    found = []

    def walk(node, where):
        if isinstance(node, dict):
            if node == {"interpretation": iid}:
                found.append(".".join(map(str, where)))
                return
            for k, v in node.items():
                walk(v, where + (k,))
        elif isinstance(node, list):
            for i, v in enumerate(node):
                walk(v, where + (i,))

    walk({k: v for k, v in doc.items() if k != "interpretations"}, ())
    return found


def _text(value):
    """A compact, deterministic rendering of a spec value for a table cell."""
    if isinstance(value, dict):
        return ", ".join(f"{k}: {_text(v)}" for k, v in value.items())
    if isinstance(value, list):
        return "[" + ", ".join(_text(v) for v in value) + "]"
    if isinstance(value, bool):
        return "true" if value else "false"
    return str(value)


def _size(operand):
    if "words" in operand:
        return f"{operand['words']} word{'s' if operand['words'] != 1 else ''}"
    return f"{operand['bits']} bit{'s' if operand['bits'] != 1 else ''}"


def _instructions(fam):
    rows = []
    for item in instruction_list(fam):
        rows.append({"name": item["name"], "st": item.get("st", item["name"]),
                     "function_code": item.get("function_code", ""),
                     "how": _text({k: v for k, v in (item["form"] if "form" in item else item).items()
                                   if k in ("form", "logic", "execution")})})
    return rows


def _layout(fam, link):
    """The words of the data operands drawn bit by bit: which word and which bits hold which field."""
    doc = fam.doc
    fields = doc["data"]["fields"]
    operands = [op for op, o in doc["operands"].items() if o["role"] in _DATA_ROLES]
    words = max(f["word"] for f in fields) + 1
    rows = []
    for w in range(words):
        cells, bit = [], WORD_BITS - 1
        for f in sorted((f for f in fields if f["word"] == w), key=lambda f: -f["lsb"]):
            top = f["lsb"] + f["width"] - 1
            if top < bit:
                cells.append({"field": None, "span": bit - top})
            cells.append({"field": f["name"], "span": f["width"], "bits": f"{top}–{f['lsb']}",
                          "encoding": f["encoding"], "range": f"{f['min']} to {f['max']}",
                          "clause": f["clause"], "clause_anchor": link("clause", f["clause"])})
            bit = f["lsb"] - 1
        if bit >= 0:
            cells.append({"field": None, "span": bit + 1})
        rows.append({"anchor": link("layout", f"word{w}"), "offset": f"+{w}",
                     "words": ", ".join(f"{op}+{w}" for op in operands), "cells": cells})
    return {"operands": operands, "bits": list(range(WORD_BITS - 1, -1, -1)), "rows": rows,
            "fields": [{"name": f["name"], "word": f"+{f['word']}", "bits": f"{f['lsb'] + f['width'] - 1}–{f['lsb']}",
                        "encoding": f["encoding"], "range": f"{f['min']} to {f['max']}", "clause": f["clause"],
                        "clause_anchor": link("clause", f["clause"])} for f in fields]}


def _selector(fam, link):
    """The selector word bit by bit, for the kinds that have one."""
    sel = fam.doc.get("selector")
    if not sel:
        return None
    meaning = {}
    for field, bit in sel["field_bits"].items():
        clause = sel["field_clauses"][field]
        verb = "1 = compare" if sel["polarity"] == "select" else "1 = mask (leave out)"
        meaning[bit] = (field, f"{field}: {verb}", clause)
    for bit in sel["reserved_bits"]:
        meaning[bit] = ("reserved", f"reserved: {_param(fam, sel['on_reserved'])} when set", sel.get("reserved_clause"))
    if "source_bit" in sel:
        meaning[sel["source_bit"]["bit"]] = ("current clock", "1 = compare with the current clock instead of the second operand",
                                             sel["source_bit"]["clause"])
    bits = []
    for bit in range(WORD_BITS - 1, -1, -1):
        short, text, clause = meaning.get(bit, ("—", "not described", None))
        bits.append({"bit": bit, "short": short, "text": text, "clause": clause,
                     "clause_anchor": link("clause", clause) if clause else None})
    return {"operand": sel["operand"], "polarity": sel["polarity"], "bits": bits,
            "no_field": _param(fam, sel["on_no_field"]), "no_field_clause": sel["no_field_clause"],
            "no_field_anchor": link("clause", sel["no_field_clause"])}


def _param(fam, value):
    """A rule parameter's value, or the interpretation that decides it with its default."""
    if isinstance(value, dict) and set(value) == {"interpretation"}:
        it = fam.interpretations[value["interpretation"]]
        return f"decided by {it['id']} (default {it['default']})"
    return _text(value)


def _parameters(fam, link):
    """Every remaining rule parameter of the spec, one row each, beside the clause it comes from."""
    rows = []

    def add(path, value, clause, interpretation=None):
        rows.append({"parameter": ".".join(map(str, path)), "value": value, "clause": clause,
                     "clause_anchor": link("clause", clause) if clause else None,
                     "interpretation": interpretation,
                     "interp_anchor": link("interpretation", interpretation) if interpretation else None})

    def walk(node, path, clause):
        if isinstance(node, dict):
            if set(node) == {"interpretation"}:
                it = fam.interpretations[node["interpretation"]]
                add(path, f"default {it['default']}", clause, it["id"])
                return
            clause = node.get("clause", clause)
            if not any(isinstance(v, (dict, list)) or k.endswith(("clause", "_clauses")) for k, v in node.items()):
                add(path, _text(node), clause)  # a small record (a date, a bit map) reads best on one row
                return
            for k, v in node.items():
                if k == "clause":
                    continue
                if k.endswith("_clause"):
                    add(path + (k[:-len("_clause")],), "rule", v)
                elif k.endswith("_clauses"):
                    for item, c in v.items():
                        add(path + (k[:-len("_clauses")], item), "rule", c)
                else:
                    walk(v, path + (k,), clause)
        elif isinstance(node, list) and any(isinstance(v, dict) for v in node):
            for i, v in enumerate(node):
                label = v.get("id", v.get("name", i)) if isinstance(v, dict) else i
                walk(v, path + (label,), clause)
        else:
            add(path, _text(node), clause)

    for key, value in fam.doc.items():
        if key in _OWN_SECTIONS:
            continue
        if key == "data":
            value = {k: v for k, v in value.items() if k != "fields"}
        walk(value, (key,), None)
    return rows


def _audit_rows(fam, audit, problems, link):
    """The audit's findings about this family, each with a stable anchor; unrecorded disagreements are problems."""
    if audit is None:
        return []
    example_line = {ex["id"]: fam.line_of("examples", i) for i, ex in enumerate(fam.doc.get("examples", []))}
    erratum_line = {e["id"]: fam.line_of("errata", i) for i, e in enumerate(fam.doc["errata"])}
    rows, seen = [], set()
    for f in audit.findings:
        if f.family != fam.name:
            continue
        where = link("audit", f"{slug(f.example or 'family')}-{f.kind}-{slug(f.cell)}")
        base, n = where, 2
        while where in seen:
            where, n = f"{base}-{n}", n + 1
        seen.add(where)
        erratum = getattr(f, "erratum", None)
        problem = (f.kind in AUDIT_PROBLEM_KINDS and erratum is None) or f.kind == AUDIT_STALE_KIND
        if problem:
            if f.kind == AUDIT_STALE_KIND and erratum in erratum_line:
                line, what = erratum_line[erratum], f"erratum {erratum}"
            else:
                line, what = example_line.get(f.example), f"example {f.example or '-'}"
            note = "" if f.kind == AUDIT_STALE_KIND else " (no erratum of the spec records it)"
            problems.add("audit", fam, line, f"{what}, {f.cell}: {f.message}{note}", where)
        extra = []
        if getattr(f, "conflicting_cells", ()):
            extra.append("cells that cannot all hold: " + "; ".join(map(str, f.conflicting_cells)))
        if getattr(f, "corrections", ()):
            extra.append("smallest sets of cells that would have to be misprinted: "
                         + " | ".join("; ".join(map(str, c)) if isinstance(c, (list, tuple)) else str(c) for c in f.corrections))
        if getattr(f, "values", None):
            extra.append("values that reproduce the table: " + _text(f.values))
        rows.append({"anchor": where, "kind": f.kind, "example": f.example or "", "cell": f.cell,
                     "printed": "" if f.printed is None else str(f.printed),
                     "derived": "" if f.derived is None else str(f.derived),
                     "message": f.message, "erratum": erratum,
                     "erratum_anchor": link("erratum", erratum) if erratum else None,
                     "extra": extra, "problem": problem})
    return rows
