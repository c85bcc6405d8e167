//! The five-bar robot given its end point (`scenes::FiveBarIk`, written as
//! drawn, the end point's coordinates its inputs), against the forward
//! five-bar of the scenes (`FiveBar`, the motors as cranks) and a loaded
//! forward five-bar written here: the inverse's answers put back through
//! the forward definitions, which share no group with it.

use crate::columns::Columns;
use crate::scenes::{FiveBar, FiveBarIk, FiveBarIkInput, FiveBarInput};
use mechanism::{mechanism, Fault, Primitive, Vector2};

mechanism! {
    /// The forward five-bar with `FiveBarIk`'s masses, gravity and payload
    /// (m, kg, N); the effector's mass rides on `forearm1` at `P`.
    pub LoadedFiveBar {
        let O1 = ground(0.0, 0.0);
        let O2 = ground(0.08, 0.0);
        let A = crank(O1, 0.1, q1) as arm1;
        let C = crank(O2, 0.1, q2) as arm2;
        let P = rrr(A, 0.16, C, 0.16, left) as (forearm1, forearm2);
        let G1 = point(arm1, from O1, 0.05, 0 deg);
        let G2 = point(arm2, from O2, 0.05, 0 deg);
        let H1 = point(forearm1, from A, 0.08, 0 deg);
        let H2 = point(forearm2, from C, 0.08, 0 deg);
        mass arm1 { m = 0.12, at = G1, j = 1.1e-4 };
        mass arm2 { m = 0.12, at = G2, j = 1.1e-4 };
        mass forearm1 { m = 0.09, at = H1, j = 2.0e-4 };
        mass forearm1 { m = 0.05, at = P };
        mass forearm2 { m = 0.09, at = H2, j = 2.0e-4 };
        gravity (0.0, -9.81);
        force at P on forearm1 = (0.0, -2.0);
    }
}

/// End points over the workspace: the forward five-bar's `P` over its
/// motors' declared ranges (q1 60..150 deg, q2 0..90 deg, a 19 x 19 grid),
/// kept where the inverse's drawn assembly (each elbow out, on the side
/// drawn) is the one the forward pose has.
fn workspace() -> Vec<(FiveBarInput, (f64, f64))> {
    let fk = FiveBar::<f64>::default();
    let mut out = Vec::new();
    for i in 0..=18 {
        for j in 0..=18 {
            let q = FiveBarInput {
                q1: (60.0 + 5.0 * i as f64).to_radians(),
                q2: (5.0 * j as f64).to_radians(),
            };
            let p = fk.position(&q).expect("the forward five-bar assembles");
            let (a, c) = (p.A, p.C);
            let elbow1 = p.P.x * a.y - p.P.y * a.x > 0.0; // A left of O1 -> P
            let d = (p.P.x - 0.08, p.P.y);
            let elbow2 = d.0 * (c.y) - d.1 * (c.x - 0.08) < 0.0; // C right of O2 -> P
            if elbow1 && elbow2 {
                out.push((q, (p.P.x, p.P.y)));
            }
        }
    }
    out
}

#[test]
fn forward_of_inverse_is_the_end_point() {
    // Proves the drawn inverse recovers the motors: at every end point of
    // the workspace grid (over 250 of the 361 forward poses have both
    // elbows out), the forward five-bar puts P back within 1e-16 m
    // (coordinates of 0.2 m: under 2 ulps), and the inverse's motor angles
    // are the forward pose's within 1e-14 rad (P's rounding over the arm's
    // length, amplified near the workspace's edge by 1 / sin of the elbow
    // angle). The drawing's 20-digit coordinates give lengths equal to 0.1
    // and 0.16 to the last bit.
    let (ik, fk) = (FiveBarIk::default(), FiveBar::<f64>::default());
    let grid = workspace();
    assert!(grid.len() > 250, "{}", grid.len());
    let (mut worst_q, mut worst_p) = (0.0f64, 0.0f64);
    for (q, (x, y)) in grid {
        let pos = ik.position(&FiveBarIkInput { x, y }).expect("in reach");
        let wrap = |d: f64| {
            (d + std::f64::consts::PI).rem_euclid(std::f64::consts::TAU) - std::f64::consts::PI
        };
        worst_q = worst_q.max(wrap(pos.arm1 - q.q1).abs().max(wrap(pos.arm2 - q.q2).abs()));
        let back = fk
            .position(&FiveBarInput {
                q1: pos.arm1,
                q2: pos.arm2,
            })
            .unwrap();
        worst_p = worst_p.max((back.P.x - x).abs().max((back.P.y - y).abs()));
    }
    println!("inverse against forward: angles {worst_q:.1e} rad, forward(inverse(P)) - P {worst_p:.1e} m");
    assert!(worst_q <= 1e-14, "{worst_q:e}");
    assert!(worst_p <= 1e-16, "{worst_p:e}");
}

