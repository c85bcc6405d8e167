//! Hand-derivable configurations (3-4-5 triangles, right angles, dyadic
//! rationals), the error variants with their numbers, `None` = zero motion,
//! and a fuzz test: no input, however wild (NaN, +-inf, 0, negative lengths,
//! 1e300, subnormals), makes any function panic or return a non-finite `Ok`.
//!
//! Tolerances: values that are dyadic rationals computed through exact
//! operations are compared with `==`. Others (1.8 = 3 * 3 / 5, ...) are not
//! representable, and each takes a few roundings: they are compared to within
//! 2 units in the last place (`ULPS`), the level of a single correctly rounded
//! operation or two, far below any formula error.

use approx::assert_ulps_eq;
use mechanism_core::driver::{actuator, crank, slider};
use mechanism_core::dyad::{prp, rpp, rpr, rrp, rrr};
use mechanism_core::guide::{Line, LineAcceleration, LineVelocity};
use mechanism_core::{link, Error, Fault, Mode, Point2, Primitive, Real, Vector2};
use proptest::prelude::*;

const ULPS: u32 = 2;

fn p(x: f64, y: f64) -> Point2<f64> {
    Point2::new(x, y)
}
fn v(x: f64, y: f64) -> Vector2<f64> {
    Vector2::new(x, y)
}
fn line(ox: f64, oy: f64, dx: f64, dy: f64) -> Line<f64> {
    Line {
        origin: p(ox, oy),
        dir: v(dx, dy),
    }
}

fn assert_vec(got: Vector2<f64>, want: Vector2<f64>) {
    assert_ulps_eq!(got.x, want.x, max_ulps = ULPS);
    assert_ulps_eq!(got.y, want.y, max_ulps = ULPS);
}

fn fault<T>(r: Result<T, Error>, primitive: Primitive) -> Fault {
    match r {
        Ok(_) => panic!("expected an error from {primitive:?}"),
        Err(e) => {
            assert_eq!(e.primitive, primitive);
            assert_eq!(e.group, "");
            e.fault
        }
    }
}

// ------------------------------------------------------- exact values --

#[test]
fn rrr_three_four_five() {
    // A=(0,0), B=(5,0), l1=3, l2=4: C=(1.8, +-2.4); right angle at C.
    let (a, b) = (p(0.0, 0.0), p(5.0, 0.0));
    let pos = rrr::position(&a, 3.0, &b, 4.0, Mode::Plus).unwrap();
    assert_vec(pos.c.coords, v(1.8, 2.4));
    let minus = rrr::position(&a, 3.0, &b, 4.0, Mode::Minus).unwrap();
    assert_vec(minus.c.coords, v(1.8, -2.4));
    // vB = (0, 1): det = cross(r1, r2) = 12, omega1 = dot(vB, r2)/12 = 0.2,
    // omega2 = dot(vB, r1)/12 = 0.2, vC = 0.2 perp(r1) = (-0.48, 0.36).
    let vel = rrr::velocity(&pos, None, Some(&v(0.0, 1.0))).unwrap();
    assert_ulps_eq!(vel.omega1, 0.2, max_ulps = ULPS);
    assert_ulps_eq!(vel.omega2, 0.2, max_ulps = ULPS);
    assert_vec(vel.vc, v(-0.48, 0.36));
    // aB = 0: w = 0.04 (r1 - r2) = 0.04 (5, 0) = (0.2, 0); alpha1 = dot(w, r2)/12
    // = -0.64/12, alpha2 = dot(w, r1)/12 = 0.36/12 = 0.03.
    let acc = rrr::acceleration(&pos, &vel, None, None).unwrap();
    assert_ulps_eq!(acc.alpha1, -0.64 / 12.0, max_ulps = ULPS);
    assert_ulps_eq!(acc.alpha2, 0.03, max_ulps = ULPS);
}

#[test]
fn rrp_three_four_five() {
    // Guide: origin (1, 0), along +x, offset 3: C travels on y = 3.
    // A = (0, 0), l = 5: distance 3 from the line, half chord 4.
    let g = line(1.0, 0.0, 1.0, 0.0);
    let a = p(0.0, 0.0);
    let pos = rrp::position(&a, 5.0, &g, 3.0, Mode::Plus).unwrap();
    assert_eq!(pos.c, p(4.0, 3.0));
    assert_eq!(pos.r1, v(4.0, 3.0));
    assert_eq!(pos.s, 3.0);
    let minus = rrp::position(&a, 5.0, &g, 3.0, Mode::Minus).unwrap();
    assert_eq!(minus.c, p(-4.0, 3.0));
    assert_eq!(minus.s, -5.0);
    // vA = (0, 1): w = -vA; omega1 = cross(dir, w)/4 = -1/4,
    // s_dot = -dot(w, r1)/4 = 3/4; vC = vA + omega1 perp(r1) = (3/4, 0).
    let va = v(0.0, 1.0);
    let vel = rrp::velocity(&pos, &g, Some(&va), None).unwrap();
    assert_eq!(vel.omega1, -0.25);
    assert_eq!(vel.s_dot, 0.75);
    assert_eq!(vel.vc, v(0.75, 0.0));
    // aA = 0: w = omega1^2 r1 = (1/4, 3/16); alpha1 = cross(dir, w)/4 = 3/64,
    // s_ddot = -dot(w, r1)/4 = -25/64; aC = (-25/64, 0).
    let acc = rrp::acceleration(&pos, &g, &vel, None, None, None).unwrap();
    assert_eq!(acc.alpha1, 3.0 / 64.0);
    assert_eq!(acc.s_ddot, -25.0 / 64.0);
    assert_eq!(acc.ac, v(-25.0 / 64.0, 0.0));
}

