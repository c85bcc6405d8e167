//! Kinetostatics: the reactions and driving efforts of `mechanism_core::force`.
//!
//! - seed 003 (an RRR group of a four-bar, solved in Turbo Pascal by Gaussian
//!   elimination) reproduced to the print's rounding, 0.005 N;
//! - every group and driver, random poses and loads: each link is in
//!   equilibrium (three equations, checked about a point the solver did not
//!   use) and inner reactions obey Newton's third law (the one reported force
//!   balances link 2 with `+` and link 1 with `-`);
//! - a stiff case (masses 1e-6 kg and 1e6 kg, millimetres) against the exact
//!   rational solution, where naive elimination fails;
//! - power balance (virtual work) for a mechanism built on each group and
//!   driver with the kinematics of `dyad` and `driver`: driving power + power
//!   of external loads + power of inertia loads (+ weight) = 0.
//!
//! Tolerances, and why:
//!
//! - equilibrium: `64 eps` relative to the largest single term of the
//!   equation (force or moment of a force), loads and reactions alike. The
//!   solver is backward stable: its residual is a few rounding units of the
//!   terms it sums, whatever the conditioning (near a singular pose the
//!   reactions grow and so does the yardstick). Observed: below `8 eps`.
//! - power balance: `1e-10` relative to the gross power (the absolute values
//!   of the power terms and of the products inside each link's power; see
//!   `check_power`). Positions, rates and reactions each carry relative errors
//!   of a few eps times the condition number, which the samples bound (poses
//!   with a relative kinematic determinant below 0.05 or `min_pivot_ratio <
//!   0.01` are rejected), but a link's load can itself be a small difference
//!   (a weight, an external force and a couple nearly cancelling), and the
//!   reactions' rounding follows the parts, not the difference: over 200 000
//!   random cases per test the worst was 2.1e-11 (`1e-12` of the terms alone
//!   failed about once in 100 000 cases, so now and then in CI). 1e-10 still
//!   catches any sign or lever-arm mistake (those are errors of order 1).
//! - seed 003: the print has two decimals; the exact solution of its inputs
//!   (rational arithmetic) differs from the print by at most 0.0030 N, and our
//!   f64 result from the exact one by ~1e-12 N, so 0.005 N. In f32, the
//!   reactions (~3000 N) carry ~1e-7 relative rounding times the condition
//!   (~10): 0.05 N.

use mechanism_core::driver::{actuator, crank, slider};
use mechanism_core::dyad::{prp, rpp, rpr, rrp, rrr};
use mechanism_core::force::{self, group, inertia_and_gravity, PrismaticReaction, Wrench};
use mechanism_core::guide::{Line, LineAcceleration, LineVelocity};
use mechanism_core::linsolve::solve;
use mechanism_core::{Error, Fault, Mode, Point2, Primitive, Vector2};
use mechanism_reference::naive::{solve_unpivoted_unscaled, NaiveError};
use proptest::prelude::*;
use proptest::test_runner::TestCaseError;

type V = Vector2<f64>;
type P = Point2<f64>;

const EPS: f64 = f64::EPSILON;

fn perp(v: &V) -> V {
    V::new(-v.y, v.x)
}

fn cross(a: &V, b: &V) -> f64 {
    a.x * b.y - a.y * b.x
}

// ---------------------------------------------------------------------------
// Seed 003
// ---------------------------------------------------------------------------

#[path = "../../../examples/common/seed003.rs"]
mod seed003;
use seed003::group as seed_003;

/// The printed results: F12 = (1317.57, 3011.05) N, F03 = (-2355.29, 2604.79) N.
///
/// Finding on the inertia couples: the text writes `Mu2 = -JS2 e2` but
/// `Mu3 = Js3 e3` (no minus); the Pascal code has `mu2 := -Js2*e2` and
/// `mu3 := -Js3*e3`. Solving exactly (rational arithmetic) both ways:
/// with `-J3 e3` the reactions are (1317.5726, 3011.0530), (-2355.2926,
/// 2604.7870), matching the print to its last digit; with `+J3 e3` they are
/// (1321.1770, 3012.8889), (-2358.8970, 2602.9511), 3.6 N off. So the printed
/// run used the code's d'Alembert sign, `Mu3 = -J3 e3`, and the text's formula
/// is a typo. Our `inertia_and_gravity` uses `-J alpha` and reproduces the
/// print.
#[test]
fn seed_003_rrr_group_reproduced() {
    let out = seed_003::<f64>(-1.0);
    let close = |x: f64, printed: f64| (x - printed).abs() <= 0.005;
    assert!(
        close(out.f12.x, 1317.57) && close(out.f12.y, 3011.05),
        "F12 {:?}",
        out.f12
    );
    assert!(
        close(out.f03.x, -2355.29) && close(out.f03.y, 2604.79),
        "F03 {:?}",
        out.f03
    );
    // Against the exact solution of the same inputs (rational arithmetic).
    let exact = [
        1317.5726493303,
        3011.0529849393,
        -2355.2926493303,
        2604.7870150607,
    ];
    let got = [out.f12.x, out.f12.y, out.f03.x, out.f03.y];
    for (g, e) in got.iter().zip(exact) {
        assert!((g - e).abs() < 1e-6, "{got:?}");
    }
    // The seed does not print the inner reaction; it balances link 3 (with
    // F03) and link 2 (with F12 and -F23), which the generic checks cover.
    assert!(out.f23.norm() > 0.0);
    assert!(out.ratio > 0.05, "indicator {}", out.ratio);

    // The text's `Mu3 = +J3 e3` misses the print by 3.6 N.
    let wrong = seed_003::<f64>(1.0);
    assert!((wrong.f12.x - 1317.57).abs() > 3.0, "{:?}", wrong.f12);
    assert!((wrong.f12.x - 1321.1770).abs() < 1e-3, "{:?}", wrong.f12);
}

#[test]
fn seed_003_in_f32() {
    let out = seed_003::<f32>(-1.0);
    let close = |x: f32, printed: f32| (x - printed).abs() <= 0.05;
    assert!(
        close(out.f12.x, 1317.57) && close(out.f12.y, 3011.05),
        "F12 {:?}",
        out.f12
    );
    assert!(
        close(out.f03.x, -2355.29) && close(out.f03.y, 2604.79),
        "F03 {:?}",
        out.f03
    );
}

