//! Branch-free, inlinable versions of what a batch of evaluations needs,
//! written so that a loop over many elements vectorizes: no calls into libm,
//! no early return, no data-dependent branch (every `if` below selects
//! between two already computed values, which the compiler turns into a
//! vector blend). Checks become a per-element `ok` flag; where an element
//! fails, harmless substitute values keep NaN and infinities out of the
//! arithmetic, and the caller (the generated `solve_batch`) evaluates that
//! element again through the scalar path, which says why it failed.
//!
//! This module: the elementary functions ([`sin_cos`], [`atan2`], [`sqrt`],
//! [`wrap_angle`]) and the rigid-body relations; one file per driver and
//! per Assur group, each the lane version of its scalar primitive in
//! [`crate::driver`] / [`crate::dyad`] with the same formulas, sign
//! conventions and modes (`sign = +1` for `Mode::Plus`): `crank`, `slider`,
//! `actuator`, `rrr`, `rrp`, `rpr`, `prp`, `rpp`, and `guide` (guide lines
//! and the motion of the bodies that carry them). Every check of a group is
//! at least as strict as the scalar one (assembly strictly outside the
//! scalar rounding band, determinants above twice the scalar singular
//! threshold), so an element a lane primitive accepts is one the scalar
//! primitive accepts; finiteness of the results is checked by the caller.
//!
//! Everything is generic over [`Real`] (`f32`, `f64`); the precision-specific
//! parts (polynomial degrees, rounding constants) are chosen by a test on
//! `T::eps()` that folds at compile time. The argument reduction of
//! [`sin_cos`] and the square root's first guess work in `f64` (exact for
//! `f32` arguments), the polynomials in `T`.
//!
//! # Accuracy
//!
//! Checked by the tests below against `std`'s `f64` functions (glibc's,
//! within an ulp of `f64`; for `f32` results far more accurate than needed),
//! in ulp of `T` at the exact value, with no absolute floor near zeros:
//!
//! - [`sin_cos`]: `|x| <= 1e5` rad ([`SIN_COS_LIMIT`]); beyond it, or for a
//!   non-finite `x`, `ok` is false. f64: within 1.5 ulp (worst found 1.0 over
//!   4 million arguments across the range and every double next to `k pi/2`,
//!   `k < 63 000`); f32: within 2 ulp (worst found 1.6 over every 17th `f32`
//!   in `[2^-20, 1e5]`, both signs).
//! - [`atan2`]: f64 within 2.5 ulp (worst found 2.0), f32 within 2 ulp (worst
//!   found 1.8), on 800 000 points on circles of radii 1e-3 to 1e4, and the
//!   libm values on the axes (signed zeros included).
//! - [`sqrt`]: within 1 ulp for normal arguments (f64 and f32).
//!
//! # Method
//!
//! - `sin_cos`: `k = round(x 2/pi)` (adding and subtracting `1.5 2^52`, which
//!   rounds to an integer for `|x| < 2^51`), `r = x - k pi/2` by Cody-Waite
//!   with `pi/2 = P1 + P2 + P3` (`P1`, `P2`: 33 significant bits, so `k P1` and
//!   `k P2` are exact for `|k| < 2^20`; `x - k P1` is exact by Sterbenz's
//!   lemma; the difference with `k P2` is split exactly into `hi + err`), `r`
//!   carried as `r + rt`; Taylor series of `sin` and `cos` on `|r| <= pi/4`
//!   (f64: through `r^17` / `r^18`, truncation below `2^-55`; f32: through
//!   `r^9` / `r^10`); the quadrant `k mod 4` picks signs and swaps by selects.
//! - `atan2`: `t = min(|x|, |y|) / max(|x|, |y|)` in `[0, 1]`, `c = round(8 t)
//!   / 8`, `atan t = atan c + atan u` with `u = (t - c) / (1 + t c)`,
//!   `|u| <= 1/16`, `atan u` by its Taylor series (f64: through `u^13`,
//!   truncation below `u 2^-56 / 15`; f32: through `u^5`); the nine `atan(j/8)`
//!   are constants (correctly rounded, computed with 300-bit arithmetic);
//!   octant corrections by selects.
//! - `sqrt`: the bit-level first guess of `1/sqrt(x)` (shift the `f64` bit
//!   pattern right by one, subtract from `0x5FE6_EB50_C7B5_37A9`; within 3.5 %),
//!   Newton steps `y (3/2 - x y^2 / 2)` (relative error 3.5e-2 -> 1.8e-3
//!   -> 4.8e-6 -> 3.5e-11; three for f64, two for f32), `s = x y` and one
//!   correction `s + y (x - s^2) / 2`, which squares the relative error of
//!   `s` (f64: about 1e-21; f32: about 2e-11), far below the last bit.
//! - The polynomials are evaluated by Estrin's scheme (pairs of terms, then
//!   powers of the square), which shortens the chain of dependent
//!   operations that a long vectorized loop body waits on.

