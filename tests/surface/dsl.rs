//! The definition language's surface in combinations the scenes, the zoo
//! and statement_kinds.rs do not write: DSL words, unicode and long names as
//! names; statements in reverse dependency order; dimensions, offsets and
//! angles from `params`, `const`s (one computed from another), arithmetic,
//! negation, integer literals; every group's offset from a parameter; a
//! guide carried by a block; points from a link's second joint and on a
//! block; output subsets down to `outputs { }` (forces only); `#[self_test]` at the
//! position and velocity levels, with two inputs, loads and a slider on a
//! carried guide; forces with loads in a force and a torque and gravity
//! from a parameter. Values are checked against the constraints recomputed
//! here, the literal twin of a parameter definition, central differences
//! and the power balance computed from the outputs.
//!
//! Definitions that did not compile before their fix: `PosOnlySelfTest`
//! (self-test helper called `velocity()`), `TorqueOnly` (structs without a
//! field of type `T`). Two more fixes have unit tests in mechanism-codegen
//! (a two-input `#[self_test]` without both ranges; a slide named `B_x`
//! beside a point `B` in the batch API).
#![allow(non_snake_case, dead_code)]
use crate::surface_defs::*;
use mechanism::mechanism;
use mechanism::{Point2, Vector2};

mechanism! {
    pub ForceNameClash {
        let O2 = ground(0.0, 0.0);
        let O4 = ground(3.0, 0.0);
        let O6 = ground(4.0, 2.0);
        let A = crank(O2, 1.0, theta) as a;
        let B = rrr(A, 3.0, O4, 2.5, left) as (b_c, a_b);
        let E = point(a_b, from O4, 1.0, 1.0);
        let F = rrr(E, 2.0, O6, 2.0, left) as (c, d);
        mass c { m = 1.0, at = F };
        range theta = (-10 deg, 10 deg);
        allow singular;
    }
}

mechanism! {
    pub IntLiterals {
        let O2 = ground(0, 0);
        let O4 = ground(3, 0);
        let A = crank(O2, 1, theta) as link2;
        let B = rrr(A, 3, O4, 2.5, left) as (link3, link4);
        let P = point(link3, from A, 1, 90 deg);
    }
}

mechanism! {
    pub PosSelfTest {
        analysis position;
        outputs { B }
        let O2 = ground(0.0, 0.0);
        let O4 = ground(3.0, 0.0);
        let A = crank(O2, 1.0, theta) as link2;
        let B = rrr(A, 3.0, O4, 2.5, left) as (link3, link4);
    }
}

mechanism! {
    pub ActuatorForces {
        params { g = 9.81 }
        dof 1;
        let A = ground(0.0, 0.0);
        let B = ground(0.8, -0.2);
        let C = actuator(A, 1.2, B, len, left) as (boom, cylinder);
        let tip = point(boom, from A, 2.5, 10 deg);
        let Gb = point(boom, from A, 1.2, 5 deg);
        mass boom { m = 50.0, at = Gb, j = 20.0 };
        gravity (0.0, -g);
        force at tip = (0.0, -100.0);
        range len = (0.9, 1.5);
    }
}

mechanism! {
    /// `TorqueOnly` with every output.
    pub TorqueAll {
        let O = ground(0.0, 0.0);
        let line = guide(O, 0 deg);
        let A = crank(O, 0.1, theta) as link2;
        let B = rrp(A, 0.4, line, plus) as (link3, slider) slide x;
        let G3 = point(link3, from A, 0.2, 0 deg);
        mass link3 { m = 1.2, at = G3, j = 0.02 };
        mass slider { m = 0.5, at = B };
        gravity (0.0, -9.81);
        force at B on slider along line = -40.0;
    }
}

mechanism! {
    #[self_test]
    pub PosOnlySelfTest {
        analysis position;
        outputs { link4 }
        let O2 = ground(0.0, 0.0);
        let O4 = ground(3.0, 0.0);
        let A = crank(O2, 1.0, theta) as link2;
        let B = rrr(A, 3.0, O4, 2.5, left) as (link3, link4);
    }
}

