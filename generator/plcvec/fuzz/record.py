"""A shrunk case recorded as a regression case (plcvec fuzz --regression): appended to its family's file
in the spec folder. The spec (plcvec.spec.regressions) reads these files; only fuzz writes them.
"""
from plcvec.output.atomic import write_atomic
from plcvec.spec.files import read_text
from plcvec.spec.regressions import parse_regressions, stanza

NEW_FILE = ("# Regression cases of {family}: the inputs of vectors that once exposed a bug, each with a note saying\n"
            "# which. No expectations: `plcvec generate` computes them from the spec. Schema: spec/schema/regressions.schema.json\n")


def append_case(path, fam, note, case):
    """Append a case to the regression file `path` of `fam` (created if missing), all or nothing: the new
    text must load as the spec would load it (no duplicate, no mistake), and replaces the file atomically."""
    old = read_text(path) if path.exists() else NEW_FILE.format(family=fam.name)
    new = old + ("\n" if old and not old.endswith("\n") else "") + stanza(note, case)
    parse_regressions(path, new, fam)
    write_atomic(path, new)
