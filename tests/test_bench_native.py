"""`plcvec bench-native --baseline REV`: the argument handling, the order in which the two sides run,
the arithmetic of the table (against numbers worked out by hand), the peak memory of the benchmark
program apart from its build, and the temporary worktree removed whatever ends the run. No real
language is built: the benches are small scripts in a throw-away git repository, or a fake runner.
(Speed itself is shown by the figures the command prints, not by a timed test.)"""
import argparse
import json
import subprocess
import textwrap
from pathlib import Path

import pytest

from plcvec import native_bench
from plcvec.cli import main
from plcvec.native_bench import Comparison, compare, summary


def _git(repo, *args):
    return subprocess.run(["git", "-C", str(repo), "-c", "user.name=t", "-c", "user.email=t@example.org", *args],
                          capture_output=True, text=True, check=True, timeout=60).stdout.strip()


def _bench(repo, lang, body):
    script = repo / "verifiers" / lang / "bench"
    script.parent.mkdir(parents=True, exist_ok=True)
    script.write_text("#!/bin/sh\n" + textwrap.dedent(body))
    script.chmod(0o755)


def _figure(vectors, rate, **more):
    return json.dumps({"lang": "x", "vectors": vectors, "seconds": vectors / rate, "vectors_per_s": rate, **more})


@pytest.fixture
def repo(tmp_path, monkeypatch):
    """A repository of two commits: `old` (benches a and c) and HEAD (a and b, a twice as slow per
    vector on a smaller set). Each bench appends `<lang> <side>` to $BENCH_LOG when it runs."""
    repo = tmp_path / "repo"
    repo.mkdir()
    _git(repo, "init", "-q")
    _bench(repo, "a", f"""\
        echo "a old" >> "$BENCH_LOG"
        echo '{_figure(3678, 2000, load_seconds=0.5)}'
        """)
    _bench(repo, "c", f"""echo '{_figure(10, 10)}'\n""")
    _git(repo, "add", "-A")
    _git(repo, "commit", "-q", "-m", "old")
    _git(repo, "tag", "old")
    _bench(repo, "a", f"""\
        echo "a new" >> "$BENCH_LOG"
        echo "building" >&2
        echo '{_figure(3526, 1000, load_seconds=0.25)}'
        """)
    _bench(repo, "b", f"""\
        echo "b new" >> "$BENCH_LOG"
        echo '{_figure(1, 1)}'
        """)
    (repo / "verifiers" / "c" / "bench").unlink()
    _git(repo, "add", "-A")
    _git(repo, "commit", "-q", "-m", "new")
    monkeypatch.setenv("BENCH_LOG", str(tmp_path / "log"))
    monkeypatch.setattr(native_bench.tempfile, "tempdir", str(tmp_path / "tmp"))
    (tmp_path / "tmp").mkdir()
    return repo


def _worktrees(repo):
    return [line for line in _git(repo, "worktree", "list", "--porcelain").splitlines() if line.startswith("worktree ")]


def _clean(repo):
    """No worktree but the repository's own, no temporary folder left."""
    assert _worktrees(repo) == [f"worktree {repo}"]
    assert list((repo.parent / "tmp").iterdir()) == []


# ---------------------------------------------------------------------------------------------------
# Arguments


@pytest.mark.parametrize("lang, named", [("zz", "zz"), ("a,", "''"), ("a,zz,b", "zz")])
def test_an_unknown_or_empty_language_is_a_usage_error_listing_the_known_ones(repo, capsys, lang, named):
    assert main(["bench-native", "--root", str(repo), "--baseline", "old", "--lang", lang]) == 2
    err = capsys.readouterr().err
    assert f"--lang {named}:" in err and "(known: a, b)" in err and "Traceback" not in err
    _clean(repo)


def test_an_unknown_revision_is_a_usage_error_naming_it(repo, capsys):
    assert main(["bench-native", "--root", str(repo), "--baseline", "no-such-rev"]) == 2
    err = capsys.readouterr().err
    assert "'no-such-rev' is not a commit" in err and "Traceback" not in err
    _clean(repo)


@pytest.mark.parametrize("rounds", ["0", "-1", "two"])
def test_rounds_must_be_a_positive_whole_number(repo, capsys, rounds):
    with pytest.raises(SystemExit) as exit:
        main(["bench-native", "--root", str(repo), "--baseline", "old", "--rounds", rounds])
    assert exit.value.code == 2 and "--rounds" in capsys.readouterr().err


