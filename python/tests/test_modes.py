"""tumble.modes: the linearisation from Python means what `tumble modes` prints, and its numbers
are the chapter's closed forms (to 1e-9 relative, the C++ suite's bar: the Jacobian is exact to
round-off)."""

from __future__ import annotations

import math
import pathlib

import numpy as np
import pytest

import tumble
from conftest import EXAMPLES, run_cli


def test_rolling_disk_wobbles_at_its_closed_form():
    # Upright, rolling at spin Omega: (I_d + M r^2) phi'' = (M g r - (I_a + M r^2) I_a Omega^2 / I_d)
    # phi; for a uniform disk (I_a = M r^2 / 2, I_d = M r^2 / 4), phi'' = (4/5)(g/r - 3 Omega^2) phi.
    r, g, omega = 0.3, 9.81, 10.0
    found = tumble.modes(EXAMPLES / "modes" / "rolling_disk.yaml", set={"Omega": omega})
    wobble = math.sqrt(0.8 * (3 * omega**2 - g / r))
    assert found.verdict == "stable"
    assert found.kinds == ["oscillating", "neutral", "neutral"]
    assert found.damped_frequency[0] == pytest.approx(wobble, rel=1e-9)
    assert found.eigenvalues[0].imag == pytest.approx(wobble, rel=1e-9)
    assert found.period[0] == pytest.approx(2 * math.pi / wobble, rel=1e-9)
    assert found.shapes.shape == (3, len(found.coordinates))
    assert abs(found.symmetry_rates[0]) == pytest.approx(omega, rel=1e-9)
    assert found.neutral_symmetries == ["the whole turning about the vertical"]
    assert found.ignorable == ["wheel.x", "wheel.y", "wheel.z"]


def test_falling_mast_is_unstable_at_its_growth_rate():
    M, L, r, g, k_ratio = 3.0, 2.0, 0.01, 9.81, 0.5
    I_O = M * (3 * r * r + L * L) / 12 + M * L * L / 4
    k = k_ratio * M * g * L / 2
    found = tumble.modes(EXAMPLES / "modes" / "inverted_mast.yaml", set={"k_ratio": k_ratio})
    assert found.verdict == "unstable"
    assert found.equilibrium
    assert found.growth_rate[0] == pytest.approx(math.sqrt((M * g * L / 2 - k) / I_O), rel=1e-9)
    assert found.coordinates == ["base.angle", "base.rate"]


def test_csv_is_the_commands(tmp_path: pathlib.Path):
    scenario = EXAMPLES / "modes" / "double_pendulum.yaml"
    done = run_cli("modes", str(scenario), "--out", str(tmp_path))
    assert done.returncode == 0, done.stderr
    written = next(tmp_path.glob("*_modes.csv")).read_text()
    assert tumble.modes(scenario).csv == written


def test_a_state_that_is_not_steady_raises_not_steady_error():
    with pytest.raises(tumble.NotSteadyError, match="base.angle moves at 0.01 rad/s"):
        tumble.modes(EXAMPLES / "inverted_mast.yaml")
    with pytest.raises(tumble.NotSteadyError, match="rests on an edge or a face"):
        tumble.modes(EXAMPLES / "box_slides_to_rest.yaml")
    assert issubclass(tumble.NotSteadyError, tumble.TumbleError)


def test_an_invalid_scenario_raises_scenario_error():
    with pytest.raises(tumble.ScenarioError):
        tumble.modes(EXAMPLES / "modes" / "bat.yaml", set={"M": -1})


def test_spinning_prism_is_a_steady_motion_with_a_growing_mode_and_its_twin():
    # About the intermediate axis (I = 5, 20, 17 spun about the third): growth
    # Omega sqrt((I2 - I1)(I3 - I2) / (I1 I3)) = 0.6 Omega, and its mirror, which decays without
    # damping. The set-aside turn about the spin axis moves at Omega: not an equilibrium.
    omega = 2.0
    found = tumble.modes(EXAMPLES / "modes" / "prism_axes.yaml", set={"axis": 3, "Omega": omega})
    assert not found.equilibrium
    assert found.drifting == {"prism.rz": pytest.approx(omega, rel=1e-15)}
    assert found.kinds[:2] == ["growing", "decaying twin"]
    assert found.twin_of[:2] == [None, 1]
    assert found.growth_rate[0] == pytest.approx(0.6 * omega, rel=1e-9)
    assert found.eigenvalues[1] == pytest.approx(-np.conj(found.eigenvalues[0]), rel=1e-9)
    assert math.isnan(found.damping_ratio[1])
    assert math.isnan(found.period[0]) and math.isnan(found.period[1])
    second_row = found.csv.splitlines()[2].split(",")
    assert second_row[1] == '"decaying twin"' and second_row[6] == "" and second_row[7] == ""
