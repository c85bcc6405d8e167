//! Interleaved timing: every method's whole sweep is timed once per round,
//! the methods one after the other inside a round, so that a slow phase of the
//! machine (another build, frequency changes) hits every method alike.

use std::time::Instant;

/// A timed sweep: runs the method over the whole grid and returns a checksum
/// (kept alive with `black_box`).
pub type Sweep<'a> = Box<dyn Fn() -> f64 + 'a>;

/// Nanoseconds per evaluation of each sweep, one entry per round.
pub fn interleaved(sweeps: &[(&Sweep, usize)], rounds: usize, min_sample_ns: f64) -> Vec<Vec<f64>> {
    // Calibrate: repetitions per sample so that each sample lasts at least
    // `min_sample_ns` (the timer's resolution and call overhead vanish).
    let reps: Vec<usize> = sweeps
        .iter()
        .map(|(f, _)| {
            let t = Instant::now();
            std::hint::black_box(f());
            let once = t.elapsed().as_nanos().max(1) as f64;
            ((min_sample_ns / once).ceil() as usize).max(1)
        })
        .collect();
    let mut out = vec![Vec::with_capacity(rounds); sweeps.len()];
    for _ in 0..rounds {
        for (k, (f, n)) in sweeps.iter().enumerate() {
            let t = Instant::now();
            for _ in 0..reps[k] {
                std::hint::black_box(f());
            }
            let ns = t.elapsed().as_nanos() as f64;
            out[k].push(ns / (reps[k] * *n) as f64);
        }
    }
    out
}

/// Median, minimum and maximum of the samples.
pub fn stats(v: &[f64]) -> (f64, f64, f64) {
    let mut s = v.to_vec();
    s.sort_by(|a, b| a.total_cmp(b));
    let n = s.len();
    let med = if n % 2 == 1 {
        s[n / 2]
    } else {
        0.5 * (s[n / 2 - 1] + s[n / 2])
    };
    (med, s[0], s[n - 1])
}
