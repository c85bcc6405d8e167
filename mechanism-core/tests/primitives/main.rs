//! The core primitives (drivers, groups, link points, kinetostatics, the
//! linear solver) against facts they do not compute themselves:
//!
//! - [`closed_forms`]: the five groups' closed-form kinetostatics against the
//!   general elimination of the same equations and, near singular poses,
//!   a double-double solution;
//! - [`exact_configurations`]: hand-derivable configurations compared exactly
//!   or to 2 ulp, the error variants with their numbers, and a fuzz test
//!   (no input panics or gives a non-finite `Ok`);
//! - [`kinematics_fd`]: velocities and accelerations against central finite
//!   differences, and loop closure, for every primitive;
//! - [`kinetostatics`]: the reactions and driving efforts against seed 003,
//!   each link's equilibrium, exact rational solutions and the power balance;
//! - [`linsolve`]: the scaled, pivoted solver against nalgebra's LU and on
//!   the failure cases of naive elimination.

mod closed_forms;
mod exact_configurations;
mod kinematics_fd;
mod kinetostatics;
mod linsolve;
