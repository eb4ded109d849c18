"""tumble.sweep, tumble.find and tumble.inertia mean what the command line's sweep, find and
inertia do: the same sweep.csv, bracket and mass properties; the GIL is released while they
run, so Python threads run them side by side."""

from __future__ import annotations

import _thread
import math
import re
import sys
import tempfile
import threading

import numpy as np
import pytest
import tumble
from conftest import EXAMPLES, run_cli

FLIP = EXAMPLES / "sweeps" / "prism_flip_time.yaml"
RAMP = EXAMPLES / "sweeps" / "ramp_critical_friction.yaml"


def test_a_sweep_is_the_command_lines_sweep_csv_byte_for_byte(cli_out):
    cli = run_cli("sweep", str(FLIP), "--vary", "decades=2:5:4", "--record",
                  "flip=first(prism.w3 < 0)", "--set", "a=4", "--threads", "2",
                  "--out", str(cli_out))
    assert cli.returncode == 0, cli.stderr
    swept = tumble.sweep(FLIP, {"decades": (2, 5, 4)}, {"flip": "first(prism.w3 < 0)"},
                         set={"a": 4}, threads=1)
    assert swept.csv == (cli_out / "sweep.csv").read_text()
    assert list(swept["decades"]) == [2.0, 3.0, 4.0, 5.0]
    assert swept["status"] == ["ok"] * 4
    # Each decade of tilt adds ln(10) / lambda to the flip time, lambda = Omega sqrt((I_k - I_i)
    # (I_j - I_k) / (I_i I_j)) = sqrt(12 * 3 / (5 * 20)) = 0.6 rad/s (examples/sweeps/
    # prism_flip_time.yaml), to within the exponential's constant's change: 1%.
    steps = np.diff(swept["flip"])
    assert np.allclose(steps, math.log(10) / 0.6, rtol=1e-2)


def test_random_points_are_the_command_lines():
    cli_args = ["--vary", "mu=0.1:0.3", "--random", "5", "--seed", "7", "--record",
                "slides=count(ramp_cylinder.slides)"]
    with tempfile.TemporaryDirectory() as out:
        cli = run_cli("sweep", str(RAMP), *cli_args, "--out", out)
        assert cli.returncode == 0, cli.stderr
        expected = open(f"{out}/sweep.csv").read()
    swept = tumble.sweep(RAMP, "mu=0.1:0.3", ["slides=count(ramp_cylinder.slides)"], random=5,
                         seed=7)
    assert swept.csv == expected
    # The cylinder slides where mu < tan(theta) / 3.
    mu_crit = math.tan(math.radians(30)) / 3
    assert list(swept["slides"] > 0) == list(swept["mu"] < mu_crit)


def test_find_brackets_the_critical_friction_as_the_command_line():
    found = tumble.find(RAMP, {"mu": (0.05, 0.5)}, "count(ramp_sphere.slides) > 0", tol=1e-10)
    cli = run_cli("find", str(RAMP), "--vary", "mu=0.05:0.5", "--when",
                  "count(ramp_sphere.slides) > 0", "--tol", "1e-10")
    assert cli.returncode == 0, cli.stderr
    lo, hi = map(float, re.search(r"bracket\s+\[(\S+), (\S+)\]", cli.stdout).groups())
    assert (found.lo, found.hi) == (lo, hi)
    assert found.at_lo and not found.at_hi and found.runs == len(found.history)
    # The chapter's worked example 2: a sphere rolls where mu >= (2/7) tan(theta).
    assert found.hi - found.lo <= 1e-10
    assert abs(found.value - 2 / 7 * math.tan(math.radians(30))) <= 1e-9


def test_find_reads_what_modes_says_the_masts_critical_spring():
    # Upright is stable for k > M g L / 2 (29.43 N m/rad), found on the verdict with no run.
    found = tumble.find(EXAMPLES / "modes" / "inverted_mast.yaml", {"k": (20, 40)}, "modes.stable",
                        tol=1e-8)
    assert not found.at_lo and found.at_hi
    assert abs(found.value - 3 * 9.81 * 2 / 2) <= 1e-9 * 29.43


