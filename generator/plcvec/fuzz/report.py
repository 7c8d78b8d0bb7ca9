"""What `plcvec fuzz` prints: the minimal case as a vector file, what differs, and the clauses behind it.

Everything here is a function of the seed, the spec and the adapter's answers (no times, no counters
of requests), so two runs with the same seed print the same bytes; the timing goes to stderr.
"""
from plcvec.output.canonical import dumps_vector_file
from plcvec.output.golden import family_header
from plcvec.spec.regressions import case_key, case_of, stanza


def vector_file(fam, vector, adapter, seed):
    """The one vector as a family file in the golden files' format and schema: `plcvec verify
    --vectors FILE` runs it as it is."""
    header = family_header(fam, [vector])
    header["generated"] = (f"Found by `plcvec fuzz --seed {seed}`: the minimal case on which {_name(adapter)} "
                           "disagrees with the spec; expectations from the spec engine. Contract: verifiers/CONTRACT.md.")
    return dumps_vector_file(header, [vector])


def _name(adapter):
    return " ".join(str(adapter.get(k)) for k in ("name", "version") if adapter.get(k))


def regression_note(adapter, seed, verdict):
    """A first note for the regression case: how it was found and what differed; say which bug it was."""
    return f"found by plcvec fuzz --seed {seed} against {_name(adapter)}: {verdict.lines[0] if verdict.lines else 'disagreement'}"


def disagreement(fam, vector, verdict, *, adapter, seed, found, examples, runs, judged_by, out, note, regression,
                 appended):
    lines = [f"plcvec fuzz: {_name(adapter)} disagrees with the spec on example {found} of {examples} (seed {seed}).",
             f"Shrunk by hypothesis ({runs} runs) to {vector['id']}:", "",
             vector_file(fam, vector, adapter, seed).rstrip("\n"), ""]
    under = "".join(f" {i}={alt}" for i, alt in sorted(judged_by.items()))
    lines.append("What differs" + (f" (judged under{under})" if under else "") + ":")
    lines += [f"  {line}" for line in verdict.lines]
    lines.append("Spec clauses it exercises:")
    for ref in vector["clauses"]:
        clause = fam.clauses[ref.split("#", 1)[1]]
        lines.append(f"  {ref}: {clause['says']}")
    if out:
        lines.append(f"Written to {out}; `plcvec verify --vectors {out}` runs it again.")
    else:
        lines.append("--out FILE writes it; `plcvec verify --vectors FILE` then runs it as a regression test.")
    case = case_of(vector)
    becomes = f"{fam.name}/{vector['instruction']}/{case_key(case)}"
    if appended:
        lines.append(f"Appended to {regression} as this regression case; `plcvec generate` makes it the golden vector {becomes}:")
    else:
        lines.append(f"To keep it as the golden vector {becomes}, append this regression case to {regression} "
                     "(or run again with --regression), say in its note which bug it caught, and run `plcvec generate`:")
    lines.append(stanza(note, case).rstrip("\n"))
    return "\n".join(lines) + "\n"


def no_disagreement(adapter, seed, examples, skipped):
    skips = f", {skipped} skipped by the adapter" if skipped else ""
    return f"plcvec fuzz: no disagreement between {_name(adapter)} and the spec in {examples} examples (seed {seed}{skips}).\n"


def not_reproduced(adapter, seed, found, examples):
    return (f"plcvec fuzz: {_name(adapter)} disagreed with the spec on example {found} of {examples} (seed {seed}), "
            "but not when the same case was run again: its answers depend on something besides the vector "
            "(state kept between vectors, the time, randomness).\n")
