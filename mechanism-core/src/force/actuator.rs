//! Kinetostatics of a linear-actuator driver: a link (link 1) turning about
//! the pivot `A` of the body carrying it, driven by a massless actuator
//! (hydraulic cylinder, linear motor) from the point `B` of another body to the
//! pin `C` of the link (the joint names of `crate::driver::actuator`).
//!
//! ```text
//!          C  (pin on link 1)
//!         / \
//!     1  /   \  actuator (two-force member: force along C - B)
//!       A     B
//! ```
//!
//! Unknowns: the pivot force `R` (the carrying body on the link, at `A`) and
//! the axial force `F_a`, positive when the actuator pushes (`F_a u` on the
//! link at `C`, `u = (C - B) / |C - B|`; `-F_a u` on the body carrying `B`).
//! Equations, with moments about `C` so that no row has a single entry and
//! the solver's pivots reflect the geometry: `R + F_a u = -F`,
//! `cross(A - C, R) = -M_C`. Singular when the actuator's line passes through
//! `A` (dead centre: it cannot turn the link); the indicator is then about
//! `|sin|` of the angle between `u` and `A - C`.

use crate::error::{Error, Fault, Primitive};
use crate::force::body::Wrench;
use crate::force::group::unit_direction;
use crate::force::PrismaticReaction;
use crate::geometry::{cross, dot, perp};
use crate::linsolve;
use crate::scalar::Real;
use nalgebra::{Point2, Vector2};

const P: Primitive = Primitive::Actuator;

/// Reactions of a linear-actuator driver.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct ActuatorReactions<T: Real> {
    /// Force of the carrying body on the link at the pivot `A` (`M L / s^2`).
    pub a: Vector2<T>,
    /// Axial actuator force (`M L / s^2`), positive when pushing `C` away from
    /// `B`; its power is `axial * l_dot` with `l_dot` the rate of `|C - B|`.
    pub axial: T,
    /// Conditioning indicator, see [`crate::linsolve::Solution::min_pivot_ratio`].
    pub min_pivot_ratio: T,
}

/// Pivot force and actuator force for a link pivoted at `a`, driven by an
/// actuator from `b` (on another body) to the pin `c` (on the link), whose
/// known load (inertia, weight, external loads, the reactions of the groups
/// attached to it, negated) is `load`, a wrench about the pivot `A`.
///
/// Errors ([`Primitive::Actuator`]): `NonFinite`; `NonPositive` when `C = B`;
/// `Singular` when the actuator's line passes through `A` (relative pivot
/// `<= 3 eps`) or `C = A`.
#[inline]
pub fn reactions<T: Real>(
    a: &Point2<T>,
    b: &Point2<T>,
    c: &Point2<T>,
    load: &Wrench<T>,
) -> Result<ActuatorReactions<T>, Error<T>> {
    if !load.is_finite() {
        return Err(Error::new(
            P,
            Fault::NonFinite {
                what: "actuator load",
            },
        ));
    }
    let u = unit_direction(&(c - b), P, "actuator length")?;
    let r = a - c;
    let m_c = load.moved(a, c).moment;
    let zero = T::zero();
    let one = T::one();
    let matrix = [[one, zero, u.x], [zero, one, u.y], [-r.y, r.x, zero]];
    let rhs = [-load.force.x, -load.force.y, -m_c];
    let s = linsolve::solve(matrix, rhs).map_err(|e| Error::new(P, e.fault))?;
    let [rx, ry, axial] = s.x;
    Ok(ActuatorReactions {
        a: Vector2::new(rx, ry),
        axial,
        min_pivot_ratio: s.min_pivot_ratio,
    })
}