/// The inertia loads against rigid-body dynamics: a crank of mass `m`,
/// moment of inertia `J` about its centre of mass `G` at distance `d` from the
/// fixed pivot, turning at `omega`, `alpha`, under gravity. The driving torque
/// must be `(J + m d^2) alpha - cross(G - O, m g)` (parallel-axis theorem;
/// the centripetal force passes through `O` and needs no torque) and the pivot
/// force `m (a_G - g)`.
#[test]
fn inertia_loads_match_rigid_body_dynamics() {
    let (m, j, omega, alpha) = (3.0, 0.02, 7.0, -40.0);
    let o = P::new(0.1, -0.2);
    let r = V::new(0.12, 0.05);
    let g_point = o + r;
    let a_g = perp(&r) * alpha - r * (omega * omega);
    let g = V::new(0.0, -9.81);
    let load = inertia_and_gravity(m, j, &g_point, &a_g, alpha, Some(&g), &o);
    let d = force::crank::reactions(&load).unwrap();
    let torque = (j + m * r.norm_squared()) * alpha - cross(&r, &(g * m));
    assert!(
        (d.torque - torque).abs() <= 8.0 * EPS * torque.abs(),
        "{} {torque}",
        d.torque
    );
    let pivot = (a_g - g) * m;
    assert!((d.pivot - pivot).norm() <= 8.0 * EPS * pivot.norm());
    // Without gravity (`None`) only the inertia remains.
    let load = inertia_and_gravity(m, j, &g_point, &a_g, alpha, None, &o);
    let torque = (j + m * r.norm_squared()) * alpha;
    assert!(
        (force::crank::reactions(&load).unwrap().torque - torque).abs() <= 8.0 * EPS * torque.abs()
    );
}

// ---------------------------------------------------------------------------
// Equilibrium of each link, and Newton's third law
// ---------------------------------------------------------------------------

/// The loads on one link, for an independent equilibrium check: forces with
/// their points of application, and free couples.
#[derive(Default, Clone)]
struct Body {
    forces: Vec<(V, P)>,
    couples: Vec<f64>,
}

impl Body {
    fn force(mut self, f: V, at: P) -> Self {
        self.forces.push((f, at));
        self
    }
    fn couple(mut self, m: f64) -> Self {
        self.couples.push(m);
        self
    }
    /// A wrench stated about `about`: its force through `about` plus its moment.
    fn wrench(self, w: &Wrench<f64>, about: P) -> Self {
        self.force(w.force, about).couple(w.moment)
    }
    /// A prismatic reaction (with `sign` +1 on the receiver, -1 on the giver)
    /// rebuilt from `normal` and the unit direction, not from `.force`.
    fn prismatic(self, r: &PrismaticReaction<f64>, dir: &V, at: P, sign: f64) -> Self {
        let n = perp(&dir.normalize());
        self.force(n * (sign * r.normal), at)
            .couple(sign * r.moment)
    }
    /// Residual of the three equations about `q`, relative to the largest
    /// term: `max(|sum F| / max|F_i|, |sum M| / max|M_i|)`.
    fn residual(&self, q: &P) -> f64 {
        let sum_f: V = self.forces.iter().map(|(f, _)| f).sum();
        let moments: Vec<f64> = self
            .forces
            .iter()
            .map(|(f, p)| cross(&(p - q), f))
            .chain(self.couples.iter().copied())
            .collect();
        let sum_m: f64 = moments.iter().sum();
        let max_f = self
            .forces
            .iter()
            .map(|(f, _)| f.norm())
            .fold(0.0, f64::max);
        let max_m = self
            .forces
            .iter()
            .map(|(f, p)| (p - q).norm() * f.norm())
            .chain(self.couples.iter().map(|m| m.abs()))
            .fold(0.0, f64::max);
        let rel = |num: f64, den: f64| if den > 0.0 { num / den } else { num };
        rel(sum_f.norm(), max_f).max(rel(sum_m.abs(), max_m))
    }
}

fn check_balanced(bodies: &[(&str, Body)], q: &P) -> Result<(), TestCaseError> {
    for (name, body) in bodies {
        let r = body.residual(q);
        prop_assert!(r <= 64.0 * EPS, "{name}: residual {r:e}");
    }
    Ok(())
}

fn check_prismatic(r: &PrismaticReaction<f64>, dir: &V) -> Result<(), TestCaseError> {
    let d = dir.normalize();
    let f = perp(&d) * r.normal;
    prop_assert!((r.force - f).norm() <= 4.0 * EPS * f.norm().max(f64::MIN_POSITIVE));
    // Frictionless: no component along the pair.
    prop_assert!(r.force.dot(&d).abs() <= 4.0 * EPS * r.force.norm());
    Ok(())
}

/// A point in a box of half-size `scale`.
fn point(scale: f64) -> impl Strategy<Value = P> {
    (-1.0f64..1.0, -1.0f64..1.0).prop_map(move |(x, y)| P::new(x * scale, y * scale))
}

fn direction() -> impl Strategy<Value = V> {
    (0.0f64..std::f64::consts::TAU, 0.1f64..10.0).prop_map(|(t, l)| V::new(t.cos(), t.sin()) * l)
}

/// A length scale and a force scale, each 10^[-3, 3] (the solver must not
/// care about units).
fn scales() -> impl Strategy<Value = (f64, f64)> {
    (-3.0f64..3.0, -3.0f64..3.0).prop_map(|(l, f)| (10f64.powf(l), 10f64.powf(f)))
}

/// A wrench with force components up to `force` and moment up to
/// `force * length`.
fn wrench(length: f64, force: f64) -> impl Strategy<Value = Wrench<f64>> {
    (-1.0f64..1.0, -1.0f64..1.0, -1.0f64..1.0)
        .prop_map(move |(x, y, m)| Wrench::new(V::new(x * force, y * force), m * force * length))
}

