//! Inverse kinematics of the five-bar robot (m, kg, N): its end point
//! driven round a circle (centre (0.04, 0.19), radius 0.03, one turn per
//! second), the two motor angles, rates and accelerations out, and the
//! motor torques that hold the end point on its path with the arms' masses,
//! gravity and a 2 N payload.
//!
//! The generated `FiveBarIk` (written as drawn, `examples/common/scenes.rs`)
//! takes the end point as its input. Its force analysis gives the force a
//! positioner would need at the end point, `D = (drive_x, drive_y)`, and
//! the torques of the two motors declared (`motor q1 = angle(arm1);`) that
//! supply it, `drive_q1` and `drive_q2` (`tau = J^T D` by virtual work).
//! Each row is checked
//! against the forward five-bar (`FiveBar`, the motors as cranks): the
//! forward position of the motor angles found is the end point given
//! (`fwd_err`, m). An end point out of reach is a typed error.
//!
//! Run: `cargo run --release --example five_bar_ik` (table) or with `-- --csv`.
#[macro_use]
#[path = "common/cli.rs"]
mod cli;
mod common;
use common::scenes::{FiveBar, FiveBarIk, FiveBarIkInput, FiveBarInput};

fn main() {
    let args = cli::parse(
        "five_bar_ik",
        "Inverse kinematics of the five-bar robot: end point round a circle in, motor angles, rates, accelerations and torques out.",
        &[cli::CSV],
    );
    let csv = args.flag("--csv");
    let (ik, fk) = (FiveBarIk::default(), FiveBar::<f64>::default());
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
            let q = FiveBarInput {
                q1: s.position.arm1,
                q2: s.position.arm2,
            };
            let fwd = fk.position(&q)?;
            let err = (fwd.P.x - p.x).hypot(fwd.P.y - p.y);
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