use crate::scalar::{single, Real};

mod actuator;
mod crank;
mod guide;
mod prp;
mod rpp;
mod rpr;
mod rrp;
mod rrr;
mod slider;

pub use actuator::{actuator_accels, actuator_rates};
pub use crank::{crank, Crank};
pub use guide::{
    carried, difference, plus, transport_acceleration, transport_velocity, Line, LineAcceleration,
    LineVelocity,
};
pub use prp::{prp, prp_accels, prp_rates, Prp};
pub use rpp::{rpp, rpp_accels, rpp_rates, Rpp};
pub use rpr::{rpr, rpr_accels, rpr_rates, Rpr};
pub use rrp::{rrp, rrp_accels, rrp_rates, Rrp};
pub use rrr::{rrr, rrr_accels, rrr_rates, Rrr};
pub use slider::{slider, slider_acceleration, slider_velocity};

/// Largest `|x|` (rad) [`sin_cos`] accepts.
pub const SIN_COS_LIMIT: f64 = 1.0e5;

/// `1.5 2^52`: `(x + R64) - R64` rounds an `f64` with `|x| < 2^51` to an integer.
const R64: f64 = 6_755_399_441_055_744.0;
/// `1.5 2^23`: the same for `f32` and `|x| < 2^22`.
const R32: f64 = 12_582_912.0;

const FRAC_2_PI: f64 = core::f64::consts::FRAC_2_PI;

/// `pi/2` minus its `f64` rounding (`FRAC_PI_2`).
const FRAC_PI_2_LO: f64 = 6.123_233_995_736_766e-17;

/// `atan(j / 8)` for `j = 0..=8`, rounded to nearest `f64`.
const ATAN_EIGHTHS: [f64; 9] = [
    0.0,
    0.124_354_994_546_761_44,
    0.244_978_663_126_864_14,
    0.358_770_670_270_572_25,
    0.463_647_609_000_806_1,
    0.558_599_315_343_562_4,
    0.643_501_108_793_284_4,
    0.718_829_999_621_624_5,
    core::f64::consts::FRAC_PI_4,
];

/// `a` where `c`, else `b`: both are computed; a blend in vector code.
#[inline(always)]
pub fn select<T: Copy>(c: bool, a: T, b: T) -> T {
    if c {
        a
    } else {
        b
    }
}

#[inline(always)]
pub(crate) fn abs<T: Real>(x: T) -> T {
    select(x < T::zero(), -x, x)
}

/// Nearest integer (ties to even) of `x` in `T`, for `|x| < 2^22` (f32) or
/// `2^51` (f64).
#[inline(always)]
fn round<T: Real>(x: T) -> T {
    let m = T::lit(if single::<T>() { R32 } else { R64 });
    (x + m) - m
}

