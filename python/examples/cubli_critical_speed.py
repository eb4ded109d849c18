"""The Cubli's critical wheel speed (the chapter's worked example 6) from Python: a sweep.

The frame, pivoted on its corner, swings up when its wheel is braked; it passes upright only if
the wheel spun faster than w0_crit = sqrt((sqrt(2) - 1) (M + m) g L I_total) / (m R^2). Sweeps
w0 around w0_crit with the brake at once (t_lock = 1 ns), records how high the frame swings
(the corner hinge's least angle: -pi/4 is upright), draws it against w0, and brackets the
critical speed with tumble.find.

    python3 python/examples/cubli_critical_speed.py [--out DIR]
"""

from __future__ import annotations

import argparse
import math
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import tumble  # noqa: E402

CUBLI = pathlib.Path(__file__).resolve().parents[2] / "examples" / "cubli.yaml"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--out", default=".", help="directory for cubli_critical_speed.png")
    out = pathlib.Path(parser.parse_args().out)
    out.mkdir(parents=True, exist_ok=True)

    fixed = {"t_lock": 1e-9}
    w0_crit = tumble.load(CUBLI, set=fixed).parameters["w0_crit"]
    swept = tumble.sweep(CUBLI, {"w0": (0.9 * w0_crit, 1.1 * w0_crit, 41)},
                         {"highest": "min(corner.angle)"}, set=fixed)
    found = tumble.find(CUBLI, {"w0": (0.95 * w0_crit, 1.05 * w0_crit)},
                        "min(corner.angle) < -pi/4", set=fixed, tol=1e-7)

    figure, axes = plt.subplots(figsize=(8, 4.5))
    axes.plot(swept["w0"], -swept["highest"] * 180 / math.pi, "o-", markersize=3,
              label="the frame's highest swing (tumble.sweep)")
    axes.axhline(45, color="0.6", linestyle=":", label="upright")
    axes.axvline(w0_crit, color="k", linestyle="--", linewidth=1,
                 label=f"w0_crit = {w0_crit:.4f} rad/s (closed form)")
    axes.set_xlabel("w0 (rad/s)")
    axes.set_ylabel("corner hinge's largest turn (deg)")
    axes.set_title("Cubli: the wheel speed that stands it up")
    axes.legend()
    figure.tight_layout()
    figure.savefig(out / "cubli_critical_speed.png", dpi=100)

    print(f"sweep: {len(swept)} runs on {swept.threads} threads, all "
          f"{'ok' if set(swept['status']) == {'ok'} else 'not ok'}")
    print(f"find: w0 in [{found.lo:.9f}, {found.hi:.9f}] rad/s after {found.runs} runs")
    print(f"closed form w0_crit = {w0_crit:.9f} rad/s; "
          f"relative difference {abs(found.value - w0_crit) / w0_crit:.1e}")
    print(f"figure {out / 'cubli_critical_speed.png'}")


if __name__ == "__main__":
    main()