def test_rounds_without_a_baseline_is_a_usage_error(repo, capsys):
    assert main(["bench-native", "--root", str(repo), "--rounds", "2"]) == 2
    assert "--rounds is for --baseline" in capsys.readouterr().err


# ---------------------------------------------------------------------------------------------------
# The order of the runs


def _recording_runner(calls, side, lang, fail_on=None):
    def run(build):
        calls.append((lang, side, "build" if build else "round"))
        if fail_on and fail_on(calls):
            return {"error": "it broke"}
        return {"vectors": 1, "vectors_per_s": 1.0}
    return run


def test_each_side_is_built_once_then_the_rounds_alternate_which_side_goes_first():
    calls = []
    runners = {side: {lang: _recording_runner(calls, side, lang) for lang in "xy"} for side in ("base", "cur")}
    results = compare(["x", "y"], runners["base"], runners["cur"], rounds=3)
    # Baseline first in rounds 1 and 3, this tree first in round 2: a drift over the run is shared.
    one = [("base", "build"), ("cur", "build"), ("base", "round"), ("cur", "round"),
           ("cur", "round"), ("base", "round"), ("base", "round"), ("cur", "round")]
    assert calls == [("x", *call) for call in one] + [("y", *call) for call in one]
    assert [(len(r.baseline), len(r.current), r.error) for r in results] == [(3, 3, None), (3, 3, None)]


def test_a_failure_ends_that_language_only_and_says_which_side():
    calls = []
    broken = lambda calls: calls[-1] == ("x", "base", "build")   # noqa: E731
    late = lambda calls: calls.count(("y", "cur", "round")) == 2   # noqa: E731
    base = {"x": _recording_runner(calls, "base", "x", broken), "y": _recording_runner(calls, "base", "y"), "z": None}
    cur = {lang: _recording_runner(calls, "cur", lang, late if lang == "y" else None) for lang in "xyz"}
    x, y, z = compare(["x", "y", "z"], base, cur, rounds=3)
    assert x.error == "baseline: it broke" and not x.current_failed and x.current == []
    # Round 2 runs this tree first: its baseline side is not run after the failure.
    assert y.error == "current, round 2: it broke" and y.current_failed and len(y.baseline) == 1
    assert z.error == "the baseline revision has no executable verifiers/z/bench"
    assert [c for c in calls if c[0] == "x"] == [("x", "base", "build")]
    assert [c for c in calls if c[0] == "z"] == []


# ---------------------------------------------------------------------------------------------------
# The arithmetic, against figures worked out by hand


def test_medians_spreads_and_ratios():
    result = Comparison("x")
    result.baseline = [{"vectors": 3678, "vectors_per_s": 100, "cpu_vectors_per_s": 200, "seconds": 0.01, "peak_mib": 10},
                       {"vectors": 3678, "vectors_per_s": 120, "cpu_vectors_per_s": 210, "seconds": 0.02, "peak_mib": 30},
                       {"vectors": 3678, "vectors_per_s": 110, "cpu_vectors_per_s": 190, "seconds": 0.03, "peak_mib": 20}]
    result.current = [{"vectors": 3526, "vectors_per_s": 99, "cpu_vectors_per_s": 180, "seconds": 0.04},
                      {"vectors": 3526, "vectors_per_s": 121, "cpu_vectors_per_s": 190, "seconds": 0.05, "peak_mib": 5},
                      {"vectors": 3526, "vectors_per_s": 88, "cpu_vectors_per_s": 170, "seconds": 0.06}]
    s = summary(result)
    base, cur = s["baseline"], s["current"]
    assert base["vectors"] == [3678] and cur["vectors"] == [3526]
    assert base["vectors_per_s"] == 110 and base["spread"] == pytest.approx(20 / 110)
    assert cur["vectors_per_s"] == 99 and cur["spread"] == pytest.approx(33 / 99)
    assert s["ratio"] == pytest.approx(0.9)                       # 99 / 110
    assert s["round_ratios"] == pytest.approx((0.8, 121 / 120))   # 99/100, 121/120, 88/110
    assert s["paired_ratio"] == pytest.approx(0.99)                # the middle one of 0.8, 0.99, 1.00833
    assert s["best_ratio"] == pytest.approx(121 / 120)             # fastest current 121, fastest baseline 120
    assert s["cpu_ratio"] == pytest.approx(0.9)                   # 180 / 200
    assert base["seconds"] == pytest.approx(0.02) and cur["seconds"] == pytest.approx(0.05)
    assert base["peak_mib"] == 20 and cur["peak_mib"] is None      # not given in every round: not shown
    assert base["load_seconds"] is None


