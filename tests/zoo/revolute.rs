//! Revolute chains: `WattII`, `StephensonIII`, `LoadedFiveBar` (see `main.rs`).

use crate::equilibrium::*;
use mechanism::mechanism;
use mechanism::Vector2;

mechanism! {
    /// Watt II six-bar (m, kg, N): crank O2-A, coupler A-B, ternary rocker
    /// O4-B-E, then coupler E-F and output O6-F. Masses on every moving
    /// link, gravity, a force on the second coupler, a couple on the output.
    pub WattII {
        dof 1;
        let O2 = ground(0.0, 0.0);
        let O4 = ground(0.40, 0.0);
        let O6 = ground(0.78, 0.22);
        let A = crank(O2, 0.10, theta) as crank;
        let B = rrr(A, 0.36, O4, 0.25, left) as (coupler, rocker);
        let E = point(rocker, from O4, 0.18, -35 deg);
        let F = rrr(E, 0.32, O6, 0.22, left) as (coupler2, output);
        let G2 = point(crank, from O2, 0.05, 0 deg);
        let G3 = point(coupler, from A, 0.18, 5 deg);
        let G4 = point(rocker, from O4, 0.12, -15 deg);
        let G5 = point(coupler2, from E, 0.16, 0 deg);
        let G6 = point(output, from O6, 0.11, 0 deg);
        mass crank { m = 0.8, at = G2, j = 0.0012 };
        mass coupler { m = 1.6, at = G3, j = 0.021 };
        mass rocker { m = 1.1, at = G4, j = 0.009 };
        mass coupler2 { m = 1.3, at = G5, j = 0.014 };
        mass output { m = 0.7, at = G6, j = 0.004 };
        gravity (0.0, -9.81);
        force at G5 = (12.0, -30.0);
        torque on output = -4.0;
    }
}

mechanism! {
    /// Stephenson III six-bar (m, kg, N): a four-bar O2-A-B-O4 whose coupler
    /// point P drives the RRR group P-C-O6 (links `l5`, `l6`: run-time
    /// parameters, shortened by the edge test below). Point masses and
    /// inertias on the coupler and the last two links, no gravity, a force at
    /// C on the last link.
    pub StephensonIII {
        params { l5 = 0.28, l6 = 0.24 }
        dof 1;
        let O2 = ground(0.0, 0.0);
        let O4 = ground(0.30, 0.0);
        let O6 = ground(0.05, 0.42);
        let A = crank(O2, 0.08, theta) as crank;
        let B = rrr(A, 0.26, O4, 0.20, left) as (coupler, rocker);
        let P = point(coupler, from A, 0.15, 40 deg);
        let C = rrr(P, l5, O6, l6, right) as (link5, link6);
        let G3 = point(coupler, from A, 0.12, 15 deg);
        let G5 = point(link5, from P, 0.14, 0 deg);
        let G6 = point(link6, from O6, 0.12, 0 deg);
        mass coupler { m = 2.0, at = G3, j = 0.015 };
        mass link5 { m = 0.9, at = G5, j = 0.006 };
        mass link6 { m = 0.6, at = G6, j = 0.003 };
        force at C on link6 = (-8.0, 5.0);
    }
}

mechanism! {
    /// A five-bar with two cranks (two inputs, two drive torques), masses on
    /// all four moving links, gravity along -y.
    pub LoadedFiveBar {
        dof 2;
        let O1 = ground(0.0, 0.0);
        let O2 = ground(0.09, 0.0);
        let A = crank(O1, 0.10, q1) as arm1;
        let C = crank(O2, 0.10, q2) as arm2;
        let P = rrr(A, 0.16, C, 0.16, left) as (forearm1, forearm2);
        let G1 = point(arm1, from O1, 0.05, 0 deg);
        let G2 = point(arm2, from O2, 0.05, 0 deg);
        let G3 = point(forearm1, from A, 0.08, 0 deg);
        let G4 = point(forearm2, from C, 0.08, 0 deg);
        mass arm1 { m = 0.3, at = G1, j = 0.0004 };
        mass arm2 { m = 0.3, at = G2, j = 0.0004 };
        mass forearm1 { m = 0.45, at = G3, j = 0.001 };
        mass forearm2 { m = 0.45, at = G4, j = 0.001 };
        gravity (0.0, -9.81);
        force at P on forearm1 = (2.0, -6.0);
        range q1 = (60 deg, 150 deg);
        range q2 = (0 deg, 90 deg);
    }
}

