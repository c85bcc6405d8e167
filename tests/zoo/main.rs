//! Mechanisms that none of the examples define, checked only against laws the
//! generated code does not use: Newton-Euler for every link (the reactions
//! the force analysis returns, the loads and the inertia terms must sum to
//! zero force and moment on each body), the power balance (the drives' power
//! equals minus the power of every load, weight and inertia term), the
//! constraint lengths, and central finite differences of the generated
//! position and velocity.
//!
//! Revolute chains (`revolute.rs`):
//!
//! - `WattII`: a four-bar whose rocker is a ternary link driving a second
//!   RRR group (two loops; the rocker carries three joints, so the second
//!   group's reactions reach the first group's force system as loads).
//! - `StephensonIII`: a four-bar whose coupler point drives an RRR group
//!   (the ternary link is the coupler, moving on both sides).
//! - `LoadedFiveBar`: two cranks (two degrees of freedom, two drive torques)
//!   with masses on all four moving links.
//! - `StephensonIII` with its last group shortened (run-time parameters) so
//!   that it cannot close over part of the turn, swept at 0.01 deg in f64
//!   and f32: a full finite solution (forces included) or a typed error
//!   naming the group, at every step.
//!
//! Prismatic pairs and linear drives (`prismatic.rs`):
//!
//! - `PistonDriven`: an offset engine driven by the force on its piston (a
//!   `slider` driver); the RRR group turns the crank against a load torque.
//! - `LoadedBoom`: a boom lifted by a hydraulic `actuator` (the drive is the
//!   cylinder's axial force; the massless cylinder is a two-force member).
//! - `LoadedYoke`: a Scotch yoke (`rpp`): the block in the yoke's slot, the
//!   yoke on its vertical guide, a resisting force along that guide; each
//!   prismatic reaction is applied as its normal force at its stated
//!   reference point plus its couple.
//! - `SlottedRocker`: an RPR (the crank's block on the rocker) and an RRP
//!   whose guide is a slot carried by the rocker: the slot's reaction loads
//!   the moving rocker, which also carries the block's.
//! - `LoadedCrossSlide`: a PRP group whose first guide is the crank's own
//!   line (carried by the crank) and whose second is fixed: both prismatic
//!   reactions and the pin between the blocks, with a resisting force
//!   along the fixed guide.
//! - `CarriedYoke`: an RPP whose guide is the crank's own line: a frame
//!   slides along it with a slot at right angles, in which a block pinned
//!   to the ground slides; the frame's reaction (force and couple) loads
//!   the crank.
//!
//! Groups whose outer joints all move (`floating.rs`):
//!
//! - `FloatingCylinder`: an RPR between a four-bar's coupler and rocker (both
//!   pins of the sleeve-and-rod pair move), and an RRP pinned to the crank
//!   whose block runs in a slot carried by the rod. The sleeve's and the
//!   block's centres are off their pins, so both prismatic couples are
//!   non-zero; a pull along the rod, a force along the slot, a couple on the
//!   rocker.
//!
//! Toggle presses, against the double-double reference's Newton-Euler and
//! closed forms (`toggle_press.rs`, bounds `c eps S / kappa^k` justified
//! there; the shared reference helpers in `dd_reference.rs`):
//!
//! - `KnucklePress`: crank -> RRR -> RRP toggle press, 100 kN on the ram,
//!   swept by decades to 1.4e-12 rad of both toggles in f64 and f32: the
//!   drive vanishes linearly, every column within 8 eps of its group's scale.
//! - `SliderKnuckle`: the knuckle driven by its ram into the RRR's fold and
//!   past it: reactions growing as `1 / sin` accurate to `eps S / sin^2`, a
//!   typed error naming the group past the fold.
//!
//! Quick return (`quick_return.rs`, against the same reference):
//!
//! - `Whitworth`: quick return with a ram, masses, gravity, a cutting force:
//!   forces over a turn (f64, f32), masses 1e-6 .. 1e6 kg, lengths times
//!   1e-6 and 1e6; the strokes' crank angles, time ratio and stroke against
//!   their closed forms.
//!
//! Triads (`triad_params.rs`, against the double-double reference's own
//! Newton, `mechanism_reference::triad`):
//!
//! - the Stephenson III triad with its legs, side and P's place from
//!   `params` (one from `sqrt`), at three parameter sets; with K2 on a
//!   second crank (two inputs) over a grid, rates and accelerations
//!   included; the typed errors of a pose that cannot assemble and of bad
//!   parameters.
//!
//! Tolerances. Equilibrium and power: each residual is a sum of a handful of
//! products of generated values, every value within a few eps times the
//! conditioning of its linear system (the poses below keep the relative
//! pivots above 0.05), so the residuals are a few hundred eps of the largest
//! term at most: 1e-13 (450 eps; the worst measured is below 4e-15, 18 eps).
//! A missing or wrong term shows at its own size: the smallest term here is
//! about 1e-3 of the largest, 1e10 times the tolerance. Finite differences:
//! `h = 1e-5` gives a truncation error of about `h^2` times the third
//! derivative (1e-10 of the scale) and a rounding error of `eps / h` (2e-11);
//! 1e-7 of the scale leaves room and catches a wrong term (order 1e-1).

#[path = "../common/equilibrium.rs"]
mod equilibrium;

mod classic;
mod dd_reference;
mod excavator;
mod floating;
mod prismatic;
mod quick_return;
mod revolute;
mod toggle_press;
mod triad_params;
