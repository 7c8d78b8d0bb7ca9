"""`plcvec export --lang L`: write (or `--check`) a native verifier's generated files."""
from __future__ import annotations

from pathlib import Path

from plcvec.errors import PlcvecError
from plcvec.export import reference
from plcvec.export.model import load_model
from plcvec.export.targets import languages, render
from plcvec.export.validate import check_vectors
from plcvec.output.atomic import write_atomic
from plcvec.output.drift import report_drift



def _checkout():
    """The checkout in use (plcvec_verify/locate.py): exports go into its verifiers/, never into an installation."""
    from plcvec_verify.locate import checkout

    return checkout()


def register(sub, spec_parent):
    # Rendered from the vector files; the spec they were generated from gives what they do not carry
    # (an instruction's form, condition and execution; the reference tables).
    e = sub.add_parser(
        "export", parents=[spec_parent], help="render the vectors and the spec's names into a native verifier (verifiers/<lang>/)",
        description="Render each language's jinja2 templates (generator/plcvec/export/templates/<lang>/) with the "
                    "vector files, and write the compact JSON Lines copy of the vectors that travels with the "
                    f"language's package. Languages: {', '.join(languages()) or '(none yet)'}. "
                    "Exit 0 written or up to date, 1 --check found a difference, 2 bad input.")
    which = e.add_mutually_exclusive_group(required=True)
    which.add_argument("--lang", action="append", metavar="L", help="a language (repeatable)")
    which.add_argument("--all", action="store_true", help="every language that has templates")
    root = _checkout()
    e.add_argument("--vectors", default=str(root / "vectors") if root else None,
                   help="the vector folder to export (default: %(default)s)")
    e.add_argument("--root", default=str(root) if root else None,
                   help="the repository the outputs go into (default: %(default)s)")
    e.add_argument("--check", action="store_true", help="write nothing; exit 1 and name each file that differs")
    e.set_defaults(func=run)


def run(args):
    known = languages()
    chosen = known if args.all else args.lang
    if not chosen:
        print("plcvec export: no language has templates yet (generator/plcvec/export/templates/<lang>/export.yaml)")
        return 0
    unknown = sorted(set(chosen) - set(known))
    if unknown:
        raise PlcvecError(f"--lang {', '.join(unknown)}: no such language (known: {', '.join(known) or 'none'})")
    if not args.root or not args.vectors:
        raise PlcvecError("export: not in a plcvec checkout; name the repository with --root and the vectors with --vectors")
    # Refused as `plcvec verify` refuses it, before anything is rendered or written.
    check_vectors(args.vectors)
    model = load_model(args.vectors, args.spec_dir)
    root = Path(args.root)
    differ, written, total = [], 0, 0
    for lang in chosen:
        target = render(lang, model)
        total += len(target.files)
        for rel, text in sorted(target.files.items()):
            path = root / rel
            current = path.read_text(encoding="utf-8") if path.is_file() else None
            if current == text:
                continue
            if args.check:
                differ.append(f"{path}: {'missing' if current is None else 'differs from what the vectors export'}")
            else:
                write_atomic(path, text)
                written += 1
        for stale in _stale(root, target):
            if args.check:
                differ.append(f"{stale}: not produced by the export (stale file?)")
            else:
                stale.unlink()
                print(f"plcvec export: removed stale {stale}")
    # The reference tables between the markers of the contract and of each language's README.
    tables = reference.render_tables(model)
    for rel in reference.targets(chosen):
        path = root / rel
        total += 1
        try:
            current = path.read_text(encoding="utf-8")
        except OSError as exc:
            raise PlcvecError(f"{path}: cannot read ({exc.strerror or exc}); it carries the reference tables") from None
        try:
            text = reference.replace_section(path, current, tables)
        except PlcvecError as exc:
            if not args.check:
                raise
            differ.append(str(exc))
            continue
        if text != current:
            if args.check:
                differ.append(f"{path}: the reference tables differ from what the spec gives")
            else:
                write_atomic(path, text)
                written += 1
    if args.check:
        if report_drift("plcvec export --check", "the exported files are not what the vectors give", differ,
                        "plcvec export --all"):
            return 1
        print(f"plcvec export --check: {total} files of {len(chosen)} language(s) match the vectors")
        return 0
    print(f"plcvec export: {written} of {total} files written for {', '.join(chosen)} "
          f"({total - written} already up to date)")
    return 0


def _stale(root: Path, target):
    produced = {root / rel for rel in target.files}
    for rel in target.generated_dirs:
        folder = root / rel
        if folder.is_dir():
            for path in sorted(folder.rglob("*")):
                if path.is_file() and path not in produced:
                    yield path
