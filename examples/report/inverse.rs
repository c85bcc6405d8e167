//! The inverse-kinematics section: the five-bar robot given its end point
//! (`scenes::FiveBarIk`, written as drawn: a target driver and two RRRs
//! hanging on it), its two motor angles, rates and accelerations over the
//! workspace, against a double-double reference and a Newton baseline.
//!
//! Inputs: the end points of the forward five-bar (`scenes::FiveBar`) at a
//! 60 x 60 grid of motor angles (q1 in 70..140 deg, q2 in 10..80 deg), in
//! rows taken in alternate directions, each one the exact `f64` point the
//! forward code gave, where both elbows are 3 deg or more from straight; the end
//! point moves at (0.3, -0.2) m/s and accelerates at (1.5, 2.5) m/s^2.
//!
//! Reference: `mechanism_reference::groups` in double-double from the exact
//! inputs, each elbow by its own RRR (`rrr_position`, `rrr_rates`,
//! `rrr_accelerations`) with the lengths 0.1 and 0.16, and the motor angles
//! by its `atan2`; it shares no code with the core.
//!
//! Baseline: Newton on the loop closure of the two arms (four equations in
//! the two motor angles and the two distal links' angles) with nalgebra's
//! fixed-size LU, warm-started from the previous end point's answer, then
//! the rate and acceleration systems with the converged Jacobian: the usual
//! numerical inverse kinematics.

use crate::baselines::{self, IK_BASE as BASE, IK_DIST as DIST, IK_PROX as PROX};
use crate::scenes::{FiveBar, FiveBarIk, FiveBarIkInput, FiveBarInput};
use crate::timing::{self, Sweep};
use mechanism::Real;
use mechanism_reference::groups::{rrr_accelerations, rrr_position, rrr_rates, v};
use mechanism_reference::Dd;
use std::fmt::Write as _;
use std::hint::black_box;

/// Grid side (inputs: `SIDE * SIDE`).
const SIDE: usize = 60;
/// The end point's velocity (m/s) and acceleration (m/s^2).
const V: (f64, f64) = (0.3, -0.2);
const A: (f64, f64) = (1.5, 2.5);
/// Columns: the motor angles, their rates, their accelerations.
const NAMES: [&str; 6] = ["q1", "q2", "d/dt q1", "d/dt q2", "d2/dt2 q1", "d2/dt2 q2"];

/// The smallest sine of an elbow angle kept (the angle between an arm and
/// its distal link): 3 deg from the workspace's edge, where the arms
/// stretch out or fold and the rates grow without bound.
const MIN_ELBOW_SINE: f64 = 0.052;

/// The end points (m) of the grid whose elbows are both at least 3 deg
/// from straight, and how many grid points were left out.
fn grid() -> (Vec<(f64, f64)>, usize) {
    let fk = FiveBar::<f64>::default();
    let mut out = Vec::with_capacity(SIDE * SIDE);
    for i in 0..SIDE {
        // Rows in alternate directions: each point next to the last (a
        // path, as a warm start expects).
        for jj in 0..SIDE {
            let j = if i % 2 == 0 { jj } else { SIDE - 1 - jj };
            let q1 = (70.0 + 70.0 * i as f64 / (SIDE - 1) as f64).to_radians();
            let q2 = (10.0 + 70.0 * j as f64 / (SIDE - 1) as f64).to_radians();
            let p = fk.position(&FiveBarInput { q1, q2 }).expect("assembles");
            let sine = |o: f64, k: mechanism::Point2<f64>| {
                let (u, w) = ((k.x - o, k.y), (p.P.x - k.x, p.P.y - k.y));
                (u.0 * w.1 - u.1 * w.0) / (PROX * DIST)
            };
            if sine(0.0, p.A).abs().min(sine(BASE, p.C).abs()) >= MIN_ELBOW_SINE {
                out.push((p.P.x, p.P.y));
            }
        }
    }
    let left_out = SIDE * SIDE - out.len();
    (out, left_out)
}

