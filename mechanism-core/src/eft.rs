//! Error-free transformations (Knuth's two-sum, Dekker's product with
//! Veltkamp's split) for the places where one rounding matters: the RRP
//! group's distance from its guide in `f32` near tangency (scalar
//! [`crate::dyad::rrp::position`] and [`crate::__private::lane::rrp`]), and the
//! Cody-Waite reduction of the sine and cosine kernels ([`reduce`]:
//! [`crate::sincos64`], [`crate::__private::lane::sin_cos`]), and the
//! double words ([`Word`]) of the triad's residuals near a branch point
//! ([`crate::triad`]). Branch-free and without
//! fused multiply-add, so they vectorize and run on a Cortex-M4F.

use crate::scalar::{single, Real};

/// Whether the RRP position ([`crate::dyad::rrp::position`], and its lane
/// version [`crate::__private::lane::rrp`]) carries rounding errors: for `f32`
/// (24-bit significand), where without it the f32 six-bar's largest rate
/// error was 7.3e-6 instead of 3.7e-6 (`docs/stability.md`, "f32 six-bar");
/// not for `f64`, whose rounding is `2^29` times finer (the f64 six-bar is
/// within 1.3e-14 without it) and where it would cost about a fifth of a
/// six-bar evaluation. A constant after inlining (no branch at run time).
#[inline(always)]
pub(crate) fn compensated<T: Real>() -> bool {
    single::<T>()
}

/// `(|v|^2 - 1) / 2` for a vector within a few ulp of unit length, with an
/// error far below `eps` (error-free squares; `|v|^2` rounds into `[1/2, 2]`,
/// where subtracting 1 is exact). `v = (x, y)` with both components split.
#[inline(always)]
pub(crate) fn half_excess<T: Real>(x: T, xh: T, xl: T, y: T, yh: T, yl: T) -> T {
    let (xx, ex) = two_product_split(x, x, xh, xl);
    let (yy, ey) = two_product_split(y, y, yh, yl);
    let (ss, es) = two_sum(xx, yy);
    ((ss - T::one()) + (es + ex + ey)) * T::lit(0.5)
}

/// `a + b = s + e` exactly, `s` the rounded sum (Knuth's two-sum: six
/// additions, no branch; exact in binary floating point without overflow).
#[inline(always)]
pub(crate) fn two_sum<T: Real>(a: T, b: T) -> (T, T) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

/// `a b = p + e` exactly, `p` the rounded product, `b = bh + bl` given split
/// (Dekker's product with Veltkamp's split, no fused multiply-add needed: the
/// targets this crate is for, e.g. a Cortex-M4F through libm, have no fast
/// one). Exact unless a factor exceeds about `max / 2^13` (f32: 4e34; the
/// split then overflows and the NaN ends as a `NonFinite` error) or the
/// product underflows.
#[inline(always)]
pub(crate) fn two_product_split<T: Real>(a: T, b: T, bh: T, bl: T) -> (T, T) {
    let p = a * b;
    let (ah, al) = split(a);
    (p, ((ah * bh - p) + ah * bl + al * bh) + al * bl)
}

/// Veltkamp's split `a = hi + lo`, each with at most half the significand's
/// bits (so products of halves are exact): constant `2^ceil(p/2) + 1`, `p` the
/// significand's bits (24 for f32, 53 for f64).
#[inline(always)]
pub(crate) fn split<T: Real>(a: T) -> (T, T) {
    let c = if single::<T>() {
        T::lit(4097.0)
    } else {
        T::lit(134_217_729.0)
    } * a;
    let hi = c - (c - a);
    (hi, a - hi)
}

/// `a b = p + e` exactly ([`two_product_split`] with `b` split here).
#[inline(always)]
pub(crate) fn two_product<T: Real>(a: T, b: T) -> (T, T) {
    let (bh, bl) = split(b);
    two_product_split(a, b, bh, bl)
}

