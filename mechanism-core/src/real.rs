//! The two implementations of [`Real`]: `f64` (its sine and cosine from
//! [`crate::sincos64`]) and `f32` (from [`crate::trig`]). Apart from the trait
//! in [`crate::scalar`], so that the kernels they call may use the trait
//! without an import circle.

use crate::scalar::Real;

impl Real for f64 {
    #[inline(always)]
    fn lit(x: f64) -> Self {
        x
    }
    #[inline(always)]
    fn as_f64(self) -> f64 {
        self
    }
    #[inline(always)]
    fn eps() -> Self {
        f64::EPSILON
    }
    #[inline(always)]
    fn finite(self) -> bool {
        self.is_finite()
    }
    #[inline(always)]
    fn sin_cos_kernel(self) -> (Self, Self) {
        #[cfg(not(target_arch = "arm"))]
        {
            crate::sincos64::sin_cos_f64(self)
        }
        #[cfg(target_arch = "arm")]
        {
            <f64 as nalgebra::ComplexField>::sin_cos(self)
        }
    }
    #[inline(always)]
    fn sqrt_kernel(self) -> Self {
        <f64 as nalgebra::ComplexField>::sqrt(self)
    }
    #[inline(always)]
    fn atan2_kernel(self, x: Self) -> Self {
        // The kernel's tables are 8.8 kB of read-only data: not on 32-bit
        // ARM, where f64 is software arithmetic anyway and flash is small.
        #[cfg(not(target_arch = "arm"))]
        {
            crate::trig64::atan2_f64(self, x)
        }
        #[cfg(target_arch = "arm")]
        {
            <f64 as nalgebra::RealField>::atan2(self, x)
        }
    }
    #[inline(always)]
    fn angle_kernel(self, x: Self) -> Self {
        let a = (self + 0.0).atan2_kernel(x);
        if a <= -core::f64::consts::PI {
            core::f64::consts::PI
        } else {
            a
        }
    }
}

impl Real for f32 {
    #[inline(always)]
    fn lit(x: f64) -> Self {
        x as f32
    }
    #[inline(always)]
    fn as_f64(self) -> f64 {
        self as f64
    }
    #[inline(always)]
    fn eps() -> Self {
        f32::EPSILON
    }
    #[inline(always)]
    fn finite(self) -> bool {
        self.is_finite()
    }
    #[inline(always)]
    fn sin_cos_kernel(self) -> (Self, Self) {
        // On 32-bit ARM (Cortex-M: single-precision FPU or none) libm's
        // `sinf`/`cosf` compute in software doubles: use the f32 kernel. Where
        // doubles are hardware (x86-64, AArch64), libm's is faster.
        #[cfg(target_arch = "arm")]
        {
            crate::trig::sin_cos_f32(self)
        }
        #[cfg(not(target_arch = "arm"))]
        {
            <f32 as nalgebra::ComplexField>::sin_cos(self)
        }
    }
    #[inline(always)]
    fn sqrt_kernel(self) -> Self {
        // libm's `sqrtf` is an integer routine on 32-bit ARM; elsewhere it is
        // the hardware instruction, faster than the kernel's Newton steps.
        #[cfg(target_arch = "arm")]
        {
            crate::trig::sqrt_f32(self)
        }
        #[cfg(not(target_arch = "arm"))]
        {
            <f32 as nalgebra::ComplexField>::sqrt(self)
        }
    }
    #[inline(always)]
    fn atan2_kernel(self, x: Self) -> Self {
        // libm's `atan2f` is single precision too, but a general routine
        // (an `atanf` call, four reduction intervals, more special-case
        // tests); the kernel is cheaper everywhere measured: about 52
        // instructions against 81 on a Cortex-M4F, 6.5 ns against 10 ns
        // (glibc) on the x86-64 development machine.
        crate::trig::atan2_f32(self, x)
    }
    #[inline(always)]
    fn angle_kernel(self, x: Self) -> Self {
        crate::trig::angle_f32(self, x)
    }
}