#[test]
fn watt_ii_closes_differentiates_and_balances() {
    let m = WattII::<f64>::default();
    let (w, al) = (12.0, -30.0);
    for k in 0..72 {
        let q = f64::to_radians(5.0 * k as f64);
        let at = |t: f64| WattIIInput {
            theta: q + w * t + 0.5 * al * t * t,
        };
        let rate = |t: f64| WattIIInput { theta: w + al * t };
        let s = m
            .solve(&at(0.0), &rate(0.0), &WattIIInput { theta: al })
            .unwrap();
        let (p, v, a, f) = (&s.position, &s.velocity, &s.acceleration, &s.forces);

        assert_len(p.A, p.O2, 0.10, "crank");
        assert_len(p.B, p.A, 0.36, "coupler");
        assert_len(p.B, p.O4, 0.25, "rocker");
        assert_len(p.E, p.O4, 0.18, "rocker O4-E");
        assert_len(p.F, p.E, 0.32, "coupler2");
        assert_len(p.F, p.O6, 0.22, "output");

        let pos = |t: f64| m.position(&at(t)).unwrap();
        let vel = |t: f64| m.velocity(&pos(t), &rate(t)).unwrap();
        for (name, got, fd) in [
            ("vF", v.F, (pos(H).F - pos(-H).F) / (2.0 * H)),
            ("vG5", v.G5, (pos(H).G5 - pos(-H).G5) / (2.0 * H)),
            ("aF", a.F, (vel(H).F - vel(-H).F) / (2.0 * H)),
            ("aG4", a.G4, (vel(H).G4 - vel(-H).G4) / (2.0 * H)),
        ] {
            close_fd(got, fd, 100.0, name);
        }

        let ext = Vector2::new(12.0, -30.0);
        Body::default()
            .force(p.O2, f.r_ground_crank)
            .force(p.A, -f.r_crank_coupler)
            .couple(f.drive_theta)
            .inertia(0.8, 0.0012, p.G2, a.G2, a.crank, G)
            .balances("crank");
        Body::default()
            .force(p.A, f.r_crank_coupler)
            .force(p.B, -f.r_coupler_rocker)
            .inertia(1.6, 0.021, p.G3, a.G3, a.coupler, G)
            .balances("coupler");
        Body::default()
            .force(p.O4, f.r_ground_rocker)
            .force(p.B, f.r_coupler_rocker)
            .force(p.E, -f.r_rocker_coupler2)
            .inertia(1.1, 0.009, p.G4, a.G4, a.rocker, G)
            .balances("rocker (ternary)");
        Body::default()
            .force(p.E, f.r_rocker_coupler2)
            .force(p.F, -f.r_coupler2_output)
            .force(p.G5, ext)
            .inertia(1.3, 0.014, p.G5, a.G5, a.coupler2, G)
            .balances("coupler2");
        Body::default()
            .force(p.O6, f.r_ground_output)
            .force(p.F, f.r_coupler2_output)
            .couple(-4.0)
            .inertia(0.7, 0.004, p.G6, a.G6, a.output, G)
            .balances("output");

        power_balances(
            &[
                f.drive_theta * v.crank,
                inertial(0.8, 0.0012, v.G2, a.G2, v.crank, a.crank, G),
                inertial(1.6, 0.021, v.G3, a.G3, v.coupler, a.coupler, G),
                inertial(1.1, 0.009, v.G4, a.G4, v.rocker, a.rocker, G),
                inertial(1.3, 0.014, v.G5, a.G5, v.coupler2, a.coupler2, G),
                inertial(0.7, 0.004, v.G6, a.G6, v.output, a.output, G),
                ext.dot(&v.G5),
                -4.0 * v.output,
            ],
            "WattII",
        );
    }
}

