//! Crank driver: a link of length `r` turning about a known pivot `O`; its angle
//! `theta` (rad, from +x, counter-clockwise), speed `omega` (rad/s) and angular
//! acceleration `alpha` (rad/s^2) are the inputs. The tip is `A = O + r (cos, sin)`.
//!
//! The crank's axis is the unit vector from `O` to `A`. When the caller already
//! has `(cos theta, sin theta)` (an encoder often does), [`position_cos_sin`]
//! skips the trigonometry.

use crate::error::{Error, Fault, Primitive};
use crate::geometry::{
    abs, all_finite, angle_limit, dot, finite_vec, max, plain_square, plus, positive,
};
use crate::link::{relative_acceleration, relative_velocity};
use crate::scalar::Real;
use nalgebra::{Point2, Vector2};

const P: Primitive = Primitive::Crank;

/// Crank at a given angle.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct CrankPosition<T: Real> {
    /// The tip `A` (L).
    pub tip: Point2<T>,
    /// `A - O` (L): the crank as a vector.
    pub r: Vector2<T>,
    /// Unit axis of the crank, `(cos theta, sin theta)`.
    pub axis: Vector2<T>,
}

/// Places the crank at `theta` (rad), `|theta|` below
/// [`angle_limit`](crate::geometry::angle_limit) (f32 1.7e7, f64 9.0e15:
/// beyond, the spacing of the type's numbers is 2 rad or more, so the input
/// no longer says where the crank is, and its link angle could not be
/// reported consistently).
///
/// Errors: `NonPositive` for `length <= 0`; `NonFinite` for a non-finite angle
/// or pivot, or an angle beyond the limit.
#[inline(always)]
pub fn position<T: Real>(
    pivot: &Point2<T>,
    length: T,
    theta: T,
) -> Result<CrankPosition<T>, Error<T>> {
    // In the scalar's own precision (f32 stays f32: see `crate::trig`). A
    // non-finite angle (NaN fails the comparison too) or one beyond the
    // limit fails `place`'s one test.
    let (sin, cos) = theta.sin_cos_kernel();
    place(
        pivot,
        length,
        Vector2::new(cos, sin),
        abs(theta) < angle_limit::<T>(),
    )
}

/// A crank angle given by its cosine and sine (as an encoder or a resolver
/// delivers it), for the generated `position_cos_sin` of a definition that
/// writes `crank(O, r, INPUT as cos_sin)`. The pair need not be exactly unit:
/// [`position_cos_sin`] normalizes it.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct CosSin<T> {
    /// `cos theta` (any positive multiple of it, together with `sin`).
    pub cos: T,
    /// `sin theta`.
    pub sin: T,
}

/// Places the crank from `(cos theta, sin theta)`, which need not be exactly
/// unit: it is normalized (an encoder's pair rarely is). Any positive
/// multiple of the pair gives the same crank, to rounding, for every finite
/// pair that is not zero, subnormal ones included (the pair is scaled by a
/// power of two before it is squared where its square would leave the normal
/// range).
///
/// Errors: `NonFinite`; `NonPositive` for `length <= 0` or a zero pair.
#[inline(always)]
pub fn position_cos_sin<T: Real>(
    pivot: &Point2<T>,
    length: T,
    cos: T,
    sin: T,
) -> Result<CrankPosition<T>, Error<T>> {
    let v = finite_vec(Vector2::new(cos, sin), P, "crank (cos, sin)")?;
    // `|v|^2` plainly where it is a normal number with room below (the
    // usual encoder pair, of size about 1); a pair far from unit size (f64
    // components below about 1e-138 or above 1e154, f32 1e-12 .. 1e19)
    // would give a subnormal, zero or infinite square: scaled first.
    let q = dot(&v, &v);
    let (v, norm) = if plain_square(q) {
        (v, q.sqrt_kernel())
    } else {
        scaled_pair(v)
    };
    let norm = positive(norm, P, "crank |(cos, sin)|")?;
    place(pivot, length, v / norm, true)
}

/// A crank carried by a moving link (a motor or an encoder between two
/// links: an elbow, a knee): its axis is the carrier's unit axis `carrier`
/// turned by `theta` (rad, counter-clockwise, the relative angle; `0` lays
/// the crank along the carrier's axis). The pivot is a point of the carrier.
/// Same limits and errors as [`position`]; a carrier axis that is not
/// finite makes the tip non-finite (`NonFinite`).
#[inline(always)]
pub fn position_on<T: Real>(
    pivot: &Point2<T>,
    length: T,
    carrier: &Vector2<T>,
    theta: T,
) -> Result<CrankPosition<T>, Error<T>> {
    let (sin, cos) = theta.sin_cos_kernel();
    place(
        pivot,
        length,
        turned(carrier, cos, sin),
        abs(theta) < angle_limit::<T>(),
    )
}

