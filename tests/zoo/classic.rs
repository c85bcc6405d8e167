//! Classic linkages, each checked against facts of its own geometry that the
//! generated code does not use:
//!
//! - `Peaucellier`: the Peaucellier-Lipkin inversor. Its point P is the
//!   inverse of A in the circle of radius `sqrt(l^2 - s^2)` about O, so it
//!   runs on a straight line: closed forms for its position, velocity and
//!   acceleration, in f64 and f32, and the double-double reference.
//! - `Hoeken`: Hoeken's straight-line four-bar, against an independent
//!   closed-form circle intersection and three exact points of its line.
//! - `JansenLeg`: Theo Jansen's leg with the "holy numbers": every link
//!   length at every pose, the double-double reference, Richardson-
//!   extrapolated central differences, the flat part of the foot's path, and
//!   a force analysis checked by Newton-Euler per body and by the power
//!   balance, each check shown to fail on a deliberate mistake.

use crate::equilibrium::*;
use mechanism::{mechanism, Point2, Real, Vector2};
use mechanism_reference::constraint::{Constraint, Linkage, Point, Side, V2};
use mechanism_reference::{loop_closure, Dd};

// ---------------------------------------------------------------------------
// Shared helpers of this file.

/// The double-double reference's positions, velocities and accelerations of
/// every point of `l` for one crank input `q` (rad), rate `w` (rad/s) and
/// acceleration `al` (rad/s^2); `start` (the code under test's answer) only
/// picks the branch, the `sides` of `l` check it.
fn reference(
    l: &Linkage,
    q: f64,
    w: f64,
    al: f64,
    start: &[(f64, f64)],
) -> (Vec<V2>, Vec<V2>, Vec<V2>) {
    let (q, w, al) = ([Dd::from_f64(q)], [Dd::from_f64(w)], [Dd::from_f64(al)]);
    let pose = loop_closure::position(l, &q, start).expect("reference position");
    let v = loop_closure::velocity(l, &pose, &q, &w).expect("reference velocity");
    let a = loop_closure::acceleration(l, &pose, &v, &q, &w, &al).expect("reference acceleration");
    (pose.points, v, a)
}

/// `|got - r|` for a generated vector against a double-double one.
fn dist(got: (f64, f64), r: V2) -> f64 {
    let d = V2::new(got.0, got.1).minus(r);
    d.dot(d).sqrt().to_f64()
}

/// `|r|` of a double-double vector.
fn len(r: V2) -> f64 {
    r.dot(r).sqrt().to_f64()
}

/// A fixed reference point.
fn fixed(x: f64, y: f64) -> Point {
    Point::Fixed(V2::new(x, y))
}

/// Each stage's worst point error against the reference, in eps of the
/// stage's largest reference vector, times `kappa^k` (k = 1, 2, 3 for
/// positions, velocities, accelerations: the bounds of `docs/stability.md`).
fn scaled_errors(
    pts: &[(f64, f64)],
    (vels, accs): (&[Vector2<f64>], &[Vector2<f64>]),
    (rp, rv, ra): (&[V2], &[V2], &[V2]),
    kappa: f64,
) -> [f64; 3] {
    let stage = |got: &[(f64, f64)], r: &[V2]| {
        let e = got
            .iter()
            .zip(r)
            .map(|(g, r)| dist(*g, *r))
            .fold(0.0, f64::max);
        let sc = r.iter().map(|r| len(*r)).fold(0.0, f64::max);
        e / (f64::EPSILON * sc)
    };
    let pairs = |vs: &[Vector2<f64>]| vs.iter().map(|v| (v.x, v.y)).collect::<Vec<_>>();
    [
        stage(pts, rp) * kappa,
        stage(&pairs(vels), rv) * kappa.powi(2),
        stage(&pairs(accs), ra) * kappa.powi(3),
    ]
}

/// The circle intersection `C` with `|C - a| = l1`, `|C - b| = l2`, on the
/// left of the directed line `a -> b` when `left` (the RRR group's
/// definition in docs/dsl.md), written here from the triangle (the foot of C
/// on `a -> b` at `(l1^2 - l2^2 + d^2) / (2 d)` from `a`, then the height).
fn circles(a: Point2<f64>, l1: f64, b: Point2<f64>, l2: f64, left: bool) -> Point2<f64> {
    let ab = b - a;
    let d = ab.norm();
    let u = ab / d;
    let along = (l1 * l1 - l2 * l2 + d * d) / (2.0 * d);
    let h = (l1 * l1 - along * along).sqrt();
    let n = Vector2::new(-u.y, u.x) * if left { h } else { -h };
    a + u * along + n
}

/// `|sin|` of the angle at `c` between `c -> a` and `c -> b`: the condition of
/// the RRR group that finds `c` from `a` and `b` (1 at right angles, 0 at
/// full extension or folding, where the position's error grows as `1 / sin`).
fn sin_at(c: Point2<f64>, a: Point2<f64>, b: Point2<f64>) -> f64 {
    let (u, v) = (a - c, b - c);
    cross(&u, &v).abs() / (u.norm() * v.norm())
}

// ---------------------------------------------------------------------------
// 1. Peaucellier-Lipkin inversor.

mechanism! {
    /// Peaucellier-Lipkin inversor (lengths in any unit): fixed pivots O and
    /// Q with `|OQ| = a`, the crank Q-A of length `a` (so A runs on a circle
    /// through O), the long arms O-B and O-C of length `l`, and the rhombus
    /// A-B-P-C of side `s` (B left of O -> A, C right of it, P the vertex
    /// opposite A). P is the inverse of A: `|OA| |OP| = l^2 - s^2`, on the
    /// line `x = (l^2 - s^2) / (2 a)`.
    ///
    /// Range: B and C exist while `l - s <= |OA| <= l + s`. With `|OA| =
    /// 2 a cos(theta / 2)` and `2 a < l + s` here, the bound is `cos(theta
    /// / 2) >= (l - s) / (2 a) = 1 / 2`: `|theta| <= 120 deg`, where B, C,
    /// A and O fall on one line (both RRR groups at full extension, B = C,
    /// and P's group folded): singular. The range stops at 115 deg, 5 deg
    /// short of it.
    ///
    /// Branch: A and P are the two vertices of the rhombus on the line of
    /// symmetry through O, at `|OA| |OP| = l^2 - s^2`, so the one nearer O
    /// is inside the circle of radius `sqrt(l^2 - s^2)` and the other
    /// outside. `2 a < sqrt(l^2 - s^2)` (2 < 2.236 here) keeps A always the
    /// inner one and P (left of B -> C, away from O) the outer one. With
    /// `|OA|` crossing `sqrt(l^2 - s^2)` the rhombus goes flat there (P =
    /// A, P's group at full extension) and a fixed mode then follows A
    /// instead of the inverse (see `peaucellier_check_finds_the_flat_rhombus`).
    pub Peaucellier {
        params { a = 1.0, l = 3.0, s = 2.0 }
        dof 1;
        range theta = (-115 deg, 115 deg);
        let O = ground(0.0, 0.0);
        let Q = ground(a, 0.0);
        let A = crank(Q, a, theta) as crank;
        let B = rrr(O, l, A, s, left) as (arm_b, side_b);
        let C = rrr(O, l, A, s, right) as (arm_c, side_c);
        let P = rrr(B, s, C, s, left) as (side_pb, side_pc);
    }
}

