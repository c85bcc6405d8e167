//! The measurements of the report section beside the benchmark table: the
//! local solver against its alternatives from the same starts, and the
//! synthesis of a second definition (Jansen's leg).

use std::f64::consts::TAU;
use std::fmt::Write as _;
use std::time::Instant;

use mechanism::Mode;
use mechanism_synthesis::cases;
use mechanism_synthesis::fourbar::PathProblem;
use mechanism_synthesis::jansen::{self, FootPath, HOLY};
use mechanism_synthesis::lm::{JacobianKind, Options, Solver};
use mechanism_synthesis::multistart;
use mechanism_synthesis::problem::{objective, Problem};
use mechanism_synthesis::rng::Rng;

use crate::measure::{jacobian_cost, median};

/// What [`measure`] found: its markdown, and its lines for the targets.
pub struct Extra {
    pub markdown: String,
    pub targets: String,
}

/// Runs the measurements.
pub fn measure() -> Extra {
    let mut md = String::new();
    local_solvers(&mut md);
    let targets = jansen_leg(&mut md);
    Extra {
        markdown: md,
        targets,
    }
}

/// Starts per case for the local-solver comparison.
const STARTS: usize = 50;

/// One local method's results over the starts.
struct Local {
    cost: Vec<f64>,
    evals: Vec<f64>,
    seconds: f64,
}

/// The local solvers from the same `STARTS` starts (the problem's sampler,
/// each the best of 10 candidates, as the multi-start draws them) on two
/// timed cases, in the mode of the case's best design.
fn local_solvers(md: &mut String) {
    let _ = writeln!(
        md,
        "### The local solver against its alternatives\n\n\
         From the same {STARTS} starts per case (the four-bar's sampler, each the best of 10 \
         draws, as the multi-start makes them; mode +1): the bounded Levenberg-Marquardt of \
         `mechanism_synthesis::lm` with the exact dual-number Jacobian, the same solver with a \
         forward-difference Jacobian (`JacobianKind::ForwardDifference`: n + 1 objective \
         evaluations per Jacobian), and Nelder-Mead (Lagarias et al. 1998's coefficients 1, 2, \
         1/2, 1/2, an initial simplex of 5 % of each variable's size, points clamped into the \
         box; written in this example rather than taken from argmin, whose solver is the same \
         textbook method, to keep its dependencies out of the crate). LM stops after 200 \
         iterations or a relative gain under 1e-13; Nelder-Mead after 4000 evaluations or a \
         simplex whose objectives agree to 1e-13. \"Reach\": starts ending within 1 % of the \
         best any method reached from any start. Evaluations: objective evaluations, a dual \
         Jacobian counted as in the table above (column `J`).\n"
    );
    let _ = writeln!(
        md,
        "| case | method | best | median | reach | median evaluations | wall s (all starts) |"
    );
    let _ = writeln!(md, "|---|---|---:|---:|---:|---:|---:|");
    for id in ["arc5_timed", "line6_timed"] {
        let Some(case) = cases::all().into_iter().find(|c| c.id == id) else {
            continue;
        };
        let p = case.problem(Mode::Plus);
        let starts = draw_starts(&p);
        let ratio = jacobian_cost(&p);
        let opt = |jacobian| Options {
            max_iterations: 200,
            jacobian,
            ..Options::default()
        };
        let methods = [
            (
                "LM, exact Jacobian",
                run_lm(&p, &starts, &opt(JacobianKind::Exact), ratio),
            ),
            (
                "LM, forward differences",
                run_lm(&p, &starts, &opt(JacobianKind::ForwardDifference), 0.0),
            ),
            ("Nelder-Mead", run_nm(&p, &starts)),
        ];
        let best = methods
            .iter()
            .flat_map(|m| m.1.cost.iter().copied())
            .fold(f64::INFINITY, f64::min);
        for (name, m) in &methods {
            let reach = m.cost.iter().filter(|&&c| c <= 1.01 * best).count();
            let _ = writeln!(
                md,
                "| {id} | {name} | {:.6e} | {:.6e} | {reach}/{} | {:.0} | {:.2} |",
                m.cost.iter().copied().fold(f64::INFINITY, f64::min),
                median(&m.cost),
                m.cost.len(),
                median(&m.evals),
                m.seconds
            );
        }
    }
    md.push('\n');
}

/// `STARTS` starts of `p`, each the best of 10 of its sampler's draws.
fn draw_starts(p: &PathProblem) -> Vec<Vec<f64>> {
    let mut rng = Rng::new(2024);
    let mut buf = vec![0.0; p.residual_count()];
    let mut cand = vec![0.0; p.dim()];
    (0..STARTS)
        .map(|_| {
            let mut best = (f64::INFINITY, cand.clone());
            for _ in 0..10 {
                p.sample(&mut rng, &mut cand);
                let c = objective(p, &cand, &mut buf);
                if c < best.0 {
                    best = (c, cand.clone());
                }
            }
            best.1
        })
        .collect()
}

/// The LM from each start; a Jacobian counted as `ratio` evaluations (0:
/// already counted in the evaluations).
fn run_lm(p: &PathProblem, starts: &[Vec<f64>], opt: &Options, ratio: f64) -> Local {
    let mut solver = Solver::new(p);
    let t = Instant::now();
    let (mut cost, mut evals) = (Vec::new(), Vec::new());
    for s in starts {
        let out = solver.minimize(p, s, opt);
        cost.push(out.cost);
        evals.push(out.evaluations as f64 + ratio * out.jacobians as f64);
    }
    Local {
        cost,
        evals,
        seconds: t.elapsed().as_secs_f64(),
    }
}

