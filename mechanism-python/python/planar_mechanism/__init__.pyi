"""Type stubs of ``planar_mechanism`` (the native module ``_native``).

Units and signs throughout: angles in rad, counter-clockwise from +x;
lengths in the definition's own unit ``L``; rates per second (rad/s,
L/s), accelerations per second squared.
"""

from typing import Any, Dict, List, Mapping, Optional, Sequence, Tuple, final

import numpy.typing as npt

__all__ = [
    "Diagnostic",
    "Input",
    "Mechanism",
    "MechanismError",
    "PoseError",
    "synthesize_path",
]

@final
class Diagnostic:
    """One error of a definition, where the text says it.

    Lines and columns are 1-based, columns counted in characters, as the
    ``--> <definition>:LINE:COLUMN`` line of the message shows them. The
    blamed text runs from (``line``, ``column``) up to, not including,
    (``end_line``, ``end_column``). ``line`` is 0 for an error about the
    definition as a whole.
    """

    @property
    def message(self) -> str:
        """The message, as the ``mechanism!`` macro reports it."""
    @property
    def line(self) -> int: ...
    @property
    def column(self) -> int: ...
    @property
    def end_line(self) -> int: ...
    @property
    def end_column(self) -> int: ...

class MechanismError(ValueError):
    """A definition that does not read.

    ``str(e)`` holds every diagnostic as rustc shows it (``error: ...``,
    `` --> <definition>:LINE:COLUMN``, the line of the text with the blamed
    characters underlined by ``^``).
    """

    diagnostics: List[Diagnostic]
    """Every error, in the order of the text."""
    text: str
    """The definition's text."""

class PoseError(ValueError):
    """The mechanism cannot be assembled at the given inputs, or its
    velocity system is singular there.

    ``str(e)`` says where and why, naming the group.
    """

    group: str
    """The definition's group (joint or block) that failed; "" if none."""
    inputs: Dict[str, float]
    """The inputs at which it failed, by name."""

@final
class Input:
    """A driver input of a definition."""

    @property
    def name(self) -> str:
        """The keyword of ``position(...)``, ``sweep(...)``."""
    @property
    def unit(self) -> str:
        """``"rad"`` for an angle, ``"L"`` for a length."""
    @property
    def range(self) -> Optional[Tuple[float, float]]:
        """``(lo, hi)`` declared or implied (a crank's ``(0, 2*pi)``), in
        ``unit``; ``None`` when it has none."""

