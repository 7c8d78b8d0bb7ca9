"""`plcvec fuzz`: live differential testing of an implementation against the spec engine.

Draws cases with hypothesis from the spec's ranges and past them, runs each through the adapter and
the spec engine, and on the first disagreement shrinks it to a minimal case, printed as a vector file
ready to keep. Deterministic with --seed under one hypothesis version. Exit 0 no disagreement, 1 one found, 2 usage or harness error.
"""
import sys
import time
from functools import partial
from pathlib import Path

from plcvec.errors import PlcvecError

DEFAULT_EXAMPLES = 1000


def register(sub, spec_parent):
    p = sub.add_parser("fuzz", parents=[spec_parent], description=__doc__,
                       help="draw random cases, run them through an implementation, shrink a disagreement")
    how = p.add_mutually_exclusive_group(required=True)
    how.add_argument("--adapter", metavar="CMD", help='an adapter process, e.g. "./emu --plcvec" (verifiers/PROTOCOL.md)')
    how.add_argument("--python", metavar="MODULE:CLASS", help="an adapter object in this process")
    p.add_argument("--examples", type=int, default=DEFAULT_EXAMPLES, metavar="N",
                   help="cases to draw and run (default %(default)s)")
    p.add_argument("--seed", type=int, default=0, help="the same seed, spec and adapter give the same run (default 0)")
    p.add_argument("--family", action="append", default=[], help="only this family (repeatable)")
    p.add_argument("--instruction", action="append", default=[], help='only this instruction, e.g. "LDDT<=" (repeatable)')
    p.add_argument("--choose", action="append", default=[], metavar="ID=ALT",
                   help="the alternative the implementation follows, for adapters that do not declare it")
    p.add_argument("--timeout", type=float, default=10.0,
                   help="seconds per request before the adapter is killed; a hang is a finding, and shrinking it waits this long per case (default %(default)s)")
    p.add_argument("--batch-size", type=int, default=64, help="cases per request while searching (default 64)")
    p.add_argument("--max-restarts", type=int, default=1000,
                   help="adapter restarts after crashes before giving up; a crash is a finding, and shrinking it "
                        "restarts the adapter once per crashing case (default %(default)s)")
    p.add_argument("--out", metavar="FILE", help="also write the minimal case here, as a vector file")
    p.add_argument("--regression", action="store_true",
                   help="append the minimal case to the spec's regressions/<family>.yaml (then `plcvec generate` "
                        "makes it a golden vector); the file is replaced atomically, and only if the spec accepts it")
    p.set_defaults(func=main_args)


def main_args(args):
    from plcvec_verify.command import make_adapter, parse_choices
    from plcvec_verify.errors import VerifyError

    if args.examples < 1 or args.timeout <= 0 or args.batch_size < 1:
        raise PlcvecError("fuzz: --examples and --batch-size must be at least 1, --timeout above 0")
    try:
        import hypothesis  # noqa: F401  (fuzzing draws and shrinks with it; the golden vectors do not need it)
    except ModuleNotFoundError:
        raise PlcvecError("fuzz: needs hypothesis, which plcvec installs only with its fuzz extra: "
                          "pip install 'plcvec[fuzz]'") from None
    try:
        families, asked = _selection(args)
        adapter = make_adapter(args)
        return _fuzz(args, families, asked, adapter, parse_choices(args.choose))
    except VerifyError as exc:
        print(f"plcvec fuzz: {exc}", file=sys.stderr)
        return 2


def _selection(args):
    """The families to announce in the handshake, and the instructions asked for in each."""
    from plcvec.spec.instructions import instruction_list
    from plcvec.spec.loader import load_spec

    families = load_spec(args.spec_dir)
    names = {fam.name: [i["name"] for i in instruction_list(fam)] for fam in families}
    for family in args.family:
        if family not in names:
            raise PlcvecError(f"fuzz: --family {family}: no such family in {args.spec_dir} (known: {', '.join(names)})")
    every = {n for ns in names.values() for n in ns}
    for instruction in args.instruction:
        if instruction not in every:
            raise PlcvecError(f"fuzz: --instruction {instruction}: no family has it")
    asked = {fam: [n for n in ns if not args.instruction or n in args.instruction]
             for fam, ns in names.items() if not args.family or fam in args.family}
    return [fam for fam in families if asked.get(fam.name)], asked


