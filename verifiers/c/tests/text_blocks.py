#!/usr/bin/env python3
"""The C failure blocks against the shared expected text (verifiers/parity/text/), byte for byte.

The C library's vectors are compiled in, and `plcvec export` renders only vector files of the
checkout's spec, which the shared cases (copied from an earlier golden set) are not. So this check
takes the shared cases whose vector is, field for field, still in the golden set: it writes a C
program whose implementation answers each of them from text/answers.json (declaring text's hello:
its interpretations and cpu_writes), builds it against the built library, and compares the failure
blocks it prints with those of text/expected.txt. The roll-up and the summary are not compared
(C does not print TEXT.md's roll-up yet).

    python3 verifiers/c/tests/text_blocks.py BUILD_DIR     # BUILD_DIR holds libplcvec.a
Exit 0 identical, 1 a difference (shown as a diff) or too few cases left to check.
"""
import difflib
import json
import subprocess
import sys
import tempfile
from pathlib import Path

REPO = Path(__file__).resolve().parents[3]
TEXT = REPO / "verifiers" / "parity" / "text"
MIN_CASES = 5       # below this the check would prove little: regenerate text/ from the current spec


def c_str(s: str) -> str:
    return json.dumps(s, ensure_ascii=False)


def current_cases() -> list[str]:
    """The shared cases whose vector is unchanged in the golden set, in the order of expected.txt."""
    golden = {}
    for path in sorted((REPO / "vectors").glob("*.json")):
        if path.name != "manifest.json":
            golden.update({v["id"]: v for v in json.loads(path.read_text(encoding="utf-8"))["vectors"]})
    same = []
    for path in sorted((TEXT / "vectors").glob("*.json")):
        if path.name != "manifest.json":
            same += [v["id"] for v in json.loads(path.read_text(encoding="utf-8"))["vectors"] if golden.get(v["id"]) == v]
    return same


def program(ids: list[str], answers: dict) -> str:
    lines = ['#include <stdio.h>', '#include <string.h>', '#include "plcvec/plcvec.h"', '',
             'static int run(void *ctx, const plcvec_vector *v, plcvec_out *o)', '{', '    (void)ctx;']
    for vid in ids:
        a = answers["answers"][vid]
        lines.append(f"    if (strcmp(v->id, {c_str(vid)}) == 0) {{")
        if "skip" in a:
            lines.append(f"        return plcvec_out_skip(o, {c_str(a['skip'])});")
        elif "error" in a:
            lines.append(f"        return plcvec_out_error(o, {c_str(a['error'])});")
        else:
            for step in a["steps"]:
                result = step.get("result")
                lines.append(f"        plcvec_out_step(o, {-1 if result is None else int(result)});")
                for device, value in step.get("devices", {}).items():
                    kind = "PLCVEC_BIT" if isinstance(value, bool) else "PLCVEC_WORD"
                    lines.append(f"        plcvec_out_named(o, {c_str(device)}, {kind}, {int(value)}u);")
            lines.append("        return 0;")
        lines.append("    }")
    lines += ['    return plcvec_out_skip(o, "not a shared case");', '}', '', 'int main(void)', '{']
    hello = answers["hello"]
    lines.append("    static const char *const cpu[] = {" + "".join(f"{c_str(d)}, " for d in hello.get("cpu_writes", []))
                 + "NULL};")
    lines.append(f"    plcvec_choice choices[{max(1, len(hello.get('interpretations', {})))}];")
    lines.append("    size_t n = 0;")
    for interp, alt in hello.get("interpretations", {}).items():
        lines.append(f"    {{ int i = plcvec_interpretation_named({c_str(interp)}); "
                     f"choices[n].interpretation = (uint8_t)i; "
                     f"choices[n++].alternative = (uint8_t)plcvec_alternative_named(i, {c_str(alt)}); }}")
    lines += ["    plcvec_impl impl = {0};", f"    impl.name = {c_str(hello['adapter']['name'])};",
              "    impl.run = run, impl.choices = choices, impl.n_choices = n, impl.cpu_writes = cpu;",
              "    char err[256];", "    plcvec_judge *j = plcvec_judge_new(&impl, err, sizeof err);",
              "    if (!j) {", '        fprintf(stderr, "%s\\n", err);', "        return 2;", "    }"]
    lines.append("    plcvec_judge_free(j);")
    lines.append("    static const char *const ids[] = {" + "".join(f"{c_str(i)}, " for i in ids) + "};")
    lines += ["    plcvec_options opt = {0};", f"    opt.selection.ids = ids, opt.selection.n_ids = {len(ids)};",
              "    plcvec_run(&impl, &opt, NULL);", "    return 0;", "}"]
    return "\n".join(lines) + "\n"