#[test]
fn rrp_on_a_spinning_guide() {
    // The same pose, A fixed, the guide's body spinning at omega = 1 about its
    // origin (1, 0) (no angular acceleration). Material velocity at C = (4, 3):
    // perp(C - O) = perp(3, 3) = (-3, 3); w = (-3, 3): omega1 = 3/4,
    // s_dot = -dot(w, r1)/4 = -(-12 + 9)/4 = 3/4; vC = 3/4 perp(4, 3) = (-9/4, 3).
    let g = line(1.0, 0.0, 1.0, 0.0);
    let pos = rrp::position(&p(0.0, 0.0), 5.0, &g, 3.0, Mode::Plus).unwrap();
    let gv = LineVelocity {
        v_origin: v(0.0, 0.0),
        omega: 1.0,
    };
    let vel = rrp::velocity(&pos, &g, None, Some(&gv)).unwrap();
    assert_eq!(vel.omega1, 0.75);
    assert_eq!(vel.s_dot, 0.75);
    assert_eq!(vel.vc, v(-2.25, 3.0));
    // a_body(C) = -(C - O) = (-3, -3); Coriolis 2 * 1 * 3/4 * (0, 1) = (0, 3/2);
    // w = (-3, -3/2) + (9/16)(4, 3) = (-3/4, 3/16): alpha1 = 3/64,
    // s_ddot = -dot(w, r1)/4 = -(-3 + 9/16)/4 = 39/64; aC = (-9/4 - 9/64 + ..)
    let acc = rrp::acceleration(&pos, &g, &vel, None, Some(&gv), None).unwrap();
    assert_eq!(acc.alpha1, 3.0 / 64.0);
    assert_eq!(acc.s_ddot, 39.0 / 64.0);
    // aC = alpha1 perp(r1) - omega1^2 r1 = (3/64)(-3, 4) - (9/16)(4, 3).
    assert_eq!(acc.ac, v(-9.0 / 64.0 - 2.25, 12.0 / 64.0 - 27.0 / 16.0));
}

#[test]
fn rpr_three_four_five() {
    // B = (0, 0), A = (4, 3), offset 3: |A - B| = 5, s = 4, u = (1, 0).
    let (a, b) = (p(4.0, 3.0), p(0.0, 0.0));
    let pos = rpr::position(&a, &b, 3.0, Mode::Plus).unwrap();
    assert_eq!(pos.axis, v(1.0, 0.0));
    assert_eq!(pos.s, 4.0);
    // Minus: s = -4, u = (-7, -24) / 25.
    let minus = rpr::position(&a, &b, 3.0, Mode::Minus).unwrap();
    assert_eq!(minus.s, -4.0);
    assert_vec(minus.axis, v(-0.28, -0.96));
    // vA = (0, 1): omega = cross(u, vA)/4 = 1/4, s_dot = dot(vA, p)/4 = 3/4.
    let vel = rpr::velocity(&pos, &a, &b, Some(&v(0.0, 1.0)), None).unwrap();
    assert_eq!(vel.omega, 0.25);
    assert_eq!(vel.s_dot, 0.75);
    // aA = 0: w = omega^2 p - 2 omega s_dot perp(u) = (1/4, 3/16 - 3/8);
    // alpha = cross(u, w)/4 = -3/64, s_ddot = dot(w, p)/4 = (1 - 9/16)/4 = 7/64.
    let acc = rpr::acceleration(&pos, &a, &b, &vel, None, None).unwrap();
    assert_eq!(acc.alpha, -3.0 / 64.0);
    assert_eq!(acc.s_ddot, 7.0 / 64.0);
}

#[test]
fn rpr_without_offset_points_at_the_block() {
    let pos = rpr::position(&p(3.0, 4.0), &p(0.0, 0.0), 0.0, Mode::Plus).unwrap();
    assert_vec(pos.axis, v(0.6, 0.8));
    assert_eq!(pos.s, 5.0);
    let minus = rpr::position(&p(3.0, 4.0), &p(0.0, 0.0), 0.0, Mode::Minus).unwrap();
    assert_vec(minus.axis, v(-0.6, -0.8));
    assert_eq!(minus.s, -5.0);
}

#[test]
fn prp_right_angle() {
    // g1: through (0, 0) along +x, offset 2 (line y = 2); g2: through (3, -1)
    // along +y, offset 1 (left of +y is -x: line x = 2). C = (2, 2), s1 = 2, s2 = 3.
    let g1 = line(0.0, 0.0, 1.0, 0.0);
    let g2 = line(3.0, -1.0, 0.0, 1.0);
    let pos = prp::position(&g1, 2.0, &g2, 1.0).unwrap();
    assert_eq!(pos.c, p(2.0, 2.0));
    assert_eq!((pos.s1, pos.s2), (2.0, 3.0));
    // g1 spins at 1/2 about (0, 0); g2 translates at (1, 0).
    // v_body1(C) = 0.5 perp(2, 2) = (-1, 1); w = (1, 0) - (-1, 1) = (2, -1):
    // s1_dot = cross(w, dir2) = 2, s2_dot = cross(w, dir1) = 1, vC = (1, 1).
    let gv1 = LineVelocity {
        v_origin: v(0.0, 0.0),
        omega: 0.5,
    };
    let gv2 = LineVelocity {
        v_origin: v(1.0, 0.0),
        omega: 0.0,
    };
    let vel = prp::velocity(&pos, &g1, &g2, Some(&gv1), Some(&gv2)).unwrap();
    assert_eq!((vel.s1_dot, vel.s2_dot), (2.0, 1.0));
    assert_eq!(vel.vc, v(1.0, 1.0));
    // a_body1(C) + Coriolis1 = -(1/4)(2, 2) + 2 (1/2) 2 (0, 1) = (-1/2, 3/2);
    // body 2: zero. w = (1/2, -3/2): s1_ddot = 1/2, s2_ddot = 3/2, aC = (0, 3/2).
    let acc = prp::acceleration(&pos, &g1, &g2, &vel, Some(&gv1), None, Some(&gv2), None).unwrap();
    assert_eq!((acc.s1_ddot, acc.s2_ddot), (0.5, 1.5));
    assert_eq!(acc.ac, v(0.0, 1.5));
}

