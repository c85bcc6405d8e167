//! The five path-generation benchmark cases of the four-bar literature
//! (Cabrera, Simon and Prado, Mech. Mach. Theory 37 (2002) 1165; Kunjur and
//! Krishnamurty 1997; Acharyya and Mandal 2009; Sleesongsom and Bureerat
//! 2018), as stated in the project's issue 37, and the solver that runs them.

use std::f64::consts::{PI, TAU};

use mechanism::Mode;

use crate::de;
use crate::fourbar::{Design, PathProblem, Timing};
use crate::lm::Options;
use crate::multistart::{self, Settings};
use crate::problem::Problem;

/// A benchmark case.
#[derive(Clone, Debug)]
pub struct Case {
    /// Its identifier (`line6_timed`, ..).
    pub id: &'static str,
    /// Target points.
    pub targets: Vec<[f64; 2]>,
    /// Prescribed or free crank angles.
    pub timing: Timing,
    /// Fixed `(theta0, x0, y0)`, or `None` when free.
    pub frame: Option<[f64; 3]>,
    /// Bounds of `r1 .. r4`.
    pub links: (f64, f64),
    /// Bounds of `rcx, rcy, x0, y0`.
    pub coords: (f64, f64),
}

impl Case {
    /// A user's path-generation case, checked: at least 3 finite `targets`;
    /// `angles` (crank angles from the ground link, rad, in `[0, 2 pi]`),
    /// one per target, or `None` for free timing; `frame` `(theta0, x0,
    /// y0)` fixed or `None` for free; `links` (bounds of `r1 .. r4`, not
    /// negative) and `coords` (bounds of `rcx, rcy, x0, y0`) each with
    /// `lo < hi`, finite. `Err`: what is wrong, as a sentence to show the
    /// user (the Python package and the `mechanism` command show it).
    pub fn path(
        targets: Vec<[f64; 2]>,
        angles: Option<Vec<f64>>,
        frame: Option<[f64; 3]>,
        links: (f64, f64),
        coords: (f64, f64),
    ) -> Result<Case, String> {
        if targets.len() < 3 {
            return Err(format!(
                "{} target points: a path needs at least 3",
                targets.len()
            ));
        }
        if !targets.iter().flatten().all(|x| x.is_finite()) {
            return Err("a target point is not finite".into());
        }
        let timing = match angles {
            None => Timing::Free,
            Some(a) if a.len() != targets.len() => {
                return Err(format!(
                    "{} angles for {} target points: give one crank angle per point, or none (free timing)",
                    a.len(),
                    targets.len()
                ))
            }
            Some(a) if !a.iter().all(|x| (0.0..=TAU).contains(x)) => {
                return Err("every crank angle is in [0, 2 pi] (rad, from the ground link)".into())
            }
            Some(a) => Timing::Prescribed(a),
        };
        if !frame.iter().flatten().all(|x| x.is_finite()) {
            return Err("the frame (theta0, x0, y0) is not finite".into());
        }
        for (name, (lo, hi)) in [("links", links), ("coords", coords)] {
            if !(lo.is_finite() && hi.is_finite() && lo < hi) {
                return Err(format!(
                    "{name} = ({lo}, {hi}): bounds need lo < hi, both finite"
                ));
            }
        }
        if links.0 < 0.0 {
            return Err(format!("links = {links:?}: lengths are not negative"));
        }
        Ok(Case {
            id: "user",
            targets,
            timing,
            frame,
            links,
            coords,
        })
    }

    /// The problem in assembly mode `mode`.
    pub fn problem(&self, mode: Mode) -> PathProblem {
        PathProblem::new(
            self.targets.clone(),
            self.timing.clone(),
            self.frame,
            self.links,
            self.coords,
            mode,
        )
    }
}

/// The six points of a vertical line.
fn line6() -> Vec<[f64; 2]> {
    (0..6).map(|k| [20.0, 20.0 + 5.0 * k as f64]).collect()
}

