"""`plcvec diff OLD NEW`: vectors added, removed and changed between two vector sets, by id.

Exit status as diff(1): 0 when the sets are the same, 1 when they differ, 2 when one cannot be read.
"""
import json
import sys

from plcvec.output import diff


def register(sub, spec_parent):
    # The spec folder plays no part: both sides are vector sets, so `spec_parent` is not inherited.
    d = sub.add_parser(
        "diff", help="compare two vector sets by vector id (folders, family files or git revisions)",
        description="Report the vectors added, removed and changed between OLD and NEW, by id; a changed vector is "
                    "classed as expectation, inputs or metadata. OLD and NEW are each a folder with manifest.json "
                    "(or a checkout holding vectors/), a family .json file, or a git revision REV or REV:PATH "
                    "(e.g. HEAD~1, main:vectors). Exit 0 when identical, 1 when different, 2 on unreadable input.")
    d.add_argument("old", metavar="OLD", help="the vector set before")
    d.add_argument("new", metavar="NEW", help="the vector set after")
    d.add_argument("--json", action="store_true", help="print the difference as JSON")
    d.add_argument("--brief", action="store_true", help="list ids and classes only, without the field-level changes")
    d.add_argument("--family", action="append", metavar="NAME", help="only this family (repeatable)")
    d.add_argument("--choose", action="append", default=[], metavar="ID=ALT",
                   help="the upgrade report for an implementation declaring this alternative (repeatable): "
                        "the vectors whose expectation changed under your declarations, the new interpretations "
                        "and their defaults, declared alternatives the new set lacks")
    d.add_argument("--expectations", metavar="FILE",
                   help="with the upgrade report: what becomes of each id of this known-failures file "
                        "(kept, merged into another vector, removed)")
    d.set_defaults(func=run)


def run(args):
    old, new = diff.load_set(args.old), diff.load_set(args.new)
    if args.choose or args.expectations:
        from plcvec.errors import PlcvecError
        from plcvec.output import upgrade

        choices = {}
        for item in args.choose:
            interp, sep, alt = item.partition("=")
            if not sep or not interp or not alt:
                raise PlcvecError(f"--choose {item}: expected ID=ALTERNATIVE")
            choices[interp] = alt
        rep = upgrade.report(old, new, choices, args.expectations)
        if args.json:
            sys.stdout.write(json.dumps(rep, indent=1, ensure_ascii=False) + "\n")
        else:
            sys.stdout.write(upgrade.render(rep))
        changed = rep["expectation_changed"] or rep["interpretations"] or rep["unknown_choices"] or (
            rep["known"] and any(e["fate"] != "kept" for e in rep["known"]["entries"]))
        return 1 if changed else 0
    report = diff.compare(old, new, args.family)
    if args.json:
        sys.stdout.write(json.dumps(report, indent=1, ensure_ascii=False) + "\n")
    else:
        sys.stdout.write(diff.render_text(report, brief=args.brief))
    return 0 if report["identical"] else 1
