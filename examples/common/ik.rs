//! Motor torques of the five-bar robot given its end point
//! (`scenes::FiveBarIk`), from the force a positioner would need there.

use super::scenes::{FiveBarIk, FiveBarIkInput, FiveBarIkPosition};
use mechanism::Error;

/// The motor torques (N m, counter-clockwise on the arms) that supply the
/// force `d` (N) at the end point: `K^T tau = d` with `K = dq/dP` from the
/// velocity at unit end-point rates (virtual work: `tau = J^T d` with
/// `J = K^-1`). `None` where `K^T` is singular to rounding (64 eps of the
/// product of its rows' sizes: the arms cannot hold the end point, a
/// forward singularity).
pub fn motor_torques(
    ik: &FiveBarIk,
    pos: &FiveBarIkPosition,
    d: (f64, f64),
) -> Result<Option<(f64, f64)>, Error<f64>> {
    let kx = ik.velocity(pos, &FiveBarIkInput { x: 1.0, y: 0.0 })?;
    let ky = ik.velocity(pos, &FiveBarIkInput { x: 0.0, y: 1.0 })?;
    // K^T = [[dq1/dx, dq2/dx], [dq1/dy, dq2/dy]].
    let (a, b, c, e) = (kx.arm1, kx.arm2, ky.arm1, ky.arm2);
    let det = a * e - b * c;
    let scale = (a.abs() + b.abs()) * (c.abs() + e.abs());
    if !(det.abs() > 64.0 * f64::EPSILON * scale) {
        return Ok(None);
    }
    Ok(Some(((d.0 * e - b * d.1) / det, (a * d.1 - c * d.0) / det)))
}
