"""Planar linkages from a declarative definition, solved in Rust.

``Mechanism(text)`` reads the text of a definition (what goes between the
braces of Rust's ``mechanism! { ... }``) at run time, through the same
stages and rules as the macro, and solves it in Rust: ``position``,
``velocity``, ``acceleration`` and ``solve`` at one pose (dicts of floats),
``sweep`` over numpy arrays of inputs (dicts of numpy arrays).
``synthesize_path`` finds a four-bar whose coupler point passes through
given points and returns its definition's text.

Units and signs: angles in rad, counter-clockwise from +x; lengths in the
definition's own unit (``L``); rates per second. See ``docs/python.md``.
"""

from ._native import (
    Diagnostic,
    Input,
    Mechanism,
    MechanismError,
    PoseError,
    synthesize_path,
)

__all__ = [
    "Diagnostic",
    "Input",
    "Mechanism",
    "MechanismError",
    "PoseError",
    "synthesize_path",
]
