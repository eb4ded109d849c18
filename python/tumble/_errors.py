"""The exceptions tumble raises (all are also tumble.TumbleError)."""

from __future__ import annotations

from typing import Any


class TumbleError(Exception):
    """Anything tumble itself refuses or cannot do."""


class ScenarioError(TumbleError, ValueError):
    """The scenario is invalid: str(error) is ``FILE:LINE:COL: KEY: why``, as the command line
    prints it, and the parts are attributes (line and column are 0 where the problem is the
    file itself, e.g. one that cannot be read)."""

    def __init__(self, message: str, file: str, line: int, column: int, key: str, why: str):
        super().__init__(message)
        self.file = file
        self.line = line
        self.column = column
        self.key = key
        self.why = why


class IntegrationError(TumbleError, RuntimeError):
    """The integration failed part way (a step size that underflows, a state that is no longer
    finite, too many steps or rows). ``result`` holds the rows computed until then (a
    tumble.Result, whose ``summary["failure"]`` says why and when)."""

    def __init__(self, message: str, result: Any):
        super().__init__(message)
        self.result = result


class FindError(TumbleError):
    """tumble.find could not bracket a change: the condition is the same at both ends of the
    range (``same_at_both_ends``), or a run was invalid or failed (``status`` is "invalid" or
    "failed", ``run_message`` why)."""

    def __init__(self, message: str, same_at_both_ends: bool, status: str, run_message: str):
        super().__init__(message)
        self.same_at_both_ends = same_at_both_ends
        self.status = status
        self.run_message = run_message


class NotSteadyError(TumbleError, ValueError):
    """tumble.modes: the initial state is neither an equilibrium nor a steady motion, or has a
    contact that has no linearisation (the command line's exit status 6); str(error) says which
    rate is off and by how much, or which contact and why."""
