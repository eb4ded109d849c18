"""The cylindrical and the universal (Hooke) joint from Python: their own columns in a run and
their coordinates in tumble.modes, against the closed forms the C++ suite holds them to
(tests/cylindrical_joint_test.cpp, tests/universal_joint_test.cpp)."""

from __future__ import annotations

import math

import numpy as np
import pytest

import tumble

G = 9.81


def test_a_shaft_pushed_and_twisted_slides_and_turns_apart():
    # A 2 kg box on a shaft along x through its COM: x = F t^2 / (2 m), theta = T t^2 / (2 I).
    m, b, c, F, T = 2.0, 0.2, 0.3, 3.0, 0.5
    I_x = m * (b * b + c * c) / 12
    result = tumble.load(f"""tumble: 1
gravity: [0, 0, -{G}]
bodies:
  box: {{shape: box, size: [0.5, {b}, {c}], mass: {m}, position: [0, 0, 0]}}
joints:
  shaft: {{type: cylindrical, body: box, at: [0, 0, 0], axis: [1, 0, 0]}}
forces:
  - {{type: force, name: push, body: box, value: [{F}, 0, 0]}}
  - {{type: torque, name: twist, body: box, value: [{T}, 0, 0]}}
simulate: {{duration: 2, integrator: dop853, rtol: 1e-12, atol: 1e-14, output_every: 0.1}}
""").run()
    t = result.t
    for name in ("shaft.angle", "shaft.rate", "shaft.travel", "shaft.speed"):
        assert name in result.columns
    np.testing.assert_allclose(result["shaft.travel"], F * t * t / (2 * m), rtol=0, atol=1e-12)
    np.testing.assert_allclose(result["shaft.angle"], T * t * t / (2 * I_x), rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(result["shaft.Fx"], 0.0, atol=1e-12 * m * G)


def test_a_box_on_a_hooke_joint_has_a_frequency_about_each_axis():
    m, a, b, c, l = 3.0, 0.2, 0.5, 0.3, 0.6
    found = tumble.modes(f"""tumble: 1
gravity: [0, 0, -{G}]
bodies:
  box: {{shape: box, size: [{a}, {b}, {c}], mass: {m}, position: [0, 0, -{l}]}}
joints:
  cross: {{type: universal, body: box, at: [0, 0, 0], axes: [[1, 0, 0], [0, 1, 0]]}}
simulate: {{duration: 1}}
""")
    assert found.coordinates == ["cross.angle1", "cross.angle2", "cross.rate1", "cross.rate2"]
    I_1 = m * (b * b + c * c) / 12 + m * l * l
    I_2 = m * (a * a + c * c) / 12 + m * l * l
    expected = sorted([math.sqrt(m * G * l / I_1), math.sqrt(m * G * l / I_2)])
    assert sorted(found.natural_frequency) == pytest.approx(expected, rel=1e-12)
    assert found.verdict == "stable"
