//! The Stephenson III six-bar (m, kg): a triad (class III
//! group) driven by link 6's angle. Shared by `examples/stephenson.rs` and
//! its tests (`tests/examples/stephenson.rs`).
#![allow(dead_code)]

use mechanism::mechanism;

mechanism! {
    /// Stephenson III six-bar (m): ground pivots O2 = (0, 0), O4 = (0.30, 0),
    /// O6 = (0.05, 0.42); link 6 (O6-C, 0.24) is driven by its angle `phi`
    /// (rad, counter-clockwise from +x). The triad: crank2 O2-A (0.08),
    /// rocker O4-B (0.20), link5 C-P (0.28) on the ternary coupler A-B
    /// (0.26) with P at 0.15 from A, 40 deg counter-clockwise from A -> B;
    /// its assembly is the one with, at phi = -49.48 deg, A near
    /// (-0.061, -0.052), B near (0.137, 0.116), P near (-0.036, 0.096).
    /// Link 6 swings between about -50.4365 deg and -2.6334 deg on it.
    #[self_test]
    pub Stephenson {
        units { length = "m", force = "N", mass = "kg" }
        params { m2 = 0.4, j2 = 2.2e-4, m3 = 1.2, j3 = 7.5e-3, m4 = 0.8, j4 = 2.7e-3,
                 m5 = 1.0, j5 = 6.5e-3, m6 = 0.9, j6 = 4.3e-3 }
        loads { fp = 0.0 }
        dof 1;
        let O2 = ground(0.0, 0.0);
        let O4 = ground(0.30, 0.0);
        let O6 = ground(0.05, 0.42);
        let C = crank(O6, 0.24, phi) as link6;
        let (A, B, P) = triad(O2, 0.08, O4, 0.20, C, 0.28, 0.26, 0.15, 40 deg,
                              phi = -49.48 deg, (-0.061, -0.052), (0.137, 0.116), (-0.036, 0.096))
            as (crank2, rocker, link5, coupler);
        let G2 = point(crank2, from O2, 0.04, 0 deg);
        let G3 = point(coupler, from A, (0.13, 0.03));
        let G4 = point(rocker, from O4, 0.10, 0 deg);
        let G5 = point(link5, from C, 0.14, 0 deg);
        let G6 = point(link6, from O6, 0.12, 0 deg);
        mass crank2 { m = m2, at = G2, j = j2 };
        mass coupler { m = m3, at = G3, j = j3 };
        mass rocker { m = m4, at = G4, j = j4 };
        mass link5 { m = m5, at = G5, j = j5 };
        mass link6 { m = m6, at = G6, j = j6 };
        gravity (0.0, -9.81);
        force at P on coupler = (0.0, fp);
        range phi = (-50.43 deg, -2.64 deg);
        outputs { O2, O4, O6, A, B, P, C, crank2, coupler, rocker, link5, link6 }
    }
}

/// The input at which the assembly is given (rad): -49.48 deg.
pub fn stated_phi() -> f64 {
    (-49.48f64).to_radians()
}

/// Link 6's speed (rad/s) and angular acceleration (rad/s^2).
pub const PHI_DOT: f64 = 1.5;
/// See [`PHI_DOT`].
pub const PHI_DDOT: f64 = -0.5;

/// The position at `phi` (rad) on the assembly of `from` (at `from_phi`),
/// followed by `position_near` in steps of at most 0.25 deg.
pub fn follow(
    m: &Stephenson<f64>,
    from: &StephensonPosition<f64>,
    from_phi: f64,
    phi: f64,
) -> Result<StephensonPosition<f64>, mechanism::Error> {
    let steps = ((phi - from_phi).abs() / 0.25f64.to_radians())
        .ceil()
        .max(1.0) as usize;
    let mut pos = *from;
    for k in 1..=steps {
        let q = from_phi + (phi - from_phi) * k as f64 / steps as f64;
        pos = m.position_near(&pos, &StephensonInput { phi: q })?;
    }
    Ok(pos)
}

/// Link 6's swing on the stated assembly (rad): from the stated input,
/// followed down and up in 0.1 deg steps until `position_near` fails, each
/// end then bisected to 1e-13 rad between the last input it assembles at and
/// the first it does not.
pub fn swing(m: &Stephenson<f64>) -> (f64, f64) {
    let q0 = stated_phi();
    let start = m
        .position(&StephensonInput { phi: q0 })
        .expect("the stated assembly exists at the stated input");
    let end = |dir: f64| {
        let step = dir * 0.1f64.to_radians();
        let (mut ok, mut pos) = (q0, start);
        let mut bad = loop {
            let q = ok + step;
            match m.position_near(&pos, &StephensonInput { phi: q }) {
                Ok(p) => (ok, pos) = (q, p),
                Err(_) => break q,
            }
        };
        while (bad - ok).abs() > 1e-13 {
            let mid = 0.5 * (ok + bad);
            match m.position_near(&pos, &StephensonInput { phi: mid }) {
                Ok(p) => (ok, pos) = (mid, p),
                Err(_) => bad = mid,
            }
        }
        ok
    };
    (end(-1.0), end(1.0))
}

