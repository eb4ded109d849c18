#!/usr/bin/env python3
"""Mutation fuzzing of tumble's Python entry points: tumble.load (a scenario's text), Model.run
(stop_at=, start=), State.save and Model.load_state (a saved state's bytes), tumble.modes,
tumble.inertia (about=), tumble.sweep (vary=, record=, random=, seed=, threads=) and tumble.find
(vary=, when=, tol=), each with set= overrides.

    PYTHONPATH=<build>/python python3 fuzz/python_entry_points.py [SECONDS] [--seed N]

Each call is made with a mutated scenario (an example's text, bytes flipped, tokens inserted,
lines dropped, doubled or taken from another example) and arguments drawn from ordinary and
hostile values (nan, inf, 1e308, negative counts, huge integers, wrong types, text with control
characters). A pass is a result or a documented refusal: tumble.TumbleError, ValueError or
TypeError. A call that runs is stopped after a quarter of a second by a signal handler's
exception, as Ctrl-C would stop it (docs/python.md), and that exception must come back. Anything
else is a finding: an unexpected exception (printed, with the call, and the input written to
build/fuzz/python-finding-*.txt), a crash (the interpreter dies: the call's input is in
build/fuzz/python-current.txt), or a call that ignores the signal for ten seconds (a traceback of
every thread, and exit 1). The draws are seeded (--seed, default 1), so a run repeats; the
libFuzzer targets (fuzz/*.cpp) cover the C++ beneath with coverage guidance, this covers the
bindings' conversions and checks.
"""

from __future__ import annotations

import argparse
import faulthandler
import math
import random
import signal
import sys
import tempfile
import time
import traceback
from pathlib import Path
from typing import Any, Callable, Dict, List, Tuple

import tumble

ROOT = Path(__file__).resolve().parent.parent
FINDINGS = ROOT / "build" / "fuzz"
CALL_SECONDS = 0.25  # then the signal handler's exception stops the call
HANG_SECONDS = 10.0  # a call still going this long after it is a finding

TOKENS = [
    ": ", "\n", "\n  ", "- ", "[", "]", "{", "}", ",", "&a ", "*a", "!!binary ", "'", '"', "#",
    "0", "-1", "1e308", "-1e308", "1e-320", "nan", ".nan", ".inf", "-.inf", "1e999", "2*pi",
    "30 deg", "x = 1", "max(", ")", "t > 0", "\x00", "\x7f", "\u00e9", "\t",
    "mass", "shape", "size", "radius", "inertia", "joints", "contacts", "events", "forces",
    "parameters", "simulate", "duration", "integrator", "rtol", "output_every", "max_rows",
    "when", "stop", "type: hinge", "axis", "parent", "child", "friction", "restitution", "ground",
]
VALUES: List[Any] = [
    0, 1, -1, 0.5, 1e308, -1e308, 1e-320, math.nan, math.inf, -math.inf, 10**400, 2**64, -(2**63),
    "2*pi", "30 deg", "", "x = 3", "nan", "1e999", "\x00", "a\nb", True, None, [1.0], {}, b"1",
]
ORDINARY: List[Any] = [0.5, 1, 2, 0.1, "1.5", 3.0]
RECORDS = [
    "final(E)", "max(KE)", "min(E)", "mean(KE)", "time_of_max(KE)", "first(t > 0.1)",
    "count(KE > 0)", "modes.stable", "modes.frequency", "x = 1", "max(KE = 2)", "final(", "",
    "final(nope)", "jump(j, KE_before)", "after(e, KE)", "1/0", "final(a, E)",
]


class TimeUp(Exception):
    """The call's quarter second is up: raised by the SIGALRM handler, as Ctrl-C raises
    KeyboardInterrupt."""


# Whether a call is under way: the alarm stops only a call. An alarm that comes as the call
# returns, after the handling of what it raised has begun, or as the timer is cancelled, does
# nothing (raised there, it escaped every handler and ended the fuzzer).
_ALARM = {"armed": False}


