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