mechanism! {
    #[self_test]
    pub VelOnlySelfTest {
        analysis velocity;
        outputs { x }
        let O = ground(0.0, 0.0);
        let line = guide(O, 0 deg);
        let A = crank(O, 0.1, theta) as link2;
        let B = rrp(A, 0.4, line, plus) as (link3, slider) slide x;
    }
}

mechanism! {
    #[self_test]
    pub Dof2Loads {
        params { g = 9.81 }
        loads { f = 1.0, tq = 0.1 }
        dof 2;
        let O1 = ground(0.0, 0.0);
        let O2 = ground(0.08, 0.0);
        let A = crank(O1, 0.1, q1 as cos_sin) as arm1;
        let C = crank(O2, 0.1, q2 as cos_sin) as arm2;
        let P = rrr(A, 0.16, C, 0.16, left) as (fore1, fore2);
        mass fore1 { m = 0.4, at = P };
        mass arm2 { m = 0.2, at = C, j = 0.001 };
        gravity (g * 0.0, -g);
        force at P on fore2 = (f, -f);
        torque on fore1 = tq;
        range q1 = (60 deg, 150 deg);
        range q2 = (0 deg, 90 deg);
    }
}

mechanism! {
    /// `OutOfOrder` with every dimension written as the literal its
    /// parameters and expressions give by default.
    pub OutOfOrderLit {
        let O = ground(0.0, 0.0);
        let line = guide((0.5, -0.2), 10 deg);
        let A = crank(O, 1.0, theta) as link2;
        let B = rrp(A, 4.0, line, minus, -0.2) as (link3, block) slide x;
        let P = point(block, from B, (0.1, -0.2));
        let Q = point(link3, from B, 0.5, -10 deg);
        outputs { P, Q, x }
    }
}

// ---------------------------------------------------------------- helpers

/// Finite-difference step (see `rate_fd`).
const H: f64 = 1e-5;

fn d2(a: Point2<f64>, b: Point2<f64>) -> f64 {
    (a - b).norm()
}

fn cross(a: Vector2<f64>, b: Vector2<f64>) -> f64 {
    a.x * b.y - a.y * b.x
}

fn dir(angle: f64) -> Vector2<f64> {
    Vector2::new(angle.cos(), angle.sin())
}

/// Asserts `got` within `tol * max(1, scale)` of `want`.
fn near(got: f64, want: f64, tol: f64, scale: f64, what: &str) {
    assert!(
        (got - want).abs() <= tol * scale.max(1.0),
        "{what}: {got} vs {want} (tolerance {tol:e} x {scale})"
    );
}

fn near_v(got: Vector2<f64>, want: Vector2<f64>, tol: f64, scale: f64, what: &str) {
    assert!(
        (got - want).norm() <= tol * scale.max(1.0),
        "{what}: {got:?} vs {want:?}"
    );
}

/// Central difference at t = 0 with step `h`.
fn cd(f: &impl Fn(f64) -> Vector2<f64>, h: f64) -> Vector2<f64> {
    (f(h) - f(-h)) / (2.0 * h)
}

/// Asserts a rate against the central difference of `f` at `H`. Near a
/// toggle the derivatives grow and the truncation error `c h^2` with them,
/// so it is estimated, Richardson's way: D(2h) - D(h) = 3 c h^2; allowed
/// 4 times that (12 times the estimated error) plus the rounding of the
/// difference quotient, eps |f| / h ~ 2e-11 |f|, taken as 1e-9 of
/// max(1, |rate|) (values <= 5 here).
fn rate_fd(got: Vector2<f64>, f: impl Fn(f64) -> Vector2<f64>, what: &str) {
    let (d1, d2) = (cd(&f, H), cd(&f, 2.0 * H));
    let tol = 4.0 * (d2 - d1).norm() + 1e-9 * got.norm().max(1.0);
    assert!(
        (got - d1).norm() <= tol,
        "{what}: {got:?} vs {d1:?} (tolerance {tol:e})"
    );
}

