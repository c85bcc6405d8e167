//! Sine, cosine, square root and `atan2` of `f32` computed in `f32` (and
//! integer) arithmetic only: [`sin_cos_f32`], [`sqrt_f32`], [`atan2_f32`].
//!
//! Why: libm's `sinf`/`cosf` evaluate in `f64`. On a core with a
//! single-precision FPU (Cortex-M4F, thumbv7em-none-eabihf) every `f64`
//! operation is a software routine (`__aeabi_dmul`, `__aeabi_dadd`, ...), so
//! one `sinf` costs hundreds of instructions and pulls in kilobytes of code.
//! [`sin_cos_f32`] uses only single-precision multiplies and adds, which the
//! FPU does in hardware, and 32-bit integer multiplies for range reduction.
//!
//! # Domain and accuracy
//!
//! Every finite `f32`. The result is within **2 ulp** of the exact sine and
//! cosine (ulp of `f32` at the exact value's magnitude, with the subnormal
//! spacing `2^-149` as the floor); non-finite inputs give `(NaN, NaN)`. The
//! bound is checked against `f64` (`std`'s `sin`/`cos` of the widened input,
//! which are far more accurate than the bound) by the tests below: exhaustively
//! over every `f32` in an `#[ignore]`d test (`cargo test --release -p
//! mechanism-core --lib trig -- --ignored`), and on a dense sample of the
//! whole range in the ordinary run. The worst error found exhaustively is
//! stated in `docs/embedded.md`.
//!
//! # Method
//!
//! 1. (Once a separate case, now part of 2.) `|x| < pi/4` (and a hair) needs
//!    no reduction: the reduction of 2 gives `q = 0`, `hi = |x|`, `lo = 0`
//!    there, exactly, so no branch of its own (fewer instructions on the
//!    whole, and smaller).
//! 2. `|x| < 24` (within 15 quadrants, the usual crank angles): Cody-Waite in
//!    f32 with `pi/2` in three parts and the rounding error carried, so that
//!    `r` is known as `hi + lo` (see `reduce_small`); about 20 instructions.
//! 3. Otherwise `|x| = (4n + q) pi/2 + r` with `|r| <= pi/4`, computed
//!    exactly enough for every `f32` by the Payne-Hanek scheme in integer
//!    arithmetic: the 24-bit significand times a 96-bit window of the binary
//!    expansion of `2/pi` (the window starts where the bits stop contributing
//!    whole turns, with zeros in front for small arguments, so that the
//!    binary point of the product is always at bit 94), giving `|x| 2/pi mod
//!    4` to within `2^-70`; the 64-bit fraction is rounded to the nearest
//!    quadrant, normalized, its top 32 bits multiplied by `pi/2` (31 bits)
//!    into a 64-bit product whose top 32 bits (from bit 31) are converted to
//!    `f32` once. The error of `r` is 0.5 ulp from that conversion plus below
//!    `2^-29 |r|` from the truncations (the fraction's and the product's,
//!    `2^-31` and `2^-30`, and `pi/2`'s rounding, `2^-31.6`), as long as the
//!    fraction keeps 32 significant bits of its 64 (its top word is not
//!    zero). A scan of every `f32` above `pi/4` found at most 29 (the
//!    closest approach to a multiple of `pi/2`, relative to `pi/2`, is above
//!    2^-30, at 2.2e10), and the exhaustive test finds the bound met.
//! 4. `sin r` and `cos r` by their Taylor series through `r^9` and `r^10`
//!    (Horner form): the truncation error at `|r| = pi/4` is below
//!    `(pi/4)^11 / 11! < 1.8e-9` and `(pi/4)^12 / 12! < 1.2e-10`, under 0.05
//!    ulp of the results there; Taylor rather than minimax coefficients so
//!    that every coefficient is an exact, checkable `1/n!`.
//!    One evaluation serves all three cases (the inline code is not
//!    duplicated per path): no reduction is `q = 0` with the correction `lo`
//!    of the reduced argument zero. For `|x| < 2^-12` the series round to
//!    `x` and 1 (the second terms are below `2^-25` relative).
//! 5. The quadrant picks `(+-sin r, +-cos r)` and the sign of `x` the sign of
//!    the sine (swaps and sign-bit flips, no branches).
//!
//! # Square root
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
//! # Arctangent
//!
//! libm's `atan2f` is single precision already, but general: a call to
//! `atanf`, which reduces its argument to one of four intervals (a division
//! and a table), special-case tests on the bit patterns of both arguments,
//! about 80 instructions per call on a Cortex-M4F. [`atan2_f32`] takes one
//! division to `[0, 1]` and one polynomial there, about 52 (see its
//! documentation for the method and the error).
//!
//! The digits of `2/pi` and `pi/2` below are the standard binary expansions
//! (hexadecimal, most significant first); the tests check them indirectly:
//! a wrong word would put large arguments' results far from `f64`'s, whose
//! reduction uses its own table.

