//! The definition language's surface: what `mechanism!` accepts, checked
//! against quantities recomputed here (constraints, closed forms, finite
//! differences, Newton-Euler, the power balance), never against the code
//! under test:
//!
//! - [`statement_kinds`]: every statement kind (drivers, groups, carried
//!   guides) through the macro;
//! - [`dsl`]: names, statement order, parameters, expressions, output
//!   subsets and `#[self_test]` in combinations the other tests do not write;
//! - [`sweep`]: the assembly-range checks (`check()`, the run-time errors at
//!   the limits, the ranges the expansion-time check suggests);
//! - [`forces`]: the force analysis on loaded definitions the zoo does not have;
//! - [`functions`]: functions in dimensions (`sqrt`, `hypot`, ...);
//! - [`masses`]: several masses on one link against the hand-merged body;
//! - [`relative_drivers`]: a crank carried by a moving link and a slider on
//!   a carried guide, against Newton-Euler worked by hand;
//! - [`describe`]: a mechanism's description of itself (`mechanism::structure`)
//!   and the pictures and tables drawn from it alone;
//! - [`self_test_scales`]: `#[self_test]` passing at scales from 1e-9 to 1e9.
//!
//! Chains of 10, 20 and 40 groups are a test crate of their own
//! (`tests/long_chain.rs`): their expansion is the largest single cost of a
//! rebuild, and on its own it builds beside this crate instead of after it.

#[path = "../common/equilibrium.rs"]
#[allow(dead_code)]
mod equilibrium;
/// The pictures' looked-at check (rendered with resvg).
#[path = "../../mechanism-plot/tests/check/png.rs"]
mod render;
#[path = "../common/surface_defs.rs"]
mod surface_defs;

mod describe;
mod drawn;
mod dsl;
mod forces;
mod functions;
mod inverse;
mod masses;
mod relative_drivers;
mod self_test_scales;
mod statement_kinds;
mod sweep;
