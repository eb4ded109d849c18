"""Every example run from Python gives the command line's trajectory CSV bit for bit, and the
same events and jumps."""

from __future__ import annotations

import csv
import io

import pytest
import tumble
from conftest import all_examples, csv_text, example_id, g17, run_cli


@pytest.mark.parametrize("scenario", all_examples(), ids=example_id)
def test_a_python_run_is_the_command_lines_csv_bit_for_bit(scenario, cli_out):
    cli = run_cli("run", str(scenario), "--out", str(cli_out))
    assert cli.returncode == 0, cli.stderr
    model = tumble.load(scenario)
    result = model.run()
    trajectories = [p for p in cli_out.rglob("*.csv") if not p.name.endswith("_events.csv")
                    and "events" not in p.name]
    assert len(trajectories) == 1, trajectories
    expected = trajectories[0].read_text()
    assert result.columns == expected.split("\n", 1)[0].split(",")
    # The 17 significant digits of the CSV read back to the same doubles: equal text is equal
    # bits (and a nan or -0 is printed as such).
    assert csv_text(result) == expected
    assert result.summary["rows"] == len(result) == expected.count("\n") - 1

    events_files = [p for p in cli_out.rglob("*.csv") if p not in trajectories]
    rows = list(csv.DictReader(io.StringIO(events_files[0].read_text()))) if events_files else []
    expected_events = [(r["t"], r["source"], r["what"]) for r in rows if r["source"] != "jump"]
    assert [(g17(e["t"]), e["source"], e["what"]) for e in result.events] == expected_events
    expected_jumps = [(r["t"], r["what"], r["KE_before"], r["KE_after"]) for r in rows
                      if r["source"] == "jump"]
    assert [(g17(j["t"]), j["what"], g17(j["KE_before"]), g17(j["KE_after"]))
            for j in result.jumps] == expected_jumps
    # An impact's numbers, as events.csv has them.
    expected_impacts = [(r["t"], r["KE_before"], r["KE_after"], r["approach_speed"],
                         r["rebound_speed"], r["Px"], r["Py"], r["Pz"])
                        for r in rows if r["source"] not in ("jump", "event") and r["approach_speed"]]
    assert [(g17(e["t"]), g17(e["KE_before"]), g17(e["KE_after"]), g17(e["approach_speed"]),
             g17(e["rebound_speed"]), *(g17(p) for p in e["impulse"]))
            for e in result.events if "approach_speed" in e] == expected_impacts
