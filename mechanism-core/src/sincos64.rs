//! Sine and cosine of `f64` together, for scalar use: [`sin_cos_f64`], within
//! 2 ulp of each (see Error below; the tests find at most 1.47), for
//! `|x| <= 1e5` rad; other arguments (zeros, NaN, infinite, larger) go to
//! libm.
//!
//! Why: the crank of every generated solve needs both; glibc's `sincos` is a
//! call (its results pass through memory) with a general reduction. This
//! kernel is inlined: one Cody-Waite reduction, two short polynomials, one
//! table row.
//!
//! # Method
//!
//! 1. `j = round(x 32/pi)` (adding and subtracting `1.5 2^52`; `|j| <=
//!    32 000 000 / pi < 2^20` for `|x| <= 1e5`), `r = x - j pi/32` by
//!    Cody-Waite with `pi/32 = Q1 + Q2 + Q3` (the three parts of `pi/2` of
//!    `eft` divided by 16, exact): `Q1`, `Q2` have 33 significant
//!    bits, so `j Q1` and `j Q2` are exact; `x - j Q1` is exact (Sterbenz:
//!    for `j != 0` the two are within a factor of 2); its difference with
//!    `j Q2` is split exactly into `hi + err` (two-sum), and `r + rt` carries
//!    the reduced argument to about `2^-100` relative. `|r| <= pi/64 + tiny`.
//!    `r` is `hi` itself and `rt = err - j Q3` (not renormalized), so the
//!    polynomials start from `r` while `rt` is still being computed.
//! 2. `sin(r + rt) = r + (r^3 S(r^2) + rt)`, `cos(r + rt) - 1 = r^2 C(r^2) -
//!    rt r`, with the Taylor coefficients `S = -1/3! + r^2/5! - r^4/7! +
//!    r^6/9!`, `C = -1/2! + r^2/4! - r^4/6! + r^6/8!`. The first omitted
//!    terms, `r^11/11!` and `r^10/10!` at `r = pi/64`, are `2^-73` and
//!    `2^-65`: below `2^-70` of `sin r` and far below an ulp of 1.
//! 3. `i = j mod 16`, the table row: `sin(i pi/32)` and `cos(i pi/32)` in
//!    double-double, `si + si_lo`, `ci + ci_lo` (from 60 digits:
//!    `scripts/sincos-f64-table.py`); `sin(i pi/32 + r) = si + (si_lo + (si
//!    cm + ci sr))`, `cos(..) = ci + (ci_lo + (ci cm - si sr))`; the quadrant
//!    `(j div 16) mod 4` swaps and negates.
//!
//! # Error
//!
//! In ulp of the result `R`: the final addition, half an ulp; the small term
//! `u = si_lo + (si cm + ci sr)` (`|u| <= pi/64 + 1.2e-3 < 2^-4`) rounds
//! three times (the product `ci sr`, its sum with `si cm`, the sum with
//! `si_lo`), half an ulp of `2^-5` each at most; the table's own error
//! (`2^-106`), the reduction's (`r + rt`, about `2^-100` relative) and the
//! truncations are far below. Where `si` is not 0, `R >= si - pi/64 >= si /
//! 2 >= 0.049` (`i >= 1`): in the binade `[2^-5, 2^-4)` the three roundings
//! are up to 1.5 ulp of `R`, above it 0.75: at most **2 ulp** (sine near
//! `pi/32 - pi/64`, where `R` is smallest against `u`), 1.25 elsewhere. `i =
//! 0`: `sin = sr`, `cos = 1 + cm`, under 0.7 ulp. Measured (tests below,
//! against a double-double reference that is accurate next to the zeros too):
//! at most 1.47 ulp over 4 million arguments (1.50 when `r + rt` was
//! renormalized before the polynomials).

/// Largest `|x|` (rad) the kernel takes; beyond, libm.
pub const SIN_COS_F64_LIMIT: f64 = 1.0e5;

