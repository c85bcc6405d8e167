//! Position, velocity and acceleration of a [`Linkage`] in double-double.
//!
//! Position: Newton-Raphson on the loop-closure equations `phi(q) = 0` from a
//! starting guess (typically the `f64` answer of the code under test: that
//! only picks the branch, the converged root does not depend on it), with the
//! Jacobian solved by [`crate::linear::solve`]. Convergence check: the last
//! Newton step is below [`STEP_TOLERANCE`] of the length scale and every
//! residual below [`RESIDUAL_TOLERANCE`] (relative, see
//! [`equations::relative_residual`]); then the branch checks
//! ([`crate::constraint::Side`]) must hold. Anything else is an error.
//!
//! Rates: `J qdot = -phi_t`, `J qddot = gamma` (see [`crate::equations`]),
//! solved by the same elimination.

use crate::constraint::{Linkage, Point, Side, V2};
use crate::equations;
use crate::linear::{solve, SingularMatrix};
use crate::Dd;

/// Residual tolerance relative to `scale^degree`: a few hundred double-double
/// rounding units (2^-104 = 4.9e-32), leaving room for the condition of the
/// geometry while still 1e12 below what an `f64` solution can reach.
pub const RESIDUAL_TOLERANCE: f64 = 1e-28;

/// Tolerance of the last Newton step relative to the length scale: Newton
/// converges quadratically, so a step this small means the previous iterate
/// was already correct to about 1e-13 and this one to the rounding level.
pub const STEP_TOLERANCE: f64 = 1e-26;

/// Iteration limit of the Newton solve.
pub const MAX_ITERATIONS: usize = 40;

/// Why a reference solve failed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ReferenceError {
    /// The description does not have as many equations as unknowns.
    NotSquare {
        /// Scalar equations.
        equations: usize,
        /// Unknown coordinates.
        unknowns: usize,
    },
    /// The Jacobian is singular at double-double precision.
    Singular(SingularMatrix),
    /// Newton did not meet the convergence check.
    NotConverged {
        /// Relative residual at the last iterate.
        residual: f64,
        /// Relative size of the last step.
        step: f64,
    },
    /// The root found is on the other branch of the side check number `index`.
    WrongBranch {
        /// Index into [`Linkage::sides`].
        index: usize,
    },
}

impl From<SingularMatrix> for ReferenceError {
    fn from(e: SingularMatrix) -> Self {
        ReferenceError::Singular(e)
    }
}

/// A converged pose: every point's position, and the final relative residual.
#[derive(Clone, Debug, PartialEq)]
pub struct Pose {
    /// Positions of all points, in the order of [`Linkage::points`].
    pub points: Vec<V2>,
    /// Relative loop-closure residual at the solution.
    pub residual: f64,
    /// Newton iterations used.
    pub iterations: usize,
}

/// Solves the positions for `inputs` (rad) from the guess `start` (one `f64`
/// pair per point; fixed points' entries are ignored).
///
/// # Errors
/// See [`ReferenceError`].
pub fn position(
    linkage: &Linkage,
    inputs: &[Dd],
    start: &[(f64, f64)],
) -> Result<Pose, ReferenceError> {
    let n = linkage.unknowns();
    let m = linkage.equations();
    if n != m {
        return Err(ReferenceError::NotSquare {
            equations: m,
            unknowns: n,
        });
    }
    let mut q = vec![Dd::ZERO; n];
    for (c, s) in linkage.columns().iter().zip(start) {
        if let Some(c) = c {
            q[*c] = Dd::from_f64(s.0);
            q[c + 1] = Dd::from_f64(s.1);
        }
    }
    let mut step = f64::INFINITY;
    for iterations in 0..MAX_ITERATIONS {
        let p = equations::points(linkage, &q);
        let f = equations::residual(linkage, &p, inputs);
        let residual = equations::relative_residual(linkage, &f);
        if residual <= RESIDUAL_TOLERANCE && step <= STEP_TOLERANCE {
            check_sides(linkage, &p)?;
            return Ok(Pose {
                points: p,
                residual,
                iterations,
            });
        }
        let j = equations::jacobian(linkage, &p);
        let dq = solve(j, f.iter().map(|&x| -x).collect())?;
        step = 0.0;
        for (qi, d) in q.iter_mut().zip(&dq) {
            *qi += *d;
            step = step.max(d.to_f64().abs() / linkage.scale);
        }
    }
    let p = equations::points(linkage, &q);
    let f = equations::residual(linkage, &p, inputs);
    Err(ReferenceError::NotConverged {
        residual: equations::relative_residual(linkage, &f),
        step,
    })
}

