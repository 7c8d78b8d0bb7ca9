#!/usr/bin/env python3
"""The C run's text against the shared expected text (verifiers/parity/text/), byte for byte.

The C library's vectors are compiled in from the golden set, and the shared cases' vectors are the
golden ones (verifiers/parity/text_cases.py keeps them so; tests/test_text_parity.py fails when they
drift). This check writes a C program whose implementation answers each case from
text/answers.json (declaring the cases' hello: its interpretations and cpu_writes), selects the
cases by id, builds it against the built library, and compares what plcvec_run prints (the failure
blocks, the roll-up by reading, the skips by reason and the summary; the header line and the time
left out) with text/expected.txt, then, with text/known.toml as its known-failures file (read from
the folder text/, as `known.toml`), with text/expected-known.txt. The expected texts hold the
`plcvec verify` form of a declaration (--choose); the program asks the roll-up for it, and the C
form is checked against TEXT.md's table by tests/test_rollup.c.

    python3 verifiers/c/tests/text_blocks.py BUILD_DIR     # BUILD_DIR holds libplcvec.a
Exit 0 identical, 1 a difference (shown as a diff) or a case the golden set no longer has.
"""
import difflib
import json
import re
import subprocess
import sys
import tempfile
from pathlib import Path

REPO = Path(__file__).resolve().parents[3]
TEXT = REPO / "verifiers" / "parity" / "text"


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
    lines = ['#include <stdio.h>', '#include <string.h>', '#include "plcvec/plcvec.h"', '#include "rollup.h"', '',
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
    lines += ['    return plcvec_out_skip(o, "not a shared case");', '}', '', 'int main(int argc, char **argv)', '{']
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
              "    plcvec_known_failure *known = NULL;", "    size_t n_known = 0;",
              "    if (argc > 1 && plcvec_known_load(argv[1], &known, &n_known, err, sizeof err) != 0) {",
              '        fprintf(stderr, "%s\\n", err);', "        return 2;", "    }",
              "    opt.known = known, opt.n_known = n_known;",
              "    plcvec_rollup_declaration_form(PLCVEC_DECLARE_CHOOSE);",
              "    plcvec_run(&impl, &opt, NULL);", "    plcvec_known_free(known, n_known);", "    return 0;", "}"]
    return "\n".join(lines) + "\n"


def machine_free(text: str, header: str) -> str:
    """The run's text without what depends on the machine: the header line and the time."""
    lines = [line for line in text.split("\n") if not line.startswith(header)]
    return "\n".join(re.sub(r" in [0-9]+\.[0-9]{2} s$", "", line) for line in lines)


def main() -> int:
    if len(sys.argv) != 2 or not (Path(sys.argv[1]) / "libplcvec.a").is_file():
        print(f"text_blocks: give the build folder that holds libplcvec.a ({__doc__.strip().splitlines()[-2].strip()})")
        return 2
    build = Path(sys.argv[1]).resolve()
    answers = json.loads((TEXT / "answers.json").read_text(encoding="utf-8"))
    ids = current_cases()
    stale = sorted(set(answers["answers"]) - set(ids))
    if stale:
        print(f"text_blocks: {len(stale)} shared cases are not the golden set's vectors ({', '.join(stale)}); "
              "run python3 verifiers/parity/text_cases.py and bring text/expected.txt up to date")
        return 1
    with tempfile.TemporaryDirectory() as tmp:
        source, exe = Path(tmp) / "text_blocks.c", Path(tmp) / "text_blocks"
        source.write_text(program(ids, answers), encoding="utf-8")
        subprocess.run(["cc", "-std=c11", "-Wall", "-Werror", f"-I{REPO / 'verifiers/c/include'}",
                        f"-I{REPO / 'verifiers/c/src'}", str(source), str(build / "libplcvec.a"), "-pthread", "-o",
                        str(exe)], check=True)
        runs = {"expected.txt": [str(exe)], "expected-known.txt": [str(exe), "known.toml"]}
        got = {name: subprocess.run(cmd, cwd=TEXT, capture_output=True, text=True, check=True).stdout
               for name, cmd in runs.items()}
    failed = 0
    for name, text in got.items():
        want = (TEXT / name).read_text(encoding="utf-8")
        text = machine_free(text, "plcvec: ")
        if text != want:
            sys.stdout.writelines(difflib.unified_diff(want.splitlines(True), text.splitlines(True), name, "C"))
            failed = 1
            continue
        print(f"text_blocks: the C run's text of the {len(ids)} shared cases is byte for byte {name}'s "
              f"({want.count(chr(10))} lines: failure blocks, roll-up by reading, skips, summary)")
    return failed


if __name__ == "__main__":
    sys.exit(main())
