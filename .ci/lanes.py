"""Run CI's independent lanes side by side, as many at a time as `--jobs` says.

Usage: python3 .ci/lanes.py [--jobs N] [--fill M] [--timeout SECONDS] SCRIPT [SCRIPT ...]

Each lane is a bash script (`.ci/lang/<lang>.sh`, `.ci/python-lane.sh`) that builds and checks one
part of the project on its own files. A lane's output goes to `build/lanes/<name>.log` while it
runs and is printed whole when it ends, so the CI log reads lane by lane instead of interleaved.
Every lane runs to its end even when another fails (one red run names every failing lane), and a
lane that outlives `--timeout` is killed with its whole process group: no wait without a bound.
The last lines are a table of each lane's status, seconds and CPU seconds, the figures to compare
when CI's time is measured, then the steps that took the most CPU (from the step lines of
.ci/steps.sh in the lanes' logs): on two cores CI's time is bound by CPU, so that table says where a
saving could come from. Exit status: 0 when every lane passed, 1 otherwise.

Why lanes: this machine has two cores, and a lane spends part of its time waiting (downloads,
Maven's and npm's start-up, linking), so two lanes at once finish sooner than one after the other.
Lanes start in the order given (CI's puts last the lane that spreads over every core, so the tail
is not one single-core lane alone). Lanes still leave cores idle now and then (a download, a link,
a test sitting out a timeout): with `--fill M`, up to M lanes more than `--jobs` are started while
the machine has been idle by at least FILL_IDLE_CORES over the last FILL_WINDOW_S seconds (read
from /proc/stat; elsewhere nothing is filled).
"""
from __future__ import annotations

import argparse
import os
import re
import signal
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
LOGS = ROOT / "build" / "lanes"
# An extra lane is started once the cores have been this idle, on average, over this many seconds
# since the last lane started (one start per window: a lane's own start-up is idle time too).
FILL_IDLE_CORES = 0.6
FILL_WINDOW_S = 15.0
# The steps listed at the end, the most CPU first.
TOP_STEPS = 12
# A step's line as .ci/steps.sh prints it when the step begins: the lane's seconds and CPU seconds
# so far (the CPU is absent where there is no /proc). The step's text may hold parentheses itself.
STEP_LINE = re.compile(r"^-- [^:\n]+: (?P<what>.*) \((?P<seconds>\d+) s, (?P<cpu>\d+(?:\.\d+)?) CPU s\)$")


class IdleMeter:
    """The machine's idle cores on average since the last reset, from /proc/stat (Linux)."""

    def __init__(self):
        self.cores = os.cpu_count() or 1
        self.reset()

    @staticmethod
    def _read():
        try:
            with open("/proc/stat", encoding="ascii") as stat:
                fields = [int(x) for x in stat.readline().split()[1:]]
        except (OSError, ValueError):
            return None
        return fields[3] + fields[4], sum(fields[:8])   # idle + iowait, all but guest time

    def reset(self):
        self.since, self.first = time.monotonic(), self._read()

    def idle_cores(self):
        """(idle cores on average, seconds) since the last reset; (0, 0) where it cannot be read."""
        now = self._read()
        if now is None or self.first is None or now[1] == self.first[1]:
            return 0.0, 0.0
        return (now[0] - self.first[0]) / (now[1] - self.first[1]) * self.cores, time.monotonic() - self.since


class Lane:
    def __init__(self, script: str):
        self.script = script
        self.name = Path(script).stem.removesuffix("-lane")
        self.log = LOGS / f"{self.name}.log"
        self.proc: subprocess.Popen | None = None
        self.started = 0.0
        self.seconds = 0.0
        # CPU seconds (user + system) of the lane and every process it waited for: on two cores,
        # the sum over lanes is what bounds CI's time, more than any lane's wall time.
        self.cpu = 0.0
        self.status = "waiting"

    def start(self) -> None:
        self.started = time.monotonic()
        with open(self.log, "wb") as out:
            # A process group of its own, so a timeout ends the lane's children (Maven, cargo) too.
            self.proc = subprocess.Popen(["bash", self.script], cwd=ROOT, stdout=out,
                                         stderr=subprocess.STDOUT, start_new_session=True)
        self.status = "running"

    def poll(self, timeout: float) -> bool:
        """True once the lane has ended (on its own, or killed for outliving `timeout`)."""
        assert self.proc is not None
        # wait4, not Popen.poll: it also gives the lane's resource usage.
        pid, status, usage = os.wait4(self.proc.pid, os.WNOHANG)
        elapsed = time.monotonic() - self.started
        if pid == 0 and elapsed > timeout:
            os.killpg(self.proc.pid, signal.SIGKILL)
            _, status, usage = os.wait4(self.proc.pid, 0)
            self.status = f"killed after {timeout:.0f} s"
        elif pid == 0:
            return False
        else:
            code = os.waitstatus_to_exitcode(status)
            self.status = "ok" if code == 0 else f"failed (exit {code})"
        self.proc.returncode = os.waitstatus_to_exitcode(status)
        self.seconds = elapsed
        self.cpu = usage.ru_utime + usage.ru_stime
        return True


