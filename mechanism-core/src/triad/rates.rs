//! Velocities and accelerations of the triad (see the module documentation
//! of [`super`]).

use super::elimination::{eliminate, Eliminated};
use super::{Triad, TriadPosition, PRIM};
use crate::error::{Error, Fault};
use crate::geometry::{abs, all_finite, check_det, cross, dot, perp};
use crate::scalar::Real;
use nalgebra::Vector2;

/// Angular velocities of the four links and the joints' velocities.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TriadVelocity<T: Real> {
    /// Leg 1 (rad/s, counter-clockwise positive).
    pub omega1: T,
    /// Leg 2 (rad/s).
    pub omega2: T,
    /// Leg 3 (rad/s).
    pub omega3: T,
    /// The ternary link (rad/s).
    pub omega: T,
    /// Velocity of `A` (L/s).
    pub va: Vector2<T>,
    /// Velocity of `B` (L/s).
    pub vb: Vector2<T>,
    /// Velocity of `P` (L/s).
    pub vp: Vector2<T>,
    /// Velocities of `K1`, `K2`, `K3` as given (zero for `None`; L/s), kept
    /// for the accelerations.
    pub vk: [Vector2<T>; 3],
    /// `|jacobian|` of the position: the conditioning, in `(16 eps, 1]`.
    pub condition: T,
    /// The rate matrix's elimination at the position these rates are for,
    /// and that position's [`TriadPosition::jacobian`]: [`acceleration`] at
    /// the same position (same matrix) solves with it.
    factored: (Eliminated<T>, T),
}

/// Angular accelerations of the four links and the joints' accelerations.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TriadAcceleration<T: Real> {
    /// Leg 1 (rad/s^2).
    pub alpha1: T,
    /// Leg 2 (rad/s^2).
    pub alpha2: T,
    /// Leg 3 (rad/s^2).
    pub alpha3: T,
    /// The ternary link (rad/s^2).
    pub alpha: T,
    /// Acceleration of `A` (L/s^2).
    pub aa: Vector2<T>,
    /// Acceleration of `B` (L/s^2).
    pub ab: Vector2<T>,
    /// Acceleration of `P` (L/s^2).
    pub ap: Vector2<T>,
}

/// `Some(v)` or zero.
fn or_zero<T: Real>(v: Option<&Vector2<T>>) -> Vector2<T> {
    v.copied().unwrap_or_else(Vector2::zeros)
}

/// The rate matrix (rows: the three legs; columns: the joint `A`'s two
/// components and `ab` times the ternary's rate, so all are lengths; leg
/// 1's row has no ternary column), after the determinant check, eliminated
/// ([`eliminate`]: `linsolve`'s row equilibration and partial pivoting,
/// unrolled).
#[inline(always)]
fn factor<T: Real>(triad: &Triad<T>, pos: &TriadPosition<T>) -> Result<Eliminated<T>, Error<T>> {
    check_det(pos.jacobian, T::one(), PRIM)?;
    let (r1, r2, r3) = (pos.r1, pos.r2, pos.r3);
    eliminate(
        [r1.x, r1.y],
        [r2.x, r2.y, cross(&pos.axis, &r2)],
        [r3.x, r3.y, cross(&pos.ap, &r3) / triad.ab],
    )
}

/// The rotation rate of a leg `r` of length `l` whose ends move at `v_end`
/// and `v_base`: `cross(r, v_end - v_base) / l^2`.
fn leg_rate<T: Real>(r: &Vector2<T>, l: T, dv: &Vector2<T>) -> T {
    let inv = T::one() / l;
    cross(&(r * inv), dv) * inv
}

