//! Proves the equations of motion of a two-input definition conserve
//! energy: the 2R leg of `examples/leg_drop.rs` (a hip motor on the ground,
//! a knee motor carried by the thigh: a double pendulum) released from rest
//! under gravity with both motors off, integrated for 10 s by
//! Dormand-Prince 5(4) at relative tolerance 1e-13. The energy is computed
//! without the dynamics: kinetic from the generated velocity analysis (each
//! mass centre's velocity and each link's angular velocity), potential from
//! the mass centres' heights. Only a right `M` and `h` (and gravity's `Q`)
//! conserve it; the tolerance, 1e-10 relative (the issue's), bounds the
//! integrator's accumulated error (about 1.3e4 steps of local error below
//! 1e-13 each; 3.5e-13 measured).
use super::leg_drop_scene::{energy, Leg, LegDrop, Motors};
use mechanism::ode::dopri5::{Dopri5, Options};

#[test]
fn a_released_leg_keeps_its_energy_for_ten_seconds() {
    let m = LegDrop::<f64>::default();
    let y0 = [0.3, 0.9, 0.0, 0.0];
    let e0 = energy(&m, &y0).unwrap();
    let mut sys = Leg(m, Motors::Off);
    let mut ode = Dopri5::new(&mut sys, 0.0, y0, Options::new(1e-13, 1e-13)).unwrap();
    let mut worst: f64 = 0.0;
    for k in 1..=100 {
        ode.advance(&mut sys, k as f64 * 0.1).unwrap();
        let e = energy(&m, ode.y()).unwrap();
        worst = worst.max((e - e0).abs() / e0.abs());
    }
    eprintln!(
        "leg energy drift over 10 s: {worst:.1e} relative, steps {:?}",
        ode.steps()
    );
    assert!(
        worst < 1e-10,
        "energy drift {worst:e} over 10 s; steps {:?}",
        ode.steps()
    );
    // It did move: the joints are not at rest at the end.
    assert!(ode.y()[2].abs() + ode.y()[3].abs() > 0.1);
}

// Proves the PD-held leg settles: from the same release the controller
// brings it to rest near its pose (gravity leaves a steady offset of about
// m g l / kp, below 0.1 rad with kp = 200 N m/rad) within 10 s.
#[test]
fn a_pd_controller_holds_the_leg() {
    let m = LegDrop::<f64>::default();
    let target = [(-80.0f64).to_radians(), 30.0f64.to_radians()];
    let mut sys = Leg(
        m,
        Motors::Pd {
            target,
            kp: 200.0,
            kd: 20.0,
        },
    );
    let mut ode = Dopri5::new(
        &mut sys,
        0.0,
        [0.3, 0.9, 0.0, 0.0],
        Options::new(1e-10, 1e-10),
    )
    .unwrap();
    ode.advance(&mut sys, 10.0).unwrap();
    let y = ode.y();
    assert!(
        (y[0] - target[0]).abs() < 0.1 && (y[1] - target[1]).abs() < 0.1,
        "{y:?}"
    );
    assert!(y[2].abs() < 1e-3 && y[3].abs() < 1e-3, "{y:?}");
}