/// `(sin x, cos x, ok)` for `x` in radians; `ok` is false (and the results
/// those of `x = 0`) when `|x| > SIN_COS_LIMIT` or `x` is not finite.
#[inline(always)]
pub fn sin_cos<T: Real>(x: T) -> (T, T, bool) {
    let ok = abs(x) <= T::lit(SIN_COS_LIMIT);
    let xd = select(ok, x, T::zero()).as_f64();
    let k = (xd * FRAC_2_PI + R64) - R64;
    let (r, rt) = crate::eft::reduce(xd, k, crate::eft::P1, crate::eft::P2, crate::eft::P3);
    // k mod 4 in 0..=3: k/4 is exact, and k/4 - 3/8 rounds to floor(k/4).
    let q = k - 4.0 * ((k * 0.25 - 0.375 + R64) - R64);
    let (s, c) = if single::<T>() {
        let r = T::lit(r);
        let r2 = r * r;
        let s = r + r
            * r2
            * (T::lit(-1.0 / 6.0)
                + r2 * (T::lit(1.0 / 120.0)
                    + r2 * (T::lit(-1.0 / 5040.0) + r2 * T::lit(1.0 / 362_880.0))));
        let c = T::one() - T::lit(0.5) * r2
            + r2 * r2
                * (T::lit(1.0 / 24.0)
                    + r2 * (T::lit(-1.0 / 720.0)
                        + r2 * (T::lit(1.0 / 40_320.0) + r2 * T::lit(-1.0 / 3_628_800.0))));
        (s, c)
    } else {
        let r2 = r * r;
        // Taylor coefficients 1/n! with alternating signs, evaluated by
        // Estrin's scheme (pairs, then powers r^4 and r^8): the same terms
        // as Horner's rule with a dependency chain of 5 operations instead of
        // 14, which is what a long vectorized loop body waits on.
        let (r4, r8) = (r2 * r2, (r2 * r2) * (r2 * r2));
        let ps = ((-1.0 / 6.0 + r2 * (1.0 / 120.0))
            + r4 * (-1.0 / 5040.0 + r2 * (1.0 / 362_880.0)))
            + r8 * ((-1.0 / 39_916_800.0 + r2 * (1.0 / 6_227_020_800.0))
                + r4 * (-1.0 / 1_307_674_368_000.0 + r2 * (1.0 / 355_687_428_096_000.0)));
        let pc = ((1.0 / 24.0 + r2 * (-1.0 / 720.0))
            + r4 * (1.0 / 40_320.0 + r2 * (-1.0 / 3_628_800.0)))
            + r8 * ((1.0 / 479_001_600.0 + r2 * (-1.0 / 87_178_291_200.0))
                + r4 * (1.0 / 20_922_789_888_000.0 + r2 * (-1.0 / 6_402_373_705_728_000.0)));
        // sin(r + rt) = sin r + rt cos r, cos(r + rt) = cos r - rt sin r, to
        // far below the last bit (|rt| about ulp(r) / 2 at most).
        let s = r + (r * r2 * ps + rt * (1.0 - 0.5 * r2));
        let c = 1.0 - 0.5 * r2 + (r2 * r2 * pc - rt * r);
        (T::lit(s), T::lit(c))
    };
    let odd = (q == 1.0) | (q == 3.0);
    let sn = select(odd, c, s);
    let cn = select(odd, s, c);
    let sin = select(q >= 2.0, -sn, sn);
    let cos = select((q == 1.0) | (q == 2.0), -cn, cn);
    (sin, cos, ok)
}

