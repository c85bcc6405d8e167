//! The 2R leg of `examples/two_r_leg.rs` (m, kg, N, s): a hip motor on the
//! ground and a knee motor carried by the thigh, walking a gait given as
//! joint trajectories, with the ground's reaction on the foot in stance.
#![allow(dead_code)]

use mechanism::mechanism;

mechanism! {
    /// A planar 2R leg (m, kg, N): the hip motor turns the thigh about the
    /// hip H (fixed here: the body held); the knee motor, on the thigh,
    /// turns the shank about the knee K by `knee`, measured from the thigh's
    /// axis (0: the leg straight, positive counter-clockwise). The foot F
    /// takes the ground's reaction `(fx, fy)` (a load, zero in swing).
    pub Leg {
        units { length = "m", force = "N", mass = "kg" }
        dof 2;
        loads { fx = 0.0, fy = 0.0 }
        let H = ground(0.0, 0.0);
        let K = crank(H, 0.40, hip) as thigh;
        let F = crank(K, 0.38, knee, thigh) as shank;
        let G1 = point(thigh, from H, 0.17, 3 deg);
        let G2 = point(shank, from K, 0.16, -4 deg);
        mass thigh { m = 6.5, at = G1, j = 0.095 };
        mass shank { m = 3.0, at = G2, j = 0.042 };
        gravity (0.0, -9.81);
        force at F = (fx, fy);
    }
}

/// Gait period (s).
pub const PERIOD: f64 = 1.2;
/// Fraction of the period with the foot on the ground (stance).
pub const STANCE: f64 = 0.6;
/// Body weight carried by this leg in stance (N).
pub const SUPPORT: f64 = 350.0;

/// One joint's trajectory `mean + amp sin(2 pi t / PERIOD + phase)` (rad):
/// angle, rate (rad/s) and acceleration (rad/s^2) at time `t` (s).
fn harmonic(mean: f64, amp: f64, phase: f64, t: f64) -> (f64, f64, f64) {
    let w = 2.0 * std::f64::consts::PI / PERIOD;
    let x = w * t + phase;
    (
        mean + amp * x.sin(),
        amp * w * x.cos(),
        -amp * w * w * x.sin(),
    )
}

/// The gait at time `t` (s): `(angles, rates, accelerations, loads)`, the
/// hip swinging about straight down (-90 deg) and the knee bending
/// (negative: the shank folds backwards), the foot loaded in stance with the
/// supported weight and a braking-then-propulsive horizontal force.
pub fn gait(t: f64) -> (LegInput<f64>, LegInput<f64>, LegInput<f64>, LegLoads<f64>) {
    let (h, hd, hdd) = harmonic(-90f64.to_radians(), 25f64.to_radians(), 0.0, t);
    let (k, kd, kdd) = harmonic(-35f64.to_radians(), 30f64.to_radians(), -1.2, t);
    let phase = (t / PERIOD).fract();
    let loads = if phase < STANCE {
        let s = phase / STANCE;
        let shape = (std::f64::consts::PI * s).sin();
        LegLoads {
            fx: -60.0 * (2.0 * std::f64::consts::PI * s).sin(),
            fy: SUPPORT * shape,
        }
    } else {
        LegLoads { fx: 0.0, fy: 0.0 }
    };
    (
        LegInput { hip: h, knee: k },
        LegInput { hip: hd, knee: kd },
        LegInput {
            hip: hdd,
            knee: kdd,
        },
        loads,
    )
}

/// Pictures: the leg drawn along the gait, its kinematics and the motor
/// torques and reactions over one period.
pub fn plots(dir: &std::path::Path) -> Result<Vec<std::path::PathBuf>, mechanism_plot::PlotError> {
    use mechanism_plot::any;
    let m = Leg::<f64>::default();
    let n = 96;
    let times: Vec<f64> = (0..n).map(|k| PERIOD * k as f64 / n as f64).collect();
    let solved: Vec<_> = times
        .iter()
        .map(|&t| {
            let (q, w, a, l) = gait(t);
            (t, m.solve(&q, &w, &a, &l).ok())
        })
        .collect();
    let title = "2R leg: hip motor on the ground, knee motor on the thigh";
    let x = ("time", "s");
    let kin: Vec<_> = solved
        .iter()
        .map(|(t, s)| {
            (
                *t,
                s.as_ref().map(|s| (s.position, s.velocity, s.acceleration)),
            )
        })
        .collect();
    let fig = any::kinematics_chart(title, x, &kin, &["F"])?;
    let forces: Vec<_> = solved
        .iter()
        .map(|(t, s)| (*t, s.as_ref().map(|s| s.forces)))
        .collect();
    let torques = any::force_chart(title, x, &forces)?;
    let poses: Vec<_> = kin.iter().map(|(t, r)| (*t, r.map(|r| r.0))).collect();
    let sk = any::sketch_with::<Leg<f64>, _>(title, &poses, &["F"], |t| format!("t = {t:.2} s"))?;
    let files = [
        dir.join("kinematics.svg"),
        dir.join("forces.svg"),
        dir.join("drawing.svg"),
        dir.join("animation.svg"),
    ];
    fig.write(&files[0])?;
    torques.write(&files[1])?;
    sk.write_drawing(n / 4, &files[2])?;
    sk.write_animation(PERIOD * 4.0, &files[3])?;
    Ok(files.to_vec())
}