/// [`position_on`] with the relative angle given by its cosine and sine
/// (normalized as in [`position_cos_sin`]). Errors as there.
#[inline(always)]
pub fn position_cos_sin_on<T: Real>(
    pivot: &Point2<T>,
    length: T,
    carrier: &Vector2<T>,
    cos: T,
    sin: T,
) -> Result<CrankPosition<T>, Error<T>> {
    let own = position_cos_sin(&Point2::origin(), T::one(), cos, sin)?.axis;
    place(pivot, length, turned(carrier, own.x, own.y), true)
}

/// `u` turned counter-clockwise by the angle whose cosine and sine are
/// `(c, s)`: `(c ux - s uy, s ux + c uy)`.
#[inline(always)]
fn turned<T: Real>(u: &Vector2<T>, c: T, s: T) -> Vector2<T> {
    Vector2::new(c * u.x - s * u.y, s * u.x + c * u.y)
}

/// `(v / m, |v / m|)` with `m` the larger component's magnitude: the pair
/// brought to a size between 1 and `sqrt 2` (each division within half an
/// ulp), so its square neither underflows nor overflows; `(v, 0)` for a
/// zero pair (cold path of [`position_cos_sin`]).
#[cold]
#[inline(never)]
fn scaled_pair<T: Real>(v: Vector2<T>) -> (Vector2<T>, T) {
    let m = max(abs(v.x), abs(v.y));
    if m > T::zero() {
        let u = v / m;
        (u, dot(&u, &u).sqrt_kernel())
    } else {
        (v, T::zero())
    }
}

/// The crank at unit `axis`: three comparisons on the ordinary path (the
/// angle below its limit, a positive length, a finite tip); a non-finite
/// angle, length or pivot makes the tip non-finite and is told apart on the
/// cold path. `angle_ok`: the angle is finite and below
/// [`angle_limit`](crate::geometry::angle_limit) (`true` for a `(cos, sin)`
/// pair).
#[inline(always)]
fn place<T: Real>(
    pivot: &Point2<T>,
    length: T,
    axis: Vector2<T>,
    angle_ok: bool,
) -> Result<CrankPosition<T>, Error<T>> {
    let r = axis * length;
    let tip = pivot + r;
    if angle_ok && length > T::zero() && all_finite([tip.x, tip.y]) {
        Ok(CrankPosition { tip, r, axis })
    } else {
        Err(bad_placement(length, angle_ok))
    }
}

/// Why [`place`] failed, in the order of the doc comments: the angle, then
/// the length, then the tip (a non-finite pivot or an overflow).
#[cold]
#[inline(never)]
fn bad_placement<T: Real>(length: T, angle_ok: bool) -> Error<T> {
    // One construction of each fault kind (the cold code stays small).
    let length_ok = length.finite() && length > T::zero();
    let what = if !angle_ok {
        "crank angle (not finite, or beyond 2^24 rad in f32, 2^53 in f64)"
    } else if length_ok {
        "crank tip"
    } else {
        "crank length"
    };
    let fault = if angle_ok && length.finite() && !length_ok {
        Fault::NonPositive {
            what,
            value: length,
        }
    } else {
        Fault::NonFinite { what }
    };
    Error::new(P, fault)
}

/// Velocity of the tip (L/s): `v_pivot + omega perp(r)`; `v_pivot = None`
/// for a crank on the ground.
///
/// Errors: `NonFinite` for a non-finite `omega` or `v_pivot`, or a result
/// that overflows (one check of the result: `r != 0`, so a non-finite
/// `omega` makes it non-finite).
#[inline(always)]
pub fn velocity<T: Real>(
    pos: &CrankPosition<T>,
    v_pivot: Option<&Vector2<T>>,
    omega: T,
) -> Result<Vector2<T>, Error<T>> {
    let v = plus(v_pivot, relative_velocity(&pos.r, omega));
    checked(v, omega.finite(), "crank speed", "crank tip velocity")
}

/// Acceleration of the tip (L/s^2): `a_pivot + alpha perp(r) - omega^2 r`.
///
/// Errors: `NonFinite`, as for [`velocity`].
#[inline(always)]
pub fn acceleration<T: Real>(
    pos: &CrankPosition<T>,
    a_pivot: Option<&Vector2<T>>,
    omega: T,
    alpha: T,
) -> Result<Vector2<T>, Error<T>> {
    let a = plus(a_pivot, relative_acceleration(&pos.r, omega, alpha));
    checked(
        a,
        omega.finite() && alpha.finite(),
        "crank speed or angular acceleration",
        "crank tip acceleration",
    )
}

/// `Ok(v)` when `v` is finite; otherwise `NonFinite` naming the input
/// (`inputs_finite` is evaluated on this error path only) or the result.
#[inline(always)]
fn checked<T: Real>(
    v: Vector2<T>,
    inputs_finite: bool,
    input: &'static str,
    result: &'static str,
) -> Result<Vector2<T>, Error<T>> {
    if all_finite([v.x, v.y]) {
        Ok(v)
    } else {
        let what = if inputs_finite { result } else { input };
        Err(Error::new(P, Fault::NonFinite { what }))
    }
}
