//! Plain differential evolution (Storn and Price, J. Global Optim. 11 (1997)
//! 341), DE/rand/1/bin: the family the path-synthesis literature uses
//! (Cabrera, Simon and Prado 2002 and its successors), here as the baseline
//! the multi-start Levenberg-Marquardt of [`crate::multistart`] is measured
//! against, on the same [`Problem`], the same parametrization and the same
//! evaluation budget.
//!
//! Each generation, every member `x_i` gets a mutant `x_a + F (x_b - x_c)`
//! (`a, b, c` distinct random members other than `i`), crossed with `x_i`
//! component by component with probability `CR` (one random component always
//! from the mutant); a mutant component outside the search box is redrawn
//! between the base member's value and the bound it crossed (Price, Storn and
//! Lampinen 2005, "bounce-back"). The trial replaces `x_i` when its objective
//! is not worse. `F` is dithered: drawn uniformly in `[f_min, f_max]` once per
//! generation (Das et al. 2005), the usual `0.5 .. 0.9` by default; `CR = 0.9`.
//!
//! Written here rather than taken from a crate: `differential-evolution`
//! (0.2.2 on crates.io) is a self-adapting variant (its own
//! `F` and `CR` per member), not the plain DE/rand/1/bin the literature
//! reports, and argmin has no DE; the baseline's point is to be exactly the
//! textbook algorithm, and its loop is thirty lines.

use crate::problem::{objective, Problem};
use crate::rng::Rng;

/// Settings of a DE run.
#[derive(Clone, Copy, Debug)]
pub struct Settings {
    /// Objective evaluations, the initial population included.
    pub budget: usize,
    /// Population size (at least 4).
    pub population: usize,
    /// Range of the dithered scale factor `F`.
    pub f: (f64, f64),
    /// Crossover probability.
    pub cr: f64,
    /// Seed of the run.
    pub seed: u64,
}

impl Settings {
    /// The usual settings for a problem of `dim` variables: a population of
    /// `10 dim` (Storn and Price's rule of thumb), `F` in `0.5 .. 0.9`,
    /// `CR = 0.9`.
    pub fn usual(dim: usize, budget: usize, seed: u64) -> Self {
        Settings {
            budget,
            population: (10 * dim).max(4),
            f: (0.5, 0.9),
            cr: 0.9,
            seed,
        }
    }
}

/// The best member of a DE run.
#[derive(Clone, Debug)]
pub struct Best {
    /// Its design variables.
    pub x: Vec<f64>,
    /// Its objective.
    pub cost: f64,
    /// Objective evaluations made.
    pub evaluations: usize,
}

/// Runs DE/rand/1/bin on `p` in its [`Problem::search_box`].
pub fn run<P: Problem>(p: &P, s: &Settings) -> Best {
    let (lo, hi) = p.search_box();
    let n = p.dim();
    let np = s.population.max(4);
    let mut rng = Rng::new(s.seed);
    let mut buf = vec![0.0; p.residual_count()];
    let mut pop: Vec<Vec<f64>> = (0..np)
        .map(|_| (0..n).map(|j| rng.range(lo[j], hi[j])).collect())
        .collect();
    let mut cost: Vec<f64> = pop.iter().map(|x| objective(p, x, &mut buf)).collect();
    let mut evaluations = np;
    let mut trial = vec![0.0; n];
    'gens: while evaluations < s.budget {
        let f = rng.range(s.f.0, s.f.1);
        for i in 0..np {
            if evaluations >= s.budget {
                break 'gens;
            }
            let [a, b, c] = distinct(&mut rng, np, i);
            let forced = rng.index(n);
            for j in 0..n {
                trial[j] = if j == forced || rng.unit() < s.cr {
                    let v = pop[a][j] + f * (pop[b][j] - pop[c][j]);
                    if v < lo[j] {
                        rng.range(lo[j], pop[a][j])
                    } else if v > hi[j] {
                        rng.range(pop[a][j], hi[j])
                    } else {
                        v
                    }
                } else {
                    pop[i][j]
                };
            }
            let c = objective(p, &trial, &mut buf);
            evaluations += 1;
            if c <= cost[i] {
                pop[i].copy_from_slice(&trial);
                cost[i] = c;
            }
        }
    }
    let k = (0..np)
        .min_by(|&a, &b| cost[a].total_cmp(&cost[b]))
        .unwrap_or(0);
    Best {
        x: pop.swap_remove(k),
        cost: cost[k],
        evaluations,
    }
}

/// Three distinct indices in `0..np`, all different from `i` (`np >= 4`).
fn distinct(rng: &mut Rng, np: usize, i: usize) -> [usize; 3] {
    let mut out = [i; 3];
    for k in 0..3 {
        loop {
            let r = rng.index(np);
            if r != i && !out[..k].contains(&r) {
                out[k] = r;
                break;
            }
        }
    }
    out
}
