//! The global strategy: many starts, each polished by the bounded
//! Levenberg-Marquardt of [`crate::lm`], the best kept.
//!
//! The starts come from the problem's own sampler (uniform in its box, or
//! something smarter: the four-bar places each random shape on the targets
//! before its first step). A screening pass draws `screen` candidates per
//! start and polishes only the best of them by objective, so most of the
//! budget goes to starts that already lie in a reasonable basin.

use crate::lm::{Options, Outcome, Solver};
use crate::problem::{objective, Problem};
use crate::rng::Rng;

/// Settings of a multi-start run.
#[derive(Clone, Copy, Debug)]
pub struct Settings {
    /// Local solves.
    pub starts: usize,
    /// Candidates drawn per local solve; the best one (by objective) starts it.
    pub screen: usize,
    /// The local solver's stopping rules for each start (short: most starts
    /// end in a basin that is not the best, and that shows early).
    pub local: Options,
    /// The stopping rules of the final polish of the best start.
    pub polish: Options,
    /// Basin hops after the starts: the best design perturbed (a random
    /// third of its variables each moved by up to `hop_scale` of its size)
    /// and polished, kept when better (monotonic basin hopping, Leary 2000).
    pub hops: usize,
    /// Relative size of a hop's perturbation.
    pub hop_scale: f64,
    /// Seed of the run.
    pub seed: u64,
}

/// The best design of a run and what it cost.
#[derive(Clone, Debug)]
pub struct Best {
    /// The best local solve's result.
    pub outcome: Outcome,
    /// Objective evaluations over the run (screening and local solves).
    pub evaluations: usize,
    /// Jacobian evaluations over the run.
    pub jacobians: usize,
}

/// Runs `settings.starts` local solves from starts drawn by `sample` and
/// returns the best. `sample` writes a candidate design into its slice.
pub fn run<P: Problem>(
    p: &P,
    settings: &Settings,
    mut sample: impl FnMut(&mut Rng, &mut [f64]),
) -> Best {
    let mut rng = Rng::new(settings.seed);
    let mut solver = Solver::new(p);
    let mut buf = vec![0.0; p.residual_count()];
    let mut cand = vec![0.0; p.dim()];
    let mut start = vec![0.0; p.dim()];
    let mut elites: Vec<Outcome> = Vec::with_capacity(ELITES + 1);
    let (mut evaluations, mut jacobians) = (0, 0);
    for _ in 0..settings.starts {
        let mut start_cost = f64::INFINITY;
        for _ in 0..settings.screen.max(1) {
            sample(&mut rng, &mut cand);
            let c = objective(p, &cand, &mut buf);
            evaluations += 1;
            if c < start_cost {
                start_cost = c;
                start.copy_from_slice(&cand);
            }
        }
        if !start_cost.is_finite() {
            continue;
        }
        let out = solver.minimize(p, &start, &settings.local);
        evaluations += out.evaluations;
        jacobians += out.jacobians;
        keep_elite(&mut elites, out);
    }
    let (lo, hi) = (p.lower(), p.upper());
    // First half of the hops: round robin over the elites (a second basin
    // that hops improve faster than the first gets its chance); second half:
    // the best of them. Only when each elite gets `MIN_SPREAD` hops or more:
    // a few hops spread over four basins move none of them far.
    let spread = if elites.len() > 1 && settings.hops / 2 >= MIN_SPREAD * elites.len() {
        settings.hops / 2
    } else {
        0
    };
    for h in 0..spread {
        let k = h % elites.len();
        let scale = settings.hop_scale * RADII[(h / elites.len()) % RADII.len()];
        perturb(&elites[k].x, &mut cand, lo, hi, scale, &mut rng);
        p.reseat(&mut cand);
        let out = solver.minimize(p, &cand, &settings.local);
        evaluations += out.evaluations;
        jacobians += out.jacobians;
        if out.cost < elites[k].cost {
            elites[k] = out;
        }
    }
    let mut best = elites.into_iter().min_by(|a, b| a.cost.total_cmp(&b.cost));
    if let Some(b) = best.as_mut() {
        for h in 0..settings.hops - spread {
            let scale = settings.hop_scale * RADII[h % RADII.len()];
            perturb(&b.x, &mut cand, lo, hi, scale, &mut rng);
            p.reseat(&mut cand);
            let out = solver.minimize(p, &cand, &settings.local);
            evaluations += out.evaluations;
            jacobians += out.jacobians;
            if out.cost < b.cost {
                *b = out;
            }
        }
        // The polish, restarted (lambda afresh) while a round gains more
        // than `POLISH_GAIN` of the objective; then the sub-problem re-solved
        // at the polished design and polished again, kept when better.
        for _ in 0..POLISH_ROUNDS {
            let out = solver.minimize(p, &b.x, &settings.polish);
            evaluations += out.evaluations;
            jacobians += out.jacobians;
            let gain = b.cost - out.cost;
            if out.cost <= b.cost {
                *b = out;
            }
            if gain <= POLISH_GAIN * b.cost {
                break;
            }
        }
        cand.copy_from_slice(&b.x);
        p.reseat(&mut cand);
        let out = solver.minimize(p, &cand, &settings.polish);
        evaluations += out.evaluations;
        jacobians += out.jacobians;
        if out.cost < b.cost {
            *b = out;
        }
        // Variables crawling towards a face their parametrization reaches
        // only in the limit: the designs on those faces, each polished, the
        // best kept when better (`Problem::faces`).
        for face in p.faces(&b.x) {
            let mut from = face;
            let mut last = f64::INFINITY;
            for _ in 0..POLISH_ROUNDS {
                let out = solver.minimize(p, &from, &settings.polish);
                evaluations += out.evaluations;
                jacobians += out.jacobians;
                let gain = last - out.cost;
                last = out.cost;
                from.copy_from_slice(&out.x);
                if out.cost < b.cost {
                    *b = out;
                }
                if gain <= POLISH_GAIN * last {
                    break;
                }
            }
        }
    }
    let outcome = best.unwrap_or(Outcome {
        x: start,
        cost: f64::INFINITY,
        evaluations: 0,
        jacobians: 0,
    });
    Best {
        outcome,
        evaluations,
        jacobians,
    }
}

