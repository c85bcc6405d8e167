//! Synthesis of a definition other than the four-bar: Jansen's leg. The
//! targets are the foot path that the holy numbers generate at 24 crank
//! angles; the synthesis recovers the six numbers left free (from a perturbed
//! start by the local solver alone, and from random starts by the multi-start)
//! and the foot path it reproduces matches the known leg's at 72 other crank
//! angles. The leg's definition is first checked against the lengths it is
//! built from, by distances computed here.

use std::f64::consts::TAU;

use mechanism_synthesis::jansen::{self, FootPath, JansenFootInput, HOLY};
use mechanism_synthesis::lm::{Options, Solver};
use mechanism_synthesis::multistart;
use mechanism_synthesis::problem::Problem;

/// The free numbers: `e, f, g, h, j, k` (indices into `HOLY`).
const FREE: [usize; 6] = [4, 5, 6, 7, 9, 10];

/// The crank angles of `count` equally spaced poses, offset by `phase`.
fn angles(count: usize, phase: f64) -> Vec<f64> {
    (0..count)
        .map(|k| phase + TAU * k as f64 / count as f64)
        .collect()
}

/// The foot points of the leg of numbers `n` at `th`.
fn path(n: &[f64; 13], th: &[f64]) -> Vec<[f64; 2]> {
    let leg = jansen::leg(n).expect("triangles close");
    th.iter()
        .map(|&t| jansen::foot(&leg, t).expect("the leg assembles"))
        .collect()
}

/// The problem: the holy leg's foot at 24 angles, the six numbers free
/// within 20 % of their values.
fn problem() -> FootPath {
    let th = angles(24, 0.0);
    let targets = path(&HOLY, &th);
    FootPath::new(FREE.to_vec(), th, targets, 0.2)
}

/// The largest distance between the foot paths of `n` and the holy leg at 72
/// angles between the targets'.
fn path_error(n: &[f64; 13]) -> f64 {
    let th = angles(72, 0.5 * TAU / 72.0);
    path(n, &th)
        .iter()
        .zip(path(&HOLY, &th))
        .map(|(p, q)| (p[0] - q[0]).hypot(p[1] - q[1]))
        .fold(0.0, f64::max)
}

#[test]
fn the_leg_has_the_holy_lengths_at_every_pose() {
    // Each of the thirteen lengths between the joints the definition places,
    // at 36 crank angles, to 1e-12 relative (a few dozen roundings of
    // coordinates of size 100).
    let leg = jansen::leg(&HOLY).expect("triangles close");
    let d = |p: mechanism::Point2<f64>, q: mechanism::Point2<f64>| (p - q).norm();
    for th in angles(36, 0.1) {
        let p = leg
            .position(&JansenFootInput { theta: th })
            .expect("assembles");
        let [a, b, c, dd, e, f, g, h, i, j, k, l, m] = HOLY;
        let o = mechanism::Point2::new(0.0, 0.0);
        let z = mechanism::Point2::new(-a, -l);
        for (got, want) in [
            (d(p.A, o), m),
            (d(p.B, p.A), j),
            (d(p.B, z), b),
            (d(p.C, p.A), k),
            (d(p.C, z), c),
            (d(p.D, z), dd),
            (d(p.D, p.B), e),
            (d(p.E, p.D), f),
            (d(p.E, p.C), g),
            (d(p.F, p.E), h),
            (d(p.F, p.C), i),
        ] {
            assert!((got - want).abs() <= 1e-12 * want, "{got} vs {want}");
        }
    }
}

#[test]
fn a_perturbed_start_recovers_the_holy_numbers() {
    // From each free number moved by 3 to 8 % (alternating signs), the
    // bounded LM alone drives the objective from about 1e2 to rounding: 48
    // residuals of coordinates about 100, each good to a few 1e-14, squared
    // and summed, are below 1e-24; 1e-20 leaves room. The six numbers are
    // then Jansen's to 1e-9 relative (the Jacobian is well conditioned
    // there: the fit determines them), and the foot path between the targets
    // is the holy leg's to 1e-9.
    let p = problem();
    let x0: Vec<f64> = FREE
        .iter()
        .enumerate()
        .map(|(k, &v)| HOLY[v] * (1.0 + if k % 2 == 0 { 0.03 } else { -0.08 }))
        .collect();
    let mut buf = vec![0.0; p.residual_count()];
    let start = mechanism_synthesis::problem::objective(&p, &x0, &mut buf);
    assert!(start > 1.0, "the start is far from the fit: {start}");
    let out = Solver::new(&p).minimize(
        &p,
        &x0,
        &Options {
            max_iterations: 200,
            ..Options::default()
        },
    );
    assert!(out.cost < 1e-20, "{}", out.cost);
    let n = p.numbers(&out.x);
    for &v in &FREE {
        assert!(
            (n[v] - HOLY[v]).abs() <= 1e-9 * HOLY[v],
            "{}: {} vs {}",
            jansen::NAMES[v],
            n[v],
            HOLY[v]
        );
    }
    assert!(path_error(&n) < 1e-9, "{}", path_error(&n));
}

#[test]
fn the_multi_start_finds_the_fit_from_random_starts() {
    // Starts uniform in the 20 % box (many do not assemble over the whole
    // turn; the screening keeps those that do): the best of 12 local solves,
    // a few hops and the polish reaches the exact fit; the foot path between
    // the targets is the holy leg's to 1e-9.
    let p = problem();
    let (lo, hi) = (p.lower().to_vec(), p.upper().to_vec());
    let settings = jansen::settings(5);
    let best = multistart::run(&p, &settings, |rng, x| {
        for (j, v) in x.iter_mut().enumerate() {
            *v = rng.range(lo[j], hi[j]);
        }
    });
    assert!(best.outcome.cost < 1e-20, "{}", best.outcome.cost);
    let n = p.numbers(&best.outcome.x);
    assert!(path_error(&n) < 1e-9, "{}", path_error(&n));
}
