"""rigidfold.sweep on Dask distributed LocalClusters: the same records whatever the number of
workers, nothing lost when a worker is killed mid-sweep, no task run twice when a sweep is run
again on its results file, and its command line (python3 -m rigidfold.sweep)."""
import glob
import json
import os
import signal
import subprocess
import sys
import threading
import time

import pytest

import rigidfold
from conftest import BUNDLED

distributed = pytest.importorskip("distributed", reason="python3-distributed (scripts/bootstrap.sh) runs sweeps")

MIURA_5x4 = {"generator": "miura_ori", "rows": 5, "cols": 4}
MIURA_4x4 = {"generator": "miura_ori", "rows": 4, "cols": 4}


def cluster(workers):
    c = distributed.LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, dashboard_address=None)
    return c, distributed.Client(c)


def serial(spec, **options):
    """The whole search in this process, in the records' plain form."""
    import rigidfold.sweep as sweep
    return sweep.plain(rigidfold.enumerate_assignments(sweep.load_pattern(spec), max_listed=2**31 - 1,
                                                       source=sweep.source_of(spec), **options))


def same_search(merged, whole):
    """Equal but for search_steps: the subtrees each walk down from the root again."""
    return {k: v for k, v in merged.items() if k != "search_steps"} == {k: v for k, v in whole.items() if k != "search_steps"}


def test_branches_of_one_depth_join_to_the_serial_search():
    import rigidfold.sweep as sweep
    pattern = rigidfold.miura_ori(rows=3, cols=3)
    whole = serial({"generator": "miura_ori", "rows": 3, "cols": 3})
    for depth in (1, 2, 3):
        branches = rigidfold.assignment_branches(pattern, depth)
        records = [{"result": sweep.plain(rigidfold.enumerate_assignments(pattern, branch=b, max_listed=10**6))}
                   for b in branches]
        merged = sweep.merge_assignments(records)
        assert merged["listed"] == whole["listed"], depth
        assert merged["assignments"] == whole["assignments"] == 82
        assert merged["foldable_classes"] == whole["foldable_classes"]
    with pytest.raises(rigidfold.InputError, match="branch\\[0\\]"):
        rigidfold.enumerate_assignments(pattern, branch=[1000])


def test_five_by_four_miura_on_one_two_and_four_workers_gives_the_same_classes():
    import rigidfold.sweep as sweep
    tasks = sweep.assignment_tasks(MIURA_5x4, tasks_wanted=24, max_verdicts=0)
    assert len(tasks) >= 24
    whole = serial(MIURA_5x4, max_verdicts=0)
    assert (whole["assignments"], whole["classes"]) == (18150, 4582)
    merged = {}
    for workers in (1, 2, 4):
        c, client = cluster(workers)
        try:
            records = rigidfold.sweep(tasks, client=client)
        finally:
            client.close()
            c.close()
        assert records.ran == len(tasks) and records.reused == 0
        assert [r["task"] for r in records] == tasks
        merged[workers] = sweep.merge_assignments(records)
        assert (merged[workers]["assignments"], merged[workers]["classes"]) == (18150, 4582)
    assert merged[1] == merged[2] == merged[4]
    assert same_search(merged[1], whole)


