//! Proves the `run_up` example's numbers (`--csv` rows and `--steady`)
//! against an independent solution: `mechanism_reference::four_bar_dynamics`
//! (every link's Newton-Euler equations with the joint constraints and
//! Lagrange multipliers, its own circle intersection for the positions, the
//! crank and flywheel merged into one body by hand, classical RK4 with
//! Richardson extrapolation). Nothing is shared with the generated code or
//! `mechanism::ode` but the problem's data.
use super::run_up_scene::*;
use mechanism_reference::four_bar_dynamics::FourBar;

/// The reference four-bar ([`FourBar::run_up`]: crank and flywheel merged
/// into one body, B on the left of A -> O4, above the x axis at 0).
fn reference() -> FourBar {
    FourBar::run_up()
}

/// Steps per second of the reference's coarse run (the fine run has twice
/// as many). With 4000 the two runs differ by about 1e-9 rad/s at most, so
/// the extrapolated values are good to well below 1e-10.
const STEPS: f64 = 4000.0;

// Proves the assembly is the one the issue asks for: B above the x axis at
// crank angle 0.
#[test]
fn b_is_above_the_x_axis_at_crank_angle_zero() {
    let pos = RunUp::<f64>::default()
        .position(&RunUpInput { phi: 0.0 })
        .unwrap();
    assert!(pos.B.y > 0.1, "{:?}", pos.B);
}

// Proves the CSV's rows (phi, omega, alpha, theta3, theta4, the motor's
// torque) at 0.5, 1, 2 and 3 s agree with the reference. Tolerance 1e-9
// relative to the row's scale (phi up to ~90 rad, omega ~35 rad/s): the
// integrator's local tolerance is 1e-12 and the run-up accumulates some
// 1e3 steps' errors; the reference's error is below 1e-10 (its two runs'
// spread, asserted, divided by ~15 by the extrapolation).
#[test]
fn csv_rows_match_the_global_formulation() {
    let times = [0.5, 1.0, 2.0, 3.0];
    let rows = run_up(&RunUp::default(), &times).unwrap();
    let fb = reference();
    let (refs, spread) = fb.run(0.0, [0.0, 0.0], &times, STEPS, &motor);
    assert!(spread < 1e-8, "reference spread {spread:e}");
    let mut worst: f64 = 0.0;
    for (row, y) in rows.iter().zip(&refs) {
        let (alpha, r) = fb.accel(y[0], y[1], motor(y[1]));
        let expect = [row[0], y[0], y[1], alpha, r[0], r[1], motor(y[1])];
        let scale = [
            1.0,
            y[0].abs().max(1.0),
            y[1].abs().max(1.0),
            alpha.abs().max(1.0),
            1.0,
            1.0,
            1.0,
        ];
        for k in 1..7 {
            let err = (row[k] - expect[k]).abs() / scale[k];
            worst = worst.max(err);
            assert!(
                err < 1e-9,
                "t {} column {k}: {} vs {} ({err:e})",
                row[0],
                row[k],
                expect[k]
            );
        }
    }
    eprintln!("run-up rows against the reference: worst {worst:.1e} relative, reference spread {spread:.1e}");
}

// Proves the CSV grid: 301 rows at exactly k / 100 s, starting at rest.
#[test]
fn csv_grid_has_301_rows_from_rest() {
    let rows = run_up(&RunUp::default(), &grid()).unwrap();
    assert_eq!(rows.len(), 301);
    assert_eq!(rows[0][..3], [0.0, 0.0, 0.0]);
    assert_eq!(rows[300][0], 3.0);
    assert_eq!(rows[1][0], 0.01);
}

// Proves the steady state: from (0, omega_0) the reference, run for exactly
// one `period`, returns to phi = 2 pi and omega_0 (1e-9: the shooting's
// tolerance is 1e-11 rad/s and the reference's error below 1e-10), and its
// speeds over the turn reach `max_speed` and `min_speed` (sampled at 8000
// times a turn and refined by a parabola through the three samples around the
// extremum: error below 1e-9 rad/s), so `delta` and `mean_speed` follow.
#[test]
fn steady_state_is_periodic_in_the_reference() {
    let s = steady(&RunUp::default());
    let fb = reference();
    let n = 8000usize;
    let times: Vec<f64> = (1..=n).map(|k| s.period * k as f64 / n as f64).collect();
    let (ys, spread) = fb.run(0.0, [0.0, s.omega_0], &times, 40000.0, &motor);
    assert!(spread < 1e-9, "reference spread {spread:e}");
    let last = ys[n - 1];
    assert!(
        (last[0] - std::f64::consts::TAU).abs() < 1e-9,
        "phi {}",
        last[0]
    );
    assert!(
        (last[1] - s.omega_0).abs() < 1e-9,
        "omega {} vs {}",
        last[1],
        s.omega_0
    );
    let w: Vec<f64> = std::iter::once(s.omega_0)
        .chain(ys.iter().map(|y| y[1]))
        .collect();
    let refine = |k: usize| {
        let (a, b, c) = (w[k - 1], w[k], w[k + 1]);
        let den = a - 2.0 * b + c;
        if den == 0.0 {
            b
        } else {
            b - (c - a).powi(2) / (8.0 * den)
        }
    };
    let kmax = (1..n).max_by(|&i, &j| w[i].total_cmp(&w[j])).unwrap();
    let kmin = (1..n).min_by(|&i, &j| w[i].total_cmp(&w[j])).unwrap();
    let (hi, lo) = (refine(kmax), refine(kmin));
    eprintln!(
        "steady state against the reference: phi {:.1e}, omega {:.1e}, max {:.1e}, min {:.1e}; spread {spread:.1e}",
        last[0] - std::f64::consts::TAU, last[1] - s.omega_0, hi - s.max_speed, lo - s.min_speed
    );
    assert!(
        (hi - s.max_speed).abs() < 1e-8,
        "max {hi} vs {}",
        s.max_speed
    );
    assert!(
        (lo - s.min_speed).abs() < 1e-8,
        "min {lo} vs {}",
        s.min_speed
    );
    let mean = std::f64::consts::TAU / s.period;
    assert!((s.mean_speed - mean).abs() < 1e-14 * mean);
    assert!((s.delta - (s.max_speed - s.min_speed) / mean).abs() < 1e-14);
}

// Proves the reduced inertia's derivative (twice the velocity-product term
// at unit speed) is the derivative of the reduced inertia (the mass
// matrix): central differences with step 1e-5 rad (error ~1e-10 of the
// 1e-2 scale of I').
#[test]
fn reduced_inertia_derivative_is_its_slope() {
    let m = RunUp::default();
    for k in 0..24 {
        let phi = k as f64 * 0.26;
        let (_, di, _) = reduced(&m, phi).unwrap();
        let d = 1e-5;
        let fd = (reduced(&m, phi + d).unwrap().0 - reduced(&m, phi - d).unwrap().0) / (2.0 * d);
        assert!((di - fd).abs() < 1e-9, "phi {phi}: {di} vs {fd}");
    }
}