/// The reference's columns at end point `p`.
fn reference(p: (f64, f64)) -> Option<[Dd; 6]> {
    let (o1, o2, pp) = (v(0.0, 0.0), v(BASE, 0.0), v(p.0, p.1));
    let (vp, ap, zero) = (v(V.0, V.1), v(A.0, A.1), v(0.0, 0.0));
    let a = rrr_position(o1, PROX, pp, DIST, true)?;
    let c = rrr_position(o2, PROX, pp, DIST, false)?;
    let (w1, w3) = rrr_rates(o1, pp, a, zero, vp)?;
    let (w2, w4) = rrr_rates(o2, pp, c, zero, vp)?;
    let (al1, _) = rrr_accelerations(o1, pp, a, zero, ap, w1, w3)?;
    let (al2, _) = rrr_accelerations(o2, pp, c, zero, ap, w2, w4)?;
    let q1 = Dd::atan2(a[1], a[0]);
    let q2 = Dd::atan2(c[1], c[0] - Dd::from(BASE));
    Some([q1, q2, w1, w2, al1, al2])
}

/// The generated solve in `T` at end point `p`, as the columns.
fn generated<T: Real>(m: &FiveBarIk<T>, p: (f64, f64)) -> Option<[f64; 6]> {
    let inp = |x: f64, y: f64| FiveBarIkInput {
        x: T::lit(x),
        y: T::lit(y),
    };
    let s = m
        .solve(&inp(p.0, p.1), &inp(V.0, V.1), &inp(A.0, A.1))
        .ok()?;
    let (pos, vel, acc) = (&s.position, &s.velocity, &s.acceleration);
    Some([pos.arm1, pos.arm2, vel.arm1, vel.arm2, acc.arm1, acc.arm2].map(T::as_f64))
}

/// Newton's answers over the grid, warm-started along it.
fn newton_rows(g: &[(f64, f64)], guess0: [f64; 4]) -> (Vec<Option<[f64; 6]>>, Vec<u32>) {
    let mut guess = guess0;
    let mut iterations = Vec::new();
    let rows = g
        .iter()
        .map(|&p| {
            let o = baselines::five_bar_ik_newton(p, V, A, guess)?;
            iterations.push(o.iterations);
            // An answer on the other elbow is no answer to this one: the
            // definition's elbows turn the distal links clockwise from arm
            // 1 and counter-clockwise from arm 2 (sin(t3 - q1) < 0 <
            // sin(t4 - q2)).
            let elbow = |q: f64, t: f64| (t - q).sin();
            if elbow(o.q[0], o.q[1]) >= 0.0 || elbow(o.q[2], o.q[3]) <= 0.0 {
                return None;
            }
            guess = o.q;
            Some([o.q[0], o.q[2], o.w[0], o.w[2], o.al[0], o.al[2]])
        })
        .collect();
    (rows, iterations)
}

/// Max over the inputs of each column's error: angles absolute (rad, up to
/// whole turns), the others relative to the column's largest |reference|
/// value.
fn errors(rows: &[Option<[f64; 6]>], refs: &[Option<[Dd; 6]>]) -> [f64; 6] {
    let mut scale = [0.0f64; 6];
    for r in refs.iter().flatten() {
        for k in 0..6 {
            scale[k] = scale[k].max(r[k].to_f64().abs());
        }
    }
    let mut worst = [0.0f64; 6];
    for (r, f) in rows.iter().zip(refs) {
        let (Some(r), Some(f)) = (r, f) else { continue };
        for k in 0..6 {
            let d = (Dd::from(r[k]) - f[k]).to_f64();
            let tau = std::f64::consts::TAU;
            let e = if k < 2 {
                (d - tau * (d / tau).round()).abs()
            } else {
                d.abs() / scale[k]
            };
            worst[k] = worst[k].max(if e.is_finite() { e } else { f64::INFINITY });
        }
    }
    worst
}

