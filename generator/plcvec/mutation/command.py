"""`plcvec mutation`: mutate the engine with cosmic-ray and check that every mutant which changes the
committed vectors touches a decision of the inventory (review/decisions.yaml). Exit 0 none missing,
1 a missing decision, 2 usage or harness error."""
import sys
from pathlib import Path

from plcvec.errors import PlcvecError
from plcvec.output.workers import add_jobs_option


def register(sub, spec_parent):
    p = sub.add_parser("mutation", parents=[spec_parent], description=__doc__,
                       help="mutate the engine: each mutant that changes the vectors must touch a listed decision")
    p.add_argument("--sample", type=int, metavar="N", help="judge N mutants drawn with --seed, not all")
    p.add_argument("--seed", type=int, default=0, help="the seed of --sample: the same seed, the same mutants (default 0)")
    p.add_argument("--file", action="append", default=[], metavar="NAME",
                   help="only the mutants of this engine file, e.g. hour_meter.py (repeatable)")
    p.add_argument("--line", action="append", default=[], metavar="FILE:LINE",
                   help="only the mutants on this line of an engine file, e.g. hour_meter.py:57 (repeatable): to "
                        "judge again a line a report named")
    p.add_argument("--timeout", type=float, metavar="S",
                   help="CPU seconds a mutant may use before it is stopped and counted as a timeout (default: five "
                        "times the unmutated engine's, at least 10)")
    p.add_argument("--vectors", metavar="DIR", help="the committed vectors to judge by (default: the checkout's vectors/)")
    p.add_argument("--json", metavar="FILE", help="also write every mutant's record here")
    add_jobs_option(p)
    p.set_defaults(func=run)


def run(args):
    from plcvec.mutation.mutants import engine_sources
    from plcvec.mutation.report import as_json, counts, text
    from plcvec.mutation.run import committed_vectors, enumerate_mutants, run_mutants, select
    from plcvec.mutation.touch import MISSING
    from plcvec.output.atomic import write_atomic
    from plcvec.review.decisions import ENGINE, load_inventory
    from plcvec_verify.locate import default_vectors

    if args.sample is not None and args.sample < 1:
        raise PlcvecError("mutation: --sample takes a number of mutants, 1 or more")
    if args.timeout is not None and args.timeout <= 0:
        raise PlcvecError("mutation: --timeout takes a number of seconds above 0")
    sources = engine_sources(ENGINE)
    lines = [_file_line(text) for text in args.line]
    everything = enumerate_mutants(sources, args.file + [file for file, _ in lines])
    if lines:
        everything = [m for m in everything if any(m.file == f and m.lines[0] <= n <= m.lines[1] for f, n in lines)]
        if not everything:
            raise PlcvecError(f"mutation: no mutant on {', '.join(args.line)}")
    selected = select(everything, args.sample, args.seed)
    vectors = Path(args.vectors) if args.vectors else default_vectors().path
    committed = committed_vectors(vectors, args.spec_dir, ENGINE, sources)
    result = run_mutants(selected, committed, load_inventory(), args.jobs, args.timeout,
                         progress=lambda done, of: print(f"plcvec mutation: {done} of {of} mutants judged",
                                                         file=sys.stderr, flush=True))
    result.total, result.files = len(everything), tuple(sorted(set(m.file for m in everything)))
    result.sample = (args.sample, args.seed) if args.sample is not None and args.sample < len(everything) else None
    if args.json:
        write_atomic(Path(args.json), as_json(result))
    sys.stdout.write(text(result, sources))
    return 1 if counts(result)[MISSING] else 0


def _file_line(text):
    """--line FILE:LINE as (file, line)."""
    file, _, line = text.rpartition(":")
    if not file or not line.isdigit():
        raise PlcvecError(f"mutation: --line takes FILE:LINE (an engine file and a line number), got {text!r}")
    return file, int(line)
