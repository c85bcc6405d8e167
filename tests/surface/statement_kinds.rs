//! Every statement kind through the macro (the examples cover crank, RRR, RRP,
//! RPR and carried guides; this file adds the slider and actuator drivers and
//! the PRP and RPP groups): loop closure, and velocity and acceleration against
//! central finite differences of the generated position along a trajectory
//! q(t) = q0 + qd t + qdd t^2 / 2.
//!
//! Velocity is checked against the central difference of position, and
//! acceleration against the central difference of the generated velocity along
//! the same trajectory (rate qd + qdd t). Tolerances: with h = 1e-5 the
//! truncation error is ~ h^2 |third derivative| ~ 1e-10 of the scale here and
//! the rounding error ~ eps |f| / h ~ 2e-11; 1e-7 of max(1, scale) leaves margin
//! and still catches any missing term (a dropped Coriolis term is ~1e-1).
use mechanism::mechanism;
use mechanism::{Point2, Vector2};

mechanism! {
    /// Scotch yoke (sine mechanism): the crank pin A drives a block in a
    /// horizontal slot of a yoke that slides vertically along x = 0.
    pub Yoke {
        let O = ground(0.0, 0.0);
        let vertical = guide(O, 90 deg);
        let A = crank(O, 0.1, phi) as crank_link;
        let Q = rpp(A, vertical, -90 deg) as (block, yoke) slide (s_slot, s_yoke);
    }
}

mechanism! {
    /// A slider input drives an RRR: block P on a 30-degree line, links to a
    /// ground pivot.
    pub SliderDriven {
        let O = ground(0.0, 0.0);
        let line = guide((0.5, 0.1), 30 deg);
        let P = slider(line, s, 0.02) as block;
        let C = rrr(P, 0.6, O, 0.5, right) as (link1, link2);
    }
}

mechanism! {
    /// An excavator-like boom lifted by a hydraulic cylinder from B to C.
    pub Boom {
        let A = ground(0.0, 0.0);
        let B = ground(0.8, -0.2);
        let C = actuator(A, 1.2, B, len, left) as (boom, cylinder);
        let tip = point(boom, from A, 2.5, 10 deg);
    }
}

mechanism! {
    /// PRP: a block on a fixed vertical guide and a block on the crank's line.
    pub CrossSlide {
        let O = ground(0.0, 0.0);
        let V = ground(0.3, 0.0);
        let vertical = guide(V, 90 deg);
        let A = crank(O, 0.1, phi) as crank_link;
        let rod_line = guide(O, crank_link);
        let C = prp(rod_line, vertical, 0.0, 0.01) as (b1, b2) slide (s1, s2);
        // At 90 and 270 deg the crank's line is parallel to the vertical
        // guide and C is at infinity: the macro rejects the default full turn.
        range phi = (-80 deg, 80 deg);
    }
}

const H: f64 = 1e-5;

fn close(a: f64, b: f64, scale: f64, what: &str) {
    assert!(
        (a - b).abs() <= 1e-7 * scale.max(1.0),
        "{what}: {a} vs {b} (scale {scale})"
    );
}

fn close_vec(a: Vector2<f64>, b: Vector2<f64>, scale: f64, what: &str) {
    close(a.x, b.x, scale, what);
    close(a.y, b.y, scale, what);
}

/// Central difference of `f` at t = 0: (f(h) - f(-h)) / 2h.
fn fd<F: Fn(f64) -> Vector2<f64>>(f: F) -> Vector2<f64> {
    (f(H) - f(-H)) / (2.0 * H)
}