def test_no_cpu_ratio_unless_both_sides_give_the_cpu_figure():
    result = Comparison("x")
    result.baseline = [{"vectors": 1, "vectors_per_s": 4}]
    result.current = [{"vectors": 1, "vectors_per_s": 5, "cpu_vectors_per_s": 6}]
    s = summary(result)
    assert s["ratio"] == 1.25 and s["cpu_ratio"] is None and s["baseline"]["spread"] == 0


# ---------------------------------------------------------------------------------------------------
# Whole runs against the throw-away repository


def test_a_whole_run_against_a_revision(repo, capsys, tmp_path):
    assert main(["bench-native", "--root", str(repo), "--baseline", "old", "--rounds", "2"]) == 0
    out = capsys.readouterr().out
    # Built, round 1 baseline first, round 2 this tree first; b is never run: not at `old`.
    assert (tmp_path / "log").read_text().split("\n") == ["a old", "a new", "a old", "a new", "a new", "a old", ""]
    summary_line = json.loads(out.strip().splitlines()[-1])
    assert summary_line["compared"]["a"] == {"ratio": 0.5, "paired_ratio": 0.5, "best_ratio": 0.5,
                                             "cpu_ratio": None, "baseline_vectors_per_s": 2000,
                                             "current_vectors_per_s": 1000, "baseline_vectors": [3678],
                                             "current_vectors": [3526]}
    assert summary_line["not_compared"] == {"b": "the baseline revision has no executable verifiers/b/bench"}
    rows = {line.split()[0]: line for line in out.splitlines() if line.startswith(("a ", "b "))}
    assert "3,678" in rows["a"] and "2,000" in rows["a"] and "0.500" in rows["a"]
    assert "3,526" in out and "0.500x by the clock (rounds 0.500x to 0.500x, median of the rounds 0.500x, " \
                              "fastest round over fastest 0.500x)" in out
    assert rows["b"].startswith("b          not compared:")
    _clean(repo)


def test_nothing_compared_exits_1(repo, capsys):
    assert main(["bench-native", "--root", str(repo), "--baseline", "old", "--lang", "b"]) == 1
    captured = capsys.readouterr()
    assert "no language could be compared" in captured.err and "Traceback" not in captured.err
    _clean(repo)


def test_a_failing_bench_of_this_tree_exits_1_and_says_why(repo, capsys):
    _bench(repo, "a", """echo "a new" >> "$BENCH_LOG"; echo "no compiler here" >&2; exit 3\n""")
    assert main(["bench-native", "--root", str(repo), "--baseline", "old", "--lang", "a"]) == 1
    out = capsys.readouterr().out
    assert "not compared: current:" in out and "exited 3: no compiler here" in out
    _clean(repo)


@pytest.mark.parametrize("stop", [KeyboardInterrupt, RuntimeError])
def test_the_worktree_is_removed_when_the_run_is_interrupted(repo, stop):
    seen = []

    def invoke(script, timeout, vectors=None):
        seen.append(Path(script))
        assert _worktrees(repo)[1:] and Path(script).is_file()   # the baseline's worktree exists meanwhile
        raise stop

    args = argparse.Namespace(lang=["a"], baseline="old", rounds=1)
    with pytest.raises(stop):
        native_bench.run_baseline(args, repo, progress=lambda message: None, invoke_bench=invoke)
    assert seen and "plcvec-bench-native-" in str(seen[0])
    _clean(repo)


def test_the_worktree_is_removed_when_a_bench_leaves_files_in_it(repo, capsys):
    _git(repo, "checkout", "-q", "old")
    _bench(repo, "a", f"""\
        mkdir -p target && echo built > target/artefact && echo '{_figure(1, 1)}'
        """)
    _git(repo, "commit", "-q", "-am", "a bench that builds into its folder")
    _git(repo, "tag", "builds")
    _git(repo, "checkout", "-q", "-")
    assert main(["bench-native", "--root", str(repo), "--baseline", "builds", "--lang", "a", "--rounds", "1"]) == 0
    _clean(repo)


# ---------------------------------------------------------------------------------------------------
# --same-vectors: both sides judge one folder