/// The five cases, in the order.
pub fn all() -> Vec<Case> {
    let line_angles = (0..6).map(|k| PI / 6.0 + k as f64 * PI / 12.0).collect();
    vec![
        Case {
            id: "line6_timed",
            targets: line6(),
            timing: Timing::Prescribed(line_angles),
            frame: None,
            links: (0.0, 60.0),
            coords: (-60.0, 60.0),
        },
        Case {
            id: "line6_free",
            targets: line6(),
            timing: Timing::Free,
            frame: None,
            links: (0.0, 60.0),
            coords: (-60.0, 60.0),
        },
        Case {
            id: "arc5_timed",
            targets: vec![
                [3.0, 3.0],
                [2.759, 3.363],
                [2.372, 3.663],
                [1.890, 3.862],
                [1.355, 3.943],
            ],
            timing: Timing::Prescribed((0..5).map(|k| PI / 6.0 + k as f64 * PI / 12.0).collect()),
            frame: Some([0.0, 0.0, 0.0]),
            links: (0.0, 50.0),
            coords: (-50.0, 50.0),
        },
        Case {
            id: "kunjur18_free",
            targets: vec![
                [0.5, 1.1],
                [0.4, 1.1],
                [0.3, 1.1],
                [0.2, 1.0],
                [0.1, 0.9],
                [0.005, 0.75],
                [0.02, 0.6],
                [0.0, 0.5],
                [0.0, 0.4],
                [0.03, 0.3],
                [0.1, 0.25],
                [0.15, 0.2],
                [0.2, 0.3],
                [0.3, 0.4],
                [0.4, 0.5],
                [0.5, 0.7],
                [0.6, 0.9],
                [0.6, 1.0],
            ],
            timing: Timing::Free,
            frame: None,
            links: (0.0, 50.0),
            coords: (-50.0, 50.0),
        },
        Case {
            id: "ellipse10_free",
            targets: vec![
                [20.0, 10.0],
                [17.66, 15.142],
                [11.736, 17.878],
                [5.0, 16.928],
                [0.60307, 12.736],
                [0.60307, 7.2638],
                [5.0, 3.0718],
                [11.736, 2.1215],
                [17.66, 4.8577],
                [20.0, 10.0],
            ],
            timing: Timing::Free,
            frame: None,
            links: (5.0, 60.0),
            coords: (-60.0, 60.0),
        },
    ]
}

/// The best design a run found.
#[derive(Clone, Debug)]
pub struct Found {
    /// The design `[r1, r2, r3, r4, rcx, rcy, theta0, x0, y0, th2_1 ..]`.
    pub design: Design,
    /// Its objective (sum of squared distances).
    pub objective: f64,
    /// The assembly mode it was found in.
    pub mode: Mode,
    /// Objective evaluations over the run (both modes).
    pub evaluations: usize,
    /// Jacobian evaluations over the run (both modes).
    pub jacobians: usize,
}

/// Candidates screened per start and iterations per local solve of
/// [`solve_user`]: the budget of the benchmark cases with free timing (the
/// example `synthesis`).
pub const USER_SCREEN: usize = 20;
/// See [`USER_SCREEN`].
pub const USER_ITERATIONS: usize = 30;

/// [`solve`] with `starts` starts and `hops` basin hops per assembly mode,
/// [`USER_SCREEN`] candidates per start and [`USER_ITERATIONS`] iterations
/// per local solve: what the Python package's `synthesize_path` and the
/// `mechanism synthesize` command run. `Err`, as a sentence to show the
/// user: no start (`starts` 0), or no design that assembles at every
/// target.
pub fn solve_user(case: &Case, starts: usize, hops: usize, seed: u64) -> Result<Found, String> {
    if starts == 0 {
        return Err("starts = 0: the search needs a start".into());
    }
    let found = solve(case, starts, USER_SCREEN, USER_ITERATIONS, hops, seed);
    if found.objective.is_finite() {
        Ok(found)
    } else {
        Err("no design assembled at every target: widen the bounds or move the targets".into())
    }
}

