//! The dynamics section: the run-up four-bar (`examples/common/run_up.rs`)
//! simulated three ways.
//!
//! - Generated: `position` then `dynamics` give `q''` from the state
//!   `(phi, omega)` (two numbers); the loops are closed by the position
//!   analysis at every evaluation.
//! - Dense global formulation, as a user writes it with nalgebra: each link's
//!   centre of mass and angle (nine coordinates, eighteen states), the four
//!   pins' eight constraints, and the accelerations with the multipliers from
//!   one 17 x 17 `DMatrix` LU per evaluation (no stabilisation).
//! - Pinocchio (`scripts/pinocchio-four-bar.py`, read from
//!   `target/report/pinocchio.json` when it is there): the four-bar as a tree
//!   of three revolute joints with the loop closed by a point constraint,
//!   `constraintDynamics` called from Python.
//!
//! Measured: ns per `q''` and per RK4 step (median of interleaved rounds over
//! 64 states), how far each loop is open after 10 s of the run-up (RK4,
//! 1 ms), and `q''` against the double-double global formulation
//! (`mechanism_reference::multibody`) at random states.

use crate::dynamics_dense::{Dense, COUPLER, CRANK, GROUND, ROCKER};
use crate::run_up::{motor, Machine, RunUp, RunUpInput};
use crate::timing::{self, Sweep};
use mechanism::ode::rk4;
use mechanism_reference::constraint::V2;
use mechanism_reference::multibody::{forward, Anchor, Input, Joint, Model, Part};
use mechanism_reference::Dd;
use std::fmt::Write as _;
use std::hint::black_box;

/// States timed (crank angle uniform over a turn, speed 0..40 rad/s).
const STATES: usize = 64;
/// Random states of the error table.
const DRAWS: usize = 1000;
/// RK4 step (s) and the run's length (s).
const STEP: f64 = 1e-3;
const SECONDS: f64 = 10.0;

/// The run-up four-bar for the double-double reference: crank (with the
/// flywheel as a second part), coupler, rocker, each in a frame from its
/// first pin along the link.
fn reference_model() -> Model {
    let part = |mass, x, inertia| Part {
        mass,
        at: V2::new(x, 0.0),
        inertia,
    };
    let on = Anchor::on;
    Model {
        bodies: vec![
            vec![part(0.5, 0.05, 4.0e-4), part(2.0, 0.0, 0.02)],
            vec![part(1.2, 0.125, 6.5e-3)],
            vec![part(0.9, 0.09, 2.5e-3)],
        ],
        joints: vec![
            Joint::Revolute(on(0, 0.0, 0.0), Anchor::ground(0.0, 0.0)),
            Joint::Revolute(on(0, CRANK, 0.0), on(1, 0.0, 0.0)),
            Joint::Revolute(on(1, COUPLER, 0.0), on(2, ROCKER, 0.0)),
            Joint::Revolute(on(2, 0.0, 0.0), Anchor::ground(GROUND, 0.0)),
        ],
        inputs: vec![Input::Angle {
            body: 0,
            carrier: None,
            offset: Dd::ZERO,
        }],
        loads: vec![],
        gravity: V2::new(0.0, -9.81),
    }
}

/// The reference's `q''` at `(phi, omega)` with the motor's torque.
fn reference_accel(model: &Model, phi: f64, omega: f64) -> f64 {
    let pos = RunUp::<f64>::default()
        .position(&RunUpInput { phi })
        .expect("assembles");
    let frame = |o: mechanism::Point2<f64>, a: mechanism::Point2<f64>| {
        [o.x, o.y, (a.y - o.y).atan2(a.x - o.x)]
    };
    let start = [[0.0, 0.0, phi], frame(pos.A, pos.B), frame(pos.O4, pos.B)];
    forward(model, &[phi], &[omega], &[motor(omega)], &start)
        .expect("the reference solves the four-bar")
        .accels[0]
        .to_f64()
}

/// Deterministic states: crank angle and speed.
fn states(n: usize, seed: u64) -> Vec<(f64, f64)> {
    let mut s = seed;
    let mut next = || {
        s ^= s >> 12;
        s ^= s << 25;
        s ^= s >> 27;
        (s.wrapping_mul(0x2545_F491_4F6C_DD1D) >> 11) as f64 / (1u64 << 53) as f64
    };
    (0..n)
        .map(|_| (std::f64::consts::TAU * next(), 40.0 * next()))
        .collect()
}

/// The Pinocchio figures, if the script's output is there.
fn pinocchio(dir: &std::path::Path) -> Option<serde_json::Value> {
    let text = std::fs::read_to_string(dir.join("pinocchio.json")).ok()?;
    serde_json::from_str(&text).ok()
}

