//! Inverse kinematics with a `target` driver: a five-bar robot whose end
//! point `P` is the input, its two motor links solved by two RRR groups
//! hanging on `P`, checked against the forward five-bar (the motors as
//! cranks, `P` their RRR's joint), a definition that shares no group with
//! it:
//!
//! - forward(inverse(P)) = P over a grid of the workspace, and the motor
//!   rates and accelerations the inverse gives reproduce the end point's
//!   velocity and acceleration through the forward one;
//! - the force a positioner needs at `P` (`drive_x`, `drive_y`) is what the
//!   motors supply: `tau = J^T D` (virtual work), with `J` the forward
//!   Jacobian read from the forward five-bar's velocities, equals the
//!   forward analysis's motor torques, masses, gravity and an end force
//!   included;
//! - outside the workspace the inverse is a typed `CannotAssemble` of the
//!   group that cannot close, never NaN.

use mechanism::{mechanism, Error, Fault, Primitive, Vector2};

mechanism! {
    /// The five-bar robot, given its end point (m, kg, N); its self-tests
    /// sweep the end point over a box inside the workspace.
    #[self_test]
    pub FiveBarIk {
        params { base = 0.08, proximal = 0.1, distal = 0.16 }
        dof 2;
        let O1 = ground(0.0, 0.0);
        let O2 = ground(base, 0.0);
        let P = target(x, y) as effector;
        let A = rrr(O1, proximal, P, distal, left) as (arm1, forearm1);
        let C = rrr(O2, proximal, P, distal, right) as (arm2, forearm2);
        let G1 = point(arm1, from O1, 0.05, 0 deg);
        let G2 = point(arm2, from O2, 0.05, 0 deg);
        let H1 = point(forearm1, from P, 0.08, 0 deg);
        let H2 = point(forearm2, from P, 0.08, 0 deg);
        mass arm1 { m = 0.12, at = G1, j = 1.1e-4 };
        mass arm2 { m = 0.12, at = G2, j = 1.1e-4 };
        mass forearm1 { m = 0.09, at = H1, j = 2.0e-4 };
        mass forearm2 { m = 0.09, at = H2, j = 2.0e-4 };
        mass effector { m = 0.05, at = P };
        gravity (0.0, -9.81);
        force at P on effector = (1.5, -4.0);
        motor q1 = angle(arm1);
        motor q2 = angle(arm2);
        range x = (0.0, 0.08);
        range y = (0.16, 0.22);
    }
}

mechanism! {
    /// The same five-bar driven by its motors (m, kg, N).
    pub FiveBarFk {
        params { base = 0.08, proximal = 0.1, distal = 0.16 }
        dof 2;
        let O1 = ground(0.0, 0.0);
        let O2 = ground(base, 0.0);
        let A = crank(O1, proximal, q1) as arm1;
        let C = crank(O2, proximal, q2) as arm2;
        let P = rrr(A, distal, C, distal, left) as (forearm1, forearm2);
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
        force at P on forearm1 = (1.5, -4.0);
    }
}

/// The workspace grid: end points from forward poses over the motors'
/// ranges (q1 in 70..140 deg, q2 in 10..80 deg), so every one is reachable
/// in the stated assemblies.
fn workspace() -> Vec<(f64, f64)> {
    let fk = FiveBarFk::<f64>::default();
    let mut out = Vec::new();
    for i in 0..=14 {
        for j in 0..=14 {
            let q1 = (70.0 + 5.0 * i as f64).to_radians();
            let q2 = (10.0 + 5.0 * j as f64).to_radians();
            let p = fk.position(&FiveBarFkInput { q1, q2 }).expect("assembles");
            out.push((p.P.x, p.P.y));
        }
    }
    out
}

