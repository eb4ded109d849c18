"""Runs from Python: stopped and gone on from a saved state, run from several threads, and the
rows reaching numpy as one array."""

from __future__ import annotations

import _thread
import threading

import numpy as np
import pytest
import tumble
from conftest import EXAMPLES, csv_text


def same_events(a, b):
    """Events lists equal field by field, bit for bit (a point, a normal, an impulse: arrays)."""
    if len(a) != len(b):
        return False
    for x, y in zip(a, b):
        if x.keys() != y.keys():
            return False
        for key in x:
            if isinstance(x[key], np.ndarray):
                if not np.array_equal(x[key], y[key]):
                    return False
            elif x[key] != y[key]:
                return False
    return True


@pytest.mark.parametrize(("example", "t1"), [("tumbling_prism", 9.0), ("backspin_disk", 0.7),
                                              ("cubli", 0.7), ("planar/backspin_disk", 0.7)])
def test_a_run_gone_on_from_its_saved_state_is_the_uninterrupted_run(example, t1):
    model = tumble.load(EXAMPLES / f"{example}.yaml")
    whole = model.run()
    before = model.run(stop_at=t1)
    assert before.state is not None and before.state.t >= t1
    # It stops at a step's end: the rows before are those up to it, the rows after come after.
    after = model.run(start=before.state)
    assert after.state is None
    assert before.t[-1] <= before.state.t < after.t[0]
    # Bit for bit: the rows, the events and the books of the whole run.
    assert np.array_equal(np.vstack([before.data, after.data]), whole.data, equal_nan=True)
    assert same_events(after.events, whole.events) and after.jumps == whole.jumps
    for key in ("accepted_steps", "rhs_evaluations", "rows", "max_energy_change"):
        assert after.summary[key] == whole.summary[key], key
    # A state goes on again as often as asked.
    assert np.array_equal(model.run(start=before.state).data, after.data)


def test_ctrl_c_stops_a_long_run_and_keeps_its_rows():
    # Before, the KeyboardInterrupt came when the whole run was over (40 s later in the test): the
    # run holds no GIL, so Python's handler could not run until it returned. Here a run of hours
    # of simulated time (tens of seconds of work) is interrupted as Ctrl-C would, 0.3 s in.
    text = (EXAMPLES / "tumbling_prism.yaml").read_text()
    text = text.replace("duration: 20", "duration: 100000").replace("output_every: 0.05",
                                                                     "output_every: 1")
    text = text.replace("rtol: 1e-8 ", "rtol: 1e-12").replace("atol: 1e-11", "atol: 1e-14")
    model = tumble.load(text)
    timer = threading.Timer(0.3, _thread.interrupt_main)
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt) as stopped:
            model.run()
    finally:
        timer.cancel()
    result = stopped.value.result
    assert not result.completed
    assert result.summary["failure"].startswith("interrupted at t = ")
    assert 0 < result.summary["t_reached"] < 100000
    # The rows so far are the run's, one a second from 0, bit for bit those of a run stopped
    # there on purpose.
    assert len(result) >= 2
    assert np.array_equal(result.t, np.arange(len(result), dtype=float))
    stopped_there = model.run(stop_at=float(result.t[-1]))
    assert np.array_equal(stopped_there.data[: len(result)], result.data)


def test_a_state_goes_on_only_in_its_own_model():
    prism = EXAMPLES / "tumbling_prism.yaml"
    state = tumble.load(prism).run(stop_at=1.0).state
    with pytest.raises(ValueError, match="start: a state goes on only in the model"):
        tumble.load(prism).run(start=state)


