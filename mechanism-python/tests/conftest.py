"""Definitions shared by the tests (texts as a user would write them)."""

import pytest

import planar_mechanism as pm

# A Grashof crank-rocker: crank a, coupler b, rocker c, ground d
# (s + l = 1 + 3.5 = 4.5 <= p + q = 2.5 + 3 = 5.5, the crank turns fully).
A, B, C, D = 1.0, 3.0, 2.5, 3.5

FOURBAR = f"""
let O2 = ground(0.0, 0.0);
let O4 = ground({D}, 0.0);
let A = crank(O2, {A}, theta) as link2;
let B = rrr(A, {B}, O4, {C}, left) as (link3, link4);
"""

# An offset slider-crank: crank r, rod l, the block's pin on the line
# y = E (the guide through the origin along +x, offset E to its left).
R, L, E = 0.1, 0.4, 0.02

SLIDER_CRANK = f"""
let O = ground(0.0, 0.0);
let line = guide((0.0, 0.0), 0 deg);
let A = crank(O, {R}, theta) as link2;
let C = rrp(A, {L}, line, plus, {E}) as (link3, ram) slide x;
"""

# The four-bar with its dimensions and circuit as run-time parameters.
PARAMETRIC = """
params { ground = 3.5, crank = 1.0, coupler = 3.0, rocker = 2.5, circuit = left }
let O2 = ground(0.0, 0.0);
let O4 = ground(ground, 0.0);
let A = crank(O2, crank, theta) as link2;
let B = rrr(A, coupler, O4, rocker, circuit) as (link3, link4);
"""

# A block driven along the x axis, joined by two links of length 1 to a
# pivot 1 above the axis: B assembles only while |s| <= sqrt(3).
# (A slider has no implied range, so the definition reads.)
REACH = """
let O4 = ground(0.0, 1.0);
let line = guide((0.0, 0.0), 0 deg);
let P = slider(line, s) as block;
let B = rrr(P, 1.0, O4, 1.0, left) as (link3, link4);
"""


@pytest.fixture
def fourbar() -> pm.Mechanism:
    return pm.Mechanism(FOURBAR)


@pytest.fixture
def slider_crank() -> pm.Mechanism:
    return pm.Mechanism(SLIDER_CRANK)


@pytest.fixture
def parametric() -> pm.Mechanism:
    return pm.Mechanism(PARAMETRIC)


@pytest.fixture
def reach() -> pm.Mechanism:
    return pm.Mechanism(REACH)
