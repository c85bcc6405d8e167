//! A 2R leg released from rest under gravity (two inputs: a hip motor on the
//! ground, a knee motor carried by the thigh), its motors given as torques:
//! off (a double pendulum; the energy stays constant) or a PD controller
//! holding a pose. Forward dynamics from the generated equations of motion
//! (`analysis dynamics`), Dormand-Prince 5(4) at relative tolerance 1e-13.
//!
//! Run: `cargo run --release --example leg_drop` (motors off: angles, rates
//! and the energy's drift every 0.5 s over 10 s) or `-- --pd` (the PD
//! controller holding hip -80 deg, knee 30 deg from the same release), or
//! `-- --csv` (the table as CSV, 17 significant digits).
#[macro_use]
#[path = "common/cli.rs"]
mod cli;
mod common;

use common::leg_drop::{energy, Leg, LegDrop, Motors};
use mechanism::ode::dopri5::{Dopri5, Options};

fn main() {
    let args = cli::parse(
        "leg_drop",
        "A 2R leg released from rest under gravity, motors off or holding a pose (PD).",
        &[
            cli::CSV,
            cli::flag(
                "--pd",
                "the motors as a PD controller holding hip -80 deg, knee 30 deg",
            ),
        ],
    );
    let m = LegDrop::<f64>::default();
    let motors = if args.flag("--pd") {
        Motors::Pd {
            target: [(-80.0f64).to_radians(), 30.0f64.to_radians()],
            kp: 200.0,
            kd: 20.0,
        }
    } else {
        Motors::Off
    };
    let y0 = [0.3, 0.9, 0.0, 0.0];
    let e0 = energy(&m, &y0).expect("assembles");
    let mut sys = Leg(m, motors);
    let mut ode = Dopri5::new(&mut sys, 0.0, y0, Options::new(1e-13, 1e-13)).expect("starts");
    let names = [
        "t",
        "hip",
        "knee",
        "hip_rate",
        "knee_rate",
        "energy",
        "drift",
    ];
    let csv = args.flag("--csv");
    if csv {
        outln!("{}", names.join(","));
    } else {
        outln!("2R leg released from rest at hip 0.3 rad, knee 0.9 rad; motors {motors:?}");
        outln!(
            "rad, rad/s, J; drift = (E - E0) / |E0|\n{}",
            common::header(&names, 13)
        );
    }
    for k in 0..=20 {
        let t = 0.5 * k as f64;
        ode.advance(&mut sys, t).expect("integrates");
        let y = *ode.y();
        let e = energy(&m, &y).expect("assembles");
        let row = [t, y[0], y[1], y[2], y[3], e, (e - e0) / e0.abs()];
        if csv {
            outln!("{}", common::csv_row(&row));
        } else {
            outln!("{}", common::table_row(&row, 13, 6));
        }
    }
    if !csv {
        let (accepted, rejected) = ode.steps();
        outln!("steps: {accepted} accepted, {rejected} rejected");
    }
}
