//! Small planar vector helpers used by every primitive (no trigonometry).
//!
//! Sign conventions: angles and angular rates are counter-clockwise positive;
//! `perp(v)` is `v` turned +90 degrees, so the velocity of a point at offset `r`
//! on a link turning at `omega` is `omega * perp(r)`.

use crate::error::{Error, Fault, Primitive};
use crate::scalar::Real;
use nalgebra::{Point2, Vector2};

/// `v` rotated by +90 degrees: `(-v.y, v.x)`.
#[inline(always)]
pub fn perp<T: Real>(v: &Vector2<T>) -> Vector2<T> {
    Vector2::new(-v.y, v.x)
}

/// The z component of the planar cross product `a x b` (positive when `b` is
/// counter-clockwise from `a`).
#[inline(always)]
pub fn cross<T: Real>(a: &Vector2<T>, b: &Vector2<T>) -> T {
    a.x * b.y - a.y * b.x
}

/// Dot product.
#[inline(always)]
pub fn dot<T: Real>(a: &Vector2<T>, b: &Vector2<T>) -> T {
    a.x * b.x + a.y * b.y
}

pub use crate::scalar::abs;

/// The smaller of `a` and `b` (`b` when either is NaN). A comparison, where
/// `RealField::min` calls libm's `fminf`/`fmin` (about 24 instructions on a
/// Cortex-M4F against 3); callers use it on values that are checked finite
/// or whose NaN is caught by a later check.
#[inline(always)]
pub fn min<T: Real>(a: T, b: T) -> T {
    if a < b {
        a
    } else {
        b
    }
}

/// The larger of `a` and `b` (`b` when either is NaN), by a comparison as
/// [`min`].
#[inline(always)]
pub fn max<T: Real>(a: T, b: T) -> T {
    if a > b {
        a
    } else {
        b
    }
}

/// Euclidean length, scaled so that it neither overflows nor underflows for
/// components between about 1e-150 and 1e150 (f64).
#[inline(always)]
pub fn length<T: Real>(v: &Vector2<T>) -> T {
    (v.x * v.x + v.y * v.y).sqrt_kernel()
}

/// Angle of `v` from +x, counter-clockwise, in radians in `(-pi, pi]`.
///
/// Through [`Real::angle_kernel`]: `v.y + 0` turns a negative zero into `+0` (IEEE 754: `-0 + 0 = +0` when
/// rounding to nearest), so a vector along `-x` gives `pi` whatever the sign
/// of its zero `y`: `atan2(-0, -1)` is `-pi`, outside the range.
///
/// A vector just below `-x` (`y` a tiny negative number, `x < 0`) has an
/// exact angle above `-pi` by less than half an ulp of `pi`; it rounds to
/// `-pi` of `T` (an f32 shaper's rod gave `-3.1415927`): that is the same
/// direction as `pi`, so `-pi` is returned as `pi`.
#[inline(always)]
pub fn angle<T: Real>(v: &Vector2<T>) -> T {
    v.y.angle_kernel(v.x)
}

/// Largest `|angle|` (rad) at which an input angle still means one: `2^24`
/// (1.7e7) for `f32`, `2^53` (9.0e15) for `f64`, where the spacing of the
/// type's numbers reaches 2 rad (one ulp of the input turns a crank by a
/// third of a turn). [`crate::driver::crank::position`] reports a larger
/// angle as an error; [`wrap_angle`] is accurate to `|angle| eps` below it.
#[inline(always)]
pub fn angle_limit<T: Real>() -> T {
    if crate::scalar::single::<T>() {
        T::lit(16_777_216.0)
    } else {
        T::lit(9_007_199_254_740_992.0)
    }
}

