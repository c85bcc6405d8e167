//! A planar 2R leg (m, kg, N, s): a hip motor on the ground and a knee motor
//! carried by the thigh (`crank(K, r, knee, thigh)`: the knee angle is
//! measured from the thigh, and the knee torque acts on the shank and
//! reacts on the thigh). Over one gait period it prints the foot's path, the
//! two motor torques, the knee's reaction and the motors' powers; the foot
//! carries the ground's reaction in stance.
//!
//! Run: `cargo run --release --example two_r_leg` (table) or with `-- --csv`
//! (17 significant digits). Also writes SVG pictures (kinematics, torques, a
//! drawing, an animation) to `target/plots/two_r_leg/`.
#[macro_use]
#[path = "common/cli.rs"]
mod cli;
mod common;
use common::leg::{gait, Leg, PERIOD};

fn main() {
    let args = cli::parse(
        "two_r_leg",
        "A 2R leg with a knee motor on the thigh: foot path, motor torques and powers over a gait.",
        &[cli::CSV],
    );
    let csv = args.flag("--csv");
    let m = Leg::<f64>::default();
    let names = [
        "t_s",
        "hip_deg",
        "knee_deg",
        "foot_x",
        "foot_y",
        "foot_vx",
        "foot_vy",
        "fx",
        "fy",
        "tau_hip",
        "tau_knee",
        "knee_rx",
        "knee_ry",
        "power_hip",
        "power_knee",
    ];
    if csv {
        outln!("{}", names.join(","));
    } else {
        outln!("2R leg: thigh 0.40 m, shank 0.38 m; gait period {PERIOD} s; torques in N m (counter-clockwise positive, on the driven link), powers in W");
        outln!("{}", common::header(&names, 10));
    }
    let n = 60;
    for k in 0..n {
        let t = PERIOD * k as f64 / n as f64;
        let (q, w, a, loads) = gait(t);
        match m.solve(&q, &w, &a, &loads) {
            Ok(s) => {
                let (p, v, f) = (&s.position, &s.velocity, &s.forces);
                let row = [
                    t,
                    q.hip.to_degrees(),
                    q.knee.to_degrees(),
                    p.F.x,
                    p.F.y,
                    v.F.x,
                    v.F.y,
                    loads.fx,
                    loads.fy,
                    f.drive_hip,
                    f.drive_knee,
                    f.r_thigh_shank.x,
                    f.r_thigh_shank.y,
                    f.drive_hip * w.hip,
                    f.drive_knee * w.knee,
                ];
                if csv {
                    outln!("{}", common::csv_row(&row));
                } else {
                    outln!("{}", common::table_row(&row, 10, 4));
                }
            }
            Err(e) if !csv => outln!("{t:>10.4}   {e}"),
            Err(_) => {}
        }
    }
    common::plots::write_and_report("two_r_leg", common::leg::plots);
}
