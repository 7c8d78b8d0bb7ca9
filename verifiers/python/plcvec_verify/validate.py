"""Checking a vector file against its JSON Schema when it is loaded.

A damaged or hand-edited file must be refused with the vector and the field that is wrong (`a
word of 70000 at initial/devices/D100`), not trusted until something downstream trips over it
with a misleading message. The schema is `schema/vector-file.schema.json` beside the vector
files (a vector folder's own, or the folder a lone family file sits in); a file with none beside
it is checked against the default vector set's schema.

Validating the golden set with jsonschema takes some seconds, many times what loading it takes. A
quick check made from the schema itself (quick_schema.py) says "valid" for a sound file in a
fraction of that, and jsonschema judges, and words, every file it does not show valid. And a file
found valid is remembered by the sha256 of its bytes and of the schema: in this process,
and across processes as an empty marker file in a cache folder ($PLCVEC_CACHE_DIR, else
$XDG_CACHE_HOME/plcvec or ~/.cache/plcvec). A changed byte is a new hash and is validated again;
a file that fails is never remembered. Without a writable cache folder every run validates.
"""
from __future__ import annotations

import hashlib
import json
import os
from functools import lru_cache
from pathlib import Path

from .errors import VerifyError
from .quick_schema import compile_schema

SCHEMA_FILE = "vector-file.schema.json"
SHOW_ERRORS = 5          # schema errors named per file; the rest are counted
_VALID: set[str] = set()  # cache keys validated in this process


def schema_for(path: Path) -> Path:
    """The vector-file schema that governs `path` (a vector folder or a family file)."""
    from .locate import default_vectors

    folder = path if path.is_dir() else path.parent
    candidates = [folder / "schema" / SCHEMA_FILE]
    try:
        candidates.append(default_vectors().path / "schema" / SCHEMA_FILE)
    except VerifyError:
        pass
    for candidate in candidates:
        if candidate.is_file():
            return candidate
    raise VerifyError(f"{path}: no {SCHEMA_FILE} to check it against (looked for "
                      + ", ".join(str(c) for c in candidates) + ")")


@lru_cache(maxsize=None)
def _validator(schema_text: str):
    """One validator per schema, its class chosen by `$schema` and the schema itself checked once."""
    import jsonschema

    schema = json.loads(schema_text)
    cls = jsonschema.validators.validator_for(schema)
    cls.check_schema(schema)
    return cls(schema)


def validate_file(file: Path, raw: bytes, data: dict, schema_path: Path) -> None:
    """Raise VerifyError naming the vector and JSON path of each way `data` breaks the schema."""
    try:
        schema_text = schema_path.read_text(encoding="utf-8")
    except OSError as exc:
        raise VerifyError(f"{schema_path}: cannot read the vector-file schema: {exc.strerror or exc}")
    # "-k": checked for repeated keys too (a file remembered before that check is checked again).
    key = (hashlib.sha256(raw).hexdigest() + "-"
           + hashlib.sha256(schema_text.encode("utf-8")).hexdigest()[:16] + "-k")
    if key in _VALID or _cached(key):
        _VALID.add(key)
        return
    _refuse_repeated_keys(file, raw, data)
    _against_schema(file, data, schema_path, schema_text)
    for v in data.get("vectors", ()):
        problem = vector_problem(v)
        if problem:
            raise VerifyError(f"{file}: vector {v.get('id')}: {problem}")
    _VALID.add(key)
    _remember(key)


def _against_schema(file: Path, data: dict, schema_path: Path, schema_text: str) -> None:
    """`data` checked against the schema: the quick check's yes, else jsonschema's judgement."""
    quick = _quick_check(schema_text)
    if quick is None or not quick(data):
        # Not shown valid by the quick check: jsonschema judges, and words what is wrong.
        _schema_errors(file, data, schema_path, schema_text)


@lru_cache(maxsize=None)
def _quick_check(schema_text: str):
    """The schema's quick check (quick_schema.py), or None where it has none: also for a schema that
    jsonschema finds unusable, which _schema_errors then refuses with jsonschema's reason."""
    try:
        _validator(schema_text)
    except Exception:
        return None
    return compile_schema(json.loads(schema_text))


def _schema_errors(file: Path, data: dict, schema_path: Path, schema_text: str) -> None:
    """jsonschema's judgement of `data`: a VerifyError naming each way it breaks the schema."""
    try:
        validator = _validator(schema_text)
    except Exception as exc:   # a broken schema file is the set's fault, not the vector's
        raise VerifyError(f"{schema_path}: not a usable JSON Schema: {exc}")
    errors = sorted(validator.iter_errors(data), key=lambda e: [str(p) for p in e.absolute_path])
    if errors:
        lines = [_describe(e, data) for e in errors[:SHOW_ERRORS]]
        more = f"\n  ... and {len(errors) - SHOW_ERRORS} more" if len(errors) > SHOW_ERRORS else ""
        raise VerifyError(f"{file}: does not match {schema_path.name}:\n  " + "\n  ".join(lines) + more)


def _kind(value) -> str:
    return "a bit (true/false)" if type(value) is bool else "a word"


