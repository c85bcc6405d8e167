"""Times a four-bar over 10^5 crank angles: planar_mechanism's numpy sweep,
a Python loop of scalar calls, and pylinkage (pip `pylinkage`): its
per-step generator `Linkage.step` and, when numba is installed, its
compiled `Linkage.step_fast`. Medians of repeated runs, milliseconds per
sweep and nanoseconds per pose, and the largest distance between the two
packages' coupler-rocker joints B over the sweep (they solve the same
dimensions and branch).

    .venv/bin/maturin develop --release -m mechanism-python/Cargo.toml
    .venv/bin/pip install pylinkage numba
    .venv/bin/python mechanism-python/bench/sweep.py

The Rust figures beside them: `cargo run --release -p mechanism-python
--example sweep_timing` (the same definition).
"""

import math
import os
import statistics
import time

import numpy as np

import planar_mechanism as pm

N = 100_000
TEXT = """
let O2 = ground(0.0, 0.0);
let O4 = ground(3.5, 0.0);
let A = crank(O2, 1.0, theta) as link2;
let B = rrr(A, 3.0, O4, 2.5, left) as (link3, link4);
"""


def median_seconds(f, runs):
    """Median wall time of `runs` calls of `f`, and its last result."""
    times, out = [], None
    for _ in range(runs):
        t = time.perf_counter()
        out = f()
        times.append(time.perf_counter() - t)
    return statistics.median(times), out


def show(what, seconds):
    print(f"{what:<58} {seconds * 1e3:>9.2f} ms  {seconds * 1e9 / N:>8.1f} ns/pose")


def pylinkage_fourbar():
    from pylinkage.actuators import Crank
    from pylinkage.components import Ground
    from pylinkage.dyads import RRRDyad
    from pylinkage.simulation import Linkage

    o2, o4 = Ground(0.0, 0.0, name="O2"), Ground(3.5, 0.0, name="O4")
    # One step turns the crank by 2 pi / N: step k is at (k + 1) 2 pi / N.
    crank = Crank(anchor=o2, radius=1.0, angular_velocity=2.0 * math.pi / N)
    rocker = RRRDyad(crank.output, o4, distance1=3.0, distance2=2.5)
    return Linkage([o2, o4, crank, rocker], name="Four-Bar")


def main():
    print(f"{os.cpu_count()} logical cores")
    m = pm.Mechanism(TEXT)
    theta = (np.arange(N) + 1.0) * (2.0 * math.pi / N)
    rates, accels = {"theta": 1.0}, {"theta": 0.0}

    t, ours = median_seconds(lambda: m.sweep(theta=theta, threads=1), 7)
    assert ours["ok"].all()
    show("planar_mechanism sweep, position, one thread", t)
    t, _ = median_seconds(lambda: m.sweep(theta=theta), 7)
    show("planar_mechanism sweep, position, threads=None", t)
    full = dict(rates=rates, accels=accels)
    t, _ = median_seconds(lambda: m.sweep(theta=theta, threads=1, **full), 7)
    show("planar_mechanism sweep, pos + vel + acc, one thread", t)
    t, _ = median_seconds(lambda: m.sweep(theta=theta, **full), 7)
    show("planar_mechanism sweep, pos + vel + acc, threads=None", t)
    t, _ = median_seconds(lambda: [m.position(theta=x) for x in theta.tolist()], 3)
    show("planar_mechanism position() in a Python loop", t)

    try:
        linkage = pylinkage_fourbar()
    except ImportError:
        print("pylinkage is not installed: pip install pylinkage")
        return
    t, steps = median_seconds(lambda: list(pylinkage_fourbar().step(iterations=N)), 3)
    show("pylinkage Linkage.step (generator), position", t)
    b = np.array([s[3] for s in steps])
    gap = np.hypot(b[:, 0] - ours["B.x"], b[:, 1] - ours["B.y"]).max()
    print(f"largest |B_pylinkage - B_planar_mechanism| over the sweep: {gap:.2e} L")
    try:
        import numba  # noqa: F401
    except ImportError:
        print("numba is not installed: pylinkage's step_fast not timed (pip install numba)")
        return
    linkage.compile()
    linkage.step_fast(iterations=N)  # the first call compiles
    t, _ = median_seconds(lambda: linkage.step_fast(iterations=N), 7)
    show("pylinkage Linkage.step_fast (numba), position", t)


if __name__ == "__main__":
    main()
