"""A scenario read once (tumble.load) and run any number of times (Model.run)."""

from __future__ import annotations

import math
import os
from typing import Any, Dict, List, Optional, Union

import numpy as np

from tumble import _tumble
from tumble._errors import IntegrationError
from tumble._source import Scenario, Values, overrides, scenario_source

#: Where a run stopped (Model.run(stop_at=...)): ``state.t`` is its time, s; Model.run(start=
#: state) goes on from it. ``state.save(path)`` writes it to a file that Model.load_state(path)
#: (of the same scenario and set= values) or ``tumble run --resume`` goes on from.
State = _tumble.State


class Result:
    """The rows of a run and what happened on the way.

    ``result["ball.vx"]`` is a column (a numpy view of ``result.data``, no copy), ``result.t``
    the times; the columns are the trajectory CSV's, in its order (docs/scenario.md, "Output"),
    with the same values bit for bit.
    """

    def __init__(self, output: Dict[str, Any]):
        #: The column names, the trajectory CSV's header.
        self.columns: List[str] = output["columns"]
        #: All rows, float64, shape (rows, columns), row-major.
        self.data: np.ndarray = output["data"]
        #: Contact events (mode changes, impacts) and the scenario's own ``events:``, in time
        #: order, as events.csv has them: dicts with t (s), source (the contact's name, or
        #: "event") and what.
        self.events: List[Dict[str, Any]] = output["events"]
        #: Jumps at breakpoints (impulses, locks, motor starts): dicts with t, what, KE_before,
        #: KE_after (J) and impulses ({joint: [Fx, Fy, Fz, Mx, My, Mz]}, N s and N m s, world).
        self.jumps: List[Dict[str, Any]] = output["jumps"]
        #: The run's report: completed, failure, t_reached, rows, integrator, rtol, atol,
        #: accepted_steps, rejected_steps, rhs_evaluations, wall_seconds, E0, max_energy_change,
        #: energy_drift (over the larger of |E0| and the largest KE), L0,
        #: max_angular_momentum_change, angular_momentum_drift, max_orthonormality_error, ...
        #: (the numbers `tumble run` prints).
        self.summary: Dict[str, Any] = output["summary"]
        #: Where a run given stop_at stopped, to go on from; None for a run to the end.
        self.state: Optional[State] = output["state"]
        self._index = {name: k for k, name in enumerate(self.columns)}

    @property
    def t(self) -> np.ndarray:
        """The rows' times, s."""
        return self.data[:, 0]

    @property
    def completed(self) -> bool:
        """Whether the run reached its end (or its stop_at, or an event with stop: true)."""
        return bool(self.summary["completed"])

    def __getitem__(self, column: str) -> np.ndarray:
        try:
            return self.data[:, self._index[column]]
        except KeyError:
            raise KeyError(f"no column {column!r}; the columns are {', '.join(self.columns)}") from None

    def __contains__(self, column: object) -> bool:
        return column in self._index

    def __len__(self) -> int:
        return self.data.shape[0]

    def to_pandas(self) -> Any:
        """The rows as a pandas DataFrame, one column per trajectory column (needs pandas)."""
        import pandas

        return pandas.DataFrame(self.data, columns=self.columns, copy=False)

    def __repr__(self) -> str:
        t = self.t
        span = f"t = {t[0]:g} to {t[-1]:g} s" if len(t) else "no rows"
        return f"<tumble.Result: {len(self)} rows x {len(self.columns)} columns, {span}>"


class Model:
    """A scenario read and built once (tumble.load); each run() starts afresh from it. Runs of
    one model may go on in several Python threads at once: the integration releases the GIL."""

    def __init__(self, loaded: Any):
        self._loaded = loaded

    @property
    def name(self) -> str:
        """The scenario's name."""
        return self._loaded.name

    @property
    def file(self) -> str:
        """The scenario's file (or the name YAML text goes by in messages)."""
        return self._loaded.file

    @property
    def parameters(self) -> Dict[str, float]:
        """The parameters' values, after set=."""
        return dict(self._loaded.parameters)

    @property
    def bodies(self) -> List[str]:
        """The bodies' names, in the file's order."""
        return list(self._loaded.bodies)

    @property
    def columns(self) -> List[str]:
        """The columns a run's result has (the trajectory CSV's header)."""
        return list(self._loaded.columns)

    @property
    def planar(self) -> bool:
        """Whether the scenario is stated in the plane (planar: true)."""
        return bool(self._loaded.planar)

    @property
    def duration(self) -> float:
        """simulate.duration, s."""
        return self._loaded.t_end - self._loaded.t0

    def run(self, *, stop_at: Optional[float] = None, start: Optional[State] = None) -> Result:
        """Integrates the scenario, as ``tumble run`` does, and returns its rows.

        stop_at: stop at the end of the first accepted step at or after this time (s); the
            result's ``state`` is where it stopped.
        start: go on from a state that a run of this model stopped at; the result has the rows
            after it, and rows before + rows after are the uninterrupted run's, bit for bit.

        Raises tumble.IntegrationError (with the rows so far as ``.result``) where the
        integration fails. Ctrl-C (or any signal handler's exception) stops a long run within
        about 0.05 s and raises KeyboardInterrupt (the handler's exception), with the rows so far
        as its ``.result``.
        """
        stop = math.inf if stop_at is None else float(stop_at)
        if math.isnan(stop):
            raise ValueError("stop_at: give a time, s")
        try:
            output = self._loaded.run(stop, start)
        except BaseException as stopped:
            partial = getattr(stopped, "_tumble_partial", None)
            if partial is not None:
                del stopped._tumble_partial
                stopped.result = Result(partial)  # type: ignore[attr-defined]
            raise
        result = Result(output)
        if not result.completed:
            raise IntegrationError(f"integration failed: {result.summary['failure']}", result)
        return result

    def load_state(self, path: Union[str, "os.PathLike[str]"]) -> State:
        """Reads a state that State.save (or ``tumble run --stop-at T --save-state FILE``) wrote,
        for ``run(start=...)`` of this model: the rows after it are the uninterrupted run's, bit
        for bit. Raises ValueError for a file that is not a whole state, or a state of another
        scenario or of other set= values (docs/checkpoints.md)."""
        return self._loaded.load_state(os.fspath(path))

    def __repr__(self) -> str:
        return f"<tumble.Model {self.name!r} from {self.file!r}: bodies {', '.join(self.bodies)}>"


def load(scenario: Scenario, *, set: Optional[Values] = None) -> Model:  # noqa: A002 (the CLI's --set)
    """Reads and builds a scenario (docs/scenario.md): a YAML file's path, or the YAML text.

    set: parameter values, {name: number or expression}, as ``tumble run --set NAME=VALUE``.

    Raises tumble.ScenarioError, whose text is ``FILE:LINE:COL: KEY: why``, for an invalid
    scenario; ValueError for a set= name that is not one of its parameters.
    """
    source, is_text, name = scenario_source(scenario)
    return Model(_tumble.load(source, is_text, name, overrides(set)))