/// `angle` (rad) reduced to `(-pi, pi]`, for every finite `angle`: a
/// crank's link angle is its input reduced this way.
///
/// - `|angle| <= pi`: unchanged (exact).
/// - `pi < |angle| < angle_limit` (f32 1.7e7, f64 9.0e15): `angle - 2 pi
///   k` with `k` the nearest integer to `angle / 2 pi`, moved into the
///   range if rounding left it just outside; the error is the rounding of
///   `2 pi k`, about `|angle| eps` (f64 at 1e5: 2e-11 rad; f32 at 1e3:
///   1e-4 rad), below 1.5 rad at the limit, so one move suffices.
/// - beyond ([`angle_limit`], where the input's own spacing is 2 rad or
///   more: the crank reports such an angle as an error) the reduction is
///   repeated until the result is in the range: in the range, but not the
///   angle of `(cos angle, sin angle)` (the one-step reduction of f32
///   2.2e8 gave -9.7, outside the range).
///
/// NaN or an infinity gives NaN.
#[inline]
pub fn wrap_angle<T: Real>(angle: T) -> T {
    let pi = T::pi();
    if angle <= pi && angle > -pi {
        return angle;
    }
    let reduced = reduce_turns(angle);
    if reduced > pi || reduced <= -pi {
        // Only beyond the limit (NaN compares false and is returned).
        return wrap_far(reduced);
    }
    reduced
}

/// [`wrap_angle`] beyond [`angle_limit`] (cold path): the reduction
/// repeated while the result is outside the range (each pass divides the
/// magnitude by about `1 / eps`; an infinity gives NaN at once).
#[cold]
#[inline(never)]
fn wrap_far<T: Real>(mut reduced: T) -> T {
    let pi = T::pi();
    while reduced.finite() && (reduced > pi || reduced <= -pi) {
        reduced = reduce_turns(reduced);
    }
    reduced
}

/// `angle - 2 pi round(angle / 2 pi)`, moved by `2 pi` when rounding left
/// it just outside `(-pi, pi]`.
#[inline]
fn reduce_turns<T: Real>(angle: T) -> T {
    let (pi, two_pi) = (T::pi(), T::two_pi());
    let reduced = angle - two_pi * (angle / two_pi).round();
    if reduced <= -pi {
        reduced + two_pi
    } else if reduced > pi {
        reduced - two_pi
    } else {
        reduced
    }
}

/// Angle of `v` from +x in degrees in `[0, 360)`, the convention of the tables.
#[inline]
pub fn angle_deg_0_360<T: Real>(v: &Vector2<T>) -> T {
    let deg = angle(v) * T::lit(180.0) / T::pi();
    if deg < T::zero() {
        let wrapped = deg + T::lit(360.0);
        // -tiny + 360 rounds to 360: keep the half-open range.
        if wrapped >= T::lit(360.0) {
            T::zero()
        } else {
            wrapped
        }
    } else {
        deg
    }
}

/// The unit vector `(cos angle, sin angle)`, through [`Real::sin_cos_kernel`]
/// (f32 in single precision).
#[inline(always)]
pub fn unit<T: Real>(angle: T) -> Vector2<T> {
    let (s, c) = angle.sin_cos_kernel();
    Vector2::new(c, s)
}

/// The smallest positive normal number of `T` (`f32`: 1.2e-38, `f64`:
/// 2.2e-308) and the largest finite one (3.4e38, 1.8e308): a product in this
/// range carries full relative precision; below it, it is subnormal (bits
/// lost) or zero, above it infinite. Constants, folded at compile time.
#[inline(always)]
pub fn normal_range<T: Real>() -> (T, T) {
    if crate::scalar::single::<T>() {
        (T::lit(f32::MIN_POSITIVE as f64), T::lit(f32::MAX as f64))
    } else {
        (T::lit(f64::MIN_POSITIVE), T::lit(f64::MAX))
    }
}

/// Whether every value of `xs` is finite: the one test each primitive makes
/// of its results on the ordinary path (a non-finite input reaches them).
///
/// `is_finite` on each value: it compiles to integer operations on the bits,
/// which run beside the floating-point work. A float-only form (the sum of
/// `x * 0` is zero exactly when every `x` is finite) executes fewer
/// instructions but competes for the floating-point units: on the x86-64
/// development machine it made the four-bar's solve 5 to 9 % slower.
///
/// Except for `f32` on 32-bit ARM with a hardware floating-point ABI
/// (Cortex-M4F and the like): there the float-only form is taken, one
/// multiply-add per value and one comparison (the integer form moves each
/// value to a core register and tests its bits, five instructions): on the
/// four-bar's full solve it saves about 70 instructions per evaluation and
/// 12 bytes of code (`docs/embedded.md` section 4). Not for `f64` there, nor on an
/// FPU-less core, where each multiply would be a software routine.
#[inline(always)]
pub fn all_finite<T: Real, const N: usize>(xs: [T; N]) -> bool {
    #[cfg(all(target_arch = "arm", target_abi = "eabihf"))]
    if crate::scalar::single::<T>() {
        // `x * 0` is a zero for finite `x` and NaN for an infinity or NaN;
        // a sum of zeros is a zero, and NaN compares unequal to it.
        let zero = T::zero();
        return xs.iter().fold(zero, |acc, &x| acc + x * zero) == zero;
    }
    xs.iter().all(|x| x.finite())
}

