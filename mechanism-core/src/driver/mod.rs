//! Drivers: the inputs of a mechanism.
pub mod actuator;
pub mod crank;
pub mod slider;
pub mod target;
