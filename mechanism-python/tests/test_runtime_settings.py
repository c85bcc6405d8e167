"""Parameters and assembly modes change at run time, and the outputs
follow: a longer crank moves A out to the new radius, the other circuit
mirrors B to the other side of the ground line. Names and units are as in
the generated structs.
"""

import math

import pytest

from conftest import A, B, C, D


def test_inputs_and_outputs_with_units(fourbar):
    (theta,) = fourbar.inputs
    assert theta.name == "theta" and theta.unit == "rad"
    assert theta.range == (0.0, 2.0 * math.pi)
    assert list(fourbar.outputs.items()) == [
        ("O2.x", "L"), ("O2.y", "L"), ("O4.x", "L"), ("O4.y", "L"),
        ("A.x", "L"), ("A.y", "L"), ("B.x", "L"), ("B.y", "L"),
        ("link2", "rad"), ("link3", "rad"), ("link4", "rad"),
    ]
    assert fourbar.columns("velocity")["B.x"] == "L/s"
    assert fourbar.columns("acceleration")["link4"] == "rad/s^2"
    assert fourbar.name == "Mechanism"


def test_set_param_changes_the_geometry(parametric):
    assert parametric.params == {"ground": D, "crank": A, "coupler": B, "rocker": C}
    parametric.set_param("crank", 1.25)
    assert parametric.params["crank"] == 1.25
    pos = parametric.position(theta=0.7)
    # A is on the crank circle of the new radius (one rounding of cos/sin).
    assert abs(math.hypot(pos["A.x"], pos["A.y"]) - 1.25) < 1e-15
    assert abs(math.hypot(pos["B.x"] - pos["A.x"], pos["B.y"] - pos["A.y"]) - B) < 1e-12


def test_set_param_rejects_unknown_names_and_non_finite(parametric):
    with pytest.raises(KeyError, match="no parameter `crnk`"):
        parametric.set_param("crnk", 1.0)
    with pytest.raises(ValueError, match="not a finite number"):
        parametric.set_param("crank", float("nan"))
    assert parametric.params["crank"] == A


def test_set_mode_switches_the_circuit(parametric):
    """This crank-rocker's two circuits are mirror images in the line
    A -> O4; at theta = 0 that line is the x axis, so B.y changes sign."""
    assert parametric.modes == {"circuit": "plus"}
    left = parametric.position(theta=0.0)
    parametric.set_mode("circuit", "right")
    assert parametric.modes == {"circuit": "minus"}
    right = parametric.position(theta=0.0)
    assert left["B.y"] > 0.0 and right["B.y"] < 0.0
    assert abs(left["B.y"] + right["B.y"]) < 1e-12
    assert abs(left["B.x"] - right["B.x"]) < 1e-12
    parametric.set_mode("circuit", "plus")
    assert parametric.position(theta=0.0) == left


def test_set_mode_rejects_unknown_names_and_words(parametric):
    with pytest.raises(KeyError, match="no mode parameter `elbow`"):
        parametric.set_mode("elbow", "left")
    with pytest.raises(ValueError, match="`up` is not a mode"):
        parametric.set_mode("circuit", "up")