/// Returns `Err(NonFinite)` unless `x` is finite.
#[inline(always)]
pub fn finite<T: Real>(x: T, primitive: Primitive, what: &'static str) -> Result<T, Error<T>> {
    if x.finite() {
        Ok(x)
    } else {
        Err(Error::new(primitive, Fault::NonFinite { what }))
    }
}

/// Returns `Err(NonFinite)` unless both components are finite.
#[inline(always)]
pub fn finite_vec<T: Real>(
    v: Vector2<T>,
    primitive: Primitive,
    what: &'static str,
) -> Result<Vector2<T>, Error<T>> {
    if v.x.finite() && v.y.finite() {
        Ok(v)
    } else {
        Err(Error::new(primitive, Fault::NonFinite { what }))
    }
}

/// Returns `Err(NonFinite)` unless both coordinates are finite.
#[inline(always)]
pub fn finite_point<T: Real>(
    p: Point2<T>,
    primitive: Primitive,
    what: &'static str,
) -> Result<Point2<T>, Error<T>> {
    finite_vec(p.coords, primitive, what).map(Point2::from)
}

/// Returns `Err(NonPositive)` unless `x` is finite and `> 0`.
#[inline(always)]
pub fn positive<T: Real>(x: T, primitive: Primitive, what: &'static str) -> Result<T, Error<T>> {
    let x = finite(x, primitive, what)?;
    if x > T::zero() {
        Ok(x)
    } else {
        Err(Error::new(primitive, Fault::NonPositive { what, value: x }))
    }
}

/// Returns `Err(NonFinite)` unless `x` is finite, `Err(Negative)` unless it
/// is `>= 0` (a moment of inertia: zero is a point mass).
#[inline(always)]
pub fn non_negative<T: Real>(
    x: T,
    primitive: Primitive,
    what: &'static str,
) -> Result<T, Error<T>> {
    let x = finite(x, primitive, what)?;
    if x >= T::zero() {
        Ok(x)
    } else {
        Err(Error::new(primitive, Fault::Negative { what, value: x }))
    }
}

/// Relative threshold below which a 2x2 rate system counts as singular:
/// `|det| <= SINGULAR_RELATIVE * eps * scale`, where `scale` is the product of
/// the lengths of the determinant's columns. At that level the rates' relative
/// error bound (about `eps / (|det| / scale)`) is already 1/16: nothing useful
/// remains, so a typed error is more honest than a number.
pub const SINGULAR_RELATIVE: f64 = 16.0;

/// Checks a determinant against its scale; `Err(Singular)` when
/// `|det| <= SINGULAR_RELATIVE * eps * scale`, `|det|` is below the normal
/// range of `T` (subnormal or zero), `scale <= 0`, or either is not finite.
#[inline(always)]
pub fn check_det<T: Real>(det: T, scale: T, primitive: Primitive) -> Result<T, Error<T>> {
    let threshold = T::lit(SINGULAR_RELATIVE) * T::eps() * scale;
    // `scale > 0` too: a scale that underflowed to zero (columns shorter than
    // about 1e-154 in f64) would otherwise pass any nonzero `det` and give an
    // infinite condition.
    // `abs(det) > threshold` is false for a NaN `det` or a NaN or infinite
    // `scale`; an infinite `det` with a finite scale is left to `all_finite`.
    // A subnormal `det` (a second power of f32 lengths below about 1e-19)
    // has lost bits and its reciprocal may overflow: `Singular` too, as a
    // number the rates cannot be resolved from.
    if abs(det) > threshold
        && abs(det) >= normal_range::<T>().0
        && scale > T::zero()
        && all_finite([det])
    {
        Ok(det)
    } else {
        Err(Error::new(primitive, Fault::Singular { det, scale }))
    }
}