/// Runs `starts` local solves of at most `local_iterations` iterations in each
/// assembly mode (`screen` candidates per start) from `seed`, then `hops`
/// basin hops from the best of each mode and its polish, and returns the better design; its objective is evaluated
/// again from the design as returned (crank angles clamped into `[0, 2 pi]`).
pub fn solve(
    case: &Case,
    starts: usize,
    screen: usize,
    local_iterations: usize,
    hops: usize,
    seed: u64,
) -> Found {
    // The two modes are independent runs with their own seeds: one thread each.
    let runs: Vec<(Mode, PathProblem, multistart::Best)> = std::thread::scope(|sc| {
        let handles: Vec<_> = [Mode::Plus, Mode::Minus]
            .into_iter()
            .enumerate()
            .map(|(k, mode)| {
                sc.spawn(move || {
                    let p = case.problem(mode);
                    let settings = Settings {
                        starts,
                        screen,
                        local: Options {
                            max_iterations: local_iterations,
                            ..Options::default()
                        },
                        polish: Options {
                            max_iterations: 2000,
                            ..Options::default()
                        },
                        hops,
                        hop_scale: 0.2,
                        seed: seed.wrapping_mul(2).wrapping_add(k as u64),
                    };
                    let b = multistart::run(&p, &settings, |rng, x| p.sample(rng, x));
                    (mode, p, b)
                })
            })
            .collect();
        handles.into_iter().filter_map(|h| h.join().ok()).collect()
    });
    let evaluations = runs.iter().map(|r| r.2.evaluations).sum();
    let jacobians = runs.iter().map(|r| r.2.jacobians).sum();
    let best = runs
        .iter()
        .filter(|r| r.2.outcome.cost.is_finite())
        .min_by(|a, b| a.2.outcome.cost.total_cmp(&b.2.outcome.cost))
        .map(|(mode, p, b)| (*mode, p, b.outcome.x.as_slice()));
    found(case, best, evaluations, jacobians)
}

/// Runs plain differential evolution ([`crate::de`], the usual settings) on
/// `case` with `budget` objective evaluations in all, half in each assembly
/// mode (one thread each, as [`solve`]), from `seed`, and returns the better
/// design, its objective evaluated again as [`solve`]'s.
pub fn solve_de(case: &Case, budget: usize, seed: u64) -> Found {
    let runs: Vec<(Mode, PathProblem, de::Best)> = std::thread::scope(|sc| {
        let handles: Vec<_> = [Mode::Plus, Mode::Minus]
            .into_iter()
            .enumerate()
            .map(|(k, mode)| {
                sc.spawn(move || {
                    let p = case.problem(mode);
                    let s = de::Settings::usual(
                        p.dim(),
                        budget / 2,
                        seed.wrapping_mul(2).wrapping_add(k as u64),
                    );
                    let b = de::run(&p, &s);
                    (mode, p, b)
                })
            })
            .collect();
        handles.into_iter().filter_map(|h| h.join().ok()).collect()
    });
    let evaluations = runs.iter().map(|r| r.2.evaluations).sum();
    let best = runs
        .iter()
        .filter(|r| r.2.cost.is_finite())
        .min_by(|a, b| a.2.cost.total_cmp(&b.2.cost))
        .map(|(mode, p, b)| (*mode, p, b.x.as_slice()));
    found(case, best, evaluations, 0)
}

/// The [`Found`] of the best `(mode, problem, variables)` of a run (`None`:
/// no design assembled), its crank angles clamped into `[0, 2 pi]` and its
/// objective evaluated again from the design.
fn found(
    case: &Case,
    best: Option<(Mode, &PathProblem, &[f64])>,
    evaluations: usize,
    jacobians: usize,
) -> Found {
    let Some((mode, p, x)) = best else {
        return Found {
            design: Design(vec![f64::NAN; 9 + case.targets.len()]),
            objective: f64::INFINITY,
            mode: Mode::Plus,
            evaluations,
            jacobians,
        };
    };
    let mut design = p.design(x);
    for t in &mut design.0[9..] {
        *t = t.clamp(0.0, TAU);
    }
    let objective = path_objective(&design, mode, &case.targets);
    Found {
        design,
        objective,
        mode,
        evaluations,
        jacobians,
    }
}

/// The sum of squared distances from the coupler point of `design` (in
/// assembly mode `mode`) at its crank angles to `targets`; `+inf` if it does
/// not assemble at one of them.
pub fn path_objective(design: &Design, mode: Mode, targets: &[[f64; 2]]) -> f64 {
    let fb = design.mechanism(mode);
    let mut s = 0.0;
    for (th, t) in design.angles().iter().zip(targets) {
        match PathProblem::coupler(&fb, *th) {
            Some(c) => s += (c[0] - t[0]).powi(2) + (c[1] - t[1]).powi(2),
            None => return f64::INFINITY,
        }
    }
    s
}