#[test]
fn stephenson_iii_closes_differentiates_and_balances() {
    let m = StephensonIII::<f64>::default();
    let (w, al) = (-8.0, 15.0);
    let mut solved = 0;
    for k in 0..72 {
        let q = f64::to_radians(5.0 * k as f64);
        let at = |t: f64| StephensonIIIInput {
            theta: q + w * t + 0.5 * al * t * t,
        };
        let rate = |t: f64| StephensonIIIInput { theta: w + al * t };
        let s = match m.solve(&at(0.0), &rate(0.0), &StephensonIIIInput { theta: al }) {
            Ok(s) => s,
            // Where the second group cannot close the error is typed and
            // names it (checked below for the whole turn).
            Err(e) => {
                assert_eq!(e.group, "C", "{e}");
                continue;
            }
        };
        solved += 1;
        let (p, v, a, f) = (&s.position, &s.velocity, &s.acceleration, &s.forces);
        assert_len(p.B, p.A, 0.26, "coupler");
        assert_len(p.B, p.O4, 0.20, "rocker");
        assert_len(p.C, p.P, 0.28, "link5");
        assert_len(p.C, p.O6, 0.24, "link6");
        // The relative pivots stay far from singular on the poses kept.
        if f.condition < 0.05 || v.condition < 0.05 {
            continue;
        }

        let pos = |t: f64| m.position(&at(t)).unwrap();
        let vel = |t: f64| m.velocity(&pos(t), &rate(t)).unwrap();
        close_fd(v.C, (pos(H).C - pos(-H).C) / (2.0 * H), 10.0, "vC");
        close_fd(a.C, (vel(H).C - vel(-H).C) / (2.0 * H), 100.0, "aC");
        close_fd(a.P, (vel(H).P - vel(-H).P) / (2.0 * H), 100.0, "aP");

        let ext = Vector2::new(-8.0, 5.0);
        let none = Vector2::zeros();
        Body::default()
            .force(p.O2, f.r_ground_crank)
            .force(p.A, -f.r_crank_coupler)
            .couple(f.drive_theta)
            .balances("crank (massless)");
        Body::default()
            .force(p.A, f.r_crank_coupler)
            .force(p.B, -f.r_coupler_rocker)
            .force(p.P, -f.r_coupler_link5)
            .inertia(2.0, 0.015, p.G3, a.G3, a.coupler, none)
            .balances("coupler (ternary)");
        Body::default()
            .force(p.O4, f.r_ground_rocker)
            .force(p.B, f.r_coupler_rocker)
            .balances("rocker (massless, two-force member)");
        Body::default()
            .force(p.P, f.r_coupler_link5)
            .force(p.C, -f.r_link5_link6)
            .inertia(0.9, 0.006, p.G5, a.G5, a.link5, none)
            .balances("link5");
        Body::default()
            .force(p.O6, f.r_ground_link6)
            .force(p.C, f.r_link5_link6)
            .force(p.C, ext)
            .inertia(0.6, 0.003, p.G6, a.G6, a.link6, none)
            .balances("link6");
        power_balances(
            &[
                f.drive_theta * v.crank,
                -2.0 * a.G3.dot(&v.G3) - 0.015 * a.coupler * v.coupler,
                -0.9 * a.G5.dot(&v.G5) - 0.006 * a.link5 * v.link5,
                -0.6 * a.G6.dot(&v.G6) - 0.003 * a.link6 * v.link6,
                ext.dot(&v.C),
            ],
            "StephensonIII",
        );
    }
    // The geometry closes over most of the turn; the test must not pass by
    // skipping everything.
    assert!(solved >= 36, "only {solved} of 72 poses assembled");
}

