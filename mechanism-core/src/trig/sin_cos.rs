//! `(sin x, cos x)` of `f32` in `f32` (and integer) arithmetic: [`sin_cos_f32`].
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
//!
//! The digits of `2/pi` and `pi/2` below are the standard binary expansions
//! (hexadecimal, most significant first); the tests check them indirectly:
//! a wrong word would put large arguments' results far from `f64`'s, whose
//! reduction uses its own table.

use super::pow2;

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

#[cfg(test)]
mod tests {
    extern crate std;
    use super::super::ulp::{ulps, BOUND_ULP};
    use super::*;

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
}