#[test]
fn rpp_scotch_yoke() {
    // Crank pin A = 5 (0.6, 0.8) = (3, 4); yoke translating along the y axis,
    // slot horizontal: w = (1, 0) = -perp(dir), so slot_dir_local = (0, -1).
    let g = line(0.0, 0.0, 0.0, 1.0);
    let a = p(3.0, 4.0);
    let pos = rpp::position(&a, &g, 0.0, &v(0.0, -1.0)).unwrap();
    assert_eq!(pos.q, p(0.0, 4.0));
    assert_eq!(pos.slot, v(1.0, 0.0));
    assert_eq!((pos.s1, pos.s2), (3.0, 4.0));
    // Crank at 1 rad/s: vA = perp(3, 4) = (-4, 3): the yoke moves at
    // 5 cos(theta) = 3, the block slides at -4.
    let vel = rpp::velocity(&pos, &a, &g, Some(&v(-4.0, 3.0)), None).unwrap();
    assert_eq!((vel.s1_dot, vel.s2_dot), (-4.0, 3.0));
    assert_eq!(vel.vq, v(0.0, 3.0));
    // aA = -(3, 4): the yoke accelerates at -5 sin(theta) = -4.
    let acc = rpp::acceleration(&pos, &a, &g, &vel, Some(&v(-3.0, -4.0)), None, None).unwrap();
    assert_eq!((acc.s1_ddot, acc.s2_ddot), (-3.0, -4.0));
    assert_eq!(acc.aq, v(0.0, -4.0));
}

#[test]
fn slider_on_a_spinning_guide() {
    // Guide through (1, 2) along +y, offset 3 (to -x): P = (1 - 3, 2 + s).
    let g = line(1.0, 2.0, 0.0, 1.0);
    let pos = slider::position(&g, 3.0, 4.0).unwrap();
    assert_eq!(pos.p, p(-2.0, 6.0));
    // Body spinning at 1 about (1, 2): v_body(P) = perp(-3, 4) = (-4, -3);
    // plus s_dot dir = (0, 2).
    let gv = LineVelocity {
        v_origin: v(0.0, 0.0),
        omega: 1.0,
    };
    assert_eq!(
        slider::velocity(&pos, &g, 4.0, 2.0, Some(&gv)).unwrap(),
        v(-4.0, -1.0)
    );
    // a_body(P) = -(-3, 4); Coriolis 2 * 1 * 2 * perp(0, 1) = (-4, 0); s_ddot dir = (0, 1).
    assert_eq!(
        slider::acceleration(&pos, &g, 4.0, 2.0, 1.0, Some(&gv), None).unwrap(),
        v(-1.0, -3.0)
    );
}

#[test]
fn actuator_three_four_five() {
    // A = (0, 0), l = 3, B = (5, 0), L = 4: C = (1.8, 2.4), right angle at C.
    let (a, b) = (p(0.0, 0.0), p(5.0, 0.0));
    let pos = actuator::position(&a, 3.0, &b, 4.0, Mode::Plus).unwrap();
    assert_vec(pos.c.coords, v(1.8, 2.4));
    // Extending at 1 L/s along e2 = (-0.8, 0.6), perpendicular to link 1:
    // link 1 turns at 1/3 rad/s, the cylinder does not turn.
    let vel = actuator::velocity(&pos, None, None, 1.0).unwrap();
    assert_ulps_eq!(vel.omega1, 1.0 / 3.0, max_ulps = ULPS);
    assert!(vel.omega2.abs() <= 4.0 * f64::EPSILON);
    assert_vec(vel.vc, v(-0.8, 0.6));
    // Steady extension: aC = -omega1^2 r1 (link 1's centripetal), which the
    // cylinder supplies by turning: alpha2 = 1/12, alpha1 = 0.
    let acc = actuator::acceleration(&pos, &vel, None, None, 1.0, 0.0).unwrap();
    assert!(acc.alpha1.abs() <= 4.0 * f64::EPSILON);
    assert_ulps_eq!(acc.alpha2, 1.0 / 12.0, max_ulps = ULPS);
    assert_vec(acc.ac, v(-0.2, -2.4 / 9.0));
}

#[test]
fn crank_and_link_point_right_angles() {
    let pos = crank::position_cos_sin(&p(1.0, 1.0), 5.0, 0.6, 0.8).unwrap();
    assert_vec(pos.tip.coords, v(4.0, 5.0));
    let vt = crank::velocity(&pos, None, 2.0).unwrap();
    assert_vec(vt, v(-8.0, 6.0));
    let at = crank::acceleration(&pos, None, 2.0, 0.0).unwrap();
    assert_vec(at, v(-12.0, -16.0));
    // A point 3 along and 4 across a link whose axis is +y: offset (-4, 3).
    let q = link::point_position(&p(0.0, 0.0), &v(0.0, 1.0), &v(3.0, 4.0)).unwrap();
    assert_eq!(q, p(-4.0, 3.0));
    assert_eq!(link::point_velocity(&q.coords, 1.0).unwrap(), v(-3.0, -4.0));
}

// ------------------------------------------------------------- errors --