/// Loop closure of the generated pose at crank angle `phi`: the largest
/// difference of a link's length from its nominal (m).
fn generated_open(phi: f64) -> f64 {
    let p = RunUp::<f64>::default()
        .position(&RunUpInput { phi })
        .expect("assembles");
    let d = |a: mechanism::Point2<f64>, b: mechanism::Point2<f64>, l: f64| {
        ((b.x - a.x).hypot(b.y - a.y) - l).abs()
    };
    d(p.O2, p.A, CRANK)
        .max(d(p.A, p.B, COUPLER))
        .max(d(p.O4, p.B, ROCKER))
}

/// Times: (name, ns per call) medians with min-max.
fn timings(dense: &Dense) -> Vec<(&'static str, (f64, f64, f64))> {
    let m = RunUp::<f64>::default();
    let st = states(STATES, 0x0d1a_5eed);
    let full: Vec<[f64; 18]> = st.iter().map(|&(p, w)| dense.state(p, w)).collect();
    let kin: Sweep = Box::new(|| {
        let mut s = 0.0;
        for &(phi, w) in &st {
            let pos = m
                .position(&RunUpInput {
                    phi: black_box(phi),
                })
                .unwrap();
            let vel = m.velocity(&pos, &RunUpInput { phi: w }).unwrap();
            let acc = m
                .acceleration(&pos, &vel, &RunUpInput { phi: 10.0 })
                .unwrap();
            s += acc.B.x;
        }
        s
    });
    let qdd: Sweep = Box::new(|| {
        let mut s = 0.0;
        for &(phi, w) in &st {
            let pos = m
                .position(&RunUpInput {
                    phi: black_box(phi),
                })
                .unwrap();
            let d = m
                .dynamics(&pos, &RunUpInput { phi: w }, &RunUpInput { phi: motor(w) })
                .unwrap();
            s += d.accels.phi;
        }
        s
    });
    let dense_qdd: Sweep = Box::new(|| {
        let mut s = 0.0;
        for y in &full {
            let y = black_box(y);
            s += dense.accel(&y[..9], &y[9..], motor(y[11])).unwrap()[2];
        }
        s
    });
    let step: Sweep = Box::new(|| {
        let mut s = 0.0;
        let mut sys = Machine(m);
        for &(phi, w) in &st {
            s += rk4::step(&mut sys, 0.0, &black_box([phi, w]), STEP).unwrap()[1];
        }
        s
    });
    let dense_step: Sweep = Box::new(|| {
        let mut s = 0.0;
        let mut sys = Dense::new();
        for y in &full {
            s += rk4::step(&mut sys, 0.0, black_box(y), STEP).unwrap()[11];
        }
        s
    });
    let sweeps = [
        (&kin, st.len()),
        (&qdd, st.len()),
        (&dense_qdd, st.len()),
        (&step, st.len()),
        (&dense_step, st.len()),
    ];
    let t = timing::interleaved(&sweeps, crate::ROUNDS, crate::MIN_SAMPLE_NS);
    let names = [
        "generated position + velocity + acceleration",
        "generated q'' (position + dynamics)",
        "dense global formulation q'' (nalgebra LU 17 x 17)",
        "generated RK4 step (2 states)",
        "dense RK4 step (18 states)",
    ];
    names
        .iter()
        .zip(&t)
        .map(|(n, v)| (*n, timing::stats(v)))
        .collect()
}

/// The section's markdown; `dir` is where `pinocchio.json` may be.
/// The timing table: the generated code, the dense formulation, Pinocchio.
fn timing_table(md: &mut String, t: &[(&str, (f64, f64, f64))], pin: Option<&serde_json::Value>) {
    let _ = writeln!(
        md,
        "| evaluation | ns median | min - max | x generated q'' |"
    );
    let _ = writeln!(md, "|---|---:|---:|---:|");
    let qdd = t[1].1 .0;
    for (name, (med, lo, hi)) in t {
        let _ = writeln!(
            md,
            "| {name} | {med:.1} | {lo:.1} - {hi:.1} | {:.2} |",
            med / qdd
        );
    }
    if let Some(p) = pin {
        let call = p["ns_call"].as_f64().unwrap_or(f64::NAN);
        let empty = p["ns_empty"].as_f64().unwrap_or(f64::NAN);
        let _ = writeln!(
            md,
            "| Pinocchio {} `constraintDynamics` (Python {}) | {call:.0} | | {:.0} |",
            p["version"].as_str().unwrap_or("?"),
            p["python"].as_str().unwrap_or("?"),
            call / qdd
        );
        let _ = writeln!(
            md,
            "| an empty Python function with the same arguments | {empty:.0} | | {:.0} |",
            empty / qdd
        );
        let run = p["run_seconds"].as_f64().unwrap_or(f64::NAN);
        let _ = writeln!(
            md,
            "| Pinocchio RK4 step (Python loop, 10 s run / 10 000 steps) | {:.0} | | {:.0} |",
            run / 1e4 * 1e9,
            run / 1e4 * 1e9 / qdd
        );
    }
}