def _time_up(_signum: int, _frame: Any) -> None:
    if _ALARM["armed"]:
        raise TimeUp()


def mutate(text: str, others: List[str], draw: random.Random) -> str:
    """A few random edits of the text: the mutations a careless user or an attacker makes."""
    if draw.random() < 0.3:
        return text  # as it is: the arguments are what is mutated
    chars = list(text)
    for _ in range(1 if draw.random() < 0.7 else draw.randint(2, 4)):
        kind = draw.randrange(6)
        at = draw.randrange(len(chars) + 1)
        if kind == 0 and chars:  # a character changed
            chars[min(at, len(chars) - 1)] = chr(draw.randrange(1, 256))
        elif kind == 1:  # a token inserted
            chars[at:at] = list(draw.choice(TOKENS))
        elif kind == 2 and chars:  # a span dropped
            del chars[at:at + draw.randint(1, 40)]
        elif kind == 3:  # a number made extreme
            chars[at:at] = list(draw.choice(["1e308", "-0", "1e-320", "nan", "99999999999"]))
        else:  # lines doubled or taken from another example
            lines = "".join(chars).split("\n")
            source = lines if kind == 4 else draw.choice(others).split("\n")
            i = draw.randrange(len(source))
            taken = "\n".join(source[i:i + draw.randint(1, 5)])
            lines.insert(draw.randrange(len(lines) + 1), taken)
            chars = list("\n".join(lines))
    mutated = "".join(chars)
    return mutated if "\n" in mutated else mutated + "\n"  # text, not a path


def pick(draw: random.Random, ordinary: List[Any], hostile: List[Any]) -> Any:
    """An ordinary argument seven times in ten, else a hostile one: most calls then get past the
    arguments' checks to the run, which is where the state is."""
    return draw.choice(ordinary) if draw.random() < 0.7 else draw.choice(hostile)


def value(draw: random.Random) -> Any:
    return pick(draw, ORDINARY, VALUES)


def overrides(model_parameters: List[str], draw: random.Random) -> Dict[Any, Any] | None:
    if draw.random() < 0.5:
        return None
    hostile: List[Any] = ["nope", "", "e", "t", "a\x00", 3]
    names = model_parameters if model_parameters and draw.random() < 0.8 else hostile
    return {draw.choice(names): value(draw) for _ in range(draw.randint(1, 2))}


def parameter_names(text: str) -> List[str]:
    """The names a scenario's parameters line gives, roughly (what set= is most often given)."""
    for line in text.split("\n"):
        if line.startswith("parameters:") and "{" in line:
            inside = line[line.index("{") + 1:line.rfind("}")]
            return [item.split(":")[0].strip() for item in inside.split(",") if ":" in item]
    return []


