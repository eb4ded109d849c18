"""What the suite shares: where the sources and the tumble executable are, and the CSV text a
result makes (the trajectory CSV's, byte for byte, when the values are the same doubles)."""

from __future__ import annotations

import os
import pathlib
import subprocess
import sys

import pytest

SOURCE_DIR = pathlib.Path(os.environ.get("TUMBLE_SOURCE_DIR", pathlib.Path(__file__).parents[2]))
TUMBLE_EXE = os.environ.get("TUMBLE_EXE", str(SOURCE_DIR / "build" / "release" / "tumble"))
EXAMPLES = SOURCE_DIR / "examples"


def all_examples() -> list[pathlib.Path]:
    return sorted(EXAMPLES.rglob("*.yaml"))


def example_id(path: pathlib.Path) -> str:
    return str(path.relative_to(EXAMPLES).with_suffix(""))


def run_cli(*args: str, cwd: os.PathLike | str | None = None) -> subprocess.CompletedProcess:
    """The tumble executable with these arguments; its status, stdout and stderr."""
    return subprocess.run([TUMBLE_EXE, *args], capture_output=True, text=True, cwd=cwd)


def run_module(*args: str, cwd: os.PathLike | str | None = None) -> subprocess.CompletedProcess:
    """python3 -m tumble with these arguments, in a fresh interpreter."""
    return subprocess.run([sys.executable, "-m", "tumble", *args], capture_output=True, text=True,
                          cwd=cwd)


def g17(value: float) -> str:
    """A number as the CSVs print it: 17 significant digits (fmt's {:.17g}, C's %.17g)."""
    return "%.17g" % value


def csv_text(result) -> str:
    """The trajectory CSV that `tumble run` writes for these rows."""
    lines = [",".join(result.columns)]
    lines += [",".join(g17(v) for v in row) for row in result.data.tolist()]
    return "\n".join(lines) + "\n"


@pytest.fixture
def cli_out(tmp_path):
    """A fresh directory for the executable's files."""
    out = tmp_path / "cli"
    out.mkdir()
    return out