/// The binary expansion of `2/pi` after the point, 32 bits per word, behind
/// one word of zeros (`TWO_OVER_PI[i]` holds bits `32 i - 31 ..= 32 i` after
/// the point; the zeros are "bits" `-31 ..= 0`): the windows of [`reduce`]
/// start between bit -20 and bit 103 and are 96 bits long, so the last word
/// used holds bits 193..=224.
const TWO_OVER_PI: [u32; 8] = [
    0,
    0xA2F9_836E,
    0x4E44_1529,
    0xFC27_57D1,
    0xF534_DDC0,
    0xDB62_9599,
    0x3C43_9041,
    0xFE51_63AB,
];

/// `pi/2 * 2^30`, rounded to nearest (31 bits).
const PIO2_Q30: u32 = 0x6487_ED51;

/// Taylor coefficients of `sin`: `-1/3!`, `1/5!`, `-1/7!`, `1/9!`.
const S3: f32 = -1.0 / 6.0;
const S5: f32 = 1.0 / 120.0;
const S7: f32 = -1.0 / 5040.0;
const S9: f32 = 1.0 / 362_880.0;
/// Taylor coefficients of `cos`: `1/4!`, `-1/6!`, `1/8!`, `-1/10!`.
const C4: f32 = 1.0 / 24.0;
const C6: f32 = -1.0 / 720.0;
const C8: f32 = 1.0 / 40_320.0;
const C10: f32 = -1.0 / 3_628_800.0;

/// `(sin x, cos x)` for `x` in radians, within 2 ulp for every finite `f32`
/// (see the module documentation); `(NaN, NaN)` for a non-finite `x`.
///
/// One evaluation of the two polynomials serves every path: an argument that
/// needs no reduction is the reduced one with `q = 0`, `lo = 0` (the terms in
/// `lo` then add exact zeros), and the quadrant and the sign of `x` are
/// applied by swapping and flipping sign bits.
#[inline]
pub fn sin_cos_f32(x: f32) -> (f32, f32) {
    if !x.is_finite() {
        return (f32::NAN, f32::NAN);
    }
    let ax = x.abs();
    let (q, hi, lo) = if ax < FAST_LIMIT {
        reduce_small(ax)
    } else {
        let (q, r) = reduce(ax);
        (q, r, 0.0)
    };
    // sin(hi + lo) = sin hi + lo cos hi and cos(hi + lo) = cos hi - lo sin hi
    // to far below f32 resolution (|lo| is below 2^-20 |hi| + 2^-36), with
    // cos hi ~ 1 - hi^2/2 and sin hi ~ hi in the correction terms. For
    // |x| < 2^-12 the series give x and 1 correctly rounded (the terms past
    // the first are below 2^-25 relative; x^2 may underflow to 0, exactly).
    let s = sin_poly(hi) + lo * (1.0 - 0.5 * hi * hi);
    let c = cos_poly(hi) - lo * hi;
    // Quadrant q: (s, c), (c, -s), (-s, -c), (-c, s); then sin(-x) = -sin x
    // (by the sign bit, so -0.0 keeps its sign).
    let (s, c) = if q & 1 == 0 { (s, c) } else { (c, s) };
    let s_flip = ((q & 2) << 30) ^ (x.to_bits() & 0x8000_0000);
    let c_flip = (q.wrapping_add(1) & 2) << 30;
    (
        f32::from_bits(s.to_bits() ^ s_flip),
        f32::from_bits(c.to_bits() ^ c_flip),
    )
}

/// `sin r` for `|r| <= pi/4`.
#[inline(always)]
fn sin_poly(r: f32) -> f32 {
    let r2 = r * r;
    r + r * r2 * (S3 + r2 * (S5 + r2 * (S7 + r2 * S9)))
}

/// `cos r` for `|r| <= pi/4`.
#[inline(always)]
fn cos_poly(r: f32) -> f32 {
    let r2 = r * r;
    1.0 - 0.5 * r2 + r2 * r2 * (C4 + r2 * (C6 + r2 * (C8 + r2 * C10)))
}

/// Above this, [`reduce`]; below, [`reduce_small`] (at most 15 quadrants).
const FAST_LIMIT: f32 = 24.0;
/// `2/pi` rounded to f32: only picks the quadrant (an off-by-one near a
/// half-quadrant leaves `|r|` a hair above `pi/4`, where the series still hold).
const FRAC_2_PI: f32 = 0.636_619_75;
/// `pi/2 = P1 + P2 + P3 + 2.5e-20`: `P1 = 823549 / 2^19` and
/// `P2 = 696865 / 2^39` have 20 significant bits, so `k P1` and `k P2` are
/// exact for `k < 16`; `P3` is the rest rounded to f32.
const P1: f32 = f32::from_bits(0x3FC9_0FD0);
const P2: f32 = f32::from_bits(0x35AA_2210);
const P3: f32 = f32::from_bits(0x2B51_846A);

