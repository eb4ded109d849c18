"""The chapter's disk with backspin (worked example 4) from Python, against its closed form.

A disk thrown along the floor at v0 with backspin w0 slides, its centre stops and reverses at
t_rev = v0 / (mu g), the slip stops at t_roll = (v0 + w0 R) / (3 mu g), and it rolls back at
v_end = (2 v0 - w0 R) / 3. Draws the centre's speed v and the backspin's rim speed w R from the run with
the closed form over them.

    python3 python/examples/backspin_disk.py [--out DIR]
"""

from __future__ import annotations

import argparse
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import tumble  # noqa: E402

EXAMPLES = pathlib.Path(__file__).resolve().parents[2] / "examples"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--out", default=".", help="directory for backspin_disk.png")
    out = pathlib.Path(parser.parse_args().out)
    out.mkdir(parents=True, exist_ok=True)

    model = tumble.load(EXAMPLES / "backspin_disk.yaml")
    p = model.parameters
    v0, w0, R, mu, g = p["v0"], p["w0"], p["R"], p["mu"], p["g"]
    result = model.run()
    t = result.t
    # The disk travels along +x with its axle along y, z up: rolling forward turns it about +y,
    # so the chapter's backspin w is -disk.wy, and the slip of the rim on the floor is v + w R.
    v = result["disk.vx"]
    rim = -result["disk.wy"] * R

    t_rev, t_roll, v_end = v0 / (mu * g), (v0 + w0 * R) / (3 * mu * g), (2 * v0 - w0 * R) / 3
    v_exact = np.where(t < t_roll, v0 - mu * g * t, v_end)
    rim_exact = np.where(t < t_roll, (w0 - 2 * mu * g * t / R) * R, -v_end)

    figure, axes = plt.subplots(figsize=(8, 4.5))
    axes.plot(t, v, label="centre speed v (tumble)", linewidth=3, alpha=0.6)
    axes.plot(t, rim, label="backspin w R (tumble)", linewidth=3, alpha=0.6)
    axes.plot(t, v_exact, "k--", linewidth=1, label="closed form")
    axes.plot(t, rim_exact, "k--", linewidth=1)
    axes.axvline(t_rev, color="0.6", linestyle=":")
    axes.axvline(t_roll, color="0.6", linestyle=":")
    axes.set_xlabel("t (s)")
    axes.set_ylabel("m/s")
    axes.set_title(f"Backspin disk: reverses at {t_rev:.3f} s, rolls from {t_roll:.3f} s")
    axes.legend()
    figure.tight_layout()
    figure.savefig(out / "backspin_disk.png", dpi=100)

    rolls = [e["t"] for e in result.events if e["source"] == "floor" and "rolls" in e["what"]]
    print(f"slip stops (rolling starts) at t = {rolls[0]:.9f} s; closed form {t_roll:.9f} s")
    print(f"rolls back at v = {v[-1]:.9f} m/s; closed form {v_end:.9f} m/s")
    print(f"largest |v - closed form| {np.max(np.abs(v - v_exact)):.2e} m/s, "
          f"|w R - closed form| {np.max(np.abs(rim - rim_exact)):.2e} m/s")
    print(f"figure {out / 'backspin_disk.png'}")


if __name__ == "__main__":
    main()