#[test]
fn five_bar_with_two_drives_balances() {
    let m = LoadedFiveBar::<f64>::default();
    let mut checked = 0;
    for i in 0..10 {
        for k in 0..10 {
            let q1 = f64::to_radians(60.0 + 10.0 * i as f64);
            let q2 = f64::to_radians(10.0 * k as f64);
            let (w1, w2, al1, al2) = (3.0, -2.0, 20.0, 7.0);
            let s = match m.solve(
                &LoadedFiveBarInput { q1, q2 },
                &LoadedFiveBarInput { q1: w1, q2: w2 },
                &LoadedFiveBarInput { q1: al1, q2: al2 },
            ) {
                Ok(s) => s,
                Err(e) => {
                    assert_eq!(e.group, "P", "{e}");
                    continue;
                }
            };
            let (p, v, a, f) = (&s.position, &s.velocity, &s.acceleration, &s.forces);
            if f.condition < 0.05 {
                continue;
            }
            checked += 1;
            let ext = Vector2::new(2.0, -6.0);
            Body::default()
                .force(p.O1, f.r_ground_arm1)
                .force(p.A, -f.r_arm1_forearm1)
                .couple(f.drive_q1)
                .inertia(0.3, 0.0004, p.G1, a.G1, a.arm1, G)
                .balances("arm1");
            Body::default()
                .force(p.O2, f.r_ground_arm2)
                .force(p.C, -f.r_arm2_forearm2)
                .couple(f.drive_q2)
                .inertia(0.3, 0.0004, p.G2, a.G2, a.arm2, G)
                .balances("arm2");
            Body::default()
                .force(p.A, f.r_arm1_forearm1)
                .force(p.P, -f.r_forearm1_forearm2)
                .force(p.P, ext)
                .inertia(0.45, 0.001, p.G3, a.G3, a.forearm1, G)
                .balances("forearm1");
            Body::default()
                .force(p.C, f.r_arm2_forearm2)
                .force(p.P, f.r_forearm1_forearm2)
                .inertia(0.45, 0.001, p.G4, a.G4, a.forearm2, G)
                .balances("forearm2");
            power_balances(
                &[
                    f.drive_q1 * w1,
                    f.drive_q2 * w2,
                    inertial(0.3, 0.0004, v.G1, a.G1, v.arm1, a.arm1, G),
                    inertial(0.3, 0.0004, v.G2, a.G2, v.arm2, a.arm2, G),
                    inertial(0.45, 0.001, v.G3, a.G3, v.forearm1, a.forearm1, G),
                    inertial(0.45, 0.001, v.G4, a.G4, v.forearm2, a.forearm2, G),
                    ext.dot(&v.P),
                ],
                "LoadedFiveBar",
            );
        }
    }
    assert!(checked >= 50, "only {checked} of 100 poses checked");
}

/// `StephensonIII` with a short last group (`l5 = 0.16`, `l6 = 0.15`,
/// against a distance from P to O6 of 0.205 to 0.356 over the turn: it
/// cannot close over part of the turn and passes through both edges of its
/// assembly, full extension, twice per turn), over a fine turn (0.01 deg) in
/// f64 and f32, with a crank rate and acceleration: every pose is either a
/// full solution with no NaN or infinity anywhere (forces included), or a
/// typed error naming the last group; both occur, and the solutions next to
/// the edges (where the reactions grow without bound) stay finite.
#[test]
fn stephenson_iii_fine_turn_is_finite_or_a_typed_error() {
    fn turn<T: mechanism::Real>() -> (usize, usize)
    where
        StephensonIIISolution<T>: core::fmt::Debug,
    {
        let m = StephensonIII::<T> {
            l5: T::lit(0.16),
            l6: T::lit(0.15),
        };
        let (mut ok, mut failed) = (0, 0);
        for k in 0..36_000 {
            let q = T::lit(f64::to_radians(0.01 * k as f64));
            let i = |x: T| StephensonIIIInput { theta: x };
            match m.solve(&i(q), &i(T::lit(-8.0)), &i(T::lit(15.0))) {
                Ok(s) => {
                    let text = format!("{s:?}");
                    assert!(
                        !text.contains("NaN") && !text.contains("inf"),
                        "at step {k}: {text}"
                    );
                    ok += 1;
                }
                Err(e) => {
                    assert_eq!(e.group, "C", "at step {k}: {e}");
                    failed += 1;
                }
            }
        }
        (ok, failed)
    }
    for (name, (ok, failed)) in [("f64", turn::<f64>()), ("f32", turn::<f32>())] {
        assert!(
            ok > 1000 && failed > 1000,
            "{name}: {ok} solved, {failed} typed errors"
        );
    }
}