@final
class Mechanism:
    """A planar mechanism read from the text of a definition.

    ``text`` is what goes between the braces of ``mechanism! { ... }`` (the
    drawn or the grouped form), or the whole ``pub Name { ... }`` item.
    Raises ``MechanismError`` carrying every diagnostic with its line and
    column. Usable from any thread; ``sweep`` releases the GIL while it
    solves.
    """

    def __new__(cls, text: str) -> "Mechanism": ...
    @property
    def name(self) -> str:
        """The type name (``"Mechanism"`` for a body alone)."""
    @property
    def inputs(self) -> List[Input]:
        """The driver inputs, in the order of the generated input struct."""
    @property
    def outputs(self) -> Dict[str, str]:
        """Position outputs ``{name: unit}`` in the generated struct's
        order: points ``"B.x"``, ``"B.y"`` (``"L"``), link angles
        ``"link3"`` (``"rad"``, of the link's axis from +x,
        counter-clockwise), slides ``"s"`` (``"L"``)."""
    def columns(self, analysis: str) -> Dict[str, str]:
        """Outputs ``{name: unit}`` of ``"position"``, ``"velocity"``
        (``"L/s"``, ``"rad/s"``), ``"acceleration"`` (``"L/s^2"``,
        ``"rad/s^2"``) or ``"forces"`` (forces ``F``, torques ``F L``, or
        the definition's ``units``). ``ValueError`` for another word."""
    @property
    def params(self) -> Dict[str, float]:
        """Run-time parameters ``{name: value}`` (a copy)."""
    def set_param(self, name: str, value: float) -> None:
        """Sets a parameter (finite). ``KeyError``: unknown name (the
        message lists the names); ``ValueError``: not finite."""
    @property
    def modes(self) -> Dict[str, str]:
        """Run-time assembly modes ``{name: "plus" | "minus"}``
        (``"plus"`` is ``left``, ``"minus"`` is ``right``)."""
    def set_mode(self, name: str, mode: str) -> None:
        """Sets a mode to ``"left"``/``"plus"`` or ``"right"``/``"minus"``.
        ``KeyError``: unknown name; ``ValueError``: another word."""
    @property
    def has_forces(self) -> bool:
        """Whether the definition has a force analysis (masses, loads or
        ``analysis forces;``)."""
    @property
    def loads(self) -> Dict[str, float]:
        """The ``loads { .. }`` values ``{name: value}`` (a copy)."""
    def set_load(self, name: str, value: float) -> None:
        """Sets a load (finite). ``KeyError``: unknown name; ``ValueError``:
        not finite."""
    def forces(
        self,
        *,
        rates: Mapping[str, float],
        accels: Mapping[str, float],
        **inputs: float,
    ) -> Dict[str, float]:
        """The force analysis at one pose with the current loads: the keys
        of ``columns("forces")``: joint reactions ``r_FROM_TO.x``, ``.y``
        (on TO from FROM), prismatic ``.force.x``, ``.force.y``,
        ``.moment``, driving efforts by name, ``condition``,
        ``power_residual``. Signs: docs/dynamics.md. ``ValueError``
        without a force analysis."""
    def position(self, **inputs: float) -> Dict[str, float]:
        """The position at one pose, every input by name (``theta=0.5``):
        ``{name: value}`` with the keys of ``outputs``.

        ``PoseError`` where it cannot be assembled; ``TypeError`` for a
        missing or unknown input."""
    def draw(
        self,
        *,
        title: Optional[str] = None,
        trace: Sequence[str] = ...,
        **inputs: float,
    ) -> str:
        """The drawing of one pose, every input by name (``theta=0.5``), as
        SVG text: ground pivots with hatching, links as bars or plates,
        blocks on their guides, joints as circles; world coordinates in the
        definition's unit, y up. ``title`` defaults to the definition's
        name; ``trace`` names points to mark.

        ``PoseError`` where the pose cannot be assembled; ``TypeError`` for
        a missing or unknown input; ``ValueError`` for a point to trace
        that does not exist."""
    def animate(
        self,
        *,
        seconds: float = 4.0,
        title: Optional[str] = None,
        trace: Sequence[str] = ...,
        **inputs: npt.ArrayLike,
    ) -> str:
        """The animation of a sweep, every input by name (a number or a 1-d
        array, broadcast together), as SVG text playing in ``seconds`` and
        repeating: ``draw``'s picture at each pose that assembles (the
        others are left out) and the paths of the ``trace``d points.

        ``ValueError`` when no pose assembles or a point to trace does not
        exist."""
    def velocity(self, *, rates: Mapping[str, float], **inputs: float) -> Dict[str, float]:
        """The velocity at one pose for the input rates ``rates`` (one per
        input, rad/s or L/s): the keys of ``columns("velocity")`` and
        ``"condition"``, the smallest scaled determinant of the groups'
        velocity systems in (0, 1] (near 0: near a singular pose)."""
    def acceleration(
        self,
        *,
        rates: Mapping[str, float],
        accels: Mapping[str, float],
        **inputs: float,
    ) -> Dict[str, float]:
        """The acceleration at one pose for the input rates and
        accelerations (one per input each): the keys of
        ``columns("acceleration")``."""
    def solve(
        self,
        *,
        rates: Optional[Mapping[str, float]] = None,
        accels: Optional[Mapping[str, float]] = None,
        forces: bool = False,
        **inputs: float,
    ) -> Dict[str, float]:
        """Every analysis asked for at one pose, as one flat dict with the
        keys of ``sweep`` (without the inputs, ``ok``, ``error``). ``accels``
        needs ``rates``; ``forces=True`` needs ``accels``."""
    def sweep(
        self,
        *,
        rates: Optional[Mapping[str, npt.ArrayLike]] = None,
        accels: Optional[Mapping[str, npt.ArrayLike]] = None,
        forces: bool = False,
        threads: Optional[int] = None,
        **inputs: npt.ArrayLike,
    ) -> Dict[str, npt.NDArray[Any]]:
        """Solves every pose of a sweep in Rust (no Python call per pose).

        Every input by name, each a number or an array; inputs, rates and
        accelerations are broadcast together as numpy broadcasts (use
        ``np.meshgrid`` for a grid), giving the shape ``S`` of every
        returned array. Returns float64 arrays of shape ``S``:

        - each input (a copy, broadcast);
        - each position output (``"B.x"``, ``"link3"``, ...);
        - with ``rates``: ``"velocity.NAME"`` for each velocity output and
          ``"velocity.condition"``;
        - with ``accels`` (needs ``rates``): ``"acceleration.NAME"``;
        - with ``forces=True`` (needs ``accels``): ``"forces.NAME"``;

        and the per-pose status:

        - ``"ok"``: bool array, ``False`` where the pose failed;
        - ``"error"``: object array, ``None`` where solved, else the
          message naming the failed group.

        A pose that fails (out of reach, singular velocity system) has NaN
        in every output of its row and only there; a solved pose never
        holds NaN. Check ``ok`` (or ``error``) before using a row.

        ``threads``: how many threads solve the rows (``None``: one per
        core, each given at least 8192 rows, so a short sweep stays on
        the calling thread; ``1``: the calling thread only). The threads
        are started and joined within the call (nothing is left running
        for a later ``fork``); the GIL is released meanwhile. The numbers
        are the same whatever the count."""
    def __repr__(self) -> str: ...

