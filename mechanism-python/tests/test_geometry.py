"""The numbers agree with closed forms written here, independently of the
Rust solver: the four-bar's rocker angle from Freudenstein's equation, the
slider-crank's slider position and velocity from the triangle A-F-C.

Tolerance: both sides evaluate a few dozen f64 operations on numbers of
order 1; the circle intersection amplifies their rounding (~1e-16) by
1/sin(transmission angle), at most ~3 for these Grashof dimensions, so
agreement to 1e-12 holds with a wide margin, while any wrong branch, sign
or formula differs by far more than 1e-6.
"""

import math

import numpy as np
import pytest

from conftest import A, B, C, D, E, L, R

TOL = 1e-12
ANGLES = np.linspace(0.0, 2.0 * math.pi, 37)


def wrap(angle: float) -> float:
    """The angle in (-pi, pi]."""
    return math.atan2(math.sin(angle), math.cos(angle))


def rocker_angles(theta: float) -> list:
    """Both solutions of Freudenstein's equation for the rocker angle
    theta4 (Norton, Design of Machinery, eq. 4.10), crank a, coupler b,
    rocker c, ground d along +x."""
    k1, k2 = D / A, D / C
    k3 = (A * A - B * B + C * C + D * D) / (2.0 * A * C)
    ca, sa = math.cos(theta), math.sin(theta)
    aa = ca - k1 - k2 * ca + k3
    bb = -2.0 * sa
    cc = k1 - (k2 + 1.0) * ca + k3
    root = math.sqrt(bb * bb - 4.0 * aa * cc)
    return [2.0 * math.atan2(-bb + s * root, 2.0 * aa) for s in (1.0, -1.0)]


@pytest.mark.parametrize("theta", ANGLES)
def test_fourbar_rocker_is_freudensteins_left_solution(fourbar, theta):
    """`left`: B lies left of the directed line A -> O4 (docs/assembly-modes.md);
    of Freudenstein's two rocker angles, the one with that B is link4."""
    pos = fourbar.position(theta=theta)
    ax, ay = A * math.cos(theta), A * math.sin(theta)
    left = []
    for t4 in rocker_angles(theta):
        bx, by = D + C * math.cos(t4), C * math.sin(t4)
        cross = (D - ax) * (by - ay) - (0.0 - ay) * (bx - ax)
        if cross > 0.0:
            left.append((t4, bx, by))
    assert len(left) == 1, "exactly one closure lies left of A -> O4"
    t4, bx, by = left[0]
    assert abs(wrap(pos["link4"] - t4)) < TOL
    assert abs(pos["B.x"] - bx) < TOL and abs(pos["B.y"] - by) < TOL
    assert abs(pos["A.x"] - ax) < TOL and abs(pos["A.y"] - ay) < TOL
    # The coupler's angle is the direction A -> B.
    assert abs(wrap(pos["link3"] - math.atan2(by - ay, bx - ax))) < TOL


@pytest.mark.parametrize("theta", ANGLES)
def test_fourbar_angular_velocities_from_the_loop_equation(fourbar, theta):
    """Differentiating the loop a e^{i t2} + b e^{i t3} = d + c e^{i t4}
    gives w3 = a w2 sin(t4 - t2) / (b sin(t3 - t4)) and
    w4 = a w2 sin(t2 - t3) / (c sin(t4 - t3)) (Norton eq. 6.18)."""
    w2 = 7.0
    pos = fourbar.position(theta=theta)
    vel = fourbar.velocity(theta=theta, rates={"theta": w2})
    t3, t4 = pos["link3"], pos["link4"]
    w3 = A * w2 * math.sin(t4 - theta) / (B * math.sin(t3 - t4))
    w4 = A * w2 * math.sin(theta - t3) / (C * math.sin(t4 - t3))
    # Rates scale the position's rounding by w2 = 7: 1e-12 * 7 margin.
    assert abs(vel["link3"] - w3) < 7 * TOL
    assert abs(vel["link4"] - w4) < 7 * TOL
    assert abs(vel["link2"] - w2) == 0.0
    assert 0.0 < vel["condition"] <= 1.0


@pytest.mark.parametrize("theta", ANGLES)
def test_slider_position_and_velocity(slider_crank, theta):
    """C = (a_x + sqrt(l^2 - (a_y - e)^2), e) for `plus` (C ahead of the
    foot F along +x), and its derivative in theta times the crank rate."""
    omega = 314.0
    sol = slider_crank.solve(theta=theta, rates={"theta": omega})
    ax, ay = R * math.cos(theta), R * math.sin(theta)
    k = ay - E
    root = math.sqrt(L * L - k * k)
    x = ax + root
    v = omega * (-R * math.sin(theta) - k * R * math.cos(theta) / root)
    assert abs(sol["C.x"] - x) < TOL and abs(sol["C.y"] - E) < TOL
    assert abs(sol["x"] - x) < TOL
    # The velocity is omega (314) times numbers of order 0.1: 314 * 1e-12.
    assert abs(sol["velocity.x"] - v) < omega * TOL
    assert abs(sol["velocity.C.x"] - v) < omega * TOL
    # The pin stays on the line y = e: no y velocity beyond rounding
    # (the solver projects omega-sized vectors on the guide's normal).
    assert abs(sol["velocity.C.y"]) < omega * TOL