#[test]
fn scotch_yoke_follows_sine_law() {
    let m = Yoke::<f64>::default();
    for k in 0..24 {
        let (q0, qd, qdd) = (0.3 + 0.25 * k as f64, 7.0, 3.0);
        let at = |t: f64| YokeInput {
            phi: q0 + qd * t + 0.5 * qdd * t * t,
        };
        let s = m
            .solve(&at(0.0), &YokeInput { phi: qd }, &YokeInput { phi: qdd })
            .unwrap();
        // Independent closed form: the yoke's displacement is r sin(phi).
        close(
            s.position.s_yoke,
            0.1 * q0.sin(),
            1e-3,
            "s_yoke = r sin phi",
        );
        close(s.velocity.s_yoke, 0.1 * q0.cos() * qd, 1e-3, "rate");
        let expected = 0.1 * (q0.cos() * qdd - q0.sin() * qd * qd);
        close(s.acceleration.s_yoke, expected, 1e-3, "acceleration");
        let rate = |t: f64| YokeInput { phi: qd + qdd * t };
        let vel = |t: f64| m.velocity(&m.position(&at(t)).unwrap(), &rate(t)).unwrap();
        close_vec(
            s.velocity.Q,
            fd(|t| m.position(&at(t)).unwrap().Q.coords),
            1.0,
            "vQ",
        );
        close_vec(s.acceleration.Q, fd(|t| vel(t).Q), 1.0, "aQ");
    }
}

#[test]
fn slider_driven_rrr_closes_and_differentiates() {
    let m = SliderDriven::<f64>::default();
    for k in 0..20 {
        let (q0, qd, qdd) = (-0.2 + 0.02 * k as f64, 0.7, -0.4);
        let at = |t: f64| SliderDrivenInput {
            s: q0 + qd * t + 0.5 * qdd * t * t,
        };
        let s = m
            .solve(
                &at(0.0),
                &SliderDrivenInput { s: qd },
                &SliderDrivenInput { s: qdd },
            )
            .unwrap();
        let p = &s.position;
        close((p.C - p.P).norm(), 0.6, 1.0, "|C - P|");
        close((p.C - p.O).norm(), 0.5, 1.0, "|C - O|");
        // P lies 0.02 to the left of the line through (0.5, 0.1) at 30 deg.
        let dir = Vector2::new(30f64.to_radians().cos(), 30f64.to_radians().sin());
        let rel = p.P - Point2::new(0.5, 0.1);
        close(dir.x * rel.y - dir.y * rel.x, 0.02, 1.0, "offset of P");
        let rate = |t: f64| SliderDrivenInput { s: qd + qdd * t };
        let vel = |t: f64| m.velocity(&m.position(&at(t)).unwrap(), &rate(t)).unwrap();
        close_vec(
            s.velocity.P,
            fd(|t| m.position(&at(t)).unwrap().P.coords),
            1.0,
            "vP",
        );
        close_vec(
            s.velocity.C,
            fd(|t| m.position(&at(t)).unwrap().C.coords),
            1.0,
            "vC",
        );
        close_vec(s.acceleration.P, fd(|t| vel(t).P), 1.0, "aP");
        close_vec(s.acceleration.C, fd(|t| vel(t).C), 1.0, "aC");
    }
}

#[test]
fn actuator_lifts_the_boom() {
    let m = Boom::<f64>::default();
    for k in 0..20 {
        let (q0, qd, qdd) = (0.8 + 0.04 * k as f64, 0.05, 0.02);
        let at = |t: f64| BoomInput {
            len: q0 + qd * t + 0.5 * qdd * t * t,
        };
        let s = m
            .solve(&at(0.0), &BoomInput { len: qd }, &BoomInput { len: qdd })
            .unwrap();
        let p = &s.position;
        close((p.C - p.A).norm(), 1.2, 1.0, "|C - A|");
        close((p.C - p.B).norm(), q0, 1.0, "cylinder length");
        close((p.tip - p.A).norm(), 2.5, 1.0, "|tip - A|");
        let rate = |t: f64| BoomInput { len: qd + qdd * t };
        let vel = |t: f64| m.velocity(&m.position(&at(t)).unwrap(), &rate(t)).unwrap();
        close_vec(
            s.velocity.tip,
            fd(|t| m.position(&at(t)).unwrap().tip.coords),
            1.0,
            "tip velocity",
        );
        close_vec(
            s.acceleration.tip,
            fd(|t| vel(t).tip),
            1.0,
            "tip acceleration",
        );
    }
}

