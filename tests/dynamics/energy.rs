//! Proves the equations of motion of a two-input definition conserve
//! energy: the 2R leg of `defs.rs` (a hip motor on the ground, a knee motor
//! carried by the thigh: a double pendulum) released from rest under
//! gravity with both motors off, integrated for 10 s by Dormand-Prince
//! 5(4) at relative tolerance 1e-13. The energy is computed without the
//! dynamics: kinetic from the generated velocity analysis (each mass
//! centre's velocity and each link's angular velocity), potential from the
//! mass centres' heights. Only a right `M` and `h` (and gravity's `Q`)
//! conserve it; the tolerance 1e-10 relative is the integrator's
//! accumulated error (about 1e4 steps of local error below 1e-14 each).
use super::defs::{Leg, LegInput};
use mechanism::ode::dopri5::{Dopri5, Options};
use mechanism::ode::System;

struct Free(Leg<f64>);

impl System<f64, 4> for Free {
    type Error = mechanism::Error;
    fn rate(&mut self, _t: f64, y: &[f64; 4]) -> Result<[f64; 4], mechanism::Error> {
        let pos = self.0.position(&LegInput { hip: y[0], knee: y[1] })?;
        let rates = LegInput { hip: y[2], knee: y[3] };
        let d = self.0.dynamics(&pos, &rates, &LegInput { hip: 0.0, knee: 0.0 })?;
        Ok([y[2], y[3], d.accels.hip, d.accels.knee])
    }
}

/// Kinetic plus potential energy (J) at the state `y = (hip, knee, hip',
/// knee')`, from the position and velocity analyses.
fn energy(m: &Leg<f64>, y: &[f64; 4]) -> f64 {
    let pos = m.position(&LegInput { hip: y[0], knee: y[1] }).unwrap();
    let vel = m.velocity(&pos, &LegInput { hip: y[2], knee: y[3] }).unwrap();
    let g = 9.81;
    let parts = [
        (2.0, 0.03, vel.Gt, vel.thigh, pos.Gt.y),
        (1.2, 0.015, vel.Gs, vel.shank, pos.Gs.y),
        (0.3, 0.0, vel.F, vel.shank, pos.F.y),
    ];
    parts
        .iter()
        .map(|(mass, j, v, w, h)| 0.5 * mass * v.norm_squared() + 0.5 * j * w * w + mass * g * h)
        .sum()
}

#[test]
fn a_released_leg_keeps_its_energy_for_ten_seconds() {
    let m = Leg::<f64>::default();
    let y0 = [0.3, 0.9, 0.0, 0.0];
    let e0 = energy(&m, &y0);
    let mut sys = Free(m);
    let mut ode = Dopri5::new(&mut sys, 0.0, y0, Options::new(1e-13, 1e-13)).unwrap();
    // The energy's scale: the largest of |E0| and the kinetic energy the
    // fall reaches (the potential's swing, ~ m g l = 30 J here).
    let scale = e0.abs().max(10.0);
    let mut worst: f64 = 0.0;
    for k in 1..=100 {
        ode.advance(&mut sys, k as f64 * 0.1).unwrap();
        let e = energy(&m, ode.y());
        worst = worst.max((e - e0).abs() / scale);
    }
    assert!(worst < 1e-10, "energy drift {worst:e} over 10 s; steps {:?}", ode.steps());
    // It did move: the knee swung through more than a radian.
    assert!(ode.y()[2].abs() + ode.y()[3].abs() > 0.1);
}