fn rate_fd_s(got: f64, f: impl Fn(f64) -> f64, what: &str) {
    rate_fd(Vector2::new(got, 0.0), |t| Vector2::new(f(t), 0.0), what);
}

/// Loop closure: every group closes to rounding, a few eps of the sizes
/// (<= 5 here): 1e-14 absolute is 20 to 50 eps of them.
const CLOSE: f64 = 1e-14;

// ---------------------------------------------------------------- tests

/// Statements in reverse dependency order, dimensions from `params`, a
/// `const`, arithmetic (`2.0 * crank + rod - 2.0`), negation (`-offset`,
/// `-(offset)`), a guide angle and a polar point's angle from a parameter in
/// `deg`, a negative RRP offset, a point on the block from a Cartesian
/// offset. Checked against the same mechanism written with literals, then
/// with changed parameters against the constraints themselves.
#[test]
fn params_consts_and_expressions_match_literals_and_constraints() {
    let (m, lit) = (
        OutOfOrder::<f64>::default(),
        OutOfOrderLit::<f64>::default(),
    );
    for k in 0..72 {
        let q = f64::to_radians(5.0 * k as f64 + 2.5);
        let (a, b) = (
            m.position(&OutOfOrderInput { theta: q }),
            lit.position(&OutOfOrderLitInput { theta: q }),
        );
        let (Ok(a), Ok(b)) = (a, b) else {
            panic!("{k}: one assembles and not the other");
        };
        // The only differences: the macro folds cos/sin of the literal
        // 10 deg at expansion time (the host's libm), the parameter version
        // computes them at run time; they agree to 1 ulp, which moves points
        // of size <= 5 by ~1e-15: 4e-15 allows 4 such roundings.
        near(a.P.x, b.P.x, 4e-15, 5.0, "P.x");
        near(a.P.y, b.P.y, 4e-15, 5.0, "P.y");
        near(a.Q.x, b.Q.x, 4e-15, 5.0, "Q.x");
        near(a.Q.y, b.Q.y, 4e-15, 5.0, "Q.y");
        near(a.x, b.x, 4e-15, 5.0, "x");
    }
    // Changed parameters: the constraints, recomputed from the outputs.
    let m = OutOfOrder {
        crank: 0.7,
        offset: -0.05,
        gangle: -25.0,
    };
    let u = dir((-25f64).to_radians());
    let n = Vector2::new(-u.y, u.x);
    let origin = Point2::new(0.5, 0.05);
    for k in 0..72 {
        let q = f64::to_radians(5.0 * k as f64);
        let p = m.position(&OutOfOrderInput { theta: q }).unwrap();
        let a = Point2::new(0.7 * q.cos(), 0.7 * q.sin());
        // B: 2 * 0.7 + 4 - 2 = 3.4 from A, offset -(-0.05) = 0.05 left of
        // the guide; x = dot(B - origin, u).
        let bpt = origin + u * p.x + n * 0.05;
        near(d2(bpt, a), 3.4, CLOSE, 5.0, "|B - A|");
        // P = B + (0.1, -offset = 0.05) in the block's frame (axis u).
        let pp = bpt + u * 0.1 + n * 0.05;
        near_v(p.P - pp, Vector2::zeros(), CLOSE, 5.0, "P");
        // Q on the rod from B, 0.5 at -gangle = +25 deg from the rod's axis
        // (A -> B).
        let rod = (bpt - a) / 3.4;
        let qq = bpt
            + (rod * 25f64.to_radians().cos()
                + Vector2::new(-rod.y, rod.x) * 25f64.to_radians().sin())
                * 0.5;
        near_v(p.Q - qq, Vector2::zeros(), CLOSE, 5.0, "Q");
    }
}

