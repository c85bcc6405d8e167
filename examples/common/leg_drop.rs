//! The 2R leg of `examples/leg_drop.rs` (m, kg, s): hip motor on the ground,
//! knee motor carried by the thigh, a foot mass; the machine as an ODE with
//! the motors off or as a PD controller, and its energy. Also read by
//! `tests/dynamics/energy.rs`.
#![allow(dead_code)]

use mechanism::mechanism;
use mechanism::ode::drive::SpringDamper;
use mechanism::ode::System;

mechanism! {
    /// A 2R leg hanging from the hip H = (0, 0) (m, kg): thigh 0.40 m (2.0 kg
    /// at 0.18 m, 0.03 kg m^2), shank 0.38 m (1.2 kg at 0.16 m, 0.015 kg m^2)
    /// with a 0.3 kg foot at its end; `hip` from +x, `knee` relative to the
    /// thigh (rad, counter-clockwise); gravity along -y.
    pub LegDrop {
        analysis dynamics;
        dof 2;
        let H = ground(0.0, 0.0);
        let K = crank(H, 0.40, hip) as thigh;
        let F = crank(K, 0.38, knee, thigh) as shank;
        let Gt = point(thigh, from H, 0.18, 0 deg);
        let Gs = point(shank, from K, 0.16, 0 deg);
        mass thigh { m = 2.0, at = Gt, j = 0.03 };
        mass shank { m = 1.2, at = Gs, j = 0.015 };
        mass shank { m = 0.3, at = F };
        gravity (0.0, -9.81);
    }
}

/// The motors: off, or a PD controller holding `(hip, knee)` with gains
/// `kp` (N m/rad) and `kd` (N m s/rad).
#[derive(Clone, Copy, Debug)]
pub enum Motors {
    /// No torque.
    Off,
    /// `tau = kp (target - q) - kd q'` on each joint.
    Pd {
        /// The pose held (rad).
        target: [f64; 2],
        /// Stiffness (N m/rad).
        kp: f64,
        /// Damping (N m s/rad).
        kd: f64,
    },
}

impl Motors {
    /// The motors' torques (N m) at the state `(hip, knee, hip', knee')`.
    pub fn torques(&self, y: &[f64; 4]) -> [f64; 2] {
        match *self {
            Motors::Off => [0.0, 0.0],
            // A PD controller is a spring and damper on each input.
            Motors::Pd { target, kp, kd } => [
                SpringDamper::new(kp, target[0], kd).effort(y[0], y[2]),
                SpringDamper::new(kp, target[1], kd).effort(y[1], y[3]),
            ],
        }
    }
}

/// The leg with its motors as an ODE: state `(hip, knee, hip', knee')`.
pub struct Leg(pub LegDrop<f64>, pub Motors);

impl System<f64, 4> for Leg {
    type Error = mechanism::Error;
    fn rate(&mut self, _t: f64, y: &[f64; 4]) -> Result<[f64; 4], mechanism::Error> {
        let pos = self.0.position(&LegDropInput {
            hip: y[0],
            knee: y[1],
        })?;
        let [th, tk] = self.1.torques(y);
        let d = self.0.dynamics(
            &pos,
            &LegDropInput {
                hip: y[2],
                knee: y[3],
            },
            &LegDropInput { hip: th, knee: tk },
        )?;
        Ok([y[2], y[3], d.accels.hip, d.accels.knee])
    }
}

/// Kinetic plus potential energy (J, zero height at the hip) at the state
/// `y`, from the position and velocity analyses alone (each mass centre's
/// velocity and height, each link's angular velocity), not the dynamics.
pub fn energy(m: &LegDrop<f64>, y: &[f64; 4]) -> Result<f64, mechanism::Error> {
    let pos = m.position(&LegDropInput {
        hip: y[0],
        knee: y[1],
    })?;
    let vel = m.velocity(
        &pos,
        &LegDropInput {
            hip: y[2],
            knee: y[3],
        },
    )?;
    let g = 9.81;
    let parts = [
        (2.0, 0.03, vel.Gt, vel.thigh, pos.Gt.y),
        (1.2, 0.015, vel.Gs, vel.shank, pos.Gs.y),
        (0.3, 0.0, vel.F, vel.shank, pos.F.y),
    ];
    Ok(parts
        .iter()
        .map(|(mass, j, v, w, h)| 0.5 * mass * v.norm_squared() + 0.5 * j * w * w + mass * g * h)
        .sum())
}