fn sci(x: f64) -> String {
    if x == 0.0 {
        "0".into()
    } else {
        format!("{x:.1e}")
    }
}

/// The section (markdown).
pub fn section() -> String {
    let (m, m32) = (FiveBarIk::<f64>::default(), FiveBarIk::<f32>::default());
    let (g, left_out) = grid();
    let g32: Vec<(f64, f64)> = g
        .iter()
        .map(|p| (p.0 as f32 as f64, p.1 as f32 as f64))
        .collect();
    let refs: Vec<_> = g.iter().map(|&p| reference(p)).collect();
    let refs32: Vec<_> = g32.iter().map(|&p| reference(p)).collect();
    let rows: Vec<_> = g.iter().map(|&p| generated(&m, p)).collect();
    let rows32: Vec<_> = g32.iter().map(|&p| generated(&m32, p)).collect();
    let first = m
        .position(&FiveBarIkInput {
            x: g[0].0,
            y: g[0].1,
        })
        .expect("in reach");
    // Newton's distal angles run from the elbows to P; the generated
    // forearms' axes run from P to the elbows (each RRR hangs them on P).
    let pi = std::f64::consts::PI;
    let guess0 = [
        first.arm1,
        first.forearm1 + pi,
        first.arm2,
        first.forearm2 + pi,
    ];
    let (nrows, iterations) = newton_rows(&g, guess0);
    let n = g.len();
    let sweeps = methods(&m, &m32, &g, &g32, guess0);
    let timed: Vec<(&Sweep, usize)> = sweeps.iter().map(|(_, s)| (s, n)).collect();
    let ns = timing::interleaved(&timed, crate::ROUNDS, crate::MIN_SAMPLE_NS);
    let base = timing::stats(&ns[0]).0;
    let errs = [
        Some(errors(&rows, &refs)),
        None,
        Some(errors(&rows32, &refs32)),
        Some(errors(&nrows, &refs)),
    ];
    let failed = [
        rows.iter().filter(|r| r.is_none()).count().to_string(),
        "-".to_string(),
        rows32.iter().filter(|r| r.is_none()).count().to_string(),
        nrows.iter().filter(|r| r.is_none()).count().to_string(),
    ];
    let mut md = intro(n, left_out);
    let _ = writeln!(
        md,
        "| method | ns median | min - max | x generated `solve` | {} | Newton iterations mean (max) | failed |",
        NAMES.join(" | ")
    );
    let _ = writeln!(md, "|---|---:|---:|---:|{}---:|---:|", "---:|".repeat(6));
    for (k, (name, _)) in sweeps.iter().enumerate() {
        let (med, mn, mx) = timing::stats(&ns[k]);
        let cols = match errs[k] {
            Some(e) => e.map(sci).join(" | "),
            None => ["-"; 6].join(" | "),
        };
        let iters = if k == 3 && !iterations.is_empty() {
            let s: u64 = iterations.iter().map(|&i| i as u64).sum();
            let mx = iterations.iter().max().copied().unwrap_or(0);
            format!("{:.2} ({mx})", s as f64 / iterations.len() as f64)
        } else {
            "-".into()
        };
        let _ = writeln!(
            md,
            "| {name} | {med:.1} | {mn:.1} - {mx:.1} | {:.2} | {cols} | {iters} | {} |",
            med / base,
            failed[k]
        );
    }
    md
}

