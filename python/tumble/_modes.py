"""The modes of a scenario's initial state (tumble.modes): the command line's ``tumble modes``,
as numbers."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Dict, List, Optional

import numpy as np

from tumble import _tumble
from tumble._source import Scenario, Values, overrides, scenario_source


@dataclass(frozen=True)
class Modes:
    """The linearisation about an equilibrium or a steady motion, and its modes (docs/modes.md).

    Per mode i, in the summary's order (growing first, then by natural frequency), a conjugate
    pair once: ``eigenvalues[i]`` (complex, 1/s), ``kinds[i]`` ("growing", "oscillating",
    "damped oscillation", "decaying", "decaying twin", "neutral"), ``natural_frequency``
    (rad/s), ``damped_frequency`` (rad/s), ``damping_ratio`` (NaN for a decaying twin, which
    decays without damping), ``growth_rate`` (1/s), ``twin_of[i]`` (a decaying twin's growing
    mode, numbered from 1 as the summary numbers them; None for the others), and ``shapes[i]``
    over ``coordinates`` (complex; the largest position 1 at phase 0). ``verdict`` is "stable",
    "marginal" or "unstable", ``verdict_text`` the summary's line. ``symmetries`` and
    ``symmetry_rates`` (rad/s) are the steady motion's turns; ``drifting`` the ignorable
    positions that move, by name, at their rates (a free prism's turn about its spin axis);
    ``equilibrium`` is true when there are neither. ``neutral_symmetries`` are the turns taken
    out at no rate; ``ignorable`` the positions set aside. ``csv`` is the text of
    STEM_modes.csv, byte for byte.
    """

    coordinates: List[str]
    units: List[str]
    ignorable: List[str]
    equilibrium: bool
    drifting: Dict[str, float]
    symmetries: List[str]
    symmetry_rates: np.ndarray
    neutral_symmetries: List[str]
    eigenvalues: np.ndarray
    kinds: List[str]
    twin_of: List[Optional[int]]
    natural_frequency: np.ndarray
    damped_frequency: np.ndarray
    damping_ratio: np.ndarray
    growth_rate: np.ndarray
    shapes: np.ndarray
    verdict: str
    verdict_text: str
    csv: str

    @property
    def frequency_hz(self) -> np.ndarray:
        """The damped frequencies in Hz (0 for a mode that does not oscillate)."""
        return self.damped_frequency / (2 * np.pi)

    @property
    def period(self) -> np.ndarray:
        """The damped periods, s (NaN for a mode that does not oscillate: the CSV's field is
        empty)."""
        oscillates = self.damped_frequency > 0
        safe = np.where(oscillates, self.damped_frequency, 1.0)
        return np.where(oscillates, 2 * np.pi / safe, np.nan)


def modes(scenario: Scenario, *, set: Optional[Values] = None) -> Modes:  # noqa: A002
    """The modes of the scenario's initial state, as ``tumble modes`` finds them. Raises
    tumble.NotSteadyError where the command exits with status 6 (neither an equilibrium nor a
    steady motion, or a contact with no linearisation) and tumble.ScenarioError for an invalid
    scenario."""
    source, is_text, name = scenario_source(scenario)
    return Modes(**_tumble.modes(source, is_text, name, overrides(set)))