def python_text(ids: list[str], answers: dict) -> str:
    """plcvec verify's text for the same cases (the rule), without the header line and the time."""
    import re

    from plcvec_verify.adapters import InProcess
    from plcvec_verify.reports import summary_text
    from plcvec_verify.runner import run
    from plcvec_verify.suite import Selection, Suite

    class Replay:
        def hello(self, request):
            return json.loads(json.dumps(answers["hello"]))

        def run(self, request):
            return json.loads(json.dumps(answers["answers"][request["id"]]))

    report = run(Suite.load(REPO / "vectors"), InProcess(Replay(), answers["hello"]["adapter"]["name"]),
                 Selection(ids=tuple(ids)))
    return machine_free(summary_text(report), "plcvec verify: ")


def machine_free(text: str, header: str) -> str:
    import re

    lines = [line for line in text.split("\n") if not line.startswith(header)]
    return "\n".join(re.sub(r" in [0-9]+\.[0-9]{2} s$", "", line) for line in lines)


def expected_blocks(ids: list[str]) -> str:
    """The failure blocks of expected.txt for `ids` (the part before the roll-up), in their order."""
    text = (TEXT / "expected.txt").read_text(encoding="utf-8")
    blocks, current = {}, None
    for line in text.splitlines(keepends=True):
        if line.startswith(("READINGS:", "NOT EXPLAINED", "SKIPPED ")) or line == "\n":
            break
        if not line.startswith(" "):
            current = line.split(" ", 1)[1].rstrip("\n")
            blocks[current] = ""
        blocks[current] += line
    return "".join(blocks[i] for i in ids if i in blocks)


def main() -> int:
    build = Path(sys.argv[1]).resolve()
    ids = current_cases()
    if len(ids) < MIN_CASES:
        print(f"text_blocks: only {len(ids)} shared cases are still in the golden set; regenerate "
              "verifiers/parity/text/ from the current spec")
        return 1
    answers = json.loads((TEXT / "answers.json").read_text(encoding="utf-8"))
    with tempfile.TemporaryDirectory() as tmp:
        source, exe = Path(tmp) / "text_blocks.c", Path(tmp) / "text_blocks"
        source.write_text(program(ids, answers), encoding="utf-8")
        subprocess.run(["cc", "-std=c11", "-Wall", "-Werror", f"-I{REPO / 'verifiers/c/include'}", str(source),
                        str(build / "libplcvec.a"), "-pthread", "-o", str(exe)], check=True)
        got = subprocess.run([str(exe)], capture_output=True, text=True, check=True).stdout
    # 1. The failure blocks against the shared expected text itself.
    want = expected_blocks(ids)
    blocks = got[:len(want)]
    if blocks != want:
        sys.stdout.writelines(difflib.unified_diff(want.splitlines(True), blocks.splitlines(True), "expected.txt", "C"))
        return 1
    # 2. The whole run's text (blocks, roll-up by reading, skips, summary) against plcvec verify's
    #    for the same cases, the header line and the time left out.
    want_all = python_text(ids, answers)
    got_all = machine_free(got, "plcvec: ")
    if got_all != want_all:
        sys.stdout.writelines(difflib.unified_diff(want_all.splitlines(True), got_all.splitlines(True),
                                                   "plcvec verify", "C"))
        return 1
    print(f"text_blocks: the C failure blocks of {len(ids)} shared cases are byte for byte expected.txt's "
          f"({want.count(chr(10))} lines), and the whole run's text is plcvec verify's ({got_all.count(chr(10))} lines)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
