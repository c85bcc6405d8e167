//! What a program that connects a mechanism to the rest of Rust relies on,
//! by subject (one module each):
//!
//! - `display`: `Display` of each result struct and of a solution prints
//!   one line per struct with units, to the formatter's precision (exact
//!   strings worked out by hand for a crank and a parallelogram four-bar);
//! - `modes`: a group's assembly mode read at run time from a parameter
//!   agrees to the bit with the two definitions that fix it at compile time,
//!   in the scalar analyses and in the batch;
//! - `serde` (feature `serde`, `cargo test --test interop --features
//!   serde`): the derives written on a definition give JSON of the user's
//!   names only, and the parameters and inputs read back.

mod display;
mod modes;
#[cfg(feature = "serde")]
mod serde;
