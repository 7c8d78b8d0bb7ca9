#!/usr/bin/env python3
"""Run the shared table of faults (faults.toml) against every runner and check each verdict.

    python3 verifiers/parity/run.py                      # every language that has a faults-entry
    python3 verifiers/parity/run.py --lang go,rust       # some of them
    python3 verifiers/parity/run.py --row 'damage-*' -v  # some rows, with each run's output

Each language provides `verifiers/<lang>/faults-entry` (README.md beside this file): `--build` once,
then one call per row with the row's environment. This script makes the damaged vector folders,
runs every row with a bound on its time, and compares the exit status and the output with the
row's verdict. It needs nothing but the standard library, so it runs before anything is installed.

Exit status: 0 every row gave its verdict in every language, 1 some did not, 2 the table, a language
or an option is wrong.
"""
from __future__ import annotations

import argparse
import contextlib
import fcntl
import fnmatch
import hashlib
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import tarfile
import tempfile
import time
import tomllib
from dataclasses import dataclass, field
from pathlib import Path

HERE = Path(__file__).resolve().parent
REPO = HERE.parents[1]
TABLE = HERE / "faults.toml"
LANGUAGES = ("python", "c", "rust", "go", "java", "typescript")
# The vector folder each language's runner reads: the golden JSON files with manifest.json, or the
# packaged JSON-lines copy with index.json (C reads its vectors through `plcvec export`, from JSON).
FORMS = {"python": "json", "c": "json", "rust": "jsonl", "go": "jsonl", "java": "jsonl",
         "typescript": "jsonl"}
# Exit status `plcvec verify` gives for each verdict (CONTRACT.md).
STATUS = {"pass": 0, "fail": 1, "usage": 2, "empty": 5}
# Languages whose entry point returns the verdict's own status, not only its test runner's.
EXACT = {"python", "c"}
# Languages whose faults-entry runs every row in one call (`faults-entry --batch PLAN OUT`, README.md):
# one test run for the rows, not a build tool and a test process started per row (Python: one
# interpreter that imports `plcvec verify` once and forks each row's process from it).
BATCH = {"java", "python"}
ROW_KEYS = {"id", "what", "verdict", "names", "file_line", "hostile", "on", "damage", "source", "env",
            "known", "filter", "except", "not_names", "once", "seconds", "known_as", "known_kind"}
EXCEPT_KEYS = {"verdict", "names", "skip", "why"}
DAMAGES = ("unknown-key", "unknown-header-key", "duplicate-id", "bit-holds-2", "word-out-of-range",
           "missing-steps", "major-version", "sha-mismatch", "non-utf8", "cut-at-line",
           "cut-mid-line", "not-json", "missing-file", "missing-index", "empty-family",
           "fifo", "device", "symlink-loop", "index-fifo", "repeated-key", "repeated-key-in-index",
           "bit-holds-2-in-final")
# A user's mistake gets a message, not a stack trace: what each language's traces look like.
TRACES = {
    "python": re.compile(r"Traceback \(most recent call last\)"),
    "go": re.compile(r"^goroutine \d+ \[", re.M),
    "rust": re.compile(r"stack backtrace:|RUST_BACKTRACE=1"),
    "java": re.compile(r"^\s+at (java|jdk|sun|org\.junit)\.[\w.$]+\(", re.M),
    "typescript": re.compile(r"^\s+at .*\((node:|file:|/).*:\d+:\d+\)$", re.M),
    "c": re.compile(r"AddressSanitizer|^#\d+ 0x[0-9a-f]+ in ", re.M),
}
BUILD_BOUND_S = 900
ROW_BOUND_S = 180
# How long a run waits for another run to finish making a folder of the shared cache (--cache).
CACHE_BOUND_S = 600


class TableError(Exception):
    """faults.toml (or an option) is wrong: exit 2 with the message."""


