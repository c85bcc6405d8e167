"""A sweep is the scalar calls in bulk: every array entry equals the
scalar `solve` at its inputs bit for bit (the same Rust code path), shapes
broadcast as numpy does, and a pose that fails marks its own row only:
NaN in its outputs, `ok` False and the message in `error`, every other
row untouched.
"""

import math

import numpy as np
import pytest

import planar_mechanism as pm


def test_sweep_equals_scalar_solve_bit_for_bit(fourbar):
    theta = np.linspace(0.0, 2.0 * math.pi, 50)
    rate = np.linspace(-3.0, 3.0, 50)
    out = fourbar.sweep(theta=theta, rates={"theta": rate}, accels={"theta": 0.5})
    assert out["ok"].all()
    assert all(e is None for e in out["error"])
    np.testing.assert_array_equal(out["theta"], theta)
    for i, t in enumerate(theta):
        one = fourbar.solve(theta=t, rates={"theta": rate[i]}, accels={"theta": 0.5})
        for key, value in one.items():
            assert out[key][i] == value, key
    keys = set(fourbar.solve(theta=0.0, rates={"theta": 1.0}, accels={"theta": 0.0}))
    assert set(out) == keys | {"theta", "ok", "error"}


def test_sweep_without_rates_has_the_position_only(fourbar):
    out = fourbar.sweep(theta=[0.1, 0.2])
    assert set(out) == set(fourbar.outputs) | {"theta", "ok", "error"}
    assert out["B.x"].dtype == np.float64
    assert out["B.x"][1] == fourbar.position(theta=0.2)["B.x"]


def test_shapes_broadcast_like_numpy(parametric):
    grid = np.linspace(0.0, 1.0, 6).reshape(2, 3)
    out = parametric.sweep(theta=grid, rates={"theta": 2.0})
    assert out["B.x"].shape == (2, 3) and out["ok"].shape == (2, 3)
    assert out["velocity.link2"].shape == (2, 3)
    assert (out["velocity.link2"] == 2.0).all()
    assert out["B.y"][1, 2] == parametric.position(theta=1.0)["B.y"]
    # A scalar sweeps one pose, shape ().
    assert parametric.sweep(theta=0.5)["B.x"].shape == ()


def test_returned_inputs_are_copies(fourbar):
    theta = np.array([0.1, 0.2])
    out = fourbar.sweep(theta=theta)
    out["theta"][0] = 9.0
    assert theta[0] == 0.1


def test_failing_rows_are_nan_with_their_error_only(reach):
    """B assembles while |s| <= sqrt(3): rows 1 and 3 fail, 0, 2, 4 do not."""
    s = np.array([0.5, 3.0, -1.0, -2.5, 1.7])
    out = reach.sweep(s=s, rates={"s": 1.0})
    np.testing.assert_array_equal(out["ok"], [True, False, True, False, True])
    for i in (1, 3):
        assert "group `B`" in out["error"][i]
        for key in reach.outputs:
            assert math.isnan(out[key][i]), key
        assert math.isnan(out["velocity.B.x"][i])
        with pytest.raises(pm.PoseError):
            reach.position(s=s[i])
    for i in (0, 2, 4):
        assert out["error"][i] is None
        one = reach.solve(s=s[i], rates={"s": 1.0})
        for key, value in one.items():
            assert out[key][i] == value and not math.isnan(value), key


def test_a_sweep_over_several_blocks_equals_the_scalar_calls(reach):
    """Rows are solved in blocks of 256 and written out per column: over
    1001 rows, with failing runs that straddle the block edges 256, 512 and
    768 (|s| > sqrt(3) fails), every row still equals its scalar call or is
    NaN with its error."""
    s = np.linspace(-1.5, 1.5, 1001)
    s[250:263], s[508:516], s[767:770] = 2.0, -2.0, 2.5
    out = reach.sweep(s=s, rates={"s": 0.7})
    fails = np.abs(s) > math.sqrt(3.0)
    np.testing.assert_array_equal(out["ok"], ~fails)
    keys = list(reach.solve(s=0.0, rates={"s": 0.7}))
    for i in range(len(s)):
        if fails[i]:
            assert "group `B`" in out["error"][i]
            assert all(math.isnan(out[key][i]) for key in keys)
            continue
        one = reach.solve(s=s[i], rates={"s": 0.7})
        for key in keys:
            assert out[key][i] == one[key], (i, key)


def test_threads_give_the_same_numbers_as_one_thread(reach):
    """Rows split over threads (each on its own copy of the definition)
    equal the calling thread's sweep bit for bit, failing rows and their
    errors included, whatever the count; `threads=0` is refused."""
    s = np.linspace(-2.0, 2.0, 3001)
    one = reach.sweep(s=s, rates={"s": 0.4}, accels={"s": -0.2}, threads=1)
    assert not one["ok"].all() and one["ok"].any()
    for threads in (2, 3, 7):
        out = reach.sweep(s=s, rates={"s": 0.4}, accels={"s": -0.2}, threads=threads)
        assert set(out) == set(one)
        for key, value in one.items():
            if key == "error":
                assert list(out[key]) == list(value)
            else:
                np.testing.assert_array_equal(out[key], value)
    with pytest.raises(ValueError):
        reach.sweep(s=s, threads=0)


def test_sweep_arguments_are_checked(fourbar):
    with pytest.raises(TypeError, match="missing values for input `theta`"):
        fourbar.sweep()
    with pytest.raises(TypeError, match="no input `phi`"):
        fourbar.sweep(theta=[0.0], phi=[1.0])
    with pytest.raises(TypeError, match="`accels` needs `rates`"):
        fourbar.sweep(theta=[0.0], accels={"theta": 0.0})
    with pytest.raises(ValueError, match="broadcast"):
        fourbar.sweep(theta=[0.0, 1.0], rates={"theta": [1.0, 2.0, 3.0]})


FIVE_BAR = """
pub FiveBar {
    params { base = 0.08, proximal = 0.1, distal = 0.16 }
    dof 2;
    let O1 = ground(0.0, 0.0);
    let O2 = ground(base, 0.0);
    let A = crank(O1, proximal, q1) as arm1;
    let C = crank(O2, proximal, q2) as arm2;
    let P = rrr(A, distal, C, distal, left) as (forearm1, forearm2);
    range q1 = (60 deg, 150 deg);
    range q2 = (0 deg, 90 deg);
}
"""


def test_two_inputs_over_a_meshgrid():
    """A whole item (`pub FiveBar { .. }`) with two inputs: a grid from
    np.meshgrid sweeps every pair; each entry is the scalar solve's."""
    m = pm.Mechanism(FIVE_BAR)
    assert m.name == "FiveBar"
    assert [i.name for i in m.inputs] == ["q1", "q2"]
    q1, q2 = np.meshgrid(np.radians([70, 100, 140]), np.radians([0, 30, 60, 90]))
    out = m.sweep(q1=q1, q2=q2)
    assert out["P.x"].shape == (4, 3) and out["ok"].all()
    for i in range(4):
        for j in range(3):
            one = m.position(q1=q1[i, j], q2=q2[i, j])
            assert out["P.x"][i, j] == one["P.x"] and out["P.y"][i, j] == one["P.y"]


def test_an_empty_sweep_is_empty(fourbar):
    out = fourbar.sweep(theta=np.array([]))
    assert out["B.x"].shape == (0,) and out["ok"].shape == (0,)
