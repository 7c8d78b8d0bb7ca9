"""Hostile implementations for the shared table of faults (verifiers/parity/faults.toml): the
reference implementation with one misbehaviour, served over the stdio protocol.

    PLCVEC_HOSTILE=<name> PLCVEC_HOSTILE_ON=<vector id> python3 verifiers/python/hostile.py

Each misbehaves on the vector PLCVEC_HOSTILE_ON only (`supports-nothing`, `skips-everything`,
`bad-choice` and `cpu-writes` on every vector as well) and answers as the reference everywhere else.
The names are those of verifiers/parity/README.md; `verifiers/python/faults-entry` runs
`plcvec verify` against this process.
"""
from __future__ import annotations

import json
import os
import signal
import subprocess
import sys

from plcvec_reference.adapter import ReferenceAdapter
from plcvec_verify.serve import serve

NAMES = ("reference", "wrong-result", "panic", "loop-forever", "empty-answer", "stray-write", "duplicate-write",
         "wrong-type", "out-of-range", "exit-zero", "exit-nonzero", "crash", "mutates-request",
         "supports-nothing", "skips-everything", "bad-choice", "cpu-writes", "word-65536", "not-a-number",
         "closes-fds", "child-holds-stdout", "follows-alternative")


def _first(devices: dict, kind) -> str:
    """The first device (by name) holding a value of `kind` (bool: a bit; int: a word)."""
    return next(d for d in sorted(devices) if type(devices[d]) is kind)


class Hostile(ReferenceAdapter):
    def __init__(self, name: str, on: str, choice: str = ""):
        super().__init__()
        self.hostile, self.on = name, on
        if name == "follows-alternative":
            # Follows the alternative in what it answers, but its hello declares the defaults.
            interp, _, alt = choice.partition("=")
            self.followed = {interp: alt}
        if name == "cpu-writes":
            self.cpu_writes = ["SM56", "SD1", "SD0"]

    def hello(self, request):
        answer = super().hello(request)
        if self.hostile == "follows-alternative":
            self.choices = self.followed
        if self.hostile == "supports-nothing":
            answer["instructions"] = []
        elif self.hostile == "bad-choice":
            answer["interpretations"]["NO-SUCH-INTERPRETATION"] = "x"
        return answer

    def run(self, request):
        name, target = self.hostile, request["id"] == self.on
        if name == "skips-everything":
            return {"skip": "this implementation skips every vector"}
        if target and name == "panic":
            raise RuntimeError("the implementation failed on purpose")
        if target and name == "loop-forever":
            while True:
                pass
        if target and name in ("exit-zero", "exit-nonzero"):
            sys.stdout.flush()
            os._exit(0 if name == "exit-zero" else 3)
        if target and name == "crash":
            sys.stdout.flush()
            os.kill(os.getpid(), signal.SIGSEGV)
        if target and name == "closes-fds":
            os.closerange(3, 1024)
            name = "wrong-result"
        if target and name == "child-holds-stdout":
            # A process that inherits stdout and stderr and outlives the answer by far.
            subprocess.Popen(["sleep", "300"], stdin=subprocess.DEVNULL)
        initial = request["initial"]["devices"]
        answer = super().run(request)
        steps = answer["steps"]
        if name == "cpu-writes":
            for step in steps:
                step["devices"].update({"SM56": True, "SD1": 1})
                if target:
                    step["devices"]["SD0"] = 1
        if not target:
            return answer
        if name == "wrong-result":
            step = steps[0]
            if "result" in step:
                step["result"] = not step["result"]
            else:
                written = [d for d in sorted(step["devices"]) if type(step["devices"][d]) is int
                           and step["devices"][d] != initial.get(d)] or [_first(step["devices"], int)]
                step["devices"][written[0]] = (step["devices"][written[0]] + 1) % 65536
        elif name == "empty-answer":
            answer["steps"] = []
        elif name == "stray-write":
            for step in steps:
                step["devices"]["D7777"] = 1
        elif name == "wrong-type":
            steps[0]["devices"][_first(steps[0]["devices"], bool)] = 1
        elif name == "out-of-range":
            steps[0]["devices"][_first(steps[0]["devices"], int)] = 70000
        elif name == "word-65536":
            steps[0]["devices"][_first(steps[0]["devices"], int)] = 65536
        elif name == "not-a-number":
            steps[0]["devices"][_first(steps[0]["devices"], int)] = float("nan")
        elif name == "mutates-request":
            request["initial"]["devices"].clear()
            request["steps"].clear()
        return answer


class RepeatingOut:
    """stdout that repeats one device key of the target's result with another value: what a JSON
    object cannot hold, a Python dict cannot answer, so it is done to the bytes."""

    def __init__(self, out, on: str):
        self.out, self.marker = out, b'"id":' + json.dumps(on, separators=(",", ":")).encode()

    def write(self, data: bytes):
        if self.marker in data:
            start = data.index(b'"devices":{') + len(b'"devices":{')
            key_end = data.index(b'":', start) + 2
            data = data[:start] + data[start:key_end] + b'12345,' + data[start:]
        return self.out.write(data)

    def flush(self):
        self.out.flush()


def main() -> int:
    name, on = os.environ.get("PLCVEC_HOSTILE") or "reference", os.environ.get("PLCVEC_HOSTILE_ON", "")
    if name not in NAMES:
        print(f"hostile.py: PLCVEC_HOSTILE={name}: no such hostile implementation; known: {', '.join(NAMES)}",
              file=sys.stderr)
        return 2
    out = RepeatingOut(sys.stdout.buffer, on) if name == "duplicate-write" else None
    return serve(Hostile(name, on, os.environ.get("PLCVEC_HOSTILE_CHOICE", "")), stdout=out)


if __name__ == "__main__":
    sys.exit(main())
