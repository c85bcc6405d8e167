//! Part 4: stiff kinetostatics. Builds on `mechanism-core/tests/primitives/kinetostatics.rs`
//! (one stiff pose against rational arithmetic, and the naive solver's zero
//! pivot at a horizontal link 2): here the same RRR group, in millimetres,
//! with a 1e6 kg link and a 1e-6 kg link (12 orders of magnitude, and their
//! inertias 1e6 * 0.1 m^2 down to 1e-6 * 1e-5 m^2 in kg mm^2), loads in N and
//! couples in N mm, swept through the angle of link 2 from horizontal,
//! 1e-1 .. 1e-13 rad, against the double-double Newton-Euler reference
//! (`mechanism_reference::groups::rrr_reactions`, moments about each link's
//! outer joint, not about `C` as the core does).

use crate::common::EPS;
use mechanism::force::{self, group, inertia_and_gravity, Wrench};
use mechanism::linsolve::solve;
use mechanism::{Point2, Real, Vector2};
use mechanism_reference::groups as refg;
use mechanism_reference::naive::solve_unpivoted_unscaled;
use mechanism_reference::Dd;

type P = Point2<f64>;
type V = Vector2<f64>;

/// Partial pivoting without row scaling, written here in textbook index form
/// (the third method of the comparison).
#[allow(clippy::needless_range_loop)]
pub fn solve_pivoted_unscaled<const N: usize>(mut a: [[f64; N]; N], mut b: [f64; N]) -> [f64; N] {
    for k in 0..N {
        let p = (k..N)
            .max_by(|&i, &j| a[i][k].abs().total_cmp(&a[j][k].abs()).then(j.cmp(&i)))
            .unwrap_or(k);
        a.swap(k, p);
        b.swap(k, p);
        for i in k + 1..N {
            let m = a[i][k] / a[k][k];
            for j in k..N {
                a[i][j] -= m * a[k][j];
            }
            b[i] -= m * b[k];
        }
    }
    let mut x = [0.0; N];
    for k in (0..N).rev() {
        let s: f64 = (k + 1..N).map(|j| a[k][j] * x[j]).sum();
        x[k] = (b[k] - s) / a[k][k];
    }
    x
}

/// One pose of the sweep: errors (normwise relative to the largest reaction)
/// of `[solve, naive (forces-first rows), pivoted unscaled]`, the naive
/// result being `None` when it divided by an exact zero.
pub struct StiffCase {
    /// Angle of link 2 from horizontal (rad).
    pub angle: f64,
    /// `min_pivot_ratio` reported by the core.
    pub min_pivot_ratio: f64,
    /// Errors of the three methods.
    pub errors: [Option<f64>; 3],
}

