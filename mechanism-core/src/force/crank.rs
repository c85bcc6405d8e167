//! Kinetostatics of a crank driver: a link turning about the pivot `O` of the
//! body carrying it (usually the ground), driven by a torque.
//!
//! Unknowns: the pivot force `R` (force of the carrying body on the crank, at
//! `O`) and the driving torque `T_d` (applied to the crank by the motor, whose
//! stator on the carrying body receives `-T_d`). With the crank's known load
//! reduced to `O` (force `F`, moment `M_O`) the three equations are
//! `R + F = 0` and `T_d + M_O = 0`: the 3x3 system is the identity, so it is
//! solved as such, exactly, and its conditioning indicator is 1. The driving
//! torque is the classical "balancing moment" (Artobolevsky; Zhukovsky's lever
//! gives the same value by virtual work, which the tests check).

use crate::error::{Error, Fault, Primitive};
use crate::force::body::Wrench;
use crate::scalar::Real;
use nalgebra::Vector2;

const P: Primitive = Primitive::Crank;

/// Reactions of a crank driver.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct CrankReactions<T: Real> {
    /// Force of the carrying body on the crank at the pivot `O` (`M L / s^2`).
    pub pivot: Vector2<T>,
    /// Driving torque on the crank (`M L^2 / s^2`), counter-clockwise positive;
    /// its power is `torque * omega` with `omega` the crank's speed relative to
    /// the carrying body.
    pub torque: T,
    /// Always 1: the system is the identity (kept for a uniform interface).
    pub min_pivot_ratio: T,
}

/// Pivot force and driving torque of a crank whose known load (inertia,
/// weight, external loads, the reactions of the groups attached to it,
/// negated) is `load`, a wrench about the pivot `O`.
///
/// Errors ([`Primitive::Crank`]): `NonFinite` for a non-finite load.
#[inline]
pub fn reactions<T: Real>(load: &Wrench<T>) -> Result<CrankReactions<T>, Error<T>> {
    if !load.is_finite() {
        return Err(Error::new(P, Fault::NonFinite { what: "crank load" }));
    }
    Ok(CrankReactions {
        pivot: -load.force,
        torque: -load.moment,
        min_pivot_ratio: T::one(),
    })
}
