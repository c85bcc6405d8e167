"""The force analysis from Python agrees with the principle of virtual
work, computed here from the package's own velocities: at rest (no inertia
loads) the driving torque T balances the press force F on the ram and the
coupler's weight, T * 1 + F . v_B + m3 g . v_G3 = 0 at a unit crank rate.
Loads set at run time enter linearly; a sweep's force columns equal the
scalar `forces` bit for bit.
"""

import math

import numpy as np
import pytest

import planar_mechanism as pm

PRESS = """
params { crank = 0.1, rod = 0.4 }
loads { press = 0.0 }
let O = ground(0.0, 0.0);
let line = guide((0.0, 0.0), 0 deg);
let A = crank(O, crank, theta) as link2;
let B = rrp(A, rod, line, plus) as (link3, ram) slide x;
let G3 = point(link3, from A, 0.2, 0 deg);
mass link3 { m = 2.0, at = G3, j = 0.03 };
mass ram { m = 5.0, at = B };
gravity (0.0, -9.81);
force at B on ram along line = -press;
"""

REST = {"theta": 0.0}


@pytest.fixture
def press() -> pm.Mechanism:
    m = pm.Mechanism(PRESS)
    m.set_load("press", 1000.0)
    return m


@pytest.mark.parametrize("theta", np.linspace(0.2, 6.0, 13))
def test_static_torque_by_virtual_work(press, theta):
    unit = press.velocity(theta=theta, rates={"theta": 1.0})
    expected = -(-1000.0 * unit["B.x"] + 2.0 * -9.81 * unit["G3.y"])
    f = press.forces(theta=theta, rates=REST, accels=REST)
    # The torque (up to ~100 N m) is a sum of a few products of loads up to
    # 1000 N and lengths up to 0.5 m, each with a few roundings: 1e-12
    # relative leaves a factor 20 over 256 eps; a wrong sign or term is off
    # by far more.
    assert abs(f["drive_theta"] - expected) <= 1e-12 * max(abs(expected), 1.0)
    assert 0.0 < f["condition"] <= 1.0


def test_loads_set_at_run_time_enter_linearly(press):
    """The torque is affine in the press load: T(2000) - T(1000) equals
    T(1000) - T(0)."""
    t = []
    for load in (0.0, 1000.0, 2000.0):
        press.set_load("press", load)
        assert press.loads == {"press": load}
        t.append(press.forces(theta=1.0, rates=REST, accels=REST)["drive_theta"])
    assert abs((t[2] - t[1]) - (t[1] - t[0])) <= 1e-12 * abs(t[2])
    with pytest.raises(KeyError, match="no load `pres`"):
        press.set_load("pres", 1.0)
    with pytest.raises(ValueError, match="not a finite number"):
        press.set_load("press", math.inf)


def test_sweep_forces_equal_scalar_forces(press):
    theta = np.linspace(0.0, 6.0, 9)
    out = press.sweep(theta=theta, rates={"theta": 30.0}, accels={"theta": 0.0}, forces=True)
    assert out["ok"].all() and press.has_forces
    for i, t in enumerate(theta):
        f = press.forces(theta=t, rates={"theta": 30.0}, accels={"theta": 0.0})
        for key, value in f.items():
            assert out["forces." + key][i] == value, key
    assert set(press.columns("forces")) == {k[len("forces."):] for k in out if k.startswith("forces.")}


def test_forces_need_a_force_analysis_and_accelerations(fourbar):
    assert not fourbar.has_forces
    with pytest.raises(ValueError, match="no force analysis"):
        fourbar.forces(theta=0.0, rates=REST, accels=REST)
    with pytest.raises(TypeError, match="needs `rates` and `accels`"):
        fourbar.sweep(theta=[0.0], rates=REST, forces=True)
