//! A rigid link: points fixed on it, and the rigid-body relations every
//! primitive uses for rates.
//!
//! A link carries an *axis*: a unit vector fixed to the link (for a crank, from
//! its pivot to its tip; for a group's link, from its known joint to its inner
//! joint). A point on the link is given in the link's local frame: `x` along the
//! axis, `y` along `perp(axis)` (90 degrees counter-clockwise from it).
//!
//! For two points on one link, `P - O = r`: `vP = vO + omega perp(r)` and
//! `aP = aO + alpha perp(r) - omega^2 r`.

use crate::error::{Error, Primitive};
use crate::geometry::{finite_point, finite_vec, perp};
use crate::scalar::Real;
use nalgebra::{Point2, Vector2};

const P: Primitive = Primitive::LinkPoint;

/// Velocity of `P` relative to `O` on a link turning at `omega`, where `r = P - O`:
/// `omega * perp(r)` (L/s).
#[inline(always)]
pub fn relative_velocity<T: Real>(r: &Vector2<T>, omega: T) -> Vector2<T> {
    perp(r) * omega
}

/// Acceleration of `P` relative to `O`: `alpha perp(r) - omega^2 r` (L/s^2).
///
/// Error: a few roundings of each term, plus the floating-point model's
/// absolute term where `omega^2` underflows (`|omega|` below about 1e-19
/// rad/s in f32, 1e-154 in f64): at most `|r|` times the subnormal spacing
/// (f32 `2^-149 |r|`; a 7.6e29 f32 crank at 5e-26 rad/s loses its 2e-21
/// L/s^2 within that 1.1e-15).
#[inline(always)]
pub fn relative_acceleration<T: Real>(r: &Vector2<T>, omega: T, alpha: T) -> Vector2<T> {
    perp(r) * alpha - r * (omega * omega)
}

/// Offset `P - O` of a point given in the link's local frame: `local.x` along
/// the unit `axis`, `local.y` along `perp(axis)` (L).
#[inline(always)]
pub fn local_offset<T: Real>(axis: &Vector2<T>, local: &Vector2<T>) -> Vector2<T> {
    axis * local.x + perp(axis) * local.y
}

/// Position of a point fixed on a link: `origin + local_offset(axis, local)`.
///
/// `axis` must be a unit vector. Errors: `NonFinite` when the result is not finite.
#[inline(always)]
pub fn point_position<T: Real>(
    origin: &Point2<T>,
    axis: &Vector2<T>,
    local: &Vector2<T>,
) -> Result<Point2<T>, Error<T>> {
    finite_point(origin + local_offset(axis, local), P, "link point")
}

/// Velocity of a point relative to the link origin, checked finite (L/s).
#[inline(always)]
pub fn point_velocity<T: Real>(offset: &Vector2<T>, omega: T) -> Result<Vector2<T>, Error<T>> {
    finite_vec(relative_velocity(offset, omega), P, "link point velocity")
}

/// Acceleration of a point relative to the link origin, checked finite (L/s^2).
#[inline(always)]
pub fn point_acceleration<T: Real>(
    offset: &Vector2<T>,
    omega: T,
    alpha: T,
) -> Result<Vector2<T>, Error<T>> {
    finite_vec(
        relative_acceleration(offset, omega, alpha),
        P,
        "link point acceleration",
    )
}

/// `base + relative`, checked finite (L/s or L/s^2): the velocity or
/// acceleration of a point of a moving link from its origin's and the
/// relative one ([`point_velocity`], [`point_acceleration`]), whose sum can
/// overflow where both are finite (f32: a coupler point at 2.9e38 plus
/// 1e38 gave an infinite `Ok`).
///
/// Errors: `NonFinite` when the sum is not finite.
#[inline(always)]
pub fn point_sum<T: Real>(base: &Vector2<T>, relative: Vector2<T>) -> Result<Vector2<T>, Error<T>> {
    finite_vec(base + relative, P, "link point velocity or acceleration")
}
