"""Compare two vector sets by vector id, so that a spec change can be reviewed by its effect.

A vector set is named by one of:
- a folder holding manifest.json and the family files it lists (`vectors/`), or a folder whose
  `vectors/` subfolder does (a checkout, `.`);
- one family file (`vectors/fx5-time-add.json`); the other side is then narrowed to that family;
- a git revision `REV` (the vectors of the checkout at REV, as for a folder) or `REV:PATH` (PATH at
  REV as git names it: from the top of the repository, or `REV:./PATH` from the current folder; a
  folder or a family file), read with `git show` in the repository of the current folder.
An argument that names an existing file or folder is read from disk; anything else is a revision.

Each vector present on both sides is classed by the most telling thing that changed:
- `expectation`: the steps' `expect`, `final`, `outcome` or `alternatives`;
- `inputs`: what the vector sets up (`initial`, `assumes`, the steps' inputs, the instruction);
- `metadata`: only what describes it (`description`, `tags`, `clauses`, `printed`, ...).
File headers (spec hash, interpretations, tags) are compared too and reported apart.

A folder's manifest.json names (under "merged") the ids the generator merged into another vector
because they were the same test; an id removed on the new side that the new side merged is reported
with the vector it went into.
"""
import json
import os
import subprocess
from dataclasses import dataclass, field
from pathlib import Path

from plcvec.errors import PlcvecError

CLASSES = ("expectation", "inputs", "metadata")
# Top-level keys of a vector whose change is a change of expectation, and those that set the vector up.
EXPECTATION_KEYS = ("final", "outcome", "alternatives")
INPUT_KEYS = ("initial", "assumes", "instruction", "st", "family")
MANIFEST = "manifest.json"
CHECKOUT_FOLDER = "vectors"
ABSENT = object()


class DiffInputError(PlcvecError):
    """A vector set that cannot be read: named with the file (or git object) at fault."""


# ---------------------------------------------------------------------------------------------- reading
class _Disk:
    def __init__(self, root):
        self.root = Path(root)

    def label(self, name):
        return str(self.root / name)

    def read(self, name):
        path = self.root / name
        if not path.is_file():
            return None
        try:
            return path.read_bytes()
        except OSError as exc:
            raise DiffInputError(f"{path}: cannot read: {exc.strerror or exc}") from None


class _Git:
    def __init__(self, rev, path):
        self.rev, self.path = rev, path.rstrip("/")

    def object(self, name):
        return f"{self.rev}:{self.path}/{name}" if self.path else f"{self.rev}:{name}"

    def label(self, name):
        return self.object(name)

    def read(self, name):
        proc = _git("cat-file", "-p", self.object(name))
        return proc.stdout if proc.returncode == 0 else None


def _git(*args):
    """Run git in the current folder; the caller reads the return code (a missing object is an answer)."""
    try:
        return subprocess.run(["git", *args], capture_output=True, cwd=os.getcwd())
    except OSError as exc:
        raise DiffInputError(f"cannot run git: {exc.strerror or exc}") from None


@dataclass
class VectorSet:
    label: str
    single: bool                       # one family file rather than a folder
    families: dict = field(default_factory=dict)   # name -> {"header": {...}, "vectors": {id: vector}}
    manifest: dict = field(default_factory=dict)   # the folder's manifest.json (empty for a single file)
    merged: dict = field(default_factory=dict)     # family -> {id merged away: the id it went into}

    def count(self):
        return sum(len(f["vectors"]) for f in self.families.values())


def load_set(arg):
    """The vector set an argument names (see the module docstring)."""
    path = Path(arg)
    if path.is_dir():
        root = path if (path / MANIFEST).is_file() or not (path / CHECKOUT_FOLDER / MANIFEST).is_file() else path / CHECKOUT_FOLDER
        return _folder(_Disk(root), str(root))
    if path.is_file():
        source = _Disk(path.parent)
        return _single(source, path.name, str(path))
    return _revision(arg)