#[test]
fn forward_of_inverse_is_the_end_point_with_its_rates() {
    // Proves the target drives the inverse kinematics: at 225 end points
    // the motor angles it finds put the forward five-bar's P back where it
    // was given, within 4e-16 m (2 ulps of coordinates of 0.2 m: each
    // chain rounds a few times); the motor rates and accelerations it
    // finds, fed to the forward five-bar, give back the end point's
    // velocity (0.3, -0.2) m/s within 1e-13 of its size and acceleration
    // (1.5, 2.5) m/s^2 within 1e-13 of its largest term (the input's, or a
    // link's omega^2 l): the two rate systems are each other's inverse and
    // amplify roundings by their condition, up to about 50 on this grid. A
    // motor angle off by 1e-9 rad moves P by about 1e-10 m and fails.
    let (ik, fk) = (FiveBarIk::<f64>::default(), FiveBarFk::<f64>::default());
    let (v, a) = (Vector2::new(0.3, -0.2), Vector2::new(1.5, 2.5));
    let (mut worst_p, mut worst_v, mut worst_a) = (0.0f64, 0.0f64, 0.0f64);
    for (x, y) in workspace() {
        let s = ik
            .solve(
                &FiveBarIkInput { x, y },
                &FiveBarIkInput { x: v.x, y: v.y },
                &FiveBarIkInput { x: a.x, y: a.y },
            )
            .expect("inside the workspace");
        let (pos, vel, acc) = (&s.position, &s.velocity, &s.acceleration);
        let q = FiveBarFkInput {
            q1: pos.arm1,
            q2: pos.arm2,
        };
        let rates = FiveBarFkInput {
            q1: vel.arm1,
            q2: vel.arm2,
        };
        let accels = FiveBarFkInput {
            q1: acc.arm1,
            q2: acc.arm2,
        };
        let f = fk.solve(&q, &rates, &accels).expect("forward assembles");
        worst_p = worst_p.max((f.position.P.x - x).abs().max((f.position.P.y - y).abs()));
        worst_v = worst_v.max((f.velocity.P - v).norm() / v.norm());
        // The acceleration's largest term: the input's, or a link's
        // centripetal term omega^2 l (l = 0.16 m, the longest link).
        let w2 = [vel.arm1, vel.arm2, vel.forearm1, vel.forearm2]
            .iter()
            .map(|w| w * w * 0.16)
            .fold(a.norm(), f64::max);
        worst_a = worst_a.max((f.acceleration.P - a).norm() / w2);
    }
    println!("forward(inverse(P)) - P: {worst_p:.1e} m; rates {worst_v:.1e}, accelerations {worst_a:.1e} (relative)");
    assert!(worst_p <= 4e-16, "{worst_p:e}");
    assert!(worst_v <= 1e-13, "{worst_v:e}");
    assert!(worst_a <= 1e-13, "{worst_a:e}");
}

#[test]
fn the_positioner_force_is_what_the_motors_supply() {
    // Proves the target's driving force is the force that holds P: mapped
    // to the motors by virtual work, tau = J^T D with J = dP/dq read from
    // the forward five-bar's velocity at unit motor rates, it equals the
    // forward analysis's motor torques (same masses, gravity and end
    // force, in motion) within 1e-12 of the largest torque (a few roundings
    // amplified by the condition of J); and the generated motor torques
    // (`motor q1 = angle(arm1);`, fields `drive_q1`, `drive_q2`) are both.
    // The generated rate map `motor_rate_map` times J is the identity
    // within 1e-13 (entries of K J are sums of products of size up to the
    // condition of J, about 50, each rounded). Leaving the effector's mass out of
    // the inverse moves the torques by 13 % of the largest and fails.
    let (ik, fk) = (FiveBarIk::<f64>::default(), FiveBarFk::<f64>::default());
    let (v, a) = (Vector2::new(0.3, -0.2), Vector2::new(1.5, 2.5));
    let (mut worst, mut worst_kj) = (0.0f64, 0.0f64);
    for (x, y) in workspace() {
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
        let d = Vector2::new(held.drive_x, held.drive_y);
        let q = FiveBarFkInput {
            q1: s.position.arm1,
            q2: s.position.arm2,
        };
        let fpos = fk.position(&q).unwrap();
        let column = |k: usize| {
            let e = FiveBarFkInput {
                q1: (k == 0) as u8 as f64,
                q2: (k == 1) as u8 as f64,
            };
            fk.velocity(&fpos, &e).unwrap().P
        };
        let tau = [column(0).dot(&d), column(1).dot(&d)];
        // The generated rate map K = dq/dP is the forward Jacobian's
        // inverse: K J = I.
        let k = ik.motor_rate_map(&s.position).unwrap();
        let (j0, j1) = (column(0), column(1));
        for (i, row) in k.iter().enumerate() {
            let kj = [row[0] * j0.x + row[1] * j0.y, row[0] * j1.x + row[1] * j1.y];
            for (c, got) in kj.into_iter().enumerate() {
                let want = if c == i { 1.0 } else { 0.0 };
                worst_kj = worst_kj.max((got - want).abs());
            }
        }
        // The generated motor torques are the same.
        let generated = (held.drive_q1 - tau[0])
            .abs()
            .max((held.drive_q2 - tau[1]).abs());
        let rates = FiveBarFkInput {
            q1: s.velocity.arm1,
            q2: s.velocity.arm2,
        };
        let accels = FiveBarFkInput {
            q1: s.acceleration.arm1,
            q2: s.acceleration.arm2,
        };
        let f = fk.solve(&q, &rates, &accels).unwrap();
        let motors = fk
            .forces(&f.position, &f.velocity, &f.acceleration)
            .unwrap();
        let scale = motors.drive_q1.abs().max(motors.drive_q2.abs());
        let miss = (tau[0] - motors.drive_q1)
            .abs()
            .max((tau[1] - motors.drive_q2).abs());
        worst = worst.max(miss.max(generated) / scale);
    }
    println!(
        "J^T D against the forward torques: {worst:.1e} of the largest; K J - I: {worst_kj:.1e}"
    );
    assert!(worst <= 1e-12, "{worst:e}");
    assert!(worst_kj <= 1e-13, "{worst_kj:e}");
}