fn singular_ok(e: &Error) -> Result<(), TestCaseError> {
    prop_assert!(matches!(e.fault, Fault::Singular { .. }), "{e}");
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(512))]

    #[test]
    fn rrr_links_balance(
        (l, f) in scales(),
        pts in (point(1.0), point(1.0), point(1.0), point(1.0)),
        w in (wrench(1.0, 1.0), wrench(1.0, 1.0)),
    ) {
        let s = |p: P| P::from(p.coords * l);
        let (a, b, c, q) = (s(pts.0), s(pts.1), s(pts.2), s(pts.3));
        let (w1, w2) = (scale(&w.0, l, f), scale(&w.1, l, f));
        match force::rrr::reactions(&a, &b, &c, &w1, &w2) {
            Err(e) => singular_ok(&e)?,
            Ok(r) => check_balanced(&[
                ("link 1", Body::default().wrench(&w1, c).force(r.a, a).force(-r.c, c)),
                ("link 2", Body::default().wrench(&w2, c).force(r.b, b).force(r.c, c)),
            ], &q)?,
        }
    }

    #[test]
    fn rrp_links_balance(
        (l, f) in scales(),
        pts in (point(1.0), point(1.0), point(1.0)),
        dir in direction(),
        w in (wrench(1.0, 1.0), wrench(1.0, 1.0)),
    ) {
        let s = |p: P| P::from(p.coords * l);
        let (a, c, q) = (s(pts.0), s(pts.1), s(pts.2));
        let (w1, w2) = (scale(&w.0, l, f), scale(&w.1, l, f));
        match force::rrp::reactions(&a, &c, &dir, &w1, &w2) {
            Err(e) => singular_ok(&e)?,
            Ok(r) => {
                check_prismatic(&r.guide, &dir)?;
                check_balanced(&[
                    ("link 1", Body::default().wrench(&w1, c).force(r.a, a).force(-r.c, c)),
                    ("block", Body::default().wrench(&w2, c).force(r.c, c)
                        .prismatic(&r.guide, &dir, c, 1.0)),
                ], &q)?;
            }
        }
    }

    #[test]
    fn rpr_links_balance(
        (l, f) in scales(),
        pts in (point(1.0), point(1.0), point(1.0)),
        dir in direction(),
        w in (wrench(1.0, 1.0), wrench(1.0, 1.0)),
    ) {
        let s = |p: P| P::from(p.coords * l);
        let (a, b, q) = (s(pts.0), s(pts.1), s(pts.2));
        let (w1, w2) = (scale(&w.0, l, f), scale(&w.1, l, f));
        match force::rpr::reactions(&a, &b, &dir, &w1, &w2) {
            Err(e) => singular_ok(&e)?,
            Ok(r) => {
                check_prismatic(&r.slide, &dir)?;
                check_balanced(&[
                    ("block", Body::default().wrench(&w1, a).force(r.a, a)
                        .prismatic(&r.slide, &dir, a, -1.0)),
                    ("rocker", Body::default().wrench(&w2, a).force(r.b, b)
                        .prismatic(&r.slide, &dir, a, 1.0)),
                ], &q)?;
            }
        }
    }

    #[test]
    fn prp_links_balance(
        (l, f) in scales(),
        pts in (point(1.0), point(1.0)),
        dirs in (direction(), direction()),
        w in (wrench(1.0, 1.0), wrench(1.0, 1.0)),
    ) {
        let s = |p: P| P::from(p.coords * l);
        let (c, q) = (s(pts.0), s(pts.1));
        let (w1, w2) = (scale(&w.0, l, f), scale(&w.1, l, f));
        match force::prp::reactions(&c, &dirs.0, &dirs.1, &w1, &w2) {
            Err(e) => singular_ok(&e)?,
            Ok(r) => {
                check_prismatic(&r.guide1, &dirs.0)?;
                check_prismatic(&r.guide2, &dirs.1)?;
                check_balanced(&[
                    ("link 1", Body::default().wrench(&w1, c).force(-r.c, c)
                        .prismatic(&r.guide1, &dirs.0, c, 1.0)),
                    ("link 2", Body::default().wrench(&w2, c).force(r.c, c)
                        .prismatic(&r.guide2, &dirs.1, c, 1.0)),
                ], &q)?;
            }
        }
    }

    #[test]
    fn rpp_links_balance(
        (l, f) in scales(),
        pts in (point(1.0), point(1.0)),
        dirs in (direction(), direction()),
        w in (wrench(1.0, 1.0), wrench(1.0, 1.0)),
    ) {
        let s = |p: P| P::from(p.coords * l);
        let (a, q) = (s(pts.0), s(pts.1));
        let (w1, w2) = (scale(&w.0, l, f), scale(&w.1, l, f));
        match force::rpp::reactions(&a, &dirs.0, &dirs.1, &w1, &w2) {
            Err(e) => singular_ok(&e)?,
            Ok(r) => {
                check_prismatic(&r.slot, &dirs.0)?;
                check_prismatic(&r.guide, &dirs.1)?;
                check_balanced(&[
                    ("block", Body::default().wrench(&w1, a).force(r.a, a)
                        .prismatic(&r.slot, &dirs.0, a, -1.0)),
                    ("link 2", Body::default().wrench(&w2, a)
                        .prismatic(&r.slot, &dirs.0, a, 1.0)
                        .prismatic(&r.guide, &dirs.1, a, 1.0)),
                ], &q)?;
            }
        }
    }

    #[test]
    fn crank_balances((l, f) in scales(), pts in (point(1.0), point(1.0)), w in wrench(1.0, 1.0)) {
        let (o, q) = (P::from(pts.0.coords * l), P::from(pts.1.coords * l));
        let w = scale(&w, l, f);
        let r = force::crank::reactions(&w).unwrap();
        prop_assert_eq!(r.min_pivot_ratio, 1.0);
        check_balanced(&[("crank", Body::default().wrench(&w, o).force(r.pivot, o).couple(r.torque))], &q)?;
    }

    #[test]
    fn slider_balances(
        (l, f) in scales(),
        pts in (point(1.0), point(1.0)),
        dir in direction(),
        w in wrench(1.0, 1.0),
    ) {
        let (p, q) = (P::from(pts.0.coords * l), P::from(pts.1.coords * l));
        let w = scale(&w, l, f);
        let r = force::slider::reactions(&dir, &w).unwrap();
        check_prismatic(&r.guide, &dir)?;
        check_balanced(&[("block", Body::default().wrench(&w, p)
            .prismatic(&r.guide, &dir, p, 1.0)
            .force(dir.normalize() * r.drive, p))], &q)?;
    }

    #[test]
    fn actuator_balances(
        (l, f) in scales(),
        pts in (point(1.0), point(1.0), point(1.0), point(1.0)),
        w in wrench(1.0, 1.0),
    ) {
        let s = |p: P| P::from(p.coords * l);
        let (a, b, c, q) = (s(pts.0), s(pts.1), s(pts.2), s(pts.3));
        let w = scale(&w, l, f);
        match force::actuator::reactions(&a, &b, &c, &w) {
            Err(e) => singular_ok(&e)?,
            Ok(r) => {
                let u = (c - b).normalize();
                check_balanced(&[("link", Body::default().wrench(&w, a).force(r.a, a)
                    .force(u * r.axial, c))], &q)?;
            }
        }
    }
}