/// Reactions of a linear-actuator driver whose cylinder has mass: a barrel
/// pivoted at `B` (on the body carrying `B`) and a rod pinned at the joint
/// `C` (on the link), sliding in each other along `u = (C - B) / |C - B|`
/// and both turning with the cylinder's angle.
///
/// ```text
///          C  rod pinned here, on link 1
///         / \
///     1  /   \  rod (from C) sliding in the barrel (from B), axis u = B -> C
///       A     B
/// ```
///
/// Signs: `n = perp(u) = (-u_y, u_x)`; forces in the global frame; moments
/// counter-clockwise positive. With the rod's known load `f_r`, `m_r` (about
/// `C`), the barrel's `f_b`, `m_b` (about `B`) and `L = |C - B|`, the moment
/// of rod and barrel together about `B` gives the normal part of the link's
/// force on the rod, `k = -(m_b + m_r + (C - B) x f_r) / L`; the link is then
/// solved as by [`reactions`] with the extra known force `-k n` at `C`
/// (axial `F'`), and the pressure force between barrel and rod is
/// `F = F' - f_r . u`. With massless, unloaded barrel and rod this is
/// [`reactions`] exactly (`k = 0`, `F = F'`).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct CylinderReactions<T: Real> {
    /// Force of the carrying body on the link at the pivot `A` (`M L / s^2`).
    pub a: Vector2<T>,
    /// Axial force of the actuator (`M L / s^2`): the pressure force between
    /// barrel and rod, positive when it pushes them apart (`F u` on the rod,
    /// `-F u` on the barrel); its power is `axial * l_dot`.
    pub axial: T,
    /// Force of the link on the rod at the joint `C` (`M L / s^2`).
    pub c: Vector2<T>,
    /// Force of the body carrying `B` on the barrel at `B` (`M L / s^2`).
    pub b: Vector2<T>,
    /// The prismatic pair's reaction of the barrel on the rod: normal force
    /// along `perp(u)` and couple, about `C` (the axial force is
    /// [`CylinderReactions::axial`]).
    pub pair: PrismaticReaction<T>,
    /// Conditioning indicator, see [`crate::linsolve::Solution::min_pivot_ratio`].
    pub min_pivot_ratio: T,
}

/// Pivot, joint and pair forces for a link pivoted at `a`, driven by a
/// cylinder with mass from `b` (on another body) to the pin `c` (on the
/// link). `arm`: the link's known load, a wrench about `A`; `rod`: the rod's
/// known load about `C`; `barrel`: the barrel's known load about `B` (each
/// with inertia, weight, external loads and the reactions of the groups
/// attached to it, negated; `Wrench::zero()` for none). See
/// [`CylinderReactions`] for the equations and signs.
///
/// Errors ([`Primitive::Actuator`]): as [`reactions`]; `NonFinite` for a
/// non-finite rod or barrel load.
#[inline]
pub fn reactions_with_cylinder<T: Real>(
    a: &Point2<T>,
    b: &Point2<T>,
    c: &Point2<T>,
    arm: &Wrench<T>,
    rod: &Wrench<T>,
    barrel: &Wrench<T>,
) -> Result<CylinderReactions<T>, Error<T>> {
    if !(rod.is_finite() && barrel.is_finite()) {
        return Err(Error::new(
            P,
            Fault::NonFinite {
                what: "actuator cylinder load",
            },
        ));
    }
    let bc = c - b;
    let u = unit_direction(&bc, P, "actuator length")?;
    let n = perp(&u);
    let k = -(barrel.moment + rod.moment + cross(&bc, &rod.force)) / dot(&bc, &u);
    let pushed = *arm + Wrench::force_at(&(n * -k), c, a);
    let s = reactions(a, b, c, &pushed)?;
    let (along, across) = (dot(&rod.force, &u), dot(&rod.force, &n));
    let axial = s.axial - along;
    let normal = -k - across;
    Ok(CylinderReactions {
        a: s.a,
        axial,
        c: n * k - u * s.axial,
        b: u * axial + n * normal - barrel.force,
        pair: PrismaticReaction::new(normal, -rod.moment, &u),
        min_pivot_ratio: s.min_pivot_ratio,
    })
}
