"""The spec's files as files: where the spec folder is, a file's text, its check against a JSON Schema,
and the line of a value. The family files (loader.py) and the regression files (regressions.py) are both
read through these.
"""
import json

from plcvec_verify.errors import VerifyError
from plcvec_verify.locate import locate

from plcvec.errors import PlcvecError, SpecError


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
