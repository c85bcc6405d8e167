//! Linear-actuator driver (hydraulic or electric cylinder): its length `L`
//! between the known point `B` and the pin `C` is the input (`L` in L,
//! `length_dot` in L/s, `length_ddot` in L/s^2). `C` is on a link (link 1) that
//! turns about the known point `A` with radius `l`.
//!
//! ```text
//!             C
//!         l  / \  L (cylinder, variable)     Mode::Plus : C left of A -> B
//!           /   \                            Mode::Minus: C right of A -> B
//!          A     B
//! ```
//!
//! Geometrically this is an RRR group with `l2 = L`, so the position is
//! [`crate::dyad::rrr::position`]'s (errors re-attributed to the actuator).
//!
//! Rates: with `r1 = C - A`, `r2 = C - B = L e2` (`e2` unit, turning with the
//! cylinder at `omega2`), `vC = vA + omega1 perp(r1) = vB + omega2 perp(r2) +
//! L_dot e2`, so `omega1 perp(r1) - omega2 perp(r2) = vB - vA + L_dot e2`: the
//! RRR matrix, determinant `cross(r1, r2)` (zero when link 1 and the cylinder
//! are aligned: the cylinder pushes through the pivot).
//! Units: lengths in the user's unit L, rates per second; angular rates in rad/s.

use crate::dyad::rrr::{self, RrrPosition};
use crate::error::{Error, Primitive};
use crate::geometry::{
    check_det_condition, difference, dot, finite, finite_vec, length, perp, plus, positive,
};
use crate::link::{relative_acceleration, relative_velocity};
use crate::mode::Mode;
use crate::scalar::Real;
use nalgebra::{Point2, Vector2};

const P: Primitive = Primitive::Actuator;

/// Closed actuator: `c` is the pin `C` (L), `r1 = C - A` (link 1, length `l`),
/// `r2 = C - B` (the cylinder, length `L`; its direction is the cylinder's axis).
pub type ActuatorPosition<T> = RrrPosition<T>;

/// Rates of the actuator and its link.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct ActuatorVelocity<T: Real> {
    /// Angular velocity of link 1 (rad/s, counter-clockwise positive).
    pub omega1: T,
    /// Angular velocity of the cylinder (rad/s).
    pub omega2: T,
    /// Velocity of `C` (L/s).
    pub vc: Vector2<T>,
    /// Condition indicator of the rate system, `|det| / scale` in `(16 eps, 1]`:
    /// `|cross(r1, r2)| / (l L)`: `|sin|` of the angle between link 1 and the
    /// cylinder. `1` is the best-conditioned pose, `0` the singular one (below `16
    /// eps` velocity returns `Singular`); the rates' relative error is about `eps /
    /// condition` at most (`docs/stability.md`). The same number governs the
    /// accelerations (same matrix).
    pub condition: T,
}

/// Accelerations of the actuator and its link.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct ActuatorAcceleration<T: Real> {
    /// Angular acceleration of link 1 (rad/s^2).
    pub alpha1: T,
    /// Angular acceleration of the cylinder (rad/s^2).
    pub alpha2: T,
    /// Acceleration of `C` (L/s^2).
    pub ac: Vector2<T>,
}

/// Places the pin `C` with `|C - A| = l` and `|C - B| = length` (both L), to the
/// left of `A -> B` for `Mode::Plus`, to the right for `Mode::Minus`.
///
/// Errors (attributed to [`Primitive::Actuator`]): `NonPositive` for `l` or
/// `length <= 0`; `NonFinite`; `CannotAssemble` when `|B - A|` lies outside
/// `[|l - length|, l + length]` beyond rounding; `Singular` when `A` and `B`
/// coincide. See [`crate::dyad::rrr::position`].
#[inline(always)]
pub fn position<T: Real>(
    a: &Point2<T>,
    l: T,
    b: &Point2<T>,
    length: T,
    mode: Mode,
) -> Result<ActuatorPosition<T>, Error<T>> {
    let l = positive(l, P, "actuator link length l")?;
    let length = positive(length, P, "actuator length")?;
    finite_vec(b - a, P, "actuator joint distance")?;
    rrr::position(a, l, b, length, mode).map_err(|e| Error::new(P, e.fault))
}