fn scale(w: &Wrench<f64>, length: f64, force: f64) -> Wrench<f64> {
    Wrench::new(w.force * force, w.moment * force * length)
}

#[test]
fn singular_poses_are_typed_errors() {
    let o = P::origin();
    let w = Wrench::new(V::new(1.0, 2.0), 3.0);
    // RRR at toggle: C on the line AB.
    let e = force::rrr::reactions(&P::new(-1.0, 0.0), &P::new(2.0, 0.0), &o, &w, &w).unwrap_err();
    assert_eq!(e.primitive, Primitive::Rrr);
    assert!(matches!(e.fault, Fault::Singular { .. }), "{e}");
    // RRP with link 1 perpendicular to the guide.
    let e = force::rrp::reactions(&P::new(0.0, 1.0), &o, &V::x(), &w, &w).unwrap_err();
    assert!(matches!(e.fault, Fault::Singular { .. }) && e.primitive == Primitive::Rrp);
    // PRP with parallel guides.
    let e = force::prp::reactions(&o, &V::x(), &(-V::x() * 2.0), &w, &w).unwrap_err();
    assert!(matches!(e.fault, Fault::Singular { .. }) && e.primitive == Primitive::Prp);
    // RPP with the slot along the guide.
    let e = force::rpp::reactions(&o, &V::y(), &V::y(), &w, &w).unwrap_err();
    assert!(matches!(e.fault, Fault::Singular { .. }) && e.primitive == Primitive::Rpp);
    // Actuator through the pivot (dead centre).
    let e = force::actuator::reactions(&o, &P::new(2.0, 0.0), &P::new(1.0, 0.0), &w).unwrap_err();
    assert!(matches!(e.fault, Fault::Singular { .. }) && e.primitive == Primitive::Actuator);
    // Zero guide direction; NaN load.
    let e = force::slider::reactions(&V::zeros(), &w).unwrap_err();
    assert!(matches!(e.fault, Fault::NonPositive { .. }), "{e}");
    let nan = Wrench::new(V::new(f64::NAN, 0.0), 0.0);
    let e = force::rrr::reactions(
        &P::new(-1.0, 0.0),
        &P::new(2.0, 0.0),
        &P::new(0.0, 1.0),
        &nan,
        &w,
    )
    .unwrap_err();
    assert!(matches!(e.fault, Fault::NonFinite { .. }) && e.primitive == Primitive::Rrr);
    // Near toggle the indicator shrinks with the angle between the links.
    let near = force::rrr::reactions(
        &P::new(-1.0, 0.0),
        &P::new(2.0, 0.0),
        &P::new(0.0, 1e-6),
        &w,
        &w,
    )
    .unwrap();
    assert!(near.min_pivot_ratio < 1e-5, "{}", near.min_pivot_ratio);
}

// ---------------------------------------------------------------------------
// Stiff case
// ---------------------------------------------------------------------------

/// Units: mm, tonnes, s, so forces in N and moments in N mm. Link 1 (A-C,
/// 500 mm) weighs 1e3 t = 1e6 kg; link 2 (C-B) 1e-9 t = 1e-6 kg and carries a
/// (1, -2) N force at D = (800, 0) mm. Gravity 9810 mm/s^2 down.
fn stiff_group(b: P) -> (P, P, P, Wrench<f64>, Wrench<f64>) {
    let a = P::new(0.0, 0.0);
    let c = P::new(300.0, 400.0);
    let g = V::new(0.0, -9810.0);
    let load1 = inertia_and_gravity(
        1e3,
        2.1e7,
        &P::new(150.0, 200.0),
        &V::new(-2500.0, 1200.0),
        3.0,
        Some(&g),
        &c,
    );
    let load2 = inertia_and_gravity(
        1e-9,
        5e-5,
        &P::new(600.0, 150.0),
        &V::new(4000.0, -700.0),
        -2.0,
        Some(&g),
        &c,
    ) + Wrench::force_at(&V::new(1.0, -2.0), &P::new(800.0, 0.0), &c);
    (a, b, c, load1, load2)
}

fn rel_err(x: &[f64; 6], exact: &[f64; 6]) -> f64 {
    let scale = exact.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    x.iter()
        .zip(exact)
        .map(|(x, e)| (x - e).abs())
        .fold(0.0, f64::max)
        / scale
}

#[test]
fn stiff_case_solved_where_naive_elimination_fails() {
    // Exact solution of the physical problem (rational arithmetic on the
    // decimal inputs), unknowns (F_A, F_B, F_C):
    let exact = [
        906923.1538491023,
        8170897.53846547,
        -3406924.1538451025,
        2839104.46154364,
        3406923.153849102,
        -2839102.4615345304,
    ];
    let (a, b, c, load1, load2) = stiff_group(P::new(900.0, -100.0));
    let r = force::rrr::reactions(&a, &b, &c, &load1, &load2).unwrap();
    let x = [r.a.x, r.a.y, r.b.x, r.b.y, r.c.x, r.c.y];
    // Measured: 5.7e-17 relative (the loads' own rounding in f64).
    let err = rel_err(&x, &exact);
    println!("stiff general pose: solve error {err:e}");
    assert!(err <= 8.0 * EPS, "error {err:e}");
    // Link 2 is light but is a two-force member for the heavy loads: F_B + F_C
    // equals minus its own 1e-5-scale load to rounding of the 3.4e6 N forces.
    let link2 = Body::default()
        .wrench(&load2, c)
        .force(r.b, b)
        .force(r.c, c);
    assert!(link2.residual(&a) <= 8.0 * EPS);

    // The same system through the naive solver. In the natural layout (rows:
    // link 1 Fx, Fy, M, link 2 Fx, Fy, M; columns F_A, F_B, F_C) its third
    // pivot is structurally zero for every pose: after the two force rows of
    // link 1, link 1's moment row has nothing in F_B's columns.
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
    assert!(matches!(
        solve_unpivoted_unscaled(sys.matrix, sys.rhs),
        Err(NaiveError::ZeroPivot { .. })
    ));
    let pivoted = solve(sys.matrix, sys.rhs).unwrap();
    assert!(rel_err(&pivoted.x, &exact) <= 8.0 * EPS);
}

