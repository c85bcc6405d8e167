//! The scalar kernels, one function per file (as libm keeps them): sine,
//! cosine, square root and `atan2` of `f32` computed in `f32` (and integer)
//! arithmetic only, [`sin_cos_f32`] (`sin_cos.rs`), [`sqrt_f32`]
//! (`sqrt.rs`), [`atan2_f32`] and [`angle_f32`] (`atan2.rs`); and `atan2` of
//! `f64` for scalar use, [`atan2_f64`] (`atan2_f64.rs`, also reached as
//! `crate::trig64`).
//!
//! Why: libm's `sinf`/`cosf` evaluate in `f64`. On a core with a
//! single-precision FPU (Cortex-M4F, thumbv7em-none-eabihf) every `f64`
//! operation is a software routine (`__aeabi_dmul`, `__aeabi_dadd`, ...), so
//! one `sinf` costs hundreds of instructions and pulls in kilobytes of code.
//! [`sin_cos_f32`] uses only single-precision multiplies and adds, which the
//! FPU does in hardware, and 32-bit integer multiplies for range reduction.
//!
//!
//! Each file states its domain, accuracy and method, and tests its bound
//! against `f64` (`std`'s functions of the widened arguments, far more
//! accurate than the bounds).

mod atan2;
pub mod atan2_f64;
mod sin_cos;
mod sqrt;
#[cfg(test)]
mod ulp;

pub use atan2::{angle_f32, atan2_f32};
pub use atan2_f64::atan2_f64;
pub use sin_cos::sin_cos_f32;
pub use sqrt::{sqrt_f32, sqrt_f32_soft};

/// `2^k` for `-126 <= k <= 127`, exactly.
#[inline(always)]
fn pow2(k: i32) -> f32 {
    f32::from_bits(((127 + k) as u32) << 23)
}
