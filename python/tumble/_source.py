"""How the functions take a scenario and its parameter values."""

from __future__ import annotations

import os
from typing import Mapping, Tuple, Union

#: A scenario: the path of a YAML file (str or os.PathLike), or the YAML text itself (a str with
#: more than one line).
Scenario = Union[str, "os.PathLike[str]"]
#: Parameter values, as ``--set NAME=VALUE`` gives them: numbers, or expressions as text
#: ("30 deg", "2*pi").
Values = Mapping[str, Union[float, int, str]]

#: How YAML text is named in error messages (``<scenario>:3:7: bodies[0].mass: ...``).
TEXT_NAME = "<scenario>"


def scenario_source(scenario: Scenario) -> Tuple[str, bool, str]:
    """(source, is_text, name) for tumble._tumble: a path, or text (a str with a newline)."""
    if isinstance(scenario, os.PathLike):
        return os.fspath(scenario), False, os.fspath(scenario)
    if not isinstance(scenario, str):
        raise TypeError(f"scenario: a path or YAML text, not {type(scenario).__name__}")
    if "\n" in scenario:
        return scenario, True, TEXT_NAME
    return scenario, False, scenario


def number_text(value: Union[float, int, str]) -> str:
    """A value as the expression that reads back to it: repr keeps every bit of a float."""
    if isinstance(value, str):
        return value
    if isinstance(value, bool):
        raise TypeError(f"a parameter's value is a number or an expression, not {value!r}")
    return repr(float(value)) if isinstance(value, float) else str(int(value))


def overrides(values: Values | None) -> list[tuple[str, str]]:
    """set={name: value} as the command line's --set NAME=VALUE pairs."""
    if values is None:
        return []
    return [(str(name), number_text(value)) for name, value in values.items()]