#[test]
fn cannot_assemble_reports_the_miss() {
    // RRR: |AB| = 10 > 3 + 4: miss 3, reach 7; |AB| = 0.5 < 4 - 3: miss 0.5, reach 1.
    let f = fault(
        rrr::position(&p(0.0, 0.0), 3.0, &p(10.0, 0.0), 4.0, Mode::Plus),
        Primitive::Rrr,
    );
    assert_eq!(
        f,
        Fault::CannotAssemble {
            miss: 3.0,
            reach: 7.0
        }
    );
    let f = fault(
        rrr::position(&p(0.0, 0.0), 3.0, &p(0.5, 0.0), 4.0, Mode::Minus),
        Primitive::Rrr,
    );
    assert_eq!(
        f,
        Fault::CannotAssemble {
            miss: 0.5,
            reach: 1.0
        }
    );
    // RRP: A 3 away from the line y = 3, l = 2: miss 1, reach 2.
    let g = line(1.0, 0.0, 1.0, 0.0);
    let f = fault(
        rrp::position(&p(0.0, 0.0), 2.0, &g, 3.0, Mode::Plus),
        Primitive::Rrp,
    );
    assert_eq!(
        f,
        Fault::CannotAssemble {
            miss: 1.0,
            reach: 2.0
        }
    );
    // RPR: |A - B| = 2 < offset 3: miss 1, reach 3.
    let f = fault(
        rpr::position(&p(2.0, 0.0), &p(0.0, 0.0), -3.0, Mode::Plus),
        Primitive::Rpr,
    );
    assert_eq!(
        f,
        Fault::CannotAssemble {
            miss: 1.0,
            reach: 3.0
        }
    );
    // Actuator: as RRR, attributed to the actuator.
    let f = fault(
        actuator::position(&p(0.0, 0.0), 3.0, &p(10.0, 0.0), 4.0, Mode::Plus),
        Primitive::Actuator,
    );
    assert_eq!(
        f,
        Fault::CannotAssemble {
            miss: 3.0,
            reach: 7.0
        }
    );
}

#[test]
fn tangent_positions_assemble_but_their_rates_are_singular() {
    // RRP with l = 3 exactly the distance: C at the foot (0, 3), det = 0.
    let g = line(1.0, 0.0, 1.0, 0.0);
    let pos = rrp::position(&p(0.0, 0.0), 3.0, &g, 3.0, Mode::Plus).unwrap();
    assert_eq!(pos.c, p(0.0, 3.0));
    assert_eq!(pos.s, -1.0);
    let f = fault(rrp::velocity(&pos, &g, None, None), Primitive::Rrp);
    assert_eq!(
        f,
        Fault::Singular {
            det: 0.0,
            scale: 3.0
        }
    );
    // RPR with |A - B| = offset: s = 0, the block sits at the foot.
    let (a, b) = (p(0.0, 3.0), p(0.0, 0.0));
    let pos = rpr::position(&a, &b, 3.0, Mode::Plus).unwrap();
    assert_eq!(pos.s, 0.0);
    assert_eq!(pos.axis, v(1.0, 0.0));
    let f = fault(rpr::velocity(&pos, &a, &b, None, None), Primitive::Rpr);
    assert_eq!(
        f,
        Fault::Singular {
            det: 0.0,
            scale: 3.0
        }
    );
    // RRR / actuator at full stretch: C on the line, det = 0.
    let pos = actuator::position(&p(0.0, 0.0), 3.0, &p(7.0, 0.0), 4.0, Mode::Plus).unwrap();
    // On the line exactly (zero height, so det = 0 below); along it within an
    // ulp of 3: `rrr::position` multiplies by a rounded `1 / (2 |d|^2)`.
    assert_eq!(pos.c.y, 0.0);
    assert!((pos.c.x - 3.0).abs() <= 3.0 * f64::EPSILON, "{}", pos.c.x);
    let f = fault(
        actuator::velocity(&pos, None, None, 1.0),
        Primitive::Actuator,
    );
    // |r1| |r2| = 3 x 4, each within an ulp (above).
    assert!(
        matches!(f, Fault::Singular { det, scale } if det == 0.0 && (scale - 12.0).abs() <= 24.0 * f64::EPSILON),
        "{f:?}"
    );
}

#[test]
fn singular_geometry_is_reported() {
    // RRR with A = B.
    let f = fault(
        rrr::position(&p(1.0, 1.0), 3.0, &p(1.0, 1.0), 3.0, Mode::Plus),
        Primitive::Rrr,
    );
    assert!(matches!(f, Fault::Singular { .. }));
    // RPR with A = B and no offset.
    let f = fault(
        rpr::position(&p(1.0, 1.0), &p(1.0, 1.0), 0.0, Mode::Plus),
        Primitive::Rpr,
    );
    assert!(matches!(f, Fault::Singular { det, .. } if det == 0.0));
    // PRP with parallel (here anti-parallel) guides.
    let f = fault(
        prp::position(
            &line(0.0, 0.0, 1.0, 0.0),
            0.0,
            &line(0.0, 1.0, -1.0, 0.0),
            0.0,
        ),
        Primitive::Prp,
    );
    assert_eq!(
        f,
        Fault::Singular {
            det: 0.0,
            scale: 1.0
        }
    );
    // RPP with the slot along the guide (beta = 0).
    let f = fault(
        rpp::position(&p(1.0, 1.0), &line(0.0, 0.0, 1.0, 0.0), 0.0, &v(1.0, 0.0)),
        Primitive::Rpp,
    );
    assert_eq!(
        f,
        Fault::Singular {
            det: 0.0,
            scale: 1.0
        }
    );
}

