//! `mechanism-core`: the `no_std`, allocation-free primitives behind the
//! `mechanism!` macro, usable directly.
//!
//! - [`driver`]: crank, slider and linear actuator inputs;
//! - [`link`]: points fixed on a link and rigid-body rate relations;
//! - [`dyad`]: the five class II Assur groups RRR, RRP, RPR, PRP, RPP, each with
//!   `position`, `velocity` and `acceleration` (and kinetostatics in [`force`]);
//! - [`triad`]: the class III group of the Stephenson III six-bar (a ternary
//!   link on three legs): every assembly by a search, the one nearest a given
//!   pose, tracking, rates and the 12x12 reactions;
//! - [`linsolve`]: Gaussian elimination with row scaling and partial pivoting on
//!   fixed-size arrays;
//! - [`error`]: the typed errors.
//!
//! Conventions: the user's length unit L throughout (results scale with it);
//! angles in radians from +x, counter-clockwise positive; rates per second.
//! Every function returns `Result`; none panics; no `Ok` holds NaN or infinity.
#![no_std]
// `deny`, not `forbid`: `trig::sqrt::hw` (the FPU's square root on ARM, inline
// assembly) is the one module allowed `unsafe`.
#![deny(unsafe_code)]
#![warn(missing_docs)]
#![cfg_attr(docsrs, feature(doc_cfg))]

pub mod driver;
#[cfg(feature = "dual")]
#[cfg_attr(docsrs, doc(cfg(feature = "dual")))]
pub mod dual;
pub mod dyad;
mod eft;
pub mod error;
pub mod force;
pub mod geometry;
pub mod guide;
pub mod link;
pub mod linsolve;
pub mod mode;
pub mod ode;
mod real;
pub mod scalar;
#[cfg(feature = "serde")]
mod ser;
pub mod sincos64;
pub mod structure;
pub mod sweep;
pub mod triad;
pub mod trig;
#[doc(inline)]
pub use trig::atan2_f64 as trig64;

#[doc(hidden)]
pub mod __private;

pub use error::{Error, Fault, Primitive};
pub use mode::Mode;
pub use nalgebra::{Point2, Vector2};
pub use scalar::Real;
