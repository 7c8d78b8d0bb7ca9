"""The reference tables of `verifiers/CONTRACT.md` and each native README, rendered from the spec.

Per family: the instructions (ladder and structured-text spellings, form, condition, execution), the
operands (device kind and words), the clock fields, the flags and error devices, and every
interpretation with its question, alternatives and default. `plcvec export` writes them between the
markers below in each file (the rest of the file is hand-written) and `--check` reports a file whose
tables differ, or that lacks the markers.
"""
from __future__ import annotations

import re
from pathlib import Path

from plcvec.errors import PlcvecError
from plcvec.spec.flags import flag_groups

BEGIN = "<!-- plcvec:reference-tables -->"
END = "<!-- /plcvec:reference-tables -->"
TEMPLATE = Path(__file__).resolve().parent / "templates" / "reference-tables.md.j2"
# Where the tables go: the contract, rendered with every language, and each language's README.
CONTRACT = "verifiers/CONTRACT.md"
README = "verifiers/{lang}/README.md"


def family_reference(fam) -> dict:
    """The reference of one loaded spec family (plcvec.spec.loader.Family), as plain values."""
    doc = fam.doc
    operands = []
    for name, op in doc["operands"].items():
        kind = "bit" if "bits" in op else "word"
        operands.append({"name": name, "role": op["role"], "kind": kind,
                         "size": op.get("words", op.get("bits", 1)),
                         "constant": bool(op.get("constant")), "clause": op["clause"]})
    fields = [{"name": f["name"], "word": f["word"], "bits": f"{f['lsb']}-{f['lsb'] + f['width'] - 1}",
               "encoding": f["encoding"], "min": f["min"], "max": f["max"], "clause": f["clause"]}
              for f in doc["data"]["fields"]]
    return {"operands": operands, "fields": fields, "flags": flag_groups(doc),
            "interpretations": [{"id": i["id"], "question": i["question"], "default": i["default"],
                                 "alternatives": [{"id": a["id"], "says": a["says"]} for a in i["alternatives"]]}
                                for i in doc["interpretations"]]}


def replace_section(path: Path, text: str, tables: str) -> str:
    """`text` with everything between the markers replaced by `tables`; PlcvecError when the markers
    are missing, doubled or out of order."""
    begins, ends = text.count(BEGIN), text.count(END)
    if begins != 1 or ends != 1 or text.index(BEGIN) > text.index(END):
        raise PlcvecError(f"{path}: needs the line {BEGIN} and, after it, {END} once each "
                          f"(found {begins} and {ends}); `plcvec export` writes the reference tables between them")
    head, rest = text.split(BEGIN, 1)
    _, tail = rest.split(END, 1)
    return f"{head}{BEGIN}\n{tables}{END}{tail}"


def render_tables(model) -> str:
    """The tables for every family of the model, as Markdown (the same text in every file)."""
    import jinja2

    from plcvec.review.render import md_cell, md_code

    env = jinja2.Environment(loader=jinja2.FileSystemLoader(str(TEMPLATE.parent)), undefined=jinja2.StrictUndefined,
                             keep_trailing_newline=True, trim_blocks=True, lstrip_blocks=True, autoescape=False)
    env.filters.update(md=md_cell, code=md_code)
    try:
        return env.get_template(TEMPLATE.name).render(suite=model)
    except jinja2.TemplateError as exc:
        raise PlcvecError(f"{TEMPLATE}: {exc}") from None


# The native runners whose README carries the tables (a language added for a test, or one without a
# README of its own, is rendered without them).
NATIVE = ("c", "go", "java", "rust", "typescript")


def targets(langs) -> list[str]:
    """The files that carry the tables for these languages: the contract and each native README."""
    return [CONTRACT] + [README.format(lang=lang) for lang in langs if lang in NATIVE]
