//! Double-double numbers: an unevaluated sum `hi + lo` of two `f64` with
//! `|lo| <= ulp(hi) / 2`, carrying about 106 significant bits (relative
//! rounding unit about 2^-104 = 4.9e-32 per operation).
//!
//! The error-free transformations are Knuth's two-sum and the fused
//! multiply-add product (`a * b - p` exact when computed by `mul_add`); the
//! composite operations follow the "sloppy" double-double algorithms analysed
//! by Dekker (1971) and Hida, Li and Bailey (QD library report, 2000). The
//! elementary functions are written here from their series and Newton
//! iterations; `tests/exact/dd.rs` checks each against `astro-float` at 200 bits.
//!
//! This type exists to be an independent reference: it shares no code with
//! `mechanism-core` or the generated code.

use core::cmp::Ordering;
use core::fmt;
use core::ops::{Add, AddAssign, Div, Mul, MulAssign, Neg, Sub, SubAssign};

/// A double-double number `hi + lo` (about 32 significant decimal digits).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Dd {
    /// Leading part: the value rounded to `f64`.
    pub hi: f64,
    /// Trailing part: the rounding error of `hi`.
    pub lo: f64,
}

/// `s + e = a + b` exactly, `s = fl(a + b)` (Knuth's two-sum, no ordering
/// assumption).
#[inline]
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

/// `s + e = a + b` exactly when `|a| >= |b|` (Dekker's fast two-sum).
#[inline]
fn quick_two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    (s, b - (s - a))
}

/// `p + e = a * b` exactly (fused multiply-add gives the exact error).
#[inline]
fn two_prod(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    (p, a.mul_add(b, -p))
}

impl Dd {
    /// Zero.
    pub const ZERO: Dd = Dd { hi: 0.0, lo: 0.0 };
    /// One.
    pub const ONE: Dd = Dd { hi: 1.0, lo: 0.0 };
    /// pi to 106 bits: hi = fl(pi), lo = fl(pi - hi).
    pub const PI: Dd = Dd {
        hi: core::f64::consts::PI,
        lo: 1.224_646_799_147_353_2e-16,
    };
    /// pi / 2 (exact halving of [`Dd::PI`]).
    pub const FRAC_PI_2: Dd = Dd {
        hi: core::f64::consts::FRAC_PI_2,
        lo: 6.123_233_995_736_766e-17,
    };
    /// 2 pi (exact doubling of [`Dd::PI`]).
    pub const TAU: Dd = Dd {
        hi: core::f64::consts::TAU,
        lo: 2.449_293_598_294_706_4e-16,
    };

    /// The exact value of an `f64`.
    #[inline]
    pub const fn from_f64(x: f64) -> Dd {
        Dd { hi: x, lo: 0.0 }
    }

    /// Nearest `f64` (hi + lo rounded once).
    #[inline]
    pub fn to_f64(self) -> f64 {
        self.hi + self.lo
    }

    /// Exact sum of two `f64`.
    #[inline]
    pub fn sum(a: f64, b: f64) -> Dd {
        let (hi, lo) = two_sum(a, b);
        Dd { hi, lo }
    }

    /// Exact product of two `f64`.
    #[inline]
    pub fn product(a: f64, b: f64) -> Dd {
        let (hi, lo) = two_prod(a, b);
        Dd { hi, lo }
    }

    /// True when both parts are finite.
    pub fn is_finite(self) -> bool {
        self.hi.is_finite() && self.lo.is_finite()
    }

    /// Absolute value.
    pub fn abs(self) -> Dd {
        if self.hi < 0.0 || (self.hi == 0.0 && self.lo < 0.0) {
            -self
        } else {
            self
        }
    }

    /// `self * 2^k` exactly (barring overflow and underflow).
    pub fn scale_pow2(self, k: i32) -> Dd {
        let f = 2f64.powi(k);
        Dd {
            hi: self.hi * f,
            lo: self.lo * f,
        }
    }

    /// Square.
    pub fn sqr(self) -> Dd {
        self * self
    }

    /// Square root (one Newton step on the `f64` root doubles its 53 bits);
    /// zero for zero, NaN for negative input.
    pub fn sqrt(self) -> Dd {
        if self.hi == 0.0 {
            return Dd::ZERO;
        }
        if self.hi < 0.0 {
            return Dd::from_f64(f64::NAN);
        }
        let y = Dd::from_f64(self.hi.sqrt());
        // y + (a - y^2) / (2 y): the residual is computed in double-double.
        y + (self - y.sqr()) / y.scale_pow2(1)
    }

    /// Sine and cosine. The argument is reduced by the nearest multiple of
    /// pi/2 (with pi/2 to 106 bits, so `|x|` up to about 1e6 keeps the full
    /// precision), then both Taylor series are summed until the term falls
    /// below 2^-110 of the result, on `|r| <= pi/4`.
    pub fn sin_cos(self) -> (Dd, Dd) {
        let k = (self / Dd::FRAC_PI_2).to_f64().round();
        let r = self - Dd::FRAC_PI_2 * Dd::from_f64(k);
        let (s, c) = sin_cos_taylor(r);
        match (k.rem_euclid(4.0)) as u8 {
            0 => (s, c),
            1 => (c, -s),
            2 => (-s, -c),
            _ => (-c, s),
        }
    }