#[test]
fn bad_inputs_are_typed() {
    let g = line(0.0, 0.0, 1.0, 0.0);
    let a = p(0.0, 1.0);
    for l in [0.0, -1.0] {
        let f = fault(rrp::position(&a, l, &g, 0.0, Mode::Plus), Primitive::Rrp);
        assert!(matches!(f, Fault::NonPositive { value, .. } if value == l));
        let f = fault(
            actuator::position(&a, 1.0, &p(1.0, 1.0), l, Mode::Plus),
            Primitive::Actuator,
        );
        assert!(matches!(f, Fault::NonPositive { value, .. } if value == l));
    }
    let nan = f64::NAN;
    assert!(matches!(
        fault(
            rrp::position(&p(nan, 0.0), 1.0, &g, 0.0, Mode::Plus),
            Primitive::Rrp
        ),
        Fault::NonFinite { .. }
    ));
    assert!(matches!(
        fault(
            rpr::position(&a, &p(0.0, 0.0), nan, Mode::Plus),
            Primitive::Rpr
        ),
        Fault::NonFinite { .. }
    ));
    assert!(matches!(
        fault(
            prp::position(&g, 0.0, &line(0.0, 0.0, 0.0, f64::INFINITY), 0.0),
            Primitive::Prp
        ),
        Fault::NonFinite { .. }
    ));
    assert!(matches!(
        fault(rpp::position(&a, &g, 0.0, &v(nan, 1.0)), Primitive::Rpp),
        Fault::NonFinite { .. }
    ));
    assert!(matches!(
        fault(slider::position(&g, 0.0, f64::INFINITY), Primitive::Slider),
        Fault::NonFinite { .. }
    ));
    let pos = slider::position(&g, 0.0, 1.0).unwrap();
    assert!(matches!(
        fault(
            slider::velocity(&pos, &g, 1.0, nan, None),
            Primitive::Slider
        ),
        Fault::NonFinite { .. }
    ));
    let pos = actuator::position(&p(0.0, 0.0), 3.0, &p(5.0, 0.0), 4.0, Mode::Plus).unwrap();
    assert!(matches!(
        fault(
            actuator::velocity(&pos, None, None, nan),
            Primitive::Actuator
        ),
        Fault::NonFinite { .. }
    ));
}

// ------------------------------------------- None is zero motion, exactly --

#[test]
fn none_means_zero_motion() {
    let z = v(0.0, 0.0);
    let gz = LineVelocity {
        v_origin: z,
        omega: 0.0,
    };
    let az = LineAcceleration {
        a_origin: z,
        alpha: 0.0,
    };
    let g = line(0.5, -0.25, 0.6, 0.8);
    let g2 = line(-1.0, 2.0, -0.8, 0.6);
    let (a, b) = (p(0.3, 1.7), p(2.1, -0.4));
    let va = v(0.7, -0.2);

    let pos = rrp::position(&a, 2.0, &g, 0.3, Mode::Minus).unwrap();
    let v1 = rrp::velocity(&pos, &g, Some(&va), None).unwrap();
    assert_eq!(v1, rrp::velocity(&pos, &g, Some(&va), Some(&gz)).unwrap());
    let a1 = rrp::acceleration(&pos, &g, &v1, None, None, None).unwrap();
    assert_eq!(
        a1,
        rrp::acceleration(&pos, &g, &v1, Some(&z), Some(&gz), Some(&az)).unwrap()
    );
    assert_eq!(
        a1,
        rrp::acceleration(&pos, &g, &v1, None, None, Some(&az)).unwrap()
    );

    let pos = rpr::position(&a, &b, 0.4, Mode::Plus).unwrap();
    let v1 = rpr::velocity(&pos, &a, &b, Some(&va), None).unwrap();
    assert_eq!(
        v1,
        rpr::velocity(&pos, &a, &b, Some(&va), Some(&z)).unwrap()
    );
    let a1 = rpr::acceleration(&pos, &a, &b, &v1, None, None).unwrap();
    assert_eq!(
        a1,
        rpr::acceleration(&pos, &a, &b, &v1, Some(&z), Some(&z)).unwrap()
    );

    let gv = LineVelocity {
        v_origin: va,
        omega: 0.5,
    };
    let pos = prp::position(&g, 0.1, &g2, -0.2).unwrap();
    let v1 = prp::velocity(&pos, &g, &g2, Some(&gv), None).unwrap();
    assert_eq!(
        v1,
        prp::velocity(&pos, &g, &g2, Some(&gv), Some(&gz)).unwrap()
    );
    let a1 = prp::acceleration(&pos, &g, &g2, &v1, Some(&gv), None, None, None).unwrap();
    assert_eq!(
        a1,
        prp::acceleration(
            &pos,
            &g,
            &g2,
            &v1,
            Some(&gv),
            Some(&az),
            Some(&gz),
            Some(&az)
        )
        .unwrap()
    );

    let local = v(0.0, 1.0);
    let pos = rpp::position(&a, &g, 0.2, &local).unwrap();
    let v1 = rpp::velocity(&pos, &a, &g, Some(&va), None).unwrap();
    assert_eq!(
        v1,
        rpp::velocity(&pos, &a, &g, Some(&va), Some(&gz)).unwrap()
    );
    let a1 = rpp::acceleration(&pos, &a, &g, &v1, None, None, None).unwrap();
    assert_eq!(
        a1,
        rpp::acceleration(&pos, &a, &g, &v1, Some(&z), Some(&gz), Some(&az)).unwrap()
    );

    let pos = slider::position(&g, 0.2, 1.5).unwrap();
    let v1 = slider::velocity(&pos, &g, 1.5, 0.3, None).unwrap();
    assert_eq!(v1, slider::velocity(&pos, &g, 1.5, 0.3, Some(&gz)).unwrap());
    let a1 = slider::acceleration(&pos, &g, 1.5, 0.3, -0.1, None, None).unwrap();
    assert_eq!(
        a1,
        slider::acceleration(&pos, &g, 1.5, 0.3, -0.1, Some(&gz), Some(&az)).unwrap()
    );

    let pos = actuator::position(&a, 1.5, &b, 2.0, Mode::Minus).unwrap();
    let v1 = actuator::velocity(&pos, None, Some(&va), 0.3).unwrap();
    assert_eq!(
        v1,
        actuator::velocity(&pos, Some(&z), Some(&va), 0.3).unwrap()
    );
    let a1 = actuator::acceleration(&pos, &v1, None, None, 0.3, 0.1).unwrap();
    assert_eq!(
        a1,
        actuator::acceleration(&pos, &v1, Some(&z), Some(&z), 0.3, 0.1).unwrap()
    );
}

// --------------------------------------------------------------- fuzz --