def test_a_state_saved_to_a_file_goes_on_in_a_model_loaded_again(tmp_path):
    # The file is all that passes from the stopped run to the resumed one: a model loaded again
    # from the same scenario goes on from it, and the rows are the uninterrupted run's.
    path = EXAMPLES / "cubli_falls_back.yaml"
    whole = tumble.load(path).run()
    before = tumble.load(path).run(stop_at=0.3)
    before.state.save(tmp_path / "held.state")
    model = tumble.load(path)
    state = model.load_state(tmp_path / "held.state")
    assert state.t == before.state.t
    after = model.run(start=state)
    assert np.array_equal(np.vstack([before.data, after.data]), whole.data)
    assert [e["t"] for e in after.events] == [e["t"] for e in whole.events]
    assert [(j["t"], j["KE_after"]) for j in after.jumps] == [
        (j["t"], j["KE_after"]) for j in whole.jumps
    ]
    assert after.summary["rhs_evaluations"] == whole.summary["rhs_evaluations"]

    # Another set= value is another run; a file changed after it was written is no state.
    with pytest.raises(ValueError, match="its text or its set= values differ"):
        tumble.load(path, set={"t_lock": 0.002}).load_state(tmp_path / "held.state")
    text = (tmp_path / "held.state").read_text()
    (tmp_path / "edited.state").write_text(text.replace("integrator.t 0.", "integrator.t 1.", 1))
    with pytest.raises(ValueError, match="not a whole tumble checkpoint"):
        model.load_state(tmp_path / "edited.state")


def test_a_state_file_without_end_is_refused_at_its_limit(monkeypatch):
    # A state named /dev/zero was read until memory ran out; its limit is lowered to 1 MiB here
    # so that the test reads little.
    monkeypatch.setenv("TUMBLE_MAX_CHECKPOINT_MIB", "1")
    model = tumble.load(EXAMPLES / "tumbling_prism.yaml")
    with pytest.raises(ValueError, match="goes on past the limit of 1 MiB .* for a checkpoint file"):
        model.load_state("/dev/zero")


def test_runs_in_several_threads_give_each_run_its_own_bits():
    # The backspin disk over its v0: each thread runs the same model at other parameter values
    # and the same model twice; the GIL is released while each integrates.
    path = EXAMPLES / "backspin_disk.yaml"
    models = [tumble.load(path, set={"v0": v0}) for v0 in (1.0, 2.0, 3.0, 4.0)]
    alone = [csv_text(m.run()) for m in models]
    together: list[list[str]] = [[] for _ in models]

    def run(k: int) -> None:
        for _ in range(3):
            together[k].append(csv_text(models[k].run()))

    threads = [threading.Thread(target=run, args=(k,)) for k in range(len(models))]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for k in range(len(models)):
        assert together[k] == [alone[k]] * 3


def test_a_result_is_one_array_that_its_columns_view():
    # 10,000 rows: the prism with a row every 2 ms.
    model = tumble.load(EXAMPLES / "tumbling_prism.yaml")
    assert model.duration == 20.0
    text = (EXAMPLES / "tumbling_prism.yaml").read_text()
    result = tumble.load(text.replace("output_every: 0.05", "output_every: 0.002")).run()
    assert result.data.shape == (10001, len(result.columns))
    assert result.data.dtype == np.float64 and result.data.flags.c_contiguous
    # The rows came as one block from the engine (the array owns no copy: its base keeps the
    # engine's buffer), and a column is a view of it.
    assert result.data.base is not None
    w1 = result["prism.w1"]
    assert np.shares_memory(w1, result.data) and w1.shape == (10001,)
    assert result.t[0] == 0.0 and result.t[-1] == 20.0
    # The columns obey the chapter: |L| and E of the torque-free prism are conserved (rtol 1e-8
    # per step; the drift stays near it over the run).
    L = np.linalg.norm(np.column_stack([result["Lx"], result["Ly"], result["Lz"]]), axis=1)
    assert np.max(np.abs(L - L[0])) / L[0] < 1e-7
    assert np.max(np.abs(result["E"] - result["E"][0])) / result["E"][0] < 1e-7
    with pytest.raises(KeyError, match="no column 'prism.nope'"):
        result["prism.nope"]


def test_to_pandas_has_the_columns():
    pandas = pytest.importorskip("pandas")
    result = tumble.load(EXAMPLES / "tumbling_prism.yaml").run()
    frame = result.to_pandas()
    assert isinstance(frame, pandas.DataFrame)
    assert list(frame.columns) == result.columns
    assert np.array_equal(frame["prism.w3"].to_numpy(), result["prism.w3"])