#[test]
fn motor_rates_and_torques_agree_with_the_forward_analysis() {
    // Proves the inverse's motor rates and accelerations, and its motor
    // torques (`drive_q1`, `drive_q2`: tau = J^T D from the positioner's
    // force), are those of the forward
    // five-bar with the same masses, gravity and payload driven by those
    // motor motions: the end point's velocity and acceleration come back
    // within 1e-13 of their largest term, the torques within 1e-12 of the
    // largest (the 2 x 2 rate map's condition, up to about 50 here, times
    // a few roundings). Dropping the inverse's effector mass moves the
    // torques by 12 % of the largest and fails.
    let (ik, fk) = (FiveBarIk::default(), LoadedFiveBar::<f64>::default());
    let (v, a) = (Vector2::new(-0.12, 0.2), Vector2::new(0.9, -1.4));
    let (mut worst_rates, mut worst_tau) = (0.0f64, 0.0f64);
    for (_, (x, y)) in workspace() {
        let s = ik
            .solve(
                &FiveBarIkInput { x, y },
                &FiveBarIkInput { x: v.x, y: v.y },
                &FiveBarIkInput { x: a.x, y: a.y },
            )
            .unwrap();
        let held = ik
            .forces(&s.position, &s.velocity, &s.acceleration)
            .unwrap();
        let tau = (held.drive_q1, held.drive_q2);
        let f = fk
            .solve(
                &LoadedFiveBarInput {
                    q1: s.position.arm1,
                    q2: s.position.arm2,
                },
                &LoadedFiveBarInput {
                    q1: s.velocity.arm1,
                    q2: s.velocity.arm2,
                },
                &LoadedFiveBarInput {
                    q1: s.acceleration.arm1,
                    q2: s.acceleration.arm2,
                },
            )
            .unwrap();
        let vel = &s.velocity;
        let term = [vel.arm1, vel.arm2, vel.forearm1, vel.forearm2]
            .iter()
            .map(|w| w * w * 0.16)
            .fold(a.norm(), f64::max);
        worst_rates = worst_rates
            .max((f.velocity.P - v).norm() / v.norm())
            .max((f.acceleration.P - a).norm() / term);
        let motors = fk
            .forces(&f.position, &f.velocity, &f.acceleration)
            .unwrap();
        let scale = motors.drive_q1.abs().max(motors.drive_q2.abs());
        let miss = (tau.0 - motors.drive_q1)
            .abs()
            .max((tau.1 - motors.drive_q2).abs());
        worst_tau = worst_tau.max(miss / scale);
    }
    println!("rates {worst_rates:.1e}, torques {worst_tau:.1e} (relative)");
    assert!(worst_rates <= 1e-13, "{worst_rates:e}");
    assert!(worst_tau <= 1e-12, "{worst_tau:e}");
}

#[test]
fn out_of_reach_is_a_typed_error_of_the_arm_that_cannot_close() {
    // Proves an end point beyond both arms' reach (0.30 m above the base's
    // middle; each arm reaches 0.26 m) is a typed CannotAssemble of the
    // first RRR (at A), missing by |P - O1| - 0.26, never NaN.
    let ik = FiveBarIk::default();
    let Err(e) = ik.position(&FiveBarIkInput { x: 0.04, y: 0.30 }) else {
        panic!("(0.04, 0.30) is out of reach");
    };
    assert_eq!(e.primitive, Primitive::Rrr);
    let Fault::CannotAssemble { miss, .. } = e.fault else {
        panic!("{e}");
    };
    let expected = 0.04f64.hypot(0.30) - 0.26;
    assert!(
        (miss - expected).abs() <= 1e-15,
        "{miss} against {expected}"
    );
}

