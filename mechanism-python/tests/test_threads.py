"""A Mechanism works from any thread: each thread solves with its own copy
read from the same text, and parameters and modes set on one thread are
the ones every thread uses (no panic, no stale setting).
"""

import threading

import numpy as np


def run_in_thread(f):
    out = {}

    def target():
        try:
            out["value"] = f()
        except BaseException as e:  # noqa: BLE001 (re-raised below)
            out["error"] = e

    t = threading.Thread(target=target)
    t.start()
    t.join()
    if "error" in out:
        raise out["error"]
    return out["value"]


def test_another_thread_gets_the_same_numbers(fourbar):
    theta = np.linspace(0.0, 6.0, 7)
    here = fourbar.sweep(theta=theta, rates={"theta": 2.0})
    there = run_in_thread(lambda: fourbar.sweep(theta=theta, rates={"theta": 2.0}))
    for key, value in here.items():
        if key != "error":
            np.testing.assert_array_equal(there[key], value)


def test_settings_reach_every_thread(parametric):
    before = run_in_thread(lambda: parametric.position(theta=0.0))  # a copy there
    parametric.set_param("crank", 1.25)
    parametric.set_mode("circuit", "right")
    here = parametric.position(theta=0.0)
    there = run_in_thread(lambda: parametric.position(theta=0.0))
    assert there == here
    assert here["A.x"] == 1.25 and here["B.y"] < 0.0 < before["B.y"]
    # A setting made on another thread is seen here too.
    run_in_thread(lambda: parametric.set_param("crank", 1.0))
    assert parametric.params["crank"] == 1.0
    assert parametric.position(theta=0.0)["A.x"] == 1.0
