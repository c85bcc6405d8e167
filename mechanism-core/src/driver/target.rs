//! Target driver: a point placed by two inputs, its coordinates. The point
//! `P = (x, y)` (L) and its rates `(x_dot, y_dot)` (L/s) and accelerations
//! `(x_ddot, y_ddot)` (L/s^2) are the inputs, all in the global frame.
//!
//! It is how inverse kinematics is written: the end point of a five-bar
//! robot, or a leg's foot, is given, and the groups hanging on it solve the
//! motors' links. The point belongs to a body of its own, the effector,
//! which translates with it and does not turn (a positioner holds it; see
//! [`crate::force::target`] for what the positioner must supply).

use crate::error::{Error, Primitive};
use crate::geometry::{finite_point, finite_vec};
use crate::scalar::Real;
use nalgebra::{Point2, Vector2};

const P: Primitive = Primitive::Target;

/// The target point at the inputs `x`, `y` (L).
///
/// Errors ([`Primitive::Target`]): `NonFinite` for a non-finite input.
#[inline]
pub fn position<T: Real>(x: T, y: T) -> Result<Point2<T>, Error<T>> {
    finite_point(Point2::new(x, y), P, "target coordinates")
}

/// The target point's velocity (L/s): its inputs' rates.
///
/// Errors ([`Primitive::Target`]): `NonFinite` for a non-finite rate.
#[inline]
pub fn velocity<T: Real>(x_dot: T, y_dot: T) -> Result<Vector2<T>, Error<T>> {
    finite_vec(Vector2::new(x_dot, y_dot), P, "target rates")
}

/// The target point's acceleration (L/s^2): its inputs' accelerations.
///
/// Errors ([`Primitive::Target`]): `NonFinite` for a non-finite acceleration.
#[inline]
pub fn acceleration<T: Real>(x_ddot: T, y_ddot: T) -> Result<Vector2<T>, Error<T>> {
    finite_vec(Vector2::new(x_ddot, y_ddot), P, "target accelerations")
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::error::Fault;

    #[test]
    fn the_point_and_its_rates_are_the_inputs() {
        // Proves the target is exactly its inputs (no rounding) and that a
        // non-finite input is a typed NonFinite error of the target.
        assert_eq!(position(0.3, -1.5).unwrap(), Point2::new(0.3, -1.5));
        assert_eq!(velocity(2.0, 0.0).unwrap(), Vector2::new(2.0, 0.0));
        assert_eq!(acceleration(-1.0, 4.0).unwrap(), Vector2::new(-1.0, 4.0));
        let e = position(f64::NAN, 0.0).unwrap_err();
        assert_eq!(e.primitive, Primitive::Target);
        assert!(matches!(e.fault, Fault::NonFinite { .. }));
        assert!(velocity(0.0, f64::INFINITY).is_err());
        assert!(acceleration(f64::NEG_INFINITY, 0.0).is_err());
    }
}