def calls(text: str, draw: random.Random, scratch: Path) -> List[Tuple[str, Callable[[], Any]]]:
    """The entry points to call on one mutated scenario, each with drawn arguments."""
    names = parameter_names(text)
    sets = overrides(names, draw)
    vary_name = draw.choice(names) if names and draw.random() < 0.8 else draw.choice(["nope", "t"])
    lo, hi = value(draw), value(draw)
    well_formed = draw.random() < 0.6
    vary: Any = ({vary_name: (lo, hi, 2)} if well_formed else
                 draw.choice([{vary_name: (lo, hi, draw.choice([1, 3, 0, -1]))},
                              f"{vary_name}={lo}:{hi}:2", {vary_name: (lo,)}, [], 7]))
    record: Any = {"r" if well_formed else draw.choice(["status", "run", "", "x y"]):
                   draw.choice(RECORDS[:8] if well_formed else RECORDS)}
    stop_at = pick(draw, [None, 0.01, 0.3], [0.0, -1.0, math.nan, math.inf, 1e300, "0.1", []])

    def run() -> Any:
        model = tumble.load(text, set=sets)
        result = model.run(stop_at=stop_at)
        if stop_at is not None and getattr(result, "state", None) is not None:
            path = scratch / "state"
            result.state.save(path)
            saved = bytearray(path.read_bytes())
            if saved and draw.random() < 0.7:  # a saved state edited or cut short
                at = draw.randrange(len(saved))
                if draw.random() < 0.5:
                    saved[at] = draw.randrange(256)
                else:
                    del saved[at:]
            path.write_bytes(bytes(saved))
            model.run(start=model.load_state(path))
        return result

    return [
        ("load+run", run),
        ("modes", lambda: tumble.modes(text, set=sets)),
        ("inertia", lambda: tumble.inertia(
            text, set=sets, about=pick(draw, [None, [0, 0, 0], [1, 2, 3]],
                                       [[math.nan, 0, 0], [1e308] * 3, [1], "abc"]))),
        ("sweep", lambda: tumble.sweep(
            text, vary, record, set=sets, random=pick(draw, [0, 3], [-1, 10**9, 2**70]),
            seed=pick(draw, [1, 7], [0, -1, 2**64, 2**64 - 1]),
            threads=pick(draw, [1, 2], [0, -1, 257, 10**6]))),
        ("find", lambda: tumble.find(
            text, {vary_name: (lo, hi)},
            draw.choice(RECORDS[:8]) + draw.choice(["", " > 0", " < 1"]), set=sets,
            tol=pick(draw, [None, 1e-3], [0.0, -1.0, math.nan, math.inf]))),
    ]


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("seconds", nargs="?", type=float, default=60.0)
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args()
    seeds = [p.read_text(encoding="utf-8") for p in sorted((ROOT / "examples").rglob("*.yaml"))]
    seeds = [s for s in seeds if "mesh" not in s]  # meshes are files beside the example
    draw = random.Random(args.seed)
    FINDINGS.mkdir(parents=True, exist_ok=True)
    current = FINDINGS / "python-current.txt"
    signal.signal(signal.SIGALRM, _time_up)
    counts: Dict[str, int] = {}
    by_call: Dict[Tuple[str, str], int] = {}
    findings = 0
    end = time.monotonic() + args.seconds
    with tempfile.TemporaryDirectory() as scratch:
        while time.monotonic() < end:
            text = mutate(draw.choice(seeds), seeds, draw)
            name, call = draw.choice(calls(text, draw, Path(scratch)))
            current.write_text(f"# {name}\n{text}", encoding="utf-8", errors="backslashreplace")
            faulthandler.dump_traceback_later(HANG_SECONDS, exit=True)
            outcome = "passed"
            try:
                try:
                    _ALARM["armed"] = True
                    signal.setitimer(signal.ITIMER_REAL, CALL_SECONDS)
                    call()
                finally:
                    # Disarmed first: from here on, an alarm raises nothing.
                    _ALARM["armed"] = False
                    signal.setitimer(signal.ITIMER_REAL, 0)
            except (tumble.TumbleError, ValueError, TypeError):
                outcome = "refused"
            except TimeUp:
                outcome = "stopped"
            except Exception:  # noqa: BLE001 (anything else is what the fuzzer is for)
                outcome = "finding"
                findings += 1
                kept = FINDINGS / f"python-finding-{findings}.txt"
                kept.write_text(current.read_text(encoding="utf-8"), encoding="utf-8")
                print(f"finding in {name} (input in {kept}):", file=sys.stderr)
                traceback.print_exc()
            finally:
                faulthandler.cancel_dump_traceback_later()
            counts[outcome] = counts.get(outcome, 0) + 1
            by_call[(name, outcome)] = by_call.get((name, outcome), 0) + 1
    total = sum(counts.values())
    print(f"python entry points: {total} calls in {args.seconds:g} s (seed {args.seed}): "
          + ", ".join(f"{k} {v}" for k, v in sorted(counts.items())))
    for name in sorted({n for n, _ in by_call}):
        print(f"  {name}: " + ", ".join(f"{o} {c}" for (n, o), c in sorted(by_call.items())
                                        if n == name))
    return 1 if findings else 0


if __name__ == "__main__":
    sys.exit(main())