/// The loop drift after the 10 s run-up with RK4 at 1 ms: the generated
/// run's and the dense run's (m), the table written.
fn drift_table(md: &mut String, dense: &Dense, pin: Option<&serde_json::Value>) -> (f64, f64) {
    // The 10 s run-up with RK4 at 1 ms.
    let steps = (SECONDS / STEP).round() as u32;
    let m = RunUp::<f64>::default();
    let y = rk4::integrate(&mut Machine(m), 0.0, &[0.0, 0.0], SECONDS, steps)
        .expect("the run-up integrates");
    let mut sys = Dense::new();
    let y0 = dense.state(0.0, 0.0);
    let yd = rk4::integrate(&mut sys, 0.0, &y0, SECONDS, steps).expect("the dense run integrates");
    let _ = writeln!(
        md,
        "\nLoop drift: the run-up from rest over {SECONDS} s with the classical RK4 at {} ms \
         (each formulation its own state), how far the loop is open at the end (m): the largest \
         distance between the two sides of a pin (dense, Pinocchio) or the largest error of a \
         link's length in the generated pose.\n",
        STEP * 1e3
    );
    // The speed at 10 s from the `run_up` example's Dormand-Prince run at
    // relative tolerance 1e-12: each RK4 run's truncation error beside it.
    let converged = crate::run_up::run_up(&m, &[SECONDS]).expect("the run-up integrates")[0][2];
    let _ = writeln!(
        md,
        "| formulation | loop open after 10 s (m) | crank speed at 10 s (rad/s) | its error (rad/s) |"
    );
    let _ = writeln!(md, "|---|---:|---:|---:|");
    let ours = generated_open(y[0]);
    let row = |md: &mut String, name: &str, open: f64, w: f64| {
        let _ = writeln!(
            md,
            "| {name} | {open:.1e} | {w:.12} | {:.1e} |",
            w - converged
        );
    };
    row(md, "generated (state phi, omega)", ours, y[1]);
    let theirs = dense.open(&yd);
    row(md, "dense global formulation (18 states)", theirs, yd[11]);
    if let Some(p) = pin {
        let open = p["open_10s"].as_f64().unwrap_or(f64::NAN);
        let w = p["omega_10s"].as_f64().unwrap_or(f64::NAN);
        row(md, "Pinocchio (no corrector)", open, w);
    }
    let _ = writeln!(
        md,
        "\nThe error column is against the generated definition's Dormand-Prince run at \
         relative tolerance 1e-12 (the `run_up` example's, held to the independent reference \
         in `tests/dynamics/run_up.rs`): {converged:.12} rad/s. The RK4 runs differ from it \
         by their truncation error at 1 ms, which depends on the coordinates integrated."
    );
    (ours, theirs)
}

