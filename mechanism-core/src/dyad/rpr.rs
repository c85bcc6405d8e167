//! RPR group: link 2 (the rocker, a slotted arm) turns about the known point
//! `B`; a block (link 1) pinned at the known point `A` slides along it.
//!
//! ```text
//!                    A (block pin)          A = B + s u + offset perp(u)
//!                  [=o=]  block
//!      B o-----------+------------->  u, link 2's axis
//!        |<--- s --->|                Mode::Plus : s > 0 (u from B towards A)
//!                                     Mode::Minus: s < 0 (u away from A)
//! ```
//!
//! The slide line is parallel to link 2's axis `u` at signed distance `offset`
//! from `B` (left of `u` positive). With `offset = 0` the two modes are
//! `u = +-(A - B) / |A - B|`; otherwise the slide line is one of the two tangents
//! from `A` to the circle of radius `|offset|` about `B`, and `u` is oriented so
//! that `s = dot(A - B, u)` has the mode's sign.
//!
//! Position in vector form: with `p = A - B`, `|p|^2 = s^2 + offset^2`, so
//! `s = m sqrt((|p| - |offset|)(|p| + |offset|))`; then `s p - offset perp(p) =
//! |p|^2 u` (expand `p = s u + offset perp(u)`) gives the axis, normalized.
//!
//! Rates: differentiating `A - B = s u + offset perp(u)` with `u' = omega perp(u)`
//! gives `s_dot u + omega perp(A - B) = vA - vB`: columns `u`, `perp(A - B)`,
//! determinant `dot(u, A - B) = s`, zero when `A` is the foot of the
//! perpendicular from `B` on the slide line (`|A - B| = |offset|`; for
//! `offset = 0`, `A` on `B`): both columns are then along `u`, and a motion of
//! `A` across the arm can neither slide the block nor turn the arm.
//! Units: lengths in the user's unit L, rates per second; angular rates in rad/s.

use crate::error::{Error, Fault, Primitive};
use crate::geometry::{
    abs, check_det_condition, cross, difference, dot, finite, finite_vec, length, max, min, perp,
    SINGULAR_RELATIVE,
};
use crate::mode::Mode;
use crate::scalar::Real;
use nalgebra::{Point2, Vector2};

const P: Primitive = Primitive::Rpr;

/// Closed RPR group.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RprPosition<T: Real> {
    /// Unit axis `u` of link 2, which is also the block's axis (the slide
    /// direction). Link 2's angle is `atan2(u.y, u.x)`.
    pub axis: Vector2<T>,
    /// Position of the block along link 2 (L): `A = B + s u + offset perp(u)`.
    /// Positive for `Mode::Plus`, negative for `Mode::Minus`.
    pub s: T,
}

/// Rates of the RPR group.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RprVelocity<T: Real> {
    /// Angular velocity of link 2 and of the block (rad/s, counter-clockwise).
    pub omega: T,
    /// Sliding speed of the block along link 2, relative to it (L/s).
    pub s_dot: T,
    /// Condition indicator in `(16 eps, 1]`: the smaller of the rate system's
    /// `|det| / scale = |s| / |A - B|` (`|cos|` of the angle between the slide
    /// line and `A - B`; below `16 eps` velocity returns `Singular`) and
    /// `|A - B| / size` (`size` the largest coordinate of `A` and `B`, which
    /// are rounded at that magnitude: with the offset 0 the axis is the
    /// direction of `A - B`, known only to `eps size / |A - B|`). `1` is the
    /// best-conditioned pose; the rates' relative error is about `eps /
    /// condition` at most (`docs/stability.md`). The same number governs the
    /// accelerations (same matrix).
    pub condition: T,
}

/// Accelerations of the RPR group.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RprAcceleration<T: Real> {
    /// Angular acceleration of link 2 and of the block (rad/s^2).
    pub alpha: T,
    /// Sliding acceleration of the block relative to link 2 (L/s^2).
    pub s_ddot: T,
}

/// Closes the group: finds link 2's axis `u` and the block's place `s` with
/// `A = B + s u + offset perp(u)` (`offset` in L, left of `u` positive) and the
/// sign of `s` chosen by `mode` (`Plus`: `s >= 0`).
///
/// Errors: `NonFinite` for non-finite inputs (or `|A - B|` so large that its
/// square overflows);
/// `CannotAssemble { miss: |offset| - |A - B|, reach: |offset| }` when `A` lies
/// inside the circle of radius
/// `|offset|` about `B` by more than `4 eps |offset|` (inside that rounding band
/// `s = 0`); `Singular { det: |A - B|, scale: size }` when `A` and `B` coincide
/// or `|A - B| <= 16 eps size`, `size` their largest coordinate (the axis is
/// undefined or rounding alone; with `offset != 0` that is `CannotAssemble`).
#[inline(always)]
pub fn position<T: Real>(
    a: &Point2<T>,
    b: &Point2<T>,
    offset: T,
    mode: Mode,
) -> Result<RprPosition<T>, Error<T>> {
    let offset = finite(offset, P, "RPR slide offset")?;
    let p = finite_vec(a - b, P, "RPR joint distance")?;
    let dist = finite(length(&p), P, "RPR joint distance")?;
    let e = abs(offset);
    let gap = dist - e; // < 0: A inside the circle the slide line is tangent to
    let band = T::lit(4.0) * T::eps() * e;
    if gap < -band {
        return Err(Error::new(
            P,
            Fault::CannotAssemble {
                miss: -gap,
                reach: e,
            },
        ));
    }
    // `A` on `B`, or so near it that `A - B` is rounding alone (`A` and `B`
    // are known to about eps of their coordinates): the axis is undefined.
    // With `offset != 0` that is `CannotAssemble` (above).
    let size = coordinate_size(a, b);
    if dist <= T::lit(SINGULAR_RELATIVE) * T::eps() * size {
        return Err(Error::new(
            P,
            Fault::Singular {
                det: dist,
                scale: if dist > T::zero() { size } else { T::zero() },
            },
        ));
    }
    let gap = if gap < T::zero() { T::zero() } else { gap };
    let s = mode.sign::<T>() * (gap * (dist + e)).sqrt_kernel();
    // |p|^2 u = s p - offset perp(p) (expand p = s u + offset perp(u)); divided
    // by |p| to keep magnitudes near |p| (the squares in `length` then overflow
    // no sooner than `dist` itself did), and normalized to remove rounding.
    let v = (p * s - perp(&p) * offset) / dist;
    let norm = length(&v);
    if !norm.finite() {
        return Err(Error::new(P, Fault::NonFinite { what: "RPR axis" }));
    }
    if norm <= T::zero() {
        return Err(Error::new(
            P,
            Fault::Singular {
                det: T::zero(),
                scale: dist,
            },
        ));
    }
    let axis = finite_vec(v / norm, P, "RPR axis")?;
    let s = finite(s, P, "RPR slide displacement s")?;
    Ok(RprPosition { axis, s })
}