def synthesize_path(
    targets: Sequence[Tuple[float, float]],
    *,
    angles: Optional[Sequence[float]] = None,
    frame: Optional[Tuple[float, float, float]] = None,
    links: Tuple[float, float] = (0.0, 60.0),
    coords: Tuple[float, float] = (-60.0, 60.0),
    starts: int = 300,
    hops: int = 300,
    seed: int = 0,
) -> Dict[str, Any]:
    """A four-bar whose coupler point passes through ``targets`` (least
    squares: the sum of squared distances from the coupler point at each
    target's crank angle to the target).

    The four-bar: ground pivot ``O2 = (x0, y0)``, the other ground pivot at
    ``r1`` from it at angle ``theta0``, crank ``r2`` at angle ``th2`` from
    the ground link, coupler ``r3``, rocker ``r4``, the coupler point at
    ``(rcx, rcy)`` in the frame of ``A -> B``; always a Grashof crank-rocker
    with the crank shortest (it turns fully), in the assembly mode that fits
    better.

    ``targets``: the points (at least 3). ``angles``: the crank angle from
    the ground link at each target (rad, in ``[0, 2 pi]``), or ``None`` for
    free timing. ``frame``: ``(theta0, x0, y0)`` fixed, or ``None`` for
    free. ``links``: bounds of ``r1 .. r4``; ``coords``: bounds of ``rcx,
    rcy, x0, y0``. ``starts`` (local solves per assembly mode), ``hops``
    (basin hops) and ``seed`` size the search; the result depends only on
    the arguments. ``ValueError`` for bad arguments or when no design
    assembles at every target.

    Returns ``objective``, ``mode`` (``"left"`` or ``"right"``), ``design``
    (``r1 .. y0`` by name), ``angles`` (crank angles from the ground link,
    rad), ``definition`` (the four-bar's text, input ``phi`` = ``theta0 +
    th2``: give it to ``Mechanism``), ``evaluations`` and ``jacobians``.
    Releases the GIL while it searches."""
