"""The adapter side of the protocol, for Python implementations.

An implementation written in Python exposes an adapter object (see adapters.py: `hello` and
`run`) and calls `serve(adapter)` from its `__main__`; it is then verifiable both in process
(`plcvec verify --python module:Class`) and as a process (`plcvec verify --adapter "python -m ..."`).
Implementations in other languages write the same loop themselves; PROTOCOL.md shows it.
"""
from __future__ import annotations

import json
import sys
import traceback

from .protocol import PROTOCOL_VERSION, encode


def serve(adapter, stdin=None, stdout=None) -> int:
    """Answer the runner on stdin/stdout until `bye` or end of input. Returns the exit status."""
    stdin = stdin or sys.stdin.buffer
    stdout = stdout or sys.stdout.buffer
    for line in stdin:
        if not line.strip():
            continue
        msg = json.loads(line)
        kind = msg.get("type")
        if kind == "hello":
            if msg.get("protocol") != PROTOCOL_VERSION:
                stdout.write(encode({"type": "fatal", "message": f"this adapter speaks protocol {PROTOCOL_VERSION}, "
                                                                  f"not {msg.get('protocol')}"}))
                stdout.flush()
                return 1
            answer = {"type": "hello", "protocol": PROTOCOL_VERSION}
            answer.update(adapter.hello(msg))
            # Devices the CPU writes on its own, declared as an attribute (adapters.InProcess does the same).
            if getattr(adapter, "cpu_writes", None) is not None and "cpu_writes" not in answer:
                answer["cpu_writes"] = list(adapter.cpu_writes)
            stdout.write(encode(answer))
            stdout.flush()
        elif kind == "run":
            write = stdout.write
            for request in msg["vectors"]:
                result = {"type": "result", "id": request["id"]}
                try:
                    result.update(adapter.run(request))
                except Exception as exc:  # the implementation's failure on this vector, not the loop's
                    result["error"] = _describe(exc)
                write(encode(result))
            # One flush per batch: a write per result would cost more than the result. If the
            # implementation dies mid-batch, the runner re-runs the unanswered vectors one at a
            # time to find the one that killed it (stdio.py).
            stdout.flush()
        elif kind == "bye":
            return 0
    return 0


def _describe(exc: BaseException) -> str:
    frame = traceback.extract_tb(exc.__traceback__)[-1] if exc.__traceback__ else None
    where = f" ({frame.filename.rsplit('/', 1)[-1]}:{frame.lineno})" if frame else ""
    return f"{type(exc).__name__}: {exc}{where}"
