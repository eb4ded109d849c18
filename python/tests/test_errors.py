"""Errors carry what the command line says and where: the file, line, column and key."""

from __future__ import annotations

import pytest
import tumble
from conftest import EXAMPLES, csv_text, run_cli

BOX = """tumble: 1
gravity: [0, 0, 0]
bodies:
  b: {shape: box, size: [4, 1, 2], mass: 12, angular_velocity: [0, 0.01, 1]}
simulate: SIMULATE
"""
BAD_MASS = """tumble: 1
parameters:
  m: 2
bodies:
  b:
    mass: -m
    shape: sphere
    radius: 1
simulate: {duration: 1}
"""


def test_a_scenario_error_names_the_file_line_column_and_key_as_the_command_line(tmp_path):
    path = tmp_path / "bad.yaml"
    path.write_text(BAD_MASS)
    with pytest.raises(tumble.ScenarioError) as raised:
        tumble.load(path)
    error = raised.value
    assert (error.file, error.line, error.column, error.key) == (str(path), 6, 11, "bodies.b.mass")
    cli = run_cli("run", str(path), "--out", str(tmp_path))
    assert cli.returncode == 3
    assert cli.stderr == str(error) + "\n"
    assert str(error).startswith(f"{path}:6:11: bodies.b.mass: ")
    assert isinstance(error, tumble.TumbleError) and isinstance(error, ValueError)


def test_yaml_text_is_named_in_its_messages():
    with pytest.raises(tumble.ScenarioError) as raised:
        tumble.load(BAD_MASS)
    assert str(raised.value).startswith("<scenario>:6:11: bodies.b.mass: ")
    assert raised.value.why in str(raised.value)


def test_a_file_that_cannot_be_read_is_a_scenario_error_at_line_0(tmp_path):
    missing = tmp_path / "missing.yaml"
    with pytest.raises(tumble.ScenarioError) as raised:
        tumble.load(missing)
    assert (raised.value.file, raised.value.line, raised.value.column) == (str(missing), 0, 0)
    # The YAML's own syntax errors are located too.
    with pytest.raises(tumble.ScenarioError) as raised:
        tumble.load("tumble: 1\nbodies: [\n")
    assert raised.value.line > 0


def test_an_error_at_a_set_value_is_located_and_an_unknown_name_is_a_value_error():
    assert tumble.load(BAD_MASS, set={"m": -2}).parameters["m"] == -2.0  # its mass -m is 2
    with pytest.raises(tumble.ScenarioError) as raised:
        tumble.load(BAD_MASS.replace("mass: -m", "mass: m"), set={"m": -2})
    assert (raised.value.line, raised.value.key) == (6, "bodies.b.mass")
    with pytest.raises(ValueError, match="no parameter nope"):
        tumble.load(BAD_MASS, set={"nope": 1})


def test_a_failed_integration_raises_with_the_rows_so_far(tmp_path):
    text = BOX.replace("SIMULATE", "{duration: 20, rtol: 1e-10, max_steps: 25}")
    with pytest.raises(tumble.IntegrationError) as raised:
        tumble.load(text).run()
    result = raised.value.result
    assert "max_steps" in str(raised.value)
    assert not result.completed and result.t[-1] < 20.0
    assert len(result) == result.summary["rows"] > 1
    # The same rows as the partial CSV the command line leaves (exit 4).
    path = tmp_path / "short.yaml"
    path.write_text(text)
    cli = run_cli("run", str(path), "--out", str(tmp_path))
    assert cli.returncode == 4
    assert csv_text(result) == (tmp_path / "short.csv").read_text()


def test_find_says_when_the_condition_is_the_same_at_both_ends():
    with pytest.raises(tumble.FindError) as raised:
        tumble.find(EXAMPLES / "sweeps" / "ramp_critical_friction.yaml", {"mu": (0.9, 1.0)},
                    "count(ramp_cylinder.slides) > 0")
    assert raised.value.same_at_both_ends


def test_sweep_arguments_that_do_not_fit_the_scenario_are_value_errors():
    prism = EXAMPLES / "tumbling_prism.yaml"
    with pytest.raises(ValueError, match="vary nope=0:1:2: no parameter nope in .*tumbling_prism"):
        tumble.sweep(prism, "nope=0:1:2", {"w": "final(prism.w1)"})
    with pytest.raises(ValueError, match="record "):
        tumble.sweep(prism, {"a": (3, 4, 2)}, {"w": "final(nosuch.w1)"})
    with pytest.raises(ValueError, match="is varied twice"):
        tumble.sweep(prism, ["a=3:4:2", "a=3:4:2"], {"w": "final(prism.w1)"})


def test_a_file_without_end_is_refused_at_the_scenario_limit():
    # The red team's tumble.load('/dev/zero') read until memory ran out.
    with pytest.raises(tumble.ScenarioError) as raised:
        tumble.load("/dev/zero")
    assert str(raised.value) == (
        "/dev/zero:0:0: goes on past the limit of 64 MiB (67108864 bytes) for a scenario file "
        "(set TUMBLE_MAX_SCENARIO_MIB to a larger number of MiB to raise it)")
    assert raised.value.file == "/dev/zero"


def test_a_sweep_of_more_threads_than_the_limit_is_a_value_error():
    # threads=10000 aborted the interpreter (an uncaught std::system_error) under a memory limit.
    for threads in (257, 10000):
        with pytest.raises(ValueError) as raised:
            tumble.sweep(EXAMPLES / "tumbling_prism.yaml", "a=3:5:2", ["w=final(E)"],
                         threads=threads)
        assert str(raised.value) == (
            f"threads: {threads} is out of range: expected 0 (every core) or 1 to 256 (the limit "
            "on a sweep's threads)")


def test_counts_and_seeds_out_of_range_are_value_errors_naming_the_range():
    # seed=-1 or 2**64, and any count past 64 bits, was the binding's "incompatible function
    # arguments" TypeError, naming neither the argument nor its range; random=10**9 went on to
    # draw a billion points (the command line's --random stops at ten million); threads=-1 was
    # taken as every core.
    prism = EXAMPLES / "tumbling_prism.yaml"
    for seed in (-1, 2**64):
        with pytest.raises(ValueError) as raised:
            tumble.sweep(prism, "a=3:5", ["w=final(E)"], seed=seed, random=2)
        assert str(raised.value) == (
            f"seed: {seed} is out of range: expected a whole number from 0 to "
            "18446744073709551615")
    for random in (-1, 10**9, 2**70):
        with pytest.raises(ValueError) as raised:
            tumble.sweep(prism, "a=3:5", ["w=final(E)"], random=random)
        assert str(raised.value) == (
            f"random: {random} is out of range: expected 0 (the grid) or 1 to 10000000 points "
            "(the most a sweep holds)")
    for threads in (-1, 2**70):
        with pytest.raises(ValueError, match=f"threads: {threads} is out of range"):
            tumble.sweep(prism, "a=3:5:2", ["w=final(E)"], threads=threads)
