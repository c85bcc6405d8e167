//! `atan2` of `f32` in `f32` arithmetic: [`atan2_f32`], and [`angle_f32`].
//!
//! libm's `atan2f` is single precision already, but general: a call to
//! `atanf`, which reduces its argument to one of four intervals (a division
//! and a table), special-case tests on the bit patterns of both arguments,
//! about 80 instructions per call on a Cortex-M4F. [`atan2_f32`] takes one
//! division to `[0, 1]` and one polynomial there, about 52 (see its
//! documentation for the method and the error).
//!

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
///    degree-8 polynomial above (Horner form on the M4F, each step one load
///    and one multiply-accumulate; Estrin's elsewhere, see `poly`),
///    truncation below `0.053 * 2^-24`
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

/// `P(s) = A3 + A5 s + ... + A19 s^8`. On 32-bit ARM in Horner's form:
/// one multiply-accumulate per coefficient, the fewest instructions for the
/// Cortex-M's in-order pipeline. Elsewhere by Estrin's scheme (pairs of
/// coefficients, combined with `s^2` and `s^4`): three more multiplications,
/// but a dependency chain of 8 operations instead of 16, which an
/// out-of-order core runs in about half the latency (on x86-64 the Horner
/// chain was a quarter of the f32 slider-crank's solve). The rounding
/// differs from Horner's by a few ulp of `P`, which enters the result as a
/// correction of at most a third of it: the same 2 ulp bound holds (the
/// tests below run on the host, so they check this form).
#[inline(always)]
fn poly(s: f32) -> f32 {
    #[cfg(target_arch = "arm")]
    {
        A3 + s
            * (A5 + s * (A7 + s * (A9 + s * (A11 + s * (A13 + s * (A15 + s * (A17 + s * A19)))))))
    }
    #[cfg(not(target_arch = "arm"))]
    {
        let s2 = s * s;
        let s4 = s2 * s2;
        let low = (A3 + A5 * s) + (A7 + A9 * s) * s2;
        let high = (A11 + A13 * s) + (A15 + A17 * s) * s2;
        low + (high + A19 * s4) * s4
    }
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
    let c = t * s * poly(s);
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
    use super::super::pow2;
    use super::super::ulp::{ulps, BOUND_ULP};
    use super::*;

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
