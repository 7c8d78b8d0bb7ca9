"""An adapter process that misbehaves on purpose, for the fault tests.

    python3 faulty.py MODE TARGET

Answers like the reference implementation, except on the vector whose id is TARGET, where it
does MODE: crash (aborts), crash-all (aborts on every vector), hang, garbage (a line that is not JSON),
unknown-id, no-id (a result without an id), fatal-run (gives up with a `fatal` message),
wrong-shape, exit-early (exit 0 without answering), close-stdout (closes its stdout and
keeps running), endless-line (writes without ever ending the line), stderr (a message on stderr,
then a correct answer), duplicate (answers the target twice), ignore-bye (does not exit after
`bye`), bad-hello (a handshake answer of the wrong shape), fatal-hello (refuses the handshake),
hang-hello (never answers the handshake), garbage-hello (a handshake that is not JSON),
two-hellos (two lines for one handshake), new-protocol (answers the handshake with protocol 2),
repeated-key (reports one device twice with two values in one JSON object).
It buffers its output per batch, as most adapters do, so the runner must find the culprit by itself.
"""
import json
import os
import sys
import time

from plcvec_reference.adapter import ReferenceAdapter
from plcvec_verify.protocol import PROTOCOL_VERSION, encode

mode, target = sys.argv[1], sys.argv[2] if len(sys.argv) > 2 else ""
adapter = ReferenceAdapter()
out = sys.stdout.buffer

for line in sys.stdin.buffer:
    msg = json.loads(line)
    if msg["type"] == "hello":
        if mode == "hang-hello":
            time.sleep(3600)
        if mode == "garbage-hello":
            out.write(b"Welcome to EmuPLC 2.1\n")
        elif mode == "two-hellos":
            out.write(encode({"type": "hello", "protocol": PROTOCOL_VERSION, **adapter.hello(msg)}) * 2)
        elif mode == "new-protocol":
            out.write(encode({"type": "hello", "protocol": 2, **adapter.hello(msg)}))
        elif mode == "bad-hello":
            out.write(encode({"type": "hello", "protocol": PROTOCOL_VERSION, "instructions": "all"}))
        elif mode == "fatal-hello":
            out.write(encode({"type": "fatal", "message": "this adapter needs a license key"}))
        else:
            out.write(encode({"type": "hello", "protocol": PROTOCOL_VERSION, **adapter.hello(msg)}))
        out.flush()
        continue
    if msg["type"] == "bye":
        if mode == "ignore-bye":
            time.sleep(3600)
        break
    for request in msg["vectors"]:
        result = {"type": "result", "id": request["id"], **adapter.run(request)}
        if mode == "crash-all":
            out.flush()
            os.abort()
        if request["id"] == target:
            if mode == "crash":
                out.flush()
                os.abort()
            if mode == "hang":
                out.flush()
                time.sleep(3600)
            if mode == "exit-early":
                out.flush()
                os._exit(0)
            if mode == "close-stdout":
                out.flush()
                os.close(1)
                time.sleep(3600)
            if mode == "endless-line":
                while True:
                    out.write(b"x" * 65536)
            if mode == "garbage":
                out.write(b"Segmentation fault in module clock.c\n")
                continue
            if mode == "no-id":
                del result["id"]
            if mode == "fatal-run":
                result = {"type": "fatal", "message": "emulator licence expired"}
            if mode == "unknown-id":
                result["id"] = "no-such/vector"
            if mode == "wrong-shape":
                result["steps"] = [{"devices": {"D100": "twelve"}}]
            if mode == "stderr":
                sys.stderr.write(f"warning: clock not set while running {request['id']}\n")
                sys.stderr.flush()
            if mode == "duplicate":
                out.write(encode(result))
            if mode == "repeated-key":
                # One listed device twice with two values: json.loads would keep the last.
                line = encode(result)
                first = next(iter(result["steps"][0]["devices"]))
                value = json.dumps(result["steps"][0]["devices"][first])
                out.write(line.replace(f'"{first}":{value}'.encode(), f'"{first}":12345,"{first}":{value}'.encode(), 1))
                continue
        out.write(encode(result))
    out.flush()