/// The errors of `q''` against the double-double reference: the generated
/// code's relative to the largest and to each state's own `q''`, and the
/// dense formulation's relative to each state's own; the table written.
fn error_table(md: &mut String, dense: &Dense, pin: Option<&serde_json::Value>) -> (f64, f64, f64) {
    let m = RunUp::<f64>::default();
    // Errors against the double-double reference: the largest error relative
    // to the largest |q''| of the draws (the report's column scale), and the
    // largest relative to each state's own |q''| (large where q'' crosses 0).
    let model = reference_model();
    let draws = states(DRAWS, 0x0e77_0123);
    let refs: Vec<f64> = draws
        .iter()
        .map(|&(p, w)| reference_accel(&model, p, w))
        .collect();
    let column = refs.iter().fold(0.0f64, |s, r| s.max(r.abs()));
    let (mut ours_err, mut ours_own, mut dense_err, mut dense_own) =
        (0.0f64, 0.0f64, 0.0f64, 0.0f64);
    for (&(phi, w), &r) in draws.iter().zip(&refs) {
        let pos = m.position(&RunUpInput { phi }).unwrap();
        let d = m
            .dynamics(&pos, &RunUpInput { phi: w }, &RunUpInput { phi: motor(w) })
            .unwrap();
        ours_err = ours_err.max((d.accels.phi - r).abs() / column);
        ours_own = ours_own.max((d.accels.phi - r).abs() / r.abs());
        let s = dense.state(phi, w);
        let a = dense.accel(&s[..9], &s[9..], motor(w)).unwrap()[2];
        dense_err = dense_err.max((a - r).abs() / column);
        dense_own = dense_own.max((a - r).abs() / r.abs());
    }
    let _ = writeln!(
        md,
        "\n`q''` against the double-double global formulation with multipliers \
         (`mechanism_reference::multibody`) over {DRAWS} random states (the same draws for \
         the generated code and the dense formulation, whose state comes from the generated \
         pose and its own velocity solve; Pinocchio at its own 100 states): the largest error \
         relative to the largest |q''| of the draws ({column:.0} rad/s^2), and relative to the \
         state's own |q''| (large only where q'' crosses zero and its terms cancel):\n"
    );
    let _ = writeln!(
        md,
        "| formulation | relative to the largest q'' | relative to the state's q'' |"
    );
    let _ = writeln!(md, "|---|---:|---:|");
    let _ = writeln!(md, "| generated | {ours_err:.1e} | {ours_own:.1e} |");
    let _ = writeln!(
        md,
        "| dense global formulation (f64) | {dense_err:.1e} | {dense_own:.1e} |"
    );
    if let Some(p) = pin {
        let (mut e, mut own, mut col) = (0.0f64, 0.0f64, 0.0f64);
        let mut pairs = Vec::new();
        for s in p["states"].as_array().into_iter().flatten() {
            let (phi, w) = (
                s["phi"].as_f64().unwrap_or(0.0),
                s["omega"].as_f64().unwrap_or(0.0),
            );
            let got = s["qdd_crank"].as_f64().unwrap_or(f64::NAN);
            let r = reference_accel(&model, phi, w);
            col = col.max(r.abs());
            pairs.push((got, r));
        }
        for (got, r) in pairs {
            e = e.max((got - r).abs() / col);
            own = own.max((got - r).abs() / r.abs());
        }
        let _ = writeln!(md, "| Pinocchio (its 100 states) | {e:.1e} | {own:.1e} |");
    }
    (ours_err, ours_own, dense_own)
}

pub fn section(dir: &std::path::Path) -> String {
    let mut md = String::new();
    let dense = Dense::new();
    let t = timings(&dense);
    let pin = pinocchio(dir);
    let _ = writeln!(md, "## Dynamics\n");
    let _ = writeln!(
        md,
        "The run-up four-bar of `examples/run_up.rs` (`examples/report/dynamics.rs`): \
         ns per call, median and min-max over {} interleaved rounds of {STATES} states \
         (crank angle over a turn, speed 0..40 rad/s, the motor's torque). The dense \
         global formulation is what a user writes with nalgebra: nine coordinates (each \
         link's centre of mass and angle), eight pin constraints, the accelerations and \
         multipliers from one 17 x 17 `DMatrix` LU per evaluation. Pinocchio: \
         `scripts/pinocchio-four-bar.py` (a tree of three revolute joints, the loop closed \
         by a point constraint, `constraintDynamics` called from Python, best of 7 timeit runs).\n",
        crate::ROUNDS
    );
    timing_table(&mut md, &t, pin.as_ref());
    let qdd = t[1].1 .0;
    let (ours, theirs) = drift_table(&mut md, &dense, pin.as_ref());
    let (ours_err, ours_own, dense_own) = error_table(&mut md, &dense, pin.as_ref());
    // Targets.
    let kin = t[0].1 .0;
    let dense_qdd = t[2].1 .0;
    let met = |ok: bool| if ok { "met" } else { "not met" };
    let _ = writeln!(md, "\n### Targets (dynamics)\n");
    let _ = writeln!(
        md,
        "- one q'' at most 2.5 x position + velocity + acceleration: {:.2} x ({qdd:.1} ns against {kin:.1} ns), {}",
        qdd / kin,
        met(qdd <= 2.5 * kin)
    );
    let _ = writeln!(
        md,
        "- at least 10 x faster than the dense global formulation: {:.1} x ({dense_qdd:.1} ns against {qdd:.1} ns), {}",
        dense_qdd / qdd,
        met(dense_qdd >= 10.0 * qdd)
    );
    let _ = writeln!(
        md,
        "- the loop closed to rounding after 10 s: {ours:.1e} m (dense: {theirs:.1e} m), {}",
        met(ours <= 1e-15)
    );
    let _ = writeln!(
        md,
        "- q'' within 1e-13 of the double-double reference: {ours_err:.1e} of the largest q'' \
         ({ours_own:.1e} of the state's own, where q'' crosses zero; the dense f64 formulation \
         {dense_own:.1e} there), {}; 7 definitions at random efforts in \
         `tests/dynamics/global_reference.rs`, at most 7.0e-14 of each state's largest q''\n",
        met(ours_err <= 1e-13)
    );
    md
}