/// Rows reordered so that naive elimination meets no structural zero
/// ("forces first": link 1 Fx, Fy, link 2 Fx, Fy, M, link 1 M): its fifth
/// pivot is then `(B - C).y`, which vanishes whenever link 2 is horizontal, a
/// regular pose that a four-bar passes every turn.
fn naive_in_force_first_order(sys: &group::GroupSystem<f64>) -> Result<[f64; 6], NaiveError> {
    let order = [0, 1, 3, 4, 5, 2];
    let m = order.map(|i| sys.matrix[i]);
    let r = order.map(|i| sys.rhs[i]);
    solve_unpivoted_unscaled(m, r)
}

#[test]
fn stiff_case_link_horizontal() {
    let joints_for = |a: P, b: P, c: P| {
        [
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
        ]
    };
    // Link 2 exactly horizontal (B = (900, 400)). Exact solution:
    let exact = [
        3036250.750002291,
        11010001.000003055,
        -5536251.749998291,
        1.000006055,
        5536250.750002291,
        1.000003055,
    ];
    let (a, b, c, load1, load2) = stiff_group(P::new(900.0, 400.0));
    let sys = group::assemble(&joints_for(a, b, c), &c, &load1, &load2);
    // Naive: division by the zero pivot.
    assert!(naive_in_force_first_order(&sys).is_err());
    // solve: measured error 0 (every component correctly rounded), including
    // the 1 N components F_B.y, F_C.y set by the 1e-6 kg link's own loads,
    // 1e-7 of the largest reaction.
    let r = force::rrr::reactions(&a, &b, &c, &load1, &load2).unwrap();
    let x = [r.a.x, r.a.y, r.b.x, r.b.y, r.c.x, r.c.y];
    assert!(
        rel_err(&x, &exact) <= 8.0 * EPS,
        "{:e}",
        rel_err(&x, &exact)
    );
    assert!(
        (r.b.y - exact[3]).abs() <= 4.0 * EPS * exact[3],
        "{}",
        r.b.y
    );

    // 1e-11 rad off horizontal (B.y = 400 + 6e-9 mm) naive elimination runs,
    // but loses digits in proportion to 1 / angle: its multiplier is
    // (A - C).y / (B - C).y = 7e10. Measured against the exact solution
    // (rational arithmetic on the same f64 inputs): naive 5.4e-13 relative
    // (about 6e-6 N on the 1.1e7 N reactions), solve 1.0e-23 (correctly
    // rounded). Mild at this angle, unbounded as the angle -> 0, and a division
    // by zero at it.
    let (a, b, c, load1, load2) = stiff_group(P::new(900.0, 400.0 + 6e-9));
    let exact = [
        3036250.750043813,
        11010001.000058418,
        -5536251.750039813,
        0.9999506925434812,
        5536250.750043813,
        1.0000584174565188,
    ];
    let sys = group::assemble(&joints_for(a, b, c), &c, &load1, &load2);
    let naive = naive_in_force_first_order(&sys).unwrap();
    let ours = solve(sys.matrix, sys.rhs).unwrap().x;
    let (e_naive, e_ours) = (rel_err(&naive, &exact), rel_err(&ours, &exact));
    println!("1e-11 rad off horizontal: naive {e_naive:e}, solve {e_ours:e}");
    assert!(e_ours <= 1e-15, "{e_ours:e}");
    assert!(
        e_naive > 10.0 * e_ours,
        "naive {e_naive:e} solve {e_ours:e}"
    );
}

// ---------------------------------------------------------------------------
// Power balance (virtual work) on whole mechanisms
// ---------------------------------------------------------------------------

const GRAVITY: V = V::new(0.0, -9.81);

/// The motion of a link: a reference point `p` with its velocity and
/// acceleration, and the link's angular velocity and acceleration.
#[derive(Clone, Copy)]
struct Motion {
    p: P,
    v: V,
    a: V,
    omega: f64,
    alpha: f64,
}

impl Motion {
    fn fixed_pivot(p: P, omega: f64, alpha: f64) -> Self {
        Motion {
            p,
            v: V::zeros(),
            a: V::zeros(),
            omega,
            alpha,
        }
    }
    fn translating(p: P, v: V, a: V) -> Self {
        Motion {
            p,
            v,
            a,
            omega: 0.0,
            alpha: 0.0,
        }
    }
    /// Velocity and acceleration of the link's material point at `q`.
    fn at(&self, q: &P) -> (V, V) {
        let r = q - self.p;
        (
            self.v + perp(&r) * self.omega,
            self.a + perp(&r) * self.alpha - r * (self.omega * self.omega),
        )
    }
    /// Power of a wrench stated about `about`, acting on this link.
    fn power(&self, w: &Wrench<f64>, about: &P) -> f64 {
        w.power(&self.at(about).0, self.omega)
    }
    /// The sum of the absolute values of the products in [`Motion::power`].
    fn gross(&self, w: &Wrench<f64>, about: &P) -> f64 {
        let v = self.at(about).0;
        (w.force.x * v.x).abs() + (w.force.y * v.y).abs() + (w.moment * self.omega).abs()
    }
}

/// Inertia and weight of a link of mass `m`, moment of inertia `j` about its
/// centre of mass `g`, reduced to `about`.
fn inertia(m: f64, j: f64, g: &P, link: &Motion, about: &P) -> Wrench<f64> {
    inertia_and_gravity(m, j, g, &link.at(g).1, link.alpha, Some(&GRAVITY), about)
}

