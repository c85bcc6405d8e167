//! What the code `mechanism!` generates calls and users should not: the
//! batch kernels ([`lane`]: one element of a structure of arrays, without a
//! branch) and the determinants the generated `check()` watches. Names and
//! signatures may change in any release; the documented API is everything
//! else. (serde's `__private` is the model.)

#[path = "lane/mod.rs"]
pub mod lane;

pub use crate::sweep::{det_prp, det_rpp, det_rpr, det_rrp, det_rrr};