/// Checks a determinant like [`check_det`] and also returns the rate system's
/// condition indicator `|det| / scale`: `(det, condition)`.
///
/// The indicator is the determinant relative to the product of its columns'
/// lengths (Hadamard's bound), so it lies in `(16 eps, 1]` whenever the check
/// passes: `1` when the columns are orthogonal (the best-conditioned pose), and
/// it falls to `0` at a singular pose (toggle, dead centre, parallel guides).
/// For the RRR group it is `|sin|` of the angle between the two links (for a
/// four-bar, the sine of the transmission angle). The rates' relative error is
/// bounded by about `eps / condition` (see `docs/stability.md`), so a user can
/// watch it fall as a singular pose approaches.
#[inline(always)]
pub fn check_det_condition<T: Real>(
    det: T,
    scale: T,
    primitive: Primitive,
) -> Result<(T, T), Error<T>> {
    let det = check_det(det, scale, primitive)?;
    // The check passed, so `scale` is finite and > 0. Rounding can push the
    // ratio a few ulp above Hadamard's bound 1: clamp, so the range holds.
    let condition = abs(det) / scale;
    Ok((
        det,
        if condition > T::one() {
            T::one()
        } else {
            condition
        },
    ))
}

/// `x - y` where `None` stands for a zero vector (a fixed point): with a
/// constant `None`, the missing terms vanish at compile time.
#[inline(always)]
pub fn difference<T: Real>(x: Option<&Vector2<T>>, y: Option<&Vector2<T>>) -> Vector2<T> {
    match (x, y) {
        (Some(x), Some(y)) => x - y,
        (Some(x), None) => *x,
        (None, Some(y)) => -y,
        (None, None) => Vector2::zeros(),
    }
}

/// `x + v` where `None` stands for a zero `x` (a fixed point).
#[inline(always)]
pub fn plus<T: Real>(x: Option<&Vector2<T>>, v: Vector2<T>) -> Vector2<T> {
    match x {
        Some(x) => x + v,
        None => v,
    }
}

/// `sqrt(gap sum)` (L) for `0 <= gap <= l <= sum <= 2 l`, the half chord of
/// the RRP's and RPR's `position`: the product is a second power of the
/// lengths, so outside the normal range of `T` (f32 lengths below about
/// 1e-19, or nearer tangency at larger ones, or above about 1e19; f64 beyond
/// about 1e-154 .. 1e154) it would be subnormal (bits silently lost), zero
/// or infinite; there [`scaled_root`] (cold) forms it from factors scaled
/// exactly by a power of two. Zero (`gap = 0`, tangency) takes that path
/// too and gives 0.
#[inline(always)]
pub(crate) fn root_of_product<T: Real>(gap: T, sum: T, l: T) -> T {
    let prod = gap * sum;
    let (lo, hi) = normal_range::<T>();
    if prod >= lo && prod <= hi {
        prod.sqrt_kernel()
    } else {
        scaled_root(gap, sum, l)
    }
}

/// [`root_of_product`] for a product outside the normal range: both factors (`0 <= gap <= l <= sum <=
/// 2 l`) scaled by `2^-e`, `2^e <= l < 2^(e+1)`, so the product lies in
/// `[0, 8)`, and the
/// root scaled back by `2^e`. Every scaling is exact (powers of two, no
/// result subnormal but a `gap` below `eps l`, which is 0 or the rounding
/// band anyway), so the root is the one an unscaled product in range gives.
#[cold]
#[inline(never)]
pub(crate) fn scaled_root<T: Real>(gap: T, sum: T, l: T) -> T {
    let (down, up) = pow2_scale(l);
    ((gap * down) * (sum * down)).sqrt_kernel() * up
}

