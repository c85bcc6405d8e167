//! Drivers between two moving links: a crank carried by a moving link (an
//! elbow or knee motor, `crank(PIVOT, r, INPUT, CARRIER)`) and a slider on a
//! guide carried by a moving link (a telescoping arm).
//!
//! Every expected value is worked out here in closed form from the inputs
//! alone, never from the generated code: the joint positions from the angles
//! summed along the chain, the rates and accelerations by differentiating
//! those by hand, and the driving torques and forces by Newton-Euler on each
//! body in turn (the distal body first, its joint reaction then applied,
//! reversed, to the body that carries it).
//!
//! Tolerances. The generated code turns the carrier's axis by the relative
//! angle where the closed forms take `cos(q1 + q2)`, and sums the same terms
//! in another order: the two agree to a few ulps of the largest term of each
//! quantity. 1e-13 relative to that term (about 450 eps) leaves room for the
//! handful of roundings in each chain and is 1e9 times smaller than the
//! deliberate mistakes checked to fail (a relative angle read as absolute,
//! the reaction torque left off the carrier).

use mechanism::{mechanism, Point2, Vector2};

/// Gravity (m/s^2).
const GY: f64 = -9.81;
/// Relative tolerance (see the module's comment).
const TOL: f64 = 1e-13;

mechanism! {
    /// A 2R leg (m, kg, N): the hip motor turns the thigh about the ground
    /// point H; the knee motor, carried by the thigh, turns the shank about
    /// the knee K by `q2` measured from the thigh's axis (0: leg straight).
    /// A ground reaction force at the foot F.
    pub Leg {
        dof 2;
        let H = ground(0.0, 0.0);
        let K = crank(H, 0.40, q1) as thigh;
        let F = crank(K, 0.35, q2, thigh) as shank;
        let G1 = point(thigh, from H, 0.17, 4 deg);
        let G2 = point(shank, from K, 0.15, -6 deg);
        mass thigh { m = 7.0, at = G1, j = 0.11 };
        mass shank { m = 3.2, at = G2, j = 0.045 };
        gravity (0.0, -9.81);
        force at F = (30.0, 250.0);
    }
}

fn unit(a: f64) -> Vector2<f64> {
    Vector2::new(a.cos(), a.sin())
}

fn perp(v: Vector2<f64>) -> Vector2<f64> {
    Vector2::new(-v.y, v.x)
}

fn cross(a: Vector2<f64>, b: Vector2<f64>) -> f64 {
    a.x * b.y - a.y * b.x
}

/// A point of a link turning at angle `th` (rates `w`, `al`) at `r` (m) from
/// a joint moving with `(p, v, a)`, `phase` (rad) from the link's axis:
/// position, velocity and acceleration.
fn carried(
    (p, v, a): (Vector2<f64>, Vector2<f64>, Vector2<f64>),
    r: f64,
    phase: f64,
    (th, w, al): (f64, f64, f64),
) -> (Vector2<f64>, Vector2<f64>, Vector2<f64>) {
    let d = unit(th + phase) * r;
    (p + d, v + perp(d) * w, a + perp(d) * al - d * (w * w))
}

