"""Adapters: how the runner reaches an implementation.

`InProcess` drives an object in this process (the interface it provides is implementation.py's);
`stdio.StdioAdapter` drives a process that speaks the same messages as JSON lines (PROTOCOL.md).
Both hand the runner the same `Answer`s.
"""
from __future__ import annotations

import importlib
import json
import os
import signal
import sys
import threading
import traceback
from pathlib import Path
from typing import NamedTuple

from .errors import VerifyError
from .implementation import Implementation
from .protocol import PROTOCOL_VERSION, message_errors


class Answer(NamedTuple):
    """What came back for one vector: a result message (not yet validated), or a fault of the adapter's.

    `bare` says `message` is an in-process adapter's return value: the result message without its
    `type` and `id`, which the runner adds only when it has to look closer (see runner.run).
    """

    id: str
    message: dict | None
    fault: str | None = None
    bare: bool = False



def result_message(answer) -> dict | None:
    """The result message of an answer, with `type` and `id`, whichever kind of adapter answered.

    `answers()` yields 4-tuples (id, message, fault, bare): an `Answer`, or for an in-process
    adapter's usual answer a plain tuple of the same fields (made once per vector of every run, a
    plain tuple costs a fraction of a named one). Unpack them, or read them through this.
    """
    vid, message, _, bare = answer
    return dict(message, type="result", id=vid) if bare else message


class AdapterAbort(VerifyError):
    """The adapter cannot be driven any further (handshake failed, kept crashing)."""


# Handshake answers already found valid, as canonical JSON: the schema walk costs about a
# millisecond, which a repeated in-process run (the pytest plugin, a benchmark) would pay each time.
_VALID_HELLOS: dict[str, None] = {}


def check_hello(answer, source: str) -> dict:
    try:
        text = json.dumps(answer, sort_keys=True)   # JSON tells true from 1 and 1.0 from 1
    except (TypeError, ValueError):
        text = None
    if text is not None and text in _VALID_HELLOS:
        return answer
    errors = message_errors("hello-response", answer)
    if errors:
        if isinstance(answer, dict) and answer.get("type") == "fatal":
            raise AdapterAbort(f"{source} refused the handshake: {answer.get('message')}")
        raise AdapterAbort(f"{source}: the handshake answer does not match hello-response.schema.json:\n  "
                           + "\n  ".join(errors))
    if answer["protocol"] != PROTOCOL_VERSION:
        raise AdapterAbort(f"{source} speaks protocol {answer['protocol']}; this runner speaks {PROTOCOL_VERSION}")
    if text is not None:
        if len(_VALID_HELLOS) >= 64:
            _VALID_HELLOS.pop(next(iter(_VALID_HELLOS)))
        _VALID_HELLOS[text] = None
    return answer


class InProcess:
    """Drive a Python adapter object in this process."""

    def __init__(self, adapter: Implementation, label: str | None = None, timeout: float | None = None):
        self.adapter = adapter
        self.label = label or type(adapter).__name__
        self.notes: list[tuple[str | None, str]] = []
        # The bound on one vector (seconds), kept by a timer in the main thread; None: no bound.
        self.timeout = timeout
        self._running = 0        # how many vectors have been started: the watchdog's sign of progress

    def hello(self, request: dict) -> dict:
        try:
            body = self.adapter.hello(request)
        except Exception as exc:
            raise AdapterAbort(f"{self.label}.hello() raised {type(exc).__name__}: {exc}")
        answer = {"type": "hello", "protocol": PROTOCOL_VERSION}
        answer.update(body or {})
        # An object may declare the devices its CPU writes on its own as an attribute instead.
        cpu_writes = getattr(self.adapter, "cpu_writes", None)
        if cpu_writes is not None and "cpu_writes" not in answer:
            answer["cpu_writes"] = list(cpu_writes)
        return check_hello(answer, self.label)

    def answers(self, requests, wire=None):
        with _Watchdog(self):
            yield from self._answers(requests)

    def _answers(self, requests):
        run = self.adapter.run
        for request in requests:
            vid = request["id"]
            self._running += 1
            try:
                body = run(request)
            except VectorTimeout:
                yield Answer(vid, None, f"{self.label}.run() gave no answer within {self.timeout:g} s (timeout; "
                                        f"PLCVEC_TIMEOUT or --timeout sets the bound) (while running {vid})")
                continue
            except Exception as exc:
                tb = traceback.extract_tb(exc.__traceback__)[-1]
                yield Answer(vid, None, f"{self.label}.run() raised {type(exc).__name__}: {exc} "
                                        f"({Path(tb.filename).name}:{tb.lineno})")
                continue
            if type(body) is not dict:
                yield Answer(vid, None, f"{self.label}.run() returned {type(body).__name__}, not a dict")
                continue
            yield vid, body, None, True     # an Answer's fields as a plain tuple: see result_message

    def close(self):
        close = getattr(self.adapter, "close", None)
        if close:
            close()


