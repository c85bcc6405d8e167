//! What the synthesis report measures with: medians, the machine's load, the
//! process's CPU time, and the cost of one Jacobian in objective evaluations
//! (counted for the budgets, measured for the table).

use std::time::Instant;

use mechanism_synthesis::fourbar::PathProblem;
use mechanism_synthesis::jacobian::{jacobian, Workspace, CHUNK};
use mechanism_synthesis::problem::{objective, Problem};
use mechanism_synthesis::rng::Rng;
use nalgebra::{DMatrix, DVector};

/// The median of `v` (the mean of the middle two for an even count).
pub fn median(v: &[f64]) -> f64 {
    let mut s = v.to_vec();
    s.sort_by(f64::total_cmp);
    let n = s.len();
    if n == 0 {
        return f64::NAN;
    }
    if n % 2 == 1 {
        s[n / 2]
    } else {
        0.5 * (s[n / 2 - 1] + s[n / 2])
    }
}

/// The load average of the last minute (`/proc/loadavg`), if readable.
pub fn load() -> String {
    std::fs::read_to_string("/proc/loadavg")
        .ok()
        .and_then(|s| s.split_whitespace().next().map(str::to_owned))
        .unwrap_or_else(|| "unknown".into())
}

/// The process's CPU time so far (s; user and system, all threads), from
/// `/proc/self/stat` at the usual 100 ticks per second; 0 where unreadable.
pub fn cpu_seconds() -> f64 {
    let Ok(s) = std::fs::read_to_string("/proc/self/stat") else {
        return 0.0;
    };
    // Fields after the command name (which is in parentheses): utime is the
    // 12th, stime the 13th.
    let rest = s.rsplit_once(')').map_or("", |r| r.1);
    let f: Vec<u64> = rest
        .split_whitespace()
        .skip(11)
        .take(2)
        .filter_map(|v| v.parse().ok())
        .collect();
    f.iter().sum::<u64>() as f64 / 100.0
}

/// The cost of one Jacobian of `p` counted in objective evaluations for the
/// budgets: one residual pass on `Dual<CHUNK>` per `CHUNK` variables, each
/// counted as `CHUNK + 1` passes on `f64` (a value and `CHUNK` derivatives
/// per operation). A fixed count, not the measurement ([`jacobian_ratio`],
/// shown beside it), so that the baseline's budget and result do not depend
/// on the machine's load; the CPU columns show what each method spent.
pub fn jacobian_cost(p: &PathProblem) -> f64 {
    (p.dim().div_ceil(CHUNK) * (CHUNK + 1)) as f64
}

/// The cost of one Jacobian of `p` in objective evaluations: the median over
/// 15 rounds of the time of 200 Jacobians over that of 200 objectives, at a
/// start the problem's sampler draws (the residual code is the same at any
/// design; only the branch taken differs).
pub fn jacobian_ratio(p: &PathProblem) -> f64 {
    let mut rng = Rng::new(7);
    let mut x = vec![0.0; p.dim()];
    let mut buf = vec![0.0; p.residual_count()];
    for _ in 0..1000 {
        p.sample(&mut rng, &mut x);
        if objective(p, &x, &mut buf).is_finite() {
            break;
        }
    }
    let mut ws = Workspace::new(p.dim(), p.residual_count());
    let mut r = DVector::zeros(p.residual_count());
    let mut jac = DMatrix::zeros(p.residual_count(), p.dim());
    let ratios: Vec<f64> = (0..15)
        .map(|_| {
            let t = Instant::now();
            let mut s = 0.0;
            for _ in 0..200 {
                s += objective(p, std::hint::black_box(&x), &mut buf);
            }
            std::hint::black_box(s);
            let f = t.elapsed().as_secs_f64();
            let t = Instant::now();
            for _ in 0..200 {
                std::hint::black_box(jacobian(p, &x, &mut ws, &mut r, &mut jac));
            }
            t.elapsed().as_secs_f64() / f.max(1e-12)
        })
        .collect();
    median(&ratios)
}