/// The leg worked by hand: `(foot, foot velocity, foot acceleration, hip
/// torque, knee torque, knee reaction on the shank)`. `absolute_knee`: the
/// mistake of reading `q2` as the shank's absolute angle.
#[allow(clippy::type_complexity)]
fn leg_by_hand(
    q: (f64, f64),
    w: (f64, f64),
    al: (f64, f64),
    absolute_knee: bool,
) -> (
    Point2<f64>,
    Vector2<f64>,
    Vector2<f64>,
    f64,
    f64,
    Vector2<f64>,
) {
    let z = Vector2::zeros();
    let t1 = (q.0, w.0, al.0);
    let t2 = if absolute_knee {
        (q.1, w.1, al.1)
    } else {
        (q.0 + q.1, w.0 + w.1, al.0 + al.1)
    };
    let k = carried((z, z, z), 0.40, 0.0, t1);
    let g1 = carried((z, z, z), 0.17, 4f64.to_radians(), t1);
    let f = carried(k, 0.35, 0.0, t2);
    let g2 = carried(k, 0.15, (-6f64).to_radians(), t2);
    let g = Vector2::new(0.0, GY);
    let load = Vector2::new(30.0, 250.0);
    // Shank: R (from the thigh, at K) + m2 g + load = m2 a_G2; about K:
    // tau2 + (G2 - K) x m2 g + (F - K) x load = J2 al2 + (G2 - K) x m2 a_G2.
    let (m2, j2) = (3.2, 0.045);
    let r_knee = g2.2 * m2 - g * m2 - load;
    let tau2 = j2 * t2.2 + cross(g2.0 - k.0, (g2.2 - g) * m2) - cross(f.0 - k.0, load);
    // Thigh about H: tau1 - tau2 + (K - H) x (-R) + (G1 - H) x m1 g
    // = J1 al1 + (G1 - H) x m1 a_G1.
    let (m1, j1) = (7.0, 0.11);
    let tau1 = j1 * t1.2 + cross(g1.0, (g1.2 - g) * m1) + tau2 + cross(k.0, r_knee);
    (Point2::from(f.0), f.1, f.2, tau1, tau2, r_knee)
}

/// `|got - want| <= TOL * scale`.
fn close(got: f64, want: f64, scale: f64, what: &str) {
    assert!(
        (got - want).abs() <= TOL * scale,
        "{what}: {got} vs {want} (scale {scale})"
    );
}

fn close_v(got: Vector2<f64>, want: Vector2<f64>, what: &str) {
    let scale = want.norm().max(got.norm());
    close(got.x, want.x, scale, what);
    close(got.y, want.y, scale, what);
}

#[test]
fn a_knee_motor_on_the_thigh_gives_the_hand_worked_leg() {
    // Proves: the relative crank's tip, link angle, rates, accelerations and
    // the relative driving torque (and its reaction on the thigh, seen in the
    // hip torque) agree with the chain and Newton-Euler worked by hand, over
    // a grid of hip and knee angles.
    let leg = Leg::<f64>::default();
    let (w, al) = ((2.5, -4.0), (-30.0, 45.0));
    let mut checked = 0;
    for i in 0..24 {
        for k in 0..24 {
            let q = (
                (-170.0 + 15.0 * i as f64).to_radians(),
                (-175.0 + 15.2 * k as f64).to_radians(),
            );
            let s = leg
                .solve(
                    &LegInput { q1: q.0, q2: q.1 },
                    &LegInput { q1: w.0, q2: w.1 },
                    &LegInput { q1: al.0, q2: al.1 },
                )
                .unwrap();
            let (foot, v, a, tau1, tau2, r_knee) = leg_by_hand(q, w, al, false);
            let (p, vel, acc, f) = (&s.position, &s.velocity, &s.acceleration, &s.forces);
            close_v(p.F.coords, foot.coords, "foot");
            close_v(vel.F, v, "foot velocity");
            close_v(acc.F, a, "foot acceleration");
            // The shank's angle, compared on the circle (both ends of
            // (-pi, pi] name the same direction).
            let turn = p.shank - (q.0 + q.1);
            close(
                turn.sin().atan2(turn.cos()),
                0.0,
                std::f64::consts::PI,
                "shank angle",
            );
            close(vel.shank, w.0 + w.1, 10.0, "shank rate");
            close(acc.shank, al.0 + al.1, 100.0, "shank acceleration");
            let scale = tau1.abs().max(tau2.abs()).max(100.0);
            close(f.drive_q1, tau1, scale, "hip torque");
            close(f.drive_q2, tau2, scale, "knee torque");
            close_v(f.r_thigh_shank, r_knee, "knee reaction");
            assert!(f.power_residual <= TOL, "{}", f.power_residual);
            checked += 1;
        }
    }
    assert_eq!(checked, 576);
    // The checker can fail: the knee angle read as absolute.
    let q = (0.7, -1.1);
    let s = leg
        .solve(
            &LegInput { q1: q.0, q2: q.1 },
            &LegInput { q1: w.0, q2: w.1 },
            &LegInput { q1: al.0, q2: al.1 },
        )
        .unwrap();
    let (foot, ..) = leg_by_hand(q, w, al, true);
    assert!((s.position.F - foot).norm() > 0.1);
}