/// `atan2(y, x)` (rad, in `[-pi, pi]`, the same quadrant and signed-zero
/// conventions as libm's `atan2`) for finite arguments; `(0, 0)` gives `0`
/// (or `+-pi` by the signs of the zeros, as libm).
#[inline(always)]
pub fn atan2<T: Real>(y: T, x: T) -> T {
    let (ax, ay) = (abs(x), abs(y));
    let swap = ay > ax;
    let mx = select(swap, ay, ax);
    let mn = select(swap, ax, ay);
    let t = mn / select(mx > T::zero(), mx, T::one());
    let j = round(t * T::lit(8.0));
    let c = j * T::lit(0.125);
    // t - c is exact (Sterbenz) for j >= 1; t c rounds once.
    let u = (t - c) / (T::one() + t * c);
    let u2 = u * u;
    let p = if single::<T>() {
        u + u * u2 * (T::lit(-1.0 / 3.0) + u2 * T::lit(1.0 / 5.0))
    } else {
        // Estrin's scheme, as in `sin_cos`.
        let (u4, u8) = (u2 * u2, (u2 * u2) * (u2 * u2));
        u + u
            * u2
            * ((T::lit(-1.0 / 3.0) + u2 * T::lit(1.0 / 5.0))
                + u4 * (T::lit(-1.0 / 7.0) + u2 * T::lit(1.0 / 9.0))
                + u8 * (T::lit(-1.0 / 11.0) + u2 * T::lit(1.0 / 13.0)))
    };
    let mut base = T::zero();
    for (i, a) in ATAN_EIGHTHS.iter().enumerate().skip(1) {
        base = select(j >= T::lit(i as f64), T::lit(*a), base);
    }
    let a = base + p;
    // pi/2 and pi as T's rounded value plus the rest (f64: 6.1e-17 and
    // 1.2e-16 below the last bit), so the differences round once.
    let (h2, h1) = (T::frac_pi_2(), T::pi());
    let l2 = T::lit(core::f64::consts::FRAC_PI_2 - h2.as_f64() + FRAC_PI_2_LO);
    let l1 = T::lit(core::f64::consts::PI - h1.as_f64() + 2.0 * FRAC_PI_2_LO);
    // Octants: a (x >= 0, |y| <= |x|), pi - a (x < 0), pi/2 - a (|y| > |x|,
    // x >= 0), pi/2 + a (|y| > |x|, x < 0); one rounding each, and the
    // first case exact (0 + a + 0).
    let neg = x.is_sign_negative();
    let z = T::zero();
    let hi = select(swap, h2, select(neg, h1, z));
    let lo = select(swap, l2, select(neg, l1, z));
    let a = hi + select(swap ^ neg, -a, a) + lo;
    select(y.is_sign_negative(), -a, a)
}

/// Angle of `(x, y)` from +x (rad, in `(-pi, pi]`), as
/// [`crate::geometry::angle`]: [`atan2`] with a negative zero `y` made `+0`,
/// so a vector along `-x` gives `pi`.
/// A result that rounded to `-pi` (a tiny negative `y`) is returned as `pi`.
#[inline(always)]
pub fn angle<T: Real>(y: T, x: T) -> T {
    let a = atan2(y + T::zero(), x);
    let pi = T::pi();
    select(a <= -pi, pi, a)
}

/// `angle` (rad) reduced to `(-pi, pi]` like [`crate::geometry::wrap_angle`]
/// (unchanged when already inside, else `angle - 2 pi round(angle / 2 pi)`
/// moved into the range), for `|angle| <= SIN_COS_LIMIT`.
#[inline(always)]
pub fn wrap_angle<T: Real>(angle: T) -> T {
    let (pi, two_pi) = (T::pi(), T::two_pi());
    let inside = (angle <= pi) & (angle > -pi);
    // Ties away from zero, as `round` in the scalar function.
    let n = angle / two_pi;
    let r = round(n);
    let d = n - r;
    let half = T::lit(0.5);
    let r = select((d == half) & (n > T::zero()), r + T::one(), r);
    let r = select((d == -half) & (n < T::zero()), r - T::one(), r);
    let reduced = angle - two_pi * r;
    let reduced = select(reduced <= -pi, reduced + two_pi, reduced);
    let reduced = select(reduced > pi, reduced - two_pi, reduced);
    select(inside, angle, reduced)
}

/// Square root of a non-negative finite `x` (within 1 ulp for normal `x`;
/// `0` for `0`). Other arguments give a meaningless finite or non-finite
/// value: the caller checks.
#[inline(always)]
pub fn sqrt<T: Real>(x: T) -> T {
    let xd = x.as_f64();
    let mut y = f64::from_bits(0x5FE6_EB50_C7B5_37A9u64.wrapping_sub(xd.to_bits() >> 1));
    // Three steps for f64 (3.5e-11 relative), two for f32 (4.8e-6): the
    // final correction squares the error of `s`.
    for _ in 0..if single::<T>() { 2 } else { 3 } {
        y *= 1.5 - 0.5 * xd * y * y;
    }
    let s = xd * y;
    T::lit(s + 0.5 * y * (xd - s * s))
}

