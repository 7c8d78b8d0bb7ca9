"""Where every fact of the spec comes from, when it is not a quote of the family's own page.

A fact is traceable when a reviewer can find it: a quote of a page excerpt the spec encodes (checked
by plcvec.review.quotes), a citation of a document the family lists under `documents` (title and,
where known, number, section and page: the project does not hold these documents, so what they state
is written in the spec's words under `states`, never as a checked quote), or a clause marked
`derived` with the reasoning that takes it from the pages to what it says. A `file:` beside a quote
may name only a page excerpt of the spec; anything else (a file of notes, a document the project
does not hold) is a problem for `plcvec review --check`.
"""
from __future__ import annotations

from plcvec.review.quotes import owner_of as _owner
from plcvec.spec.checks import _walk   # (path, mapping) of every mapping of a spec document


def document_label(document):
    """`Title (number)`, the way a reader asks a library for it."""
    return document["title"] + (f" ({document['number']})" if document.get("number") else "")


def family_provenance(fam, manuals, problems, link):
    """The documents, citations and derived facts of one family, and a problem for each untraceable one.

    manuals: the page excerpt of every family of the spec (the only files a quote may name).
    problems: plcvec.review.model.Problems; link(kind, ident): an anchor of the report.
    """
    doc = fam.doc
    documents = {d["id"]: d for d in doc.get("documents", ())}
    cited = set()
    citations, derived = [], []
    for where, node in _walk({k: v for k, v in doc.items() if k != "documents"}):
        owner = _owner(doc, where)
        if isinstance(node.get("file"), str) and "quote" in node and node["file"] not in manuals:
            problems.add("provenance", fam, fam.line_of(*where, "file"),
                         f"{owner}: cites {node['file']!r}, a file the project does not hold (the page excerpts are "
                         f"{', '.join(sorted(manuals))}); cite another manual's fact with `document:` from `documents`",
                         link("family", None))
        if isinstance(node.get("document"), str) and "states" in node:
            line = fam.line_of(*where, "document")
            document = documents.get(node["document"])
            if document is None:
                problems.add("provenance", fam, line,
                             f"{owner}: cites document {node['document']!r}, which `documents` does not list "
                             f"(listed: {', '.join(sorted(documents)) or 'none'})", link("family", None))
                continue
            cited.add(node["document"])
            citations.append({"owner": owner, "line": line, "document": node["document"],
                              "label": document_label(document), "section": node["section"],
                              "page": node.get("page", ""), "states": node["states"]})
        if isinstance(node.get("derived"), str):
            derived.append({"owner": owner, "line": fam.line_of(*where, "derived"),
                            "says": node.get("says", ""), "reasoning": node["derived"],
                            "quote": (node.get("source") or {}).get("quote", "") if "source" in node else "",
                            "anchor": link("clause", node["id"]) if where[:1] == ("clauses",) else link("family", None)})
    for i, d in enumerate(doc.get("documents", ())):
        if d.get("excerpt") is not None and d["excerpt"] != doc["manual"]:
            problems.add("provenance", fam, fam.line_of("documents", i, "excerpt"),
                         f"document {d['id']!r}: excerpt {d['excerpt']!r} is not this family's page ({doc['manual']})",
                         link("family", None))
        elif d["id"] not in cited and d.get("excerpt") is None:
            problems.add("provenance", fam, fam.line_of("documents", i),
                         f"document {d['id']!r} is listed but nothing cites it", link("family", None))
    return {"documents": [dict(d, label=document_label(d)) for d in doc.get("documents", ())],
            "citations": citations, "derived": derived}