/// One Peaucellier pose's worst errors, each divided by `eps` times its
/// scale and the conditioning factor it is allowed (see the test).
#[derive(Default, Debug)]
struct PeaucellierWorst {
    position: f64,
    velocity: f64,
    acceleration: f64,
    inversion: f64,
    min_kappa: f64,
}

/// Sweeps the inversor in `T` over `theta` in [-115, 115] deg (0.5 deg
/// steps) with a crank rate and acceleration, and measures the generated
/// P against the exact straight-line motion. Exact values are evaluated in
/// f64 from the scene's own `T` values (the f32 input and lengths widened
/// exactly), so the only error measured is the generated code's.
fn peaucellier_sweep<T: Real>() -> PeaucellierWorst {
    let m = Peaucellier::<T>::default();
    let (a, l, s) = (m.a.as_f64(), m.l.as_f64(), m.s.as_f64());
    let (w, al) = (T::lit(1.3), T::lit(-0.7));
    let (wf, alf) = (w.as_f64(), al.as_f64());
    let eps = T::eps().as_f64();
    let k = l * l - s * s;
    let x_line = k / (2.0 * a);
    let mut worst = PeaucellierWorst {
        min_kappa: 1.0,
        ..Default::default()
    };
    for i in -230..=230 {
        let q = T::lit(f64::to_radians(0.5 * i as f64));
        let i = |x: T| PeaucellierInput { theta: x };
        let sol = m.solve(&i(q), &i(w), &i(al)).unwrap();
        let (p, v, acc) = (&sol.position, &sol.velocity, &sol.acceleration);
        let th = q.as_f64();

        // Exact motion: A = Q + a (cos, sin), |OA| = 2 a cos(theta / 2) = r,
        // P = k A / r^2, so P = (k / (2 a)) (1, tan(theta / 2)); its
        // velocity and acceleration are the derivatives of the second
        // coordinate (u = theta / 2):
        // y' = (K / 2) sec^2(u) w, y'' = (K / 2) sec^2(u) (al + tan(u) w^2).
        let u = 0.5 * th;
        let sec2 = 1.0 / (u.cos() * u.cos());
        let py = x_line * u.tan();
        let vy = 0.5 * x_line * sec2 * wf;
        let ay = 0.5 * x_line * sec2 * (alf + u.tan() * wf * wf);

        // Conditioning, from the exact geometry: with B's foot on O -> A at
        // `xb = (l^2 - s^2 + r^2) / (2 r)` and height `h = sqrt(l^2 - xb^2)`
        // (half of BC), B's group has `sin(OBA) = h r / (l s)` and P's
        // group `sin(BPC) = 2 h sqrt(s^2 - h^2) / s^2`.
        let r = 2.0 * a * u.cos();
        let xb = (k + r * r) / (2.0 * r);
        let h = (l * l - xb * xb).sqrt();
        let kb = h * r / (l * s);
        let kp = 2.0 * h * (s * s - h * h).sqrt() / (s * s);
        let kappa = kb * kp;

        // Scales: positions by the longest vector (|OP| grows as tan(u)),
        // velocities by w times it, accelerations by (w^2 + |al|) times it
        // plus P's own acceleration (which grows as sec^2(u) tan(u)).
        let pp = (p.P.x.as_f64(), p.P.y.as_f64());
        let lp = (x_line * x_line + py * py).sqrt().max(2.0 * a + l);
        let lv = wf.abs() * lp + vy.abs();
        let la = (wf * wf + alf.abs()) * lp + ay.abs();
        let ep = ((pp.0 - x_line).powi(2) + (pp.1 - py).powi(2)).sqrt();
        let ev = Vector2::new(v.P.x.as_f64(), v.P.y.as_f64() - vy).norm();
        let ea = Vector2::new(acc.P.x.as_f64(), acc.P.y.as_f64() - ay).norm();
        // Inversion: |OA| |OP| = k, relative to k.
        let oa = Vector2::new(p.A.x.as_f64(), p.A.y.as_f64()).norm();
        let op = Vector2::new(pp.0, pp.1).norm();
        let einv = (oa * op - k).abs() / k;

        worst.position = worst.position.max(ep / (eps * lp / kappa));
        worst.velocity = worst.velocity.max(ev / (eps * lv / (kappa * kappa)));
        worst.acceleration = worst.acceleration.max(ea / (eps * la / kappa.powi(3)));
        worst.inversion = worst.inversion.max(einv / (eps / kappa));
        worst.min_kappa = worst.min_kappa.min(kappa);
    }
    worst
}

/// P on the line `x = (l^2 - s^2) / (2 a)` with the exact `y`, `P.x' = 0`,
/// `P.x'' = 0`, `|OA| |OP| = l^2 - s^2`, in f64 and f32.
///
/// Tolerances. Each group's position is exact to a few eps of its lengths
/// divided by the sine of its angle (the condition of the circle
/// intersection); P's group takes B's and C's errors, amplified by its own
/// `1 / sin`: an error of `c eps L / (kb kp)`. A rate system has the same
/// matrix (one more `1 / kappa` for the error its position data carry
/// into it), the acceleration one more again: the bounds are `c eps L /
/// kappa^k` with `k` = 1, 2, 3 for position, velocity and acceleration and
/// `kappa = kb kp` from the exact geometry (0.25 at 0 deg, 0.128 at 115).
/// `c = 16` for every stage and both precisions: the worst measured (`cargo
/// test --test zoo classic -- --nocapture`) is printed: 0.66, 0.22, 0.19
/// and 1.31 (inversion) in f64, 0.66, 0.20, 0.14, 1.34 in f32.
/// A wrong term (a missing Coriolis term, a sign) shows at its own size, a
/// fraction of the scale, 1e12 (f64) or 1e4 (f32) times the bound.
#[test]
fn peaucellier_moves_on_its_straight_line() {
    for (name, w) in [
        ("f64", peaucellier_sweep::<f64>()),
        ("f32", peaucellier_sweep::<f32>()),
    ] {
        println!("Peaucellier {name}: worst / (eps L kappa^-k): {w:?}");
        for (what, x) in [
            ("position", w.position),
            ("velocity", w.velocity),
            ("acceleration", w.acceleration),
            ("inversion", w.inversion),
        ] {
            assert!(x <= 16.0, "{name} {what}: {x} eps L / kappa^k");
        }
    }
}

