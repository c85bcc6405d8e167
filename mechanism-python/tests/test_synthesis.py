"""``synthesize_path``: four-bar path synthesis from Python.

Targets are the coupler points of a crank-rocker computed here (a circle
intersection written in this file, not the Rust solver), at prescribed
crank angles: an exact fit exists, so a search that works reaches an
objective at rounding level (1e-9 of the squared path size allows a
polish that stops at a relative step of 1e-10 or so, and a wrong
definition text, mode or angle convention misses by far more). The
returned definition, read by ``Mechanism``, must reproduce the returned
objective from its own coupler point, and the design must be the
Grashof crank-rocker the function promises.
"""

import math

import pytest

import planar_mechanism as pm


def coupler_point(r1, r2, r3, r4, rcx, rcy, theta0, x0, y0, th2, left=True):
    """The coupler point of the four-bar of ``synthesize_path``'s docstring
    at crank angle ``th2`` from the ground link: B where the circles about
    A (radius r3) and O4 (radius r4) meet, on the left of A -> O4 for
    ``left``."""
    ax = x0 + r2 * math.cos(theta0 + th2)
    ay = y0 + r2 * math.sin(theta0 + th2)
    ox = x0 + r1 * math.cos(theta0)
    oy = y0 + r1 * math.sin(theta0)
    dx, dy = ox - ax, oy - ay
    d = math.hypot(dx, dy)
    a = (r3 * r3 - r4 * r4 + d * d) / (2.0 * d)
    h = math.sqrt(r3 * r3 - a * a) * (1.0 if left else -1.0)
    bx = ax + (a * dx - h * dy) / d
    by = ay + (a * dy + h * dx) / d
    ux, uy = (bx - ax) / r3, (by - ay) / r3
    return ax + rcx * ux - rcy * uy, ay + rcx * uy + rcy * ux


# A crank-rocker: r2 = 1.2 shortest, 1.2 + 4.5 <= 3.5 + 4.0.
TRUE = dict(r1=4.0, r2=1.2, r3=3.5, r4=4.5, rcx=1.5, rcy=1.0, theta0=0.3, x0=0.5, y0=-0.2)
ANGLES = [0.4 + 0.5 * k for k in range(8)]
TARGETS = [coupler_point(**TRUE, th2=t) for t in ANGLES]


@pytest.fixture(scope="module")
def found():
    return pm.synthesize_path(
        TARGETS, angles=ANGLES, links=(0.0, 10.0), coords=(-10.0, 10.0), starts=100, hops=100
    )


def test_an_exact_fit_is_found(found):
    scale = max(x * x + y * y for x, y in TARGETS)
    assert found["objective"] <= 1e-9 * scale, found


def test_the_definition_reproduces_the_objective(found):
    m = pm.Mechanism(found["definition"])
    d = found["design"]
    total = 0.0
    for th2, (tx, ty) in zip(found["angles"], TARGETS):
        p = m.position(phi=d["theta0"] + th2)
        total += (p["P.x"] - tx) ** 2 + (p["P.y"] - ty) ** 2
        # The same point from this file's own circle intersection.
        cx, cy = coupler_point(**d, th2=th2, left=found["mode"] == "left")
        assert abs(cx - p["P.x"]) <= 1e-9 and abs(cy - p["P.y"]) <= 1e-9
    assert total == pytest.approx(found["objective"], rel=1e-6, abs=1e-20)
    assert found["angles"] == pytest.approx(ANGLES, abs=0.0)


def test_the_design_is_a_grashof_crank_rocker_within_bounds(found):
    d = found["design"]
    links = [d["r1"], d["r2"], d["r3"], d["r4"]]
    assert d["r2"] == min(links)
    s, l = min(links), max(links)
    p, q = sorted(links)[1:3]
    assert s + l <= p + q + 1e-12
    assert all(0.0 <= r <= 10.0 for r in links)
    assert all(-10.0 <= d[k] <= 10.0 for k in ("rcx", "rcy", "x0", "y0"))
    assert found["mode"] in ("left", "right")
    assert found["evaluations"] > 0 and found["jacobians"] > 0


def test_the_same_seed_gives_the_same_design():
    args = dict(angles=ANGLES[:5], links=(0.0, 10.0), coords=(-10.0, 10.0), starts=10, hops=5)
    a = pm.synthesize_path(TARGETS[:5], seed=7, **args)
    b = pm.synthesize_path(TARGETS[:5], seed=7, **args)
    assert a == b


def test_free_timing_returns_ascending_angles():
    found = pm.synthesize_path(
        TARGETS, links=(0.0, 10.0), coords=(-10.0, 10.0), starts=20, hops=20, seed=1
    )
    a = found["angles"]
    assert len(a) == len(TARGETS)
    assert all(0.0 <= x <= 2.0 * math.pi for x in a)
    assert a == sorted(a)
    assert math.isfinite(found["objective"])


@pytest.mark.parametrize(
    "kwargs, message",
    [
        (dict(targets=[(0.0, 0.0), (1.0, 1.0)]), "at least 3"),
        (dict(targets=TARGETS, angles=ANGLES[:3]), "one crank angle per point"),
        (dict(targets=TARGETS, angles=[7.0] * len(TARGETS)), "[0, 2 pi]"),
        (dict(targets=TARGETS, links=(5.0, 1.0)), "lo < hi"),
        (dict(targets=[(0.0, 0.0), (float("nan"), 1.0), (2.0, 2.0)]), "not finite"),
        (dict(targets=TARGETS, starts=0), "starts = 0"),
    ],
)
def test_bad_arguments_are_value_errors(kwargs, message):
    with pytest.raises(ValueError, match=__import__("re").escape(message)):
        pm.synthesize_path(**kwargs)
