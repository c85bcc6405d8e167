#!/usr/bin/env python3
"""Pinocchio's constrained forward dynamics of the run-up four-bar, for the
dynamics section of the report (examples/report/dynamics.rs reads the JSON
this prints).

The four-bar as a Pinocchio user builds it: a kinematic tree of three
revolute joints about z (crank at O2, coupler on the crank at A, rocker at
O4), the loop cut at B and closed by a 3D point constraint between the
coupler and the rocker (RigidConstraintModel CONTACT_3D; its z row is
redundant in the plane, which the proximal solver absorbs), solved by
`constraintDynamics`. Masses as examples/common/run_up.rs (crank and
flywheel merged: 2.5 kg at 0.01 m from O2, 0.0214 kg m^2), gravity 9.81 m/s^2
along -y, the DC motor 1.2 (1 - omega / 40) N m on the crank.

Measured:
- ns per `constraintDynamics` call at fixed states (timeit, best of 7 runs
  of the median loop), beside an empty Python function taking the same
  arguments (the cost of the call itself);
- q'' of the crank at given states (compared by the report with the
  double-double reference);
- the run-up over 10 s with the classical RK4 at 1 ms on (q, v), the
  constraint without a corrector (its default): how far the loop is open
  at B at the end (m).

Usage: python3 scripts/pinocchio-four-bar.py > target/report/pinocchio.json
(needs `pip install pin` in a virtual environment).
"""
import json
import math
import sys
import timeit

import numpy as np
import pinocchio as pin

GROUND, CRANK, COUPLER, ROCKER = 0.30, 0.10, 0.25, 0.18


def build():
    model = pin.Model()
    model.gravity.linear = np.array([0.0, -9.81, 0.0])

    def inertia(m, g, j):
        return pin.Inertia(m, np.array([g, 0.0, 0.0]), np.diag([j, j, j]))

    def at(x):
        return pin.SE3(np.eye(3), np.array([x, 0.0, 0.0]))

    j1 = model.addJoint(0, pin.JointModelRZ(), at(0.0), "crank")
    model.appendBodyToJoint(j1, inertia(2.5, 0.01, 0.0214), pin.SE3.Identity())
    j2 = model.addJoint(j1, pin.JointModelRZ(), at(CRANK), "coupler")
    model.appendBodyToJoint(j2, inertia(1.2, 0.125, 6.5e-3), pin.SE3.Identity())
    j3 = model.addJoint(0, pin.JointModelRZ(), at(GROUND), "rocker")
    model.appendBodyToJoint(j3, inertia(0.9, 0.09, 2.5e-3), pin.SE3.Identity())
    return model, j2, j3


def assemble(phi):
    """(th3, th4): coupler and rocker angles, B left of A -> O4."""
    ax, ay = CRANK * math.cos(phi), CRANK * math.sin(phi)
    dx, dy = GROUND - ax, -ay
    d = math.hypot(dx, dy)
    along = (COUPLER**2 - ROCKER**2 + d * d) / (2 * d)
    h = math.sqrt(max(COUPLER**2 - along**2, 0.0))
    ux, uy = dx / d, dy / d
    bx, by = ax + along * ux - h * uy, ay + along * uy + h * ux
    return math.atan2(by - ay, bx - ax), math.atan2(by, bx - GROUND)


def rates(phi, th3, th4, omega):
    """(w3, w4) from the loop's velocity equations."""
    # A + l3 e3 = O4 + l4 e4, differentiated.
    a = np.array([[-COUPLER * math.sin(th3), ROCKER * math.sin(th4)],
                  [COUPLER * math.cos(th3), -ROCKER * math.cos(th4)]])
    b = np.array([CRANK * math.sin(phi) * omega, -CRANK * math.cos(phi) * omega])
    return np.linalg.solve(a, b)


def state(phi, omega):
    th3, th4 = assemble(phi)
    w3, w4 = rates(phi, th3, th4, omega)
    return np.array([phi, th3 - phi, th4]), np.array([omega, w3 - omega, w4])


def motor(omega):
    return 1.2 * (1.0 - omega / 40.0)


def main():
    model, j2, j3 = build()
    data = model.createData()
    placement2 = pin.SE3(np.eye(3), np.array([COUPLER, 0.0, 0.0]))
    placement3 = pin.SE3(np.eye(3), np.array([ROCKER, 0.0, 0.0]))
    cm = pin.RigidConstraintModel(pin.ContactType.CONTACT_3D, model, j2, placement2, j3,
                                  placement3, pin.ReferenceFrame.LOCAL)
    cms = pin.StdVec_RigidConstraintModel()
    cms.append(cm)
    cds = pin.StdVec_RigidConstraintData()
    cds.append(cm.createData())
    pin.initConstraintDynamics(model, data, cms, cds)
    prox = pin.ProximalSettings(1e-14, 1e-12, 10)

    def qdd(q, v, tau):
        return pin.constraintDynamics(model, data, q, v, tau, cms, cds, prox)

    states = []
    # 100 states: crank angles over a turn, speeds 0..39.6 rad/s.
    for k in range(100):
        phi, omega = 2 * math.pi * k / 100 + 0.01, 0.4 * ((37 * k) % 100)
        q, v = state(phi, omega)
        tau = np.array([motor(omega), 0.0, 0.0])
        states.append({"phi": phi, "omega": omega, "tau": motor(omega),
                       "qdd_crank": float(qdd(q, v, tau)[0])})

    q, v = state(0.7, 12.0)
    tau = np.array([motor(12.0), 0.0, 0.0])

    def empty(model, data, q, v, tau, cms, cds, prox):
        return None

    def per_call(stmt, number=20000):
        runs = timeit.repeat(stmt, number=number, repeat=7)
        return min(runs) / number * 1e9

    ns_call = per_call(lambda: pin.constraintDynamics(model, data, q, v, tau, cms, cds, prox))
    ns_empty = per_call(lambda: empty(model, data, q, v, tau, cms, cds, prox))

    def run():
        q, v = state(0.0, 0.0)
        h, steps = 1e-3, 10000

        def f(q, v):
            a = qdd(q, v, np.array([motor(v[0]), 0.0, 0.0]))
            return v.copy(), a.copy()

        for _ in range(steps):
            k1 = f(q, v)
            k2 = f(q + 0.5 * h * k1[0], v + 0.5 * h * k1[1])
            k3 = f(q + 0.5 * h * k2[0], v + 0.5 * h * k2[1])
            k4 = f(q + h * k3[0], v + h * k3[1])
            q = q + h / 6 * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0])
            v = v + h / 6 * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1])
        pin.forwardKinematics(model, data, q)
        b2 = data.oMi[j2].act(np.array([COUPLER, 0.0, 0.0]))
        b3 = data.oMi[j3].act(np.array([ROCKER, 0.0, 0.0]))
        return float(np.linalg.norm(b2 - b3)), float(q[0]), float(v[0])

    t0 = timeit.default_timer()
    open_plain, phi_plain, omega_plain = run()
    seconds = timeit.default_timer() - t0
    print(json.dumps({
        "version": pin.__version__,
        "python": sys.version.split()[0],
        "ns_call": ns_call,
        "ns_empty": ns_empty,
        "states": states,
        "rk4_step_s": 1e-3,
        "run_seconds": seconds,
        "open_10s": open_plain,
        "phi_10s": phi_plain,
        "omega_10s": omega_plain,
    }, indent=1))


if __name__ == "__main__":
    main()
