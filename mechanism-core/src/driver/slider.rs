//! Slider driver: a block translating along a guide `g`; its displacement `s`
//! (L, along `g.dir` from `g.origin`), speed `s_dot` (L/s) and acceleration
//! `s_ddot` (L/s^2) are the inputs. Its pin is `P = g.at(s, offset)`.
//!
//! ```text
//!              P  (pin, at `offset` to the left of the guide)
//!            +-o-+
//!            |   |  block
//!   o--------+---+------------->  g.dir
//!   g.origin |<-- s -->|
//! ```
//!
//! The guide may be carried by a moving body ([`LineVelocity`],
//! [`LineAcceleration`]; `None` = fixed guide). Then the pin moves with the
//! body's material point under it plus the slide: `vP = v_body(P) + s_dot dir`,
//! and, since `dir` turns with the body at `omega`,
//! `aP = a_body(P) + 2 omega s_dot perp(dir) + s_ddot dir` (Coriolis term).
//!
//! [`transport_velocity`] and [`transport_acceleration`] are those body terms,
//! shared with the groups that slide on guides (RRP, PRP, RPP).

use crate::error::{Error, Primitive};
use crate::geometry::{finite, finite_point, finite_vec, perp, plus};
use crate::guide::{Line, LineAcceleration, LineVelocity};
use crate::scalar::Real;
use nalgebra::{Point2, Vector2};

const P: Primitive = Primitive::Slider;

/// Slider at a given displacement.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct SliderPosition<T: Real> {
    /// The block's pin `P = g.at(s, offset)` (L).
    pub p: Point2<T>,
}

/// Velocity (L/s) of the material point of the guide's body that is at `p`:
/// `v_origin + omega perp(p - g.origin)`. `None` for a fixed guide, so that the
/// caller's [`crate::geometry::difference`] / [`plus`] fold the term away.
#[inline(always)]
pub fn transport_velocity<T: Real>(
    g: &Line<T>,
    p: &Point2<T>,
    gv: Option<&LineVelocity<T>>,
) -> Option<Vector2<T>> {
    gv.map(|v| v.velocity_at(&g.origin, p))
}

/// Acceleration (L/s^2) that a point at `p` moving with velocity `rel` (L/s)
/// *relative to the guide's body* (measured in that body's frame, expressed in
/// world axes) has apart from its relative acceleration: the body's material
/// acceleration at `p`, `a_origin + alpha perp(r) - omega^2 r` with
/// `r = p - g.origin`, plus the Coriolis term `2 omega perp(rel)`.
///
/// `gv = None` means `omega = 0` and `ga = None` means `a_origin = 0`,
/// `alpha = 0`; both `None` (a fixed guide) gives `None`.
#[inline(always)]
pub fn transport_acceleration<T: Real>(
    g: &Line<T>,
    p: &Point2<T>,
    gv: Option<&LineVelocity<T>>,
    ga: Option<&LineAcceleration<T>>,
    rel: &Vector2<T>,
) -> Option<Vector2<T>> {
    match (gv, ga) {
        (None, None) => None,
        (Some(v), None) => {
            let r = p - g.origin;
            Some(perp(rel) * (T::lit(2.0) * v.omega) - r * (v.omega * v.omega))
        }
        (None, Some(a)) => Some(a.a_origin + perp(&(p - g.origin)) * a.alpha),
        (Some(v), Some(a)) => {
            Some(a.acceleration_at(&g.origin, p, v.omega) + perp(rel) * (T::lit(2.0) * v.omega))
        }
    }
}

/// Places the block's pin at displacement `s` (L) along `g` and signed offset
/// `offset` (L, left of `g.dir` positive): `P = g.origin + s dir + offset perp(dir)`.
/// `g.dir` must be a unit vector.
///
/// Errors: `NonFinite` for a non-finite input or result.
#[inline(always)]
pub fn position<T: Real>(g: &Line<T>, offset: T, s: T) -> Result<SliderPosition<T>, Error<T>> {
    let s = finite(s, P, "slider displacement")?;
    let offset = finite(offset, P, "slider pin offset")?;
    let p = finite_point(g.at(s, offset), P, "slider pin")?;
    Ok(SliderPosition { p })
}

/// Velocity of the pin (L/s): `v_body(P) + s_dot dir` (`gv = None`: fixed guide,
/// then simply `s_dot dir`). `s` is only checked (the pin's place is `pos.p`).
///
/// Errors: `NonFinite` for a non-finite input or result.
#[inline(always)]
pub fn velocity<T: Real>(
    pos: &SliderPosition<T>,
    g: &Line<T>,
    s: T,
    s_dot: T,
    gv: Option<&LineVelocity<T>>,
) -> Result<Vector2<T>, Error<T>> {
    finite(s, P, "slider displacement")?;
    let s_dot = finite(s_dot, P, "slider speed")?;
    let vm = transport_velocity(g, &pos.p, gv);
    finite_vec(plus(vm.as_ref(), g.dir * s_dot), P, "slider pin velocity")
}

/// Acceleration of the pin (L/s^2):
/// `a_body(P) + 2 omega s_dot perp(dir) + s_ddot dir`, the middle (Coriolis)
/// term from differentiating `s_dot dir` with `dir' = omega perp(dir)`.
/// `gv = None` means the body is not turning at this instant (`omega = 0`,
/// though `ga` may still give it an angular acceleration); `ga = None` means
/// zero body accelerations (`a_origin = 0`, `alpha = 0`).
///
/// Errors: `NonFinite` for a non-finite input or result.
#[inline(always)]
pub fn acceleration<T: Real>(
    pos: &SliderPosition<T>,
    g: &Line<T>,
    s: T,
    s_dot: T,
    s_ddot: T,
    gv: Option<&LineVelocity<T>>,
    ga: Option<&LineAcceleration<T>>,
) -> Result<Vector2<T>, Error<T>> {
    finite(s, P, "slider displacement")?;
    let s_dot = finite(s_dot, P, "slider speed")?;
    let s_ddot = finite(s_ddot, P, "slider acceleration")?;
    let am = transport_acceleration(g, &pos.p, gv, ga, &(g.dir * s_dot));
    finite_vec(
        plus(am.as_ref(), g.dir * s_ddot),
        P,
        "slider pin acceleration",
    )
}