/// One row of the example's table: the input (rad) and the analyses.
pub struct Row {
    /// Link 6's angle (rad).
    pub phi: f64,
    /// The position.
    pub p: StephensonPosition<f64>,
    /// The velocity at [`PHI_DOT`].
    pub v: StephensonVelocity<f64>,
    /// The acceleration at [`PHI_DDOT`].
    pub a: StephensonAcceleration<f64>,
}

/// `n` rows at the middles of `n` equal parts of the swing `(lo, hi)`, on
/// the stated assembly (followed from the stated input).
pub fn rows(m: &Stephenson<f64>, (lo, hi): (f64, f64), n: usize) -> Vec<Row> {
    let q0 = stated_phi();
    let start = m
        .position(&StephensonInput { phi: q0 })
        .expect("the stated assembly exists at the stated input");
    let (mut prev, mut prev_q) = (start, q0);
    (0..n)
        .map(|k| {
            let phi = lo + (hi - lo) * (k as f64 + 0.5) / n as f64;
            let p = follow(m, &prev, prev_q, phi).expect("assembles inside the swing");
            (prev, prev_q) = (p, phi);
            let v = m
                .velocity(&p, &StephensonInput { phi: PHI_DOT })
                .expect("regular inside the swing");
            let a = m
                .acceleration(&p, &v, &StephensonInput { phi: PHI_DDOT })
                .expect("regular inside the swing");
            Row { phi, p, v, a }
        })
        .collect()
}

/// The CSV columns the example prints first, in order.
pub const COLUMNS: [&str; 16] = [
    "phi_deg",
    "ax",
    "ay",
    "bx",
    "by",
    "px",
    "py",
    "theta_crank2_deg",
    "theta_coupler_deg",
    "theta_rocker_deg",
    "omega_crank2",
    "omega_coupler",
    "omega_rocker",
    "alpha_crank2",
    "alpha_coupler",
    "alpha_rocker",
];

impl Row {
    /// The values of [`COLUMNS`].
    pub fn columns(&self) -> [f64; 16] {
        let (p, v, a) = (&self.p, &self.v, &self.a);
        [
            self.phi.to_degrees(),
            p.A.x,
            p.A.y,
            p.B.x,
            p.B.y,
            p.P.x,
            p.P.y,
            p.crank2.to_degrees(),
            p.coupler.to_degrees(),
            p.rocker.to_degrees(),
            v.crank2,
            v.coupler,
            v.rocker,
            a.crank2,
            a.coupler,
            a.rocker,
        ]
    }
}

/// The pictures (`docs/plots.md`): the crank2, coupler and rocker angles,
/// rates and accelerations over the swing (`kinematics.svg`), a drawing at
/// the stated input with the path of P (`drawing.svg`) and an animation
/// over the swing and back (`animation.svg`).
pub fn plots(dir: &std::path::Path) -> Result<Vec<std::path::PathBuf>, mechanism_plot::PlotError> {
    use mechanism_plot::any;
    let m = Stephenson::<f64>::default();
    let swing = swing(&m);
    let rows: Vec<_> = rows(&m, swing, 60)
        .into_iter()
        .map(|r| (r.phi.to_degrees(), Some((r.p, r.v, r.a))))
        .collect();
    let title = "Stephenson III six-bar, link 6 at 1.5 rad/s";
    let fig = any::kinematics_chart(
        title,
        ("link 6 angle φ", "deg"),
        &rows,
        &["crank2", "coupler", "rocker"],
    )?;
    let there: Vec<_> = rows
        .iter()
        .map(|(x, r)| (*x, r.as_ref().map(|r| r.0)))
        .collect();
    let back = there.iter().rev().skip(1).take(there.len() - 2).cloned();
    let poses: Vec<_> = there.iter().cloned().chain(back).collect();
    let sk =
        any::sketch_with::<Stephenson<f64>, _>(title, &poses, &["P"], |d| format!("φ = {d:.1}°"))?;
    let files = [
        dir.join("kinematics.svg"),
        dir.join("drawing.svg"),
        dir.join("animation.svg"),
    ];
    fig.write(&files[0])?;
    // The row nearest the stated input.
    let stated = stated_phi().to_degrees();
    let k = there
        .iter()
        .enumerate()
        .min_by(|a, b| (a.1 .0 - stated).abs().total_cmp(&(b.1 .0 - stated).abs()))
        .map_or(0, |(k, _)| k);
    sk.write_drawing(k, &files[1])?;
    sk.write_animation(6.0, &files[2])?;
    Ok(files.to_vec())
}