/// Beyond the assembly bound (120 deg, see the definition) the position is
/// a typed error naming B's group (the first to fail in the solve order),
/// just inside it a finite solution; in f64 and f32.
#[test]
fn peaucellier_stops_at_its_assembly_bound() {
    fn at<T: Real>(deg: f64) -> Result<f64, &'static str> {
        let m = Peaucellier::<T>::default();
        m.position(&PeaucellierInput {
            theta: T::lit(deg.to_radians()),
        })
        .map(|p| p.P.y.as_f64())
        .map_err(|e| e.group)
    }
    let bound = 120.0;
    for d in [bound - 0.5, -(bound - 0.5)] {
        assert!(at::<f64>(d).unwrap().is_finite());
        assert!(at::<f32>(d).unwrap().is_finite());
    }
    for d in [bound + 0.5, -(bound + 0.5), 180.0] {
        assert_eq!(at::<f64>(d), Err("B"), "{d} deg");
        assert_eq!(at::<f32>(d), Err("B"), "{d} deg");
    }
}

/// Run-time `check()` over the declared range: clean with the defaults; with
/// `l = 2`, `s = 1.4` (`sqrt(l^2 - s^2) = 1.428 < 2 a`) the rhombus goes flat
/// where `|OA| = 2 a cos(theta / 2) = sqrt(l^2 - s^2)`, `theta = +-2
/// acos(0.7141) = +-88.85 deg`: P's group (B and C at full extension `2 s`
/// apart) is singular there, twice, and nothing else is. The reported angle
/// is accurate to 1e-4 deg (docs/checks.md); 1e-3 deg here.
#[test]
fn peaucellier_check_finds_the_flat_rhombus() {
    let good = Peaucellier::<f64>::default().check();
    assert!(good.assembles() && good.is_clean(), "{good:?}");
    let flat = Peaucellier::<f64> {
        l: 2.0,
        s: 1.4,
        ..Default::default()
    }
    .check();
    assert!(flat.assembles(), "{flat:?}");
    let expect = 2.0 * f64::acos(f64::sqrt(4.0 - 1.96) / 2.0);
    for g in &flat.groups {
        if g.group == "P" {
            assert_eq!(g.singular, 2, "{flat:?}");
            let first = g.first_singular.unwrap()[0];
            assert!(
                (first + expect).abs() <= 1e-3f64.to_radians(),
                "{} deg vs {} deg",
                first.to_degrees(),
                -expect.to_degrees()
            );
        } else {
            assert_eq!(g.singular, 0, "{flat:?}");
        }
    }
}

/// The inversor's double-double reference: O, Q fixed; A on the crank;
/// the six lengths; B left of O -> A, C right, P left of B -> C.
fn peaucellier_linkage(a: f64, l: f64, s: f64) -> Linkage {
    // Points: 0 O, 1 Q, 2 A, 3 B, 4 C, 5 P.
    let d = |p, q, len| Constraint::Distance { p, q, len };
    Linkage {
        points: vec![
            fixed(0.0, 0.0),
            fixed(a, 0.0),
            Point::Unknown,
            Point::Unknown,
            Point::Unknown,
            Point::Unknown,
        ],
        constraints: vec![
            Constraint::Crank {
                p: 2,
                o: 1,
                r: a,
                input: 0,
            },
            d(3, 0, l),
            d(3, 2, s),
            d(4, 0, l),
            d(4, 2, s),
            d(5, 3, s),
            d(5, 4, s),
        ],
        sides: vec![
            Side::Left {
                p: 3,
                a: 0,
                b: 2,
                sign: 1.0,
            },
            Side::Left {
                p: 4,
                a: 0,
                b: 2,
                sign: -1.0,
            },
            Side::Left {
                p: 5,
                a: 3,
                b: 4,
                sign: 1.0,
            },
        ],
        scale: l,
    }
}

/// Every point of the inversor against the double-double reference (f64),
/// normwise over the points per stage, with the same `c eps L / kappa^k`
/// form and reasoning as the closed-form test; here `L` is the largest
/// reference position (velocity, acceleration) of the pose.
#[test]
fn peaucellier_matches_the_double_double_reference() {
    let m = Peaucellier::<f64>::default();
    let lk = peaucellier_linkage(m.a, m.l, m.s);
    let (w, al) = (1.3, -0.7);
    let mut worst = [0.0f64; 3];
    for i in -23..=23 {
        let q = f64::to_radians(5.0 * i as f64);
        let i = |x| PeaucellierInput { theta: x };
        let s = m.solve(&i(q), &i(w), &i(al)).unwrap();
        let (p, v, a) = (&s.position, &s.velocity, &s.acceleration);
        let pts = [p.O, p.Q, p.A, p.B, p.C, p.P];
        let start: Vec<(f64, f64)> = pts.iter().map(|p| (p.x, p.y)).collect();
        let (rp, rv, ra) = reference(&lk, q, w, al, &start);
        let kappa = sin_at(p.B, p.O, p.A).min(sin_at(p.C, p.O, p.A)) * sin_at(p.P, p.B, p.C);
        let vs = [Vector2::zeros(), Vector2::zeros(), v.A, v.B, v.C, v.P];
        let accs = [Vector2::zeros(), Vector2::zeros(), a.A, a.B, a.C, a.P];
        let e = scaled_errors(&start, (&vs, &accs), (&rp, &rv, &ra), kappa);
        for (x, e) in worst.iter_mut().zip(e) {
            *x = x.max(e);
        }
    }
    println!("Peaucellier vs double-double: worst / (eps L kappa^-k) {worst:?}");
    for (what, x) in ["position", "velocity", "acceleration"].iter().zip(worst) {
        assert!(x <= 16.0, "{what}: {x}");
    }
}

