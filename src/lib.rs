//! `mechanism`: planar linkage analysis generated per mechanism.
//!
//! Depend on this crate only. It re-exports the `no_std` core
//! ([`mechanism_core`], as [`core_api`]) and the [`mechanism!`] macro.
#![no_std]
#![forbid(unsafe_code)]

pub use mechanism_core as core_api;
pub use mechanism_core::*;
pub use mechanism_macros::mechanism;

mod batch;
#[cfg(feature = "rayon")]
pub use batch::par_solve;
pub use batch::BatchSplit;