/// Velocities and accelerations of the listed point and scalar outputs of a
/// one-input definition against central differences along
/// q(t) = q0 + w t + al t^2 / 2 (position for the velocity, velocity with
/// rate w + al t for the acceleration); `FD_TOL` justified at `H`.
macro_rules! fd_check {
    ($m:expr, $input:ident, $q:ident, $q0:expr, $w:expr, $al:expr, [$($p:ident),*], [$($s:ident),*]) => {{
        let m = &$m;
        let (q0, w, al): (f64, f64, f64) = ($q0, $w, $al);
        let at = |t: f64| $input { $q: q0 + w * t + 0.5 * al * t * t };
        let rate = |t: f64| $input { $q: w + al * t };
        let pos = |t: f64| m.position(&at(t)).unwrap();
        let vel = |t: f64| m.velocity(&pos(t), &rate(t)).unwrap();
        let s = m.solve(&at(0.0), &rate(0.0), &$input { $q: al }).unwrap();
        $(
            rate_fd(s.velocity.$p, |t| pos(t).$p.coords, concat!("v ", stringify!($p)));
            rate_fd(s.acceleration.$p, |t| vel(t).$p, concat!("a ", stringify!($p)));
        )*
        $(
            rate_fd_s(s.velocity.$s, |t| pos(t).$s, concat!("v ", stringify!($s)));
            rate_fd_s(s.acceleration.$s, |t| vel(t).$s, concat!("a ", stringify!($s)));
        )*
        s
    }};
}

#[test]
fn out_of_order_rates_with_changed_params() {
    let m = OutOfOrder {
        crank: 0.7,
        offset: -0.05,
        gangle: -25.0,
    };
    for k in 0..36 {
        let q0 = f64::to_radians(10.0 * k as f64 + 1.0);
        fd_check!(m, OutOfOrderInput, theta, q0, 3.0, -2.0, [P, Q], [x]);
    }
}

/// A guide carried by an RRP's block (at a parameter angle to the block's
/// axis), an RRP on it, a point on that RRP's first link from its second
/// joint C, and an RRR between two coupler points.
#[test]
fn guide_on_a_block_and_points_from_second_joints() {
    let m = BlockGuide::<f64>::default();
    let mut solved = 0;
    for k in 0..72 {
        let q0 = f64::to_radians(5.0 * k as f64);
        let Ok(p) = m.position(&BlockGuideInput { theta: q0 }) else {
            continue;
        };
        solved += 1;
        // The carried guide passes through B at 0.3 rad to the block's axis
        // (+x): C lies on it at its offset 0.
        let u = dir(0.3);
        near(
            cross(u, p.C - p.B),
            0.0,
            CLOSE,
            1.0,
            "C on the carried guide",
        );
        near(d2(p.C, p.O3), 0.6, CLOSE, 1.0, "|C - O3|");
        near(d2(p.F, p.D), 0.5, CLOSE, 1.0, "|F - D|");
        near(d2(p.F, p.E), 0.5, CLOSE, 1.0, "|F - E|");
        // E = C + (0.05, 0.02) in link5's frame, whose axis points O3 -> C.
        let ax = (p.C - p.O3) / 0.6;
        let e = p.C + ax * 0.05 + Vector2::new(-ax.y, ax.x) * 0.02;
        near_v(p.E - e, Vector2::zeros(), CLOSE, 1.0, "E");
        fd_check!(
            m,
            BlockGuideInput,
            theta,
            q0,
            5.0,
            1.0,
            [C, D, E, F],
            [x, y, link5, link7]
        );
    }
    assert!(solved > 30, "only {solved} poses assemble");
}