/// Values that break naive code, mixed with ordinary ones (so that some
/// positions assemble and their rates get exercised too).
fn wild() -> impl Strategy<Value = f64> {
    prop_oneof![
        6 => -3.0..3.0f64,
        1 => Just(0.0),
        1 => Just(-0.0),
        1 => Just(1.0),
        1 => Just(-1.0),
        1 => Just(f64::NAN),
        1 => Just(f64::INFINITY),
        1 => Just(f64::NEG_INFINITY),
        1 => Just(1e300),
        1 => Just(-1e300),
        1 => Just(1e-300),
        1 => Just(5e-324),
        1 => Just(f64::MAX),
        1 => Just(1e20),
        1 => Just(3e38),
        1 => Just(1e-40),
    ]
}

/// Draws inputs from a pool of wild values, cycling.
struct Pool<'a> {
    vals: &'a [f64],
    bits: u64,
    i: usize,
}

impl Pool<'_> {
    fn bit(&mut self) -> bool {
        self.i += 1;
        (self.bits >> (self.i % 64)) & 1 == 1
    }
    fn x<T: Real>(&mut self) -> T {
        self.i += 1;
        T::lit(self.vals[self.i % self.vals.len()])
    }
    fn vec<T: Real>(&mut self) -> Vector2<T> {
        Vector2::new(self.x(), self.x())
    }
    fn pt<T: Real>(&mut self) -> Point2<T> {
        Point2::from(self.vec::<T>())
    }
    fn opt<T: Real>(&mut self) -> Option<Vector2<T>> {
        self.bit().then(|| self.vec())
    }
    fn mode(&mut self) -> Mode {
        if self.bit() {
            Mode::Plus
        } else {
            Mode::Minus
        }
    }
    /// A direction: usually a unit vector (from a wild angle), sometimes wild.
    fn dir<T: Real>(&mut self) -> Vector2<T> {
        if self.bit() || self.bit() {
            let a: T = self.x();
            Vector2::new(a.cos(), a.sin())
        } else {
            self.vec()
        }
    }
    fn line<T: Real>(&mut self) -> Line<T> {
        Line {
            origin: self.pt(),
            dir: self.dir(),
        }
    }
    fn gv<T: Real>(&mut self) -> Option<LineVelocity<T>> {
        self.bit().then(|| LineVelocity {
            v_origin: self.vec(),
            omega: self.x(),
        })
    }
    fn ga<T: Real>(&mut self) -> Option<LineAcceleration<T>> {
        self.bit().then(|| LineAcceleration {
            a_origin: self.vec(),
            alpha: self.x(),
        })
    }
}

fn all_finite<T: Real>(xs: &[T]) -> bool {
    xs.iter().all(|x| x.finite())
}

macro_rules! ensure_finite {
    ($what:expr, $result:expr, |$o:ident| $fields:expr) => {
        if let Ok($o) = &$result {
            let fields = $fields;
            prop_assert!(all_finite(&fields), "{}: non-finite Ok {:?}", $what, $o);
        }
    };
}

