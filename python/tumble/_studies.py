"""Many runs of one scenario (tumble.sweep, tumble.find) and its bodies' mass properties
(tumble.inertia): the command line's sweep, find and inertia, as numbers."""

from __future__ import annotations

import os
from dataclasses import dataclass
from typing import Any, Dict, Iterable, List, Mapping, Optional, Sequence, Tuple, Union

import numpy as np

from tumble import _tumble
from tumble._source import Scenario, Values, number_text, overrides, scenario_source

#: A range as the command line's --vary takes it ("mu=0.1:0.4:4"), or {name: (start, stop,
#: count)} / {name: "start:stop:count"} (with random=, (lo, hi)).
Vary = Union[str, Sequence[str], Mapping[str, Union[str, Sequence[Union[float, int, str]]]]]
#: What each run records: {name: reduction} ({"t_flip": "first(prism.w3 < 0)"}), or the command
#: line's "NAME=REDUCTION" strings.
Record = Union[str, Sequence[str], Mapping[str, str]]


def _vary_arguments(vary: Vary) -> List[str]:
    if isinstance(vary, str):
        return [vary]
    if isinstance(vary, Mapping):
        arguments = []
        for name, bounds in vary.items():
            text = bounds if isinstance(bounds, str) else ":".join(number_text(b) for b in bounds)
            arguments.append(f"{name}={text}")
        return arguments
    return [str(v) for v in vary]


def _record_arguments(record: Optional[Record]) -> List[str]:
    if record is None:
        return []
    if isinstance(record, str):
        return [record]
    if isinstance(record, Mapping):
        return [f"{name}={reduction}" for name, reduction in record.items()]
    return [str(r) for r in record]


class SweepResult:
    """sweep.csv's columns: ``result["mu"]``, ``result["status"]``, ``result["t_flip"]``...

    The columns are run, the varied parameters, status ("ok", "failed", "invalid"), steps,
    E_drift, L_drift, each recorded value (nan where a run did not finish) and message; numbers
    are numpy arrays, status and message lists of str. ``csv`` is the text `tumble sweep` writes
    for the same arguments, byte for byte.
    """

    def __init__(self, output: Dict[str, Any]):
        self.columns: Dict[str, Any] = output["columns"]
        self.varied: List[str] = output["varied"]
        self.csv: str = output["csv"]
        self.threads: int = output["threads"]

    def __getitem__(self, column: str) -> Any:
        return self.columns[column]

    def __len__(self) -> int:
        return len(self.columns["run"])

    def to_csv(self, path: Union[str, "os.PathLike[str]"]) -> None:
        """Writes sweep.csv's text to path."""
        with open(path, "w", encoding="utf-8", newline="") as f:
            f.write(self.csv)

    def to_pandas(self) -> Any:
        """The runs as a pandas DataFrame (needs pandas)."""
        import pandas

        return pandas.DataFrame(self.columns)

    def __repr__(self) -> str:
        return f"<tumble.SweepResult: {len(self)} runs over {', '.join(self.varied)}>"


def sweep(
    scenario: Scenario,
    vary: Vary,
    record: Optional[Record] = None,
    *,
    set: Optional[Values] = None,  # noqa: A002 (the command line's --set)
    random: int = 0,
    seed: int = 1,
    threads: int = 0,
) -> SweepResult:
    """Runs the scenario at every point of a grid of its parameters, as ``tumble sweep``.

    vary: the ranges, e.g. ``{"mu": (0.1, 0.4, 4)}`` or ``"mu=0.1:0.4:4"`` (bounds may be
        expressions: "30 deg"); several make a grid whose first varies slowest.
    record: what each run records, e.g. ``{"t_flip": "first(prism.w3 < 0)"}`` (docs/sweeps.md:
        final, max, min, mean, time_of_max, first, count).
    set: parameters fixed for every run. random: instead of the grid, this many points drawn
        uniformly in [lo, hi) of each range (vary as {name: (lo, hi)}), seeded by seed.
    threads: threads to run on, 1 to 256 (0: every core, at most 256; more is a ValueError). The
        GIL is released while the runs go on.

    Raises tumble.ScenarioError where the scenario is invalid at its own values, ValueError for a
    range, a set= or a record that does not fit it. A run that fails or is invalid is a row.
    """
    source, is_text, name = scenario_source(scenario)
    return SweepResult(
        _tumble.sweep(source, is_text, name, overrides(set), _vary_arguments(vary),
                      _record_arguments(record), int(random), int(seed), int(threads))
    )