@dataclass
class Row:
    id: str
    what: str
    verdict: str
    names: list[str] = field(default_factory=list)
    file_line: bool = False
    hostile: str = "reference"
    on: str | None = None
    damage: str | None = None
    source: str | None = None
    env: dict[str, str] = field(default_factory=dict)
    known: str | None = None
    filter: str | None = None
    exceptions: dict[str, dict] = field(default_factory=dict)
    not_names: list[str] = field(default_factory=list)
    once: list[str] = field(default_factory=list)
    seconds: float | None = None
    known_as: str = "PLCVEC_KNOWN_FAILURES"
    known_kind: str | None = None


def load_table(path: Path = TABLE) -> list[Row]:
    try:
        data = tomllib.loads(path.read_text(encoding="utf-8"))
    except (OSError, UnicodeDecodeError, tomllib.TOMLDecodeError) as e:
        raise TableError(f"{path}: {e}") from None
    rows, seen = [], set()
    for i, raw in enumerate(data.get("fault", [])):
        where = f"{path.name}: fault #{i + 1} ({raw.get('id', 'no id')})"
        unknown = set(raw) - ROW_KEYS
        if unknown:
            raise TableError(f"{where}: unknown key(s) {', '.join(sorted(unknown))}")
        for key in ("id", "what", "verdict"):
            if not isinstance(raw.get(key), str) or not raw[key]:
                raise TableError(f"{where}: `{key}` is required")
        if raw["id"] in seen:
            raise TableError(f"{where}: the id is used twice")
        seen.add(raw["id"])
        if raw["verdict"] not in STATUS:
            raise TableError(f"{where}: verdict must be one of {', '.join(STATUS)}")
        if raw.get("damage") is not None and raw["damage"] not in DAMAGES:
            raise TableError(f"{where}: unknown damage {raw['damage']!r}")
        if raw.get("damage") and not raw.get("on"):
            raise TableError(f"{where}: a damage needs `on`, the vector it is applied to")
        if raw.get("source") not in (None, "release"):
            raise TableError(f"{where}: source must be \"release\"")
        if raw.get("source") and raw.get("damage"):
            raise TableError(f"{where}: a row takes a damage or a source, not both")
        if raw.get("filter") not in (None, "no-match"):
            raise TableError(f"{where}: filter must be \"no-match\"")
        if raw.get("known_kind") not in (None, "fifo"):
            raise TableError(f"{where}: known_kind must be \"fifo\"")
        if raw.get("known_as", "PLCVEC_KNOWN_FAILURES") not in ("PLCVEC_KNOWN_FAILURES", "PLCVEC_EXPECTATIONS"):
            raise TableError(f"{where}: known_as must be PLCVEC_KNOWN_FAILURES or PLCVEC_EXPECTATIONS")
        if raw.get("seconds") is not None and not (isinstance(raw["seconds"], (int, float)) and raw["seconds"] > 0):
            raise TableError(f"{where}: seconds must be a positive number")
        exceptions = raw.get("except", {})
        for lang, exc in exceptions.items():
            if lang not in LANGUAGES:
                raise TableError(f"{where}: except.{lang}: no such language")
            if set(exc) - EXCEPT_KEYS or not exc.get("why"):
                raise TableError(f"{where}: except.{lang} takes verdict, names, skip and a `why`")
            if "verdict" in exc and exc["verdict"] not in STATUS:
                raise TableError(f"{where}: except.{lang}: verdict must be one of {', '.join(STATUS)}")
        rows.append(Row(id=raw["id"], what=raw["what"], verdict=raw["verdict"],
                        names=list(raw.get("names", [])), file_line=bool(raw.get("file_line")),
                        hostile=raw.get("hostile", "reference"), on=raw.get("on"),
                        damage=raw.get("damage"), source=raw.get("source"),
                        env={k: str(v) for k, v in raw.get("env", {}).items()},
                        known=raw.get("known"), filter=raw.get("filter"), exceptions=exceptions,
                        not_names=list(raw.get("not_names", [])), once=list(raw.get("once", [])),
                        seconds=raw.get("seconds"), known_as=raw.get("known_as", "PLCVEC_KNOWN_FAILURES"),
                        known_kind=raw.get("known_kind")))
    if not rows:
        raise TableError(f"{path}: no [[fault]] rows")
    return rows