/// Calls every position/velocity/acceleration function with wild inputs; the
/// rates are fed both the position just computed (when it succeeded) and a
/// wild position struct built directly.
fn fuzz<T: Real + core::fmt::Debug>(pool: &mut Pool) -> Result<(), TestCaseError> {
    // RRR
    let pos = rrr::position(&pool.pt::<T>(), pool.x(), &pool.pt(), pool.x(), pool.mode());
    ensure_finite!("rrr position", pos, |o| [
        o.c.x, o.c.y, o.r1.x, o.r1.y, o.r2.x, o.r2.y, o.det
    ]);

    // RRP
    let g = pool.line::<T>();
    let pos = rrp::position(&pool.pt::<T>(), pool.x(), &g, pool.x(), pool.mode());
    ensure_finite!("rrp position", pos, |o| [o.c.x, o.c.y, o.r1.x, o.r1.y, o.s]);
    let wild_pos = rrp::RrpPosition {
        c: pool.pt(),
        r1: pool.vec(),
        s: pool.x(),
        l: pool.x(),
    };
    for p in [pos.ok(), Some(wild_pos)].into_iter().flatten() {
        let (va, gv) = (pool.opt::<T>(), pool.gv::<T>());
        let vel = rrp::velocity(&p, &g, va.as_ref(), gv.as_ref());
        ensure_finite!("rrp velocity", vel, |o| [o.omega1, o.s_dot, o.vc.x, o.vc.y]);
        let wild_vel = rrp::RrpVelocity {
            omega1: pool.x(),
            s_dot: pool.x(),
            vc: pool.vec(),
            condition: pool.x(),
        };
        for v in [vel.ok(), Some(wild_vel)].into_iter().flatten() {
            let (aa, ga) = (pool.opt::<T>(), pool.ga::<T>());
            let acc = rrp::acceleration(&p, &g, &v, aa.as_ref(), gv.as_ref(), ga.as_ref());
            ensure_finite!("rrp acceleration", acc, |o| [
                o.alpha1, o.s_ddot, o.ac.x, o.ac.y
            ]);
        }
    }

    // RPR
    let (a, b) = (pool.pt::<T>(), pool.pt::<T>());
    let pos = rpr::position(&a, &b, pool.x(), pool.mode());
    ensure_finite!("rpr position", pos, |o| [o.axis.x, o.axis.y, o.s]);
    let wild_pos = rpr::RprPosition {
        axis: pool.dir(),
        s: pool.x(),
        dist: pool.x(),
    };
    for p in [pos.ok(), Some(wild_pos)].into_iter().flatten() {
        let (va, vb) = (pool.opt::<T>(), pool.opt::<T>());
        let vel = rpr::velocity(&p, &a, &b, va.as_ref(), vb.as_ref());
        ensure_finite!("rpr velocity", vel, |o| [o.omega, o.s_dot]);
        let wild_vel = rpr::RprVelocity {
            omega: pool.x(),
            s_dot: pool.x(),
            condition: pool.x(),
        };
        for v in [vel.ok(), Some(wild_vel)].into_iter().flatten() {
            let (aa, ab) = (pool.opt::<T>(), pool.opt::<T>());
            let acc = rpr::acceleration(&p, &a, &b, &v, aa.as_ref(), ab.as_ref());
            ensure_finite!("rpr acceleration", acc, |o| [o.alpha, o.s_ddot]);
        }
    }

    // PRP
    let (g1, g2) = (pool.line::<T>(), pool.line::<T>());
    let pos = prp::position(&g1, pool.x(), &g2, pool.x());
    ensure_finite!("prp position", pos, |o| [o.c.x, o.c.y, o.s1, o.s2]);
    let wild_pos = prp::PrpPosition {
        c: pool.pt(),
        s1: pool.x(),
        s2: pool.x(),
    };
    for p in [pos.ok(), Some(wild_pos)].into_iter().flatten() {
        let (gv1, gv2) = (pool.gv::<T>(), pool.gv::<T>());
        let vel = prp::velocity(&p, &g1, &g2, gv1.as_ref(), gv2.as_ref());
        ensure_finite!("prp velocity", vel, |o| [
            o.s1_dot, o.s2_dot, o.vc.x, o.vc.y
        ]);
        let wild_vel = prp::PrpVelocity {
            s1_dot: pool.x(),
            s2_dot: pool.x(),
            vc: pool.vec(),
            condition: pool.x(),
        };
        for v in [vel.ok(), Some(wild_vel)].into_iter().flatten() {
            let (ga1, ga2) = (pool.ga::<T>(), pool.ga::<T>());
            let acc = prp::acceleration(
                &p,
                &g1,
                &g2,
                &v,
                gv1.as_ref(),
                ga1.as_ref(),
                gv2.as_ref(),
                ga2.as_ref(),
            );
            ensure_finite!("prp acceleration", acc, |o| [
                o.s1_ddot, o.s2_ddot, o.ac.x, o.ac.y
            ]);
        }
    }

    // RPP
    let (a, g) = (pool.pt::<T>(), pool.line::<T>());
    let pos = rpp::position(&a, &g, pool.x(), &pool.dir());
    ensure_finite!("rpp position", pos, |o| [
        o.q.x, o.q.y, o.slot.x, o.slot.y, o.s1, o.s2
    ]);
    let wild_pos = rpp::RppPosition {
        q: pool.pt(),
        slot: pool.dir(),
        s1: pool.x(),
        s2: pool.x(),
    };
    for p in [pos.ok(), Some(wild_pos)].into_iter().flatten() {
        let (va, gv) = (pool.opt::<T>(), pool.gv::<T>());
        let vel = rpp::velocity(&p, &a, &g, va.as_ref(), gv.as_ref());
        ensure_finite!("rpp velocity", vel, |o| [
            o.s1_dot, o.s2_dot, o.vq.x, o.vq.y
        ]);
        let wild_vel = rpp::RppVelocity {
            s1_dot: pool.x(),
            s2_dot: pool.x(),
            vq: pool.vec(),
            condition: pool.x(),
        };
        for v in [vel.ok(), Some(wild_vel)].into_iter().flatten() {
            let (aa, ga) = (pool.opt::<T>(), pool.ga::<T>());
            let acc = rpp::acceleration(&p, &a, &g, &v, aa.as_ref(), gv.as_ref(), ga.as_ref());
            ensure_finite!("rpp acceleration", acc, |o| [
                o.s1_ddot, o.s2_ddot, o.aq.x, o.aq.y
            ]);
        }
    }

    // Crank
    let pos = crank::position(&pool.pt::<T>(), pool.x(), pool.x());
    ensure_finite!("crank position", pos, |o| [
        o.tip.x, o.tip.y, o.r.x, o.r.y, o.axis.x, o.axis.y
    ]);
    let pos2 = crank::position_cos_sin(&pool.pt::<T>(), pool.x(), pool.x(), pool.x());
    ensure_finite!("crank position_cos_sin", pos2, |o| [
        o.tip.x, o.tip.y, o.r.x, o.r.y, o.axis.x, o.axis.y
    ]);
    let wild_pos = crank::CrankPosition {
        tip: pool.pt(),
        r: pool.vec(),
        axis: pool.dir(),
    };
    for p in [pos.ok(), pos2.ok(), Some(wild_pos)].into_iter().flatten() {
        let vp = pool.opt::<T>();
        let vel = crank::velocity(&p, vp.as_ref(), pool.x());
        ensure_finite!("crank velocity", vel, |o| [o.x, o.y]);
        let ap = pool.opt::<T>();
        let acc = crank::acceleration(&p, ap.as_ref(), pool.x(), pool.x());
        ensure_finite!("crank acceleration", acc, |o| [o.x, o.y]);
    }

    // Slider
    let (g, s) = (pool.line::<T>(), pool.x::<T>());
    let pos = slider::position(&g, pool.x(), s);
    ensure_finite!("slider position", pos, |o| [o.p.x, o.p.y]);
    let wild_pos = slider::SliderPosition { p: pool.pt() };
    for p in [pos.ok(), Some(wild_pos)].into_iter().flatten() {
        let gv = pool.gv::<T>();
        let vel = slider::velocity(&p, &g, s, pool.x(), gv.as_ref());
        ensure_finite!("slider velocity", vel, |o| [o.x, o.y]);
        let ga = pool.ga::<T>();
        let acc = slider::acceleration(&p, &g, s, pool.x(), pool.x(), gv.as_ref(), ga.as_ref());
        ensure_finite!("slider acceleration", acc, |o| [o.x, o.y]);
    }

    // Actuator
    let pos = actuator::position(&pool.pt::<T>(), pool.x(), &pool.pt(), pool.x(), pool.mode());
    ensure_finite!("actuator position", pos, |o| [
        o.c.x, o.c.y, o.r1.x, o.r1.y, o.r2.x, o.r2.y, o.det
    ]);
    let wild_pos = actuator::ActuatorPosition::new(pool.pt(), pool.vec(), pool.vec());
    for p in [pos.ok(), Some(wild_pos)].into_iter().flatten() {
        let (va, vb) = (pool.opt::<T>(), pool.opt::<T>());
        let ld = pool.x::<T>();
        let vel = actuator::velocity(&p, va.as_ref(), vb.as_ref(), ld);
        ensure_finite!("actuator velocity", vel, |o| [
            o.omega1, o.omega2, o.vc.x, o.vc.y
        ]);
        let wild_vel = actuator::ActuatorVelocity {
            omega1: pool.x(),
            omega2: pool.x(),
            vc: pool.vec(),
            condition: pool.x(),
        };
        for v in [vel.ok(), Some(wild_vel)].into_iter().flatten() {
            let (aa, ab) = (pool.opt::<T>(), pool.opt::<T>());
            let acc = actuator::acceleration(&p, &v, aa.as_ref(), ab.as_ref(), ld, pool.x());
            ensure_finite!("actuator acceleration", acc, |o| [
                o.alpha1, o.alpha2, o.ac.x, o.ac.y
            ]);
        }
    }

    // Link points
    let q = link::point_position(&pool.pt::<T>(), &pool.dir(), &pool.vec());
    ensure_finite!("link point", q, |o| [o.x, o.y]);
    let r = pool.vec::<T>();
    let lv = link::point_velocity(&r, pool.x());
    ensure_finite!("link point velocity", lv, |o| [o.x, o.y]);
    let la = link::point_acceleration(&r, pool.x(), pool.x());
    ensure_finite!("link point acceleration", la, |o| [o.x, o.y]);
    Ok(())
}

