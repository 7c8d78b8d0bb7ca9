"""Load spec/*.yaml: safe YAML with lines, JSON Schema, then the checks a schema cannot express."""
import hashlib
import json
from functools import lru_cache
from pathlib import Path

from plcvec.errors import SpecError
from plcvec.spec.checks import check_family
from plcvec.spec.files import default_spec, line_of, read_text, schema_path, validate
from plcvec.spec.regressions import load_regressions
from plcvec.spec.yaml_lines import load_with_lines
from plcvec_verify.quick_schema import compile_schema

REGRESSIONS_DIR = "regressions"   # spec/regressions/<family>.yaml: see spec/regressions.py


class Family:
    """One instruction family as written in its spec file, plus where each value came from."""

    def __init__(self, path, doc, lines, text):
        self.path, self.doc, self.lines = Path(path), doc, lines
        self.sha256 = hashlib.sha256(text.encode()).hexdigest()
        self.name = doc["family"]
        self.kind = doc["kind"]
        self.clauses = {c["id"]: c for c in doc["clauses"]}
        self.interpretations = {i["id"]: i for i in doc["interpretations"]}
        self.regressions = None   # the family's spec/regressions/<family>.yaml, once loaded (Regressions)

    def line_of(self, *where):
        return line_of(self.lines, where)

    def error(self, where, message):
        return SpecError(self.path, self.line_of(*where), message)

    def default_choices(self):
        return {iid: i["default"] for iid, i in self.interpretations.items()}

    def clause_ref(self, clause_id):
        """The id a vector uses for a clause: family-qualified so ids are unique suite-wide."""
        return f"{self.name}#{clause_id}"


_validator = None


def _schema_validator():
    # jsonschema is imported here, when a spec is first validated, not with this module: the CLI
    # imports the module to word its --help, and most commands (verify, diff) read no spec.
    import jsonschema

    global _validator
    if _validator is None:
        schema = json.loads(schema_path("spec.schema.json").read_text())
        _validator = jsonschema.Draft202012Validator(schema)
    return _validator


@lru_cache(maxsize=None)
def _quick_check():
    """The spec schema's quick check (plcvec_verify/quick_schema.py: jsonschema's answer to "valid?"
    in a fraction of its time, without its import); jsonschema words the errors of a file it refuses."""
    return compile_schema(json.loads(schema_path("spec.schema.json").read_text()))


# The sha256 of each spec text this process has found valid against the schema: the same text parses to
# the same document, so it is valid again. The schema walk is most of a load, and a process may load
# the same files many times (a test session loads copies of spec/ that differ in one file).
_VALID_TEXTS: set = set()


def load_family(path):
    path = Path(path)
    text = read_text(path)
    doc, lines = load_with_lines(path, text)
    if not isinstance(doc, dict):
        raise SpecError(path, 1, "a spec file must be a mapping at the top level")
    digest = hashlib.sha256(text.encode()).hexdigest()
    if digest not in _VALID_TEXTS:
        quick = _quick_check()
        if quick is None or not quick(doc):
            validate(path, doc, lines, _schema_validator())
        _VALID_TEXTS.add(digest)
    family = Family(path, doc, lines, text)
    check_family(family)
    return family


def load_spec(spec_dir=None):
    """All families in a spec folder, sorted by family name, with unique names."""
    spec_dir = Path(spec_dir or default_spec().path)
    files = sorted(spec_dir.glob("*.yaml"))
    if not files:
        raise SpecError(spec_dir, None, "no *.yaml spec files in this folder")
    families = {}
    for f in files:
        fam = load_family(f)
        if fam.name in families:
            raise fam.error(("family",), f"family {fam.name!r} is also defined in {families[fam.name].path.name}")
        families[fam.name] = fam
    load_regressions(spec_dir / REGRESSIONS_DIR, families)
    return [families[k] for k in sorted(families)]


def spec_hash(families):
    h = hashlib.sha256()
    for fam in families:
        h.update(fam.name.encode() + b"\0" + fam.sha256.encode() + b"\n")
        if fam.regressions is not None:
            h.update(f"{REGRESSIONS_DIR}/{fam.name}".encode() + b"\0" + fam.regressions.sha256.encode() + b"\n")
    return h.hexdigest()
