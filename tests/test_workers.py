"""The golden set built in worker processes: the same bytes as one process gives, results in the
families' order whichever worker finishes first, and a worker's failure reported, not waited on."""
import os
import signal
import time

import pytest

from plcvec.errors import PlcvecError, SpecError
from plcvec.output import workers
from plcvec.output.golden import build_golden, family_cost
from plcvec.output.workers import map_families

pytestmark = pytest.mark.skipif(not workers.can_fork(), reason="worker processes are forked on Linux only")


class Fam:
    """Stands in for a spec family: map_families only reads its name."""

    def __init__(self, name):
        self.name = name


FAMS = [Fam(f"f{k}") for k in range(5)]


def noting_pid(folder, function):
    """`function`, run by a worker that first leaves its process id in `folder`."""
    def noted(fam):
        (folder / f"{fam.name}.tmp").write_text(str(os.getpid()))
        os.replace(folder / f"{fam.name}.tmp", folder / f"{fam.name}.pid")   # never read half-written
        return function(fam)
    return noted


def worker_pids(folder):
    return [int(p.read_text()) for p in sorted(folder.glob("*.pid"))]


def assert_no_worker_left(folder):
    """Every worker that started is gone: exited or killed, and reaped (a zombie would still answer)."""
    pids = worker_pids(folder)
    assert pids and os.getpid() not in pids
    for pid in pids:
        with pytest.raises(ProcessLookupError):
            os.kill(pid, 0)


@pytest.mark.slow
def test_two_jobs_give_the_same_files_as_one(families, generated):
    # The whole set as `plcvec generate` builds it (workers send back the files alone): every file,
    # byte for byte, the manifest, the CSV and each family's. (The default run has the same through
    # the command: test_generate_with_jobs_writes_the_files_one_process_gives.)
    assert build_golden(list(families.values()), jobs=2, keep_vectors=False) == (generated[0], None)


def test_two_jobs_give_the_same_vectors_as_one(families):
    # Workers that send back the vectors too: two small families, the costlier one (HOUR, whose six
    # interpretations make more combinations than TADD's four) handed out first though it comes second.
    few = [families["fx5-time-add"], families["fc6a-hour-meter"]]
    assert family_cost(few[1]) > family_cost(few[0])
    assert build_golden(few, jobs=2) == build_golden(few, jobs=1)


def test_results_come_in_the_families_order_whatever_order_the_work_is_handed_out(tmp_path):
    def slow_first(fam):
        time.sleep(0.2 if fam.name == "f0" else 0)   # f0 finishes last
        return fam.name, os.getpid()

    results = map_families(noting_pid(tmp_path, slow_first), FAMS, 3,
                           cost=lambda fam: -int(fam.name[1:]))   # f4 handed out first
    assert [name for name, _ in results] == [f.name for f in FAMS]
    assert os.getpid() not in {pid for _, pid in results}   # worked out in other processes
    assert_no_worker_left(tmp_path)


def test_one_job_works_in_this_process():
    assert map_families(lambda fam: os.getpid(), FAMS, 1) == [os.getpid()] * len(FAMS)
    assert map_families(lambda fam: os.getpid(), FAMS[:1], 4) == [os.getpid()]   # one family: no worker


def test_a_workers_error_is_raised_here_as_it_was_raised_there(tmp_path):
    def fails_on_f3(fam):
        if fam.name == "f3":
            raise SpecError("spec/f3.yaml", 12, "something the user wrote")
        time.sleep(0.3 if fam.name == "f4" else 0)   # still at work when f3 fails
        return fam.name

    with pytest.raises(SpecError) as caught:
        map_families(noting_pid(tmp_path, fails_on_f3), FAMS, 2)
    assert (caught.value.path, caught.value.line, str(caught.value)) == (
        "spec/f3.yaml", 12, "spec/f3.yaml:12: something the user wrote")
    assert_no_worker_left(tmp_path)


def test_a_worker_that_dies_is_reported_with_its_family(tmp_path):
    def dies_on_f2(fam):
        if fam.name == "f2":
            os._exit(9)
        return fam.name

    with pytest.raises(PlcvecError, match=r"worker process building f2 died \(exit 9; .*--jobs 1"):
        map_families(noting_pid(tmp_path, dies_on_f2), FAMS, 2)
    assert_no_worker_left(tmp_path)