/// RPR, PRP and RPP offsets and the RPP's slot angle from parameters
/// (negative ones included), a const computed from a const, a guide through
/// parameter coordinates, a PRP on the crank's carried line.
#[test]
fn group_offsets_from_params() {
    let m = ParamGroups::<f64>::default();
    for k in 0..24 {
        let q0 = f64::to_radians(-57.5 + 5.0 * k as f64);
        let s = fd_check!(
            m,
            ParamGroupsInput,
            phi,
            q0,
            4.0,
            -3.0,
            [D, E, Q],
            [s, s1, s2, t1, t2, link3, yoke]
        );
        let p = &s.position;
        let a = Point2::new(0.125 * q0.cos(), 0.125 * q0.sin());
        // D is 0.6 / 2 * 4 / 4 + 0.3 = 0.6 from C along link3, whose axis
        // passes at offset -0.01 from A (A lies 0.01 right of the axis).
        near(d2(p.D, p.C), 0.6, CLOSE, 1.0, "|D - C|");
        let u3 = dir(p.link3);
        near(cross(u3, a - p.C), -0.01, CLOSE, 1.0, "RPR offset");
        near(
            (a - p.C).dot(&u3),
            p.s,
            CLOSE,
            1.0,
            "RPR slide s = dot(A - B, u)",
        );
        // PRP: E is o1 = 0.02 left of the crank's line through O, o2 = -0.03
        // left of the vertical through (0.3, 0.05).
        near(cross(dir(q0), p.E.coords), 0.02, CLOSE, 1.0, "PRP offset 1");
        near(
            cross(dir(90f64.to_radians()), p.E - Point2::new(0.3, 0.05)),
            -0.03,
            CLOSE,
            1.0,
            "PRP offset 2",
        );
        // RPP: the yoke translates along y = -0.05, its reference point Q
        // on the line offset -0.01 to the left of that guide (the core's
        // `g.at(s2, offset)`; docs/dsl.md does not say what the offset
        // moves); its slot at -90 deg to the guide passes through Q and
        // holds the block pinned at D.
        let slot = dir(-90f64.to_radians());
        near(
            cross(slot, p.D - p.Q),
            0.0,
            CLOSE,
            1.0,
            "D in the slot through Q",
        );
        near(
            p.Q.y,
            -0.06,
            CLOSE,
            1.0,
            "Q on the offset line of the guide",
        );
        near(
            p.Q.x,
            p.t2,
            CLOSE,
            1.0,
            "t2 = Q's displacement along the guide",
        );
    }
}

/// Forces: gravity from a parameter, a mass without `j` (link3) and one
/// with, loads used in a force and in a torque, a force at the joint A of
/// two links with `on`, a force on the ram with `on`. The power balance
/// computed here from the outputs: the driving torque's power plus the
/// external loads', the weights' and the inertia loads' is zero, to 1e-12
/// of the largest term (the reactions are solved to a few eps over
/// conditions >= 0.3 here; a term dropped or on the wrong point is of the
/// order of the largest). Gravity and the press load changed at run time.
#[test]
fn loaded_press_power_balance() {
    let m = LoadedPress {
        g: 3.7,
        m3: 1.5,
        ..Default::default()
    };
    let loads = LoadedPressLoads {
        press: 40.0,
        t: -6.0,
    };
    for k in 0..36 {
        let q = f64::to_radians(10.0 * k as f64 + 3.0);
        let (w, al) = (9.0, -4.0);
        let i = |x| LoadedPressInput { theta: x };
        let s = m.solve(&i(q), &i(w), &i(al), &loads).unwrap();
        let (p, v, a, f) = (&s.position, &s.velocity, &s.acceleration, &s.forces);
        let grav = Vector2::new(0.0, -3.7);
        let terms = [
            f.drive_theta * w,
            Vector2::new(-40.0, 20.0).dot(&v.B),
            Vector2::new(-6.0, 0.0).dot(&v.A),
            (-6.0 * 0.1 - 40.0 * 0.001) * v.link3,
            (grav * 1.5 - a.G3 * 1.5).dot(&v.G3),
            (grav * 5.0 - a.B * 5.0).dot(&v.B),
            (grav * 0.5 - a.A * 0.5).dot(&v.A) - 0.001 * al * w,
        ];
        let scale = terms.iter().fold(0.0f64, |x, t| x.max(t.abs()));
        let sum: f64 = terms.iter().sum();
        assert!(
            sum.abs() <= 1e-12 * scale,
            "{k}: {sum:e} of {scale:e}: {terms:?}"
        );
        assert!(f.power_residual <= 1e-12, "{k}: {}", f.power_residual);
        // G3 is 0.2 along the rod from A.
        near(d2(p.G3, p.A), 0.2, CLOSE, 1.0, "|G3 - A|");
    }
}