/// Nelder-Mead from each start.
fn run_nm(p: &PathProblem, starts: &[Vec<f64>]) -> Local {
    let t = Instant::now();
    let (mut cost, mut evals) = (Vec::new(), Vec::new());
    for s in starts {
        let (c, e) = nelder_mead(p, s, 4000);
        cost.push(c);
        evals.push(e as f64);
    }
    Local {
        cost,
        evals,
        seconds: t.elapsed().as_secs_f64(),
    }
}

/// Nelder-Mead on `p`'s objective from `x0`, points clamped into the box:
/// the best objective and the evaluations made.
fn nelder_mead<P: Problem>(p: &P, x0: &[f64], budget: usize) -> (f64, usize) {
    let n = p.dim();
    let (lo, hi) = (p.lower(), p.upper());
    let mut buf = vec![0.0; p.residual_count()];
    let evals = std::cell::Cell::new(0usize);
    let mut f = |x: &mut Vec<f64>| {
        for (j, v) in x.iter_mut().enumerate() {
            *v = v.clamp(lo[j], hi[j]);
        }
        evals.set(evals.get() + 1);
        objective(p, x, &mut buf)
    };
    let mut simplex: Vec<(f64, Vec<f64>)> = (0..=n)
        .map(|k| {
            let mut x = x0.to_vec();
            if k > 0 {
                let j = k - 1;
                x[j] += 0.05 * x[j].abs().max(0.1);
            }
            (f(&mut x), x)
        })
        .collect();
    while evals.get() < budget {
        simplex.sort_by(|a, b| a.0.total_cmp(&b.0));
        let (fb, fw) = (simplex[0].0, simplex[n].0);
        if fw.is_finite() && fw - fb <= 1e-13 * fb.abs() {
            break;
        }
        let centroid: Vec<f64> = (0..n)
            .map(|j| simplex[..n].iter().map(|s| s.1[j]).sum::<f64>() / n as f64)
            .collect();
        let along = |t: f64| -> Vec<f64> {
            (0..n)
                .map(|j| centroid[j] + t * (simplex[n].1[j] - centroid[j]))
                .collect()
        };
        let mut xr = along(-1.0);
        let fr = f(&mut xr);
        if fr < simplex[0].0 {
            let mut xe = along(-2.0);
            let fe = f(&mut xe);
            simplex[n] = if fe < fr { (fe, xe) } else { (fr, xr) };
        } else if fr < simplex[n - 1].0 {
            simplex[n] = (fr, xr);
        } else {
            let t = if fr < fw { -0.5 } else { 0.5 };
            let mut xc = along(t);
            let fc = f(&mut xc);
            if fc < fr.min(fw) {
                simplex[n] = (fc, xc);
            } else {
                let best = simplex[0].1.clone();
                for s in simplex.iter_mut().skip(1) {
                    let mut x: Vec<f64> =
                        (0..n).map(|j| best[j] + 0.5 * (s.1[j] - best[j])).collect();
                    *s = (f(&mut x), x);
                }
            }
        }
    }
    let best = simplex.iter().map(|s| s.0).fold(f64::INFINITY, f64::min);
    (best, evals.get())
}

/// Jansen's leg: the foot path of the holy numbers at 24 crank angles, six
/// numbers free in a 20 % box, the multi-start from uniform random starts;
/// returns the target line.
fn jansen_leg(md: &mut String) -> String {
    let th: Vec<f64> = (0..24).map(|k| TAU * k as f64 / 24.0).collect();
    let Some(leg) = jansen::leg(&HOLY) else {
        return String::new();
    };
    let targets: Vec<[f64; 2]> = th.iter().filter_map(|&t| jansen::foot(&leg, t)).collect();
    let free = vec![4, 5, 6, 7, 9, 10];
    let p = FootPath::new(free.clone(), th, targets, 0.2);
    let (lo, hi) = (p.lower().to_vec(), p.upper().to_vec());
    let settings = jansen::settings(5);
    let t = Instant::now();
    let best = multistart::run(&p, &settings, |rng, x| {
        for (j, v) in x.iter_mut().enumerate() {
            *v = rng.range(lo[j], hi[j]);
        }
    });
    let secs = t.elapsed().as_secs_f64();
    let n = p.numbers(&best.outcome.x);
    let dev = free
        .iter()
        .map(|&v| ((n[v] - HOLY[v]) / HOLY[v]).abs())
        .fold(0.0, f64::max);
    let _ = writeln!(
        md,
        "### Another definition: Jansen's leg\n\n\
         `mechanism_synthesis::jansen`: the leg (three RRR dyads on a crank, the thirteen \
         numbers as run-time parameters) fitted to the foot path its holy numbers generate at \
         24 crank angles, with e, f, g, h, j, k free in a box of +-20 % about them, by the same \
         multi-start (12 uniform random starts screened 10 to 1, 4 hops, the polish): objective \
         {:.3e} (sum of squared distances, Jansen's units), the six numbers recovered to \
         {dev:.1e} relative, {} evaluations and {} Jacobians, {secs:.2} s. \
         (`mechanism-synthesis/tests/jansen.rs` holds the same synthesis to 1e-20 and the path \
         between the targets to 1e-9.)\n",
        best.outcome.cost, best.evaluations, best.jacobians
    );
    format!(
        "- another definition (Jansen's leg, six of its numbers from random starts): objective \
         {:.3e}, numbers to {dev:.1e}, {}\n",
        best.outcome.cost,
        if best.outcome.cost < 1e-20 {
            "met"
        } else {
            "not met"
        }
    )
}