// ---------------------------------------------------------------------------
// 2. Hoeken's straight-line linkage.

mechanism! {
    /// Hoeken's linkage in its classic proportions (crank 1, ground 2,
    /// rocker 2.5, coupler 2.5 between its pins, extended to P at 5 from
    /// the crank pin, the rocker pin its midpoint): while the crank turns
    /// from 90 to 270 deg, P runs nearly straight along `y = 4`.
    pub Hoeken {
        dof 1;
        let O2 = ground(0.0, 0.0);
        let O4 = ground(2.0, 0.0);
        let A = crank(O2, 1.0, theta) as crank;
        let B = rrr(A, 2.5, O4, 2.5, left) as (coupler, rocker);
        let P = point(coupler, from A, 5.0, 0 deg);
    }
}

/// Hoeken's P by the independent circle intersection (f64).
fn hoeken_p(theta: f64) -> Point2<f64> {
    let a = Point2::new(theta.cos(), theta.sin());
    let b = circles(a, 2.5, Point2::new(2.0, 0.0), 2.5, true);
    a + (b - a) * 2.0
}

/// Hoeken's linkage: loop closure at every 0.25 deg of the turn; P against
/// the independent closed form; P's exact points at 90, 180 and 270 deg
/// (worked out by hand: (4, 4), (2, 4), (0, 4), the rocker pin B at (2,
/// 2.5), (0.5, 2), (0, 1.5)); the straight part's deviation from `y = 4`
/// against the closed form's; the velocity against central differences.
///
/// Tolerances: lengths 1 to 5, coordinates below 5, the RRR group's sine
/// above 0.39 over the turn (checked; 0.392 at its lowest): each position
/// within a few roundings of 5 (eps 5 = 1.1e-15) amplified by at most 1 /
/// 0.39, twice over for P at twice the coupler's length: below 1e-14; the
/// closed form carries the same; 2e-14 between them (measured: printed).
/// Velocity: central difference with `h = 1e-5` (see `main.rs`), 1e-7.
#[test]
fn hoeken_runs_straight_and_matches_the_closed_form() {
    let m = Hoeken::<f64>::default();
    let mut dev = (0.0f64, 0.0f64);
    let mut min_sin = 1.0f64;
    let mut worst_cf = 0.0f64;
    for k in 0..1440 {
        let q = f64::to_radians(0.25 * k as f64);
        let w = 2.0;
        let at = |t: f64| HoekenInput { theta: q + w * t };
        let p = m.position(&at(0.0)).unwrap();
        let v = m.velocity(&p, &HoekenInput { theta: w }).unwrap();
        assert_len(p.A, p.O2, 1.0, "crank");
        assert_len(p.B, p.A, 2.5, "coupler");
        assert_len(p.B, p.O4, 2.5, "rocker");
        assert_len(p.P, p.A, 5.0, "A-P");
        assert!(
            (p.B - (p.A + (p.P - p.A) * 0.5)).norm() <= 1e-14,
            "B is not P's midpoint with A"
        );
        min_sin = min_sin.min(sin_at(p.B, p.A, p.O4));
        let cf = hoeken_p(q);
        assert!((p.P - cf).norm() <= 2e-14, "{k}: {:?} vs {cf:?}", p.P);
        worst_cf = worst_cf.max((p.P - cf).norm());
        let fd = (m.position(&at(H)).unwrap().P - m.position(&at(-H)).unwrap().P) / (2.0 * H);
        close_fd(v.P, fd, 10.0, "vP");
        if (360..=1080).contains(&k) {
            dev.0 = dev.0.max((p.P.y - 4.0).abs());
            dev.1 = dev.1.max((cf.y - 4.0).abs());
        }
    }
    assert!(min_sin > 0.39, "{min_sin}");
    println!("Hoeken: largest |P - closed form| {worst_cf:e}, lowest sine {min_sin}");
    for (deg, x) in [(90.0, 4.0), (180.0, 2.0), (270.0, 0.0)] {
        let p = m
            .position(&HoekenInput {
                theta: f64::to_radians(deg),
            })
            .unwrap();
        assert!(
            (p.P - Point2::new(x, 4.0)).norm() <= 1e-14,
            "{deg}: {:?}",
            p.P
        );
    }
    // The largest deviation from y = 4 over the straight part (90 to 270
    // deg, sampled every 0.25 deg), as generated and as the closed form has
    // it: 0.00974 (0.24 % of the part's length 4), at about 130 and 230 deg.
    println!(
        "Hoeken: largest deviation from y = 4: {:e} (closed form {:e})",
        dev.0, dev.1
    );
    assert!((dev.0 - dev.1).abs() <= 2e-14, "{dev:?}");
    assert!(dev.1 > 0.0097 && dev.1 < 0.0098, "{dev:?}");
}

// ---------------------------------------------------------------------------
// 3. Theo Jansen's leg.

// The "holy numbers" (Jansen, strandbeest.com; lengths in mm here). The
// geometry convention is the one two independent public implementations
// agree on (an MIT course's Matlab strandbeest exercise: crank centre (0, 0),
// fixed pivot (-38, -7.8), pivot-to-outer vertex d = 40.1 and upper-joint-
// to-outer e = 55.8, lower-joint-to-foot i = 49 and knee-to-foot h = 65.7;
// bernhard-42/bd_animation's `examples/jansen.py`: the same lengths with
// the pivot at the origin and the crank centre at (+38, +7.8), so the same
// relative position): crank m about O; the fixed pivot Z at (-a, -l);
// j from the crank pin A to the upper joint B, b from Z to B; k from A to
// the lower joint C, c from Z to C; the upper ternary link Z-B-D (sides b,
// e = |BD|, d = |ZD|); f from D to the knee E; the foot link C-E-F (sides
// g = |CE|, i = |CF|, h = |EF|). Branches: B above the line A-Z, C below
// it, D outboard (left of Z -> B), E right of D -> C, F below (left of C
// -> E): the walking leg. The foot path below (stride 68 mm, lift 22 mm,
// the flat stance) is what that convention gives.
const JA: f64 = 38.0;
const JB: f64 = 41.5;
const JC: f64 = 39.3;
const JD: f64 = 40.1;
const JE: f64 = 55.8;
const JF: f64 = 39.4;
const JG: f64 = 36.7;
const JH: f64 = 65.7;
const JI: f64 = 49.0;
const JJ: f64 = 50.0;
const JK: f64 = 61.9;
const JL: f64 = 7.8;
const JM: f64 = 15.0;