/// DSL words as names: a point `ground`, a ground point `guide`, a crank
/// tip `crank`, a group point `point`, an input `analysis`, links `mass`,
/// `range`, `outputs`. Unicode names with a single-letter lower-case point
/// `a` beside `A`.
#[test]
fn keyword_and_unicode_names_work() {
    let m = KwNames::<f64>::default();
    let u = Unicode::<f64>::default();
    for k in 0..36 {
        let q = f64::to_radians(10.0 * k as f64);
        let p = m.position(&KwNamesInput { analysis: q }).unwrap();
        near(d2(p.crank, p.ground), 1.0, CLOSE, 1.0, "crank");
        near(d2(p.point, p.crank), 3.0, CLOSE, 1.0, "coupler");
        near(d2(p.point, p.guide), 2.5, CLOSE, 1.0, "rocker");
        // `left`: point to the left of crank -> guide.
        assert!(cross(p.guide - p.crank, p.point - p.crank) > 0.0);
        near(
            p.mass,
            q.sin().atan2(q.cos()),
            1e-15,
            1.0,
            "link `mass` = the crank angle",
        );
        let r = u.position(&UnicodeInput { θ: q }).unwrap();
        near_v(r.A - p.point, Vector2::zeros(), 0.0, 1.0, "same four-bar");
        near(
            d2(
                r.a_very_long_name_for_a_coupler_point_that_goes_on_and_on_and_on,
                r.A,
            ),
            1.0,
            CLOSE,
            1.0,
            "long name",
        );
        let v = m.velocity(&p, &KwNamesInput { analysis: 2.0 }).unwrap();
        near(v.mass, 2.0, 0.0, 1.0, "crank rate");
        near(
            v.point.dot(&(p.point - p.crank)),
            v.crank.dot(&(p.point - p.crank)),
            1e-13,
            1.0,
            "rigid coupler",
        );
        let _ = (v.range, v.outputs);
    }
}

/// Two cranks, one read `as cos_sin`: `position_cos_sin` against
/// `position`; f32 and f64 of the same definition in one program; changed
/// parameters; `check()`.
#[test]
fn two_cranks_cos_sin_f32_f64_and_check() {
    let m = TwoCranks {
        base: 0.09,
        ..Default::default()
    };
    let m32 = TwoCranks::<f32> {
        base: 0.09,
        ..Default::default()
    };
    let report = m.check();
    assert!(report.assembles(), "{report:?}");
    for (q1, q2) in [(1.2, 0.3), (2.0, 1.0), (1.6, 0.7)] {
        let a = m.position(&TwoCranksInput { q1, q2 }).unwrap();
        let b = m
            .position_cos_sin(&TwoCranksCosSin {
                q1: mechanism::driver::crank::CosSin {
                    cos: 2.0 * f64::cos(q1),
                    sin: 2.0 * f64::sin(q1),
                },
                q2,
            })
            .unwrap();
        // The normalization and cos/sin roundings: a few ulp of 0.3.
        near_v(
            a.P - b.P,
            Vector2::zeros(),
            1e-16,
            1.0,
            "P by angle vs by cos, sin",
        );
        near(
            d2(a.P, Point2::new(0.09 + 0.1 * q2.cos(), 0.1 * q2.sin())),
            0.16,
            CLOSE,
            1.0,
            "|P - C|",
        );
        let c = m32
            .position(&TwoCranksInput {
                q1: q1 as f32,
                q2: q2 as f32,
            })
            .unwrap();
        // f32: inputs rounded to f32 (6e-8 relative) and f32 arithmetic,
        // amplified by the RRR's 1/condition (>= 0.3 here): 1e-6 of 0.3.
        near(
            (c.P.x as f64 - a.P.x)
                .abs()
                .max((c.P.y as f64 - a.P.y).abs()),
            0.0,
            1e-6,
            1.0,
            "f32 vs f64",
        );
    }
}

