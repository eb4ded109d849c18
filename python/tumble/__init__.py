"""tumble: rigid-body dynamics you can check, from Python.

    import tumble
    model = tumble.load("examples/tumbling_prism.yaml")
    result = model.run()
    result.t, result["prism.w1"]          # numpy arrays: the trajectory CSV's columns
    result.summary["energy_drift"]        # what tumble run's summary reports
    tumble.sweep("examples/tumbling_prism.yaml", {"tilt": (0.01, 0.1, 10)},
                 {"t_flip": "first(prism.w3 < 0)"})

The scenarios are the command line's (docs/scenario.md), and each function means what its
command does: load + Model.run is ``tumble run``, sweep and find ``tumble sweep`` and ``tumble
find``, inertia ``tumble inertia``, modes ``tumble modes``; ``python3 -m tumble`` is the command
line itself.
"""

from tumble._errors import (
    FindError,
    IntegrationError,
    NotSteadyError,
    ScenarioError,
    TumbleError,
)
from tumble._model import Model, Result, State, load
from tumble._modes import Modes, modes
from tumble._studies import BodyInertia, FindResult, SweepResult, find, inertia, sweep
from tumble._tumble import __version__

__all__ = [
    "BodyInertia",
    "FindError",
    "FindResult",
    "IntegrationError",
    "Model",
    "Modes",
    "NotSteadyError",
    "Result",
    "ScenarioError",
    "State",
    "SweepResult",
    "TumbleError",
    "__version__",
    "find",
    "inertia",
    "load",
    "modes",
    "sweep",
]
