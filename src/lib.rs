//! `mechanism`: planar linkage analysis generated per mechanism.
//!
//! Depend on this crate only. It re-exports the `no_std` core
//! ([`mechanism_core`], as [`core_api`]) and the [`mechanism!`] macro.
#![no_std]
#![forbid(unsafe_code)]

pub use mechanism_core as core_api;
pub use mechanism_core::*;
pub use mechanism_macros::mechanism;

pub mod batch;
#[cfg(feature = "rayon")]
pub use batch::par_solve;
pub use batch::{BatchError, BatchSplit};

#[cfg(feature = "alloc")]
extern crate alloc;

/// `alloc` for the owned batch form of the generated code (inside
/// `__with_alloc!`, feature `alloc`; see [`batch`]). Not public API.
#[cfg(feature = "alloc")]
#[doc(hidden)]
pub mod __alloc {
    pub use alloc::vec::Vec;
}
