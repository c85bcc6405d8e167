//! The example mechanisms (gathered in `examples/common/scenes.rs`: four-bar, six-bar,
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
//!   against the forward five-bar;
//! - [`scenes_file`]: `examples/common/scenes.rs` holds the examples' own
//!   definitions, as they are now.
#![allow(clippy::duplicate_mod)]

/// The examples' command line, at the crate root where its macros expect it.
#[path = "../../examples/common/cli.rs"]
mod cli;
#[path = "../../examples/common/mod.rs"]
mod common;
/// The scenes as `crate::scenes`, where `tests/firmware/src/rows.rs` expects them
/// (the examples' definitions, gathered by [`scenes_file`]).
#[path = "../../examples/common/scenes.rs"]
mod scenes;

// The examples' own files, for their `pictures` (each also has its `main`,
// unused here). Each mounts the examples' `common` as its own module, as it
// does when built as an example: the copies are meant (clippy::duplicate_mod).
#[allow(dead_code, unused_imports, unused_macros)]
#[path = "../../examples/five_bar.rs"]
mod example_five_bar;
#[allow(dead_code, unused_imports, unused_macros)]
#[path = "../../examples/fourbar.rs"]
mod example_fourbar;
#[allow(dead_code, unused_imports, unused_macros)]
#[path = "../../examples/geared_five_bar.rs"]
mod example_geared_five_bar;
#[allow(dead_code, unused_imports, unused_macros)]
#[path = "../../examples/shaper.rs"]
mod example_shaper;
#[allow(dead_code, unused_imports, unused_macros)]
#[path = "../../examples/shaper_forces.rs"]
mod example_shaper_forces;
#[allow(dead_code, unused_imports, unused_macros)]
#[path = "../../examples/sine_mechanism.rs"]
mod example_sine_mechanism;
#[allow(dead_code, unused_imports, unused_macros)]
#[path = "../../examples/sixbar.rs"]
mod example_sixbar;
#[allow(dead_code, unused_imports, unused_macros)]
#[path = "../../examples/slider_crank.rs"]
mod example_slider_crank;

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
mod scenes_file;
mod stephenson;