/// Rates of the triad from the known points' velocities (L/s; `None`: fixed).
///
/// Errors ([`Primitive::Triad`]): `Singular` when `|jacobian| <= 16 eps`
/// (a branch point: two assemblies meet) or the elimination finds a relative
/// pivot `<= 3 eps`; `NonFinite` for a non-finite input or result.
pub fn velocity<T: Real>(
    triad: &Triad<T>,
    pos: &TriadPosition<T>,
    vk1: Option<&Vector2<T>>,
    vk2: Option<&Vector2<T>>,
    vk3: Option<&Vector2<T>>,
) -> Result<TriadVelocity<T>, Error<T>> {
    let m = factor(triad, pos)?;
    let vk = [or_zero(vk1), or_zero(vk2), or_zero(vk3)];
    let rhs = [
        dot(&pos.r1, &vk[0]),
        dot(&pos.r2, &vk[1]),
        dot(&pos.r3, &vk[2]),
    ];
    let [vx, vy, w_c] = m.solve(rhs)?;
    let omega = w_c / triad.ab;
    let va = Vector2::new(vx, vy);
    let vb = va + perp(&pos.ab) * omega;
    let vp = va + perp(&pos.ap) * omega;
    let out = TriadVelocity {
        omega1: leg_rate(&pos.r1, triad.l1, &(va - vk[0])),
        omega2: leg_rate(&pos.r2, triad.l2, &(vb - vk[1])),
        omega3: leg_rate(&pos.r3, triad.l3, &(vp - vk[2])),
        omega,
        va,
        vb,
        vp,
        vk,
        condition: abs(pos.jacobian),
        factored: (m, pos.jacobian),
    };
    let check = [out.omega1, out.omega2, out.omega3, vb.x, vb.y, vp.x, vp.y];
    if all_finite(check) {
        Ok(out)
    } else {
        Err(Error::new(
            PRIM,
            Fault::NonFinite {
                what: "triad rates",
            },
        ))
    }
}

/// Accelerations from the known points' accelerations (L/s^2; `None`:
/// fixed) and the rates `vel` at this `pos`.
///
/// Second derivatives of the leg equations: `r1 . aA = r1 . aK1 - |vA -
/// vK1|^2`, `r2 . (aA + alpha perp(ab)) = r2 . aK2 - |vB - vK2|^2 + omega^2
/// r2 . ab`, likewise for leg 3 with `ap`: the rate matrix again, whose
/// elimination `vel` carries when it was solved at this `pos` (the matrix is
/// then not checked and eliminated a second time). Errors as for
/// [`velocity`].
pub fn acceleration<T: Real>(
    triad: &Triad<T>,
    pos: &TriadPosition<T>,
    vel: &TriadVelocity<T>,
    ak1: Option<&Vector2<T>>,
    ak2: Option<&Vector2<T>>,
    ak3: Option<&Vector2<T>>,
) -> Result<TriadAcceleration<T>, Error<T>> {
    // The velocity's elimination when `vel` was solved at this position
    // (the same determinant, bit for bit), else the matrix again.
    let fresh;
    let m = if vel.factored.1 == pos.jacobian {
        &vel.factored.0
    } else {
        fresh = factor(triad, pos)?;
        &fresh
    };
    let ak = [or_zero(ak1), or_zero(ak2), or_zero(ak3)];
    let w2 = vel.omega * vel.omega;
    let (d1, d2, d3) = (vel.va - vel.vk[0], vel.vb - vel.vk[1], vel.vp - vel.vk[2]);
    let rhs = [
        dot(&pos.r1, &ak[0]) - dot(&d1, &d1),
        dot(&pos.r2, &ak[1]) - dot(&d2, &d2) + w2 * dot(&pos.r2, &pos.ab),
        dot(&pos.r3, &ak[2]) - dot(&d3, &d3) + w2 * dot(&pos.r3, &pos.ap),
    ];
    let [ax, ay, al_c] = m.solve(rhs)?;
    let alpha = al_c / triad.ab;
    let aa = Vector2::new(ax, ay);
    let ab = aa + perp(&pos.ab) * alpha - pos.ab * w2;
    let ap = aa + perp(&pos.ap) * alpha - pos.ap * w2;
    let out = TriadAcceleration {
        alpha1: leg_rate(&pos.r1, triad.l1, &(aa - ak[0])),
        alpha2: leg_rate(&pos.r2, triad.l2, &(ab - ak[1])),
        alpha3: leg_rate(&pos.r3, triad.l3, &(ap - ak[2])),
        alpha,
        aa,
        ab,
        ap,
    };
    let check = [out.alpha1, out.alpha2, out.alpha3, ab.x, ab.y, ap.x, ap.y];
    if all_finite(check) {
        Ok(out)
    } else {
        Err(Error::new(
            PRIM,
            Fault::NonFinite {
                what: "triad accelerations",
            },
        ))
    }
}