/// `sum(terms) = 0` to `1e-10` of the gross power: the sum of the terms'
/// absolute values and of the absolute values of the products inside each
/// link's power (`gross`, from [`Motion::gross`]). A link's power can be a
/// small difference of large products, and the reactions' rounding follows
/// the products (see the module documentation for the bound).
fn check_power(terms: &[f64], gross: &[f64]) -> Result<(), TestCaseError> {
    let sum: f64 = terms.iter().sum();
    let scale: f64 = terms.iter().chain(gross).map(|t| t.abs()).sum();
    prop_assert!(
        sum.abs() <= 1e-10 * scale,
        "power residual {:e} of {scale:e}: {terms:?}",
        sum.abs()
    );
    Ok(())
}

fn mode(plus: bool) -> Mode {
    if plus {
        Mode::Plus
    } else {
        Mode::Minus
    }
}

fn unit(t: f64) -> V {
    V::new(t.cos(), t.sin())
}

/// A crank of length `r` about the origin: its motion and the motion of its tip.
struct CrankState {
    o: P,
    tip: P,
    crank: Motion,
    tip_v: V,
    tip_a: V,
    g: P,
}

fn crank_state(r: f64, theta: f64, omega: f64, alpha: f64) -> Result<CrankState, Error> {
    let o = P::origin();
    let pos = crank::position(&o, r, theta)?;
    let tip_v = crank::velocity(&pos, None, omega)?;
    let tip_a = crank::acceleration(&pos, None, omega, alpha)?;
    Ok(CrankState {
        o,
        tip: pos.tip,
        crank: Motion::fixed_pivot(o, omega, alpha),
        tip_v,
        tip_a,
        g: o + pos.r * 0.4 + perp(&pos.r) * 0.1,
    })
}

/// Masses (kg), inertias (kg m^2), external loads (N, N m): random but of
/// realistic size for a 0.1 - 0.4 m mechanism.
fn masses() -> impl Strategy<Value = [(f64, f64); 3]> {
    prop::array::uniform3((0.1f64..10.0, 1e-4f64..0.1))
}

fn crank_input() -> impl Strategy<Value = (f64, f64, f64)> {
    (
        0.0f64..std::f64::consts::TAU,
        -30.0f64..30.0,
        -300.0f64..300.0,
    )
}

fn ext() -> impl Strategy<Value = (V, f64)> {
    (-100.0f64..100.0, -100.0f64..100.0, -10.0f64..10.0).prop_map(|(x, y, m)| (V::new(x, y), m))
}

