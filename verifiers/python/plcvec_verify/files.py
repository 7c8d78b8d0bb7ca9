"""Reading the files a run trusts: only regular files, and JSON with no key given twice.

A named pipe nobody writes, a device that never ends (/dev/zero) or a loop of symbolic links where
a vector file belongs would hang a loader that opens it without looking, so a path is looked at
first and refused by name (CONTRACT.md, "Loading"). A JSON object holding one key twice is refused
too: parsers in other languages disagree on which value wins, so the six runners could judge one
file six ways.
"""
from __future__ import annotations

import errno
import json
import os
import stat
from pathlib import Path

from .errors import VerifyError

_KINDS = ((stat.S_ISFIFO, "a named pipe"), (stat.S_ISCHR, "a character device"), (stat.S_ISBLK, "a block device"),
          (stat.S_ISSOCK, "a socket"), (stat.S_ISDIR, "a folder"))


def not_regular(path) -> str:
    """'' when `path` is a regular file (or nothing is there), else why it is not one (the message
    of CONTRACT.md without the path)."""
    try:
        mode = os.stat(path).st_mode
    except FileNotFoundError:
        return ""
    except OSError as exc:
        if exc.errno == errno.ELOOP:
            return "a loop of symbolic links"
        return ""                        # let the open say what it is
    for test, kind in _KINDS:
        if test(mode):
            return f"not a regular file ({kind})"
    return "" if stat.S_ISREG(mode) else "not a regular file"


def check_regular(path) -> None:
    """Refuse `path` by name when something other than a regular file is there."""
    why = not_regular(path)
    if why:
        raise VerifyError(f"{path}: {why}")


def read_bytes(path: Path) -> bytes:
    """The bytes of a regular file, refused by name when it is anything else or cannot be read. The
    file is opened without blocking and looked at again, in case it was swapped after the look."""
    check_regular(path)
    try:
        fd = os.open(path, os.O_RDONLY | os.O_NONBLOCK)
    except FileNotFoundError:
        raise VerifyError(f"{path}: no such file")
    except OSError as exc:
        if exc.errno == errno.ELOOP:
            raise VerifyError(f"{path}: a loop of symbolic links")
        raise VerifyError(f"{path}: {exc.strerror}")
    with os.fdopen(fd, "rb") as f:
        if not stat.S_ISREG(os.fstat(fd).st_mode):
            raise VerifyError(f"{path}: not a regular file")
        return f.read()


def read_text(path: Path) -> str:
    raw = read_bytes(path)
    try:
        return raw.decode("utf-8")
    except UnicodeDecodeError as exc:
        line = raw[:exc.start].count(b"\n") + 1
        raise VerifyError(f"{path}:{line}: not UTF-8 text (byte {exc.start})")


# --- repeated keys --------------------------------------------------------------------------------

class _Repeated(Exception):
    pass


def _unique_pairs(pairs):
    d = dict(pairs)
    if len(d) != len(pairs):
        raise _Repeated()
    return d


def has_repeated_key(text: str) -> bool:
    """Whether some object of the JSON `text` (valid JSON) holds one key twice."""
    try:
        json.loads(text, object_pairs_hook=_unique_pairs)
    except _Repeated:
        return True
    return False


def repeated_key(text: str) -> tuple[int, str, list] | None:
    """(line, key, path) of the first key that repeats one of its object's earlier keys in the JSON
    `text`, in text order; `path` the keys and indexes leading to that object. None when none does.
    A small scanner of its own, run only on a text already known to hold a repeat (json gives no
    positions)."""
    line, i, n = 1, 0, len(text)
    # One frame per open container: [kind, keys seen (objects), the key or index of the value now read].
    stack: list[list] = []
    want_key = False
    while i < n:
        c = text[i]
        if c == "\n":
            line += 1
        elif c == "{":
            stack.append(["{", set(), None])
            want_key = True
        elif c == "[":
            stack.append(["[", None, 0])
        elif c in "}]":
            stack.pop()
            want_key = False
        elif c == "," and stack:
            if stack[-1][0] == "[":
                stack[-1][2] += 1
            else:
                want_key = True
        elif c == '"':
            j = i + 1
            while text[j] != '"':
                j += 2 if text[j] == "\\" else 1
            if want_key and stack and stack[-1][0] == "{":
                key = json.loads(text[i:j + 1])
                if key in stack[-1][1]:
                    return line, key, [frame[2] for frame in stack[:-1]]
                stack[-1][1].add(key)
                stack[-1][2] = key
                want_key = False
            line += text.count("\n", i, j)
            i = j
        i += 1
    return None


def repeated_key_message(where: str, text: str, line_offset: int = 0, vector_of=None) -> str:
    """`<where>:<line>: [vector <id>: ]repeated key "<key>"` for the first repeat in `text`.
    `vector_of(path)` names the vector the repeat is inside, or returns None."""
    found = repeated_key(text)
    if found is None:
        return f"{where}: repeated key"
    line, key, path = found
    vector = vector_of(path) if vector_of else None
    return (f"{where}:{line + line_offset}: " + (f"vector {vector}: " if vector else "")
            + f"repeated key {json.dumps(key, ensure_ascii=False)}")


__all__ = ["check_regular", "not_regular", "read_bytes", "read_text", "has_repeated_key", "repeated_key",
           "repeated_key_message"]