fn check_sides(linkage: &Linkage, p: &[V2]) -> Result<(), ReferenceError> {
    for (index, s) in linkage.sides.iter().enumerate() {
        let value = match *s {
            Side::Left { p: q, a, b, sign } => {
                p[b].minus(p[a]).cross(p[q].minus(p[a])).to_f64() * sign
            }
            Side::Ahead { p: q, a, from, to } => {
                p[q].minus(p[a]).dot(p[to].minus(p[from])).to_f64()
            }
        };
        if value.partial_cmp(&0.0) != Some(core::cmp::Ordering::Greater) {
            return Err(ReferenceError::WrongBranch { index });
        }
    }
    Ok(())
}

/// Spreads the unknown vector `x` over every point (fixed points: zero).
fn spread(linkage: &Linkage, x: &[Dd]) -> Vec<V2> {
    linkage
        .points
        .iter()
        .zip(linkage.columns())
        .map(|(p, c)| match (p, c) {
            (Point::Unknown, Some(c)) => V2 {
                x: x[c],
                y: x[c + 1],
            },
            _ => V2::default(),
        })
        .collect()
}

/// Velocities of every point (L/s; zero for fixed points) for input rates.
///
/// # Errors
/// [`ReferenceError::Singular`] at a singular (toggle) pose.
pub fn velocity(
    linkage: &Linkage,
    pose: &Pose,
    inputs: &[Dd],
    rates: &[Dd],
) -> Result<Vec<V2>, ReferenceError> {
    let j = equations::jacobian(linkage, &pose.points);
    let b = equations::velocity_rhs(linkage, inputs, rates);
    Ok(spread(linkage, &solve(j, b)?))
}

/// Accelerations of every point (L/s^2) for input rates and accelerations,
/// given the velocities from [`velocity`].
///
/// # Errors
/// [`ReferenceError::Singular`] at a singular pose.
pub fn acceleration(
    linkage: &Linkage,
    pose: &Pose,
    vel: &[V2],
    inputs: &[Dd],
    rates: &[Dd],
    accels: &[Dd],
) -> Result<Vec<V2>, ReferenceError> {
    let j = equations::jacobian(linkage, &pose.points);
    let b = equations::acceleration_rhs(linkage, vel, inputs, rates, accels);
    Ok(spread(linkage, &solve(j, b)?))
}

/// Angle of `B - A` from +x (rad, (-pi, pi]).
pub fn angle(p: &[V2], a: usize, b: usize) -> Dd {
    let d = p[b].minus(p[a]);
    Dd::atan2(d.y, d.x)
}

/// Angular velocity of the segment `A -> B`: `cross(d, d') / |d|^2` (rad/s).
pub fn angular_velocity(p: &[V2], v: &[V2], a: usize, b: usize) -> Dd {
    let d = p[b].minus(p[a]);
    let dv = v[b].minus(v[a]);
    d.cross(dv) / d.dot(d)
}

/// Angular acceleration of the segment `A -> B`: the derivative of
/// `cross(d, d') / |d|^2`, i.e. `cross(d, d'') / |d|^2 - 2 cross(d, d') (d . d')
/// / |d|^4` (rad/s^2).
pub fn angular_acceleration(p: &[V2], v: &[V2], acc: &[V2], a: usize, b: usize) -> Dd {
    let d = p[b].minus(p[a]);
    let dv = v[b].minus(v[a]);
    let da = acc[b].minus(acc[a]);
    let n = d.dot(d);
    d.cross(da) / n - Dd::from_f64(2.0) * d.cross(dv) * d.dot(dv) / n.sqr()
}
