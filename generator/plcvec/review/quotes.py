"""Every provenance quote of the spec must be found in the manual text it names.

The manual excerpts are text copies of PDFs: line breaks, hyphenation breaks and table cell borders
fall where the PDF put them, so quotes are compared with all white space removed. Nothing else is
forgiven: a quote that differs in a letter is reported, since a reviewer must be able to find it.
"""
import re
from dataclasses import dataclass
from pathlib import Path

from plcvec.errors import PlcvecError

# The singular of each top-level list that holds quoted items, for naming a quote's owner.
_OWNER = {"clauses": "clause", "interpretations": "interpretation", "errata": "erratum", "examples": "example",
          "accounting": "accounting"}


@dataclass(frozen=True)
class Quote:
    """One `quote` of a spec file: where it is written and which manual file it must be found in."""
    family: str
    spec_file: Path
    line: int | None
    owner: str          # "clause purpose", "interpretation FX5-SM709-SCOPE", "erratum ...", "example ..."
    source: str         # the manual file the quote comes from
    quote: str

    def location(self):
        return f"{self.spec_file}:{self.line}" if self.line else str(self.spec_file)


def squash(text):
    return re.sub(r"\s+", "", text)


def spec_quotes(fam):
    """Every `quote` in a family's spec document, in document order.

    A quote's source file is the `file` written beside it, else the family's `manual`.
    """
    found = []

    def walk(node, where):
        if isinstance(node, dict):
            if isinstance(node.get("quote"), str):
                found.append(Quote(fam.name, fam.path, fam.line_of(*where, "quote"), owner_of(fam.doc, where),
                                   node.get("file") or fam.doc["manual"], node["quote"]))
            for k, v in node.items():
                walk(v, where + (k,))
        elif isinstance(node, list):
            for i, v in enumerate(node):
                walk(v, where + (i,))

    walk(fam.doc, ())
    # The texts of the sentence accounting (plcvec.review.accounting) are quotes of the page too.
    for i, entry in enumerate(fam.doc.get("accounting", ())):
        for j, text in enumerate(entry["texts"]):
            found.append(Quote(fam.name, fam.path, fam.line_of("accounting", i, "texts", j),
                               f"accounting entry {i + 1} ({entry['as']})", fam.doc["manual"], text))
    return found


def owner_of(doc, where):
    """`clause purpose`, `interpretation FX5-SM709-SCOPE`: the item of the spec a value at `where` belongs to."""
    if len(where) >= 2 and where[0] in _OWNER and isinstance(where[1], int):
        item = doc[where[0]][where[1]]
        return f"{_OWNER[where[0]]} {item.get('id', where[1])}"
    return ".".join(map(str, where))


def read_manual(manual_dir):
    """{file name: text with white space removed} of every file in the manual folder.

    Bad input is the user's: a folder that is missing or unreadable raises PlcvecError.
    """
    folder = Path(manual_dir)
    if not folder.is_dir():
        raise PlcvecError(f"--manual-dir {folder}: not a folder")
    texts = {}
    try:
        for path in sorted(folder.iterdir()):
            if path.is_file():
                texts[path.name] = squash(path.read_text(encoding="utf-8"))
    except OSError as exc:
        raise PlcvecError(f"--manual-dir {folder}: cannot read {exc.filename or folder}: {exc.strerror or exc}") from None
    except UnicodeDecodeError as exc:
        raise PlcvecError(f"--manual-dir {folder}: {path.name} is not UTF-8 text ({exc.reason})") from None
    if not texts:
        raise PlcvecError(f"--manual-dir {folder}: the folder holds no files")
    return texts


@dataclass(frozen=True)
class MissingQuote:
    quote: Quote
    reason: str         # "not found in <file>", or "no file <file> in the manual folder"

    def message(self):
        return f"{self.quote.owner}: quote {self.reason}: {self.quote.quote!r}"

    def problem(self):
        return f"{self.quote.location()}: {self.message()}"


def check_quotes(families, texts):
    """(every quote of the families, the MissingQuote of each one not found in its manual file).

    texts: the manual as read_manual returns it.
    """
    checked, missing = [], []
    for fam in families:
        for q in spec_quotes(fam):
            checked.append(q)
            if q.source not in texts:
                missing.append(MissingQuote(q, f"no file {q.source} in the manual folder"))
            elif squash(q.quote) not in texts[q.source]:
                missing.append(MissingQuote(q, f"not found in {q.source}"))
    return checked, missing