/// Output subsets: a slide only at the position level, a link angle only at
/// the velocity level, a ground point only, and no output at all (which did
/// not compile: the structs had no field of type `T`).
#[test]
fn output_subsets() {
    for k in 0..36 {
        let q = f64::to_radians(10.0 * k as f64);
        let x = SlideOnly::<f64>::default()
            .position(&SlideOnlyInput { theta: q })
            .unwrap()
            .x;
        // Slider-crank on the crank's own line: x = r cos q + sqrt(l^2 - r^2 sin^2 q).
        let want = 0.1 * q.cos() + (0.16 - 0.01 * q.sin() * q.sin()).sqrt();
        near(x, want, CLOSE, 1.0, "x");
        let m = AngleOnly::<f64>::default();
        let at = |t: f64| {
            m.position(&AngleOnlyInput { theta: q + 2.0 * t })
                .unwrap()
                .link4
        };
        let v = m
            .velocity(
                &m.position(&AngleOnlyInput { theta: q }).unwrap(),
                &AngleOnlyInput { theta: 2.0 },
            )
            .unwrap();
        rate_fd_s(v.link4, at, "omega4");
        let g = GroundOnly::<f64>::default();
        let p = g.position(&GroundOnlyInput { theta: q }).unwrap();
        assert_eq!((p.O4.x, p.O4.y), (3.0, 0.0));
        let v = g.velocity(&p, &GroundOnlyInput { theta: 1.0 }).unwrap();
        assert_eq!((v.O4.x, v.O4.y), (0.0, 0.0));
        // `outputs { }` with masses: the forces alone, the same numbers (the
        // same operations) as with every output, from smaller structs.
        let (only, all) = (TorqueOnly::<f64>::default(), TorqueAll::<f64>::default());
        let f_only = only
            .solve(
                &TorqueOnlyInput { theta: q },
                &TorqueOnlyInput { theta: 5.0 },
                &TorqueOnlyInput { theta: 1.0 },
            )
            .unwrap()
            .forces;
        let s_all = all
            .solve(
                &TorqueAllInput { theta: q },
                &TorqueAllInput { theta: 5.0 },
                &TorqueAllInput { theta: 1.0 },
            )
            .unwrap();
        assert_eq!(f_only.drive_theta, s_all.forces.drive_theta);
        assert_eq!(f_only.r_ground_link2, s_all.forces.r_ground_link2);
        assert_eq!(f_only.r_ground_slider, s_all.forces.r_ground_slider);
        // The torque balances the loads' power (computed here from the
        // full twin's motion): drive * omega + weights + load + inertia = 0.
        let (p, v, a) = (&s_all.position, &s_all.velocity, &s_all.acceleration);
        let g = mechanism::Vector2::new(0.0, -9.81);
        let power = f_only.drive_theta * 5.0 + (g * 1.2 - a.G3 * 1.2).dot(&v.G3)
            - 0.02 * a.link3 * v.link3
            + (g * 0.5 - a.B * 0.5).dot(&v.B)
            - 40.0 * v.B.x;
        let scale =
            (f_only.drive_theta * 5.0).abs() + 1.2 * 9.81 * v.G3.norm() + 40.0 * v.B.x.abs();
        // A few roundings of terms up to `scale`: 1e-13 of it (450 eps).
        assert!(
            power.abs() <= 1e-13 * scale,
            "power {power:e} of {scale:e} at {q}"
        );
        let _ = p;
        assert!(
            core::mem::size_of::<TorqueOnlyPosition<f64>>()
                < core::mem::size_of::<TorqueAllPosition<f64>>()
        );
    }
}
