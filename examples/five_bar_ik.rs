//! Inverse kinematics of the five-bar robot (m, kg, N): its end point
//! driven round a circle (centre (0.04, 0.19), radius 0.03, one turn per
//! second), the two motor angles, rates and accelerations out, and the
//! motor torques that hold the end point on its path with the arms' masses,
//! gravity and a 2 N payload.
//!
//! The generated `FiveBarIk` (written as drawn, below)
//! takes the end point as its input. Its force analysis gives the force a
//! positioner would need at the end point, `D = (drive_x, drive_y)`, and
//! the torques of the two motors declared (`motor q1 = angle(arm1);`) that
//! supply it, `drive_q1` and `drive_q2` (`tau = J^T D` by virtual work).
//! Each row is checked
//! against the forward five-bar, worked out here by plain geometry (the
//! distal links' circles about the elbows, [`forward`]): the forward
//! position of the motor angles found is the end point given (`fwd_err`,
//! m). An end point out of reach is a typed error.
//!
//! Run: `cargo run --release --example five_bar_ik` (table) or with `-- --csv`.
#[macro_use]
#[path = "common/cli.rs"]
mod cli;
mod common;
use mechanism::mechanism;

mechanism! {
    /// The five-bar robot of the `five_bar` example given its end point (m, kg, N):
    /// inverse kinematics, written as drawn. The drawing is the robot at
    /// q1 = 100 deg, q2 = 45 deg (coordinates to 20 digits, so the lengths
    /// read from it are 0.1 and 0.16 to the last bit); the end point `P`
    /// is the input, `input x = P.x; input y = P.y;`, and each motor link
    /// hangs on it by an RRR whose elbow is on the side drawn. Masses at
    /// the links' midpoints (`G1`, `G2`, `H1`, `H2`, drawn as points of
    /// their links) and on the effector (`P_effector`, the body moving
    /// with `P`: a pen holder), gravity along -y and a 2 N payload at `P`.
    /// The motors turning `arm1` and `arm2` about the base pivots hold `P`
    /// on its path: their torques are the forces' `drive_q1`, `drive_q2`.
    pub FiveBarIk {
        units { length = "m", force = "N", mass = "kg" }
        joints {
            O1 = (0.0, 0.0),
            O2 = (0.08, 0.0),
            A = (-0.017364817766693034885, 0.098480775301220805937),
            C = (0.15071067811865475244, 0.07071067811865475244),
            P = (0.088752052427120438854, 0.2182272151659171658),
            G1 = (-0.0086824088833465174425, 0.049240387650610402968),
            G2 = (0.11535533905932737622, 0.03535533905932737622),
            H1 = (0.035693617330213701984, 0.15835399523356898587),
            H2 = (0.11973136527288759565, 0.14446894664228595912),
        }
        links {
            ground = [O1, O2],
            arm1 = [O1, A, G1],
            arm2 = [O2, C, G2],
            forearm1 = [A, P, H1],
            forearm2 = [C, P, H2],
        }
        input x = P.x;
        input y = P.y;
        motor q1 = angle(arm1);
        motor q2 = angle(arm2);
        mass arm1 { m = 0.12, at = G1, j = 1.1e-4 };
        mass arm2 { m = 0.12, at = G2, j = 1.1e-4 };
        mass forearm1 { m = 0.09, at = H1, j = 2.0e-4 };
        mass forearm2 { m = 0.09, at = H2, j = 2.0e-4 };
        mass P_effector { m = 0.05, at = P };
        gravity (0.0, -9.81);
        force at P on P_effector = (0.0, -2.0);
    }
}

/// The forward five-bar by plain geometry (m, rad): the elbows
/// `A = O1 + 0.1 (cos q1, sin q1)` and `C = O2 + 0.1 (cos q2, sin q2)`, and
/// the end point where the distal links' circles (radius 0.16 about each
/// elbow) meet, on the left of the directed line A -> C (the side drawn).
/// `None` where the circles do not meet.
fn forward(q1: f64, q2: f64) -> Option<(f64, f64)> {
    let (proximal, distal, base) = (0.1, 0.16, 0.08);
    let a = (proximal * q1.cos(), proximal * q1.sin());
    let c = (base + proximal * q2.cos(), proximal * q2.sin());
    let (dx, dy) = (c.0 - a.0, c.1 - a.1);
    let d = dx.hypot(dy);
    let h2 = distal * distal - d * d / 4.0;
    if d == 0.0 || h2 < 0.0 {
        return None;
    }
    let h = h2.sqrt() / d;
    // Midpoint of A-C plus h times A->C turned a quarter turn to the left.
    Some((a.0 + dx / 2.0 - h * dy, a.1 + dy / 2.0 + h * dx))
}

fn main() {
    let args = cli::parse(
        "five_bar_ik",
        "Inverse kinematics of the five-bar robot: end point round a circle in, motor angles, rates, accelerations and torques out.",
        &[cli::CSV],
    );
    let csv = args.flag("--csv");
    let ik = FiveBarIk::default();
    let names = [
        "t_s", "x", "y", "q1_deg", "q2_deg", "w1", "w2", "al1", "al2", "tau1", "tau2", "fwd_err",
    ];
    if csv {
        outln!("{}", names.join(","));
    } else {
        outln!(
            "Five-bar given its end point: circle centre (0.04, 0.19) m, radius 0.03 m, 1 turn/s"
        );
        outln!("(motor rates rad/s, accelerations rad/s^2, torques N m; fwd_err: |forward(q) - P| in m)");
        outln!("{}", common::header(&names, 10));
    }
    let (c, r, w) = ((0.04, 0.19), 0.03, 2.0 * std::f64::consts::PI);
    for k in 0..=12 {
        let t = k as f64 / 12.0;
        let (cs, sn) = ((w * t).cos(), (w * t).sin());
        let p = FiveBarIkInput {
            x: c.0 + r * cs,
            y: c.1 + r * sn,
        };
        let v = FiveBarIkInput {
            x: -r * w * sn,
            y: r * w * cs,
        };
        let a = FiveBarIkInput {
            x: -r * w * w * cs,
            y: -r * w * w * sn,
        };
        let row = ik.solve(&p, &v, &a).and_then(|s| {
            let f = ik.forces(&s.position, &s.velocity, &s.acceleration)?;
            let fwd = forward(s.position.arm1, s.position.arm2);
            let err = fwd.map_or(f64::INFINITY, |(x, y)| (x - p.x).hypot(y - p.y));
            let (pos, vel, acc) = (&s.position, &s.velocity, &s.acceleration);
            Ok([
                t,
                p.x,
                p.y,
                pos.arm1.to_degrees(),
                pos.arm2.to_degrees(),
                vel.arm1,
                vel.arm2,
                acc.arm1,
                acc.arm2,
                f.drive_q1,
                f.drive_q2,
                err,
            ])
        });
        match row {
            Ok(row) if csv => outln!("{}", common::csv_row(&row)),
            Ok(row) => outln!("{}", common::table_row(&row, 10, 4)),
            Err(e) if !csv => outln!("{t:>10.4}   {e}"),
            Err(_) => {}
        }
    }
    if !csv {
        let out = FiveBarIkInput { x: 0.04, y: 0.30 };
        match ik.position(&out) {
            Ok(_) => outln!("(0.04, 0.30) m: reachable"),
            Err(e) => outln!("(0.04, 0.30) m is out of reach: {e}"),
        }
    }
}