/// `32 / pi`.
const INV_PI_32: f64 = 32.0 / core::f64::consts::PI;
/// `1.5 2^52`: `(x + R52) - R52` rounds `|x| < 2^51` to an integer.
const R52: f64 = 6_755_399_441_055_744.0;
/// `pi/32 = Q1 + Q2 + Q3`: the parts of `pi/2` of `eft` over 16.
const Q1: f64 = crate::eft::P1 / 16.0;
const Q2: f64 = crate::eft::P2 / 16.0;
const Q3: f64 = crate::eft::P3 / 16.0;

/// `[sin hi, sin lo, cos hi, cos lo]` of `i pi/32`, `i = 0..=15`, each value
/// in double-double (hi the nearest `f64`, lo the nearest to the rest).
const TABLE: [[f64; 4]; 16] = [
    [
        f64::from_bits(0x0000000000000000), /* 0.0 */
        f64::from_bits(0x0000000000000000), /* 0.0 */
        f64::from_bits(0x3ff0000000000000), /* 1.0 */
        f64::from_bits(0x0000000000000000), /* 0.0 */
    ],
    [
        f64::from_bits(0x3fb917a6bc29b42c), /* 0.0980171403295606 */
        f64::from_bits(0xbc3e2718d26ed688), /* -1.634582362244256e-18 */
        f64::from_bits(0x3fefd88da3d12526), /* 0.9951847266721969 */
        f64::from_bits(0xbc887df6378811c7), /* -4.248691367830441e-17 */
    ],
    [
        f64::from_bits(0x3fc8f8b83c69a60b), /* 0.19509032201612828 */
        f64::from_bits(0xbc626d19b9ff8d82), /* -7.991079068461731e-18 */
        f64::from_bits(0x3fef6297cff75cb0), /* 0.9807852804032304 */
        f64::from_bits(0x3c7562172a361fd3), /* 1.8546939997825006e-17 */
    ],
    [
        f64::from_bits(0x3fd294062ed59f06), /* 0.2902846772544624 */
        f64::from_bits(0xbc75d28da2c4612d), /* -1.892797870777425e-17 */
        f64::from_bits(0x3fee9f4156c62dda), /* 0.9569403357322088 */
        f64::from_bits(0x3c8760b1e2e3f81e), /* 4.05538698618757e-17 */
    ],
    [
        f64::from_bits(0x3fd87de2a6aea963), /* 0.3826834323650898 */
        f64::from_bits(0xbc672cedd3d5a610), /* -1.0050772696461588e-17 */
        f64::from_bits(0x3fed906bcf328d46), /* 0.9238795325112867 */
        f64::from_bits(0x3c7457e610231ac2), /* 1.7645047084336677e-17 */
    ],
    [
        f64::from_bits(0x3fde2b5d3806f63b), /* 0.47139673682599764 */
        f64::from_bits(0x3c5e0d891d3c6841), /* 6.516678136069013e-18 */
        f64::from_bits(0x3fec38b2f180bdb1), /* 0.881921264348355 */
        f64::from_bits(0xbc76e0b1757c8d07), /* -1.9843248405890562e-17 */
    ],
    [
        f64::from_bits(0x3fe1c73b39ae68c8), /* 0.5555702330196022 */
        f64::from_bits(0x3c8b25dd267f6600), /* 4.709410940561677e-17 */
        f64::from_bits(0x3fea9b66290ea1a3), /* 0.8314696123025452 */
        f64::from_bits(0x3c39f630e8b6dac8), /* 1.4073856984728024e-18 */
    ],
    [
        f64::from_bits(0x3fe44cf325091dd6), /* 0.6343932841636455 */
        f64::from_bits(0x3c68076a2cfdc6b3), /* 1.0420901929280035e-17 */
        f64::from_bits(0x3fe8bc806b151741), /* 0.773010453362737 */
        f64::from_bits(0xbc82c5e12ed1336d), /* -3.256590703364977e-17 */
    ],
    [
        f64::from_bits(0x3fe6a09e667f3bcd), /* 0.7071067811865476 */
        f64::from_bits(0xbc8bdd3413b26456), /* -4.833646656726457e-17 */
        f64::from_bits(0x3fe6a09e667f3bcd), /* 0.7071067811865476 */
        f64::from_bits(0xbc8bdd3413b26456), /* -4.833646656726457e-17 */
    ],
    [
        f64::from_bits(0x3fe8bc806b151741), /* 0.773010453362737 */
        f64::from_bits(0xbc82c5e12ed1336d), /* -3.256590703364977e-17 */
        f64::from_bits(0x3fe44cf325091dd6), /* 0.6343932841636455 */
        f64::from_bits(0x3c68076a2cfdc6b3), /* 1.0420901929280035e-17 */
    ],
    [
        f64::from_bits(0x3fea9b66290ea1a3), /* 0.8314696123025452 */
        f64::from_bits(0x3c39f630e8b6dac8), /* 1.4073856984728024e-18 */
        f64::from_bits(0x3fe1c73b39ae68c8), /* 0.5555702330196022 */
        f64::from_bits(0x3c8b25dd267f6600), /* 4.709410940561677e-17 */
    ],
    [
        f64::from_bits(0x3fec38b2f180bdb1), /* 0.881921264348355 */
        f64::from_bits(0xbc76e0b1757c8d07), /* -1.9843248405890562e-17 */
        f64::from_bits(0x3fde2b5d3806f63b), /* 0.47139673682599764 */
        f64::from_bits(0x3c5e0d891d3c6841), /* 6.516678136069013e-18 */
    ],
    [
        f64::from_bits(0x3fed906bcf328d46), /* 0.9238795325112867 */
        f64::from_bits(0x3c7457e610231ac2), /* 1.7645047084336677e-17 */
        f64::from_bits(0x3fd87de2a6aea963), /* 0.3826834323650898 */
        f64::from_bits(0xbc672cedd3d5a610), /* -1.0050772696461588e-17 */
    ],
    [
        f64::from_bits(0x3fee9f4156c62dda), /* 0.9569403357322088 */
        f64::from_bits(0x3c8760b1e2e3f81e), /* 4.05538698618757e-17 */
        f64::from_bits(0x3fd294062ed59f06), /* 0.2902846772544624 */
        f64::from_bits(0xbc75d28da2c4612d), /* -1.892797870777425e-17 */
    ],
    [
        f64::from_bits(0x3fef6297cff75cb0), /* 0.9807852804032304 */
        f64::from_bits(0x3c7562172a361fd3), /* 1.8546939997825006e-17 */
        f64::from_bits(0x3fc8f8b83c69a60b), /* 0.19509032201612828 */
        f64::from_bits(0xbc626d19b9ff8d82), /* -7.991079068461731e-18 */
    ],
    [
        f64::from_bits(0x3fefd88da3d12526), /* 0.9951847266721969 */
        f64::from_bits(0xbc887df6378811c7), /* -4.248691367830441e-17 */
        f64::from_bits(0x3fb917a6bc29b42c), /* 0.0980171403295606 */
        f64::from_bits(0xbc3e2718d26ed688), /* -1.634582362244256e-18 */
    ],
];