/// Hop radii in turn, in units of `hop_scale`: near basins and far ones
/// each get a share (a fourth radius of 0.125 left kunjur18_free seed 2 at
/// 5.4e-3 instead of 3.24e-3).
const RADII: [f64; 3] = [0.5, 1.0, 2.0];

/// Most restarts of the final polish.
const POLISH_ROUNDS: usize = 10;

/// Relative gain of a polish round below which the polish stops.
const POLISH_GAIN: f64 = 1e-9;

/// Elites kept from the starts for the first half of the hops.
const ELITES: usize = 4;

/// Fewest hops per elite for the round robin to run.
const MIN_SPREAD: usize = 25;

/// Inserts `out` among the `ELITES` lowest-cost outcomes (finite costs only;
/// one within a relative `1e-6` of a kept one is the same basin, kept once).
fn keep_elite(elites: &mut Vec<Outcome>, out: Outcome) {
    if !out.cost.is_finite() {
        return;
    }
    if let Some(same) = elites
        .iter_mut()
        .find(|e| (e.cost - out.cost).abs() <= 1e-6 * e.cost.max(out.cost))
    {
        if out.cost < same.cost {
            *same = out;
        }
        return;
    }
    elites.push(out);
    elites.sort_by(|a, b| a.cost.total_cmp(&b.cost));
    elites.truncate(ELITES);
}

/// A hop from `x` into `cand`: a random third of the variables each moved by
/// up to `scale` of its size (its magnitude, at least a tenth of its box up to
/// one unit), clamped into the box.
fn perturb(x: &[f64], cand: &mut [f64], lo: &[f64], hi: &[f64], scale: f64, rng: &mut Rng) {
    for (j, v) in cand.iter_mut().enumerate() {
        let xj = x[j];
        *v = if rng.unit() < 1.0 / 3.0 {
            let size = xj.abs().max(0.1 * (hi[j] - lo[j]).min(1.0));
            (xj + scale * size * (2.0 * rng.unit() - 1.0)).clamp(lo[j], hi[j])
        } else {
            xj
        };
    }
}
