"""Resident memory stays flat over 10,000 runs: every run's rows, events and state are freed
with its result, and a model loaded again and again leaves nothing behind."""

from __future__ import annotations

import gc

import tumble
from conftest import EXAMPLES

MiB = 1 << 20


def resident_bytes() -> int:
    with open("/proc/self/status") as status:
        for line in status:
            if line.startswith("VmRSS:"):
                return int(line.split()[1]) * 1024
    raise RuntimeError("no VmRSS in /proc/self/status")


def test_resident_memory_stays_flat_over_10000_runs():
    # The prism for 2 s with a row every 0.05 s: 41 rows x 31 columns, 10 kB of rows a result.
    text = (EXAMPLES / "tumbling_prism.yaml").read_text().replace("duration: 20", "duration: 2")
    model = tumble.load(text)
    for _ in range(1000):  # the allocator's pools and numpy's caches settle
        model.run()
    gc.collect()
    before = resident_bytes()
    for k in range(10_000):
        result = model.run(stop_at=1.0) if k % 2 else model.run()
        assert len(result) > 0
        if result.state is not None:
            model.run(start=result.state)
    gc.collect()
    grown = resident_bytes() - before
    # A leaked result would be 10 kB a run, 100 MB over the runs; a leaked state or event list a
    # few hundred bytes, several MiB. 2 MiB leaves room for the allocator's own growth.
    assert grown < 2 * MiB, f"resident memory grew by {grown / MiB:.2f} MiB over 10,000 runs"


def test_resident_memory_stays_flat_over_1000_loads():
    path = EXAMPLES / "cubli.yaml"
    for _ in range(100):
        tumble.load(path)
    gc.collect()
    before = resident_bytes()
    for _ in range(1000):
        tumble.load(path)
    gc.collect()
    grown = resident_bytes() - before
    # A leaked scenario and model would be tens of kB a load, tens of MB here.
    assert grown < 2 * MiB, f"resident memory grew by {grown / MiB:.2f} MiB over 1,000 loads"