/// `(sin x, cos x)` for `x` in radians (see the module documentation).
#[inline(always)]
pub fn sin_cos_f64(x: f64) -> (f64, f64) {
    // Zeros (for the sign of `sin(-0)`), NaN, infinities and `|x| > 1e5`.
    if !(x.abs() <= SIN_COS_F64_LIMIT && x != 0.0) {
        return rare(x);
    }
    let jf = (x * INV_PI_32 + R52) - R52;
    let (r, rt) = crate::eft::reduce(x, jf, Q1, Q2, Q3);
    let r2 = r * r;
    // Estrin's scheme (pairs, then r^4): four dependent operations instead of
    // Horner's six.
    let r4 = r2 * r2;
    let ps = (-1.0 / 6.0 + r2 * (1.0 / 120.0)) + r4 * (-1.0 / 5040.0 + r2 * (1.0 / 362_880.0));
    let pc = (-0.5 + r2 * (1.0 / 24.0)) + r4 * (-1.0 / 720.0 + r2 * (1.0 / 40_320.0));
    let sr = r + (r * r2 * ps + rt);
    let cm = r2 * pc - rt * r;
    let j = jf as i64;
    // The row's sine and cosine turned by the quadrant `q = (j >> 4) & 3`,
    // i.e. of `q pi/2 + (j & 15) pi/32`: `(s, c)` becomes `(c, -s)`,
    // `(-s, -c)`, `(-c, s)` for `q = 1, 2, 3`. Swaps and sign flips are exact,
    // and they depend on `j` only, so they run beside the polynomials
    // (a `match` on the result put a jump table on the critical path).
    // The swap is a bit select on a mask, not a branch: sweeps in random
    // order would mispredict half of them.
    let [s0, s0_lo, c0, c0_lo] = TABLE[(j & 15) as usize];
    let swap = (((j >> 4) & 1) as u64).wrapping_neg();
    let sin_sign = (((j >> 5) & 1) as u64) << 63;
    let cos_sign = (((((j >> 4) + 1) >> 1) & 1) as u64) << 63;
    let pick = |keep: f64, other: f64, sign: u64| {
        let (k, o) = (keep.to_bits(), other.to_bits());
        f64::from_bits((k ^ ((k ^ o) & swap)) ^ sign)
    };
    let (si, si_lo) = (pick(s0, c0, sin_sign), pick(s0_lo, c0_lo, sin_sign));
    let (ci, ci_lo) = (pick(c0, s0, cos_sign), pick(c0_lo, s0_lo, cos_sign));
    let s = si + (si_lo + (si * cm + ci * sr));
    let c = ci + (ci_lo + (ci * cm - si * sr));
    (s, c)
}

