//! Drivers: the inputs of a mechanism.
pub mod crank;
