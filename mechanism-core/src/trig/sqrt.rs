//! Square root of `f32`: [`sqrt_f32`] (the FPU's where there is one),
//! [`sqrt_f32_soft`].
//!
//! libm's `sqrtf` is an integer routine (about 60 instructions on a
//! Cortex-M4F), and the FPU's `vsqrt.f32` is out of reach of safe stable Rust
//! without `std` (`core::f32::math::sqrt` is unstable in Rust 1.95, and libm
//! has no ARM path). [`sqrt_f32`] therefore reaches it with three lines of
//! inline assembly on ARM targets with a hardware floating-point ABI (the
//! IEEE square root: correctly rounded; one instruction plus the moves in
//! and out of a core register), and elsewhere runs [`sqrt_f32_soft`]: a
//! bit-level first guess and three Newton steps with the divide, at most one
//! step from the correctly rounded square root (checked against `f64` for
//! every `f32` by an `#[ignore]`d test). An exact integer test of the
//! neighbours would make the software kernel correctly rounded but costs
//! more than libm's `sqrtf` on the Cortex-M3.
//!

use super::pow2;

/// Square root of `x`: `NaN` for `x < 0` or NaN, `x` itself for `+-0` and
/// `+inf`.
///
/// On 32-bit ARM with a hardware floating-point ABI (`eabihf`: Cortex-M4F,
/// M7, M33, ...; every such FPU has `vsqrt.f32`) the FPU's square root,
/// which is IEEE 754's, correctly rounded. Elsewhere the software kernel
/// [`sqrt_f32_soft`], at most one representable step from the correctly
/// rounded result (the Cortex-M3, `thumbv7m-none-eabi`, has no FPU).
/// (Not inlined: a handful of call sites per mechanism.)
#[inline(never)]
pub fn sqrt_f32(x: f32) -> f32 {
    #[cfg(all(target_arch = "arm", target_abi = "eabihf"))]
    {
        hw::vsqrt(x)
    }
    #[cfg(not(all(target_arch = "arm", target_abi = "eabihf")))]
    {
        sqrt_f32_soft(x)
    }
}

/// The FPU's square root, `vsqrt.f32`: the one `unsafe` of the crate.
///
/// Stable Rust offers no safe way to it without `std` (`core::f32::math::sqrt`
/// is unstable in Rust 1.95), and inline assembly cannot name a
/// single-precision register on these targets (the `sreg` class requires the
/// `vfp2` target feature, which the single-precision-only FPU targets such as
/// `thumbv7em-none-eabihf` do not enable; module-level assembly is assembled
/// without the FPU features). So the value passes through a core register,
/// and `s0` is saved and restored around the instruction in another one.
#[cfg(all(target_arch = "arm", target_abi = "eabihf"))]
#[allow(unsafe_code)]
mod hw {
    /// `vsqrt.f32` of `x` (IEEE 754 square root, round to nearest).
    #[inline(always)]
    pub(super) fn vsqrt(x: f32) -> f32 {
        let mut bits = x.to_bits();
        // SAFETY: only registers are touched: `s0` is read into `save`
        // (an output that does not share a register with the input) and
        // written back before the end, so the compiler's view of every
        // register it knows is intact; no memory, stack or flags (`vsqrt`
        // sets the FPU's cumulative exception bits only, which Rust does not
        // model). The FPU is on: the target's ABI passes floats in it.
        unsafe {
            core::arch::asm!(
                "vmov {save}, s0",
                "vmov s0, {v}",
                "vsqrt.f32 s0, s0",
                "vmov {v}, s0",
                "vmov s0, {save}",
                v = inout(reg) bits,
                save = out(reg) _,
                options(pure, nomem, nostack, preserves_flags),
            );
        }
        f32::from_bits(bits)
    }
}

/// Square root of `x` in software (single-precision divides and adds, the
/// FPU's on a Cortex-M4F, an integer routine's on a Cortex-M3), at most one
/// representable step from the correctly rounded result (so within 1.5 ulp;
/// about 3 in 4 results are the correctly rounded one): `NaN` for `x < 0` or
/// NaN, `x` itself for `+-0` and `+inf`. [`sqrt_f32`] on targets without an
/// FPU square root.
#[inline(never)]
pub fn sqrt_f32_soft(x: f32) -> f32 {
    if x.is_nan() || x < 0.0 {
        return f32::NAN;
    }
    if x == 0.0 || x == f32::INFINITY {
        return x;
    }
    if x < f32::MIN_POSITIVE {
        // Subnormal: sqrt(x 2^24) 2^-12, both scalings exact; x 2^24 is
        // normal, so this recursion is one level deep (and keeps a single
        // copy of the Newton steps in the code).
        return sqrt_f32_soft(x * pow2(24)) * pow2(-12);
    }
    sqrt_normal(x)
}

/// Square root of a positive normal `x`.
#[inline(always)]
fn sqrt_normal(x: f32) -> f32 {
    // First guess: halve the biased exponent (and, roughly, the logarithm of
    // the significand); within about 3.5 %.
    let mut y = f32::from_bits((x.to_bits() >> 1) + 0x1FBD_1DF5);
    // Newton: the relative error e goes to about e^2 / 2 per step (3.5 % ->
    // 6e-4 -> 2e-7 -> rounding level).
    for _ in 0..3 {
        y = 0.5 * (y + x / y);
    }
    y
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;

    /// f64's square root of an f32, rounded to f32, is the correctly rounded
    /// f32 square root (53 >= 2 * 24 + 2 bits: the double rounding is harmless).
    fn sqrt_reference(x: f32) -> f32 {
        (x as f64).sqrt() as f32
    }

    /// Representable steps between the kernel's square root and the correctly
    /// rounded one (both positive: bit patterns are ordered like values).
    fn sqrt_steps(x: f32) -> u32 {
        sqrt_f32_soft(x)
            .to_bits()
            .abs_diff(sqrt_reference(x).to_bits())
    }

    #[test]
    fn sqrt_within_one_step_on_a_dense_sample() {
        for b in (0..0x7F80_0000u32).step_by(251) {
            let x = f32::from_bits(b);
            assert!(sqrt_steps(x) <= 1, "{x:e}");
        }
        // Perfect squares and their neighbours (exact results, ties avoided).
        for k in 1..5000u32 {
            let x = (k * k) as f32;
            assert_eq!(sqrt_f32_soft(x), k as f32);
            for n in [
                f32::from_bits(x.to_bits() - 1),
                f32::from_bits(x.to_bits() + 1),
            ] {
                assert!(sqrt_steps(n) <= 1, "{n:e}");
            }
        }
    }

    #[test]
    fn sqrt_special_values() {
        assert_eq!(sqrt_f32_soft(0.0).to_bits(), 0.0f32.to_bits());
        assert_eq!(sqrt_f32_soft(-0.0).to_bits(), (-0.0f32).to_bits());
        assert_eq!(sqrt_f32_soft(f32::INFINITY), f32::INFINITY);
        assert!(sqrt_f32_soft(-1.0).is_nan() && sqrt_f32_soft(f32::NAN).is_nan());
        assert!(sqrt_f32_soft(f32::NEG_INFINITY).is_nan());
        assert!(sqrt_steps(f32::MAX) <= 1 && sqrt_steps(f32::from_bits(1)) <= 1);
    }

    #[test]
    #[ignore = "exhaustive over all 2^31 non-negative bit patterns"]
    fn exhaustive_sqrt_within_one_step() {
        let worst = (0..0x7F80_0000u32)
            .map(|b| sqrt_steps(f32::from_bits(b)))
            .max();
        assert_eq!(worst, Some(1));
    }
}