/// The stiff RRR group with link 2 at `angle` from horizontal.
pub fn stiff_case(angle: f64) -> StiffCase {
    let a = P::new(0.0, 0.0);
    let c = P::new(300.0, 400.0);
    let b = P::new(900.0, 400.0 + 600.0 * angle.tan());
    let g = V::new(0.0, -9810.0); // mm/s^2
                                  // Link 1: 1e6 kg, J = 1e11 kg mm^2; link 2: 1e-6 kg, J = 10 kg mm^2 * 1e-6.
    let (m1, j1, g1, ag1, al1) = (
        1e6,
        1e11,
        P::new(150.0, 200.0),
        V::new(-2500.0, 1200.0),
        3.0,
    );
    let (m2, j2, g2, ag2, al2) = (
        1e-6,
        1e-5,
        P::new(600.0, 400.0),
        V::new(4000.0, -700.0),
        -2.0,
    );
    let (fx, fp) = (V::new(1.0, -2.0), P::new(800.0, 0.0));
    let load1 = inertia_and_gravity(m1, j1, &g1, &ag1, al1, Some(&g), &c);
    let load2 =
        inertia_and_gravity(m2, j2, &g2, &ag2, al2, Some(&g), &c) + Wrench::force_at(&fx, &fp, &c);
    let r = force::rrr::reactions(&a, &b, &c, &load1, &load2).expect("regular pose");
    let ours = [r.a.x, r.a.y, r.b.x, r.b.y, r.c.x, r.c.y];

    // Reference, from the physical data (not from the core's wrenches).
    let dd = |x: f64| Dd::from(x);
    let f1 = refg::scale(dd(m1), refg::sub(refg::v(g.x, g.y), refg::v(ag1.x, ag1.y)));
    let f2a = refg::scale(dd(m2), refg::sub(refg::v(g.x, g.y), refg::v(ag2.x, ag2.y)));
    // Link 2's loads: inertia + weight through G2, and the external force at
    // fp; combine into one force through G2 plus a couple.
    let fxd = refg::v(fx.x, fx.y);
    let f2 = refg::add(f2a, fxd);
    let m2c =
        -(dd(j2) * dd(al2)) + refg::cross(refg::sub(refg::v(fp.x, fp.y), refg::v(g2.x, g2.y)), fxd);
    let exact = refg::rrr_reactions(
        refg::v(a.x, a.y),
        refg::v(b.x, b.y),
        refg::v(c.x, c.y),
        f1,
        refg::v(g1.x, g1.y),
        -(dd(j1) * dd(al1)),
        f2,
        refg::v(g2.x, g2.y),
        m2c,
    )
    .expect("regular pose");
    let size = exact.iter().fold(0.0f64, |m, x| m.max(x.abs().to_f64()));
    let err = |x: &[f64; 6]| {
        x.iter()
            .zip(&exact)
            .map(|(x, e)| (Dd::from(*x) - *e).abs().to_f64())
            .fold(0.0, f64::max)
            / size
    };

    let joints = [
        group::Joint {
            pair: group::Pair::Revolute { point: a },
            connection: group::Connection::OutsideToLink1,
        },
        group::Joint {
            pair: group::Pair::Revolute { point: b },
            connection: group::Connection::OutsideToLink2,
        },
        group::Joint {
            pair: group::Pair::Revolute { point: c },
            connection: group::Connection::Link1ToLink2,
        },
    ];
    let sys = group::assemble(&joints, &c, &load1, &load2);
    // Forces-first row order, as in the core's kinetostatics test: the only
    // order in which naive elimination meets no structural zero.
    let order = [0, 1, 3, 4, 5, 2];
    let naive = solve_unpivoted_unscaled(order.map(|i| sys.matrix[i]), order.map(|i| sys.rhs[i]))
        .ok()
        .filter(|x| x.iter().all(|v| v.is_finite()));
    let pivoted = solve_pivoted_unscaled(sys.matrix, sys.rhs);
    // Sanity: the core's general 6x6 solve on the assembled system is as
    // accurate as the group's own (`force::rrr` eliminates the inner joint
    // exactly and solves the remaining 4x4, so the two round differently;
    // `ours` is held to 8 eps by the sweep below, and so is this).
    let general = solve(sys.matrix, sys.rhs).expect("regular pose").x;
    assert!(
        err(&general) <= 8.0 * EPS,
        "general solve: {:e}",
        err(&general)
    );
    StiffCase {
        angle,
        min_pivot_ratio: r.min_pivot_ratio,
        errors: [
            Some(err(&ours)),
            naive.map(|x| err(&x)),
            Some(err(&pivoted)),
        ],
    }
}

/// Angles of the sweep: 1e-1 .. 1e-13 rad, two per decade, and 0.
pub fn angles() -> Vec<f64> {
    let mut v: Vec<f64> = (2..=26).map(|k| 10f64.powf(-0.5 * k as f64)).collect();
    v.push(0.0);
    v
}