mechanism! {
    /// Theo Jansen's leg (mm, t, s, so forces in N and moments in N mm):
    /// the holy numbers (see the constants above), with `phi` the angle at Z
    /// from Z -> B to Z -> D and `psi` the angle at C from C -> E to C -> F
    /// (law of cosines; the literals are those values, the test sets them
    /// from `acos` and checks the literals against them); `(gux, guy)` and
    /// `(gfx, gfy)` the centroids of the two triangles in their links'
    /// frames. Masses on all seven moving links, gravity, and the ground's
    /// contact force on the foot (`loads`).
    pub JansenLeg {
        params {
            phi = 1.505666012627363, psi = 1.7295561572633906,
            gux = 14.703293172690763, guy = 13.33832626890207,
            gfx = 9.651135331516803, gfy = 16.12792706013989
        }
        loads { fx = 0.0, fy = 0.0 }
        dof 1;
        let O = ground(0.0, 0.0);
        let Z = ground(-38.0, -7.8);
        let A = crank(O, 15.0, theta) as crank;
        let B = rrr(A, 50.0, Z, 41.5, right) as (rodj, upper);
        let C = rrr(A, 61.9, Z, 39.3, left) as (rodk, lower);
        let D = point(upper, from Z, 40.1, phi);
        let E = rrr(D, 39.4, C, 36.7, right) as (rodf, foot);
        let F = point(foot, from C, 49.0, psi);
        let Gc = point(crank, from O, 7.5, 0 deg);
        let Gj = point(rodj, from A, 25.0, 0 deg);
        let Gk = point(rodk, from A, 30.95, 0 deg);
        let Gl = point(lower, from Z, 19.65, 0 deg);
        let Gf = point(rodf, from D, 19.7, 0 deg);
        let Gu = point(upper, from Z, (gux, guy));
        let Gt = point(foot, from C, (gfx, gfy));
        mass crank { m = 0.0003, at = Gc, j = 0.006 };
        mass rodj { m = 0.0002, at = Gj, j = 0.042 };
        mass rodk { m = 0.00025, at = Gk, j = 0.08 };
        mass lower { m = 0.00016, at = Gl, j = 0.021 };
        mass rodf { m = 0.00016, at = Gf, j = 0.021 };
        mass upper { m = 0.0004, at = Gu, j = 0.15 };
        mass foot { m = 0.0005, at = Gt, j = 0.3 };
        gravity (0.0, -9810.0);
        force at F on foot = (fx, fy);
    }
}

/// The leg with its triangle angles and centroids computed here from the
/// holy numbers (law of cosines, f64); the literal defaults must agree to a
/// few ulp (they were printed from the same formulas).
fn jansen() -> JansenLeg<f64> {
    let phi = ((JB * JB + JD * JD - JE * JE) / (2.0 * JB * JD)).acos();
    let psi = ((JG * JG + JI * JI - JH * JH) / (2.0 * JG * JI)).acos();
    let m = JansenLeg {
        phi,
        psi,
        gux: (JB + JD * phi.cos()) / 3.0,
        guy: JD * phi.sin() / 3.0,
        gfx: (JG + JI * psi.cos()) / 3.0,
        gfy: JI * psi.sin() / 3.0,
    };
    let d = JansenLeg::<f64>::default();
    for (x, y) in [
        (m.phi, d.phi),
        (m.psi, d.psi),
        (m.gux, d.gux),
        (m.guy, d.guy),
        (m.gfx, d.gfx),
        (m.gfy, d.gfy),
    ] {
        assert!((x - y).abs() <= 4.0 * f64::EPSILON * x.abs(), "{x} vs {y}");
    }
    m
}

/// The leg's double-double reference, with the holy numbers as distances
/// (the triangles by their three sides, not by the angles above): points 0
/// O, 1 Z, 2 A, 3 B, 4 C, 5 D, 6 E, 7 F.
fn jansen_linkage() -> Linkage {
    let d = |p, q, len| Constraint::Distance { p, q, len };
    let side = |p, a, b, sign| Side::Left { p, a, b, sign };
    let mut points = vec![fixed(0.0, 0.0), fixed(-JA, -JL)];
    points.extend([Point::Unknown; 6]);
    Linkage {
        points,
        constraints: vec![
            Constraint::Crank {
                p: 2,
                o: 0,
                r: JM,
                input: 0,
            },
            d(3, 2, JJ),
            d(3, 1, JB),
            d(4, 2, JK),
            d(4, 1, JC),
            d(5, 1, JD),
            d(5, 3, JE),
            d(6, 5, JF),
            d(6, 4, JG),
            d(7, 4, JI),
            d(7, 6, JH),
        ],
        sides: vec![
            side(3, 2, 1, -1.0),
            side(4, 2, 1, 1.0),
            side(5, 1, 3, 1.0),
            side(6, 5, 4, -1.0),
            side(7, 4, 6, 1.0),
        ],
        scale: 100.0,
    }
}

/// Every holy number as a distance between the generated points, at every
/// degree of the turn: the eleven lengths of the reference plus the crank.
/// `assert_len` allows 1e-14 of the length (30 eps of the 100 mm
/// coordinates at 65.7: a few roundings of each group, the groups' sines
/// staying above 0.15 over the turn (asserted; C's group is the lowest,
/// near 190 deg), and the ternary points' rotation by sin/cos of `phi`,
/// `psi` within 2 ulp).
#[test]
fn jansen_keeps_every_length() {
    let m = jansen();
    let mut lowest = 1.0f64;
    for k in 0..360 {
        let p = m
            .position(&JansenLegInput {
                theta: f64::to_radians(k as f64),
            })
            .unwrap();
        assert_len(p.A, p.O, JM, "m");
        assert_len(p.B, p.A, JJ, "j");
        assert_len(p.B, p.Z, JB, "b");
        assert_len(p.C, p.A, JK, "k");
        assert_len(p.C, p.Z, JC, "c");
        assert_len(p.D, p.Z, JD, "d");
        assert_len(p.D, p.B, JE, "e");
        assert_len(p.E, p.D, JF, "f");
        assert_len(p.E, p.C, JG, "g");
        assert_len(p.F, p.C, JI, "i");
        assert_len(p.F, p.E, JH, "h");
        assert_eq!(p.Z, Point2::new(-JA, -JL));
        lowest = lowest
            .min(sin_at(p.B, p.A, p.Z))
            .min(sin_at(p.C, p.A, p.Z))
            .min(sin_at(p.E, p.D, p.C));
    }
    assert!(lowest > 0.15, "{lowest}");
}

