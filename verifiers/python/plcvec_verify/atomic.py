"""Replacing a report file whole: a CI dashboard reads the old report or the new one, never half.

The generator has the same writer (generator/plcvec/output/atomic.py); the verifier keeps its own
because it imports nothing from the generator and must be usable with the vector files alone.
"""
from __future__ import annotations

import os
import tempfile
from pathlib import Path


def write_atomic(path, text: str) -> None:
    """Write `text` to `path` through a temporary file in the same folder, then rename it.

    mkstemp creates the file with mode 0600 whatever the umask, which would leave a report
    unreadable to a CI uploader running as another user; the file gets the mode an ordinary
    `open(path, "w")` would give it (0666 less the umask) before it takes the report's name.
    """
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as f:
            f.write(text)
            f.flush()
            os.fsync(f.fileno())
        os.chmod(tmp, 0o666 & ~current_umask())
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise


def current_umask() -> int:
    """The process umask. Reading it means setting it; set it straight back."""
    mask = os.umask(0o022)
    os.umask(mask)
    return mask