/// Cody-Waite reduction for `0 <= ax < 24` in f32 arithmetic:
/// `(q, hi, lo)` with `ax = (4n + q) pi/2 + hi + lo`, `|hi| <= pi/4` (and a
/// hair), `lo` the rounding error of `hi` (exact) minus `k P3`.
///
/// `ax - k P1` is exact (Sterbenz: `k P1` is within a factor 2 of `ax`), and so
/// is `k P2`; the difference of the two is split exactly into `hi + err`
/// (Knuth's two-sum). What remains is the rounding of `k P3` and of
/// `err - k P3` (below 2^-60 here) and the `2.5e-20 k` left out of `pi/2`:
/// far below 2^-24 of the smallest `|r|` of any f32 in this range (about
/// 1.2e-8, at 3 pi/2), so `hi + lo` is `r` to about 2^-40 relative. For
/// `k = 0` (`ax` below about `pi/4`) every step is exact: `hi = ax`, `lo = 0`.
#[inline(always)]
fn reduce_small(ax: f32) -> (u32, f32, f32) {
    let k = (ax * FRAC_2_PI + 0.5) as u32;
    let kf = k as f32;
    let t1 = ax - kf * P1;
    let w = kf * P2;
    let hi = t1 - w;
    let v = hi - t1;
    let err = (t1 - (hi - v)) + (-w - v);
    (k, hi, err - kf * P3)
}

/// `2^k` for `-126 <= k <= 127`, exactly.
#[inline(always)]
fn pow2(k: i32) -> f32 {
    f32::from_bits(((127 + k) as u32) << 23)
}

/// Reduces a finite `ax >= 24` (any finite `ax > pi/4` works) to `(q, r)`
/// with `ax = (4n + q) pi/2 + r`, `|r| <= pi/4` (see the module
/// documentation for the error). 32-bit integer arithmetic and three
/// 32 x 32 multiplies (a Cortex-M4 multiplies 32 x 32 -> 64 bits in one
/// instruction).
#[inline(never)]
fn reduce(ax: f32) -> (u32, f32) {
    let bits = ax.to_bits();
    // ax = m * 2^e, m a 24-bit integer; ax > pi/4 is normal: the biased
    // exponent is 126..=254 and e = biased - 150 in -24..=104.
    let m = (bits & 0x007F_FFFF) | 0x0080_0000;
    // The 96-bit window W of 2/pi from bit e - 1 to bit e + 94 after the
    // point (bits before the point are zeros): the bits before it contribute
    // multiples of 4 (whole turns) to ax * 2/pi, and with it
    // ax * 2/pi = m W 2^-94 (mod 4), truncated by less than m 2^-94 < 2^-70.
    // In the table the window starts `pos = e + 30` bits in (11..=134).
    let pos = ((bits >> 23) & 0xFF).wrapping_sub(120);
    // `min` only tells the compiler that the words are in range (pos / 32
    // <= 4 already).
    let (idx, sh) = (((pos / 32) as usize).min(4), pos % 32);
    let t = &TWO_OVER_PI[idx..idx + 4];
    let word = |j: usize| (t[j] << sh) | ((t[j + 1] >> 1) >> (31 - sh));
    let (w0, w1, w2) = (word(0), word(1), word(2));
    // The low 96 bits p2:p1:p0 of m W (the higher ones are whole turns).
    let a = u64::from(m) * u64::from(w2);
    let b = u64::from(m) * u64::from(w1) + (a >> 32);
    let p2 = m.wrapping_mul(w0).wrapping_add((b >> 32) as u32);
    let (p1, p0) = (b as u32, a as u32);
    // Quadrant: bits 94 and 95 (the top two of p2); fraction: the 64 bits
    // below them.
    let mut q = p2 >> 30;
    let mut frac = (u64::from((p2 << 2) | (p1 >> 30)) << 32) | u64::from((p1 << 2) | (p0 >> 30));
    let negative = frac >> 63 != 0;
    if negative {
        // Round to the nearest quadrant: r is negative.
        q = q.wrapping_add(1);
        frac = frac.wrapping_neg();
    }
    // Normalize the fraction (value frac * 2^-64), keep 32 bits, times pi/2
    // in fixed point (2^30 pi/2, 31 bits). Its top word is never zero: it
    // has at most 29 leading zeros for every finite f32 (module
    // documentation); `& 31` only keeps the shifts in range.
    let (fh, fl) = ((frac >> 32) as u32, frac as u32);
    let lz = fh.leading_zeros() & 31;
    let top = (fh << lz) | ((fl >> 1) >> (31 - lz));
    let prod = u64::from(top) * u64::from(PIO2_Q30);
    // top >= 2^31 and PIO2_Q30 >= 2^30: 2^61 <= prod < 2^63, so its top 32
    // bits from bit 31 have 31 or 32 significant ones (truncated by less
    // than 2^-30 relative), rounded once to f32 by the conversion.
    let hi32 = (prod >> 31) as u32;
    // frac * 2^-64 = top * 2^(-32 - lz), so r = prod * 2^(-62 - lz) = hi32 * 2^k,
    // k = -31 - lz, between -62 and -31: 2^k is normal.
    let k = -31 - lz as i32;
    let r = (hi32 as f32) * pow2(k);
    (q, if negative { -r } else { r })
}

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