class VectorTimeout(BaseException):
    """Raised inside an adapter object's run() that outlived its bound. A BaseException, so that the
    adapter's own `except Exception` does not swallow it."""


class _Watchdog:
    """A per-vector bound on an adapter object, at no cost per vector but a counter: a timer in the main
    thread ticks every quarter of the bound and raises VectorTimeout in run() when no vector has
    started for a whole bound (so the bound is kept within a quarter). Elsewhere than the main thread
    (no signals there) there is no bound."""

    def __init__(self, owner: InProcess):
        self.owner, self.armed = owner, False

    def __enter__(self):
        owner = self.owner
        if not owner.timeout or threading.current_thread() is not threading.main_thread() \
                or not hasattr(signal, "setitimer"):
            return self
        tick = owner.timeout / 4
        state = {"seen": -1, "ticks": 0}

        def on_tick(signum, frame):
            if owner._running != state["seen"]:
                state["seen"], state["ticks"] = owner._running, 0
                return
            state["ticks"] += 1
            if state["ticks"] >= 4:
                state["ticks"] = 0
                raise VectorTimeout()

        self.previous = signal.signal(signal.SIGALRM, on_tick)
        signal.setitimer(signal.ITIMER_REAL, tick, tick)
        self.armed = True
        return self

    def __exit__(self, *exc):
        if self.armed:
            signal.setitimer(signal.ITIMER_REAL, 0)
            signal.signal(signal.SIGALRM, self.previous)
        return False


def load_python_adapter(spec: str, args=()):
    """`module:Class` (or `path/to/file.py:Class`) -> an instance, built with `args` as strings."""
    if ":" not in spec:
        raise VerifyError(f"--python takes MODULE:CLASS (e.g. plcvec_reference.adapter:ReferenceAdapter), got {spec!r}")
    module_name, _, attr = spec.rpartition(":")
    try:
        if module_name.endswith(".py"):
            path = Path(module_name).resolve()
            if not path.exists():
                raise VerifyError(f"--python {spec}: no such file {path}")
            sys.path.insert(0, str(path.parent))
            module_name = path.stem
        elif os.getcwd() not in sys.path and "" not in sys.path:
            # The current folder, as `python -m` has it: the `plcvec` command's own folder is on the path
            # instead, so a module beside the user would not be found.
            sys.path.insert(0, os.getcwd())
        module = importlib.import_module(module_name)
    except VerifyError:
        raise
    except ImportError as exc:
        raise VerifyError(f"--python {spec}: cannot import {module_name}: {exc}; the forms are MODULE:CLASS (a "
                          f"module importable here or in the current folder, {os.getcwd()}) and "
                          "path/to/file.py:CLASS")
    except Exception as exc:
        raise VerifyError(f"--python {spec}: importing {module_name} raised {type(exc).__name__}: {exc}")
    factory = getattr(module, attr, None)
    if factory is None:
        raise VerifyError(f"--python {spec}: {module_name} has no {attr}")
    try:
        return factory(*args)
    except Exception as exc:
        raise VerifyError(f"--python {spec}: {attr}({', '.join(map(repr, args))}) raised {type(exc).__name__}: {exc}")
