"""Times `sweep` of a four-bar (position, velocity, acceleration) on one
thread (`threads=1`) against the default (one thread per core, each given
at least 8192 rows), from 10^4 to 3 x 10^5 rows: medians of 15 calls,
nanoseconds per pose, and their ratio.

    .venv/bin/maturin develop --release -m mechanism-python/Cargo.toml
    .venv/bin/python mechanism-python/bench/threads.py
"""

import statistics
import time

import numpy as np

import planar_mechanism as pm

TEXT = """
let O2 = ground(0.0, 0.0);
let O4 = ground(3.5, 0.0);
let A = crank(O2, 1.0, theta) as link2;
let B = rrr(A, 3.0, O4, 2.5, left) as (link3, link4);
"""


def per_pose(m, theta, **kwargs):
    """Median ns per pose of 15 full sweeps at `theta`."""
    times = []
    for _ in range(15):
        start = time.perf_counter()
        m.sweep(theta=theta, rates={"theta": 10.0}, accels={"theta": 0.0}, **kwargs)
        times.append(time.perf_counter() - start)
    return statistics.median(times) / len(theta) * 1e9


def main():
    m = pm.Mechanism(TEXT)
    for n in (10_000, 20_000, 50_000, 100_000, 300_000):
        theta = np.linspace(0.0, 2.0 * np.pi, n)
        one = per_pose(m, theta, threads=1)
        default = per_pose(m, theta)
        print(
            f"{n:>7} rows: one thread {one:.0f} ns/pose, "
            f"default {default:.0f} ns/pose, ratio {one / default:.2f}"
        )


if __name__ == "__main__":
    main()
