"""The Python rows of the shared table of faults in one call: `faults-entry --batch PLAN OUT`
(verifiers/parity/README.md), run from the repository root.

Each row is still `python3 -m plcvec verify` in a process of its own, with the row's environment, its
own session, its output in a file and its exit status as the interpreter would give it: the process
is forked from this one after the modules `plcvec verify` imports have been imported once, instead
of a new interpreter importing them again for every row. Nothing else is done before the fork: the
row's process reads its environment, builds its parser, loads its vectors and starts its adapter
(the hostile implementation, always a process of its own) as a run of the row alone does.

A row that pytest runs (PLCVEC_FILTER) runs the one-row entry itself, in the forked process.
"""
from __future__ import annotations

import atexit
import importlib
import json
import os
import pkgutil
import runpy
import select
import shlex
import signal
import sys
import time
import traceback
from pathlib import Path

ROOT = Path.cwd()
ENTRY = ROOT / "verifiers" / "python" / "faults-entry"


def preload() -> None:
    """Import what `python3 -m plcvec verify` imports: the command line with every command's module,
    and the runner's modules (not its pytest plugin, which only pytest loads)."""
    import plcvec.cli
    import plcvec_verify

    for name in plcvec.cli._STAGE_COMMANDS:
        importlib.import_module(name)
    for info in pkgutil.iter_modules(plcvec_verify.__path__, "plcvec_verify."):
        if info.name not in ("plcvec_verify.pytest_plugin", "plcvec_verify.__main__"):
            importlib.import_module(info.name)


def exit_status(code) -> int:
    """The exit status the interpreter gives for `sys.exit(code)`."""
    if code is None:
        return 0
    if isinstance(code, int):
        return code & 0xFF
    print(code, file=sys.stderr)
    return 1


def run_row(row_env: dict, env: dict, output: Path, adapter: str) -> None:
    """In the forked process: become the row's `python3 -m plcvec verify`, then end with its status."""
    os.setsid()   # a session of its own, as run.py gives a row: its group is killed at the bound
    fd = os.open(output, os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o644)
    os.dup2(fd, 1)
    os.dup2(fd, 2)
    os.close(fd)
    null = os.open(os.devnull, os.O_RDONLY)
    os.dup2(null, 0)
    os.close(null)
    os.environ.clear()
    os.environ.update(env)
    if env.get("PLCVEC_FILTER"):
        os.execve(str(ENTRY), [str(ENTRY)], row_env)
    sys.argv = ["-m", "verify", "--adapter", adapter, "--no-progress"]
    try:
        runpy.run_module("plcvec", run_name="__main__", alter_sys=True)
        status = 0
    except SystemExit as exc:
        status = exit_status(exc.code)
    except BaseException:   # what the interpreter does with an exception nothing caught
        traceback.print_exc()
        status = 1
    status = finish(status)
    os._exit(status)


def finish(status: int) -> int:
    """The interpreter's own end: wait for the threads, run the atexit functions, flush the streams
    (a flush that fails gives 120)."""
    threading = sys.modules.get("threading")
    if threading is not None:
        threading._shutdown()
    atexit._run_exitfuncs()
    for stream in (sys.stdout, sys.stderr):
        try:
            stream.flush()
        except Exception:
            status = 120
    return status


def wait_bounded(pid: int, bound: float) -> int | None:
    """The row's exit status, or None when it is still running at the bound (its group is killed)."""
    pidfd = os.pidfd_open(pid)
    try:
        ready, _, _ = select.select([pidfd], [], [], bound)
    finally:
        os.close(pidfd)
    if not ready:
        kill_group(pid)
        os.waitpid(pid, 0)
        return None
    _, wait = os.waitpid(pid, 0)
    return os.waitstatus_to_exitcode(wait)   # as subprocess gives it: -N for a signal N


def kill_group(pid: int) -> None:
    try:
        os.killpg(pid, signal.SIGKILL)
    except ProcessLookupError:
        pass


def main(plan_path: str, out: str) -> int:
    sys.path[0] = str(ROOT)   # as `python3 -m` has it: the working folder first, not this file's
    preload()
    # Quoted as plcvec verify splits it (shlex): the checkout's path may hold a space.
    adapter = shlex.join([os.environ.get("PYTHON", "python3"), str(ROOT / "verifiers" / "python" / "hostile.py")])
    out_dir = Path(out)
    for row in json.loads(Path(plan_path).read_text(encoding="utf-8")):
        env = dict(row["env"], PYTHONPATH=os.environ["PYTHONPATH"])   # what the one-row entry exports
        output = out_dir / f"{row['id']}.out"
        sys.stdout.flush()
        sys.stderr.flush()
        started = time.monotonic()
        pid = os.fork()
        if pid == 0:
            try:
                run_row(row["env"], env, output, adapter)
            finally:
                os._exit(70)   # never back into the batch's loop
        status = wait_bounded(pid, row["bound"])
        seconds = time.monotonic() - started
        kill_group(pid)   # anything the row left behind
        text = output.read_bytes().decode("utf-8", "replace")
        output.unlink()
        result = {"status": status, "output": text, "seconds": seconds}
        (out_dir / f"{row['id']}.json").write_text(json.dumps(result), encoding="utf-8")
    return 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:]))
