//! The example mechanisms of `examples/common/scenes.rs` (four-bar, six-bar,
//! shaper, slider-crank, five-bar and their loaded variants), checked without
//! trusting any number the code prints:
//!
//! - [`kinematics`]: loop closure, velocities and accelerations against
//!   finite differences, f32 against f64, the source documents' values;
//! - [`forces`]: the force analysis against the documents' tables, closed
//!   forms, the power balance and every link's equilibrium;
//! - [`plots`]: the examples' SVG pictures read back with an XML parser;
//! - [`png`]: the examples' pictures rendered to pixels and looked at;
//! - [`firmware_table`]: the host's values the firmware compares with
//!   (`tests/firmware/src/expected.rs`) equal what the host computes now;
//! - [`cli_options`]: the examples' command line (options, `--help`, typos);
//! - [`drawn`]: the four-bar, five-bar, slider-crank, six-bar (a block on
//!   the crank's own line), Stephenson III, shaper (with its forces) and sine
//!   mechanism written as drawn, against the grouped scenes over their input
//!   ranges;
//! - [`inverse`]: the five-bar robot given its end point (`five_bar_ik`)
//!   against the forward five-bar.

/// The examples' command line, at the crate root where its macros expect it.
#[path = "../../examples/common/cli.rs"]
mod cli;
#[path = "../../examples/common/mod.rs"]
mod common;
/// The scenes as `crate::scenes`, where `tests/firmware/src/rows.rs` expects them.
use common::scenes;

#[path = "../../mechanism-plot/tests/check/mod.rs"]
mod check;
#[path = "../../mechanism-plot/tests/check/png.rs"]
mod render;

mod cli_options;
/// Drawn-against-grouped comparisons by column (`drawn`, `inverse`).
#[path = "../common/columns.rs"]
mod columns;
mod drawn;
mod firmware_table;
mod forces;
mod inverse;
mod kinematics;
mod plots;
mod png;
mod stephenson;