#[test]
fn the_knee_torque_reacts_on_the_thigh() {
    // Proves: the knee motor's torque acts on the shank and its reaction on
    // the thigh. With the leg at rest and only the foot force, the hip torque
    // is the moment of the foot force about the hip alone: leaving the
    // reaction off the thigh would give that moment plus the knee torque.
    let leg = Leg::<f64>::default();
    let zero = LegInput { q1: 0.0, q2: 0.0 };
    let q = (0.4, -1.3);
    let s = leg
        .solve(&LegInput { q1: q.0, q2: q.1 }, &zero, &zero)
        .unwrap();
    let p = &s.position;
    let g = Vector2::new(0.0, GY);
    let load = Vector2::new(30.0, 250.0);
    // Statics of the whole leg about H: hip torque balances the load's and
    // both weights' moments.
    let moment =
        cross(p.F.coords, load) + cross(p.G1.coords, g * 7.0) + cross(p.G2.coords, g * 3.2);
    let f = &s.forces;
    close(f.drive_q1, -moment, moment.abs(), "hip torque at rest");
    assert!(f.drive_q2.abs() > 10.0, "knee torque {}", f.drive_q2);
    assert!((f.drive_q1 + moment + f.drive_q2).abs() > 10.0);
}

mechanism! {
    /// A telescoping arm (m, kg, N): the arm turns about the ground point O
    /// by `q`; a block slides along a guide carried by the arm through O,
    /// driven by `s` (its distance from O along the arm).
    pub Telescope {
        dof 2;
        let O = ground(0.0, 0.0);
        let E = crank(O, 0.3, q) as arm;
        let g = guide(O, arm);
        let P = slider(g, s) as block;
        let Ga = point(arm, from O, 0.12, 0 deg);
        mass arm { m = 2.0, at = Ga, j = 0.02 };
        mass block { m = 1.5, at = P, j = 0.004 };
        gravity (0.0, -9.81);
        force at P on block = (-12.0, 5.0);
    }
}

#[test]
fn a_slider_on_a_turning_arm_gives_the_hand_worked_drive() {
    // Proves: a slider on a guide carried by a moving link moves with the
    // guide (Coriolis term included) and its driving force is the relative
    // one along the guide; the arm's torque carries the block's reaction.
    let arm = Telescope::<f64>::default();
    let g = Vector2::new(0.0, GY);
    let load = Vector2::new(-12.0, 5.0);
    for i in 0..36 {
        for k in 0..6 {
            let (q, s) = (
                (-175.0 + 10.0 * i as f64).to_radians(),
                0.05 + 0.1 * k as f64,
            );
            let (w, sd, al, sdd) = (1.7, -0.8, 6.0, 2.5);
            let sol = arm
                .solve(
                    &TelescopeInput { q, s },
                    &TelescopeInput { q: w, s: sd },
                    &TelescopeInput { q: al, s: sdd },
                )
                .unwrap();
            let (u, n) = (unit(q), perp(unit(q)));
            let p = u * s;
            let v = u * sd + n * (s * w);
            let a = u * (sdd - s * w * w) + n * (s * al + 2.0 * sd * w);
            close_v(sol.position.P.coords, p, "block");
            close_v(sol.velocity.P, v, "block velocity");
            close_v(sol.acceleration.P, a, "block acceleration");
            // Block along the guide: F_drive + (m g + load) . u = m a . u.
            let drive = 1.5 * (a - g).dot(&u) - load.dot(&u);
            // Whole arm and block about O.
            let ga = carried(
                (Vector2::zeros(), Vector2::zeros(), Vector2::zeros()),
                0.12,
                0.0,
                (q, w, al),
            );
            let torque =
                0.02 * al + 0.004 * al + cross(ga.0, (ga.2 - g) * 2.0) + cross(p, (a - g) * 1.5)
                    - cross(p, load);
            let f = &sol.forces;
            close(f.drive_s, drive, drive.abs().max(10.0), "slide force");
            close(f.drive_q, torque, torque.abs().max(10.0), "arm torque");
            assert!(f.power_residual <= TOL, "{}", f.power_residual);
        }
    }
}

