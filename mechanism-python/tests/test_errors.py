"""Bad input raises Python exceptions that say where and why: a definition
that does not read raises `MechanismError` (a `ValueError`) with every
diagnostic, rustc-style, and each as a `Diagnostic` with its line and
column; a pose that cannot be assembled raises `PoseError` naming the
group; a missing or unknown input is a `TypeError`.
"""

import pytest

import planar_mechanism as pm

TWO_ERRORS = """let O2 = ground(0.0, 0.0);
let A = crank(O9, 1.0, theta) as link2;
let B = rrr(A, 3.0, O7, 2.5, left) as (link3, link4);
"""


def test_definition_errors_carry_line_and_column():
    with pytest.raises(pm.MechanismError) as caught:
        pm.Mechanism(TWO_ERRORS)
    e = caught.value
    assert isinstance(e, ValueError)
    assert e.text == TWO_ERRORS
    # Every error at once, in the order of the text.
    assert [(d.line, d.column) for d in e.diagnostics] == [(2, 15), (3, 21)]
    first = e.diagnostics[0]
    assert "`O9`" in first.message
    assert (first.end_line, first.end_column) == (2, 17)  # "O9" spans 15..17
    text = str(e)
    assert " --> <definition>:2:15" in text
    assert "2 | let A = crank(O9, 1.0, theta) as link2;" in text
    assert "  |               ^^" in text
    assert "due to 2 previous errors" in text


def test_a_syntax_error_is_a_mechanism_error():
    with pytest.raises(pm.MechanismError) as caught:
        pm.Mechanism("let O2 = ground(0.0, 0.0)\nlet A = crank(O2, 1.0, theta) as link2;")
    assert caught.value.diagnostics[0].line >= 1


def test_unreadable_text_is_a_mechanism_error():
    with pytest.raises(pm.MechanismError):
        pm.Mechanism("let O2 = ground(0.0, 0.0); )(")


def test_pose_error_names_group_and_inputs(reach):
    with pytest.raises(pm.PoseError) as caught:
        reach.position(s=3.0)
    e = caught.value
    assert isinstance(e, ValueError)
    assert e.group == "B" and e.inputs == {"s": 3.0}
    assert "group `B`" in str(e) and "s=3" in str(e)


def test_inputs_are_checked_by_name(fourbar):
    with pytest.raises(TypeError, match="missing value for input `theta`"):
        fourbar.position()
    with pytest.raises(TypeError, match="no input `phi`; the inputs are: `theta`"):
        fourbar.position(theta=0.0, phi=1.0)
    with pytest.raises(TypeError, match="missing rate for input `theta`"):
        fourbar.velocity(theta=0.0, rates={})
    with pytest.raises(ValueError, match="no analysis `jerk`"):
        fourbar.columns("jerk")
