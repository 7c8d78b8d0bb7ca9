"""`plcvec review`: write the review (HTML and Markdown) and, with --check, fail on its problems."""
import sys
from pathlib import Path

from plcvec.errors import PlcvecError
from plcvec.output.workers import add_jobs_option

FILES = ("review.html", "review.md")


def default_out():
    """build/review of the checkout in use, else of the current folder."""
    from plcvec_verify.locate import checkout

    return (checkout() or Path.cwd()) / "build" / "review"


def register(sub, spec_parent):
    r = sub.add_parser("review", parents=[spec_parent],
                       help="render the spec for a reviewer: rules beside manual quotes, audit, coverage",
                       description="Render the whole spec as one self-contained HTML file and as Markdown: "
                                   "layouts, every rule beside its manual quote, interpretations with the vectors "
                                   "they affect, errata and wording notes, the audit of the manual's tables, and "
                                   "the coverage matrix.")
    r.add_argument("--out", default=str(default_out()),
                   help="folder for review.html and review.md (default: %(default)s)")
    r.add_argument("--manual-dir", metavar="DIR",
                   help="the manual text files; every provenance quote of the spec must be found in them")
    r.add_argument("--check", action="store_true",
                   help="exit 1 on a missing quote, an uncovered clause, a sentence of a page nothing accounts for "
                        "(with --manual-dir), a wording note or accounting entry naming a clause or erratum the family "
                        "does not have, a combination of the coverage model no vector exercises, or an audit "
                        "disagreement no erratum records")
    r.add_argument("--no-write", action="store_true", help="with --check: only check, write no report")
    add_jobs_option(r)
    r.set_defaults(func=run)


def run(args):
    from plcvec.output.atomic import write_atomic
    from plcvec.output.golden import family_cost, vectors_and_cells
    from plcvec.output.workers import map_families
    from plcvec.review.model import build_model, run_audit
    from plcvec.review.quotes import check_quotes, read_manual
    from plcvec.review.render import render
    from plcvec_verify.collector import collector_paused
    from plcvec.spec.loader import load_spec

    if args.no_write and not args.check:
        raise PlcvecError("--no-write only makes sense with --check")
    # The manual folder is read first: a wrong path is reported before the slower work.
    manual = read_manual(args.manual_dir) if args.manual_dir else None
    families = load_spec(args.spec_dir)
    quotes = check_quotes(families, manual) if manual is not None else None
    # The vectors this spec generates, built in process (not read from vectors/), so the review always
    # describes the spec given by --spec-dir; the files' serialization is not needed here.
    with collector_paused():
        built = map_families(vectors_and_cells, families, args.jobs, family_cost)
    vectors = {fam.name: fam_vectors for fam, (fam_vectors, _) in zip(families, built)}
    cells = {fam.name: fam_cells for fam, (_, fam_cells) in zip(families, built)}
    pages = _pages(args.manual_dir, families) if manual is not None else None
    model = build_model(families, vectors, quotes=quotes, audit=run_audit(families), cells=cells, pages=pages)
    out = Path(args.out)
    if not args.no_write:
        if out.exists() and not out.is_dir():
            raise PlcvecError(f"--out {out}: not a folder")
        for name, text in render(model).items():
            write_atomic(out / name, text)
    print(_headline(model["summary"], args.spec_dir) + ("" if args.no_write else f"; wrote {', '.join(str(out / n) for n in FILES)}"))
    if args.check:
        for line in model["problem_lines"]:
            print(line, file=sys.stderr)
        if model["problems"]:
            print(f"plcvec review --check: {len(model['problems'])} problems", file=sys.stderr)
            return 1
    return 0


def _pages(manual_dir, families):
    """{page file name: (path, text)} of every family's page found in the manual folder (one that is
    missing is already reported by the quote check)."""
    pages = {}
    for fam in families:
        path = Path(manual_dir) / fam.doc["manual"]
        if path.is_file():
            try:
                pages[path.name] = (path, path.read_text(encoding="utf-8"))
            except (OSError, UnicodeDecodeError) as exc:
                raise PlcvecError(f"--manual-dir {manual_dir}: cannot read {path.name}: {exc}") from None
    return pages


def _headline(s, spec_dir):
    quotes = "quotes not checked" if s["quotes_checked"] is None else \
        f"{s['quotes_missing']} of {s['quotes_checked']} quotes missing"
    audit = f"{s['audit_unrecorded']} unrecorded audit disagreements" if s["audit_available"] else "audit not available"
    sentences = "sentences not checked" if s["sentences"] is None else \
        f"{s['sentences_unaccounted']} of {s['sentences']} sentences and table rows unaccounted for"
    return (f"plcvec review of {spec_dir}: {s['families']} families, {s['clauses']} clauses, {s['vectors']} vectors; {quotes}; "
            f"{sentences}; {s['derived']} derived claims; {s['decisions']} engine decisions; "
            f"{s['uncovered']} uncovered clauses; {s['model_missing']} of {s['model_required']} coverage-model "
            f"combinations with no vector; {audit}")