def vector_problem(v: dict) -> str:
    """What the schema cannot say of one vector: each device keeps one JSON type (a bit is true/false
    everywhere, a word an integer everywhere) across initial, set, expect and final, alternatives
    included. A bit holding 2 in `initial` would otherwise be blamed on the implementation. And an
    entry's unjudged devices are the vector's own, under one of the entry's choices, and the entry
    expects nothing of them."""
    problem = _unjudged_problem(v)
    if problem:
        return problem
    seen: dict[str, tuple] = {}      # device -> (is a bit, the path where it was first met)
    places = [("initial/devices", v["initial"]["devices"]), ("final/devices", v["final"]["devices"])]
    for i, step in enumerate(v["steps"]):
        places.append((f"steps/{i}/set", step.get("set") or {}))
        places.append((f"steps/{i}/expect/devices", step["expect"].get("devices") or {}))
    for a, alt in enumerate(v.get("alternatives", ())):
        for i, expect in enumerate(alt.get("expect", ())):
            places.append((f"alternatives/{a}/expect/{i}/devices", expect.get("devices") or {}))
        places.append((f"alternatives/{a}/final/devices", alt["final"]["devices"]))
    for where, devices in places:
        for device, value in devices.items():
            bit = type(value) is bool
            first = seen.setdefault(device, (bit, where, value))
            if first[0] is not bit:
                return (f"at {where}/{device}: {json.dumps(value)} is {_kind(value)}, but at {first[1]}/{device} "
                        f"the same device holds {json.dumps(first[2])}, {_kind(first[2])}")
    return ""


def _refuse_repeated_keys(file: Path, raw: bytes, data: dict) -> None:
    """A key given twice in one object, named by file, line and vector (CONTRACT.md, "Loading")."""
    from .files import has_repeated_key, repeated_key_message

    text = raw.decode("utf-8")
    if file.suffix == ".jsonl":
        for number, line in enumerate(text.split("\n"), 1):
            if line and has_repeated_key(line):
                vector = data["vectors"][number - 2].get("id") if number > 1 else None
                raise VerifyError(repeated_key_message(str(file), line, number - 1,
                                                       lambda path: vector if isinstance(vector, str) else None))
    elif has_repeated_key(text):
        def vector_of(path):
            if len(path) >= 2 and path[0] == "vectors" and isinstance(path[1], int):
                v = data["vectors"][path[1]]
                return v.get("id") if isinstance(v, dict) else None
            return None
        raise VerifyError(repeated_key_message(str(file), text, 0, vector_of))


def _unjudged_problem(v: dict) -> str:
    listed = v["initial"]["devices"]
    for a, alt in enumerate(v.get("alternatives", ())):
        for interp, devices in alt.get("unjudged", {}).items():
            where = f"at alternatives/{a}/unjudged/{interp}"
            if interp not in alt["choices"]:
                return f"{where}: {interp} is not one of the entry's choices"
            if list(devices) != sorted(devices):
                return f"{where}: the devices are not sorted"
            for device in devices:
                if device not in listed:
                    return f"{where}: {device} is not in initial/devices"
                expected = [f"final/devices/{device}"] if device in alt["final"]["devices"] else []
                expected += [f"expect/{i}/devices/{device}" for i, e in enumerate(alt["expect"]) if device in e["devices"]]
                if expected:
                    return (f"at alternatives/{a}/{expected[0]}: {device} is unjudged under {interp}={alt['choices'][interp]}, "
                            "so the entry cannot expect a value of it")
    return ""


def _describe(error, data) -> str:
    """`vector <id>: at initial/devices/D100: 70000 is greater than the maximum of 65535`."""
    # Under oneOf/anyOf, say what the branch that came closest found ("greater than the maximum":
    # the value had the branch's type), not only that no branch matched.
    detail = min(error.context, key=lambda e: (e.validator == "type", len(e.absolute_path))) \
        if error.context else error
    path = list(error.absolute_path)
    if len(path) >= 2 and path[0] == "vectors" and isinstance(path[1], int):
        v = data["vectors"][path[1]]
        name = v.get("id") if isinstance(v, dict) and isinstance(v.get("id"), str) else f"#{path[1]}"
        where, what = "/".join(str(p) for p in path[2:]) or "(the vector)", f"vector {name}"
    else:
        where, what = "/".join(str(p) for p in path) or "(the file)", "header"
    return f"{what}: at {where}: {detail.message}"


def _cache_dir() -> Path | None:
    if os.environ.get("PLCVEC_CACHE_DIR"):
        root = Path(os.environ["PLCVEC_CACHE_DIR"])
    elif os.environ.get("XDG_CACHE_HOME"):
        root = Path(os.environ["XDG_CACHE_HOME"]) / "plcvec"
    else:
        try:
            root = Path.home() / ".cache" / "plcvec"
        except RuntimeError:    # no home folder
            return None
    return root / "valid-vector-files"


def _cached(key: str) -> bool:
    folder = _cache_dir()
    return folder is not None and (folder / key).is_file()


def _remember(key: str) -> None:
    folder = _cache_dir()
    if folder is None:
        return
    try:
        folder.mkdir(parents=True, exist_ok=True)
        (folder / key).touch()
    except OSError:   # a read-only home: validate every time rather than fail
        pass