mechanism! {
    /// The 2R leg's kinematics with the knee angle read from an encoder as
    /// `(cos, sin)`.
    pub LegEncoder {
        dof 2;
        let H = ground(0.0, 0.0);
        let K = crank(H, 0.40, q1) as thigh;
        let F = crank(K, 0.35, q2 as cos_sin, thigh) as shank;
    }
}

#[test]
fn a_relative_encoder_pair_gives_the_angle_form() {
    // Proves: the relative crank's `(cos, sin)` form (an encoder on the knee)
    // places the foot where the angle form does, for pairs of any positive
    // scale.
    let leg = LegEncoder::<f64>::default();
    for i in 0..72 {
        let (q1, q2) = (0.3 + 0.05 * i as f64, (5.0 * i as f64 - 180.0).to_radians());
        let by_angle = leg.position(&LegEncoderInput { q1, q2 }).unwrap();
        for scale in [1.0, 3.5e-3, 2.0e4] {
            let cs = LegEncoderCosSin {
                q1,
                q2: mechanism::driver::crank::CosSin {
                    cos: q2.cos() * scale,
                    sin: q2.sin() * scale,
                },
            };
            let by_pair = leg.position_cos_sin(&cs).unwrap();
            close_v(by_pair.F.coords, by_angle.F.coords, "foot from the pair");
        }
    }
}

mechanism! {
    /// A five-bar with both motors on the left (m, kg, N): the shoulder
    /// motor on the ground at O1, the elbow motor carried by the upper arm
    /// at A, and an RRR closing the loop to the ground pivot O2. A load at C.
    pub StackedFiveBar {
        dof 2;
        let O1 = ground(0.0, 0.0);
        let O2 = ground(0.25, 0.0);
        let A = crank(O1, 0.12, q1) as upper;
        let B = crank(A, 0.10, q2, upper) as fore;
        let C = rrr(B, 0.22, O2, 0.20, left) as (l3, l4);
        let G1 = point(upper, from O1, 0.06, 0 deg);
        let G2 = point(fore, from A, 0.05, 8 deg);
        let G3 = point(l3, from B, 0.11, -5 deg);
        let G4 = point(l4, from O2, 0.1, 0 deg);
        mass upper { m = 0.8, at = G1, j = 0.002 };
        mass fore { m = 0.5, at = G2, j = 0.0011 };
        mass l3 { m = 0.6, at = G3, j = 0.0026 };
        mass l4 { m = 0.55, at = G4, j = 0.0019 };
        gravity (0.0, -9.81);
        force at C on l3 = (14.0, -30.0);
    }
}

/// Every body of the stacked five-bar in equilibrium (Newton-Euler with the
/// generated reactions, each at the point its doc comment names) and the
/// power balance; `drop_reaction`: the mistake of leaving the elbow motor's
/// reaction off the upper arm.
fn check_stacked(s: &StackedFiveBarSolution, w: (f64, f64), drop_reaction: bool) {
    use crate::equilibrium::{inertial, power_balances, Body, G};
    let (p, v, a, f) = (&s.position, &s.velocity, &s.acceleration, &s.forces);
    let load = Vector2::new(14.0, -30.0);
    let elbow = if drop_reaction { 0.0 } else { -f.drive_q2 };
    Body::default()
        .force(p.O1, f.r_ground_upper)
        .force(p.A, -f.r_upper_fore)
        .couple(f.drive_q1)
        .couple(elbow)
        .inertia(0.8, 0.002, p.G1, a.G1, a.upper, G)
        .balances("upper arm");
    Body::default()
        .force(p.A, f.r_upper_fore)
        .force(p.B, -f.r_fore_l3)
        .couple(f.drive_q2)
        .inertia(0.5, 0.0011, p.G2, a.G2, a.fore, G)
        .balances("forearm");
    Body::default()
        .force(p.B, f.r_fore_l3)
        .force(p.C, -f.r_l3_l4)
        .force(p.C, load)
        .inertia(0.6, 0.0026, p.G3, a.G3, a.l3, G)
        .balances("l3");
    Body::default()
        .force(p.O2, f.r_ground_l4)
        .force(p.C, f.r_l3_l4)
        .inertia(0.55, 0.0019, p.G4, a.G4, a.l4, G)
        .balances("l4");
    power_balances(
        &[
            f.drive_q1 * w.0,
            f.drive_q2 * w.1,
            load.dot(&v.C),
            inertial(0.8, 0.002, v.G1, a.G1, v.upper, a.upper, G),
            inertial(0.5, 0.0011, v.G2, a.G2, v.fore, a.fore, G),
            inertial(0.6, 0.0026, v.G3, a.G3, v.l3, a.l3, G),
            inertial(0.55, 0.0019, v.G4, a.G4, v.l4, a.l4, G),
        ],
        "StackedFiveBar",
    );
}

