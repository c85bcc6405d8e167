//! An independent high-precision reference for `mechanism`.
//!
//! Nothing here shares code with `mechanism-core` or the code `mechanism!`
//! generates: the arithmetic is double-double ([`Dd`], about 106 bits), the
//! solvers are written from the equations (loop closure, Newton-Euler), and
//! the elementary functions are checked against `astro-float` in the tests.
//! Used by the report, the benchmarks and the stability tests; `std` only.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod constraint;
mod dd;
pub mod equations;
pub mod four_bar_dynamics;
pub mod groups;
pub mod linear;
pub mod loop_closure;
pub mod multibody;
pub mod naive;
pub mod newton_euler;
pub mod triad;

pub use dd::Dd;
