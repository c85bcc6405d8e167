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
use crate::scalar::{abs, Real};
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

/// The torques of the two motors that hold an inverse-kinematics linkage's
/// target point, and how well they are determined.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct MotorTorques<T: Real> {
    /// Each motor's torque on its link (`M L^2 / s^2`, counter-clockwise
    /// positive), in the order the rates were given.
    pub torque: [T; 2],
    /// `|det K| / (|k_x| |k_y|)`, the sine of the angle between the rate
    /// map's rows, in (0, 1]: small towards a pose where the motors cannot
    /// hold the point (a forward singularity).
    pub min_pivot_ratio: T,
}

/// The motor torques `tau` that supply the force `drive` (the positioner's,
/// [`reactions`]) at the target point: `K^T tau = drive`, with
/// `K = d q / d P` the rate map of the motors' angles `q` by the point's
/// coordinates; `k_x` and `k_y` are its columns, the two motors' rates
/// (rad/s) at unit rates of `x` and of `y` (L/s) (virtual work: the motors'
/// power `tau . q_dot` equals the positioner's `drive . v_P` for every
/// `v_P`, so `tau = J^T drive` with `J = K^-1`).
///
/// Errors ([`Primitive::Target`]): `NonFinite`; `Singular` when
/// `|det K| <= 16 eps |k_x| |k_y|`: the motors' rates do not span the
/// point's motions, so no torques hold it (the five-bar's distal links in
/// line).
#[inline]
pub fn motor_torques<T: Real>(
    k_x: [T; 2],
    k_y: [T; 2],
    drive: &Vector2<T>,
) -> Result<MotorTorques<T>, Error<T>> {
    let finite = k_x.iter().chain(&k_y).all(|v| v.finite()) && drive.x.finite() && drive.y.finite();
    if !finite {
        return Err(Error::new(
            P,
            Fault::NonFinite {
                what: "motor rates or target force",
            },
        ));
    }
    // K^T tau = drive: rows k_x . tau = drive.x, k_y . tau = drive.y.
    let det = k_x[0] * k_y[1] - k_x[1] * k_y[0];
    let scale =
        ((k_x[0] * k_x[0] + k_x[1] * k_x[1]) * (k_y[0] * k_y[0] + k_y[1] * k_y[1])).sqrt_kernel();
    let ratio = if scale > T::zero() {
        abs(det) / scale
    } else {
        T::zero()
    };
    // `ratio` is finite here (finite rates); at or below the threshold the
    // torques would be rounding noise.
    if ratio <= T::lit(16.0) * T::eps() {
        return Err(Error::new(P, Fault::Singular { det, scale }));
    }
    let torque = [
        (drive.x * k_y[1] - k_x[1] * drive.y) / det,
        (k_x[0] * drive.y - k_y[0] * drive.x) / det,
    ];
    // Finite rates and force can still give torques beyond the scalar's
    // range (a force of 1e30 on a lever of 1e-10).
    if !(torque[0].finite() && torque[1].finite()) {
        return Err(Error::new(
            P,
            Fault::NonFinite {
                what: "motor torques",
            },
        ));
    }
    Ok(MotorTorques {
        torque,
        min_pivot_ratio: ratio,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn motor_torques_do_the_positioners_work() {
        // Proves the torques solve K^T tau = D: for every end-point rate v
        // the motors' power tau . (K v) equals the positioner's D . v
        // (checked at two rates, to 1e-15 of the terms), and rows in line
        // (a forward singularity) are a typed Singular error.
        let (k_x, k_y) = ([2.0f64, -0.5], [0.7, 3.0]);
        let d = Vector2::new(1.5, -2.0);
        let m = motor_torques(k_x, k_y, &d).unwrap();
        for v in [Vector2::new(1.0, 0.0), Vector2::new(0.3, -0.8)] {
            let q_dot = [k_x[0] * v.x + k_y[0] * v.y, k_x[1] * v.x + k_y[1] * v.y];
            let motors = m.torque[0] * q_dot[0] + m.torque[1] * q_dot[1];
            assert!((motors - d.dot(&v)).abs() <= 1e-15 * 10.0, "{motors}");
        }
        assert!(m.min_pivot_ratio > 0.9 && m.min_pivot_ratio <= 1.0);
        let e = motor_torques([1.0, 2.0], [2.0, 4.0], &d).unwrap_err();
        assert!(matches!(e.fault, Fault::Singular { .. }));
        assert_eq!(e.primitive, Primitive::Target);
    }

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