/// `omega perp(r)`: velocity of a point at offset `r` on a link turning at `omega`.
#[inline(always)]
pub fn rel_vel<T: Real>(rx: T, ry: T, omega: T) -> (T, T) {
    (-ry * omega, rx * omega)
}

/// `alpha perp(r) - omega^2 r`.
#[inline(always)]
pub fn rel_acc<T: Real>(rx: T, ry: T, omega: T, alpha: T) -> (T, T) {
    let w2 = omega * omega;
    (-ry * alpha - rx * w2, rx * alpha - ry * w2)
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;

    /// Error of `got` against `want` (exact or nearly, f64) in ulp of `T` at
    /// `|want|`, with the spacing floored at `floor` (an absolute bound near
    /// zeros of the function).
    fn ulps(got: f64, want: f64, eps: f64, floor: f64) -> f64 {
        let w = want.abs();
        let spacing = if w == 0.0 {
            floor
        } else {
            (2f64.powi(w.log2().floor() as i32) * eps).max(floor)
        };
        (got - want).abs() / spacing
    }

    /// `sin`, `cos` of many arguments against `std` (f64: glibc's sin/cos,
    /// correctly rounded in practice; f32: f64's values, exact enough).
    fn check_sin_cos<T: Real>(xs: impl Iterator<Item = f64>, floor: f64, bound: f64) {
        let eps = T::eps().as_f64();
        let mut worst = (0.0f64, 0.0f64);
        for x in xs {
            let xt = T::lit(x);
            let xe = xt.as_f64();
            let (s, c, ok) = sin_cos(xt);
            assert!(ok, "{x}");
            let es = ulps(s.as_f64(), xe.sin(), eps, floor);
            let ec = ulps(c.as_f64(), xe.cos(), eps, floor);
            if es.max(ec) > worst.0 {
                worst = (es.max(ec), x);
            }
        }
        std::println!(
            "sin_cos {}: worst {:.3} ulp at {}",
            core::any::type_name::<T>(),
            worst.0,
            worst.1
        );
        assert!(worst.0 <= bound, "{} ulp at {}", worst.0, worst.1);
    }

    #[test]
    fn sin_cos_f64_dense_within_1_5_ulp() {
        // 2 million arguments across [-1e5, 1e5] (a step that is no multiple
        // of pi) and 2 million across [-8, 8] (the usual crank angles).
        let xs = (0..2_000_000).map(|i| -1.0e5 + i as f64 * 0.100_000_000_37);
        check_sin_cos::<f64>(xs, 0.0, 1.5);
        let xs = (0..2_000_000).map(|i| -8.0 + i as f64 * 8.000_000_3e-6);
        check_sin_cos::<f64>(xs, 0.0, 1.5);
    }

    #[test]
    fn sin_cos_f64_near_multiples_of_pi_over_2() {
        // The doubles nearest k pi/2 and their neighbours: the cancellation
        // cases of the reduction.
        let mut xs = std::vec::Vec::new();
        for k in 1..63_000i64 {
            let x = k as f64 * core::f64::consts::FRAC_PI_2;
            let b = x.to_bits();
            xs.extend([b - 1, b, b + 1].map(f64::from_bits));
        }
        check_sin_cos::<f64>(xs.into_iter(), 0.0, 1.5);
    }

    #[test]
    fn sin_cos_f32_dense_within_2_ulp() {
        // Every 17th f32 in [2^-20, 1e5] and the negatives (the reduction is
        // in f64, r is rounded to f32 once, then the f32 polynomials).
        let lo = (2f32).powi(-20).to_bits();
        let hi = 1.0e5f32.to_bits();
        let xs = (lo..=hi)
            .step_by(17)
            .map(|b| f32::from_bits(b) as f64)
            .flat_map(|x| [x, -x]);
        check_sin_cos::<f32>(xs, 0.0, 2.0);
    }

    #[test]
    fn sin_cos_out_of_range_is_flagged_without_nan() {
        for x in [1.0e5 + 1.0, -2.0e5, f64::INFINITY, f64::NAN, 1e300] {
            let (s, c, ok) = sin_cos(x);
            assert!(!ok && s == 0.0 && c == 1.0, "{x}");
        }
        let (s, c, ok) = sin_cos(f32::NAN);
        assert!(!ok && s == 0.0 && c == 1.0);
        assert!(sin_cos(1.0e5f64).2 && sin_cos(-1.0e5f32).2);
    }

    fn check_atan2<T: Real>(bound: f64) {
        let eps = T::eps().as_f64();
        let mut worst = (0.0, 0.0, 0.0);
        // Points on circles of several radii at 200 001 angles, plus the axes.
        for r in [1e-3, 1.0, 7.3, 1e4] {
            for i in 0..=200_000 {
                let a = -core::f64::consts::PI + i as f64 * (core::f64::consts::TAU / 200_000.0);
                let (y, x) = (T::lit(r * a.sin()), T::lit(r * a.cos()));
                let got = atan2(y, x).as_f64();
                let want = y.as_f64().atan2(x.as_f64());
                let e = ulps(got, want, eps, f64::MIN_POSITIVE);
                if e > worst.0 {
                    worst = (e, y.as_f64(), x.as_f64());
                }
            }
        }
        std::println!(
            "atan2 {}: worst {:.3} ulp at ({}, {})",
            core::any::type_name::<T>(),
            worst.0,
            worst.1,
            worst.2
        );
        assert!(
            worst.0 <= bound,
            "{} ulp at ({}, {})",
            worst.0,
            worst.1,
            worst.2
        );
        for (y, x) in [
            (0.0, 1.0),
            (0.0, -1.0),
            (-0.0, -1.0),
            (1.0, 0.0),
            (-1.0, -0.0),
        ] {
            let (yt, xt) = (T::lit(y), T::lit(x));
            assert_eq!(
                atan2(yt, xt).as_f64(),
                T::lit(y.atan2(x)).as_f64(),
                "{y} {x}"
            );
        }
    }

    /// A vector along `-x` is at `pi` whichever sign its zero `y` has, as in
    /// the scalar path (`geometry::angle`); `atan2` keeps libm's `-pi`.
    #[test]
    fn angle_along_minus_x_is_pi() {
        for y in [0.0f64, -0.0] {
            assert_eq!(angle(y, -2.5f64), core::f64::consts::PI);
            assert_eq!(angle(y as f32, -2.5f32), core::f32::consts::PI);
        }
        assert!(atan2(-0.0f64, -2.5) < 0.0);
    }

    #[test]
    fn atan2_f64_within_2_5_ulp() {
        // Worst found 2.0: the rounding of atan(j/8), of the sum, of the
        // division and of the octant correction can add up; 2.5 leaves the
        // last a margin.
        check_atan2::<f64>(2.5);
    }

    #[test]
    fn atan2_f32_within_2_ulp() {
        check_atan2::<f32>(2.0);
    }

    #[test]
    fn sqrt_within_1_ulp() {
        for i in 0..1_000_000u64 {
            // Spread over 2^-600 .. 2^600.
            let x = 2f64.powf(-600.0 + i as f64 * 1.2e-3) * (1.0 + (i % 97) as f64 / 97.0);
            let got = sqrt(x);
            assert!(ulps(got, x.sqrt(), f64::EPSILON, 0.0) <= 1.0, "{x}");
            let xf = x as f32;
            if xf.is_normal() {
                let got = sqrt(xf) as f64;
                let want = (xf as f64).sqrt();
                assert!(ulps(got, want, f32::EPSILON as f64, 0.0) <= 1.0, "{xf}");
            }
        }
        assert_eq!(sqrt(0.0f64), 0.0);
        assert_eq!(sqrt(0.0f32), 0.0);
    }

    #[test]
    fn wrap_angle_matches_the_scalar_one() {
        for i in 0..200_000 {
            let a = -1.0e5 + i as f64 * 1.000_003;
            assert_eq!(wrap_angle(a), crate::geometry::wrap_angle(a), "{a}");
            let af = a as f32;
            assert_eq!(wrap_angle(af), crate::geometry::wrap_angle(af), "{af}");
        }
    }
}
