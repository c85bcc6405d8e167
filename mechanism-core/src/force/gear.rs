//! Kinetostatics of a gear pair: a link turning about the pivot `O` of the
//! body carrying it, held by the teeth of the gear it meshes with (center
//! `C`) instead of a motor.
//!
//! Geometry: the centers are `d = |C - O|` apart; with `ratio` the pitch
//! radius of the meshing gear over this one's (positive for external
//! gears, negative for an internal pair), this gear's signed pitch radius
//! is `rho = d / (1 + ratio)` and the pitch point (where the teeth touch)
//! is `P = O + rho e`, `e = (C - O) / d`. The tooth force on this gear is
//! `F = F_t t + |F_t| tan(phi) u`: `t = perp(e)` the common tangent
//! (counter-clockwise of `e`), `phi` the pressure angle, and `u` the
//! direction of the separating force on the teeth of this gear: `-e` for
//! external gears (pushed apart along the line of centers), `+e` for an
//! internal pair (the pinion pushed toward the ring's center, the ring
//! outward at the contact). It acts along the line of action, `phi` from
//! the tangent.
//!
//! Unknowns: the pivot force `R` (of the carrying body on this gear, at `O`)
//! and the tangential component `F_t`. With the gear's known load reduced
//! to `O` (force `L`, moment `M_O`), the moment balance about `O`,
//! `rho F_t + M_O = 0`, gives `F_t`, and the force balance `R + F + L = 0`
//! gives `R`. The meshing gear receives `-F` at `P` (Newton's third law),
//! the carrying body `-R` at `O`. Sources: the spur gear force components
//! as in Shigley's Mechanical Engineering Design, ch. 13 (tangential and
//! radial components, `W_r = W_t tan(phi)`).

use crate::error::{Error, Fault, Primitive};
use crate::force::body::Wrench;
use crate::geometry::{perp, unit};
use crate::scalar::{abs, Real};
use nalgebra::{Point2, Vector2};

/// A gear's errors are tagged as its crank's: its position is the crank
/// primitive's at the geared angle.
const P: Primitive = Primitive::Crank;

/// Reactions of a gear pair on the driven gear's link.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct GearReactions<T: Real> {
    /// Force of the carrying body on the gear's link at its pivot `O`
    /// (`M L / s^2`).
    pub pivot: Vector2<T>,
    /// Force of the meshing gear's teeth on this gear at the pitch point
    /// (`M L / s^2`), along the line of action.
    pub tooth: Vector2<T>,
    /// Its tangential component along `t = perp(e)` (`M L / s^2`, signed):
    /// the force that transmits the torque.
    pub tangential: T,
    /// The pitch point `P`, where the teeth touch (L).
    pub contact: Point2<T>,
}

/// The pivot and tooth forces of a gear about `pivot` meshing with the gear
/// centered at `center`, at `ratio` (pitch radius of the meshing gear over
/// this one's; never 0 or -1) and pressure angle `pressure` (rad, in
/// (0, pi/2)), whose known load (inertia, weight, external loads, the
/// reactions of the groups attached to it, negated) is `load`, a wrench
/// about `pivot`.
///
/// Errors ([`Primitive::Crank`]): `NonFinite` for a non-finite load, for
/// coincident centers (no pitch point) or a ratio of -1.
#[inline]
pub fn reactions<T: Real>(
    load: &Wrench<T>,
    pivot: &Point2<T>,
    center: &Point2<T>,
    ratio: T,
    pressure: T,
) -> Result<GearReactions<T>, Error<T>> {
    let non_finite = |what| Err(Error::new(P, Fault::NonFinite { what }));
    if !load.is_finite() {
        return non_finite("gear load");
    }
    let c = center - pivot;
    let d = (c.x * c.x + c.y * c.y).sqrt_kernel();
    let rho = d / (T::one() + ratio);
    let apart = d > T::zero() && rho.finite() && abs(rho) > T::zero();
    if !apart {
        return non_finite("gear center distance");
    }
    let e = c / d;
    let t = perp(&e);
    let u = if ratio > T::zero() { -e } else { e };
    let tangential = -load.moment / rho;
    let (tan_phi, cos_phi) = {
        let v = unit(pressure);
        (v.y / v.x, v.x)
    };
    let acute = cos_phi > T::zero() && tan_phi.finite();
    if !acute {
        return non_finite("gear pressure angle");
    }
    let tooth = t * tangential + u * (abs(tangential) * tan_phi);
    Ok(GearReactions {
        pivot: -load.force - tooth,
        tooth,
        tangential,
        contact: pivot + e * rho,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_gear_balances_its_load_and_pushes_along_the_line_of_action() {
        // Proves, for external and internal pairs, that the pivot and tooth
        // forces balance the load (forces and moment about the pivot, to
        // 1e-12 of loads of size 10), that the pitch point divides the
        // center distance as the ratio says, and that the tooth force is
        // at the pressure angle from the tangent, its radial part away from
        // the meshing gear (external) or toward it (internal).
        let o = Point2::new(1.0, 2.0);
        let c = Point2::new(4.0, 6.0); // d = 5
        let load = Wrench {
            force: Vector2::new(3.0, -7.0),
            moment: 9.0,
        };
        let phi = 20f64.to_radians();
        for (ratio, rho) in [(1.5, 2.0), (-3.0, -2.5), (-0.5, 10.0)] {
            let r = reactions(&load, &o, &c, ratio, phi).unwrap();
            let sum = r.pivot + r.tooth + load.force;
            assert!(sum.norm() <= 1e-12, "{sum}");
            let arm = r.contact - o;
            let m = arm.x * r.tooth.y - arm.y * r.tooth.x + load.moment;
            assert!(m.abs() <= 1e-12, "{m}");
            assert!((arm.norm() - f64::abs(rho)).abs() <= 1e-12);
            let e = (c - o) / 5.0;
            let radial = r.tooth.dot(&e);
            let tangential = r.tooth.dot(&perp(&e));
            assert!((radial.abs() / tangential.abs() - phi.tan()).abs() <= 1e-12);
            assert!(radial * ratio < 0.0, "{ratio}: {radial}");
        }
    }

    #[test]
    fn coincident_centers_are_an_error() {
        // Proves a pair without a center distance is a typed error, not NaN.
        let load = Wrench {
            force: Vector2::new(1.0, 0.0),
            moment: 1.0,
        };
        let o = Point2::new(0.0, 0.0);
        assert!(reactions(&load, &o, &o, 2.0, 0.3).is_err());
        let c = Point2::new(1.0, 0.0);
        assert!(reactions(&load, &o, &c, -1.0, 0.3).is_err());
    }
}
