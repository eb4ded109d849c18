"""The chapter's tumbling prism from Python: omega in the body's axes, and the flip.

A box 4 x 1 x 2 m of 12 kg spun at 1 rad/s about its intermediate axis (body z, I = 17 kg m^2,
between 5 and 20) with a small tilt about y: the spin leaves that axis and comes back reversed,
again and again (the intermediate-axis instability). Draws omega_1, omega_2, omega_3 against t,
with each flip (omega_3 through zero) marked, and E and |L|, which stay constant.

    python3 python/examples/prism_flip.py [--out DIR]
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


def flips(t: np.ndarray, w3: np.ndarray) -> np.ndarray:
    """Where omega_3 changes sign, each between its two rows by linear interpolation (s)."""
    k = np.nonzero(np.sign(w3[:-1]) != np.sign(w3[1:]))[0]
    return t[k] - w3[k] * (t[k + 1] - t[k]) / (w3[k + 1] - w3[k])


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--out", default=".", help="directory for prism_flip.png")
    out = pathlib.Path(parser.parse_args().out)
    out.mkdir(parents=True, exist_ok=True)

    result = tumble.load(EXAMPLES / "tumbling_prism.yaml").run()
    t = result.t
    L = np.linalg.norm(np.column_stack([result["Lx"], result["Ly"], result["Lz"]]), axis=1)
    flip_times = flips(t, result["prism.w3"])

    figure, (spin, books) = plt.subplots(2, 1, figsize=(8, 6), sharex=True,
                                         gridspec_kw={"height_ratios": [3, 1]})
    for k, name in enumerate(("w1", "w2", "w3"), start=1):
        spin.plot(t, result[f"prism.{name}"], label=f"$\\omega_{k}$ (body axis {k})")
    for flip in flip_times:
        spin.axvline(flip, color="0.6", linestyle=":", linewidth=1)
    spin.set_ylabel("rad/s")
    spin.set_title("The tumbling prism: omega in body axes; dotted: omega_3 = 0 (a flip)")
    spin.legend(loc="lower left")
    books.plot(t, result["E"] / result["E"][0] - 1, label="E / E0 - 1")
    books.plot(t, L / L[0] - 1, label="|L| / |L0| - 1")
    books.set_xlabel("t (s)")
    books.legend(loc="lower left")
    figure.tight_layout()
    figure.savefig(out / "prism_flip.png", dpi=100)

    print(f"rows {len(result)}, {result.summary['accepted_steps']} steps")
    print("flips (omega_3 = 0) at t = " + ", ".join(f"{f:.3f}" for f in flip_times) + " s")
    print(f"energy drift {result.summary['energy_drift']:.2e}, "
          f"|L| drift {result.summary['angular_momentum_drift']:.2e}")
    print(f"figure {out / 'prism_flip.png'}")


if __name__ == "__main__":
    main()
