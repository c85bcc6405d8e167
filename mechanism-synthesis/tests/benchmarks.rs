//! The benchmark cases with small budgets: every design the solver returns is
//! re-evaluated by an independent closed-form four-bar (the tests' own
//! circle intersection, `common`, both assembly modes), its reported
//! objective is one of the two, its bounds and constraints hold (Grashof crank-rocker with the
//! crank shortest, free crank angles ascending in [0, 2 pi]), and it is at
//! least as good as the figures the metaheuristics of the literature report.

use std::f64::consts::TAU;

use mechanism_synthesis::cases::{self, Case, Found};
use mechanism_synthesis::fourbar::Timing;

mod common;
use common::coupler;

/// The objective of design `d` in mode `m` by [`coupler`].
fn objective(case: &Case, d: &[f64], m: f64) -> f64 {
    let mut s = 0.0;
    for (k, t) in case.targets.iter().enumerate() {
        match coupler(d, d[9 + k], m) {
            Some(c) => s += (c[0] - t[0]).powi(2) + (c[1] - t[1]).powi(2),
            None => return f64::INFINITY,
        }
    }
    s
}

/// Checks `f` against `case`'s bounds and constraints and the independent
/// objective; returns that objective.
fn verify(case: &Case, f: &Found) -> f64 {
    let d = &f.design.0;
    assert_eq!(d.len(), 9 + case.targets.len(), "{}", case.id);
    // Bounds, with the rounding of the parametrization (a few ulps of 60).
    let tol = 1e-12;
    for &r in &d[0..4] {
        assert!(
            r >= case.links.0 - tol && r <= case.links.1 + tol,
            "{}: {d:?}",
            case.id
        );
    }
    let free_frame = case.frame.is_none();
    let coords: &[usize] = if free_frame { &[4, 5, 7, 8] } else { &[4, 5] };
    for &j in coords {
        assert!(
            d[j] >= case.coords.0 - tol && d[j] <= case.coords.1 + tol,
            "{}",
            case.id
        );
    }
    if let Some(fr) = case.frame {
        assert_eq!(&d[6..9], &fr[..], "{}", case.id);
    } else {
        assert!((0.0..=TAU).contains(&d[6]), "{}: theta0 {}", case.id, d[6]);
    }
    // Crank-rocker: r2 shortest, s + l <= p + q (a relative ulp-level slack:
    // the boundary is where the optimum of some cases lies).
    let r = [d[0], d[1], d[2], d[3]];
    assert!(
        r.iter().all(|&x| d[1] <= x * (1.0 + 1e-12)),
        "{}: {r:?}",
        case.id
    );
    let l = r.iter().copied().fold(f64::MIN, f64::max);
    let sum: f64 = r.iter().sum();
    assert!(
        d[1] + l <= (sum - d[1] - l) * (1.0 + 1e-12),
        "{}: Grashof {r:?}",
        case.id
    );
    match &case.timing {
        Timing::Prescribed(a) => assert_eq!(&d[9..], &a[..], "{}", case.id),
        Timing::Free => {
            let th = &d[9..];
            assert!(th.iter().all(|t| (0.0..=TAU).contains(t)), "{}", case.id);
            assert!(th.windows(2).all(|w| w[0] <= w[1]), "{}: {th:?}", case.id);
        }
    }
    let (plus, minus) = (objective(case, d, 1.0), objective(case, d, -1.0));
    // The reported objective is one mode's, to rounding (1e-9 relative: the
    // two evaluations differ in the order of a few dozen operations; plus
    // 1e-24 absolute: at an exact fit each residual is rounding, about
    // 30 operations x 2^-52 x 60 = 4e-13 on coordinates up to 60, so two
    // evaluations of 2n <= 36 squared residuals of 1e-14 differ by up to
    // 2 x 36 x 1e-14 x 4e-13 = 3e-25).
    let close = |a: f64| (a - f.objective).abs() <= 1e-9 * f.objective + 1e-24;
    assert!(
        close(plus) || close(minus),
        "{}: reported {} vs {plus}, {minus}",
        case.id,
        f.objective
    );
    f.objective
}

fn case(id: &str) -> Case {
    cases::all()
        .into_iter()
        .find(|c| c.id == id)
        .expect("known case")
}

#[test]
fn arc5_timed_beats_the_published_runs_and_verifies() {
    // 31 runs each of three published algorithms stop at 2.6e-3, a Nelder-Mead
    // run at 3.8e-4 (issue 37); multi-start LM reaches 7.4e-7 with 20 starts.
    let c = case("arc5_timed");
    let f = cases::solve(&c, 20, 10, 30, 0, 1);
    assert!(verify(&c, &f) < 1e-6, "{}", f.objective);
}

#[test]
fn line6_free_is_fitted_exactly_and_verifies() {
    // 12 equations, 15 unknowns: an exact fit exists (longer runs reach
    // 1e-28); a small budget gets within 1e-6 (a thousandth of a unit per
    // point), four orders below the prescribed-timing case's best (4.4e-2).
    let c = case("line6_free");
    let f = cases::solve(&c, 20, 10, 30, 30, 1);
    assert!(verify(&c, &f) < 1e-6, "{}", f.objective);
}

#[test]
fn line6_timed_kunjur18_and_ellipse10_verify_on_a_small_budget() {
    // Budgets too small to find the best: the constraints and the independent
    // objective are what this proves; the bounds on the objective are the
    // range the literature's metaheuristics report (Cabrera et al. 2002 and
    // successors: line ~1e-1 or above, Kunjur ~1e-2, ellipse ~2).
    // Twenty starts and thirty hops (a hundredth of the example's budget):
    // with six starts and ten, a few seeds of ellipse10 still sit at 3 to 20.
    for (id, bound) in [
        ("line6_timed", 0.5),
        ("kunjur18_free", 0.05),
        ("ellipse10_free", 3.0),
    ] {
        let c = case(id);
        let f = cases::solve(&c, 20, 10, 30, 30, 3);
        assert!(verify(&c, &f) < bound, "{id}: {}", f.objective);
    }
}