def test_a_worker_killed_mid_sweep_loses_nothing_and_a_rerun_does_no_task_twice(tmp_path):
    """4 x 4 Miura with every class's verdict, 2 workers: one worker process is killed once the
    first records are written; the sweep still returns every class once, with the serial
    search's verdicts. Run again on the same file, it runs nothing; with its last line cut
    short (a kill mid-write), it runs that task alone again."""
    import rigidfold.sweep as sweep
    tasks = sweep.assignment_tasks(MIURA_4x4, tasks_wanted=32)
    out = tmp_path / "miura.jsonl"
    c, client = cluster(2)
    outcome = {}
    try:
        pids = list(client.run(os.getpid).values())
        thread = threading.Thread(target=lambda: outcome.update(records=rigidfold.sweep(tasks, client=client, out=str(out))))
        thread.start()
        deadline = time.monotonic() + 300
        while (not out.exists() or out.read_text().count("\n") < 2) and time.monotonic() < deadline:
            time.sleep(0.01)
        written_at_kill = out.read_text().count("\n")
        os.kill(pids[0], signal.SIGKILL)
        thread.join(600)
    finally:
        client.close()
        c.close()
    assert written_at_kill < len(tasks), "the sweep ended before the kill: the test proves nothing"
    records = outcome["records"]
    merged = sweep.merge_assignments(records)
    whole = serial(MIURA_4x4)
    assert (merged["assignments"], merged["classes"]) == (2604, 655)
    assert same_search(merged, whole)
    lines = out.read_text().splitlines()
    assert sorted(json.loads(line)["id"] for line in lines) == sorted(sweep.task_id(t) for t in tasks)

    again = rigidfold.sweep(tasks, out=str(out), workers=1)
    assert (again.ran, again.reused) == (0, len(tasks))
    assert out.read_text().splitlines() == lines
    assert list(again) == list(records)

    out.write_text("\n".join(lines[:-1]) + "\n" + lines[-1][: len(lines[-1]) // 2])
    third = rigidfold.sweep(tasks, out=str(out), workers=1)
    assert (third.ran, third.reused) == (1, len(tasks) - 1)
    assert sorted(out.read_text().splitlines()) == sorted(lines)
    assert list(third) == list(records)


def run_cli(*args, cwd):
    return subprocess.run([sys.executable, "-m", "rigidfold.sweep", *args], cwd=cwd, capture_output=True, text=True,
                          timeout=600)


def test_command_line_grids_and_folders_and_bad_specs(tmp_path):
    spec = tmp_path / "spec.json"
    spec.write_text(json.dumps({"tasks": [
        {"kind": "waterbomb", "grid": {"n": [6, 8], "theta0": {"from": 0.2, "to": 0.8, "num": 3}}},
        {"kind": "metamaterial", "grid": {"theta": {"from": 0.5, "to": 2.5, "num": 5}}, "alpha": 2.5},
        {"kind": "check", "patterns": os.path.join(BUNDLED, "square_twist_30_type*.fold")},
        {"kind": "assignments", "pattern": {"generator": "miura_ori", "rows": 3, "cols": 3}, "split_depth": 2},
    ]}))
    out = tmp_path / "r.jsonl"
    r = run_cli(str(spec), "--out", str(out), "--workers", "2", cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    records = [json.loads(line) for line in out.read_text().splitlines()]
    kinds = [rec["task"]["kind"] for rec in records]
    twists = glob.glob(os.path.join(BUNDLED, "square_twist_30_type*.fold"))
    assert kinds.count("waterbomb") == 6 and kinds.count("metamaterial") == 5 and kinds.count("check") == len(twists) > 1
    assert all("result" in rec for rec in records), [rec for rec in records if "error" in rec]
    assert "82 assignments" in r.stdout, r.stdout
    for rec in records:
        if rec["task"]["kind"] == "waterbomb":
            t = rec["task"]
            assert rec["result"] == rigidfold.sweep.plain(rigidfold.waterbomb_bistability(t["n"], t["theta0"]))
        if rec["task"]["kind"] == "check":
            expected = rigidfold.check(rigidfold.load(rec["task"]["pattern"]), explore_branches=False)
            assert rec["result"]["verdict_class"] == expected["verdict_class"]
    assert "sweep:" in r.stderr  # progress lines

    before = out.read_bytes()
    again = run_cli(str(spec), "--out", str(out), "--quiet", cwd=tmp_path)
    assert again.returncode == 0 and "0 run now" in again.stdout and again.stderr == "", (again.stdout, again.stderr)
    assert out.read_bytes() == before

    for bad, place in [({"tasks": [{"kind": "fold"}]}, "tasks[0].kind"),
                       ({"tasks": [{"kind": "waterbomb", "n": 6}]}, "tasks[0]: waterbomb needs theta0"),
                       ({"tasks": [{"kind": "waterbomb", "grid": {"n": []}, "theta0": 1}]}, "tasks[0].grid.n"),
                       ({"tasks": [{"kind": "check", "patterns": "nothing/*.fold"}]}, "tasks[0].patterns"),
                       ({"task": []}, "\"tasks\"")]:
        spec.write_text(json.dumps(bad))
        r = run_cli(str(spec), "--out", str(out), cwd=tmp_path)
        assert r.returncode == 2 and place in r.stderr, (bad, r.stderr)
        assert "Traceback" not in r.stderr
        assert out.read_bytes() == before
    r = run_cli(str(tmp_path / "missing.json"), "--out", str(out), cwd=tmp_path)
    assert r.returncode == 2 and "missing.json" in r.stderr
    # A task whose input is refused is a record with its error, not a failed sweep.
    spec.write_text(json.dumps({"tasks": [
        {"kind": "waterbomb", "n": 2, "theta0": 0.5},
        {"kind": "check", "pattern": {"generator": "miura_ori", "rows": 2, "colz": 3}}]}))
    r = run_cli(str(spec), "--out", str(tmp_path / "e.jsonl"), "--workers", "1", cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    records = {json.loads(line)["task"]["kind"]: json.loads(line) for line in (tmp_path / "e.jsonl").read_text().splitlines()}
    assert records["waterbomb"]["error"]["type"] == "InputError" and "n" in records["waterbomb"]["error"]["message"]
    assert records["check"]["error"]["type"] == "TypeError" and "colz" in records["check"]["error"]["message"]