/// `pi/2 = PIO2_HI + PIO2_LO` to about 6e-17: `PIO2_HI` is `pi/2` rounded to
/// f32 (1.57079637), `PIO2_LO` the rest (-4.37e-8) rounded to f32.
const PIO2_HI: f32 = f32::from_bits(0x3FC9_0FDB);
const PIO2_LO: f32 = f32::from_bits(0xB33B_BD2E);
/// `pi = PI_HI + PI_LO` likewise (3.14159274 and -8.74e-8).
const PI_HI: f32 = f32::from_bits(0x4049_0FDB);
const PI_LO: f32 = f32::from_bits(0xB3BB_BD2E);

/// `pi/4` and `3 pi/4` rounded to f32 (0.785398185 and 2.35619450).
const PIO4: f32 = f32::from_bits(0x3F49_0FDB);
const PI3O4: f32 = f32::from_bits(0x4016_CBE4);

/// `atan t = t + t^3 (A3 + A5 s + A7 s^2 + ... + A19 s^8)`, `s = t^2`, for
/// `t` in `[0, 1]`, within a relative `3.2e-9` (`0.053 * 2^-24`): the minimax
/// polynomial for the relative error of `atan` on `[0, 1]` (Remez exchange
/// in 40-digit arithmetic; the equioscillating error of the exact minimax
/// coefficients is `2.57e-9`), its coefficients rounded to f32 one at a time,
/// lowest first, the higher ones fitted again to what the rounded lower ones
/// leave (rounding all at once would give `1.2e-8`). The bound of the f32
/// coefficients as written here is checked against `f64` by a test. The
/// exact minimax coefficients for comparison: `-0.333332991`, `0.199985483`,
/// `-0.142642417`, `0.109521861`, `-0.0840345134`, `0.0579576115`,
/// `-0.0311778642`, `0.0109146158`, `-0.00179362402` (Taylor's `-1/3`, `1/5`,
/// `-1/7`, ... would need thousands of terms at `t = 1`).
const A3: f32 = f32::from_bits(0xBEAA_AA9F); // -0.333332986
const A5: f32 = f32::from_bits(0x3E4C_C8F2); // 0.199985296
const A7: f32 = f32::from_bits(0xBE12_1056); // -0.142640442
const A9: f32 = f32::from_bits(0x3DE0_4894); // 0.109513432
const A11: f32 = f32::from_bits(0xBDAC_1216); // -0.0840188712
const A13: f32 = f32::from_bits(0x3D6D_5C91); // 0.0579496063
const A15: f32 = f32::from_bits(0xBCFF_827C); // -0.0311901495
const A17: f32 = f32::from_bits(0x3C33_1D2D); // 0.0109322490
const A19: f32 = f32::from_bits(0xBAEB_ED18); // -0.00179997366

