//! The class II Assur groups, one per file, with the same function names inside:
//! `position`, `velocity`, `acceleration`.
pub mod rrr;
