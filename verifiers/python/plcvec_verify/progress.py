"""A progress bar on a terminal, nothing anywhere else (CI logs stay clean)."""
from __future__ import annotations

import time

WIDTH = 30
EVERY_S = 0.1      # redraw at most this often: drawing per vector would cost more than the vector


class Progress:
    def __init__(self, stream):
        self.stream = stream
        self.last = 0.0
        self.drawn = False

    @classmethod
    def for_stream(cls, stream):
        return cls(stream) if hasattr(stream, "isatty") and stream.isatty() else None

    def __call__(self, done: int, total: int, failed: int):
        now = time.monotonic()
        if now - self.last < EVERY_S and done < total:
            return
        self.last = now
        filled = WIDTH * done // max(total, 1)
        self.stream.write(f"\r[{'#' * filled}{'.' * (WIDTH - filled)}] {done}/{total} vectors, {failed} failing ")
        self.stream.flush()
        self.drawn = True

    def done(self):
        if self.drawn:
            self.stream.write("\r" + " " * (WIDTH + 40) + "\r")
            self.stream.flush()
