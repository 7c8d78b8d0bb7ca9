"""An adapter that starts a child process, answers the first vector, then hangs: for the tests
that stop a running `plcvec verify` and look for processes left behind.

    python3 spawner.py PIDFILE

Writes "<its pid> <its child's pid>" to PIDFILE once both run, and "answered" on a second line
once the first answer is flushed.
"""
import json
import os
import subprocess
import sys
import time

from plcvec_reference.adapter import ReferenceAdapter
from plcvec_verify.protocol import PROTOCOL_VERSION, encode

pidfile = sys.argv[1]
# A child that would outlive the adapter if only the adapter were killed (an emulator behind a
# bridge script, say).
child = subprocess.Popen([sys.executable, "-c", "import time; time.sleep(600)"])
with open(pidfile + ".tmp", "w") as f:
    f.write(f"{os.getpid()} {child.pid}\n")
os.replace(pidfile + ".tmp", pidfile)

adapter = ReferenceAdapter()
out = sys.stdout.buffer
for line in sys.stdin.buffer:
    msg = json.loads(line)
    if msg["type"] == "hello":
        out.write(encode({"type": "hello", "protocol": PROTOCOL_VERSION, **adapter.hello(msg)}))
        out.flush()
    elif msg["type"] == "run":
        first = msg["vectors"][0]
        out.write(encode({"type": "result", "id": first["id"], **adapter.run(first)}))
        out.flush()
        with open(pidfile, "a") as f:
            f.write("answered\n")
        time.sleep(600)