/// Determinant of the rate system, `dot(u, A - B) = s`, checked against
/// `16 eps |u| |A - B|`, and the condition indicator: the smaller of
/// `|s| / |A - B|` and `|A - B| / size`, with `size` the largest coordinate
/// of `A` and `B`. `A` and `B` are known to about `eps size` (they are
/// rounded at their coordinates' magnitude), so the direction of `A - B`,
/// and with it the rates, only to about `eps size / |A - B|`: with the
/// offset 0 and `A` near `B`, `|s| / |A - B|` stays 1 while the rates lose
/// all their digits, and the second ratio says so. (`position` returns
/// `Singular` where `|A - B| <= 16 eps size`.)
#[inline(always)]
fn determinant<T: Real>(
    pos: &RprPosition<T>,
    a: &Point2<T>,
    b: &Point2<T>,
    p: &Vector2<T>,
) -> Result<(T, T), Error<T>> {
    let dist = length(p);
    let (det, condition) = check_det_condition(dot(&pos.axis, p), length(&pos.axis) * dist, P)?;
    let size = coordinate_size(a, b);
    let spread = if dist < size { dist / size } else { T::one() };
    Ok((det, min(condition, spread)))
}

/// The largest absolute coordinate of `a` and `b` (L): the magnitude at
/// which they are rounded.
#[inline(always)]
fn coordinate_size<T: Real>(a: &Point2<T>, b: &Point2<T>) -> T {
    max(max(abs(a.x), abs(a.y)), max(abs(b.x), abs(b.y)))
}

/// Rates of the group from the velocities of `A` and `B` (L/s; `None`: fixed).
///
/// With `p = A - B`, `w = vA - vB`: `omega = cross(u, w) / s`,
/// `s_dot = dot(w, p) / s` (`s = dot(u, p)`).
///
/// Errors: `Singular` when `|s| <= 16 eps |A - B|` (`A` at the foot of the
/// perpendicular from `B` on the slide line: both columns along `u`);
/// `NonFinite` for a non-finite input or result.
#[inline(always)]
pub fn velocity<T: Real>(
    pos: &RprPosition<T>,
    a: &Point2<T>,
    b: &Point2<T>,
    va: Option<&Vector2<T>>,
    vb: Option<&Vector2<T>>,
) -> Result<RprVelocity<T>, Error<T>> {
    let p = a - b;
    let (det, condition) = determinant(pos, a, b, &p)?;
    let w = finite_vec(difference(va, vb), P, "RPR joint velocity")?;
    let omega = finite(cross(&pos.axis, &w) / det, P, "RPR angular velocity")?;
    let s_dot = finite(dot(&w, &p) / det, P, "RPR sliding speed")?;
    Ok(RprVelocity {
        omega,
        s_dot,
        condition,
    })
}

/// Accelerations of the group from the accelerations of `A` and `B` (L/s^2;
/// `None`: fixed) and the rates.
///
/// Differentiating once more: `s_ddot u + alpha perp(A - B) = aA - aB -
/// 2 omega s_dot perp(u) + omega^2 (A - B)` (Coriolis and centripetal terms),
/// the same matrix as for the rates. Errors as for [`velocity`].
#[inline(always)]
pub fn acceleration<T: Real>(
    pos: &RprPosition<T>,
    a: &Point2<T>,
    b: &Point2<T>,
    vel: &RprVelocity<T>,
    aa: Option<&Vector2<T>>,
    ab: Option<&Vector2<T>>,
) -> Result<RprAcceleration<T>, Error<T>> {
    let p = a - b;
    let (det, _) = determinant(pos, a, b, &p)?;
    let w = finite_vec(
        difference(aa, ab) + p * (vel.omega * vel.omega)
            - perp(&pos.axis) * (T::lit(2.0) * vel.omega * vel.s_dot),
        P,
        "RPR joint acceleration",
    )?;
    let alpha = finite(cross(&pos.axis, &w) / det, P, "RPR angular acceleration")?;
    let s_ddot = finite(dot(&w, &p) / det, P, "RPR sliding acceleration")?;
    Ok(RprAcceleration { alpha, s_ddot })
}