/// `(2^-e, 2^e)` for `2^e <= x < 2^(e+1)`, `x > 0` finite, with `e` kept
/// within `T`'s normal exponents (`f32`: -126 ..= 126, `f64`: -1022 ..=
/// 1022) so both are normal numbers of `T`. For `f64` (and the dual
/// numbers over it) read off the exponent bits ([`pow2_scale_bits`]); for
/// `f32` by [`pow2_scale_steps`], in `f32` arithmetic: no `f64` on a
/// single-precision FPU (a conversion there is a software routine). The
/// two give the same powers (tested).
#[inline(always)]
pub(crate) fn pow2_scale<T: Real>(x: T) -> (T, T) {
    if crate::scalar::single::<T>() {
        pow2_scale_steps(x)
    } else {
        pow2_scale_bits(x)
    }
}

/// [`pow2_scale`] from the bits of `x` as an `f64`: `e` is the exponent
/// field less the bias, clamped to -1022 ..= 1022 (a subnormal, zero or
/// negative `x` gives -1022, an infinite one 1022, NaN 0: what the steps
/// give), and the powers are built from their bits. A few integer
/// operations where the steps take a loop of compares.
#[inline(always)]
fn pow2_scale_bits<T: Real>(x: T) -> (T, T) {
    let v = x.as_f64();
    let e = if v.is_nan() {
        0
    } else if v > 0.0 {
        ((v.to_bits() >> 52) & 0x7ff) as i64 - 1023
    } else {
        -1022
    };
    let e = e.clamp(-1022, 1022);
    // 2^k for k in -1022 ..= 1022: a normal f64 with exponent field k + 1023.
    let pow = |k: i64| f64::from_bits(((1023 + k) as u64) << 52);
    (T::lit(pow(-e)), T::lit(pow(e)))
}

/// [`pow2_scale`] in `T`'s own arithmetic, by exact steps of `2^256`,
/// `2^64`, `2^16`, `2^4` and `2`, a few of each: no logarithm, no libm.
#[inline(never)]
pub(crate) fn pow2_scale_steps<T: Real>(x: T) -> (T, T) {
    let single = crate::scalar::single::<T>();
    let max = if single { 126 } else { 1022 };
    let (mut m, mut e) = (x, 0i32);
    let (mut down, mut up) = (T::one(), T::one());
    // One step size: `big = 2^s`, `small = 2^-s` (literals, so no
    // conversion is left at run time).
    let mut step = |s: i32, big: T, small: T| {
        while m >= big && e + s <= max {
            m *= small;
            e += s;
            down *= small;
            up *= big;
        }
        while m * big < T::lit(2.0) && e - s >= -max {
            m *= big;
            e -= s;
            down *= big;
            up *= small;
        }
    };
    if !single {
        step(
            256,
            T::lit(1.157_920_892_373_162e77),
            T::lit(8.636_168_555_094_445e-78),
        );
    }
    step(
        64,
        T::lit(18_446_744_073_709_551_616.0),
        T::lit(5.421_010_862_427_522e-20),
    );
    step(16, T::lit(65_536.0), T::lit(1.525_878_906_25e-5));
    step(4, T::lit(16.0), T::lit(0.0625));
    step(1, T::lit(2.0), T::lit(0.5));
    (down, up)
}

/// Whether `q = |r|^2` gives `|r|` plainly as `sqrt(q)`: `q` at least
/// `min_normal / eps^2` and finite (f32 lengths about 1e-12 .. 1e19, f64
/// 1e-138 .. 1e154). Outside, [`scaled_length`] (cold) scales the
/// components by a power of two first. The lower threshold leaves room for
/// a square that is subnormal beside a larger one: below half an ulp of
/// the sum, it changes nothing, so the result is bit for bit the scaled
/// one's (what makes a group's outputs scale exactly with powers of two).
#[inline(always)]
pub(crate) fn plain_square<T: Real>(q: T) -> bool {
    let (lo, hi) = normal_range::<T>();
    q >= lo / (T::eps() * T::eps()) && q <= hi
}

