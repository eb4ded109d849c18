"""python3 -m tumble is the command line: the same help, files, summary and exit statuses."""

from __future__ import annotations

from conftest import EXAMPLES, run_cli, run_module


def without_wall_time(text: str) -> str:
    return "\n".join(line for line in text.splitlines() if "wall time" not in line)


def test_help_is_the_command_lines():
    for args in (["--help"], ["run", "--help"], ["sweep", "--help"], ["--version"]):
        assert run_module(*args).stdout == run_cli(*args).stdout


def test_a_run_writes_the_same_files_and_summary(tmp_path):
    (tmp_path / "cli").mkdir()
    (tmp_path / "py").mkdir()
    scenario = str(EXAMPLES / "bouncing_ball.yaml")
    cli = run_cli("run", scenario, "--out", "out", cwd=tmp_path / "cli")
    module = run_module("run", scenario, "--out", "out", cwd=tmp_path / "py")
    assert cli.returncode == module.returncode == 0
    assert without_wall_time(module.stdout) == without_wall_time(cli.stdout)
    files = sorted(p.name for p in (tmp_path / "cli" / "out").iterdir())
    assert files == sorted(p.name for p in (tmp_path / "py" / "out").iterdir())
    assert "bouncing_ball_events.csv" in files
    for name in files:
        assert (tmp_path / "py" / "out" / name).read_bytes() == \
            (tmp_path / "cli" / "out" / name).read_bytes()


def test_exit_statuses_are_the_command_lines(tmp_path):
    bad = tmp_path / "bad.yaml"
    bad.write_text("tumble: 1\nbodies:\n  b: {shape: sphere, radius: -1, mass: 1}\n")
    cases = [
        ["run", str(bad)],                                         # 3: invalid scenario
        ["run"],                                                   # 2: bad command line
        ["sweep", str(EXAMPLES / "tumbling_prism.yaml"), "--vary", "nope=0:1:2"],  # 2
    ]
    for args in cases:
        cli, module = run_cli(*args, cwd=tmp_path), run_module(*args, cwd=tmp_path)
        assert module.returncode == cli.returncode != 0, args
        assert module.stderr == cli.stderr, args
