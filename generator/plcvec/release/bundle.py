"""The files of a release, by their path in the archive.

    plcvec-vectors-<version>/
        vectors/        the family files, manifest.json, vectors.csv, schema/vector-file.schema.json
        jsonl/          each family as JSON Lines (line 1 the file header, then one vector per line)
        protocol/       the JSON Schemas of the process protocol's messages
        review/         review.html and review.md: the spec for a reviewer
        CONTRACT.md, PROTOCOL.md, CHANGES.md
        SHA256SUMS      sha256sum's format, of every other file, in path order

Everything comes from the spec in use, generated in memory and checked against the vector folder
first: a release is never made of vectors that differ from the committed ones.
"""
import hashlib
import importlib.resources
import json

from plcvec.errors import PlcvecError
from plcvec.output import diff
from plcvec.output.golden import build_golden
from plcvec.output.jsonl import family_jsonl

DOCS = ("CONTRACT.md", "PROTOCOL.md")
VECTOR_SCHEMA = "schema/vector-file.schema.json"


class _Memory:
    """Generated files as a folder `plcvec diff` can read."""

    def __init__(self, files, label):
        self.files, self.name = files, label

    def label(self, name):
        return f"{self.name}/{name}"

    def read(self, name):
        text = self.files.get(name)
        return None if text is None else text.encode("utf-8")


def root_name(version):
    return f"plcvec-vectors-{version}"


def golden_checked(families, vectors_dir, jobs):
    """The golden files the spec generates (in `jobs` worker processes), after checking the vector
    folder holds exactly them."""
    files, by_family = build_golden(families, jobs=jobs)
    differ = [name for name, text in sorted(files.items())
              if not (vectors_dir / name).is_file() or (vectors_dir / name).read_text(encoding="utf-8") != text]
    if differ:
        raise PlcvecError(f"release: {', '.join(str(vectors_dir / n) for n in differ)} differ from what the spec "
                          "generates; run `plcvec generate` (and commit) before releasing")
    if not (vectors_dir / VECTOR_SCHEMA).is_file():
        raise PlcvecError(f"release: {vectors_dir / VECTOR_SCHEMA}: no such file")
    return files, by_family


def current_set(files, version):
    return diff.load_source(_Memory(files, root_name(version)), root_name(version))


def protocol_schemas():
    folder = importlib.resources.files("plcvec_verify") / "schema"
    return {f"protocol/{p.name}": p.read_bytes() for p in sorted(folder.iterdir(), key=lambda p: p.name)
            if p.name.endswith(".json")}


def bundle(version, golden, vectors_dir, review_files, docs_dir, changes):
    """{archive path: bytes} of the whole release, SHA256SUMS included."""
    root = root_name(version) + "/"
    out = {f"vectors/{name}": text.encode("utf-8") for name, text in golden.items()}
    out[f"vectors/{VECTOR_SCHEMA}"] = (vectors_dir / VECTOR_SCHEMA).read_bytes()
    manifest = json.loads(golden["manifest.json"])
    for name, entry in sorted(manifest["families"].items()):
        out[f"jsonl/{name}.jsonl"] = family_jsonl(json.loads(golden[entry["file"]])).encode("utf-8")
    out.update(protocol_schemas())
    out.update({f"review/{name}": text.encode("utf-8") for name, text in review_files.items()})
    for name in DOCS:
        path = docs_dir / name
        if not path.is_file():
            raise PlcvecError(f"release: {path}: no such file")
        out[name] = path.read_bytes()
    out["CHANGES.md"] = changes.encode("utf-8")
    sums = "".join(f"{hashlib.sha256(out[name]).hexdigest()}  {name}\n" for name in sorted(out))
    out["SHA256SUMS"] = sums.encode("utf-8")
    return {root + name: data for name, data in out.items()}
