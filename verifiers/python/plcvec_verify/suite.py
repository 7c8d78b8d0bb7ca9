"""Loading a vector set and choosing which of its vectors to run.

A vector set is a folder with `manifest.json` and the family files it names (what `plcvec
generate` writes), or a single family file. Nothing here depends on the generator: an
implementer needs only the published files.
"""
from __future__ import annotations

import fnmatch
import json
import zlib
from dataclasses import dataclass, field
from pathlib import Path

from .errors import VerifyError
from .expect import Expectations
from .validate import schema_for, validate_file

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

    def __post_init__(self):
        self.by_id = {v["id"]: v for v in self.vectors}

    @classmethod
    def load(cls, path) -> "Suite":
        path = Path(path)
        if path.is_dir():
            manifest = _read_json(path / "manifest.json")
            try:
                files = [path / entry["file"] for entry in manifest["families"].values()]
            except (KeyError, TypeError, AttributeError):
                raise VerifyError(f"{path / 'manifest.json'}: no `families` with a `file` each; is this a plcvec vector folder?")
            suite_version = str(manifest.get("generator_version") or "")
            manifest_hash = manifest.get("spec_sha256", "")
        elif path.exists():
            files, suite_version, manifest_hash = [path], "", ""
        else:
            raise VerifyError(f"{path}: no such vector folder or file")
        schema = schema_for(path)
        headers, vectors, spec_hashes, schema_versions = {}, [], set(), set()
        for file in files:
            raw = _read_bytes(file)
            data = _parse_json(file, raw)
            if not isinstance(data, dict) or not isinstance(data.get("vectors"), list) or "family" not in data:
                raise VerifyError(f"{file}: not a plcvec vector file (no `family` and `vectors`)")
            version = str(data.get("schema_version", ""))
            major = version.split(".")[0]
            if major != str(SCHEMA_MAJOR):
                raise VerifyError(f"{file}: schema_version {version or '(none)'} is not {SCHEMA_MAJOR}.x; "
                                  f"this verifier reads {SCHEMA_MAJOR}.x files only (see CONTRACT.md, Versioning)")
            schema_versions.add(version)
            spec_hashes.add(data.get("spec_sha256", ""))
            headers[data["family"]] = {k: v for k, v in data.items() if k != "vectors"}
            for index, v in enumerate(data["vectors"]):
                problem = _shape_problem(v, data["family"])
                if problem:
                    name = v.get("id") if isinstance(v, dict) and isinstance(v.get("id"), str) else f"#{index}"
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
        return cls(vectors=vectors, headers=headers, source=str(path), suite_version=suite_version,
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


# What the runner reads of a vector, checked once at load so that a damaged file is reported by
# name rather than failing half-way through a run (the full schema is vectors/schema/).
_VECTOR_KEYS = {"id": str, "family": str, "instruction": str, "initial": dict, "steps": list,
                "final": dict, "outcome": dict}


def _shape_problem(v, family) -> str:
    if not isinstance(v, dict):
        return "not a JSON object"
    for key, kind in _VECTOR_KEYS.items():
        if not isinstance(v.get(key), kind):
            return f"no `{key}` ({kind.__name__})"
    if v["family"] != family:
        return f"family {v['family']!r} in a {family!r} file"
    if not isinstance(v["initial"].get("devices"), dict) or not isinstance(v["initial"].get("operands"), dict):
        return "`initial` needs `devices` and `operands`"
    if not v["steps"] or not all(isinstance(st, dict) and isinstance(st.get("expect"), dict) for st in v["steps"]):
        return "every step needs an `expect`"
    if not isinstance(v["final"].get("devices"), dict):
        return "`final` needs `devices`"
    return ""


def _read_json(path: Path):
    return _parse_json(path, _read_bytes(path))


def _read_bytes(path: Path) -> bytes:
    try:
        return path.read_bytes()
    except FileNotFoundError:
        raise VerifyError(f"{path}: no such file")
    except OSError as exc:
        raise VerifyError(f"{path}: {exc.strerror}")


def _parse_json(path: Path, raw: bytes):
    try:
        return json.loads(raw.decode("utf-8"))
    except UnicodeDecodeError as exc:
        raise VerifyError(f"{path}: not UTF-8 text (byte {exc.start})")
    except json.JSONDecodeError as exc:
        raise VerifyError(f"{path}:{exc.lineno}: not valid JSON ({exc.msg})")


def touched_interpretations(vector: dict) -> set[str]:
    """The interpretations a vector's outcome depends on."""
    return set(vector["outcome"].get("interpretations", ()))


@dataclass(frozen=True)
class Selection:
    """Filters; each list is OR within itself, and the filters are AND together."""

    families: tuple = ()
    instructions: tuple = ()
    tags: tuple = ()
    ids: tuple = ()                  # glob patterns (fnmatch) on the id
    interpretations: tuple = ()      # vectors whose outcome depends on one of these
    shard: tuple | None = None       # (k, n), 1 <= k <= n

    def matches(self, v: dict) -> bool:
        if self.families and v["family"] not in self.families:
            return False
        if self.instructions and v["instruction"] not in self.instructions:
            return False
        if self.tags and not set(self.tags) & set(v.get("tags", ())):
            return False
        if self.ids and not any(fnmatch.fnmatchcase(v["id"], p) for p in self.ids):
            return False
        if self.interpretations and not set(self.interpretations) & touched_interpretations(v):
            return False
        if self.shard and shard_of(v["id"], self.shard[1]) != self.shard[0]:
            return False
        return True

    @property
    def everything(self) -> bool:
        """Whether the selection has no filter at all (every vector is selected)."""
        return not (self.families or self.instructions or self.tags or self.ids or self.interpretations
                    or self.shard)

    def apply(self, vectors: list[dict]) -> list[dict]:
        if self.everything:     # the usual gate run: no per-vector test to pay for
            return list(vectors)
        return [v for v in vectors if self.matches(v)]

    def check(self, suite: "Suite", option_prefix: str = "--") -> None:
        """Refuse names the suite does not have, listing those it has, and id globs that match nothing.

        An unknown name would select nothing, and a gate that selects nothing must not look like one
        that passed; a usage error says which word was mistyped.
        """
        named = (("family", self.families), ("instruction", self.instructions), ("tag", self.tags),
                 ("interpretation", self.interpretations))
        # The names are gathered from every vector: only when a name was given to check.
        known = suite.names() if any(given for _, given in named) else {}
        for kind, given in named:
            for name in given:
                if name not in known[kind]:
                    raise VerifyError(f"{option_prefix}{kind} {name}: {suite.source} has no such {kind}; "
                                      f"known: {', '.join(known[kind]) or '(none)'}")
        for pattern in self.ids:
            if not any(fnmatch.fnmatchcase(vid, pattern) for vid in suite.by_id):
                example = next(iter(suite.by_id), "")
                raise VerifyError(f"{option_prefix}id {pattern}: matches no vector id in {suite.source} "
                                  f"(ids look like {example}; a glob matches the whole id)")


def shard_of(vector_id: str, n: int) -> int:
    """The shard (1..n) a vector belongs to.

    A hash of the id rather than its position: adding a vector to the suite moves no other vector
    to another shard, so a CI job's history stays comparable.
    """
    return zlib.crc32(vector_id.encode("utf-8")) % n + 1


def parse_shard(text: str) -> tuple[int, int]:
    try:
        k, n = (int(x) for x in text.split("/"))
    except ValueError:
        raise VerifyError(f"--shard takes K/N (e.g. 2/4), got {text!r}")
    if not 1 <= k <= n:
        raise VerifyError(f"--shard {text}: K must be between 1 and N")
    return k, n
