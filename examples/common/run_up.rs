//! The run-up four-bar of `examples/run_up.rs` (SI units): its definition,
//! the machine as an ODE, the run-up, the steady state and the reduced
//! inertia; also read by `tests/dynamics/run_up.rs`, which checks them
//! against the global formulation of `mechanism-reference`.
#![allow(dead_code)]

use mechanism::mechanism;
use mechanism::ode::dopri5::{Dopri5, Options};
use mechanism::ode::drive::DcMotor;
use mechanism::ode::machine::{self, Steady};
use mechanism::ode::{Halt, System};

mechanism! {
    /// The `run_up` four-bar (m, kg, s). `jf`: the flywheel's moment of
    /// inertia (kg m^2), a parameter so that flywheel sizing can change it.
    pub RunUp {
        params { jf = 0.02 }
        analysis dynamics;
        let O2 = ground(0.0, 0.0);
        let O4 = ground(0.30, 0.0);
        let A = crank(O2, 0.10, phi) as crank;
        let B = rrr(A, 0.25, O4, 0.18, left) as (coupler, rocker);
        let G2 = point(crank, from O2, 0.05, 0 deg);
        let G3 = point(coupler, from A, 0.125, 0 deg);
        let G4 = point(rocker, from O4, 0.09, 0 deg);
        mass crank { m = 0.5, at = G2, j = 4.0e-4 };
        mass crank { m = 2.0, at = O2, j = jf };
        mass coupler { m = 1.2, at = G3, j = 6.5e-3 };
        mass rocker { m = 0.9, at = G4, j = 2.5e-3 };
        gravity (0.0, -9.81);
    }
}

/// The DC motor on the crank: 1.2 N m at rest, no torque at 40 rad/s.
pub const MOTOR: DcMotor<f64> = DcMotor {
    stall: 1.2,
    no_load_speed: 40.0,
};

/// The motor's torque (N m) at crank speed `omega` (rad/s):
/// `1.2 (1 - omega / 40)`.
pub fn motor(omega: f64) -> f64 {
    MOTOR.torque(omega)
}

/// The machine as an ODE: state `(phi, omega)`.
pub struct Machine(pub RunUp<f64>);

impl System<f64, 2> for Machine {
    type Error = mechanism::Error;
    fn rate(&mut self, _t: f64, y: &[f64; 2]) -> Result<[f64; 2], mechanism::Error> {
        let pos = self.0.position(&RunUpInput { phi: y[0] })?;
        let d = self.0.dynamics(
            &pos,
            &RunUpInput { phi: y[1] },
            &RunUpInput { phi: motor(y[1]) },
        )?;
        Ok([y[1], d.accels.phi])
    }
}

/// The integrator's tolerances: relative 1e-12, absolute 1e-12 (rad, rad/s).
pub fn tight() -> Options<f64> {
    Options::new(1e-12, 1e-12)
}

/// One row of the run-up: `t, phi, omega, alpha, theta3, theta4,
/// motor_torque`.
pub fn row(m: &RunUp<f64>, t: f64, y: &[f64; 2], rate: &[f64; 2]) -> [f64; 7] {
    let pos = m
        .position(&RunUpInput { phi: y[0] })
        .expect("the crank-rocker assembles at every crank angle");
    let (a, b, o4) = (pos.A, pos.B, pos.O4);
    let theta3 = (b.y - a.y).atan2(b.x - a.x);
    let theta4 = (b.y - o4.y).atan2(b.x - o4.x);
    [t, y[0], y[1], rate[1], theta3, theta4, motor(y[1])]
}

/// The run-up from rest at crank angle 0: a row at each of `times` (s,
/// increasing from 0), the integrator stepping exactly onto each.
pub fn run_up(m: &RunUp<f64>, times: &[f64]) -> Result<Vec<[f64; 7]>, Halt<f64, mechanism::Error>> {
    let mut sys = Machine(*m);
    let mut ode = Dopri5::new(&mut sys, 0.0, [0.0, 0.0], tight())?;
    let mut rows = Vec::with_capacity(times.len());
    for &t in times {
        ode.advance(&mut sys, t)?;
        rows.push(row(m, t, ode.y(), ode.rate()));
    }
    Ok(rows)
}

/// The periodic steady state (shooting from 30 rad/s, to 1e-11 rad/s).
pub fn steady(m: &RunUp<f64>) -> Steady<f64> {
    machine::steady_state(&mut Machine(*m), 30.0, tight(), 10.0, 1e-11, 50)
        .expect("the motor drives the four-bar round at a steady speed")
}

/// The reduced inertia `I(phi)` (kg m^2) and its derivative `dI/dphi`
/// (kg m^2/rad): the mass matrix, and twice the velocity-product term at a
/// unit speed (`h = I' omega^2 / 2` for one input); the generalized force of
/// gravity `Q(phi)` (N m).
pub fn reduced(m: &RunUp<f64>, phi: f64) -> Result<(f64, f64, f64), mechanism::Error> {
    let pos = m.position(&RunUpInput { phi })?;
    let d = m.dynamics(&pos, &RunUpInput { phi: 1.0 }, &RunUpInput { phi: 0.0 })?;
    Ok((
        d.mass[0][0],
        2.0 * d.velocity_terms[0],
        d.generalized_forces[0],
    ))
}

/// The grid of the CSV: 0.00 .. 3.00 s by 0.01 (301 times).
pub fn grid() -> Vec<f64> {
    (0..=300).map(|k| k as f64 / 100.0).collect()
}