/// RRR's rates with wild inputs (f32, `r1`, `r2` from 1e-40 to 1e20): every
/// angular rate inside an `Ok` is finite. This test found `omega2 = inf` in an
/// `Ok` before `rrr.rs` checked its rates.
fn fuzz_rrr_rates<T: Real + core::fmt::Debug>(pool: &mut Pool) -> Result<(), TestCaseError> {
    let pos = rrr::position(&pool.pt::<T>(), pool.x(), &pool.pt(), pool.x(), pool.mode());
    let wild_pos = rrr::RrrPosition::new(pool.pt(), pool.vec(), pool.vec());
    for p in [pos.ok(), Some(wild_pos)].into_iter().flatten() {
        let (va, vb) = (pool.opt::<T>(), pool.opt::<T>());
        let vel = rrr::velocity(&p, va.as_ref(), vb.as_ref());
        ensure_finite!("rrr velocity", vel, |o| [
            o.omega1, o.omega2, o.vc.x, o.vc.y
        ]);
        let wild_vel = rrr::RrrVelocity {
            omega1: pool.x(),
            omega2: pool.x(),
            vc: pool.vec(),
            condition: pool.x(),
            inv_det: pool.x(),
        };
        for v in [vel.ok(), Some(wild_vel)].into_iter().flatten() {
            let (aa, ab) = (pool.opt::<T>(), pool.opt::<T>());
            let acc = rrr::acceleration(&p, &v, aa.as_ref(), ab.as_ref());
            ensure_finite!("rrr acceleration", acc, |o| [
                o.alpha1, o.alpha2, o.ac.x, o.ac.y
            ]);
        }
    }

    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 1024, ..ProptestConfig::default() })]

    #[test]
    fn wild_inputs_never_panic_nor_leak_non_finite(
        vals in prop::collection::vec(wild(), 40),
        bits in any::<u64>(),
        start in 0usize..40,
    ) {
        fuzz::<f64>(&mut Pool { vals: &vals, bits, i: start })?;
        fuzz::<f32>(&mut Pool { vals: &vals, bits, i: start })?;
    }

    #[test]
    fn wild_inputs_rrr_rates(
        vals in prop::collection::vec(wild(), 40),
        bits in any::<u64>(),
        start in 0usize..40,
    ) {
        fuzz_rrr_rates::<f64>(&mut Pool { vals: &vals, bits, i: start })?;
        fuzz_rrr_rates::<f32>(&mut Pool { vals: &vals, bits, i: start })?;
    }
}

/// `wrap_angle` against exact multiples: inputs `x + 2 pi k` with `x` in
/// `(-pi, pi]` come back as `x` to the rounding of `2 pi k` (|k| <= 20:
/// 2.5e-14 at most, so 64 eps times |input| is the bound); `pi` stays `pi`,
/// `-pi` becomes `pi`; in f32 too.
#[test]
fn wrap_angle_reduces_to_minus_pi_pi() {
    use mechanism_core::geometry::wrap_angle;
    use std::f64::consts::PI;
    assert_eq!(wrap_angle(PI), PI);
    assert_eq!(wrap_angle(-PI), PI);
    assert_eq!(wrap_angle(0.25), 0.25);
    for k in -20i32..=20 {
        for j in 0..50 {
            let x = -PI + 2.0 * PI * (j as f64 + 0.5) / 50.0;
            let input = x + 2.0 * PI * k as f64;
            let got = wrap_angle(input);
            assert!(got > -PI && got <= PI, "{input} -> {got}");
            assert!(
                (got - x).abs() <= 64.0 * f64::EPSILON * input.abs().max(1.0),
                "{input}: {got} vs {x}"
            );
            let got32 = wrap_angle(input as f32);
            assert!(got32 > -std::f32::consts::PI && got32 <= std::f32::consts::PI);
            assert!(
                (f64::from(got32) - x).abs()
                    <= 64.0 * f64::from(f32::EPSILON) * input.abs().max(1.0)
            );
        }
    }
}