def steps_of(lane: Lane) -> list[tuple[float, float, str]]:
    """(CPU seconds, seconds, "lane: step") for each step of an ended lane: from its line to the next
    step's, the last to the lane's end; a lane that marks no step is one step."""
    marks = []
    for line in lane.log.read_text(encoding="utf-8", errors="replace").splitlines():
        found = STEP_LINE.match(line)
        if found:
            marks.append((found["what"], int(found["seconds"]), float(found["cpu"])))
    if not marks:
        return [(lane.cpu, lane.seconds, f"{lane.name}: the whole lane (it marks no steps)")]
    ends = [(seconds, cpu) for _, seconds, cpu in marks[1:]] + [(lane.seconds, lane.cpu)]
    return [(max(0.0, end_cpu - cpu), max(0.0, end_s - seconds), f"{lane.name}: {what}")
            for (what, seconds, cpu), (end_s, end_cpu) in zip(marks, ends)]


def print_steps(lanes: list[Lane]) -> None:
    steps = sorted((step for lane in lanes for step in steps_of(lane)), key=lambda step: -step[0])
    if not steps:
        return
    print(f"lanes: the {min(TOP_STEPS, len(steps))} steps that took the most CPU, of {len(steps)} "
          f"(a step's CPU is that of what its lane ran from its line to the next)")
    for cpu, seconds, what in steps[:TOP_STEPS]:
        print(f"  {cpu:7.1f} s of CPU {seconds:5.0f} s  {what}")
    rest = steps[TOP_STEPS:]
    if rest:
        print(f"  {sum(cpu for cpu, _, _ in rest):7.1f} s of CPU in the other {len(rest)} steps")


def _may_fill(idle: IdleMeter, running: int, args) -> bool:
    """Whether one lane more than --jobs may start now: room under --fill, and the cores idle enough
    over a whole window since the last start."""
    if running >= args.jobs + args.fill:
        return False
    cores, seconds = idle.idle_cores()
    if seconds < FILL_WINDOW_S:
        return False
    if cores < FILL_IDLE_CORES:
        idle.reset()   # a new window: the idle time of an hour ago says nothing of now
        return False
    return True


def _stop(signum, frame):
    """SIGTERM (CI's run ended from outside): the same as Ctrl-C, so that the lanes' process groups,
    sessions of their own, are ended too."""
    raise KeyboardInterrupt


def main(argv: list[str]) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--jobs", type=int, default=2, help="lanes at once (default 2)")
    parser.add_argument("--fill", type=int, default=0,
                        help="lanes more than --jobs started while cores are idle (default 0)")
    parser.add_argument("--timeout", type=float, default=2400, help="seconds a lane may take (default 2400)")
    parser.add_argument("scripts", nargs="+")
    args = parser.parse_args(argv)
    missing = [s for s in args.scripts if not (ROOT / s).is_file()]
    if missing:
        print(f"lanes: no such script: {', '.join(missing)}", file=sys.stderr)
        return 2
    LOGS.mkdir(parents=True, exist_ok=True)
    waiting = [Lane(s) for s in args.scripts]
    lanes = list(waiting)
    running: list[Lane] = []
    began = time.monotonic()
    idle = IdleMeter()
    try:
        while waiting or running:
            while waiting and (len(running) < args.jobs or _may_fill(idle, len(running), args)):
                lane = waiting.pop(0)
                print(f"-- lane {lane.name}: started{'' if len(running) < args.jobs else ' (cores idle)'}",
                      flush=True)
                lane.start()
                running.append(lane)
                idle.reset()
            time.sleep(0.5)
            for lane in [lane for lane in running if lane.poll(args.timeout)]:
                running.remove(lane)
                print(f"== lane {lane.name}: {lane.status} in {lane.seconds:.0f} s "
                      f"({lane.cpu:.0f} s of CPU)", flush=True)
                sys.stdout.buffer.write(lane.log.read_bytes())
                print(f"== end of lane {lane.name}", flush=True)
    finally:
        # Ctrl-C or an error here: the lanes run in sessions of their own, so end them by hand.
        for lane in running:
            os.killpg(lane.proc.pid, signal.SIGKILL)
    print(f"lanes: {len(lanes)} in {time.monotonic() - began:.0f} s with {args.jobs} at a time"
          f"{f' (up to {args.jobs + args.fill} while cores were idle)' if args.fill else ''}, "
          f"{sum(lane.cpu for lane in lanes):.0f} s of CPU")
    for lane in lanes:
        print(f"  {lane.name:<12} {lane.status:<24} {lane.seconds:7.0f} s {lane.cpu:7.0f} s of CPU")
    print_steps([lane for lane in lanes if lane.status != "waiting"])
    return 0 if all(lane.status == "ok" for lane in lanes) else 1


if __name__ == "__main__":
    signal.signal(signal.SIGTERM, _stop)
    try:
        sys.exit(main(sys.argv[1:]))
    except KeyboardInterrupt:
        sys.exit(130)
