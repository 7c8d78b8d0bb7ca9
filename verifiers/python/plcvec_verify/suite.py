"""Loading a vector set (VOCABULARY.md: `suite`).

A vector set is a folder with `manifest.json` and the family files it names (what `plcvec
generate` writes), or a single family file. Nothing here depends on the generator: an
implementer needs only the published files. Which of its vectors a run takes is selection.py's.
"""
from __future__ import annotations

import hashlib
import json
import os
from dataclasses import dataclass, field
from pathlib import Path

from .collector import collector_paused
from .errors import VerifyError
from .expect import Expectations
from .files import has_repeated_key, not_regular, read_bytes, repeated_key_message
from .validate import schema_for, validate_file
from .vector import shape_problem
# Named here too, where 0.1.0's users import them from (the selection was this module's then).
from .selection import Selection, parse_shard, shard_of  # noqa: F401
from .vector import touched_interpretations  # noqa: F401

# A vector folder's index: the JSON form's manifest.json (plcvec generate), or the packaged
# JSON-lines form's index.json (plcvec export, a release bundle's jsonl/).
INDEXES = ("manifest.json", "index.json")

# The major schema version this verifier understands (CONTRACT.md, "Versioning"): a 2.x file may
# mean something else by the same fields, so it is refused rather than misread.
SCHEMA_MAJOR = 1


@dataclass
class Suite:
    """The vectors of one set, with each family file's header."""

    vectors: list[dict]
    headers: dict[str, dict]          # family -> file header (everything but "vectors")
    source: str
    suite_version: str = ""
    schema_version: str = ""
    spec_sha256: str = ""
    by_id: dict[str, dict] = field(default_factory=dict)
    # Each vector's request and expectation, made once for all the runs over this set.
    expectations: Expectations = field(default_factory=Expectations, repr=False, compare=False)
    # Ids the generator merged into another vector (the index's `merged`), each with the id it became
    # (last, so that a Suite built by position as in 0.1.0 still is).
    merged: dict[str, str] = field(default_factory=dict)

    def __post_init__(self):
        self.by_id = {v["id"]: v for v in self.vectors}

    @classmethod
    def load(cls, path) -> "Suite":
        """A vector folder (`manifest.json` and the JSON family files it names, as `plcvec generate`
        writes them, or `index.json` and the JSON-lines family files of the packaged form that
        `plcvec export` and a release bundle's `jsonl/` hold), or one family file of either form."""
        path = Path(path)
        if path.is_dir():
            # Whatever is there under an index's name is read as the index (a named pipe is refused by
            # name when read, not taken for "no index").
            index_path = next((path / name for name in INDEXES if os.path.lexists(path / name)), None)
            if index_path is None:
                raise VerifyError(f"{path}: no manifest.json (a vector folder) or index.json (the packaged "
                                  "JSON-lines form); is this a plcvec vector folder?")
            index = _read_json(index_path)
            try:
                entries = [(path / entry["file"], entry.get("sha256"), entry.get("count"))
                           for entry in index["families"].values()]
            except (KeyError, TypeError, AttributeError):
                raise VerifyError(f"{index_path}: no `families` with a `file` each; is this a plcvec vector folder?")
            suite_version = str(index.get("suite_version") or index.get("generator_version") or "")
            merged = _merged_ids(index.get("merged"))
            manifest_hash = index.get("spec_sha256", "")
        elif path.exists() or not_regular(path):
            index_path, entries, suite_version, manifest_hash = None, [(path, None, None)], "", ""
            merged = {}
        else:
            raise VerifyError(f"{path}: no such vector folder or file")
        schema = schema_for(path)
        headers, vectors, spec_hashes, schema_versions = {}, [], set(), set()
        with collector_paused():   # every vector is kept: the collector would only walk them again
            for file, sha256, count in entries:
                raw = _read_bytes(file)
                data = _parse_jsonl(file, raw) if file.suffix == ".jsonl" else _parse_json(file, raw)
                if sha256 is not None and hashlib.sha256(raw).hexdigest() != sha256:
                    raise VerifyError(f"{file}: its sha256 is not the one {index_path.name} records "
                                      f"({sha256[:12]}…): the file was changed or cut after it was written")
                if not isinstance(data, dict) or not isinstance(data.get("vectors"), list) or "family" not in data:
                    raise VerifyError(f"{file}: not a plcvec vector file (no `family` and `vectors`)")
                if isinstance(count, int) and count != len(data["vectors"]):
                    raise VerifyError(f"{file}: {len(data['vectors'])} vectors, but {index_path.name} records {count}: "
                                      "the file was cut or changed after it was written")
                version = str(data.get("schema_version", ""))
                major = version.split(".")[0]
                if major != str(SCHEMA_MAJOR):
                    raise VerifyError(f"{file}: schema_version {version or '(none)'} is not {SCHEMA_MAJOR}.x; "
                                      f"this verifier reads {SCHEMA_MAJOR}.x files only (see CONTRACT.md, Versioning)")
                schema_versions.add(version)
                spec_hashes.add(data.get("spec_sha256", ""))
                headers[data["family"]] = {k: v for k, v in data.items() if k != "vectors"}
                for index_no, v in enumerate(data["vectors"]):
                    problem = shape_problem(v, data["family"])
                    if problem:
                        named = isinstance(v, dict) and isinstance(v.get("id"), str)
                        name = v["id"] if named else f"#{index_no}"
                        raise VerifyError(f"{file}: vector {name}: {problem} (is the file a plcvec vector file, unedited?)")
                # Then every value against the schema: a word of 70000 is named where it is, not
                # discovered later as an expectation that "does not add up".
                validate_file(file, raw, data, schema)
                vectors.extend(data["vectors"])
        seen = set()
        for v in vectors:
            if v["id"] in seen:
                raise VerifyError(f"{path}: vector id {v['id']} appears twice")
            seen.add(v["id"])
        return cls(vectors=vectors, headers=headers, source=str(path), suite_version=suite_version, merged=merged,
                   schema_version=", ".join(sorted(schema_versions)),
                   spec_sha256=manifest_hash or ", ".join(sorted(h for h in spec_hashes if h)))

    def interpretations(self, families=None) -> dict[str, dict]:
        """interpretation id -> {"families", "default", "alternatives": [ids]} for the given families.

        One interpretation may belong to several families (the FX5 time and date comparisons share
        theirs): an implementation declares it once, and it holds for all of them.
        """
        out = {}
        for family, header in sorted(self.headers.items()):
            if families is not None and family not in families:
                continue
            for interp in header.get("interpretations", []):
                alternatives = [a["id"] for a in interp["alternatives"]]
                seen = out.setdefault(interp["id"], {"families": [], "default": interp["default"],
                                                     "alternatives": alternatives})
                if (seen["default"], seen["alternatives"]) != (interp["default"], alternatives):
                    raise VerifyError(f"{self.source}: interpretation {interp['id']} has other alternatives or "
                                      f"another default in {family} than in {seen['families'][0]}")
                seen["families"].append(family)
        return out

    def instructions(self) -> dict[str, list[str]]:
        return {family: list(h.get("instructions", [])) for family, h in sorted(self.headers.items())}

    def names(self) -> dict[str, list[str]]:
        """The names a selection may use, by kind: family, instruction, tag, interpretation."""
        instructions, tags = set(), set()
        for header in self.headers.values():
            instructions.update(header.get("instructions", ()))
            tags.update(header.get("tags", {}))
        for v in self.vectors:
            instructions.add(v["instruction"])
            tags.update(v.get("tags", ()))
        return {"family": sorted(self.headers), "instruction": sorted(instructions), "tag": sorted(tags),
                "interpretation": sorted(self.interpretations())}