/// The timed methods, in the table's order: the generated `solve`, with
/// `forces`, in f32, and the Newton baseline (warm-started from `guess0`).
fn methods<'a>(
    m: &'a FiveBarIk<f64>,
    m32: &'a FiveBarIk<f32>,
    g: &'a [(f64, f64)],
    g32: &'a [(f64, f64)],
    guess0: [f64; 4],
) -> [(&'static str, Sweep<'a>); 4] {
    let inp = |x: f64, y: f64| FiveBarIkInput { x, y };
    let (vel, acc) = (inp(V.0, V.1), inp(A.0, A.1));
    [
        (
            "generated `solve` (position, velocity, acceleration)",
            Box::new(move || {
                let mut s = 0.0;
                for &(x, y) in g {
                    if let Ok(o) = m.solve(&inp(x, y), &vel, &acc) {
                        s += o.position.arm1 + o.velocity.arm2 + o.acceleration.arm1;
                    }
                }
                black_box(s)
            }),
        ),
        (
            "generated `solve` + `forces` (motor torques)",
            Box::new(move || {
                let mut s = 0.0;
                for &(x, y) in g {
                    if let Ok(o) = m.solve(&inp(x, y), &vel, &acc) {
                        if let Ok(f) = m.forces(&o.position, &o.velocity, &o.acceleration) {
                            s += f.drive_q1 + f.drive_q2;
                        }
                    }
                }
                black_box(s)
            }),
        ),
        (
            "generated f32 `solve`",
            Box::new(move || {
                let inp32 = |x: f64, y: f64| FiveBarIkInput {
                    x: x as f32,
                    y: y as f32,
                };
                let (v32, a32) = (inp32(V.0, V.1), inp32(A.0, A.1));
                let mut s = 0.0f32;
                for &(x, y) in g32 {
                    if let Ok(o) = m32.solve(&inp32(x, y), &v32, &a32) {
                        s += o.position.arm1 + o.velocity.arm2 + o.acceleration.arm1;
                    }
                }
                black_box(s as f64)
            }),
        ),
        (
            "Newton, nalgebra SMatrix 4x4 LU (warm start)",
            Box::new(move || {
                let (mut s, mut guess) = (0.0, guess0);
                for &p in g {
                    if let Some(o) = baselines::five_bar_ik_newton(p, V, A, guess) {
                        guess = o.q;
                        s += o.q[0] + o.w[2] + o.al[0];
                    }
                }
                black_box(s)
            }),
        ),
    ]
}

/// The section's heading and what it measures (`n` end points, `left_out`
/// grid points left out).
fn intro(n: usize, left_out: usize) -> String {
    let mut md = String::new();
    let _ = writeln!(
        md,
        "## Five-bar given its end point (inverse kinematics)\n\n\
         The five-bar robot of `examples/five_bar_ik.rs` (`scenes::FiveBarIk`, drawn; the end \
         point is the input, each arm an RRR hanging on it): {n} end points, the forward \
         five-bar's at a {SIDE} x {SIDE} grid of motor angles (q1 70..140 deg, q2 10..80 deg) \
         where both elbows are at least 3 deg from straight ({left_out} grid points nearer the \
         workspace's edge left out: there the rates grow without bound), moving at ({}, {}) m/s and accelerating at ({}, {}) m/s^2. Reference: \
         `mechanism_reference::groups` in double-double (each arm's RRR from the exact input, \
         the motor angles by its `atan2`); for f32, from the inputs rounded to f32. Baseline: \
         Newton on the two arms' loop closure (four equations in the motor and distal angles, \
         nalgebra `SMatrix` LU, warm-started from the previous point, stop at the first step \
         below {:.0e} rad, at most {} iterations), then its rate and acceleration \
         systems; an answer on the other elbow counts as failed. ns per end point, median and min-max over {} interleaved rounds. Errors: max \
         over the points; angles absolute (rad), rates and accelerations relative to the \
         column's largest |reference| value. The motor torques are not in the reference: they \
         are checked against the forward five-bar's force analysis (`tests/examples/inverse.rs`, \
         8.5e-15 of the largest), itself checked against Newton-Euler in the forces section.\n",
        V.0,
        V.1,
        A.0,
        A.1,
        baselines::IK_TOL,
        baselines::IK_MAX_ITER,
        crate::ROUNDS
    );
    md
}
