//! The Rust side of the sweep timing in docs/python.md: one four-bar
//! (the Python benchmark's, `bench/sweep.py`) over 10^5 crank angles,
//! solved by the code `mechanism!` generates (its owned batch form) and by
//! the run-time mechanism walking its plan (what `planar_mechanism`
//! calls), each as the position alone and as position, velocity and
//! acceleration. Medians of 7 runs, in ms per sweep and ns per pose.
//!
//! `cargo run --release -p mechanism-python --example sweep_timing`

use mechanism::mechanism;
use mechanism_codegen::runtime::Mechanism;
use std::time::Instant;

mechanism! {
    pub FourBar {
        let O2 = ground(0.0, 0.0);
        let O4 = ground(3.5, 0.0);
        let A = crank(O2, 1.0, theta) as link2;
        let B = rrr(A, 3.0, O4, 2.5, left) as (link3, link4);
    }
}

mechanism! {
    pub PositionOnly {
        analysis position;
        let O2 = ground(0.0, 0.0);
        let O4 = ground(3.5, 0.0);
        let A = crank(O2, 1.0, theta) as link2;
        let B = rrr(A, 3.0, O4, 2.5, left) as (link3, link4);
    }
}

/// The same definition as text, for the run-time mechanism.
const TEXT: &str = "
    let O2 = ground(0.0, 0.0);
    let O4 = ground(3.5, 0.0);
    let A = crank(O2, 1.0, theta) as link2;
    let B = rrr(A, 3.0, O4, 2.5, left) as (link3, link4);
";

/// Poses per sweep.
const N: usize = 100_000;
/// Runs per figure (the median is reported).
const RUNS: usize = 7;

/// The median time of `RUNS` calls of `f`, in seconds; `f` returns a
/// number that depends on its work (summed so the work is not removed).
fn median(mut f: impl FnMut() -> f64) -> (f64, f64) {
    let mut times = Vec::with_capacity(RUNS);
    let mut check = 0.0;
    for _ in 0..RUNS {
        let t = Instant::now();
        check += std::hint::black_box(f());
        times.push(t.elapsed().as_secs_f64());
    }
    times.sort_by(f64::total_cmp);
    (times[RUNS / 2], check)
}

fn report(what: &str, (seconds, check): (f64, f64)) {
    println!(
        "{what:<58} {:>8.2} ms  {:>7.1} ns/pose  (check {check:.6e})",
        seconds * 1e3,
        seconds * 1e9 / N as f64
    );
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let theta: Vec<f64> = (0..N)
        .map(|k| k as f64 * std::f64::consts::TAU / N as f64)
        .collect();

    let m = PositionOnly::<f64>::default();
    let mut b = PositionOnly::<f64>::batch(N);
    b.in_theta.clone_from(&theta);
    report(
        "generated batch, position",
        median(|| {
            let failed = m.solve_columns(&mut b).map_or(usize::MAX, |f| f);
            b.pos_B_x.iter().sum::<f64>() + failed as f64
        }),
    );

    let m = FourBar::<f64>::default();
    let mut b = FourBar::<f64>::batch(N);
    b.in_theta.clone_from(&theta);
    b.rate_theta = vec![1.0; N];
    b.accel_theta = vec![0.0; N];
    report(
        "generated batch, position + velocity + acceleration",
        median(|| {
            let failed = m.solve_columns(&mut b).map_or(usize::MAX, |f| f);
            b.acc_B_x.iter().sum::<f64>() + failed as f64
        }),
    );

    let rt = Mechanism::new(TEXT).map_err(|e| e.to_string())?;
    // Storage made once, as `planar_mechanism`'s sweep does (`*_into`
    // allocate nothing per pose).
    let mut pos = rt.new_position();
    let (mut vel, mut acc) = (rt.new_rates(), rt.new_rates());
    report(
        "run-time walk, position",
        median(|| {
            let mut sum = 0.0;
            for t in &theta {
                sum += match rt.position_into(&[*t], &mut pos) {
                    Ok(()) => pos.values[6],
                    Err(_) => f64::NAN,
                };
            }
            sum
        }),
    );
    report(
        "run-time walk, position + velocity + acceleration",
        median(|| {
            let mut sum = 0.0;
            for t in &theta {
                let ok = rt.position_into(&[*t], &mut pos).is_ok()
                    && rt.velocity_into(&pos, &[1.0], &mut vel).is_ok()
                    && rt.acceleration_into(&pos, &vel, &[0.0], &mut acc).is_ok();
                sum += if ok { acc.values[6] } else { f64::NAN };
            }
            sum
        }),
    );
    Ok(())
}