def _parse_jsonl(path: Path, raw: bytes) -> dict:
    """A JSON-lines family file: its header on the first line, then one vector per line."""
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError as exc:
        line = raw[:exc.start].count(b"\n") + 1
        raise VerifyError(f"{path}:{line}: not UTF-8 text (byte {exc.start})")
    if not text.endswith("\n"):
        raise VerifyError(f"{path}:{text.count(chr(10)) + 1}: the last line does not end: the file was cut")
    lines = text[:-1].split("\n")
    parsed = []
    for number, line in enumerate(lines, 1):
        try:
            parsed.append(json.loads(line))
        except json.JSONDecodeError as exc:
            raise VerifyError(f"{path}:{number}: not valid JSON ({exc.msg})")
    header = parsed[0] if parsed else None
    if not isinstance(header, dict) or "vectors" in header:
        raise VerifyError(f"{path}:1: not the header of a JSON-lines vector file")
    return {**header, "vectors": parsed[1:]}


def _merged_ids(merged) -> dict[str, str]:
    """{old id: the id it is now} from an index's {family: {old id: the id it went to}}, each chain of
    merges followed to its end (a vector merged into one that was merged again)."""
    flat = {}
    for ids in (merged or {}).values():
        if isinstance(ids, dict):
            flat.update({k: v for k, v in ids.items() if isinstance(k, str) and isinstance(v, str)})
    out = {}
    for old, new in flat.items():
        seen = {old}
        while new in flat and new not in seen:
            seen.add(new)
            new = flat[new]
        out[old] = new
    return out


def _read_json(path: Path):
    """An index: small, so checked for a repeated key at every load."""
    raw = _read_bytes(path)
    data = _parse_json(path, raw)
    text = raw.decode("utf-8")
    if has_repeated_key(text):
        raise VerifyError(repeated_key_message(str(path), text))
    return data


def _read_bytes(path: Path) -> bytes:
    return read_bytes(path)


def _parse_json(path: Path, raw: bytes):
    try:
        return json.loads(raw.decode("utf-8"))
    except UnicodeDecodeError as exc:
        raise VerifyError(f"{path}: not UTF-8 text (byte {exc.start})")
    except json.JSONDecodeError as exc:
        raise VerifyError(f"{path}:{exc.lineno}: not valid JSON ({exc.msg})")

