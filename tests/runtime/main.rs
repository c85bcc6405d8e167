//! The run-time mechanism (`mechanism_codegen::runtime`, definitions read
//! from text) against the code `mechanism!` generates from the same text.
//!
//! - `agreement`: every definition of the examples' and the tests' scenes,
//!   its text cut from the very file the compiled definition comes from, at
//!   random inputs, rates and accelerations: every output of position,
//!   velocity and acceleration is the same `f64`, bit for bit, and every
//!   failing pose fails with the same typed error (group, primitive, fault
//!   and its numbers). Both walk the same plan calling the same core
//!   primitives with the same arguments, so nothing looser is expected.
//! - `forces`: the force analysis of the definitions with masses and
//!   loads, bit for bit, with random load values.
//! - `diagnostics`: every UI failure case (`tests/ui/*.rs` with its
//!   `.stderr`) gives, read at run time, the messages rustc shows.

mod agreement;
mod diagnostics;
mod force_kinds;
mod forces;
mod text;