def _counting_bench(repo, side, rate):
    """A bench `d` that judges the folder PLCVEC_VECTORS names: its `count` file is how many
    vectors; it logs `d <side> <folder>`."""
    _bench(repo, "d", f"""\
        echo "d {side} $PLCVEC_VECTORS" >> "$BENCH_LOG"
        n=$(cat "$PLCVEC_VECTORS/count") || exit 4
        echo "{{\\"lang\\": \\"d\\", \\"vectors\\": $n, \\"vectors_per_s\\": {rate}}}"
        """)


def test_same_vectors_names_one_folder_to_both_sides(repo, capsys, tmp_path):
    _counting_bench(repo, "old", 400)
    _git(repo, "add", "-A")
    _git(repo, "commit", "-q", "-m", "d reads PLCVEC_VECTORS")
    _git(repo, "tag", "d-old")
    _counting_bench(repo, "new", 300)
    _git(repo, "commit", "-q", "-am", "d slower")
    folder = tmp_path / "shared-vectors"
    folder.mkdir()
    (folder / "count").write_text("3526\n")
    args = ["bench-native", "--root", str(repo), "--baseline", "d-old", "--lang", "d", "--rounds", "1"]
    assert main(args + ["--same-vectors", "--vectors", str(folder)]) == 0
    out = capsys.readouterr().out
    assert (tmp_path / "log").read_text().split("\n") == [f"d old {folder}", f"d new {folder}"] * 2 + [""]
    summary_line = json.loads(out.strip().splitlines()[-1])
    assert summary_line["same_vectors"] == str(folder)
    assert summary_line["compared"]["d"]["ratio"] == 0.75
    assert summary_line["compared"]["d"]["baseline_vectors"] == summary_line["compared"]["d"]["current_vectors"] == [3526]
    assert f"both sides judged the same vectors: {folder}" in out
    _clean(repo)


def test_same_vectors_refuses_a_language_whose_sides_report_different_counts(repo, capsys):
    # `a` judges its own set whatever PLCVEC_VECTORS says: 3678 vectors at `old`, 3526 now.
    folder = repo.parent / "elsewhere"
    folder.mkdir()
    assert main(["bench-native", "--root", str(repo), "--baseline", "old", "--lang", "a", "--rounds", "1",
                 "--same-vectors", "--vectors", str(folder)]) == 1
    out = capsys.readouterr().out
    assert ("a          not compared: --same-vectors: the two sides judged different numbers of vectors, "
            "3678 (baseline) and 3526 (current)") in out
    assert json.loads(out.strip().splitlines()[-1])["compared"] == {}
    _clean(repo)


def test_same_vectors_needs_a_baseline_and_an_existing_folder(repo, capsys):
    assert main(["bench-native", "--root", str(repo), "--same-vectors"]) == 2
    assert "--same-vectors is for --baseline" in capsys.readouterr().err
    missing = repo.parent / "no-such-folder"
    assert main(["bench-native", "--root", str(repo), "--baseline", "old", "--same-vectors", "--vectors", str(missing)]) == 2
    err = capsys.readouterr().err
    assert f"{missing}: no such vector folder" in err and "Traceback" not in err
    _clean(repo)


# ---------------------------------------------------------------------------------------------------
# Peak memory: the benchmark program's, not its build's


def test_peak_memory_is_the_benchmark_programs_not_the_build_steps(tmp_path):
    allocate = ("import json, sys, time; x = bytearray({mib} * 1024 * 1024); x[::4096] = b'1' * len(x[::4096]); "
                "time.sleep(0.5); print(json.dumps({{'vectors': 1, 'vectors_per_s': 1}}) if {last} else '')")
    script = tmp_path / "lang" / "bench"
    script.parent.mkdir()
    script.write_text("#!/bin/sh\nset -e\n"
                      f"python3 -c \"{allocate.format(mib=300, last=False)}\" >&2\n"            # the "build"
                      f"exec python3 -c \"{allocate.format(mib=60, last=True)}\"\n")            # the benchmark
    script.chmod(0o755)
    figure = native_bench.invoke(script)
    assert figure["vectors_per_s"] == 1 and figure["wall_seconds"] >= 1.0
    assert 60 <= figure["peak_mib"] < 300