/// The generated points in the reference's order.
fn jansen_points(p: &JansenLegPosition<f64>) -> [Point2<f64>; 8] {
    [p.O, p.Z, p.A, p.B, p.C, p.D, p.E, p.F]
}

/// The leg's conditioning at a pose: the smallest sine of the groups that
/// find B and C, times the sine of E's group (E takes their errors), as in
/// the inversor's test.
fn jansen_kappa(p: &JansenLegPosition<f64>) -> f64 {
    sin_at(p.B, p.A, p.Z).min(sin_at(p.C, p.A, p.Z)) * sin_at(p.E, p.D, p.C)
}

/// Positions, velocities and accelerations of every point against the
/// double-double reference every 2 deg, normwise per stage, in the form
/// `c eps L / kappa^k` of the inversor's test (L the largest reference
/// value of the stage, k = 1, 2, 3); `c = 16`, the measured worst printed
/// (1.19, 2.66, 2.19; the lowest kappa over the turn 0.054, near 190 deg).
/// Also the foot's path: the stance (crank from -60 to 60 deg) keeps the
/// foot within 0.39 mm of its lowest height while it advances 46 mm
/// monotonically (figures of the reference, asserted on the generated
/// points and shown equal to the reference's to 1e-12 mm).
#[test]
fn jansen_matches_the_double_double_reference() {
    let m = jansen();
    let lk = jansen_linkage();
    let (w, al) = (std::f64::consts::TAU, 3.0);
    let mut worst = [0.0f64; 3];
    let mut min_kappa = 1.0f64;
    let mut stance = Vec::new();
    let mut stance_ref = Vec::new();
    let (mut ymin, mut ymax) = (f64::INFINITY, f64::NEG_INFINITY);
    for k in 0..180 {
        let q = f64::to_radians(2.0 * k as f64);
        let i = |x| JansenLegInput { theta: x };
        let s = m
            .solve(&i(q), &i(w), &i(al), &JansenLegLoads { fx: 0.0, fy: 0.0 })
            .unwrap();
        let (p, v, a) = (&s.position, &s.velocity, &s.acceleration);
        let pts = jansen_points(p);
        let start: Vec<(f64, f64)> = pts.iter().map(|p| (p.x, p.y)).collect();
        let (rp, rv, ra) = reference(&lk, q, w, al, &start);
        let kappa = jansen_kappa(p);
        min_kappa = min_kappa.min(kappa);
        let z = Vector2::zeros();
        let vs = [z, z, v.A, v.B, v.C, v.D, v.E, v.F];
        let accs = [z, z, a.A, a.B, a.C, a.D, a.E, a.F];
        let e = scaled_errors(&start, (&vs, &accs), (&rp, &rv, &ra), kappa);
        for (x, e) in worst.iter_mut().zip(e) {
            *x = x.max(e);
        }
        ymin = ymin.min(p.F.y);
        ymax = ymax.max(p.F.y);
        // Stance: -60..60 deg, i.e. 300..358 and 0..60 in this loop.
        let deg = 2 * k;
        if deg >= 300 || deg <= 60 {
            let order = if deg >= 300 { deg - 360 } else { deg };
            stance.push((order, p.F));
            stance_ref.push((order, rp[7].x.to_f64(), rp[7].y.to_f64()));
        }
    }
    println!(
        "Jansen vs double-double: worst / (eps L kappa^-k) {worst:?}, lowest kappa {min_kappa}"
    );
    for (what, x) in ["position", "velocity", "acceleration"].iter().zip(worst) {
        assert!(x <= 16.0, "{what}: {x}");
    }

    stance.sort_by_key(|s| s.0);
    stance_ref.sort_by_key(|s| s.0);
    let band = |ys: &mut dyn Iterator<Item = f64>| {
        let (lo, hi) = ys.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), y| {
            (lo.min(y), hi.max(y))
        });
        (lo, hi)
    };
    let (lo, hi) = band(&mut stance.iter().map(|s| s.1.y));
    let (rlo, rhi) = band(&mut stance_ref.iter().map(|s| s.2));
    let stride = stance.last().unwrap().1.x - stance[0].1.x;
    let rstride = stance_ref.last().unwrap().1 - stance_ref[0].1;
    println!(
        "Jansen foot: stance band {:.4} mm (reference {:.4}), stride {stride:.3} mm \
         (reference {rstride:.3}), lowest {lo:.4}, whole turn {ymin:.4}..{ymax:.4}",
        hi - lo,
        rhi - rlo
    );
    assert!(((hi - lo) - (rhi - rlo)).abs() <= 1e-12, "band");
    assert!((stride - rstride).abs() <= 1e-12, "stride");
    assert!(hi - lo < 0.39 && hi - lo > 0.38, "stance band {}", hi - lo);
    assert!(stride > 45.9 && stride < 46.1, "stride {stride}");
    // The stance holds the lowest point of the whole path, and the foot
    // advances monotonically through it (+x, the crank turning
    // counter-clockwise).
    assert_eq!(lo, ymin);
    assert!(stance.windows(2).all(|s| s[1].1.x > s[0].1.x));
    assert!(
        ymax - ymin > 22.0 && ymax - ymin < 22.6,
        "lift {}",
        ymax - ymin
    );
}

/// Central difference of `f` at 0 with step `h`.
fn central(f: &dyn Fn(f64) -> Vector2<f64>, h: f64) -> Vector2<f64> {
    (f(h) - f(-h)) / (2.0 * h)
}

/// Richardson-extrapolated central difference of `f` at 0 and a bound on its
/// error. With `D(h) = f' + h^2 f'''/6 + h^4 f^(5)/120 + ..`, `R(h) = (4
/// D(h/2) - D(h)) / 3 = f' - h^4 f^(5)/480 + O(h^6)`; `R(2h)` has 16 times
/// that term, so `|R(h) - R(2h)| / 15` estimates the truncation error of
/// `R(h)` (taken twice over for the neglected `h^6` terms). Rounding: each
/// value of `f` is within `delta` of the exact one, so `D(h/2)` is within
/// `2 delta / h`, `D(h)` within `delta / h` and `R(h)` within `3 delta / h`.
fn richardson(f: &dyn Fn(f64) -> Vector2<f64>, h: f64, delta: f64) -> (Vector2<f64>, f64) {
    let r = |h: f64| (central(f, h / 2.0) * 4.0 - central(f, h)) / 3.0;
    let (r1, r2) = (r(h), r(2.0 * h));
    (r1, 2.0 * (r1 - r2).norm() / 15.0 + 3.0 * delta / h)
}