#[test]
fn cross_slide_on_a_carried_guide() {
    let m = CrossSlide::<f64>::default();
    for k in 0..20 {
        let (q0, qd, qdd) = (-1.0 + 0.1 * k as f64, 2.0, 5.0);
        let at = |t: f64| CrossSlideInput {
            phi: q0 + qd * t + 0.5 * qdd * t * t,
        };
        let s = m
            .solve(
                &at(0.0),
                &CrossSlideInput { phi: qd },
                &CrossSlideInput { phi: qdd },
            )
            .unwrap();
        // C on the crank's line through O, and 0.01 left of the vertical guide (x = 0.29).
        let c = s.position.C;
        close(c.x, 0.29, 1.0, "C on the offset vertical");
        close(c.y, 0.29 * q0.tan(), 1.0, "C on the crank line");
        let rate = |t: f64| CrossSlideInput { phi: qd + qdd * t };
        let vel = |t: f64| m.velocity(&m.position(&at(t)).unwrap(), &rate(t)).unwrap();
        close_vec(
            s.velocity.C,
            fd(|t| m.position(&at(t)).unwrap().C.coords),
            1.0,
            "vC",
        );
        close_vec(s.acceleration.C, fd(|t| vel(t).C), 1.0, "aC");
    }
}

mechanism! {
    /// The seed 002 four-bar with its crank angle given as (cos, sin).
    pub EncoderFourBar {
        let O2 = ground(0.0, 0.0);
        let O4 = ground(304.8, 0.0);
        let A = crank(O2, 101.6, theta2 as cos_sin) as link2;
        let B = rrr(A, 254.0, O4, 177.8, left) as (link3, link4);
        outputs { B, link2, link3, link4 }
    }
}

/// `position_cos_sin` against `position` at the same angles, and the rates
/// from either: the pair is normalized (an encoder's unscaled reading, here
/// 3.7 times the unit vector), so the only differences are the roundings of
/// the normalization and of cos/sin themselves: a few ulp of the 254 mm
/// coupler (1e-12 mm) and of pi (1e-14 rad).
#[test]
fn crank_input_as_cos_sin() {
    let m = EncoderFourBar::<f64>::default();
    for step in 0..72 {
        let q = f64::to_radians(5.0 * step as f64);
        let by_angle = m.position(&EncoderFourBarInput { theta2: q }).unwrap();
        let reading = mechanism::driver::crank::CosSin {
            cos: 3.7 * q.cos(),
            sin: 3.7 * q.sin(),
        };
        let by_pair = m
            .position_cos_sin(&EncoderFourBarCosSin { theta2: reading })
            .unwrap();
        assert!((by_angle.B - by_pair.B).norm() < 1e-12, "{step}");
        for (a, b) in [
            (by_angle.link2, by_pair.link2),
            (by_angle.link3, by_pair.link3),
            (by_angle.link4, by_pair.link4),
        ] {
            let d = (a - b).rem_euclid(2.0 * std::f64::consts::PI);
            assert!(
                d.min(2.0 * std::f64::consts::PI - d) < 1e-14,
                "{step}: {a} {b}"
            );
        }
        let rates = EncoderFourBarInput { theta2: 250.0 };
        let (va, vp) = (
            m.velocity(&by_angle, &rates).unwrap(),
            m.velocity(&by_pair, &rates).unwrap(),
        );
        assert!(
            (va.B - vp.B).norm() < 1e-12 * va.B.norm().max(1.0),
            "{step}"
        );
    }
    // A zero reading is a typed error naming the crank, not a NaN.
    let zero = mechanism::driver::crank::CosSin { cos: 0.0, sin: 0.0 };
    let err = m
        .position_cos_sin(&EncoderFourBarCosSin { theta2: zero })
        .unwrap_err();
    assert_eq!(err.group, "A");
}