/// Determinant `cross(r1, r2)`, checked against `16 eps |r1| |r2|`, the
/// cylinder's length `|r2|` (> 0 when the check passes) and the condition
/// indicator `|det| / (|r1| |r2|)`.
#[inline(always)]
fn determinant<T: Real>(pos: &ActuatorPosition<T>) -> Result<(T, T, T), Error<T>> {
    let len = length(&pos.r2);
    let (det, condition) = check_det_condition(pos.det, length(&pos.r1) * len, P)?;
    Ok((det, len, condition))
}

/// Rates from the velocities of `A` and `B` (L/s; `None`: fixed) and the
/// extension rate `length_dot` (L/s).
///
/// With `w = vB - vA + length_dot e2` (`e2 = r2 / |r2|`): `omega1 = dot(w, r2) /
/// det`, `omega2 = dot(w, r1) / det`, `det = cross(r1, r2)`; `vc = vA + omega1
/// perp(r1)`.
///
/// Errors: `Singular` when `|cross(r1, r2)| <= 16 eps |r1| |r2|` (link 1 and the
/// cylinder aligned); `NonFinite` for a non-finite input or result.
#[inline(always)]
pub fn velocity<T: Real>(
    pos: &ActuatorPosition<T>,
    va: Option<&Vector2<T>>,
    vb: Option<&Vector2<T>>,
    length_dot: T,
) -> Result<ActuatorVelocity<T>, Error<T>> {
    let length_dot = finite(length_dot, P, "actuator extension rate")?;
    let (det, len, condition) = determinant(pos)?;
    let e2 = pos.r2 / len;
    let w = finite_vec(
        difference(vb, va) + e2 * length_dot,
        P,
        "actuator joint velocity",
    )?;
    let omega1 = finite(dot(&w, &pos.r2) / det, P, "actuator link angular velocity")?;
    let omega2 = finite(dot(&w, &pos.r1) / det, P, "actuator angular velocity")?;
    let vc = finite_vec(
        plus(va, relative_velocity(&pos.r1, omega1)),
        P,
        "actuator velocity of C",
    )?;
    Ok(ActuatorVelocity {
        omega1,
        omega2,
        vc,
        condition,
    })
}

/// Accelerations from the accelerations of `A` and `B` (L/s^2; `None`: fixed),
/// the rates, and `length_dot` (L/s), `length_ddot` (L/s^2).
///
/// Differentiating `r2 = L e2` twice (`e2' = omega2 perp(e2)`):
/// `r2'' = L'' e2 + 2 L' omega2 perp(e2) + alpha2 perp(r2) - omega2^2 r2`, so
/// `alpha1 perp(r1) - alpha2 perp(r2) = aB - aA + omega1^2 r1 - omega2^2 r2 +
/// L'' e2 + 2 L' omega2 perp(e2)`, the same matrix as for the rates.
/// Errors as for [`velocity`].
#[inline(always)]
pub fn acceleration<T: Real>(
    pos: &ActuatorPosition<T>,
    vel: &ActuatorVelocity<T>,
    aa: Option<&Vector2<T>>,
    ab: Option<&Vector2<T>>,
    length_dot: T,
    length_ddot: T,
) -> Result<ActuatorAcceleration<T>, Error<T>> {
    let length_dot = finite(length_dot, P, "actuator extension rate")?;
    let length_ddot = finite(length_ddot, P, "actuator extension acceleration")?;
    let (det, len, _) = determinant(pos)?;
    let e2 = pos.r2 / len;
    let w = finite_vec(
        difference(ab, aa) + pos.r1 * (vel.omega1 * vel.omega1)
            - pos.r2 * (vel.omega2 * vel.omega2)
            + e2 * length_ddot
            + perp(&e2) * (T::lit(2.0) * length_dot * vel.omega2),
        P,
        "actuator joint acceleration",
    )?;
    let alpha1 = finite(
        dot(&w, &pos.r2) / det,
        P,
        "actuator link angular acceleration",
    )?;
    let alpha2 = finite(dot(&w, &pos.r1) / det, P, "actuator angular acceleration")?;
    let ac = finite_vec(
        plus(aa, relative_acceleration(&pos.r1, vel.omega1, alpha1)),
        P,
        "actuator acceleration of C",
    )?;
    Ok(ActuatorAcceleration { alpha1, alpha2, ac })
}
