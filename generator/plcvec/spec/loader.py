"""Load spec/*.yaml: safe YAML with lines, JSON Schema, then the checks a schema cannot express."""
import hashlib
import json
from pathlib import Path

from plcvec_verify.errors import VerifyError
from plcvec_verify.locate import locate

from plcvec.errors import PlcvecError, SpecError
from plcvec.spec.checks import check_family
from plcvec.spec.yaml_lines import load_with_lines

REGRESSIONS_DIR = "regressions"   # spec/regressions/<family>.yaml: see spec/regressions.py


def default_spec():
    """The spec folder used when none is named: the checkout's spec/, else the copy installed with
    plcvec (plcvec_verify/locate.py says how it is chosen), as a Location (path and kind)."""
    try:
        return locate("plcvec", "spec", "*.yaml")
    except VerifyError as exc:
        raise PlcvecError(f"{exc} (--spec-dir DIR)") from None


def default_spec_help():
    """For --help: the folder used when --spec-dir is not given, and whose it is."""
    try:
        return default_spec().describe()
    except PlcvecError as exc:
        return f"none: {exc}"


def schema_path(name):
    """A JSON Schema of the spec's files (spec/schema/NAME): the default spec's, whichever folder is loaded."""
    return default_spec().path / "schema" / name


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


def _describe(error):
    """A plain sentence for a schema error, and the path of the value it is about."""
    where = tuple(error.absolute_path)
    if error.validator == "additionalProperties" and isinstance(error.instance, dict):
        allowed = set(error.schema.get("properties", {}))
        extra = sorted(k for k in error.instance if k not in allowed)
        if extra:
            return where + (extra[0],), f"unknown key {extra[0]!r}" + (
                f" (allowed here: {', '.join(sorted(allowed))})" if allowed else "")
    if error.validator is False or error.validator_value is False:
        return where, f"key {where[-1]!r} is not allowed for this kind of instruction family"
    if error.validator == "required":
        return where, (f"{'.'.join(map(str, where))}: " if where else "") + \
            error.message.replace("is a required property", "is required but missing")
    if error.validator == "type":
        return where, f"{'.'.join(map(str, where)) or 'value'}: expected {error.validator_value}, got {json.dumps(error.instance, default=str)[:60]}"
    return where, f"{'.'.join(map(str, where)) or 'document'}: {error.message[:300]}"


def _describe_forbidden(error, doc):
    """A `false` subschema under `properties`: jsonschema leaves the key out of the error's path, so find it."""
    where = tuple(error.absolute_path)
    container = doc
    for step in where:
        container = container[step]
    key = None
    if isinstance(container, dict):
        same = [k for k, v in container.items() if v is error.instance] or \
               [k for k, v in container.items() if v == error.instance]
        key = same[0] if same else None
    kind = doc.get("kind") if isinstance(doc, dict) else None
    if key is None:
        return where, f"{'.'.join(map(str, where)) or 'document'}: a value is not allowed here for kind {kind!r}"
    return where + (key,), f"key {key!r} is not allowed for this kind of instruction family (kind: {kind})"


def read_text(path):
    """The text of a spec file, or a SpecError naming it (unreadable; not UTF-8, with line and column)."""
    try:
        raw = path.read_bytes()
    except OSError as exc:
        raise SpecError(path, None, f"cannot read: {exc.strerror or exc}") from None
    try:
        return raw.decode("utf-8")
    except UnicodeDecodeError as exc:
        line = raw.count(b"\n", 0, exc.start) + 1
        column = exc.start - (raw.rfind(b"\n", 0, exc.start) + 1) + 1
        raise SpecError(path, line, f"not UTF-8 text: byte {raw[exc.start]:#04x} at column {column} "
                                    f"cannot be decoded ({exc.reason}); save the file as UTF-8") from None


def validate(path, doc, lines, validator):
    """Raise a SpecError at the line of the first (most telling) schema error of `doc`, if any."""
    errors = sorted(validator.iter_errors(doc), key=lambda e: (list(map(str, e.absolute_path)), str(e.validator)))
    if not errors:
        return
    # A key the family's kind forbids (a `false` subschema) is the cause of whatever else is wrong
    # with its value, so it is reported first.
    forbidden = [e for e in errors if e.schema is False]
    if forbidden:
        where, message = _describe_forbidden(forbidden[0], doc)
    else:
        import jsonschema

        best = jsonschema.exceptions.best_match(errors)
        # best_match may name an `allOf`/`if` wrapper: prefer the deepest concrete error below it.
        while best.context:
            best = jsonschema.exceptions.best_match(best.context)
        where, message = _describe(best)
    raise SpecError(path, line_of(lines, where), message)


def line_of(lines, where):
    """The line of the value at path `where`, or of the nearest enclosing value that has one."""
    where = tuple(where)
    while where and where not in lines:
        where = where[:-1]
    return lines.get(where)


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
    from plcvec.spec.regressions import load_regressions  # it uses this module's readers

    load_regressions(spec_dir / REGRESSIONS_DIR, families)
    return [families[k] for k in sorted(families)]


def spec_hash(families):
    h = hashlib.sha256()
    for fam in families:
        h.update(fam.name.encode() + b"\0" + fam.sha256.encode() + b"\n")
        if fam.regressions is not None:
            h.update(f"{REGRESSIONS_DIR}/{fam.name}".encode() + b"\0" + fam.regressions.sha256.encode() + b"\n")
    return h.hexdigest()