@dataclass(frozen=True)
class FindResult:
    """Where the condition changes: in [lo, hi], true or false at each end."""

    name: str  #: the parameter
    lo: float
    hi: float
    at_lo: bool  #: the condition at lo
    at_hi: bool  #: the condition at hi
    runs: int
    tolerance: float  #: the bracket's width is at most this
    history: List[Tuple[float, bool, int]]  #: each run: (value, condition, accepted steps)

    @property
    def value(self) -> float:
        """The bracket's middle."""
        return self.lo + 0.5 * (self.hi - self.lo)


def find(
    scenario: Scenario,
    vary: Union[str, Mapping[str, Sequence[Union[float, int, str]]]],
    when: str,
    *,
    set: Optional[Values] = None,  # noqa: A002
    tol: Optional[float] = None,
) -> FindResult:
    """The value of one parameter at which a yes/no outcome changes, by bisection, as
    ``tumble find``: e.g. ``find("cubli.yaml", {"w0": (95, 115)}, "min(corner.angle) < -pi/4")``.

    tol: the final bracket's width (default 1e-9 of the larger bound's magnitude).

    Raises tumble.FindError where the condition is the same at both ends or a run fails,
    tumble.ScenarioError and ValueError as sweep does.
    """
    arguments = _vary_arguments(vary)
    if len(arguments) != 1:
        raise ValueError(f"vary: find varies one parameter, not {len(arguments)}")
    source, is_text, name = scenario_source(scenario)
    found = _tumble.find(source, is_text, name, overrides(set), arguments[0], when,
                         None if tol is None else float(tol))
    return FindResult(**found)


@dataclass(frozen=True)
class BodyInertia:
    """A body's mass properties, as ``tumble inertia`` prints them (SI units)."""

    mass: float  #: kg
    com_body: np.ndarray  #: the COM in the body's frame, m
    com_world: np.ndarray  #: the COM in the world at t = 0, m
    inertia_com_body: np.ndarray  #: about the COM, body axes, kg m^2
    principal_moments: np.ndarray  #: ascending, kg m^2
    principal_axes: np.ndarray  #: as columns, body axes (a rotation)
    given: bool  #: the inertia was given by inertia: rather than computed from the shape
    about: Optional[np.ndarray] = None  #: the world point O of about=, m
    inertia_about_body: Optional[np.ndarray] = None  #: about O, body axes
    inertia_about_world: Optional[np.ndarray] = None  #: about O, world axes at t = 0
    principal_moments_about: Optional[np.ndarray] = None  #: about O


def inertia(
    scenario: Scenario,
    *,
    set: Optional[Values] = None,  # noqa: A002
    about: Optional[Iterable[float]] = None,
) -> Dict[str, BodyInertia]:
    """Each body's mass properties, {name: BodyInertia}, as ``tumble inertia``; with about=
    [x, y, z] (a world point at t = 0, m), also its inertia about that point by the parallel
    axis theorem. The scenario needs no simulate: section."""
    source, is_text, name = scenario_source(scenario)
    point = None if about is None else np.asarray(list(about), dtype=float)
    if point is not None and point.shape != (3,):
        raise ValueError("about: a point [x, y, z], m")
    bodies = _tumble.inertia(source, is_text, name, overrides(set), point)
    return {body: BodyInertia(**values) for body, values in bodies.items()}