    /// Sine.
    pub fn sin(self) -> Dd {
        self.sin_cos().0
    }

    /// Cosine.
    pub fn cos(self) -> Dd {
        self.sin_cos().1
    }

    /// Four-quadrant arctangent of `y / x` in (-pi, pi]: the `f64` estimate
    /// refined by two Newton steps on `y cos z - x sin z = 0` (each step
    /// doubles the correct bits: 53 -> 106).
    pub fn atan2(y: Dd, x: Dd) -> Dd {
        let mut z = Dd::from_f64(y.hi.atan2(x.hi));
        if x.hi == 0.0 && y.hi == 0.0 {
            return z;
        }
        for _ in 0..2 {
            let (s, c) = z.sin_cos();
            let f = y * c - x * s;
            let df = x * c + y * s;
            z += f / df;
        }
        z
    }
}

/// Taylor series of sine and cosine for `|r| <= pi/4` (about 27 terms for
/// 106 bits).
fn sin_cos_taylor(r: Dd) -> (Dd, Dd) {
    let r2 = r.sqr();
    let tiny = 2f64.powi(-110);
    // sin: r - r^3/3! + ...; cos: 1 - r^2/2! + ...
    let mut sin = r;
    let mut term = r;
    let mut n = 1.0;
    while term.hi.abs() > tiny * sin.hi.abs().max(tiny) {
        term = -(term * r2) / Dd::from_f64((n + 1.0) * (n + 2.0));
        sin += term;
        n += 2.0;
    }
    let mut cos = Dd::ONE;
    let mut term = Dd::ONE;
    let mut n = 0.0;
    while term.hi.abs() > tiny {
        term = -(term * r2) / Dd::from_f64((n + 1.0) * (n + 2.0));
        cos += term;
        n += 2.0;
    }
    (sin, cos)
}

impl Add for Dd {
    type Output = Dd;
    #[inline]
    fn add(self, b: Dd) -> Dd {
        // Accurate (IEEE-style) double-double addition: both parts summed
        // with error-free transformations, then renormalized.
        let (s, e) = two_sum(self.hi, b.hi);
        let (t, f) = two_sum(self.lo, b.lo);
        let (s, e) = quick_two_sum(s, e + t);
        let (hi, lo) = quick_two_sum(s, e + f);
        Dd { hi, lo }
    }
}

impl Sub for Dd {
    type Output = Dd;
    #[inline]
    fn sub(self, b: Dd) -> Dd {
        self + (-b)
    }
}

impl Neg for Dd {
    type Output = Dd;
    #[inline]
    fn neg(self) -> Dd {
        Dd {
            hi: -self.hi,
            lo: -self.lo,
        }
    }
}

impl Mul for Dd {
    type Output = Dd;
    #[inline]
    fn mul(self, b: Dd) -> Dd {
        let (p, e) = two_prod(self.hi, b.hi);
        let e = e + (self.hi * b.lo + self.lo * b.hi);
        let (hi, lo) = quick_two_sum(p, e);
        Dd { hi, lo }
    }
}

impl Div for Dd {
    type Output = Dd;
    #[inline]
    fn div(self, b: Dd) -> Dd {
        // Long division: three f64 quotient digits, each remainder formed in
        // double-double.
        let q1 = self.hi / b.hi;
        let r = self - b * Dd::from_f64(q1);
        let q2 = r.hi / b.hi;
        let r = r - b * Dd::from_f64(q2);
        let q3 = r.hi / b.hi;
        let (hi, lo) = quick_two_sum(q1, q2);
        Dd { hi, lo } + Dd::from_f64(q3)
    }
}

impl AddAssign for Dd {
    fn add_assign(&mut self, b: Dd) {
        *self = *self + b;
    }
}

impl SubAssign for Dd {
    fn sub_assign(&mut self, b: Dd) {
        *self = *self - b;
    }
}

impl MulAssign for Dd {
    fn mul_assign(&mut self, b: Dd) {
        *self = *self * b;
    }
}

impl From<f64> for Dd {
    fn from(x: f64) -> Dd {
        Dd::from_f64(x)
    }
}

impl PartialOrd for Dd {
    fn partial_cmp(&self, other: &Dd) -> Option<Ordering> {
        match self.hi.partial_cmp(&other.hi) {
            Some(Ordering::Equal) => self.lo.partial_cmp(&other.lo),
            ord => ord,
        }
    }
}

impl fmt::Display for Dd {
    /// Prints `hi` and `lo` with 17 significant digits each, e.g.
    /// `3.1415926535897931e0 + 1.2246467991473532e-16`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{:.16e} + {:.16e}", self.hi, self.lo)
    }
}
