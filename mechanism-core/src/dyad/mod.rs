//! The class II Assur groups, one per file, with the same function names inside:
//! `position`, `velocity`, `acceleration`.
pub mod prp;
pub mod rpp;
pub mod rpr;
pub mod rrp;
pub mod rrr;
