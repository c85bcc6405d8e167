"""`Mechanism.draw` and `Mechanism.animate`: the SVG text parses as XML,
its joint circles sit where `position` puts the joints (under the one
uniform, y-up screen map the two ground pivots fix), a pose that cannot
be assembled raises `PoseError`, and an animation has one frame per pose
that assembles.

Tolerance: the SVG writes screen coordinates with two decimals (0.005 px
each); the scale taken from the pivots' rounded places errs by at most
0.01 px / 3.5 per unit over coordinates below 4, so 0.03 px holds, while a
joint drawn at a wrong place (another branch, a wrong angle) is off by
tens of pixels.
"""

import math
import xml.etree.ElementTree as ET

import numpy as np
import pytest

import planar_mechanism as pm

from conftest import D, REACH

SVG = "{http://www.w3.org/2000/svg}"
TOL_PX = 0.03


def joints(svg: str) -> dict:
    """Screen centre of each named joint circle (the first of each name)."""
    root = ET.fromstring(svg)
    out: dict = {}
    for c in root.iter(SVG + "circle"):
        name = c.get("data-name")
        if name is not None and name not in out:
            out[name] = (float(c.get("cx")), float(c.get("cy")))
    return out


def test_draw_puts_the_joints_where_position_does(fourbar: pm.Mechanism) -> None:
    theta = math.radians(30.0)
    svg = fourbar.draw(theta=theta)
    at = joints(svg)
    o, o4 = at["O2"], at["O4"]
    assert abs(o[1] - o4[1]) < 0.01, "the ground line is horizontal"
    scale = (o4[0] - o[0]) / D
    assert scale > 0.0
    pos = fourbar.position(theta=theta)
    for name in ("A", "B"):
        want = (o[0] + scale * pos[f"{name}.x"], o[1] - scale * pos[f"{name}.y"])
        got = at[name]
        assert abs(want[0] - got[0]) < TOL_PX and abs(want[1] - got[1]) < TOL_PX, (
            name,
            got,
            want,
        )


def test_draw_title_and_caption(fourbar: pm.Mechanism) -> None:
    svg = fourbar.draw(title="crank-rocker", theta=math.radians(30.0))
    assert "crank-rocker" in svg
    assert "theta = 30 deg" in svg


def test_draw_of_a_pose_that_does_not_assemble_raises_pose_error() -> None:
    m = pm.Mechanism(REACH)
    with pytest.raises(pm.PoseError):
        m.draw(s=3.0)


def test_draw_names_a_missing_input_and_an_unknown_traced_point(
    fourbar: pm.Mechanism,
) -> None:
    with pytest.raises(TypeError, match="theta"):
        fourbar.draw()
    with pytest.raises(ValueError, match="no point `Q`"):
        fourbar.draw(trace=["Q"], theta=0.5)


def test_animate_has_one_frame_per_pose_that_assembles() -> None:
    # The block's joint B exists while |s| <= sqrt(3): of the 9 values of s
    # from -3 to 3, the 5 in [-1.5, 1.5] assemble.
    m = pm.Mechanism(REACH)
    s = np.linspace(-3.0, 3.0, 9)
    ok = [abs(v) <= math.sqrt(3.0) for v in s]
    svg = m.animate(s=s, seconds=2.0, trace=["B"])
    root = ET.fromstring(svg)
    frames = [
        g for g in root.iter(SVG + "g") if "frame" in (g.get("class") or "").split()
    ]
    assert len(frames) == sum(ok)
    with pytest.raises(ValueError, match="no pose"):
        m.animate(s=np.array([5.0, 6.0]))