/// `|r|` (L) with the components scaled exactly by the power of two below
/// the larger one first: for a square outside [`plain_square`]'s range (cold
/// path). 0 for a zero vector, NaN for a non-finite one.
#[cold]
#[inline(never)]
pub(crate) fn scaled_length<T: Real>(r: &Vector2<T>) -> T {
    let m = max(abs(r.x), abs(r.y));
    if !(m > T::zero() && m.finite()) {
        // 0 for a zero vector; NaN or infinity as the plain form gives.
        return (r.x * r.x + r.y * r.y).sqrt_kernel();
    }
    let (down, up) = pow2_scale(m);
    length(&(r * down)) * up
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Proves the `f64` powers read off the exponent bits are those of the
    /// exact steps, bit for bit, at every power of two in range and one ulp
    /// on either side, at scattered values between, at the ends (subnormal,
    /// largest finite, clamped exponents) and for the inputs outside the
    /// contract (zero, negative, infinite, NaN), so the frames scaled by
    /// them are unchanged.
    #[test]
    fn pow2_scale_bits_match_the_steps() {
        let check = |x: f64| {
            let (d, u) = pow2_scale_bits(x);
            let (ds, us) = pow2_scale_steps(x);
            assert_eq!(
                (d.to_bits(), u.to_bits()),
                (ds.to_bits(), us.to_bits()),
                "{x:e}"
            );
        };
        for k in -1074..=1023 {
            // 2^k from its bits (subnormal below -1022).
            let p = if k >= -1022 {
                f64::from_bits(((1023 + k) as u64) << 52)
            } else {
                f64::from_bits(1u64 << (k + 1074))
            };
            let bits = p.to_bits();
            for x in [p, f64::from_bits(bits + 1), f64::from_bits(bits - 1)] {
                check(x);
                check(3.3 * x);
            }
        }
        let specials = [
            0.0,
            -0.0,
            -1.5,
            f64::MIN_POSITIVE,
            f64::MAX,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NAN,
            0.28,
            1e-300,
            7.5e306,
        ];
        for x in specials {
            check(x);
        }
    }

    /// A vector along `-x` is at `pi`, the top of `(-pi, pi]`, whichever
    /// sign its zero `y` has (a rounded difference gives `-0` as readily as
    /// `+0`); in f64 and f32, through the kernels the generated code calls.
    #[test]
    fn angle_along_minus_x_is_pi() {
        for y in [0.0f64, -0.0] {
            assert_eq!(angle(&Vector2::new(-2.5f64, y)), core::f64::consts::PI);
            assert_eq!(
                angle(&Vector2::new(-2.5f32, y as f32)),
                core::f32::consts::PI
            );
        }
        // Elsewhere the sign of a zero component is kept: -0 along +x stays
        // 0 (its sign aside), and a negative y gives a negative angle where
        // that angle is above `-pi` of the type.
        assert_eq!(angle(&Vector2::new(1.0f64, -0.0)), 0.0);
        assert!(angle(&Vector2::new(-1.0f64, -1e-10)) < 0.0);
        assert!(angle(&Vector2::new(-1.0f32, -1e-3)) < 0.0);
    }

    /// A vector just below `-x`, whose exact angle `-pi + |y|` rounds to
    /// `-pi` of the type, is at `pi` (the same direction, inside `(-pi,
    /// pi]`): f32 `(-1, -1e-10)` gave `-3.1415927` through an f32 shaper's
    /// rod (found by the run-time fuzzer), f64 `(-1, -1e-300)` gave
    /// `-3.141592653589793`.
    #[test]
    fn angle_just_below_minus_x_is_pi() {
        assert_eq!(angle(&Vector2::new(-1.0f32, -1e-10)), core::f32::consts::PI);
        assert_eq!(
            angle(&Vector2::new(-1.0f64, -1e-300)),
            core::f64::consts::PI
        );
        assert_eq!(
            crate::__private::lane::angle(-1e-10f32, -1.0),
            core::f32::consts::PI
        );
        assert_eq!(
            crate::__private::lane::angle(-1e-300f64, -1.0),
            core::f64::consts::PI
        );
        for k in 1..200 {
            let y = -(k as f64) * 1e-9;
            let a = angle(&Vector2::new(-1.0f32, y as f32));
            assert!(
                a > -core::f32::consts::PI && a <= core::f32::consts::PI,
                "{y}: {a}"
            );
        }
    }
}