def test_a_worker_that_hangs_is_given_up_on_and_stopped(monkeypatch, tmp_path):
    monkeypatch.setattr(workers, "FAMILY_TIMEOUT_S", 0.5)

    def hangs_on_f1(fam):
        if fam.name == "f1":
            time.sleep(60)
        return fam.name

    start = time.monotonic()
    with pytest.raises(PlcvecError, match=r"more than 0.5 s over f1"):
        map_families(noting_pid(tmp_path, hangs_on_f1), FAMS, 2)
    assert time.monotonic() - start < 10
    assert_no_worker_left(tmp_path)   # the hanging worker killed, not left to sleep on


def test_the_costliest_family_is_the_one_with_most_instructions_and_readings(families):
    # CP1E: 18 instructions and six interpretations (144 combinations), the largest family here.
    assert max(families.values(), key=family_cost).name == "cp1e-time-compare"


def test_generate_with_jobs_writes_the_files_one_process_gives(tmp_path, generated, capsys):
    from plcvec import cli

    assert cli.main(["generate", "--out", str(tmp_path), "--jobs", "3"]) == 0
    files, _ = generated
    assert {p.name: p.read_text(encoding="utf-8") for p in tmp_path.iterdir()} == files


@pytest.mark.parametrize("command", [["generate", "--check"], ["review", "--check"], ["release", "--out", "unused"]])
@pytest.mark.parametrize("jobs", ["0", "-2", "two", "1.5"])
def test_each_command_refuses_a_number_of_jobs_that_is_not_one_or_more(command, jobs, capsys):
    from plcvec import cli

    with pytest.raises(SystemExit) as caught:
        cli.main([*command, "--jobs", jobs])
    assert caught.value.code == 2
    assert f"argument --jobs/-j: {jobs!r} is not a number of processes" in capsys.readouterr().err


def test_an_interrupted_map_stops_its_workers_and_waits_for_them(tmp_path):
    def sleeps(fam):
        time.sleep(30)

    def interrupt(signum, frame):
        raise KeyboardInterrupt

    previous = signal.signal(signal.SIGALRM, interrupt)
    signal.setitimer(signal.ITIMER_REAL, 0.5)   # ^C half a second in, as the parent sees it
    start = time.monotonic()
    try:
        with pytest.raises(KeyboardInterrupt):
            map_families(noting_pid(tmp_path, sleeps), FAMS, 2)
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)
    assert time.monotonic() - start < 5
    assert len(worker_pids(tmp_path)) == 2   # two workers were at work
    assert_no_worker_left(tmp_path)


def test_workers_leave_ctrl_c_to_the_parent(tmp_path):
    def naps(fam):
        time.sleep(0.6)
        return fam.name

    def ctrl_c_to_the_workers(signum, frame):   # what a terminal's ^C does to the whole group
        for pid in worker_pids(tmp_path):
            os.kill(pid, signal.SIGINT)

    previous = signal.signal(signal.SIGALRM, ctrl_c_to_the_workers)
    signal.setitimer(signal.ITIMER_REAL, 0.3)
    try:
        assert map_families(noting_pid(tmp_path, naps), FAMS[:2], 2) == ["f0", "f1"]   # neither worker stopped
        assert len(worker_pids(tmp_path)) == 2
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)


def _refuse_to_load():
    raise ValueError("this object does not load")


class _Unreadable:
    """Pickles, but does not unpickle."""

    def __reduce__(self):
        return _refuse_to_load, ()


def test_a_result_that_does_not_read_back_is_reported_with_its_family(tmp_path):
    def unreadable_for_f1(fam):
        return _Unreadable() if fam.name == "f1" else fam.name

    with pytest.raises(PlcvecError, match=r"worker process building f1 sent back what cannot be read "
                                          r"\(this object does not load\); try again with --jobs 1"):
        map_families(noting_pid(tmp_path, unreadable_for_f1), FAMS, 2)
    assert_no_worker_left(tmp_path)
