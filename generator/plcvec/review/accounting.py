"""Every sentence of the pages accounted for.

Each page excerpt is cut into units: a table row (a line holding a tab or starting with `|`) is one
unit; any other line is cut into sentences. A unit is accounted for when quotes of the family's spec
cover at least half of its letters and digits: a clause's quote, an interpretation's, an erratum's,
an example's prose, or an entry of the spec's `accounting` list, which records what is left:

    accounting:
      - {as: clause, clauses: [example.1], why: "...", texts: ["| (s1) | 6 | | (s2) | 7 | ..."]}
      - {as: not-normative, why: "The CPU models the page applies to.", texts: ["FX5S FX5UJ FX5U FX5UC"]}
      - {as: wording, clauses: [sm700], says: "...", rule: "...", why: "...", texts: ["..."]}
      - {as: erratum, erratum: TADD-EXCEEDS-24, why: "...", texts: ["..."]}

Accounting for a sentence is not agreeing with it. Where the words of the page say more or less than
the rule they are filed under, or only touch it, the entry is a wording note: the `clauses` of the rule,
what the words `says`, what the `rule` says and `why` the rule stands; the review lists the notes beside
the errata. (An older wording entry gives only what the rest of the page shows `instead`.)

`plcvec review --check` names each unit nobody accounted for as `file:line` of the page, and an entry
that names a clause or an erratum the family does not have. Like the quote check, matching ignores
white space (the excerpts are PDF text copies whose line breaks fall anywhere), so a quote may run
across lines and units; the texts of every entry are quotes, so a text not on the page is a missing quote.
"""
from __future__ import annotations

import re
from dataclasses import dataclass

# Half of a unit's letters and digits: a quote of part of a sentence accounts for it (the reviewer sees
# the sentence used), a word it shares with a quote of another sentence does not.
COVERED_SHARE = 0.5
# A sentence ends at . ! ? followed by space and a capital (or a bullet, a quote, a parenthesis), or at a
# full stop glued to the next sentence's capital, as the HOUR page's PDF text has them ("2-1.Source").
_SENTENCE_END = re.compile(r"(?<=[.!?])\s+(?=[A-Z(\"■•-])|(?<=[a-z0-9)\"”]\.)(?=[A-Z])")
_ALNUM = re.compile(r"[0-9A-Za-z]")


@dataclass(frozen=True)
class Unit:
    file: str
    line: int
    text: str
    start: int      # in the page's text with white space removed
    end: int


def units(name: str, text: str) -> list[Unit]:
    """The sentences and table rows of a page, each with its line and its span in the squashed text."""
    out, offset = [], 0
    for number, line in enumerate(text.split("\n"), 1):
        pieces = [line] if ("\t" in line or line.lstrip().startswith("|")) else _SENTENCE_END.split(line)
        for piece in pieces:
            squashed = re.sub(r"\s+", "", piece)
            if _ALNUM.search(squashed):
                out.append(Unit(name, number, piece.strip(), offset, offset + len(squashed)))
            offset += len(squashed)
    return out


def _covered(squashed_page: str, quotes) -> bytearray:
    mask = bytearray(len(squashed_page))
    for quote in quotes:
        q = re.sub(r"\s+", "", quote)
        if not q:
            continue
        at = squashed_page.find(q)
        while at != -1:
            mask[at:at + len(q)] = b"\1" * len(q)
            at = squashed_page.find(q, at + 1)
    return mask


def unaccounted(name: str, text: str, quotes) -> tuple[list[Unit], list[Unit]]:
    """(every unit of the page, the units the quotes do not account for)."""
    squashed = re.sub(r"\s+", "", text)
    mask = _covered(squashed, quotes)
    every, left = units(name, text), []
    for unit in every:
        letters = [i for i in range(unit.start, unit.end) if _ALNUM.match(squashed[i])]
        if sum(mask[i] for i in letters) < COVERED_SHARE * len(letters):
            left.append(unit)
    return every, left


def family_quotes(fam) -> list[str]:
    """Every quote of the family's spec that is taken from its own page (plcvec.review.quotes finds them)."""
    from plcvec.review.quotes import spec_quotes

    return [q.quote for q in spec_quotes(fam) if q.source == fam.doc["manual"]]


def family_accounting(fam, page_text: str | None, page_path, problems, link):
    """The accounting of one family's page: counts, the spec's entries, its wording notes, and a problem per
    unit left and per entry that names what the family does not have.

    page_text: the page as read from --manual-dir, or None when no manual folder was given.
    """
    entries = [{"as": e["as"], "texts": e["texts"], "why": e["why"], "clauses": e.get("clauses", []),
                "erratum": e.get("erratum", ""), "says": e.get("says", ""), "rule": e.get("rule", ""),
                "instead": e.get("instead", ""), "index": i, "line": fam.line_of("accounting", i), "note": ""}
               for i, e in enumerate(fam.doc.get("accounting", ()))]
    _check_names(fam, entries, problems, link)
    notes = wording_notes(fam, entries, link)
    if page_text is None:
        return {"checked": False, "units": None, "left": [], "entries": entries, "notes": notes}
    every, left = unaccounted(fam.doc["manual"], page_text, family_quotes(fam))
    for unit in left:
        problems.add_at("accounting", f"{page_path}:{unit.line}", fam.doc["manual"], unit.line,
                        f"no clause, interpretation, erratum or accounting entry accounts for {_short(unit.text)!r}",
                        link("family", None))
    return {"checked": True, "units": len(every), "left": [{"line": u.line, "text": u.text} for u in left],
            "entries": entries, "notes": notes}


def _check_names(fam, entries, problems, link):
    """An erratum entry names an erratum of the family, a clause or wording entry clauses of the family."""
    errata = {e["id"] for e in fam.doc.get("errata", ())}
    for e in entries:
        what = "wording note" if e["as"] == "wording" else "accounting"
        if e["as"] == "erratum" and e["erratum"] not in errata:
            problems.add("accounting", fam, e["line"],
                         f"accounting: erratum {e['erratum']!r} is not an erratum of this family", link("family", None))
        for cid in e["clauses"]:
            if cid not in fam.clauses:
                problems.add("accounting", fam, e["line"],
                             f"{what}: clause {cid!r} is not a clause of this family", link("family", None))


def wording_notes(fam, entries, link):
    """The wording entries, each with its anchor (also set as the entry's `note`) and the rule it is filed
    under: its clauses with their `says`."""
    notes = []
    for e in (e for e in entries if e["as"] == "wording"):
        e["note"] = link("wording", len(notes) + 1)
        e["filed_under"] = [{"id": cid, "says": fam.clauses[cid]["says"], "anchor": link("clause", cid)}
                            for cid in e["clauses"] if cid in fam.clauses]
        notes.append(e)
    return notes


def _short(text, limit=120):
    return text if len(text) <= limit else text[:limit - 1] + "…"