def _revision(arg):
    rev, _, where = arg.partition(":")
    if not rev:
        raise DiffInputError(f"{arg}: no such file or folder, and not a git revision")
    inside = _git("rev-parse", "--is-inside-work-tree")
    if inside.returncode != 0:
        raise DiffInputError(f"{arg}: no such file or folder, and {os.getcwd()} is not in a git repository")
    kind = _git("cat-file", "-t", f"{rev}:{where}")
    if kind.returncode != 0:
        reason = kind.stderr.decode(errors="replace").strip().splitlines()
        raise DiffInputError(f"{arg}: no such file or folder, and git knows no {rev}:{where}"
                             + (f" ({reason[-1]})" if reason else ""))
    if kind.stdout.strip() == b"blob":
        folder, _, name = where.rpartition("/")
        return _single(_Git(rev, folder), name, arg)
    source = _Git(rev, where)
    if source.read(MANIFEST) is None and _Git(rev, f"{where}/{CHECKOUT_FOLDER}" if where else CHECKOUT_FOLDER).read(MANIFEST) is not None:
        source = _Git(rev, f"{where}/{CHECKOUT_FOLDER}" if where else CHECKOUT_FOLDER)
    return _folder(source, arg)


def _json(source, name):
    raw = source.read(name)
    where = source.label(name)
    if raw is None:
        raise DiffInputError(f"{where}: no such file")
    try:
        return json.loads(raw.decode("utf-8"))
    except UnicodeDecodeError as exc:
        raise DiffInputError(f"{where}: not UTF-8 text (byte {exc.start})") from None
    except json.JSONDecodeError as exc:
        raise DiffInputError(f"{where}:{exc.lineno}: not valid JSON: {exc.msg} (column {exc.colno})") from None


def _folder(source, label):
    if source.read(MANIFEST) is None:
        raise DiffInputError(f"{source.label(MANIFEST)}: no such file (a vector set is a folder with manifest.json "
                             f"and the family files it lists, a family file, or a git revision)")
    manifest = _json(source, MANIFEST)
    families = manifest.get("families") if isinstance(manifest, dict) else None
    if not isinstance(families, dict) or not all(isinstance(e, dict) and isinstance(e.get("file"), str) for e in families.values()):
        raise DiffInputError(f"{source.label(MANIFEST)}: not a vector manifest (no \"families\" with a \"file\" for each)")
    out = VectorSet(label, single=False, manifest=manifest, merged=_merged(source, manifest))
    for name in sorted(families):
        doc = _family(source, families[name]["file"])
        if doc["header"]["family"] != name:
            raise DiffInputError(f"{source.label(families[name]['file'])}: holds family {doc['header']['family']!r}, "
                                 f"but {MANIFEST} lists it as {name!r}")
        out.families[name] = doc
    return out


def _merged(source, manifest):
    """{family: {dropped id: kept id}} from the manifest's "merged"; {} for a manifest without it."""
    merged = manifest.get("merged", {})
    if not isinstance(merged, dict) or not all(
            isinstance(m, dict) and all(isinstance(k, str) and isinstance(v, str) for k, v in m.items())
            for m in merged.values()):
        raise DiffInputError(f"{source.label(MANIFEST)}: \"merged\" is not {{family: {{merged id: kept id}}}}")
    return merged


def load_source(source, label):
    """The vector set of any folder-like `source`: an object with label(name) and read(name) -> bytes or
    None (as _Disk and _Git), e.g. a folder inside an archive read into memory."""
    return _folder(source, label)


def _single(source, name, label):
    doc = _family(source, name)
    return VectorSet(label, single=True, families={doc["header"]["family"]: doc})


def _family(source, name):
    doc = _json(source, name)
    where = source.label(name)
    if not isinstance(doc, dict) or not isinstance(doc.get("family"), str) or not isinstance(doc.get("vectors"), list):
        raise DiffInputError(f"{where}: not a vector file (a JSON object with \"family\" and a list of \"vectors\")")
    vectors = {}
    for i, v in enumerate(doc["vectors"]):
        if not isinstance(v, dict) or not isinstance(v.get("id"), str):
            raise DiffInputError(f"{where}: vector {i} has no string \"id\"")
        if v["id"] in vectors:
            raise DiffInputError(f"{where}: vector id {v['id']!r} appears twice")
        vectors[v["id"]] = v
    return {"header": {k: v for k, v in doc.items() if k != "vectors"}, "vectors": vectors}