#[test]
fn an_elbow_motor_inside_a_closed_loop_balances_every_body() {
    // Proves: a crank carried by a crank link, inside a loop closed by an
    // RRR, gives reactions and relative driving torques under which every
    // body is in equilibrium and the power balances, over a grid of both
    // motor angles (poses that cannot close give the RRR's typed error).
    let m = StackedFiveBar::<f64>::default();
    let (w, al) = ((3.0, -2.0), (12.0, 25.0));
    let mut checked = 0;
    for i in 0..30 {
        for k in 0..30 {
            let q = StackedFiveBarInput {
                q1: (12.0 * i as f64).to_radians(),
                q2: (12.0 * k as f64 - 180.0).to_radians(),
            };
            let rates = StackedFiveBarInput { q1: w.0, q2: w.1 };
            let accels = StackedFiveBarInput { q1: al.0, q2: al.1 };
            match m.solve(&q, &rates, &accels) {
                Ok(s) if s.forces.condition > 0.05 => {
                    check_stacked(&s, w, false);
                    if checked == 0 {
                        let mistake = std::panic::catch_unwind(|| check_stacked(&s, w, true));
                        assert!(mistake.is_err(), "the checker missed a dropped reaction");
                    }
                    checked += 1;
                }
                Ok(_) => {}
                Err(e) => assert_eq!(e.group, "C", "{e}"),
            }
        }
    }
    assert!(checked >= 200, "only {checked} poses checked");
}

mechanism! {
    /// The 2R leg's kinematics with the knee's encoder zero 30 deg from the
    /// thigh's axis.
    pub LegZero {
        dof 2;
        let H = ground(0.0, 0.0);
        let K = crank(H, 0.40, q1) as thigh;
        let F = crank(K, 0.35, q2, thigh, 30 deg) as shank;
    }
}

#[test]
fn a_carried_crank_measures_its_input_from_its_zero_angle() {
    // Proves: `crank(K, r, q, CARRIER, zero)` turns the link by `zero + q`
    // from the carrier's axis: the foot is where the hand-worked chain puts
    // it at the knee angle plus 30 deg, its rates unchanged by the zero.
    let leg = LegZero::<f64>::default();
    let (w, al) = ((1.5, -2.0), (4.0, 7.0));
    for i in 0..36 {
        let q = (0.2 + 0.1 * i as f64, (10.0 * i as f64 - 175.0).to_radians());
        let zero = 30f64.to_radians();
        let s = leg.position(&LegZeroInput { q1: q.0, q2: q.1 }).unwrap();
        let v = leg
            .velocity(&s, &LegZeroInput { q1: w.0, q2: w.1 })
            .unwrap();
        let a = leg
            .acceleration(&s, &v, &LegZeroInput { q1: al.0, q2: al.1 })
            .unwrap();
        let (foot, fv, fa, ..) = leg_by_hand((q.0, q.1 + zero), w, al, false);
        close_v(s.F.coords, foot.coords, "foot");
        close_v(v.F, fv, "foot velocity");
        close_v(a.F, fa, "foot acceleration");
    }
}