def test_the_peak_of_a_go_test_binary_started_from_another_thread_of_its_parent(tmp_path):
    # `go test` starts the test binary from any of its threads; /proc lists a child under the
    # thread that started it. Here the parent (60 MiB at most with the interpreter) starts, from a
    # second thread, a program that holds 150 MiB and has `-test.bench` among its arguments.
    program = tmp_path / "go_like.py"
    program.write_text(textwrap.dedent(f"""\
        import subprocess, sys, threading
        child = "import time; x = bytearray(150 * 2**20); x[::4096] = b'1' * len(x[::4096]); time.sleep(0.5)"
        thread = threading.Thread(target=subprocess.run, args=([sys.executable, "-c", child, "-test.bench=."],))
        thread.start()
        thread.join()
        print({_figure(1, 1)!r})
        """))
    script = tmp_path / "lang" / "bench"
    script.parent.mkdir()
    script.write_text(f"#!/bin/sh\nexec python3 {program}\n")
    script.chmod(0o755)
    figure = native_bench.invoke(script)
    assert figure["vectors_per_s"] == 1 and figure["peak_mib"] >= 150


def test_no_peak_memory_when_the_script_runs_no_program_of_its_own(tmp_path):
    # A script that never execs into a program (env and the shell are launchers, and a child it
    # waits for is a build step) gives no figure rather than the launcher's or the child's.
    script = tmp_path / "lang" / "bench"
    script.parent.mkdir()
    script.write_text(f"#!/usr/bin/env sh\nsleep 0.3\necho '{_figure(1, 1)}'\n")
    script.chmod(0o755)
    figure = native_bench.invoke(script)
    assert figure["vectors_per_s"] == 1 and "peak_mib" not in figure


def test_a_bench_that_outlives_its_bound_is_stopped_and_reported(tmp_path):
    script = tmp_path / "lang" / "bench"
    script.parent.mkdir()
    script.write_text("#!/bin/sh\nsleep 30 &\nwait\n")
    script.chmod(0o755)
    figure = native_bench.invoke(script, timeout=0.5)
    assert figure == {"error": f"{script}: no result within 0.5 s (stopped)"}


# ---------------------------------------------------------------------------------------------------
# Without --baseline: each bench beside Python, and the guarded figure where a bench gives one


def test_the_guarded_figure_is_printed_under_its_language_with_the_benchs_own_ratio(tmp_path, monkeypatch, capsys):
    import plcvec_verify.bench

    root = tmp_path / "repo"
    _bench(root, "g", f"""echo '{_figure(3526, 4000, guarded_vectors_per_s=3000, guarded_ratio=0.9)}'\n""")
    _bench(root, "u", f"""echo '{_figure(3526, 2000)}'\n""")
    monkeypatch.setattr(plcvec_verify.bench, "in_process_rate", lambda vectors: (3526, 1000.0))
    assert main(["bench-native", "--root", str(root), "--vectors", str(tmp_path)]) == 0
    lines = capsys.readouterr().out.splitlines()
    g = next(i for i, line in enumerate(lines) if line.startswith("g "))
    # 3000 vectors/s is 3.0 times Python's 1000; the ratio is the bench's own (0.9: against its
    # unguarded judging, which need not be its headline figure), not 3000/4000 worked out here.
    assert lines[g + 1].split() == ["g,", "under", "the", "per-vector", "bound", "3,526", "3,000", "3.0", "x", "0.90",
                                    "of", "unguarded"]
    # Where the bench gives the unguarded judging's own figure, it is shown beside the ratio.
    _bench(root, "h", f"""echo '{_figure(3526, 9000, guarded_vectors_per_s=3000, guarded_ratio=0.97,
                                          unguarded_loop_vectors_per_s=3100)}'\n""")
    assert main(["bench-native", "--root", str(root), "--vectors", str(tmp_path), "--lang", "h"]) == 0
    h = capsys.readouterr().out.splitlines()
    h = h[next(i for i, line in enumerate(h) if line.startswith("h ")) + 1]
    assert h.endswith("x 0.97 of unguarded (3,100 vectors/s, the same judging without the bound)")
    # A bench without the guarded figure gets no such line.
    assert [line for line in lines if "per-vector bound" in line] == [lines[g + 1]]


def test_different_counts_under_common_vectors_name_that_option():
    # Two sides that judged 2814 and 2790 vectors: the message names the option the user gave.
    from types import SimpleNamespace
    from plcvec.native_bench import same_counts

    result = SimpleNamespace(lang="a", error=None, baseline=[{"vectors": 2814}], current=[{"vectors": 2790}])
    assert same_counts([result], "--common-vectors") == ["a"]
    assert result.error.startswith("--common-vectors: the two sides judged different numbers of vectors, "
                                   "2814 (baseline) and 2790 (current)")