#[test]
fn an_end_point_out_of_reach_is_a_typed_error() {
    // Proves an end point the arms cannot reach (beyond proximal + distal
    // from O1, and at the base line between the pivots) is a typed
    // CannotAssemble of the RRR that fails, with how far it misses, never
    // NaN; and a non-finite input is NonFinite of the target.
    let ik = FiveBarIk::<f64>::default();
    let Err(far): Result<_, Error<f64>> = ik.position(&FiveBarIkInput { x: 0.0, y: 0.27 }) else {
        panic!("an end point 0.27 m from O1 is out of reach");
    };
    assert_eq!(far.primitive, Primitive::Rrr);
    match far.fault {
        Fault::CannotAssemble { miss, .. } => assert!((miss - 0.01).abs() < 1e-12, "{miss}"),
        other => panic!("{other:?}"),
    }
    let Err(nan) = ik.position(&FiveBarIkInput {
        x: f64::NAN,
        y: 0.2,
    }) else {
        panic!("a NaN input is an error");
    };
    assert_eq!(nan.primitive, Primitive::Target);
    assert!(matches!(nan.fault, Fault::NonFinite { .. }));
}

mechanism! {
    /// The 2R leg of `relative_drivers` given its foot (m, kg, N): the hip
    /// motor turns the thigh from the ground, the knee motor the shank
    /// from the thigh. The shank's frame runs from the foot to the knee
    /// here (the RRR hangs it on F), so its mass centre, 0.15 m from K at
    /// -6 deg from K -> F there, is at 174 deg from this axis.
    pub LegIk {
        let H = ground(0.0, 0.0);
        let F = target(x, y) as foot;
        let K = rrr(H, 0.40, F, 0.35, right) as (thigh, shank);
        let G1 = point(thigh, from H, 0.17, 4 deg);
        let G2 = point(shank, from K, 0.15, 174 deg);
        mass thigh { m = 7.0, at = G1, j = 0.11 };
        mass shank { m = 3.2, at = G2, j = 0.045 };
        gravity (0.0, -9.81);
        force at F on foot = (30.0, 250.0);
        motor q1 = angle(thigh);
        motor q2 = angle(shank, thigh);
    }
}

#[test]
fn a_knee_motor_carried_by_the_thigh_holds_the_foot() {
    // Proves motors between moving links: the leg given its foot, with
    // the knee motor measured from the thigh (`angle(shank, thigh)`), has
    // the forward leg's relative knee angle and rates, and its generated
    // motor torques equal the forward leg's hip and knee torques (the
    // knee's reacting on the thigh) within 1e-12 of the largest, over a
    // 9 x 9 grid of stance poses in motion. Taking the knee's rate as the
    // shank's absolute one changes the torques by far more and fails.
    use crate::relative_drivers::{Leg, LegInput};
    let (ik, fk) = (LegIk::<f64>::default(), Leg::<f64>::default());
    let wrap = |a: f64| {
        (a + std::f64::consts::PI).rem_euclid(std::f64::consts::TAU) - std::f64::consts::PI
    };
    let mut worst = 0.0f64;
    for i in 0..9 {
        for j in 0..9 {
            let q = LegInput {
                q1: (-150.0 + 15.0 * i as f64).to_radians(),
                q2: (10.0 + 17.5 * j as f64).to_radians(),
            };
            let (w, al) = (
                LegInput { q1: 1.3, q2: -2.1 },
                LegInput { q1: -4.0, q2: 6.5 },
            );
            let f = fk.solve(&q, &w, &al).unwrap();
            let (p, v, a) = (f.position.F, f.velocity.F, f.acceleration.F);
            let s = ik
                .solve(
                    &LegIkInput { x: p.x, y: p.y },
                    &LegIkInput { x: v.x, y: v.y },
                    &LegIkInput { x: a.x, y: a.y },
                )
                .unwrap();
            // The shank's axis runs F -> K here, K -> F in the forward leg.
            let knee = wrap(s.position.shank - s.position.thigh - std::f64::consts::PI);
            assert!((knee - q.q2).abs() <= 1e-13, "{knee} against {}", q.q2);
            assert!((s.velocity.shank - s.velocity.thigh - w.q2).abs() <= 1e-12);
            let held = ik
                .forces(&s.position, &s.velocity, &s.acceleration)
                .unwrap();
            let motors = fk
                .forces(&f.position, &f.velocity, &f.acceleration)
                .unwrap();
            let scale = motors.drive_q1.abs().max(motors.drive_q2.abs());
            let miss = (held.drive_q1 - motors.drive_q1)
                .abs()
                .max((held.drive_q2 - motors.drive_q2).abs());
            worst = worst.max(miss / scale);
        }
    }
    println!("leg given its foot: torques {worst:.1e} of the largest");
    assert!(worst <= 1e-12, "{worst:e}");
}