/// Proves: on a group whose link masses span 12 orders of magnitude (loads
/// in N and N mm), the row-scaled pivoting solver's reactions are correct to
/// `8 eps` of the largest reaction at every pose, while naive elimination (no
/// pivoting, no scaling, in the only row order where it starts at all) loses
/// digits in proportion to 1 / angle and divides by zero at angle 0. Partial
/// pivoting without row scaling is as good as the scaled solver on this
/// group (its rows are not badly scaled against each other in the pivot
/// columns): here the fix is the pivoting; the scaling's own failure case is
/// `badly_scaled_force_moment_mix` in `mechanism-core/tests/primitives/linsolve.rs`.
/// The measured numbers are printed for `docs/stability.md`.
#[test]
fn stiff_sweep_scaled_pivoting_against_naive() {
    let mut worst_ours: f64 = 0.0;
    let mut naive_small_angle: f64 = 0.0;
    for angle in angles() {
        let case = stiff_case(angle);
        let [ours, naive, pivoted] = case.errors;
        let ours = ours.unwrap();
        println!(
            "angle {:8.1e}: min pivot ratio {:.2e}; solve {:.2e}, naive {}, pivoted-unscaled {:.2e}",
            case.angle,
            case.min_pivot_ratio,
            ours,
            naive.map_or("division by zero".to_string(), |e| format!("{e:.2e}")),
            pivoted.unwrap()
        );
        worst_ours = worst_ours.max(ours);
        if angle == 0.0 {
            assert!(
                naive.is_none(),
                "naive elimination should meet a zero pivot"
            );
        } else if angle <= 1e-9 {
            naive_small_angle = naive_small_angle.max(naive.unwrap_or(f64::INFINITY));
        }
    }
    // Backward stable and well conditioned after scaling: a few roundings of
    // the largest reaction (measured 1.2e-16, about 0.5 eps).
    assert!(worst_ours <= 8.0 * EPS, "solve: {worst_ours:e}");
    // The naive multiplier is (A - C).y / (B - C).y = 400 / (600 angle): at
    // angle <= 1e-9 it is >= 6e8. Measured: naive up to 6.1e-14 (275 eps,
    // 1000 times ours) at 3.2e-13 rad, growing as the angle shrinks, and a
    // division by zero at 0. Floor 100 eps: a loss that no rounding luck of a
    // stable method produces (ours stays below 0.5 eps at every angle).
    assert!(
        naive_small_angle >= 100.0 * EPS,
        "naive at small angles: {naive_small_angle:e}"
    );
}

/// Reactions of an RRR group whose two links both have mass `m` (inertia
/// `m * 0.01`), divided by `m`.
fn per_unit_mass<T: Real>(m: f64) -> [f64; 6] {
    let p = |x: f64, y: f64| Point2::new(T::lit(x), T::lit(y));
    let v = |x: f64, y: f64| Vector2::new(T::lit(x), T::lit(y));
    let (a, b, c) = (p(0.0, 0.0), p(0.9, 0.1), p(0.3, 0.4));
    let g = v(0.0, -9.81);
    let mt = T::lit(m);
    let load1 = inertia_and_gravity(
        mt,
        T::lit(m * 0.01),
        &p(0.15, 0.2),
        &v(-2.5, 1.2),
        T::lit(3.0),
        Some(&g),
        &c,
    );
    let load2 = inertia_and_gravity(
        mt,
        T::lit(m * 0.01),
        &p(0.6, 0.25),
        &v(4.0, -0.7),
        T::lit(-2.0),
        Some(&g),
        &c,
    );
    let r = force::rrr::reactions(&a, &b, &c, &load1, &load2).expect("regular pose");
    [r.a.x, r.a.y, r.b.x, r.b.y, r.c.x, r.c.y].map(|x| x.as_f64() / mt.as_f64())
}

/// Proves: masses from 1e-9 to 1e6 kg scale the reactions linearly to a few
/// ulp in `f64` and `f32` (nothing underflows, no absolute threshold): the
/// reactions per unit mass agree with those at 1 kg within 8 eps of the
/// largest (the mass and inertia round by half an ulp each; measured below 2
/// eps).
#[test]
fn masses_scale_linearly() {
    fn run<T: Real>() -> f64 {
        let eps = T::eps().as_f64();
        let base = per_unit_mass::<T>(1.0);
        let size = base.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        let mut worst: f64 = 0.0;
        for k in -9..=6 {
            let r = per_unit_mass::<T>(10f64.powi(k));
            for (x, y) in r.iter().zip(&base) {
                worst = worst.max((x - y).abs() / size / eps);
            }
        }
        worst
    }
    let (w64, w32) = (run::<f64>(), run::<f32>());
    println!("masses 1e-9..1e6 kg: reactions / m agree within f64 {w64:.2} eps, f32 {w32:.2} eps");
    assert!(w64 <= 8.0 && w32 <= 8.0, "{w64} {w32}");
}