/// Zeros, NaN, infinite and large arguments: libm's.
#[cold]
#[inline(never)]
fn rare(x: f64) -> (f64, f64) {
    <f64 as nalgebra::ComplexField>::sin_cos(x)
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;
    use mechanism_reference::Dd;
    use std::vec::Vec;

    /// Error of `got` against the double-double `want`, in ulp of `want`
    /// (the spacing of f64 at `|want|`; subnormal spacing near zero).
    fn ulps(got: f64, want: Dd) -> f64 {
        let w = want.hi.abs();
        let e = if w < f64::MIN_POSITIVE {
            -1074
        } else {
            ((w.to_bits() >> 52) as i32) - 1023 - 52
        };
        let diff = (Dd::from_f64(got) - want).to_f64().abs();
        diff / 2f64.powi(e)
    }

    /// Arguments: every `f64` next to the reduction's boundaries and to the
    /// zeros of sine and cosine (`k pi/64` for the first 20 000 `k`, and the
    /// two neighbours of each), random arguments over the range (uniform,
    /// and log-uniform from 1e-300), and tiny ones.
    fn arguments(n_random: usize) -> Vec<f64> {
        let mut xs = Vec::new();
        for k in 1..20_000u32 {
            let c = (Dd::from_f64(k as f64) * Dd::PI / Dd::from_f64(64.0)).to_f64();
            for x in [
                f64::from_bits(c.to_bits() - 1),
                c,
                f64::from_bits(c.to_bits() + 1),
            ] {
                xs.push(x);
                xs.push(-x);
            }
        }
        let mut state = 0x9E37_79B9_7F4A_7C15u64;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        for _ in 0..n_random {
            let u = next();
            xs.push((2.0 * u - 1.0) * SIN_COS_F64_LIMIT);
            let l = next();
            let sign = if next() < 0.5 { -1.0 } else { 1.0 };
            xs.push(sign * 10f64.powf(-300.0 + l * 305.0).min(SIN_COS_F64_LIMIT));
        }
        xs.extend([5e-324, 1e-310, 2.2e-308, 1e-20, 0.049, 0.0491, 1e5, -1e5]);
        xs
    }

    /// `pi/2` as a sum of four `f64` (60-digit `mpmath`; the rest is below
    /// `3e-66`).
    const PIO2: [f64; 4] = [
        core::f64::consts::FRAC_PI_2,
        6.123_233_995_736_766e-17,
        -1.497_384_904_859_169_8e-33,
        5.562_271_104_316_826e-50,
    ];

    /// Double-double `(sin x, cos x)` accurate relative to each result, also
    /// next to their zeros: `Dd::sin_cos` reduces with `pi/2` to 106 bits,
    /// which near a zero of `sin` at `x = 29 pi` leaves an absolute error of
    /// `6e-31` against a result of `1.2e-18` (1000 ulp); here `x - k pi/2` is
    /// taken with `pi/2` to 212 bits (each product `k p` exact in
    /// double-double, the first difference exact), then `Dd::sin_cos` of the
    /// reduced argument (which it does not reduce again).
    fn reference(x: f64) -> (Dd, Dd) {
        let k = (x / PIO2[0]).round();
        let mut r = Dd::from_f64(x);
        for p in PIO2 {
            r -= Dd::from_f64(k) * Dd::from_f64(p);
        }
        let (s, c) = r.sin_cos();
        match (k as i64).rem_euclid(4) {
            0 => (s, c),
            1 => (c, -s),
            2 => (-s, -c),
            _ => (-c, s),
        }
    }

    /// The worst errors (sin, cos) in ulp, with their arguments.
    fn worst(xs: &[f64]) -> ((f64, f64), (f64, f64)) {
        let (mut ws, mut wc) = ((0.0, 0.0), (0.0, 0.0));
        for &x in xs {
            let (s, c) = sin_cos_f64(x);
            let (rs, rc) = reference(x);
            let (es, ec) = (ulps(s, rs), ulps(c, rc));
            if es > ws.0 {
                ws = (es, x);
            }
            if ec > wc.0 {
                wc = (ec, x);
            }
        }
        (ws, wc)
    }

    /// Within 1.6 ulp on about 200 000 arguments (the analysis's bound is 2
    /// ulp; the worst found over 4 million is 1.47, so 1.6 keeps the test at
    /// the kernel's measured accuracy); the largest errors are printed.
    #[test]
    fn within_the_bound() {
        let ((es, xs), (ec, xc)) = worst(&arguments(40_000));
        std::println!("sin: {es:.3} ulp at {xs:e}; cos: {ec:.3} ulp at {xc:e}");
        assert!(es <= 1.6, "sin: {es} ulp at {xs:e}");
        assert!(ec <= 1.6, "cos: {ec} ulp at {xc:e}");
    }

    /// The same over 4 million random arguments (slow in a debug build:
    /// `cargo test --release -p mechanism-core --lib sincos64 -- --ignored
    /// --nocapture`).
    #[test]
    #[ignore]
    fn within_the_bound_dense() {
        let ((es, xs), (ec, xc)) = worst(&arguments(2_000_000));
        std::println!("sin: {es:.3} ulp at {xs:e}; cos: {ec:.3} ulp at {xc:e}");
        assert!(es <= 1.6 && ec <= 1.6);
    }

    /// Zeros keep libm's signs, and arguments outside the kernel's range
    /// (NaN, infinities, beyond 1e5) get libm's values.
    #[test]
    fn special_arguments() {
        let (s, c) = sin_cos_f64(-0.0);
        assert!(s == 0.0 && s.is_sign_negative() && c == 1.0);
        let (s, c) = sin_cos_f64(0.0);
        assert!(s == 0.0 && s.is_sign_positive() && c == 1.0);
        for x in [f64::NAN, f64::INFINITY, -f64::INFINITY] {
            let (s, c) = sin_cos_f64(x);
            assert!(s.is_nan() && c.is_nan(), "{x}");
        }
        for x in [1.000_001e5, 3e7, -1e300] {
            assert_eq!(sin_cos_f64(x), (x.sin(), x.cos()), "{x}");
        }
    }
}
