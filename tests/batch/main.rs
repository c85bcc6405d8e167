//! The batch API (`solve_batch` and its lane kernel) against the scalar path,
//! element by element, over grids that include failing poses:
//!
//! - [`examples`]: every example scene and the drivers and groups the scenes do
//!   not use; the tolerance and the four points checked are stated there;
//! - [`surface`]: the unusual definitions of `tests/common/surface_defs.rs`
//!   and more (carried guides, points on blocks, two inputs, output subsets).

// Unicode names in `surface.rs`'s definitions.
#![allow(mixed_script_confusables, confusable_idents)]

// `compare!` and `one_input!`: the comparison both modules run.
#[macro_use]
#[path = "../common/batch_compare.rs"]
mod batch_compare;
#[path = "../common/surface_defs.rs"]
mod surface_defs;

mod examples;
mod forces;
mod surface;