# --- the damaged vector folders ----------------------------------------------------------------

def sha256(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


def jsonl_source() -> Path:
    """The packaged JSON-lines copy the natives read (`plcvec export` writes the same one to each)."""
    for lang in ("rust", "go", "typescript"):
        folder = REPO / "verifiers" / lang / "vectors"
        if (folder / "index.json").is_file():
            return folder
    raise TableError("no packaged JSON-lines vectors (verifiers/<lang>/vectors/index.json); "
                     "run `python3 -m plcvec export --all`")


class Folder:
    """A copy of one form of the vector files, and the family file a damage is applied to."""

    def __init__(self, form: str, root: Path, on: str):
        self.form, self.root, self.on = form, root, on
        self.family = on.split("/", 1)[0]
        self.index = root / ("manifest.json" if form == "json" else "index.json")
        self.file = root / f"{self.family}.{form}"

    def read_index(self) -> dict:
        return json.loads(self.index.read_text(encoding="utf-8"))

    def write_index(self, index: dict) -> None:
        self.index.write_text(json.dumps(index, indent=1, sort_keys=True) + "\n", encoding="utf-8")

    def reseal(self, count: int | None = None) -> None:
        """Record the family file's new sha256 (and count), so that only the intended damage is there."""
        index = self.read_index()
        entry = index["families"][self.family]
        entry["sha256"] = sha256(self.file)
        if count is not None:
            entry["count"] = count
        self.write_index(index)

    # The family file as a header and a list of vectors, whichever its form.
    def read(self) -> tuple[dict, list[dict]]:
        text = self.file.read_text(encoding="utf-8")
        if self.form == "json":
            data = json.loads(text)
            return {k: v for k, v in data.items() if k != "vectors"}, data["vectors"]
        lines = text.splitlines()
        return json.loads(lines[0]), [json.loads(line) for line in lines[1:] if line]

    def write(self, header: dict, vectors: list[dict]) -> None:
        if self.form == "json":
            text = json.dumps({**header, "vectors": vectors}, indent=1, ensure_ascii=False) + "\n"
        else:
            if "count" in header:
                header = {**header, "count": len(vectors)}
            text = "".join(json.dumps(obj, ensure_ascii=False, sort_keys=True, separators=(",", ":"))
                           + "\n" for obj in [header, *vectors])
        self.file.write_text(text, encoding="utf-8")
        self.reseal(count=len(vectors))

    def target(self, vectors: list[dict]) -> dict:
        for v in vectors:
            if v.get("id") == self.on:
                return v
        raise TableError(f"vector {self.on} is not in {self.file.name}")

    def target_line(self, data: bytes) -> int:
        """The 0-based line of the file on which the target vector starts."""
        needle = json.dumps(self.on).encode()
        for i, line in enumerate(data.split(b"\n")):
            if needle in line and b'"id"' in line:
                return i
        raise TableError(f"vector {self.on} is not in {self.file.name}")


# The damages, by what they break: the file's kind, the document's content, or its bytes.
NOT_A_REGULAR_FILE = ("fifo", "device", "symlink-loop", "index-fifo")
IN_THE_BYTES = ("repeated-key", "non-utf8", "not-json", "cut-mid-line", "cut-at-line")


def damage(folder: Folder, kind: str) -> None:
    if kind in NOT_A_REGULAR_FILE:
        _not_a_regular_file(folder, kind)
    elif kind == "repeated-key-in-index":
        text = folder.index.read_text(encoding="utf-8")
        folder.index.write_text(text.replace('{', '{"families": {}, ', 1), encoding="utf-8")
    elif kind in IN_THE_BYTES:
        _damage_bytes(folder, kind)
    else:
        _damage_document(folder, kind)


def _not_a_regular_file(folder: Folder, kind: str) -> None:
    # Not a regular file where one is expected: a loader that opens it without looking blocks
    # (a pipe nobody writes), reads for ever (/dev/zero) or fails with ELOOP.
    path = folder.index if kind == "index-fifo" else folder.file
    path.unlink()
    if kind in ("fifo", "index-fifo"):
        os.mkfifo(path)
    elif kind == "device":
        path.symlink_to("/dev/zero")
    else:
        path.symlink_to(path.name)


def _damage_document(folder: Folder, kind: str) -> None:
    """A damage a JSON document can carry: written whole, and sealed (the index's digest matches)."""
    header, vectors = folder.read()
    if kind == "bit-holds-2-in-final":
        v = folder.target(vectors)
        devices = v["final"]["devices"]
        name = next(d for d, value in sorted(devices.items()) if value is True or value is False)
        devices[name] = 2
        folder.write(header, vectors)
    elif kind in ("unknown-key", "bit-holds-2", "word-out-of-range", "missing-steps", "duplicate-id"):
        v = folder.target(vectors)
        if kind == "unknown-key":
            v["surprise"] = 1
        elif kind == "missing-steps":
            del v["steps"]
        elif kind == "duplicate-id":
            vectors.insert(vectors.index(v) + 1, json.loads(json.dumps(v)))
        else:
            devices = v["initial"]["devices"]
            want = bool if kind == "bit-holds-2" else int
            name = next(d for d, value in devices.items()
                        if type(value) is want)  # noqa: E721 (a bool is not a word here)
            devices[name] = 2 if kind == "bit-holds-2" else 70000
        folder.write(header, vectors)
    elif kind == "unknown-header-key":
        folder.write({**header, "surprise": 1}, vectors)
    elif kind == "major-version":
        folder.write({**header, "schema_version": "2.0.0"}, vectors)
        index = folder.read_index()
        index["schema_version"] = "2.0.0"
        folder.write_index(index)
    elif kind == "empty-family":
        folder.write(header, [])
    elif kind == "sha-mismatch":
        index = folder.read_index()
        index["families"][folder.family]["sha256"] = "0" * 64
        folder.write_index(index)
    elif kind == "missing-file":
        folder.file.unlink()
    elif kind == "missing-index":
        folder.index.unlink()
    else:
        raise TableError(f"no damage is named {kind!r}")


def _damage_bytes(folder: Folder, kind: str) -> None:
    """A damage of the bytes themselves. A repeated key and a byte that is not UTF-8 are sealed (the
    loader must find them in a file whose digest matches); the cuts and the broken line are left
    unsealed, as an interrupted copy would be."""
    if kind == "repeated-key":
        # A JSON object cannot hold a key twice, so the bytes are written: the target's `description`
        # again, first, with another text (parsers differ on which one wins).
        folder.write(*folder.read())
    data = folder.file.read_bytes()
    lines = data.split(b"\n")
    at = folder.target_line(data)
    if kind in ("repeated-key", "non-utf8"):
        # The JSON form spreads a vector over lines (its description on a later one); the
        # JSON-lines form holds it on one.
        j = next(i for i in range(at, len(lines)) if b'"description":' in lines[i])
        if kind == "repeated-key":
            lines[j] = re.sub(rb'"description": ?"', lambda m: b'"description":"a second description",' + m.group(0),
                              lines[j], count=1)
        else:
            lines[j] = re.sub(rb'"description": ?"', lambda m: m.group(0) + b"\xff", lines[j], count=1)
        folder.file.write_bytes(b"\n".join(lines))
        folder.reseal()
        return
    if kind == "not-json":
        lines[at] = b'{"id": this is not JSON'
    elif kind == "cut-mid-line":
        lines = lines[:at] + [lines[at][: len(lines[at]) // 2]]
    elif kind == "cut-at-line":
        lines = lines[:at]
        lines.append(b"")
    folder.file.write_bytes(b"\n".join(lines))


class Cache:
    """Damaged folders and the release bundle made once for several runs of this script over one tree
    (CI's lanes, one language each, side by side): the first run that needs one makes it, the others
    copy it. Making them is most of the script's own time (the JSON re-encoded for each damage, a
    `plcvec release`); copying is a few milliseconds. The folders live under a digest of this script
    and of the vector indexes they are made from, so a cache folder given vectors that changed is not
    read; but the release bundle also carries files no index covers (CHANGES.md, the licence), so a
    cache is for one tree as it stands: CI gives a new folder to each run. Each folder is renamed
    into place once whole, and a run copies it, never uses it in place."""

    def __init__(self, root: Path):
        digest = hashlib.sha256(Path(__file__).read_bytes())
        for index in (REPO / "vectors" / "manifest.json", *(REPO / "verifiers" / lang / "vectors" / "index.json"
                                                          for lang in ("rust", "go", "typescript"))):
            digest.update(index.read_bytes() if index.is_file() else b"-")
        self.root = root / digest.hexdigest()[:16]
        self.root.mkdir(parents=True, exist_ok=True)

    def copy(self, name: str, dest: Path, make) -> None:
        """dest := a copy of the cached `name`, which `make(folder)` makes first if no run has."""
        made = self.root / name
        with self._lock(name):
            if not made.is_dir():
                partial = self.root / f".{name}.partial"
                shutil.rmtree(partial, ignore_errors=True)
                make(partial)
                os.rename(partial, made)
        shutil.copytree(made, dest, symlinks=True)

    @contextlib.contextmanager
    def _lock(self, name: str):
        fd = os.open(self.root / f".{name}.lock", os.O_CREAT | os.O_RDWR, 0o644)
        try:
            deadline = time.monotonic() + CACHE_BOUND_S
            while True:
                try:
                    fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
                    break
                except BlockingIOError:
                    if time.monotonic() > deadline:
                        raise TableError(f"{self.root / name}: another run has been making it for "
                                         f"{CACHE_BOUND_S} s; remove {self.root} if no run is")
                    time.sleep(0.05)
            yield
        finally:
            os.close(fd)   # releases the lock


class Folders:
    """The damaged copies, made once per (damage, form, vector), and the release bundle, made once;
    all removed at the end. With a Cache, made once for every run that shares it."""

    def __init__(self, base: Path, cache: Cache | None = None):
        self.base, self.made, self.cache = base, {}, cache
        self.bundle: Path | None = None

    def release(self, form: str) -> Path:
        """The folder of a release bundle (`plcvec release`, unpacked) that a runner of `form` reads:
        a user downloads the bundle and points the runner at it as it is."""
        if self.bundle is None:
            unpacked = self.base / "release"
            if self.cache is None:
                _make_release(unpacked)
            else:
                self.cache.copy("release", unpacked, _make_release)
            self.bundle = next(p for p in unpacked.iterdir() if p.is_dir())
        return self.bundle / ("vectors" if form == "json" else "jsonl")

    def get(self, kind: str, form: str, on: str) -> Folder:
        key = (kind, form, on)
        if key not in self.made:
            root = self.base / f"{len(self.made):02d}-{kind}-{form}"

            def make(folder: Path) -> None:
                shutil.copytree(REPO / "vectors" if form == "json" else jsonl_source(), folder)
                damage(Folder(form, folder, on), kind)

            # A folder holding a pipe or a device is made anew: a copy would read from it.
            if self.cache is None or kind in NOT_A_REGULAR_FILE:
                make(root)
            else:
                self.cache.copy(re.sub(r"[^\w.+-]", "_", f"{kind}-{form}-{on}"), root, make)
            self.made[key] = Folder(form, root, on)
        return self.made[key]


def _make_release(unpacked: Path) -> None:
    """unpacked/<bundle>/: this tree's `plcvec release`, unpacked as a user would."""
    with tempfile.TemporaryDirectory(prefix="plcvec-release-") as out:
        proc = subprocess.run([sys.executable, "-m", "plcvec", "release", "--out", out], cwd=REPO,
                              capture_output=True, text=True, timeout=900)
        if proc.returncode != 0:
            raise TableError(f"plcvec release failed: {proc.stderr.strip()}")
        archive = next(Path(out).glob("plcvec-vectors-*.tar.gz"))
        # The "data" filter where the interpreter has it (3.10.12, 3.11.4 and later): on an older
        # patch release the argument is unknown, and the archive is the one this run just wrote.
        safe = {"filter": "data"} if hasattr(tarfile, "data_filter") else {}
        shutil.unpack_archive(archive, unpacked, **safe)


# --- running a row -----------------------------------------------------------------------------

@dataclass
class Outcome:
    lang: str
    row: Row
    ok: bool
    why: str
    status: int | None
    seconds: float
    output: str


def entry(lang: str) -> Path:
    return REPO / "verifiers" / lang / "faults-entry"


def run_bounded(cmd: list[str], env: dict, bound: float) -> tuple[int | None, str, float]:
    """Run in its own process group; kill the group at the bound. (status or None on a hang, output)"""
    started = time.monotonic()
    with tempfile.TemporaryFile() as out:
        proc = subprocess.Popen(cmd, cwd=REPO, env=env, stdin=subprocess.DEVNULL, stdout=out,
                                stderr=subprocess.STDOUT, start_new_session=True)
        try:
            status = proc.wait(timeout=bound)
        except subprocess.TimeoutExpired:
            os.killpg(proc.pid, signal.SIGKILL)
            proc.wait()
            status = None
        finally:
            try:
                os.killpg(proc.pid, signal.SIGKILL)  # anything the entry left behind
            except ProcessLookupError:
                pass
        out.seek(0)
        text = out.read().decode("utf-8", "replace")
    return status, text, time.monotonic() - started


def expected(row: Row, lang: str) -> tuple[str, list[str], bool]:
    """(verdict, names, skipped) for one language, with its exception if the row has one."""
    exc = row.exceptions.get(lang, {})
    return exc.get("verdict", row.verdict), list(exc.get("names", row.names)), bool(exc.get("skip"))


def prepare_row(lang: str, row: Row, folders: Folders, scratch: Path, bound: float):
    """The row's environment, its placeholders and its bound; or its Outcome, when the language skips it."""
    verdict, names, skipped = expected(row, lang)
    if skipped:
        return Outcome(lang, row, True, f"skipped: {row.exceptions[lang]['why']}", None, 0.0, "")
    env = {k: v for k, v in os.environ.items() if not k.startswith("PLCVEC_")}
    env.update(row.env)
    env["PLCVEC_HOSTILE"] = row.hostile
    if row.on:
        env["PLCVEC_HOSTILE_ON"] = row.on
    if row.filter:
        env["PLCVEC_FILTER"] = row.filter
    subst = {"on": row.on or "", "file": "", "index": "", "known": "known.toml"}
    if row.damage:
        folder = folders.get(row.damage, FORMS[lang], row.on)
        env["PLCVEC_VECTORS"] = str(folder.root)
        subst.update(file=folder.file.name, index=folder.index.name)
    if row.source == "release":
        env["PLCVEC_VECTORS"] = str(folders.release(FORMS[lang]))
    if row.known is not None:
        known = scratch / lang / row.id / "known.toml"
        known.parent.mkdir(parents=True, exist_ok=True)
        if row.known_kind == "fifo":
            if known.exists():
                known.unlink()
            os.mkfifo(known)
        else:
            known.write_text(row.known.lstrip("\n"), encoding="utf-8")
        env[row.known_as] = str(known)
    # A row with its own time limit is not left to hang for the whole bound past it.
    if row.seconds is not None:
        bound = min(bound, row.seconds + 30)
    return env, subst, bound


def run_row(lang: str, row: Row, folders: Folders, scratch: Path, bound: float) -> Outcome:
    prepared = prepare_row(lang, row, folders, scratch, bound)
    if isinstance(prepared, Outcome):
        return prepared
    env, subst, bound = prepared
    status, output, seconds = run_bounded([str(entry(lang))], env, bound)
    return judge_row(lang, row, subst, bound, status, output, seconds)


def run_batch(lang: str, rows: list[Row], folders: Folders, scratch: Path, bound: float) -> list[Outcome]:
    """Every row in one call of `faults-entry --batch PLAN OUT` (a language in BATCH): PLAN lists each
    row's id, environment and bound; the entry writes OUT/<id>.json with the row's exit status (null
    for a hang), output and seconds, each judged here as a row run on its own."""
    out = scratch / lang / "batch"
    out.mkdir(parents=True, exist_ok=True)
    plan, prepared, done = [], {}, {}
    for row in rows:
        p = prepare_row(lang, row, folders, scratch, bound)
        if isinstance(p, Outcome):
            done[row.id] = p
            continue
        env, subst, row_bound = p
        prepared[row.id] = (subst, row_bound)
        plan.append({"id": row.id, "env": env, "bound": row_bound})
    (out / "plan.json").write_text(json.dumps(plan), encoding="utf-8")
    status, output, _ = run_bounded([str(entry(lang)), "--batch", str(out / "plan.json"), str(out)], dict(os.environ),
                                    min(BUILD_BOUND_S, bound * max(1, len(plan))))
    outcomes = []
    for row in rows:
        if row.id in done:
            outcomes.append(done[row.id])
            continue
        subst, row_bound = prepared[row.id]
        result = out / f"{row.id}.json"
        if result.is_file():
            r = json.loads(result.read_text(encoding="utf-8"))
            outcomes.append(judge_row(lang, row, subst, row_bound, r["status"], r["output"], r["seconds"]))
        else:   # the batch ended (or hung) before this row: what it printed says why
            outcomes.append(judge_row(lang, row, subst, row_bound, None, f"(no result; the batch exited {status})\n"
                                      + output, 0.0))
    return outcomes


def judge_row(lang: str, row: Row, subst: dict, bound: float, status: int | None, output: str,
              seconds: float) -> Outcome:
    verdict, names, _ = expected(row, lang)
    problems = []
    if status is None:
        problems.append(f"no answer within {bound:.0f} s (a hang)")
    elif row.seconds is not None and seconds > row.seconds:
        problems.append(f"took {seconds:.0f} s, more than the row's {row.seconds:g} s")
    elif lang in EXACT:
        if status != STATUS[verdict]:
            problems.append(f"exit {status}, expected {STATUS[verdict]} ({verdict})")
    elif (status == 0) != (verdict == "pass"):
        problems.append(f"exit {status}, expected {'0' if verdict == 'pass' else 'non-zero'} ({verdict})")
    for name in names:
        name = name.format(**subst)
        if name not in output:
            problems.append(f"output does not name {name!r}")
    for name in row.not_names:
        if name.format(**subst) in output:
            problems.append(f"output names {name.format(**subst)!r}, which it must not")
    for name in row.once:
        n = output.count(name.format(**subst))
        if n != 1:
            problems.append(f"output holds {name.format(**subst)!r} {n} times, not once")
    if row.file_line:
        named = subst["known"] if row.known is not None else subst["file"]
        if not re.search(re.escape(named) + r":\d+", output):
            problems.append(f"output does not name {named}:<line>")
    if verdict == "usage" and TRACES[lang].search(output):
        problems.append("a stack trace for a user's mistake")
    return Outcome(lang, row, not problems, "; ".join(problems) or "ok", status, seconds, output)


def build(lang: str) -> str | None:
    status, output, seconds = run_bounded([str(entry(lang)), "--build"], dict(os.environ), BUILD_BOUND_S)
    if status != 0:
        tail = "\n".join(output.splitlines()[-30:])
        return f"{lang}: `faults-entry --build` {'hung' if status is None else f'exited {status}'}\n{tail}"
    print(f"== {lang}: built in {seconds:.0f} s", flush=True)
    return None


def excerpt(o: Outcome, keep: int = 60) -> str:
    """A row's exit status and output, indented; a long output as its first and last `keep` lines (a
    build tool's report around the runner's own lines)."""
    lines = o.output.splitlines()
    if len(lines) > 2 * keep:
        lines = [*lines[:keep], f"... {len(lines) - 2 * keep} lines left out ...", *lines[-keep:]]
    return "\n".join([f"     | (exit status {o.status})", *("     | " + line for line in lines)])


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--lang", default="", help="comma-separated languages (default: every one "
                        "with a faults-entry): " + ", ".join(LANGUAGES))
    parser.add_argument("--row", action="append", default=[], help="row id or glob (repeatable)")
    parser.add_argument("--list", action="store_true", help="list the rows and exit")
    parser.add_argument("--no-build", action="store_true", help="do not call `faults-entry --build`")
    parser.add_argument("--bound", type=float, default=ROW_BOUND_S, help="seconds a row may take")
    parser.add_argument("-v", "--verbose", action="store_true", help="print the output of every row (that of a row that fails is always printed)")
    parser.add_argument("--keep", action="store_true", help="keep the damaged folders")
    parser.add_argument("--cache", type=Path, default=os.environ.get("FAULTS_TABLE_CACHE") or None,
                        metavar="DIR", help="make the damaged folders and the release bundle once for "
                        "every run given the same DIR (runs over one tree, as CI's lanes; default: "
                        "$FAULTS_TABLE_CACHE, else none)")
    return parser


def _chosen_rows(globs: list[str]) -> list[Row]:
    rows = load_table()
    if not globs:
        return rows
    unmatched = [g for g in globs if not any(fnmatch.fnmatchcase(r.id, g) for r in rows)]
    if unmatched:
        raise TableError(f"--row {', '.join(unmatched)} matches no row; rows: " + ", ".join(r.id for r in rows))
    return [r for r in rows if any(fnmatch.fnmatchcase(r.id, g) for g in globs)]


def _chosen_langs(lang: str) -> list[str]:
    if not lang:
        langs = [x for x in LANGUAGES if os.access(entry(x), os.X_OK)]
        if not langs:
            raise TableError("no language has a verifiers/<lang>/faults-entry")
        return langs
    langs = [x.strip() for x in lang.split(",")]
    bad = [x for x in langs if x not in LANGUAGES]
    if bad or not all(langs):
        raise TableError(f"--lang {lang}: known languages: {', '.join(LANGUAGES)}")
    missing = [x for x in langs if not os.access(entry(x), os.X_OK)]
    if missing:
        raise TableError("no executable faults-entry for " + ", ".join(
            f"{x} ({entry(x).relative_to(REPO)})" for x in missing))
    return langs


def main(argv: list[str] | None = None) -> int:
    args = _parser().parse_args(argv)
    try:
        rows = _chosen_rows(args.row)
        if args.list:
            for r in rows:
                print(f"{r.id:34} {r.verdict:6} {r.what}")
            return 0
        langs = _chosen_langs(args.lang)
        try:
            cache = Cache(args.cache) if args.cache else None
        except OSError as e:
            raise TableError(f"--cache {args.cache}: {e.strerror}")
    except TableError as e:
        print(f"run.py: {e}", file=sys.stderr)
        return 2

    failures = 0
    outcomes: list[Outcome] = []
    base = Path(tempfile.mkdtemp(prefix="plcvec-faults-"))
    try:
        folders = Folders(base / "vectors", cache)
        for lang in langs:
            if not args.no_build:
                problem = build(lang)
                if problem:
                    print(problem, file=sys.stderr)
                    failures += len(rows)
                    continue
            try:
                if lang in BATCH:
                    results = run_batch(lang, rows, folders, base / "scratch", args.bound)
                else:
                    results = (run_row(lang, row, folders, base / "scratch", args.bound) for row in rows)
                for o in results:
                    outcomes.append(o)
                    mark = "ok  " if o.ok else "FAIL"
                    print(f"{mark} {lang:10} {o.row.id:34} {o.seconds:5.1f} s  {o.why}", flush=True)
                    if not o.ok:
                        failures += 1
                    # A failing row always shows what the runner printed: a CI log must explain its
                    # own failure, which may not come back on a second run.
                    if not o.ok or args.verbose:
                        print(excerpt(o), flush=True)
            except TableError as e:
                print(f"run.py: {e}", file=sys.stderr)
                return 2
    finally:
        if args.keep:
            print(f"damaged folders kept in {base}")
        else:
            shutil.rmtree(base, ignore_errors=True)
    passed = sum(o.ok for o in outcomes)
    print(f"faults: {passed} passed, {failures} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    try:
        sys.exit(main())
    except BrokenPipeError:  # `run.py --list | head`: the reader has gone, which is no error
        sys.stderr.close()
        sys.exit(0)