def test_inertia_is_the_chapters_box_and_the_parallel_axis_theorem():
    # The prism: a box a x b x c = 4 x 1 x 2 m of 12 kg: I = m (b^2 + c^2) / 12, ... about its
    # COM; about a point d from it, I_O = I_G + m (|d|^2 E - d d^T).
    bodies = tumble.inertia(EXAMPLES / "tumbling_prism.yaml", about=[0.0, 0.0, 1.0])
    prism = bodies["prism"]
    m, a, b, c = 12.0, 4.0, 1.0, 2.0
    I_G = np.diag([m * (b * b + c * c) / 12, m * (a * a + c * c) / 12, m * (a * a + b * b) / 12])
    assert prism.mass == m
    np.testing.assert_allclose(prism.inertia_com_body, I_G, rtol=1e-15, atol=0)
    np.testing.assert_allclose(prism.principal_moments, sorted(np.diag(I_G)), rtol=1e-15)
    d = np.array([0.0, 0.0, -1.0])  # from O to the COM
    I_O = I_G + m * (d @ d * np.eye(3) - np.outer(d, d))
    np.testing.assert_allclose(prism.inertia_about_world, I_O, rtol=1e-15, atol=1e-15)
    # The same numbers the command line prints (to its 8 significant digits).
    cli = run_cli("inertia", str(EXAMPLES / "tumbling_prism.yaml"), "--about", "0", "0", "1")
    assert cli.returncode == 0
    lines = cli.stdout.splitlines()
    header = next(k for k, line in enumerate(lines) if "world axes (kg m^2)" in line)
    printed = [[float(x) for x in line.strip(" []").split()] for line in lines[header + 1:header + 4]]
    np.testing.assert_allclose(printed, I_O, rtol=1e-8)


def test_inertia_about_a_point_that_is_not_finite_is_refused():
    # As the command line refuses --about nan 0 0 (it printed NaN tensors with exit status 0).
    for bad in (math.nan, math.inf, -math.inf):
        with pytest.raises(ValueError, match=r"expected three finite numbers \(m, world\)"):
            tumble.inertia(EXAMPLES / "tumbling_prism.yaml", about=[0.0, bad, 0.0])


def test_a_sweep_releases_the_gil_while_it_runs():
    # With a switch interval of 100 s, a thread that holds the GIL is never made to drop it:
    # the main thread gets to count only where the sweep releases it while it runs.
    started, done = threading.Event(), threading.Event()
    swept = []

    def sweep() -> None:
        started.set()
        swept.append(tumble.sweep(FLIP, {"decades": (2, 8, 200)}, {"flip": "first(prism.w3 < 0)"},
                                  threads=1))
        done.set()

    interval = sys.getswitchinterval()
    sys.setswitchinterval(100.0)
    try:
        thread = threading.Thread(target=sweep)
        thread.start()
        started.wait()
        counted = 0
        while not done.is_set():
            counted += 1
            done.wait(0.001)  # blocks without the GIL: the sweep's thread can take it back
        thread.join()
    finally:
        sys.setswitchinterval(interval)
    assert swept[0]["status"] == ["ok"] * 200  # about 0.2 s of runs
    assert counted >= 10


def test_ctrl_c_stops_a_sweep():
    # Twenty thousand runs (tens of seconds) interrupted as Ctrl-C would, 0.3 s in: the sweep
    # held no GIL, so before, the KeyboardInterrupt came only once every run was done.
    timer = threading.Timer(0.3, _thread.interrupt_main)
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            tumble.sweep(FLIP, {"decades": (2, 8, 20000)}, {"flip": "first(prism.w3 < 0)"},
                         threads=2)
    finally:
        timer.cancel()


def _endless_prism() -> str:
    # The chapter's prism for a billion seconds at rtol 1e-12: days of work, which only Ctrl-C
    # ends, one row a second (max_rows raised to match).
    text = (EXAMPLES / "tumbling_prism.yaml").read_text()
    text = text.replace("duration: 20", "duration: 1e9\n  max_rows: 2000000000")
    text = text.replace("output_every: 0.05", "output_every: 1")
    return text.replace("rtol: 1e-8 ", "rtol: 1e-12").replace("atol: 1e-11", "atol: 1e-14")


@pytest.mark.parametrize("study", ["sweep", "find"])
def test_ctrl_c_stops_a_study_in_the_middle_of_a_run(study):
    # Before, a sweep looked at Ctrl-C only between runs, and find not at all: a KeyboardInterrupt
    # 0.3 s into either waited for the run going on, here for days (the test's timeout).
    text = _endless_prism()
    assert "max_rows: 2000000000" in text
    timer = threading.Timer(0.3, _thread.interrupt_main)
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            if study == "sweep":
                tumble.sweep(text, {"a": (4, 4.5, 2)}, {"w3": "final(prism.w3)"},
                             threads=1)
            else:
                tumble.find(text, {"a": (4, 4.5)}, "min(prism.w3) < 0")
    finally:
        timer.cancel()


def test_sweeps_in_two_python_threads_give_each_its_own_rows():
    expected = tumble.sweep(FLIP, {"decades": (2, 7, 6)}, {"flip": "first(prism.w3 < 0)"},
                            threads=1).csv
    results: list[str] = []

    def sweep() -> None:
        results.append(tumble.sweep(FLIP, {"decades": (2, 7, 6)},
                                    {"flip": "first(prism.w3 < 0)"}, threads=1).csv)

    threads = [threading.Thread(target=sweep) for _ in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert results == [expected, expected]
