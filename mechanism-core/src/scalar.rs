//! The scalar type every primitive is generic over.
//!
//! [`Real`] is nalgebra's [`RealField`] (so results are ordinary `Point2<T>` /
//! `Vector2<T>` that users can feed to the rest of nalgebra) plus the three
//! things the primitives need that `RealField` does not name unambiguously:
//! converting a literal, widening to `f64` (for the sweep's conditioning
//! figures and the generated self-test), and machine epsilon.
//!
//! Why not a scalar trait of our own from scratch: users want nalgebra types at
//! the API, and nalgebra's arithmetic on `Vector2<T>` needs `RealField`-like
//! bounds anyway. Why not bare `RealField`: `FromPrimitive::from_f64` returns an
//! `Option` (a panic path if unwrapped) and `abs` is ambiguous between two
//! supertraits; [`Real::lit`] and [`crate::geometry::abs`] avoid both.
//! Implemented for `f32` and `f64` only.

use nalgebra::RealField;

/// `true` when `T` is `f32` (24-bit significand), `false` for `f64`: a
/// comparison of constants that folds at compile time, for the places whose
/// method depends on the precision (polynomial degrees, rounding constants,
/// compensated sums).
#[inline(always)]
pub(crate) fn single<T: Real>() -> bool {
    T::eps() > T::lit(1e-10)
}

/// `true` when `T` is `f32` or `f64` itself, `false` for a dual number
/// ([`crate::dual::Dual`]): the error-free transformations of
/// [`crate::eft`] are exact only on the former (Veltkamp's split rounds a
/// dual number's derivatives). Folds at compile time.
#[inline(always)]
pub(crate) fn native<T: Real>() -> bool {
    use core::any::TypeId;
    let t = TypeId::of::<T>();
    t == TypeId::of::<f64>() || t == TypeId::of::<f32>()
}

/// A floating-point scalar: `f32` or `f64`. `LowerExp` (`{:e}`) so that an
/// [`Error<T>`](crate::Error) prints its numbers in their own precision
/// from generic code.
pub trait Real: RealField + Copy + core::fmt::LowerExp + crate::triad::Kernels {
    /// Converts an `f64` literal (rounding to nearest for `f32`).
    fn lit(x: f64) -> Self;
    /// Widens to `f64` (exact for both implementations); used where results
    /// of either precision are compared in `f64` (sweep, self-test).
    fn as_f64(self) -> f64;
    /// Machine epsilon: the gap between 1 and the next representable number.
    fn eps() -> Self;
    /// `true` when the value is neither NaN nor infinite.
    fn finite(self) -> bool;
    /// `(sin self, cos self)` (radians) computed in this type's own precision:
    /// `f32` on 32-bit ARM through [`crate::trig::sin_cos_f32`] (within 2 ulp,
    /// single-precision arithmetic only, so a single-precision FPU does it in
    /// hardware; libm's `sinf` computes in `f64`, software there), `f64`
    /// through [`crate::sincos64::sin_cos_f64`] (inlined, within 2 ulp;
    /// about 10 ns faster per crank than glibc's `sincos` call in the
    /// four-bar's solve) except on 32-bit ARM (libm: software doubles there
    /// anyway), and `f32` elsewhere through nalgebra's `sin_cos` (libm, or
    /// `std` when enabled).
    fn sin_cos_kernel(self) -> (Self, Self);
    /// Square root in this type's own precision: `f32` on 32-bit ARM through
    /// [`crate::trig::sqrt_f32`] (FPU divide and Newton steps, where libm's
    /// `sqrtf` is a slow integer routine), elsewhere and for `f64` through
    /// nalgebra's `sqrt` (the hardware instruction).
    fn sqrt_kernel(self) -> Self;
    /// `atan2(self, x)`: the angle (rad, in `[-pi, pi]`) of the vector
    /// `(x, self)` from +x, counter-clockwise, with libm's conventions for
    /// signed zeros, infinities and NaN. `f32` through
    /// [`crate::trig::atan2_f32`] (within 2 ulp; cheaper than libm's on a
    /// Cortex-M4F and on x86-64), `f64` through [`crate::trig64::atan2_f64`]
    /// (within 1.9 ulp; 1.5 to 2 times glibc's speed on x86-64) except on
    /// 32-bit ARM (libm there: the kernel's tables are 8.8 kB).
    fn atan2_kernel(self, x: Self) -> Self;
    /// The angle (rad, in `(-pi, pi]`) of the vector `(x, self)` from +x,
    /// counter-clockwise: [`Real::atan2_kernel`] with a negative zero `self`
    /// made `+0` (a vector along -x gives `pi`, not `-pi`) and a result that
    /// rounded to `-pi` (`self` a tiny negative number, `x < 0`: the exact
    /// angle is above `-pi` by less than half an ulp) returned as `pi`, the
    /// same direction. `f32` through [`crate::trig::angle_f32`] (out of line:
    /// one copy of the fold on a Cortex-M).
    fn angle_kernel(self, x: Self) -> Self;
}

/// Absolute value.
#[inline(always)]
pub fn abs<T: Real>(x: T) -> T {
    if x < T::zero() {
        -x
    } else {
        x
    }
}