# ---------------------------------------------------------------------------------------------- comparing
def changes(old, new, path=()):
    """[(path, old, new)] for every leaf that differs; ABSENT where a key or item is missing on one side."""
    if old == new:
        return []
    if isinstance(old, dict) and isinstance(new, dict):
        out = []
        for k in sorted(set(old) | set(new)):
            out += changes(old.get(k, ABSENT), new.get(k, ABSENT), path + (k,))
        return out
    if isinstance(old, list) and isinstance(new, list) and _records(old) and _records(new):
        if path == ("alternatives",):  # matched by the choices they stand for, not their position
            old_k, new_k = _by_choices(old), _by_choices(new)
            return [c for k in sorted(set(old_k) | set(new_k))
                    for c in changes(old_k.get(k, ABSENT), new_k.get(k, ABSENT), path + (k,))]
        return [c for i in range(max(len(old), len(new)))
                for c in changes(old[i] if i < len(old) else ABSENT, new[i] if i < len(new) else ABSENT, path + (i,))]
    return [(path, old, new)]


def _records(items):
    return bool(items) and all(isinstance(i, dict) for i in items)


def _by_choices(alternatives):
    return {"[" + ", ".join(f"{k}={v}" for k, v in sorted(a.get("choices", {}).items())) + "]": a for a in alternatives}


def change_class(path):
    top = path[0]
    if top in EXPECTATION_KEYS or (top == "steps" and (len(path) < 3 or path[2] == "expect")):
        return "expectation"  # a step added or removed brings or takes its expectation
    if top in INPUT_KEYS or top == "steps":
        return "inputs"
    return "metadata"


def compare(old, new, only=None):
    """The difference of two vector sets, as plain data (the --json document)."""
    names = sorted(set(old.families) | set(new.families))
    if old.single != new.single:  # a family file against a folder: that family only
        names = sorted(set((old if old.single else new).families))
    if only:
        unknown = sorted(set(only) - set(old.families) - set(new.families))
        if unknown:
            raise DiffInputError(f"no family {', '.join(unknown)} in {old.label} or {new.label}")
        names = [n for n in names if n in only]
    report = {"old": old.label, "new": new.label, "families": {}}
    totals = dict.fromkeys(("added", "removed") + CLASSES, 0)
    for name in names:
        a = old.families.get(name, {"header": {}, "vectors": {}})
        b = new.families.get(name, {"header": {}, "vectors": {}})
        fam = {"old_count": len(a["vectors"]), "new_count": len(b["vectors"]),
               "present": [side for side, s in (("old", old), ("new", new)) if name in s.families],
               "added": sorted(set(b["vectors"]) - set(a["vectors"])),
               "removed": sorted(set(a["vectors"]) - set(b["vectors"])),
               "merged": {},
               "changed": [], "header": [_entry(c) for c in changes(a["header"], b["header"])],
               "interpretation_changes": _interpretation_changes(a["header"], b["header"])}
        for vid in sorted(set(a["vectors"]) & set(b["vectors"])):
            found = changes(a["vectors"][vid], b["vectors"][vid])
            if found:
                cls = min((change_class(p) for p, _, _ in found), key=CLASSES.index)
                fam["changed"].append({"id": vid, "class": cls, "changes": [_entry(c) for c in found]})
        went = new.merged.get(name, {})
        fam["merged"] = {vid: went[vid] for vid in fam["removed"] if vid in went}
        fam["counts"] = {"added": len(fam["added"]), "removed": len(fam["removed"]),
                         **{c: sum(1 for v in fam["changed"] if v["class"] == c) for c in CLASSES}}
        for k, v in fam["counts"].items():
            totals[k] += v
        report["families"][name] = fam
    report["totals"] = totals
    report["identical"] = not any(sum(f["counts"].values()) or f["header"] or len(f["present"]) < 2
                                  for f in report["families"].values())
    return report


def _interpretation_changes(old_header, new_header):
    from plcvec.output.upgrade import interpretation_changes

    def by_id(header):
        return {i["id"]: {"question": i.get("question", ""), "default": i["default"],
                          "alternatives": [a["id"] for a in i["alternatives"]], "families": [header.get("family", "")]}
                for i in header.get("interpretations", ())}
    return interpretation_changes(by_id(old_header), by_id(new_header))