mechanism! {
    /// `scenes::FiveBarIk` written with groups: the target, the two RRRs
    /// with their elbows' modes, the mass centres as link points.
    pub GroupedFiveBarIk {
        let O1 = ground(0.0, 0.0);
        let O2 = ground(0.08, 0.0);
        let P = target(x, y) as P_effector;
        let A = rrr(O1, 0.1, P, 0.16, left) as (arm1, forearm1);
        let C = rrr(O2, 0.1, P, 0.16, right) as (arm2, forearm2);
        let G1 = point(arm1, from O1, 0.05, 0 deg);
        let G2 = point(arm2, from O2, 0.05, 0 deg);
        let H1 = point(forearm1, from P, 0.08, 0 deg);
        let H2 = point(forearm2, from P, 0.08, 0 deg);
        mass arm1 { m = 0.12, at = G1, j = 1.1e-4 };
        mass arm2 { m = 0.12, at = G2, j = 1.1e-4 };
        mass forearm1 { m = 0.09, at = H1, j = 2.0e-4 };
        mass forearm2 { m = 0.09, at = H2, j = 2.0e-4 };
        mass P_effector { m = 0.05, at = P };
        gravity (0.0, -9.81);
        force at P on P_effector = (0.0, -2.0);
        motor q1 = angle(arm1);
        motor q2 = angle(arm2);
    }
}

#[test]
fn drawn_and_grouped_forms_agree() {
    // Proves the drawn inverse kinematics is the grouped one: over the
    // workspace grid, in motion, the elbows, the motor angles, rates and
    // accelerations agree within 8 ulps of each column's largest value
    // (the drawing's lengths are 0.1 and 0.16 to the last bit), the motor
    // torques within 1e-13 (measured 1.4e-14): the mass centres are drawn
    // joints in one and link points in the other, so their places round
    // differently, and the torques divide by the rate map's determinant
    // (condition up to about 50 on this grid).
    let (drawn, grouped) = (FiveBarIk::default(), GroupedFiveBarIk::<f64>::default());
    let (v, a) = ((0.25, 0.1), (-2.0, 0.7));
    // Per column, its largest difference against its scale: the
    // kinematics, and the motor torques.
    let (mut motion, mut torques) = (Columns::default(), Columns::default());
    for (_, (x, y)) in workspace() {
        let d = drawn
            .solve(
                &FiveBarIkInput { x, y },
                &FiveBarIkInput { x: v.0, y: v.1 },
                &FiveBarIkInput { x: a.0, y: a.1 },
            )
            .unwrap();
        let g = grouped
            .solve(
                &GroupedFiveBarIkInput { x, y },
                &GroupedFiveBarIkInput { x: v.0, y: v.1 },
                &GroupedFiveBarIkInput { x: a.0, y: a.1 },
            )
            .unwrap();
        let fd = drawn
            .forces(&d.position, &d.velocity, &d.acceleration)
            .unwrap();
        let fg = grouped
            .forces(&g.position, &g.velocity, &g.acceleration)
            .unwrap();
        motion.scalar("q1", d.position.arm1, g.position.arm1);
        motion.scalar("q2", d.position.arm2, g.position.arm2);
        motion.point("A", d.position.A, g.position.A);
        motion.point("C", d.position.C, g.position.C);
        motion.scalar("d/dt q1", d.velocity.arm1, g.velocity.arm1);
        motion.scalar("d/dt q2", d.velocity.arm2, g.velocity.arm2);
        motion.scalar("d2/dt2 q1", d.acceleration.arm1, g.acceleration.arm1);
        motion.scalar("d2/dt2 q2", d.acceleration.arm2, g.acceleration.arm2);
        torques.scalar("drive_q1", fd.drive_q1, fg.drive_q1);
        torques.scalar("drive_q2", fd.drive_q2, fg.drive_q2);
    }
    let ((m_name, m), (t_name, t)) = (motion.worst(), torques.worst());
    println!("drawn against grouped: motion {m:.1e} ({m_name}), torques {t:.1e} ({t_name})");
    assert!(m <= 8.0 * f64::EPSILON, "{m_name}: {m:e}");
    assert!(t <= 1e-13, "{t_name}: {t:e}");
}
