#!/usr/bin/env python3
"""Runs every example with its own integrator and with `integrator: auto`, and checks what
docs/integrators.md says of auto on them:
  - auto takes at most 1.2 times the steps of the example's own method;
  - where the example's method is dop853, auto is dop853 step for step: the same CSV, byte for
    byte (none of them is stiff);
  - elsewhere the two end within 1e3 rtol of each other (relative to max(1, |value|)), or, where
    they do not (a chaotic motion, whose errors grow apart), auto ends no further than the
    example's own method from a reference run (dop853 at rtol 1e-13);
  - the summary says which methods took the steps, and each switch.
    scripts/check_auto_on_examples.py TUMBLE_EXE
"""
import csv
import pathlib
import re
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent
STEP_RATIO = 1.2
AGREEMENT = 1e3  # times the example's rtol


def with_integrator(text, method, tolerances=None):
    """The scenario's text with its (first, uncommented) integrator replaced."""
    lines = text.split("\n")
    for i, line in enumerate(lines):
        code = line.split("#")[0]
        if re.search(r"integrator:\s*\w+", code):
            lines[i] = re.sub(r"integrator:\s*\w+", f"integrator: {method}", line, count=1)
            if tolerances:
                lines[i] = re.sub(r"rtol:\s*[-+.\deE]+", f"rtol: {tolerances[0]}", lines[i])
                lines[i] = re.sub(r"atol:\s*[-+.\deE]+", f"atol: {tolerances[1]}", lines[i])
            break
    else:
        raise SystemExit("no integrator key")
    if tolerances:
        lines = [re.sub(r"^(\s+)rtol:\s*[-+.\deE]+", rf"\g<1>rtol: {tolerances[0]}", l) for l in lines]
        lines = [re.sub(r"^(\s+)atol:\s*[-+.\deE]+", rf"\g<1>atol: {tolerances[1]}", l) for l in lines]
    return "\n".join(lines)


def run(exe, text, name, work):
    folder = work / name
    folder.mkdir(parents=True)
    scenario = folder / "scenario.yaml"
    scenario.write_text(text)
    done = subprocess.run([exe, "run", str(scenario), "--out", str(folder / "out")],
                          capture_output=True, text=True)
    if done.returncode != 0:
        raise SystemExit(f"{name}: exit {done.returncode}\n{done.stderr}")
    steps = int(re.search(r"steps\s+(\d+) accepted", done.stdout).group(1))
    rtol = re.search(r"rtol ([-+.\deE]+)", done.stdout)
    trajectories = sorted(p for p in (folder / "out").glob("*.csv") if p.name != "events.csv"
                          and not p.name.endswith("events.csv"))
    return steps, float(rtol.group(1)) if rtol else None, trajectories[0], done.stdout


def last_row(path):
    with open(path) as f:
        rows = list(csv.reader(f))
    return rows[0], [float(x) for x in rows[-1]]


def difference(a, b):
    header, x = last_row(a)
    _, y = last_row(b)
    return max(abs(p - q) / max(1.0, abs(q)) for p, q in zip(x, y))


def main():
    exe = sys.argv[1]
    examples = sorted(ROOT.glob("examples/*.yaml")) + sorted(ROOT.glob("examples/*/*.yaml"))
    failures = []
    with tempfile.TemporaryDirectory() as scratch:
        work = pathlib.Path(scratch)
        for path in examples:
            name = str(path.relative_to(ROOT / "examples")).replace("/", "_")[:-5]
            text = path.read_text()
            own_method = re.search(r"integrator:\s*(\w+)", "\n".join(
                l.split("#")[0] for l in text.split("\n"))).group(1)
            own_steps, rtol, own_csv, _ = run(exe, text, name + ".own", work)
            auto_steps, _, auto_csv, summary = run(exe, with_integrator(text, "auto"),
                                                   name + ".auto", work)
            note = f"{name}: {own_method} {own_steps} steps, auto {auto_steps}"
            if not re.search(r"^  methods +dop853 \d+ steps, radau5 \d+ steps", summary, re.M):
                failures.append(f"{note}: no methods line in the summary")
            switches = "".join(f"\n    {line.strip()}"
                               for line in re.findall(r"^  switch .*", summary, re.M))
            if auto_steps > STEP_RATIO * own_steps:
                failures.append(f"{note}: more than {STEP_RATIO} times the steps")
            if own_method == "dop853":
                if own_csv.read_bytes() != auto_csv.read_bytes():
                    failures.append(f"{note}: not dop853's CSV")
            elif rtol is not None:
                apart = difference(auto_csv, own_csv)
                note += f", ends {apart:.2e} apart"
                if apart > AGREEMENT * rtol:
                    _, _, reference_csv, _ = run(
                        exe, with_integrator(text, "dop853", ("1e-13", "1e-15")),
                        name + ".reference", work)
                    auto_error = difference(auto_csv, reference_csv)
                    own_error = difference(own_csv, reference_csv)
                    note += f" (from a reference: auto {auto_error:.2e}, {own_method} {own_error:.2e})"
                    if auto_error > own_error:
                        failures.append(f"{note}: further from the reference than {own_method}")
            print(note + switches)
    for failure in failures:
        print("FAILED", failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
