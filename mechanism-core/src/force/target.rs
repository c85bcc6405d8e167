//! Kinetostatics of a target driver: the effector, a body translating with
//! the target point `P` and held by a positioner (a gantry, or in inverse
//! kinematics the motors acting through the linkage).
//!
//! Unknowns: the force `D` the positioner applies to the effector (through
//! `P`) and its couple `M`. With the effector's known load reduced to `P`
//! (force `F`, moment `M_P`, the reactions of the groups pinned at `P`
//! included): `D + F = 0`, `M + M_P = 0`. The system is the identity: the
//! conditioning indicator is 1.
//!
//! `D` is what the positioner must push with to hold `P` on its path; its
//! power is `dot(D, v_P)`. When motors elsewhere in the linkage do the
//! positioning, their torques `tau` supply it: `tau = J^T D` with
//! `J = d P / d q` the forward Jacobian (virtual work).

use crate::error::{Error, Fault, Primitive};
use crate::force::body::Wrench;
use crate::scalar::Real;
use nalgebra::Vector2;

const P: Primitive = Primitive::Target;

/// Reactions of a target driver.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct TargetReactions<T: Real> {
    /// Force of the positioner on the effector, through `P` (`M L / s^2`,
    /// global frame).
    pub drive: Vector2<T>,
    /// Couple of the positioner on the effector (`M L^2 / s^2`,
    /// counter-clockwise positive); zero unless loads act on the effector
    /// off `P`.
    pub couple: T,
    /// Always 1: the system is the identity (kept for a uniform interface).
    pub min_pivot_ratio: T,
}

/// The positioner's force and couple on the effector whose known load is
/// `load`, a wrench about the target point.
///
/// Errors ([`Primitive::Target`]): `NonFinite` for a non-finite load.
#[inline]
pub fn reactions<T: Real>(load: &Wrench<T>) -> Result<TargetReactions<T>, Error<T>> {
    if !load.is_finite() {
        return Err(Error::new(
            P,
            Fault::NonFinite {
                what: "target load",
            },
        ));
    }
    Ok(TargetReactions {
        drive: -load.force,
        couple: -load.moment,
        min_pivot_ratio: T::one(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_positioner_balances_the_load() {
        // Proves the drive and couple are the load's opposites (the
        // effector's equilibrium) and a non-finite load is a typed error.
        let load = Wrench::new(Vector2::new(3.0, -4.0), 0.5);
        let r = reactions(&load).unwrap();
        assert_eq!(r.drive, Vector2::new(-3.0, 4.0));
        assert_eq!(r.couple, -0.5);
        let bad = Wrench::new(Vector2::new(f64::NAN, 0.0), 0.0);
        assert_eq!(reactions(&bad).unwrap_err().primitive, Primitive::Target);
    }
}