/// `atan2(y, x)`: the angle of the vector `(x, y)` from +x, counter-clockwise,
/// in radians in `[-pi, pi]` (`pi` rounded up to f32, as libm), within **2
/// ulp** of the exact value for every pair of `f32` (ulp of `f32` at the
/// exact value, the subnormal spacing `2^-149` the floor), in
/// single-precision arithmetic only. libm's conventions (C99 Annex F) for the
/// rest: NaN if either argument is NaN; `y = +-0` gives `+-0` for `x > 0` or
/// `x = +0` and `+-pi` for `x < 0` or `x = -0`; `x = +-0` with `y != 0`,
/// `+-pi/2`; both infinite, `+-pi/4` or `+-3 pi/4`; one infinite, the limit.
///
/// # Method
///
/// 1. `t = min(|x|, |y|) / max(|x|, |y|)` in `[0, 1]`: one division,
///    correctly rounded (subnormal quotients to the subnormal spacing). It is
///    NaN only for a NaN argument, `0/0` or `inf/inf`: those are handled
///    apart (`x + y`; `t = 0`; the rounded `pi/4` or `3 pi/4`).
/// 2. `a = atan t = t + c`, `c = t s P(s)` with `s = t^2` and `P` the
///    degree-8 polynomial above (Horner form; each step one load and one
///    multiply-accumulate on the M4F), truncation below `0.053 * 2^-24`
///    relative. No second reduction (about `tan(pi/8)`, as libm's `atanf`):
///    it would cost a comparison, a branch, a second division and a sum of
///    two parts, more than the four terms it saves.
/// 3. The octant: `a` (`x >= 0`, `|y| <= |x|`); `pi - a` (`x < 0`);
///    `pi/2 - a` (`|y| > |x|`, `x >= 0`), as `(PIO2_HI - t) + (PIO2_LO -
///    c)`, whose first difference is exact for `t >= pi/4` (Sterbenz), where
///    the result is near `pi/4` and finest; `pi/2 + a` (`|y| > |x|`,
///    `x < 0`); `pi` and `pi/2` in two parts so that only the last sum
///    rounds at the result's scale. Then the sign of `y` (`copysign`, so
///    `-0` counts as negative).
///
/// Error: the quotient's rounding (half an ulp of `t`, which is a whole ulp
/// of `a` where `t` is just above a power of two and `atan t` just below
/// it), the last sum's rounding (half an ulp), the polynomial's rounding and
/// truncation (a few hundredths): about 1.6 ulp at worst, the measured worst
/// is in `docs/embedded.md` (section 3) and the tests check 2 ulp.
#[inline(never)]
pub fn atan2_f32(y: f32, x: f32) -> f32 {
    atan2_or_angle(y, x, false)
}

/// The angle (rad, in `(-pi, pi]`) of `(x, y)` from +x: [`atan2_f32`] of
/// `y + 0` (a negative zero made `+0`), with a result of magnitude `pi`
/// returned as `+pi` (a tiny negative `y` and `x < 0`, whose exact angle
/// is above `-pi` by less than half an ulp, rounds to `-pi`: the same
/// direction). [`crate::Real::angle_kernel`] for `f32`; one body with
/// [`atan2_f32`], of which an image holds the one it calls.
#[inline(never)]
pub fn angle_f32(y: f32, x: f32) -> f32 {
    atan2_or_angle(y + 0.0, x, true)
}

