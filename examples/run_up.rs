//! The run-up of a crank-rocker four-bar under a DC motor (SI units), and
//! its periodic steady state: forward dynamics from the definition's
//! generated equations of motion (`analysis dynamics`), integrated by
//! `mechanism::ode`.
//!
//! Ground pivots O2 = (0, 0), O4 = (0.30, 0); crank O2-A 0.10 m, coupler
//! A-B 0.25 m, rocker O4-B 0.18 m, B above the x axis at crank angle 0.
//! Crank 0.5 kg at the midpoint of O2-A, 4.0e-4 kg m^2 about it; a flywheel
//! on the crank, 2.0 kg centred at O2, 0.02 kg m^2; coupler 1.2 kg at the
//! midpoint of A-B, 6.5e-3 kg m^2; rocker 0.9 kg at the midpoint of O4-B,
//! 2.5e-3 kg m^2; gravity 9.81 m/s^2 along -y. The motor on the crank:
//! `tau = 1.2 (1 - omega / 40)` N m, counter-clockwise positive. Start at
//! crank angle 0 and rest.
//!
//! Run: `cargo run --release --example run_up` (a table, the steady state,
//! the reduced inertia and a flywheel sized for half the fluctuation; SVG
//! pictures to `target/plots/run_up/`), `-- --csv` (t = 0.00 .. 3.00 s by
//! 0.01: `t,phi,omega,alpha,theta3,theta4,motor_torque`, 17 significant
//! digits, Dormand-Prince 5(4) at relative tolerance 1e-12 stepping exactly
//! onto every row's time), `-- --steady` (one JSON object: `period`,
//! `mean_speed`, `max_speed`, `min_speed`, `delta` of the periodic steady
//! state, by shooting on the speed at crank angle 0).
#[macro_use]
#[path = "common/cli.rs"]
mod cli;
mod common;

use mechanism::ode::dopri5::Dopri5;
use mechanism::ode::machine::{self, Steady};

use common::run_up::*;

fn main() {
    let args = cli::parse(
        "run_up",
        "The run-up of a four-bar under a DC motor, its steady state, reduced inertia and flywheel.",
        &[
            cli::CSV,
            cli::flag("--steady", "print only the periodic steady state as one JSON object"),
        ],
    );
    let m = RunUp::<f64>::default();
    if args.flag("--csv") {
        outln!("t,phi,omega,alpha,theta3,theta4,motor_torque");
        for r in run_up(&m, &grid()).expect("the run-up integrates") {
            outln!("{}", common::csv_row(&r));
        }
        return;
    }
    let s = steady(&m);
    if args.flag("--steady") {
        outln!(
            "{{\"period\":{:.16e},\"mean_speed\":{:.16e},\"max_speed\":{:.16e},\"min_speed\":{:.16e},\"delta\":{:.16e}}}",
            s.period, s.mean_speed, s.max_speed, s.min_speed, s.delta
        );
        return;
    }
    report(&m, &s);
}

/// The table, the steady state, the reduced inertia, the flywheel and the
/// pictures.
fn report(m: &RunUp<f64>, s: &Steady<f64>) {
    outln!("Run-up of the four-bar under a DC motor tau = 1.2 (1 - omega/40) N m, from rest at phi = 0");
    let names = [
        "t_s",
        "phi_rad",
        "omega",
        "alpha",
        "theta3",
        "theta4",
        "torque_Nm",
    ];
    outln!("{}", common::header(&names, 12));
    let times: Vec<f64> = (0..=30).map(|k| k as f64 / 10.0).collect();
    let rows = run_up(m, &times).expect("the run-up integrates");
    for r in &rows {
        outln!("{}", common::table_row(r, 12, 4));
    }
    outln!(
        "\nSteady state (shooting, {} secant iterations, residual {:.1e} rad/s): period {:.6} s, mean speed {:.6} rad/s, max {:.6}, min {:.6}, delta {:.6}",
        s.iterations, s.residual, s.period, s.mean_speed, s.max_speed, s.min_speed, s.delta
    );
    outln!("\nReduced inertia over a turn (kg m^2) and its derivative (kg m^2/rad); gravity's Q (N m):");
    outln!("{}", common::header(&["phi_deg", "I", "dI/dphi", "Q"], 14));
    for k in 0..12 {
        let phi = (30.0 * k as f64).to_radians();
        let (i, di, q) = reduced(m, phi).expect("assembles");
        outln!("{}", common::table_row(&[30.0 * k as f64, i, di, q], 14, 6));
    }
    let target = 0.5 * s.delta;
    let fly = machine::flywheel(720, s.mean_speed, motor(s.mean_speed), target, |phi| {
        reduced(m, phi)
    })
    .expect("assembles");
    let mut bigger = *m;
    bigger.jf += fly.added;
    let check = steady(&bigger);
    outln!(
        "\nFlywheel for delta = {target:.6} (half of today's): energy fluctuation {:.6} J, mean reduced inertia {:.6} kg m^2, add {:.6} kg m^2; simulated with it: delta {:.6}",
        fly.energy, fly.mean_inertia, fly.added, check.delta
    );
    common::plots::write_and_report("run_up", pictures);
}

/// Speed against time in the run-up, speed against crank angle at steady
/// state, the reduced inertia over a turn.
fn pictures(dir: &std::path::Path) -> Result<Vec<std::path::PathBuf>, mechanism_plot::PlotError> {
    use mechanism_plot::Plot;
    let m = RunUp::<f64>::default();
    let rows = run_up(&m, &grid()).expect("the run-up integrates");
    let (t, w): (Vec<f64>, Vec<f64>) = rows.iter().map(|r| (r[0], r[2])).unzip();
    let s = steady(&m);
    let times: Vec<f64> = (0..=200).map(|k| s.period * k as f64 / 200.0).collect();
    let mut sys = Machine(m);
    let mut ode = Dopri5::new(&mut sys, 0.0, [0.0, s.omega_0], tight()).expect("starts");
    let mut turn = (Vec::new(), Vec::new());
    for &tk in &times {
        ode.advance(&mut sys, tk).expect("integrates");
        turn.0.push(ode.y()[0].to_degrees());
        turn.1.push(ode.y()[1]);
    }
    let phis: Vec<f64> = (0..=360).map(|d| d as f64).collect();
    let inertia: Vec<f64> = phis
        .iter()
        .map(|d| reduced(&m, d.to_radians()).map(|r| r.0).unwrap_or(f64::NAN))
        .collect();
    let files = [
        dir.join("run_up_speed.svg"),
        dir.join("steady_speed.svg"),
        dir.join("reduced_inertia.svg"),
    ];
    Plot::new("Run-up: crank speed")
        .x_axis("time", "s")
        .y_axis("ω", "rad/s")
        .series("ω", &t, &w)
        .write(&files[0])?;
    Plot::new("Steady state: crank speed over a turn")
        .x_axis("crank angle φ", "deg")
        .y_axis("ω", "rad/s")
        .series("ω", &turn.0, &turn.1)
        .write(&files[1])?;
    Plot::new("Reduced inertia on the crank")
        .x_axis("crank angle φ", "deg")
        .y_axis("I", "kg m²")
        .series("I(φ)", &phis, &inertia)
        .write(&files[2])?;
    Ok(files.to_vec())
}
