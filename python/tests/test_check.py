"""check(): the kernel's verdict, equal to what `rigidfold check --json` prints."""
import os

import pytest

import rigidfold
from conftest import SOURCE_DIR, bundled

TIMING_KEYS = {"seconds", "exploration_seconds"}


def without_timings(value):
    if isinstance(value, dict):
        return {k: without_timings(v) for k, v in value.items() if k not in TIMING_KEYS}
    if isinstance(value, list):
        return [without_timings(v) for v in value]
    return value


def test_corrugated_p_is_foldable_with_one_dof(cli):
    path = bundled("corrugated_p_rigid.fold")
    r = rigidfold.check(rigidfold.load(path))
    assert r["verdict_class"] == "foldable"
    assert r["rigidly_foldable"] is True
    assert r["is_proof"] is True
    assert r["dof"] == 1
    assert r["model"] == "multiplier-propagation"
    assert r["reason"].startswith("rigidly foldable, 1 DOF")
    expected = cli("check", path)
    assert r["verdict_class"] == expected["verdict_class"]
    assert r["reason"] == expected["reason"]


BUNDLED_NAMES = sorted(n for n in os.listdir(os.path.join(SOURCE_DIR, "data", "bundled")) if n.endswith(".fold"))


@pytest.mark.parametrize("use_assignment", [True, False])
@pytest.mark.parametrize("name", BUNDLED_NAMES)
def test_check_equals_the_cli_bit_for_bit(cli, name, use_assignment):
    path = bundled(name)
    r = rigidfold.check(rigidfold.load(path), use_assignment=use_assignment, source=path)
    args = ["check", path] + ([] if use_assignment else ["--ignore-assignment"])
    expected = cli(*args)
    del expected["file"]
    assert without_timings(r) == without_timings(expected)


def test_coordinate_tolerance_equals_the_cli_and_is_checked(cli):
    path = bundled("miura_4x4_alpha60.fold")
    for given, flag in ((0.0, "exact"), (1e-3, "0.001")):
        r = rigidfold.check(rigidfold.load(path), coordinate_tolerance=given, source=path)
        expected = cli("check", path, "--tolerance", flag)
        del expected["file"]
        assert without_timings(r) == without_timings(expected)
    assert "stated with --tolerance" in r["coordinate_precision"]
    for bad in (-1.0, float("nan"), float("inf")):
        with pytest.raises(ValueError, match="coordinate_tolerance"):
            rigidfold.check(rigidfold.load(path), coordinate_tolerance=bad)


def test_not_foldable_assignment_is_a_proof():
    # Square twist type 1 (seed 001): its assignment admits no rigid motion.
    r = rigidfold.check(rigidfold.square_twist("type1"))
    assert r["verdict_class"] == "not foldable (proof)"
    assert r["is_proof"] is True and r["dof"] == 0
    assert r["obstruction"] is not None
    free = rigidfold.check(rigidfold.square_twist("type1"), use_assignment=False)
    assert free["rigidly_foldable"] is True


def test_check_releases_the_gil():
    # The general model on the modified square twist type 1M takes ~0.5 s. While it runs, this
    # thread must keep running Python code: it could not if the GIL were held.
    import threading
    import time

    pattern = rigidfold.square_twist("type1m")
    span = {}

    def work():
        span["start"] = time.perf_counter()
        span["result"] = rigidfold.check(pattern)
        span["end"] = time.perf_counter()

    worker = threading.Thread(target=work)
    stamps = []
    worker.start()
    while worker.is_alive():
        stamps.append(time.perf_counter())
    worker.join()
    assert span["end"] - span["start"] > 0.1
    inside = [t for t in stamps if span["start"] + 0.02 < t < span["end"] - 0.02]
    assert len(inside) > 1000
    assert span["result"]["verdict_class"] == "not foldable (evidence)"


def test_ctrl_c_stops_a_long_check():
    # A check of the corpus hyperbolic paraboloid (seconds; minutes under AddressSanitizer) in a
    # child interpreter that sends itself SIGINT a quarter second in: KeyboardInterrupt must come
    # out of the call itself (no result), not after the whole run.
    import subprocess
    import sys
    import textwrap

    code = textwrap.dedent(f"""
        import os, signal, threading, time
        import rigidfold
        pattern = rigidfold.load({os.path.join(SOURCE_DIR, 'tests', 'data', 'corpus', 'origami-simulator', 'hypar.svg')!r})
        threading.Timer(0.25, os.kill, (os.getpid(), signal.SIGINT)).start()
        start = time.monotonic()
        result = None
        try:
            result = rigidfold.check(pattern)
        except KeyboardInterrupt:
            print("interrupted", time.monotonic() - start - 0.25)
        else:
            print("finished", time.monotonic() - start)
        """)
    run = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=600)
    assert run.returncode == 0, run.stderr
    words = run.stdout.split()
    assert words[0] == "interrupted", run.stdout
    assert float(words[1]) < 15.0, run.stdout  # seconds from the signal to the exception