def path_text(path):
    out = ""
    for step in path:
        if isinstance(step, int):
            out += f"[{step}]"
        elif step.startswith("["):
            out += step
        else:
            out += ("." if out else "") + step
    return out


def _entry(change):
    path, old, new = change
    entry = {"path": path_text(path)}
    if old is not ABSENT:
        entry["old"] = old
    if new is not ABSENT:
        entry["new"] = new
    return entry


# ---------------------------------------------------------------------------------------------- writing
COUNT_WORDS = {"added": "added", "removed": "removed", "expectation": "expectation changed",
               "inputs": "inputs changed", "metadata": "metadata only"}
MAX_VALUE = 100


def counts_text(fam):
    parts = [f"{n} {COUNT_WORDS[k]}" for k, n in fam["counts"].items() if n]
    if fam["header"]:
        parts.append(f"{len(fam['header'])} header field{'s' if len(fam['header']) > 1 else ''} changed")
    if len(fam["present"]) < 2:
        parts.append(f"family only in {fam['present'][0] if fam['present'] else 'neither'}")
    return ", ".join(parts) or "identical"


def value_text(entry, side):
    if side not in entry:
        return "(absent)"
    text = json.dumps(entry[side], sort_keys=True, ensure_ascii=False)
    return text if len(text) <= MAX_VALUE else text[:MAX_VALUE - 1] + "…"


def change_line(entry):
    old, new = entry.get("old", ABSENT), entry.get("new", ABSENT)
    if isinstance(old, list) and isinstance(new, list) and all(isinstance(x, str) for x in old + new):
        gone, came = [x for x in old if x not in new], [x for x in new if x not in old]
        if gone or came:  # a list of names (tags, clauses): what left and what came
            return f"{entry['path']}: " + " ".join([f"-{x}" for x in gone] + [f"+{x}" for x in came])
    return f"{entry['path']}: {value_text(entry, 'old')} -> {value_text(entry, 'new')}"


def _header_lines(fam, brief):
    """A family header's changes: interpretations by id (added with question and default), then, unless
    brief, every other header field changed."""
    from plcvec.output.upgrade import interpretation_lines

    lines = interpretation_lines(fam.get("interpretation_changes", ()), "  ")
    others = [e for e in fam["header"] if not e["path"].startswith("interpretations")]
    if others:
        if brief:
            lines.append(f"  header: {', '.join(sorted({e['path'].split('.')[0].split('[')[0] for e in others}))} changed")
        else:
            lines.append("  header:")
            lines += [f"      {change_line(e)}" for e in others]
    return lines


def render_text(report, brief=False):
    old_total = sum(f["old_count"] for f in report["families"].values())
    new_total = sum(f["new_count"] for f in report["families"].values())
    lines = [f"plcvec diff: {report['old']} ({old_total} vectors) -> {report['new']} ({new_total} vectors)"]
    for name, fam in report["families"].items():
        if counts_text(fam) == "identical":
            continue
        lines.append(f"{name}: {counts_text(fam)}")
        lines += [f"  + {vid}" for vid in fam["added"]]
        lines += [f"  - {vid}" + (f" (the same test as {fam['merged'][vid]}, which now carries its tags and reasons)"
                                  if vid in fam.get("merged", {}) else "") for vid in fam["removed"]]
        for v in fam["changed"]:
            lines.append(f"  ~ {v['id']} ({v['class']})")
            if not brief:
                lines += [f"      {change_line(e)}" for e in v["changes"]]
        if fam["header"]:
            lines += _header_lines(fam, brief)
    lines.append("summary:")
    lines += [f"  {name}: {counts_text(fam)} ({fam['old_count']} -> {fam['new_count']} vectors)"
              for name, fam in report["families"].items()]
    t = report["totals"]
    lines.append("total: " + (", ".join(f"{n} {COUNT_WORDS[k]}" for k, n in t.items() if n) or "no vector differs")
                 + ("" if report["identical"] else "; the sets differ") )
    return "\n".join(lines) + "\n"