macro_rules! ok_or_reject {
    ($e:expr) => {
        match $e {
            Ok(v) => v,
            Err(_) => return Err(TestCaseError::reject("does not assemble or singular")),
        }
    };
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(512))]

    /// Four-bar: crank + RRR (coupler loaded by a force, rocker by a couple).
    #[test]
    fn power_balance_crank_rrr(
        (theta, omega, alpha) in crank_input(),
        ms in masses(),
        plus in any::<bool>(),
        (fe, te) in ext(),
    ) {
        let k = ok_or_reject!(crank_state(0.1, theta, omega, alpha));
        let (a, b) = (k.tip, P::new(0.35, 0.05));
        let pos = ok_or_reject!(rrr::position(&a, 0.3, &b, 0.25, mode(plus)));
        prop_assume!(cross(&pos.r1, &pos.r2).abs() > 0.05 * 0.3 * 0.25);
        let vel = ok_or_reject!(rrr::velocity(&pos, Some(&k.tip_v), None));
        let acc = ok_or_reject!(rrr::acceleration(&pos, &vel, Some(&k.tip_a), None));
        let c = pos.c;
        let coupler = Motion { p: a, v: k.tip_v, a: k.tip_a, omega: vel.omega1, alpha: acc.alpha1 };
        let rocker = Motion::fixed_pivot(b, vel.omega2, acc.alpha2);
        let g1 = a + pos.r1 * 0.3 + perp(&pos.r1) * 0.2;
        let g2 = b + pos.r2 * 0.6 - perp(&pos.r2) * 0.1;
        let e = a + pos.r1 * 0.7 + perp(&pos.r1) * 0.3;
        let load1 = inertia(ms[1].0, ms[1].1, &g1, &coupler, &c) + Wrench::force_at(&fe, &e, &c);
        let load2 = inertia(ms[2].0, ms[2].1, &g2, &rocker, &c).with_couple(te);
        let r = force::rrr::reactions(&a, &b, &c, &load1, &load2).unwrap();
        prop_assume!(r.min_pivot_ratio > 0.01);
        let own = inertia(ms[0].0, ms[0].1, &k.g, &k.crank, &k.o);
        let d = force::crank::reactions(&own.with_force_at(&-r.a, &a, &k.o)).unwrap();
        check_power(&[
            d.torque * omega,
            k.crank.power(&own, &k.o),
            coupler.power(&load1, &c),
            rocker.power(&load2, &c),
        ], &[k.crank.gross(&own, &k.o), coupler.gross(&load1, &c), rocker.gross(&load2, &c)])?;
    }

    /// Slider-crank: crank + RRP on a fixed guide (the piston loaded by a gas
    /// force along the guide, the rod by a couple).
    #[test]
    fn power_balance_crank_rrp(
        (theta, omega, alpha) in crank_input(),
        ms in masses(),
        plus in any::<bool>(),
        (phi, offset) in (-0.5f64..0.5, -0.05f64..0.05),
        (fe, te) in ext(),
    ) {
        let k = ok_or_reject!(crank_state(0.1, theta, omega, alpha));
        let a = k.tip;
        let g = Line { origin: P::new(0.0, -0.02), dir: unit(phi) };
        let pos = ok_or_reject!(rrp::position(&a, 0.3, &g, offset, mode(plus)));
        prop_assume!(pos.r1.dot(&g.dir).abs() > 0.05 * 0.3);
        let vel = ok_or_reject!(rrp::velocity(&pos, &g, Some(&k.tip_v), None));
        let acc = ok_or_reject!(rrp::acceleration(&pos, &g, &vel, Some(&k.tip_a), None, None));
        let c = pos.c;
        let rod = Motion { p: a, v: k.tip_v, a: k.tip_a, omega: vel.omega1, alpha: acc.alpha1 };
        let piston = Motion::translating(c, vel.vc, acc.ac);
        let g1 = a + pos.r1 * 0.35 + perp(&pos.r1) * 0.05;
        let g2 = c + g.dir * 0.02 + perp(&g.dir) * 0.01;
        let load1 = inertia(ms[1].0, ms[1].1, &g1, &rod, &c).with_couple(te);
        let load2 = inertia(ms[2].0, ms[2].1, &g2, &piston, &c)
            .with_force_at(&(g.dir * fe.x + perp(&g.dir) * fe.y), &(c + g.dir * 0.03), &c);
        let r = force::rrp::reactions(&a, &c, &g.dir, &load1, &load2).unwrap();
        prop_assume!(r.min_pivot_ratio > 0.01);
        let own = inertia(ms[0].0, ms[0].1, &k.g, &k.crank, &k.o);
        let d = force::crank::reactions(&own.with_force_at(&-r.a, &a, &k.o)).unwrap();
        check_power(&[
            d.torque * omega,
            k.crank.power(&own, &k.o),
            rod.power(&load1, &c),
            piston.power(&load2, &c),
        ], &[k.crank.gross(&own, &k.o), rod.gross(&load1, &c), piston.gross(&load2, &c)])?;
    }

    /// Crank and slotted lever: crank + RPR (block on the crank pin slides
    /// along a rocker pivoted at B).
    #[test]
    fn power_balance_crank_rpr(
        (theta, omega, alpha) in crank_input(),
        ms in masses(),
        plus in any::<bool>(),
        offset in -0.03f64..0.03,
        (fe, te) in ext(),
    ) {
        let k = ok_or_reject!(crank_state(0.1, theta, omega, alpha));
        let (a, b) = (k.tip, P::new(0.0, -0.25));
        let pos = ok_or_reject!(rpr::position(&a, &b, offset, mode(plus)));
        prop_assume!(pos.s.abs() > 0.05 * (a - b).norm());
        let vel = ok_or_reject!(rpr::velocity(&pos, &a, &b, Some(&k.tip_v), None));
        let acc = ok_or_reject!(rpr::acceleration(&pos, &a, &b, &vel, Some(&k.tip_a), None));
        let u = pos.axis;
        let block = Motion { p: a, v: k.tip_v, a: k.tip_a, omega: vel.omega, alpha: acc.alpha };
        let rocker = Motion::fixed_pivot(b, vel.omega, acc.alpha);
        let g1 = a + u * 0.01;
        let g2 = b + u * 0.2 + perp(&u) * 0.01;
        let load1 = inertia(ms[1].0, ms[1].1, &g1, &block, &a);
        let load2 = inertia(ms[2].0, ms[2].1, &g2, &rocker, &a)
            .with_force_at(&fe, &(b + u * 0.4), &a)
            .with_couple(te);
        let r = force::rpr::reactions(&a, &b, &u, &load1, &load2).unwrap();
        prop_assume!(r.min_pivot_ratio > 0.01);
        let own = inertia(ms[0].0, ms[0].1, &k.g, &k.crank, &k.o);
        let d = force::crank::reactions(&own.with_force_at(&-r.a, &a, &k.o)).unwrap();
        check_power(&[
            d.torque * omega,
            k.crank.power(&own, &k.o),
            block.power(&load1, &a),
            rocker.power(&load2, &a),
        ], &[k.crank.gross(&own, &k.o), block.gross(&load1, &a), rocker.gross(&load2, &a)])?;
    }

    /// Scotch yoke: crank + RPP (block on the crank pin slides in the slot of
    /// a yoke that translates on a fixed guide).
    #[test]
    fn power_balance_crank_rpp(
        (theta, omega, alpha) in crank_input(),
        ms in masses(),
        (phi, beta, offset) in (-0.5f64..0.5, 0.3f64..2.8, -0.05f64..0.05),
        (fe, _te) in ext(),
    ) {
        let k = ok_or_reject!(crank_state(0.1, theta, omega, alpha));
        let a = k.tip;
        let g = Line { origin: P::new(0.02, -0.01), dir: unit(phi) };
        let pos = ok_or_reject!(rpp::position(&a, &g, offset, &unit(beta)));
        let vel = ok_or_reject!(rpp::velocity(&pos, &a, &g, Some(&k.tip_v), None));
        let acc = ok_or_reject!(rpp::acceleration(&pos, &a, &g, &vel, Some(&k.tip_a), None, None));
        let block = Motion::translating(a, k.tip_v, k.tip_a);
        let yoke = Motion::translating(pos.q, vel.vq, acc.aq);
        let g1 = a + pos.slot * 0.01;
        let g2 = pos.q + g.dir * 0.05 + pos.slot * 0.02;
        let load1 = inertia(ms[1].0, ms[1].1, &g1, &block, &a);
        let load2 = inertia(ms[2].0, ms[2].1, &g2, &yoke, &a)
            .with_force_at(&fe, &(pos.q + g.dir * 0.1), &a);
        let r = force::rpp::reactions(&a, &pos.slot, &g.dir, &load1, &load2).unwrap();
        prop_assume!(r.min_pivot_ratio > 0.01);
        let own = inertia(ms[0].0, ms[0].1, &k.g, &k.crank, &k.o);
        let d = force::crank::reactions(&own.with_force_at(&-r.a, &a, &k.o)).unwrap();
        check_power(&[
            d.torque * omega,
            k.crank.power(&own, &k.o),
            block.power(&load1, &a),
            yoke.power(&load2, &a),
        ], &[k.crank.gross(&own, &k.o), block.gross(&load1, &a), yoke.gross(&load2, &a)])?;
    }

    /// Slotted crank + PRP: block 1 slides in a slot along the crank (a guide
    /// carried by a rotating body), block 2 on a fixed guide, pinned at C.
    #[test]
    fn power_balance_crank_prp(
        (theta, omega, alpha) in crank_input(),
        ms in masses(),
        (phi, off1, off2) in (-0.5f64..0.5, -0.02f64..0.02, -0.02f64..0.02),
        (fe, te) in ext(),
    ) {
        let k = ok_or_reject!(crank_state(0.1, theta, omega, alpha));
        let g1 = Line { origin: k.o, dir: unit(theta) };
        let gv1 = LineVelocity { v_origin: V::zeros(), omega };
        let ga1 = LineAcceleration { a_origin: V::zeros(), alpha };
        let g2 = Line { origin: P::new(0.1, 0.15), dir: unit(phi) };
        prop_assume!(cross(&g1.dir, &g2.dir).abs() > 0.05);
        let pos = ok_or_reject!(prp::position(&g1, off1, &g2, off2));
        prop_assume!((pos.c - k.o).norm() < 2.0);
        let vel = ok_or_reject!(prp::velocity(&pos, &g1, &g2, Some(&gv1), None));
        let acc = ok_or_reject!(prp::acceleration(
            &pos, &g1, &g2, &vel, Some(&gv1), Some(&ga1), None, None
        ));
        let c = pos.c;
        let block1 = Motion { p: c, v: vel.vc, a: acc.ac, omega, alpha };
        let block2 = Motion::translating(c, vel.vc, acc.ac);
        let gp1 = c + g1.dir * 0.01;
        let gp2 = c + g2.dir * 0.01 + perp(&g2.dir) * 0.005;
        let load1 = inertia(ms[1].0, ms[1].1, &gp1, &block1, &c).with_couple(te);
        let load2 = inertia(ms[2].0, ms[2].1, &gp2, &block2, &c)
            .with_force_at(&fe, &(c + g2.dir * 0.02), &c);
        let r = force::prp::reactions(&c, &g1.dir, &g2.dir, &load1, &load2).unwrap();
        prop_assume!(r.min_pivot_ratio > 0.01);
        let own = inertia(ms[0].0, ms[0].1, &k.g, &k.crank, &k.o);
        // Block 1 acts on the crank's slot with the opposite of guide 1's
        // reaction (stated about C).
        let on_crank = own + (-r.guide1.wrench()).moved(&c, &k.o);
        let d = force::crank::reactions(&on_crank).unwrap();
        check_power(&[
            d.torque * omega,
            k.crank.power(&own, &k.o),
            block1.power(&load1, &c),
            block2.power(&load2, &c),
        ], &[k.crank.gross(&own, &k.o), block1.gross(&load1, &c), block2.gross(&load2, &c)])?;
    }

    /// Slider driver + RRR: the block's pin is the RRR's joint A.
    #[test]
    fn power_balance_slider_rrr(
        (s, s_dot, s_ddot) in (-0.1f64..0.1, -2.0f64..2.0, -50.0f64..50.0),
        (phi, offset) in (-0.5f64..0.5, -0.03f64..0.03),
        ms in masses(),
        plus in any::<bool>(),
        (fe, te) in ext(),
    ) {
        let g = Line { origin: P::new(0.0, 0.0), dir: unit(phi) };
        let sp = slider::position(&g, offset, s).unwrap();
        let vp = slider::velocity(&sp, &g, s, s_dot, None).unwrap();
        let ap = slider::acceleration(&sp, &g, s, s_dot, s_ddot, None, None).unwrap();
        let (a, b) = (sp.p, P::new(0.3, 0.15));
        let pos = ok_or_reject!(rrr::position(&a, 0.25, &b, 0.2, mode(plus)));
        prop_assume!(cross(&pos.r1, &pos.r2).abs() > 0.05 * 0.25 * 0.2);
        let vel = ok_or_reject!(rrr::velocity(&pos, Some(&vp), None));
        let acc = ok_or_reject!(rrr::acceleration(&pos, &vel, Some(&ap), None));
        let c = pos.c;
        let block = Motion::translating(a, vp, ap);
        let link1 = Motion { p: a, v: vp, a: ap, omega: vel.omega1, alpha: acc.alpha1 };
        let link2 = Motion::fixed_pivot(b, vel.omega2, acc.alpha2);
        let load1 = inertia(ms[1].0, ms[1].1, &(a + pos.r1 * 0.5), &link1, &c)
            .with_force_at(&fe, &(a + pos.r1 * 0.8), &c);
        let load2 = inertia(ms[2].0, ms[2].1, &(b + pos.r2 * 0.5), &link2, &c).with_couple(te);
        let r = force::rrr::reactions(&a, &b, &c, &load1, &load2).unwrap();
        prop_assume!(r.min_pivot_ratio > 0.01);
        let own = inertia(ms[0].0, ms[0].1, &(a + g.dir * 0.01), &block, &a);
        let d = force::slider::reactions(&g.dir, &(own + Wrench::new(-r.a, 0.0))).unwrap();
        check_power(&[
            d.drive * s_dot,
            block.power(&own, &a),
            link1.power(&load1, &c),
            link2.power(&load2, &c),
        ], &[block.gross(&own, &a), link1.gross(&load1, &c), link2.gross(&load2, &c)])?;
    }

    /// Linear actuator turning a loaded arm (the cylinder massless).
    #[test]
    fn power_balance_actuator(
        (len, len_dot, len_ddot) in (0.3f64..0.5, -0.5f64..0.5, -5.0f64..5.0),
        m in (0.1f64..50.0, 1e-3f64..1.0),
        plus in any::<bool>(),
        (fe, te) in ext(),
    ) {
        let (a, b) = (P::origin(), P::new(0.4, -0.1));
        let pos = ok_or_reject!(actuator::position(&a, 0.2, &b, len, mode(plus)));
        prop_assume!(cross(&pos.r1, &pos.r2).abs() > 0.05 * 0.2 * len);
        let vel = ok_or_reject!(actuator::velocity(&pos, None, None, len_dot));
        let acc = ok_or_reject!(actuator::acceleration(&pos, &vel, None, None, len_dot, len_ddot));
        let arm = Motion::fixed_pivot(a, vel.omega1, acc.alpha1);
        let load = inertia(m.0, m.1, &(a + pos.r1 * 0.6 + perp(&pos.r1) * 0.1), &arm, &a)
            .with_force_at(&fe, &(a + pos.r1 * 1.5), &a)
            .with_couple(te);
        let r = force::actuator::reactions(&a, &b, &pos.c, &load).unwrap();
        prop_assume!(r.min_pivot_ratio > 0.01);
        check_power(&[r.axial * len_dot, arm.power(&load, &a)], &[arm.gross(&load, &a)])?;
    }
}
