//! Drive and load models for the efforts of `analysis dynamics`: functions
//! of an input's rate (and position) that give the effort the generated
//! `dynamics(&pos, &rates, &efforts)` takes, so that a machine's ODE
//! (`System::rate`) reads `efforts = motor.torque(omega) + spring.effort(q,
//! omega)`. Generic over [`Real`] (`f32`, `f64`), `no_std`, no panics.
//!
//! Sign convention: an effort is positive along the input (counter-clockwise
//! for a crank's angle, along the guide for a slider, pushing for a
//! cylinder's length); its power is `effort * rate`.

use crate::scalar::Real;

/// A DC motor's steady-state torque-speed line (a permanent-magnet or
/// shunt motor at constant voltage, armature inductance neglected):
/// `torque = stall (1 - omega / no_load_speed)`: `stall` at rest, zero at
/// `no_load_speed`, negative (braking, generating) above it.
///
/// `stall`: torque at rest (F L, or F for a linear motor); `no_load_speed`:
/// the speed (rad/s, or L/s) where the torque vanishes, non-zero; its sign
/// is the direction the motor runs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DcMotor<T> {
    /// Torque at rest (N m for a rotary motor).
    pub stall: T,
    /// Speed at zero torque (rad/s), non-zero.
    pub no_load_speed: T,
}

impl<T: Real> DcMotor<T> {
    /// The motor of a stall torque (F L) and a no-load speed (rad/s).
    pub fn new(stall: T, no_load_speed: T) -> Self {
        DcMotor {
            stall,
            no_load_speed,
        }
    }

    /// The torque at speed `omega` (rad/s): `stall (1 - omega /
    /// no_load_speed)` (F L). A zero `no_load_speed` gives a non-finite
    /// value, which the integrators report as [`super::Halt::NonFinite`].
    pub fn torque(&self, omega: T) -> T {
        self.stall * (T::one() - omega / self.no_load_speed)
    }

    /// The mechanical power `torque(omega) * omega` (F L / s); largest,
    /// `stall * no_load_speed / 4`, at half the no-load speed.
    pub fn power(&self, omega: T) -> T {
        self.torque(omega) * omega
    }
}

/// A linear spring and a viscous damper acting on an input coordinate:
/// `effort = -stiffness (q - free) - damping q'`.
///
/// `stiffness` (F L / rad, or F / L) and `damping` (F L s / rad, or
/// F s / L) are non-negative; `free` is the input's value where the spring
/// is relaxed (rad or L). For a torsion spring on a crank, `q` is the crank
/// angle and the effort a torque; on a slider or cylinder, a force along it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SpringDamper<T> {
    /// Stiffness (F L / rad, or F / L).
    pub stiffness: T,
    /// The input's value at which the spring is relaxed (rad, or L).
    pub free: T,
    /// Viscous damping (F L s / rad, or F s / L).
    pub damping: T,
}

impl<T: Real> SpringDamper<T> {
    /// A spring of `stiffness` relaxed at `free` with viscous `damping`.
    pub fn new(stiffness: T, free: T, damping: T) -> Self {
        SpringDamper {
            stiffness,
            free,
            damping,
        }
    }

    /// The effort on the input at value `q` and rate `rate`:
    /// `-stiffness (q - free) - damping rate`.
    pub fn effort(&self, q: T, rate: T) -> T {
        -(self.stiffness * (q - self.free)) - self.damping * rate
    }

    /// The spring's stored energy `stiffness (q - free)^2 / 2` (F L); the
    /// damper dissipates `damping rate^2` (power).
    pub fn energy(&self, q: T) -> T {
        let d = q - self.free;
        T::lit(0.5) * self.stiffness * d * d
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    // Proves the torque line's two ends and its sign above no-load speed,
    // in f32 and f64 (exact at these binary-friendly values).
    #[test]
    fn dc_motor_line() {
        let m = DcMotor::new(1.25f64, 40.0);
        assert_eq!(m.torque(0.0), 1.25);
        assert_eq!(m.torque(40.0), 0.0);
        assert_eq!(m.torque(20.0), 0.625);
        assert!(m.torque(50.0) < 0.0);
        assert_eq!(m.power(20.0), 12.5);
        let m = DcMotor::new(1.25f32, 40.0);
        assert_eq!(m.torque(20.0), 0.625);
    }

    // Proves the spring-damper's effort opposes displacement and motion and
    // its energy's derivative is minus the spring's effort.
    #[test]
    fn spring_damper_effort_and_energy() {
        let s = SpringDamper::new(200.0f64, 0.5, 3.0);
        assert_eq!(s.effort(0.5, 0.0), 0.0);
        assert_eq!(s.effort(0.75, 0.0), -50.0);
        assert_eq!(s.effort(0.5, 2.0), -6.0);
        let (q, h) = (0.8, 1e-6);
        let de = (s.energy(q + h) - s.energy(q - h)) / (2.0 * h);
        assert!((de + s.effort(q, 0.0)).abs() < 1e-6);
    }
}