/// [`atan2_f32`] (`angle == false`) or [`angle_f32`]'s fold of `-pi`.
#[inline(always)]
fn atan2_or_angle(y: f32, x: f32, angle: bool) -> f32 {
    let (ax, ay) = (x.abs(), y.abs());
    let swap = ay > ax;
    let (mn, mx) = if swap { (ax, ay) } else { (ay, ax) };
    let mut t = mn / mx;
    if t.is_nan() {
        // A NaN argument, both zero (0/0) or both infinite (inf/inf).
        if x.is_nan() || y.is_nan() {
            return x + y;
        }
        if mx != 0.0 {
            // Both infinite: pi/4 or 3 pi/4, rounded (libm's values).
            let r = if x.is_sign_negative() { PI3O4 } else { PIO4 };
            return r.copysign(y);
        }
        // Both zero: t = 0 gives 0 or pi by the sign of x (libm's values).
        t = 0.0;
    }
    let s = t * t;
    let p = A3
        + s * (A5 + s * (A7 + s * (A9 + s * (A11 + s * (A13 + s * (A15 + s * (A17 + s * A19)))))));
    let c = t * s * p;
    let r = match (swap, x.is_sign_negative()) {
        (false, false) => t + c,
        (false, true) => (PI_LO - (t + c)) + PI_HI,
        (true, false) => (PIO2_HI - t) + (PIO2_LO - c),
        (true, true) => (PIO2_LO + (t + c)) + PIO2_HI,
    };
    if angle && r >= core::f32::consts::PI {
        r
    } else {
        r.copysign(y)
    }
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;

    /// Error of `got` against the exact value `want` (f64), in units of the
    /// f32 spacing at `|want|` (floored at the smallest subnormal spacing).
    fn ulps(got: f32, want: f64) -> f64 {
        let w32 = (want as f32).abs();
        let spacing = if w32 == 0.0 || w32 < f32::MIN_POSITIVE {
            2f64.powi(-149)
        } else {
            // Spacing of f32 at |want|: 2^(exponent - 23); when |want| rounds
            // up to a power of two, use the smaller spacing below it.
            let e = ((w32.to_bits() >> 23) & 0xFF) as i32 - 127;
            let s = 2f64.powi(e - 23);
            if (w32 as f64) > want.abs() && w32.to_bits() & 0x007F_FFFF == 0 {
                s / 2.0
            } else {
                s
            }
        };
        ((got as f64) - want).abs() / spacing
    }

    /// The worst errors (sin, cos) over the given inputs, with the arguments.
    fn worst(xs: impl Iterator<Item = f32>) -> ((f64, f32), (f64, f32)) {
        let mut ws = (0.0, 0.0f32);
        let mut wc = (0.0, 0.0f32);
        for x in xs {
            let (s, c) = sin_cos_f32(x);
            let es = ulps(s, (x as f64).sin());
            let ec = ulps(c, (x as f64).cos());
            if es > ws.0 {
                ws = (es, x);
            }
            if ec > wc.0 {
                wc = (ec, x);
            }
        }
        (ws, wc)
    }

    /// The stated bound.
    const BOUND_ULP: f64 = 2.0;

    #[test]
    fn dense_sample_of_every_finite_f32_within_2_ulp() {
        // Every 997th bit pattern of the positive finite f32 (about 2.1
        // million arguments spread evenly over all exponents), and their
        // negatives; 997 is prime so the low significand bits vary.
        let xs = (0..0x7F80_0000u32)
            .step_by(997)
            .map(f32::from_bits)
            .flat_map(|x| [x, -x]);
        let ((es, xs_), (ec, xc)) = worst(xs);
        assert!(es <= BOUND_ULP, "sin: {es} ulp at {xs_:e}");
        assert!(ec <= BOUND_ULP, "cos: {ec} ulp at {xc:e}");
    }

    #[test]
    fn every_f32_in_one_turn_either_way_within_2_ulp() {
        // The range of crank angles: every third f32 in [2^-3, 32] (no
        // reduction, the small-argument path, the switch to the general one).
        let lo = 0.125f32.to_bits();
        let hi = 32.0f32.to_bits();
        let ((es, xs_), (ec, xc)) = worst((lo..=hi).step_by(3).map(f32::from_bits));
        assert!(es <= BOUND_ULP, "sin: {es} ulp at {xs_:e}");
        assert!(ec <= BOUND_ULP, "cos: {ec} ulp at {xc:e}");
    }

    #[test]
    fn hard_cases_near_multiples_of_pi_over_2() {
        // Arguments nearest to k pi/2 (the cancellation cases of the reduction)
        // for k up to 2^20, and the f32 neighbours on both sides: the small
        // result must still be accurate relative to itself.
        let mut xs = std::vec::Vec::new();
        for k in 1..(1u32 << 20) {
            let x = (k as f64 * core::f64::consts::FRAC_PI_2) as f32;
            let b = x.to_bits();
            xs.extend([b - 1, b, b + 1].map(f32::from_bits));
        }
        let ((es, xs_), (ec, xc)) = worst(xs.into_iter());
        assert!(es <= BOUND_ULP, "sin: {es} ulp at {xs_:e}");
        assert!(ec <= BOUND_ULP, "cos: {ec} ulp at {xc:e}");
    }

    #[test]
    fn the_three_parts_of_pi_over_2() {
        // The exact values the reduction relies on (20-bit P1 and P2) and the
        // sum against f64's pi/2 (whose own error is 6e-17).
        assert_eq!(P1 as f64, 823_549.0 / 2f64.powi(19));
        assert_eq!(P2 as f64, 696_865.0 / 2f64.powi(39));
        let sum = P1 as f64 + P2 as f64 + P3 as f64;
        assert!((sum - core::f64::consts::FRAC_PI_2).abs() < 1e-16);
    }

    #[test]
    #[ignore = "exhaustive over the small-argument path [0, 24]: a minute in release"]
    fn exhaustive_small_path_within_2_ulp() {
        // From 0: the path also serves the arguments that need no reduction.
        let lo = 0;
        let hi = FAST_LIMIT.to_bits() + 16;
        let ((es, xs_), (ec, xc)) = worst((lo..=hi).map(f32::from_bits));
        std::println!("small path: worst sin {es:.4} ulp at {xs_:e}; cos {ec:.4} ulp at {xc:e}");
        assert!(es <= BOUND_ULP && ec <= BOUND_ULP);
    }

    #[test]
    fn special_values() {
        assert_eq!(sin_cos_f32(0.0), (0.0, 1.0));
        let (s, c) = sin_cos_f32(-0.0);
        assert!(s == 0.0 && s.is_sign_negative() && c == 1.0);
        // The smallest subnormal: sin x = x exactly, cos x = 1.
        let tiny = f32::from_bits(1);
        assert_eq!(sin_cos_f32(tiny), (tiny, 1.0));
        for x in [f32::NAN, f32::INFINITY, f32::NEG_INFINITY] {
            let (s, c) = sin_cos_f32(x);
            assert!(s.is_nan() && c.is_nan());
        }
        // Largest finite: against f64 (uses the last words of the table).
        for x in [f32::MAX, -f32::MAX] {
            let (s, c) = sin_cos_f32(x);
            assert!(ulps(s, (x as f64).sin()) <= BOUND_ULP);
            assert!(ulps(c, (x as f64).cos()) <= BOUND_ULP);
        }
    }

    #[test]
    fn sin_squared_plus_cos_squared_is_one() {
        // An identity independent of any reference implementation: with both
        // within 2 ulp (2 * 2^-24 relative at most), s^2 + c^2 is within about
        // 4 * 2 * 2^-24 of 1; 1e-6 leaves room for the f32 squaring.
        for k in 0..100_000 {
            let x = -1.0e4 + 0.2 * k as f32;
            let (s, c) = sin_cos_f32(x);
            let n = (s as f64).powi(2) + (c as f64).powi(2);
            assert!((n - 1.0).abs() < 1e-6, "{x}: {n}");
        }
    }

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

    #[test]
    #[ignore = "exhaustive over all 2^31 non-negative bit patterns: minutes in release"]
    fn exhaustive_every_f32_within_2_ulp() {
        // Non-negative arguments only: the kernel computes -x as x with the
        // sine's sign flipped, exactly. Four threads over interleaved chunks.
        let workers: std::vec::Vec<_> = (0..4u32)
            .map(|t| {
                std::thread::spawn(move || {
                    let lo = t * 0x1FE0_0000;
                    worst((lo..lo + 0x1FE0_0000).map(f32::from_bits))
                })
            })
            .collect();
        let mut all = ((0.0, 0.0f32), (0.0, 0.0f32));
        for w in workers {
            let (s, c) = w.join().expect("worker");
            if s.0 > all.0 .0 {
                all.0 = s;
            }
            if c.0 > all.1 .0 {
                all.1 = c;
            }
        }
        let ((es, xs_), (ec, xc)) = all;
        std::println!(
            "worst sin error {es:.4} ulp at {xs_:e}; worst cos error {ec:.4} ulp at {xc:e}"
        );
        assert!(es <= BOUND_ULP && ec <= BOUND_ULP);
    }

    /// Error of [`atan2_f32`] against `f64` (`std`'s `atan2` of the widened
    /// arguments, correct to about 1 ulp of f64: far below the f32 bound).
    fn atan2_err(y: f32, x: f32) -> f64 {
        ulps(atan2_f32(y, x), (y as f64).atan2(x as f64))
    }

    /// The worst error over the given `(y, x)` pairs, with the pair.
    fn worst_atan2(pairs: impl Iterator<Item = (f32, f32)>) -> (f64, f32, f32) {
        let mut w = (0.0, 0.0f32, 0.0f32);
        for (y, x) in pairs {
            let e = atan2_err(y, x);
            // A NaN error (a NaN result) is kept: the callers' `<=` fails.
            if e.is_nan() || e > w.0 {
                w = (e, y, x);
            }
        }
        w
    }

    /// `(y, x)`, `(y, -x)`, `(-y, x)`, `(-y, -x)`: the four fix-ups.
    fn four_signs((y, x): (f32, f32)) -> [(f32, f32); 4] {
        [(y, x), (y, -x), (-y, x), (-y, -x)]
    }

    #[test]
    fn atan2_polynomial_within_its_truncation_bound() {
        // The f32 coefficients evaluated in f64 (rounding errors near 1e-16)
        // against f64's atan at a million points of (0, 1]: the relative
        // error is the truncation alone; the Remez fit gives 3.123e-9 (the
        // bound stated at the coefficients is 3.2e-9). A mistyped
        // coefficient shows by orders of magnitude.
        let cs = [A3, A5, A7, A9, A11, A13, A15, A17, A19].map(f64::from);
        let mut worst = 0.0f64;
        for k in 1..=1_000_000 {
            let t = k as f64 / 1e6;
            let s = t * t;
            let p = cs.iter().rev().fold(0.0, |acc, &c| acc * s + c);
            let a = t + t * s * p;
            worst = worst.max((a / t.atan() - 1.0).abs());
        }
        assert!(worst <= 3.2e-9, "{worst:e}");
        assert!(
            worst > 2.5e-9,
            "{worst:e}: below the minimax error, a wrong check"
        );
    }

    #[test]
    fn atan2_every_pair_of_a_bit_pattern_sample_within_2_ulp() {
        // Every 1_999_993rd bit pattern of the non-negative finite f32 (1071
        // values from 0 over the subnormals to 3.4e38; the step is prime so
        // the significands vary), all 1.1 million ordered pairs in all four
        // sign combinations: every ratio |y/x| from 0 to infinity, overflow
        // and underflow of the quotient included.
        let vals: std::vec::Vec<f32> = (0..0x7F80_0000u32)
            .step_by(1_999_993)
            .map(f32::from_bits)
            .collect();
        let pairs = vals
            .iter()
            .flat_map(|&y| vals.iter().map(move |&x| (y, x)))
            .flat_map(four_signs);
        let (e, y, x) = worst_atan2(pairs);
        assert!(e <= BOUND_ULP, "{e} ulp at ({y:e}, {x:e})");
    }

    #[test]
    fn atan2_around_the_circle_within_2_ulp() {
        // 100 000 directions evenly around the circle (every octant, the
        // axes and the diagonals included: 100 000 is a multiple of 8) at
        // radii from the subnormals to near overflow; the point is rounded
        // to f32 and the reference is the angle of the rounded point.
        for r in [1e-42, 1e-30, 1e-3, 1.0, 7.3e3, 1e30, 3e38] {
            let n = 100_000;
            let pairs = (0..n).map(|k| {
                let th = -core::f64::consts::PI + 2.0 * core::f64::consts::PI * k as f64 / n as f64;
                ((r * th.sin()) as f32, (r * th.cos()) as f32)
            });
            let (e, y, x) = worst_atan2(pairs);
            assert!(e <= BOUND_ULP, "radius {r:e}: {e} ulp at ({y:e}, {x:e})");
        }
    }

    #[test]
    fn atan2_near_the_diagonals_and_powers_of_two_within_2_ulp() {
        // |y/x| near 1 (where the min/max swap and the result is finest
        // relative to pi/2) and just around 2^-k (the quotient's spacing
        // twice the result's: the division's rounding costs most there):
        // 2048 significands of x in [1, 2), y its 64 neighbours either side
        // of x 2^-k for k = 0..6, all four sign combinations.
        let mut pairs = std::vec::Vec::new();
        for j in 0..2048u32 {
            let x = f32::from_bits(1.0f32.to_bits() + j * 4096 + 1);
            for k in 0..6 {
                let c = (x * pow2(-k)).to_bits();
                for b in c - 64..=c + 64 {
                    pairs.extend(four_signs((f32::from_bits(b), x)));
                }
            }
        }
        let (e, y, x) = worst_atan2(pairs.into_iter());
        assert!(e <= BOUND_ULP, "{e} ulp at ({y:e}, {x:e})");
    }

    #[test]
    fn atan2_special_values_follow_libm() {
        // libm's (and C99's) special cases, bit for bit against f64's
        // atan2 rounded to f32: signed zeros, +-pi, +-pi/2, +-pi/4, +-3pi/4.
        let vals = [
            0.0,
            -0.0,
            f32::from_bits(1),
            -f32::from_bits(1),
            1.0,
            -1.0,
            f32::MAX,
            -f32::MAX,
            f32::INFINITY,
            f32::NEG_INFINITY,
        ];
        for y in vals {
            for x in vals {
                let got = atan2_f32(y, x);
                let want = (y as f64).atan2(x as f64) as f32;
                let special = y == 0.0 || x == 0.0 || y.is_infinite() || x.is_infinite();
                if special {
                    assert_eq!(got.to_bits(), want.to_bits(), "({y:e}, {x:e}): {got:e}");
                } else {
                    assert!(atan2_err(y, x) <= BOUND_ULP, "({y:e}, {x:e}): {got:e}");
                }
            }
            // NaN in, NaN out, whatever the other argument.
            assert!(atan2_f32(y, f32::NAN).is_nan() && atan2_f32(f32::NAN, y).is_nan());
        }
        assert!(atan2_f32(f32::NAN, f32::NAN).is_nan());
    }

    #[test]
    #[ignore = "3.1e9 pairs: minutes in release"]
    fn atan2_dense_within_2_ulp() {
        // 40 significands of x in [1, 2) (plus its negative) against every
        // 7th f32 y in [2^-30, 4) (38 million per x): ratios |y/x| from
        // 2^-31 to 4, so t = min/max densely over [2^-31, 1] (scaling
        // both arguments by a power of two changes nothing while no quotient
        // or argument is subnormal; those are in the ordinary tests) and all four
        // fix-ups (a positive or negative y is the same computation up to
        // the final copysign; the ordinary tests cover both). Four threads.
        let lo = pow2(-30).to_bits();
        let hi = 4.0f32.to_bits();
        let workers: std::vec::Vec<_> = (0..4u32)
            .map(|w| {
                std::thread::spawn(move || {
                    let mut all = (0.0, 0.0f32, 0.0f32);
                    for j in (w..40).step_by(4) {
                        let x = f32::from_bits(1.0f32.to_bits() + j * 209_715 + 17);
                        let ys = (lo..hi).step_by(7).map(f32::from_bits);
                        let r = worst_atan2(ys.flat_map(|y| [(y, x), (y, -x)]));
                        if r.0 > all.0 {
                            all = r;
                        }
                    }
                    all
                })
            })
            .collect();
        let mut all = (0.0, 0.0f32, 0.0f32);
        for w in workers {
            let r = w.join().expect("worker");
            if r.0 > all.0 {
                all = r;
            }
        }
        let (e, y, x) = all;
        std::println!("atan2: worst {e:.4} ulp at ({y:e}, {x:e})");
        assert!(e <= BOUND_ULP);
    }
}