def _fuzz(args, families, asked, adapter, choose):
    from plcvec.fuzz.draw import Space
    from plcvec.fuzz.run import Target, search, spec_suite
    from plcvec.fuzz.shrink import NotReproduced, shrink
    from plcvec.fuzz import report
    from plcvec.output.atomic import write_atomic
    from plcvec.spec.loader import REGRESSIONS_DIR
    from plcvec.fuzz.record import append_case
    from plcvec.spec.regressions import case_of
    from plcvec_verify.expect import expected_of

    try:
        target = Target(adapter, spec_suite(families, args.spec_dir), families, choose)
    except BaseException:
        adapter.close()
        raise
    try:
        instructions = {fam: [n for n in ns if n in target.supported] for fam, ns in asked.items()}
        space = Space(families, instructions)
        if not space.drawers:
            raise PlcvecError(f"fuzz: the adapter supports none of the instructions asked for "
                              f"({', '.join(n for ns in asked.values() for n in ns)})")
        started = time.perf_counter()
        found = search(space, target, args.examples, args.seed, args.batch_size)
        searched = time.perf_counter() - started
        if found.choices is None:
            sys.stdout.write(report.no_disagreement(target.name, args.seed, found.examples, target.skipped))
            _timing(found.examples, searched)
            return 0
        started = time.perf_counter()
        try:
            case, runs = shrink(space.strategy, found.choices, lambda c: target.differs(space.vector(c)), args.seed)
        except NotReproduced:
            sys.stdout.write(report.not_reproduced(target.name, args.seed, found.examples, args.examples))
            _timing(found.examples, searched)
            return 1
        vector = space.vector(case)
        # Run once more under the vector's own id: the printed differences are those of this vector.
        verdict = target.judge([vector], ids=[vector["id"]])[0]
        shrunk = time.perf_counter() - started
        if not verdict.differs:
            sys.stdout.write(report.not_reproduced(target.name, args.seed, found.examples, args.examples))
            return 1
        fam = space.families[vector["family"]]
        judged_by = expected_of(vector, target.choices, target.defaults).choices
        if args.out:
            write_atomic(args.out, report.vector_file(fam, vector, target.name, args.seed))
        note = report.regression_note(target.name, args.seed, verdict)
        regression = Path(args.spec_dir) / REGRESSIONS_DIR / f"{fam.name}.yaml"
        printed = partial(report.disagreement, fam, vector, verdict, adapter=target.name, seed=args.seed,
                          found=found.examples, examples=args.examples, runs=runs, judged_by=judged_by,
                          out=args.out, note=note, regression=regression)
        if args.regression:
            from plcvec_verify.locate import inside_installation

            if inside_installation(regression):
                sys.stdout.write(printed(appended=False))
                raise PlcvecError(f"fuzz --regression: {regression} belongs to the installed plcvec, which is never "
                                  "written; run in a checkout or name a spec folder of your own with --spec-dir")
            try:
                append_case(regression, fam, note, case_of(vector))
            except (PlcvecError, OSError):   # the case is still printed, to append by hand
                sys.stdout.write(printed(appended=False))
                raise
        sys.stdout.write(printed(appended=args.regression))
        _timing(found.examples, searched, runs, shrunk)
        return 1
    finally:
        target.close()


def _timing(examples, seconds, runs=None, shrink_seconds=None):
    line = f"plcvec fuzz: {examples} examples in {seconds:.2f} s ({examples / max(seconds, 1e-9):,.0f} examples/s)"
    if runs is not None:
        line += f"; shrinking: {runs} runs in {shrink_seconds:.2f} s"
    print(line, file=sys.stderr)