/// Velocities and accelerations of every moving point of the leg against
/// Richardson-extrapolated central differences of the generated position
/// and velocity, along a motion with crank acceleration (theta = q + w t +
/// al t^2 / 2), every 5 deg.
///
/// Step: `h = 2.5e-4 s` (1.6e-3 rad of crank). Rounding: the positions are
/// within 16 eps L / kappa of exact and the velocities within 16 eps V /
/// kappa^2 (the reference test's bounds, `kappa` the pose's, down to
/// 0.054 near 190 deg; L = 100 mm, V = 1000 mm/s, which bounds every
/// point's speed here: asserted), at worst 7e-12 mm and 1.2e-9 mm/s, so `3
/// delta / h` is below 1e-7 mm/s and 1.5e-5 mm/s^2. Truncation: estimated
/// per pose as above; near lift-off (170 to 190 deg) the foot's
/// acceleration changes fast and the estimate reaches 5e-6 mm/s^2 (at 1e-3 s
/// it was 8e-5: it scales as h^4, as measured down to 1e-4 s). The sum is
/// asserted below 1e-8 of the scale (V, and A = 2e4 mm/s^2 bounding every
/// acceleration: asserted), so the check cannot become vacuous; a rate
/// wrong by a term of its own size fails by 1e6 or more.
#[test]
fn jansen_rates_match_richardson_differences() {
    let m = jansen();
    let (w, al) = (std::f64::consts::TAU, 3.0);
    let h = 2.5e-4;
    let (lp, lv, la) = (100.0, 1000.0, 2e4);
    let mut worst = (0.0f64, 0.0f64);
    for k in 0..72 {
        let q = f64::to_radians(5.0 * k as f64);
        let at = |t: f64| JansenLegInput {
            theta: q + w * t + 0.5 * al * t * t,
        };
        let rate = |t: f64| JansenLegInput { theta: w + al * t };
        let p = m.position(&at(0.0)).unwrap();
        let v = m.velocity(&p, &rate(0.0)).unwrap();
        let a = m
            .acceleration(&p, &v, &JansenLegInput { theta: al })
            .unwrap();
        let kappa = jansen_kappa(&p);
        let (dp, dv) = (
            16.0 * f64::EPSILON * lp / kappa,
            16.0 * f64::EPSILON * lv / (kappa * kappa),
        );
        let pos = |t: f64| m.position(&at(t)).unwrap();
        let vel = |t: f64| m.velocity(&pos(t), &rate(t)).unwrap();
        type Pick = fn(&JansenLegPosition<f64>) -> Point2<f64>;
        type PickV = fn(&JansenLegVelocity<f64>) -> Vector2<f64>;
        type Row = (&'static str, Pick, PickV, Vector2<f64>, Vector2<f64>);
        let points: [Row; 6] = [
            ("A", |p| p.A, |v| v.A, v.A, a.A),
            ("B", |p| p.B, |v| v.B, v.B, a.B),
            ("C", |p| p.C, |v| v.C, v.C, a.C),
            ("D", |p| p.D, |v| v.D, v.D, a.D),
            ("E", |p| p.E, |v| v.E, v.E, a.E),
            ("F", |p| p.F, |v| v.F, v.F, a.F),
        ];
        for (name, pick, pick_v, got_v, got_a) in points {
            let (fd_v, tol_v) = richardson(&|t| pick(&pos(t)).coords, h, dp);
            let (fd_a, tol_a) = richardson(&|t| pick_v(&vel(t)), h, dv);
            let (scale_v, scale_a) = (lv, la);
            assert!(got_v.norm() <= lv && got_a.norm() <= la, "{name} at {k}");
            assert!(tol_v <= 1e-8 * scale_v, "{name} at {k}: vel tol {tol_v:e}");
            assert!(tol_a <= 1e-8 * scale_a, "{name} at {k}: acc tol {tol_a:e}");
            let (ev, ea) = ((got_v - fd_v).norm(), (got_a - fd_a).norm());
            assert!(
                ev <= tol_v,
                "v{name} at {k}: {got_v:?} vs {fd_v:?} (tol {tol_v:e})"
            );
            assert!(
                ea <= tol_a,
                "a{name} at {k}: {got_a:?} vs {fd_a:?} (tol {tol_a:e})"
            );
            worst.0 = worst.0.max(ev / scale_v);
            worst.1 = worst.1.max(ea / scale_a);
        }
    }
    println!("Jansen vs Richardson: worst relative velocity, acceleration error {worst:?}");
}

// ---------------------------------------------------------------------------
// 4. Forces on Jansen's leg.

/// The leg's masses (t) and inertias about the centres (t mm^2), as in the
/// definition, per link: crank, rodj, rodk, lower, rodf, upper, foot.
const JMASS: [(f64, f64); 7] = [
    (0.0003, 0.006),
    (0.0002, 0.042),
    (0.00025, 0.08),
    (0.00016, 0.021),
    (0.00016, 0.021),
    (0.0004, 0.15),
    (0.0005, 0.3),
];

/// Gravity (mm/s^2).
const JG9: Vector2<f64> = Vector2::new(0.0, -9810.0);

/// Newton-Euler for each of the seven moving links of one solved pose,
/// from the generated reactions, drive torque, the contact force `contact`
/// at F and the inertia and weight terms; `flip` negates the reaction of
/// `rodk` on `foot` at C in the copy applied to the foot (the deliberate
/// mistake). Returns the worst relative residual (force or moment).
fn jansen_newton_euler(s: &JansenLegSolution<f64>, contact: Vector2<f64>, flip: f64) -> f64 {
    let (p, a, f) = (&s.position, &s.acceleration, &s.forces);
    let mm = |i: usize| JMASS[i];
    let bodies = [
        Body::default()
            .force(p.O, f.r_ground_crank)
            .force(p.A, -f.r_crank_rodj)
            .force(p.A, -f.r_crank_rodk)
            .couple(f.drive_theta)
            .inertia(mm(0).0, mm(0).1, p.Gc, a.Gc, a.crank, JG9),
        Body::default()
            .force(p.A, f.r_crank_rodj)
            .force(p.B, -f.r_rodj_upper)
            .inertia(mm(1).0, mm(1).1, p.Gj, a.Gj, a.rodj, JG9),
        Body::default()
            .force(p.A, f.r_crank_rodk)
            .force(p.C, -f.r_rodk_lower)
            .force(p.C, -f.r_rodk_foot)
            .inertia(mm(2).0, mm(2).1, p.Gk, a.Gk, a.rodk, JG9),
        Body::default()
            .force(p.Z, f.r_ground_lower)
            .force(p.C, f.r_rodk_lower)
            .inertia(mm(3).0, mm(3).1, p.Gl, a.Gl, a.lower, JG9),
        Body::default()
            .force(p.D, f.r_upper_rodf)
            .force(p.E, -f.r_rodf_foot)
            .inertia(mm(4).0, mm(4).1, p.Gf, a.Gf, a.rodf, JG9),
        Body::default()
            .force(p.Z, f.r_ground_upper)
            .force(p.B, f.r_rodj_upper)
            .force(p.D, -f.r_upper_rodf)
            .inertia(mm(5).0, mm(5).1, p.Gu, a.Gu, a.upper, JG9),
        Body::default()
            .force(p.C, f.r_rodk_foot * flip)
            .force(p.E, f.r_rodf_foot)
            .force(p.F, contact)
            .inertia(mm(6).0, mm(6).1, p.Gt, a.Gt, a.foot, JG9),
    ];
    bodies
        .iter()
        .map(|b| {
            let (fr, mr) = b.residual();
            fr.max(mr)
        })
        .fold(0.0, f64::max)
}

/// The drive torque from the power balance (N mm): `tau w + F . v_F +
/// sum(weights and inertia loads' power) = 0`, from the generated motion
/// only; `skip` leaves out one link's inertia term (the deliberate mistake;
/// `None` for the real balance). Also returns the largest single power.
fn jansen_power_torque(
    s: &JansenLegSolution<f64>,
    contact: Vector2<f64>,
    w: f64,
    skip: Option<usize>,
) -> (f64, f64) {
    let (v, a) = (&s.velocity, &s.acceleration);
    let links = [
        (v.Gc, a.Gc, v.crank, a.crank),
        (v.Gj, a.Gj, v.rodj, a.rodj),
        (v.Gk, a.Gk, v.rodk, a.rodk),
        (v.Gl, a.Gl, v.lower, a.lower),
        (v.Gf, a.Gf, v.rodf, a.rodf),
        (v.Gu, a.Gu, v.upper, a.upper),
        (v.Gt, a.Gt, v.foot, a.foot),
    ];
    let mut terms = vec![contact.dot(&v.F)];
    for (i, (vg, ag, om, alpha)) in links.into_iter().enumerate() {
        if skip != Some(i) {
            let (m, j) = JMASS[i];
            terms.push(inertial(m, j, vg, ag, om, alpha, JG9));
        }
    }
    let sum: f64 = terms.iter().sum();
    let scale = terms.iter().fold(0.0f64, |x, t| x.max(t.abs()));
    (-sum / w, scale)
}

/// The leg's force analysis over the turn (every 5 deg), crank at 1 rev/s
/// speeding up at 3 rad/s^2, with the ground pushing on the foot (40 N up,
/// 6 N back) through the stance (crank -60 to 60 deg) and nothing
/// elsewhere:
///
/// - Newton-Euler per link, from the generated reactions (the seven links,
///   every joint: A and C each join three links): net force and moment
///   within `TOL` (1e-13, see `main.rs`; the force systems' relative pivots
///   are printed, their lowest is what the `eps / condition` of docs/dsl.md
///   allows) of the largest term;
/// - the drive torque against the one the power balance gives from the
///   motion alone, within `TOL` of the largest power divided by `w`;
/// - each check fails on a deliberate mistake: the foot's reaction at C
///   negated (a residual of the size of that reaction: above 1e-2 of the
///   scale at every pose, 3.7e-2 the least measured), the foot's inertia
///   left out of the power (the torque off by that term's share: above
///   1e-4 of the scale at every pose, 3.5e-4 the least measured); both
///   1e9 times `TOL` or more. Measured (printed): Newton-Euler 6.4e-16,
///   power 2.1e-15, lowest force-system condition 0.29.
#[test]
fn jansen_forces_balance_per_link_and_by_power() {
    let m = jansen();
    let (w, al) = (std::f64::consts::TAU, 3.0);
    let mut worst = (0.0f64, 0.0f64);
    let mut lowest_condition = 1.0f64;
    let mut caught = (f64::INFINITY, f64::INFINITY);
    for k in 0..72 {
        let deg = 5 * k;
        let stance = !(65..300).contains(&deg);
        let contact = if stance {
            Vector2::new(-6.0, 40.0)
        } else {
            Vector2::zeros()
        };
        let i = |x| JansenLegInput { theta: x };
        let loads = JansenLegLoads {
            fx: contact.x,
            fy: contact.y,
        };
        let s = m
            .solve(&i(f64::to_radians(deg as f64)), &i(w), &i(al), &loads)
            .unwrap();
        let f = &s.forces;
        lowest_condition = lowest_condition.min(f.condition);

        let ne = jansen_newton_euler(&s, contact, 1.0);
        assert!(ne <= TOL, "Newton-Euler at {deg} deg: {ne:e}");
        worst.0 = worst.0.max(ne);
        let (tau, scale) = jansen_power_torque(&s, contact, w, None);
        let e = (tau - f.drive_theta).abs() / (scale / w);
        assert!(
            e <= TOL,
            "drive at {deg} deg: {} vs {tau} by power ({e:e})",
            f.drive_theta
        );
        worst.1 = worst.1.max(e);

        // The deliberate mistakes.
        let wrong = jansen_newton_euler(&s, contact, -1.0);
        assert!(
            wrong > 1e-2,
            "a negated reaction passes at {deg} deg: {wrong:e}"
        );
        let (tau_wrong, _) = jansen_power_torque(&s, contact, w, Some(6));
        let off = (tau_wrong - f.drive_theta).abs() / (scale / w);
        assert!(
            off > 1e-4,
            "a missing inertia term passes at {deg} deg: {off:e}"
        );
        caught.0 = caught.0.min(wrong);
        caught.1 = caught.1.min(off);
    }
    println!(
        "Jansen forces: worst Newton-Euler {:e}, power {:e}; lowest condition {lowest_condition}; \
         smallest deliberate mistakes seen: {:e}, {:e}",
        worst.0, worst.1, caught.0, caught.1
    );
}
