//! The double-double reference against answers it does not compute itself:
//!
//! - [`dd`]: the arithmetic and functions against astro-float at 256 bits;
//! - [`loop_closure`]: the position solver against exact answers, its rates
//!   against its own positions differentiated numerically;
//! - [`newton_euler`]: the reaction solver against hand-derived answers, the
//!   power balance and its typed errors.

mod dd;
mod loop_closure;
mod newton_euler;