/// A double word: the unevaluated sum `hi + lo` with `|lo|` at most about
/// half an ulp of `hi`, about twice the significand's bits. The operations
/// are the "sloppy" ones of the double-double literature (Dekker 1971;
/// Joldes, Muller and Popescu, "Tight and rigorous error bounds for basic
/// building blocks of double-word arithmetic", ACM TOMS 44, 2017): a sum's
/// error is within a few `eps^2` of `|a| + |b|` (not of the result: no
/// accuracy is claimed for a cancelling sum beyond that), a product's within
/// a few `eps^2` of itself. Used where a residual must be evaluated beyond
/// the working precision ([`crate::triad`]'s polish near a branch point);
/// only with `f32` and `f64` (Veltkamp's split of a dual number's
/// derivatives is not exact).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Word<T: Real> {
    pub(crate) hi: T,
    pub(crate) lo: T,
}

impl<T: Real> Word<T> {
    /// `x` exactly.
    #[inline(always)]
    pub(crate) fn of(x: T) -> Self {
        Word {
            hi: x,
            lo: T::zero(),
        }
    }

    /// `hi + lo` renormalized (two-sum: no assumption on their sizes).
    #[inline(always)]
    pub(crate) fn new(hi: T, lo: T) -> Self {
        let (hi, lo) = two_sum(hi, lo);
        Word { hi, lo }
    }

    /// `self + o`.
    #[inline(always)]
    pub(crate) fn add(self, o: Self) -> Self {
        let (s, e) = two_sum(self.hi, o.hi);
        Word::new(s, e + (self.lo + o.lo))
    }

    /// `self - o`.
    #[inline(always)]
    pub(crate) fn sub(self, o: Self) -> Self {
        self.add(Word {
            hi: -o.hi,
            lo: -o.lo,
        })
    }

    /// `self b` for a working-precision `b`.
    #[inline(always)]
    pub(crate) fn scale(self, b: T) -> Self {
        let (p, e) = two_product(self.hi, b);
        Word::new(p, e + self.lo * b)
    }

    /// `self^2`.
    #[inline(always)]
    pub(crate) fn square(self) -> Self {
        let (p, e) = two_product(self.hi, self.hi);
        Word::new(p, e + T::lit(2.0) * self.hi * self.lo)
    }

    /// The value rounded to the working precision.
    #[inline(always)]
    pub(crate) fn value(self) -> T {
        self.hi + self.lo
    }
}

/// `x - k (p1 + p2 + p3)` as an unevaluated sum `r + rt` (`|rt|` at most
/// about `ulp(r) / 2`: the two-sum's error plus `k p3`), for `k` an integer
/// with `k p1` and `k p2` exact (`p1`, `p2` with at most `53 - b`
/// significant bits for `|k| < 2^b`) and `x - k p1` exact (Sterbenz: `x` and
/// `k p1` within a factor of 2, or `k = 0`): the difference with `k p2` is
/// split exactly (two-sum) and `k p3` subtracted from its error term, so the
/// reduced argument is good to about `2^-100` relative whatever the
/// cancellation. Cody and Waite's scheme with Dekker's correction.
///
/// `r` is the rounded difference itself, not renormalized with `rt`: the
/// polynomials start from it while the two-sum's error is still being
/// computed beside them (`rt` only enters their last additions), which takes
/// seven dependent operations off the sine and cosine's critical path.
#[inline(always)]
pub(crate) fn reduce(x: f64, k: f64, p1: f64, p2: f64, p3: f64) -> (f64, f64) {
    let t = x - k * p1;
    let w = k * p2;
    let hi = t - w;
    let v = hi - t;
    let err = (t - (hi - v)) + (-w - v);
    (hi, err - k * p3)
}

/// `pi/2 = P1 + P2 + P3` for the argument reductions of `lane::sin_cos` and
/// [`crate::sincos64`]: `P1`, `P2` have 33 significant bits, so `k P1` and
/// `k P2` are exact for `|k| < 2^20`; `P3` is the rest, rounded.
pub(crate) const P1: f64 = 1.570_796_326_734_125_6; // 0x1.921fb544p+0, 33 bits
pub(crate) const P2: f64 = 6.077_100_506_303_966e-11; // 0x1.0b4611a6p-34, 33 bits
pub(crate) const P3: f64 = 2.022_266_248_795_950_6e-21; // the rest, rounded
