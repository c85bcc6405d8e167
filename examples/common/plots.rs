//! Pictures of the example mechanisms, all from the generic calls of
//! `mechanism_plot::any` (the definitions describe themselves): for each scene, the
//! inputs it is solved at and which outputs to chart; no geometry. The examples write
//! them to `target/plots/<example>/`; `tests/examples/plots.rs` writes them to a
//! temporary directory and checks every SVG, `tests/examples/png.rs` renders them.
//!
//! The curves use a finer input grid than the examples' tables (which keep the source
//! documents' grids) so that they read as curves.
#![allow(dead_code)]

use super::scenes::*;
use mechanism_plot::any::{self, Pose};
use mechanism_plot::{Figure, PlotError, Sketch};
use std::f64::consts::PI;
use std::path::{Path, PathBuf};

/// Seconds per animation cycle.
const CYCLE_S: f64 = 4.0;

/// `target/plots/<example>/`: under `CARGO_TARGET_DIR` if set (at run time, else at
/// build time), else under the workspace's `target/` (the nearest directory up
/// from the manifest's with a `Cargo.lock`: the examples are the facade's, the
/// tests that call this `mechanism-dev`'s).
pub fn out_dir(example: &str) -> PathBuf {
    let manifest = Path::new(env!("CARGO_MANIFEST_DIR"));
    let root = manifest
        .ancestors()
        .find(|d| d.join("Cargo.lock").is_file())
        .unwrap_or(manifest);
    let target = std::env::var_os("CARGO_TARGET_DIR")
        .map(PathBuf::from)
        .or_else(|| option_env!("CARGO_TARGET_DIR").map(PathBuf::from))
        .unwrap_or_else(|| root.join("target"));
    let target = if target.is_relative() {
        root.join(target)
    } else {
        target
    };
    target.join("plots").join(example)
}

/// Writes the pictures of `example` with `make` and says where on stderr (stdout keeps
/// the table or the CSV unchanged); a failure is reported, not fatal.
pub fn write_and_report(example: &str, make: fn(&Path) -> Result<Vec<PathBuf>, PlotError>) {
    let dir = out_dir(example);
    match make(&dir) {
        Ok(files) => {
            let names: Vec<String> = files
                .iter()
                .filter_map(|f| f.file_name().map(|n| n.to_string_lossy().into_owned()))
                .collect();
            eprintln!("pictures: {} ({})", dir.display(), names.join(", "));
        }
        Err(e) => eprintln!("pictures: not written to {}: {e}", dir.display()),
    }
}

/// Inputs from `lo` to `hi` (deg) in `n` equal steps, both ends included.
fn grid(lo: f64, hi: f64, n: usize) -> Vec<f64> {
    (0..=n)
        .map(|k| lo + (hi - lo) * k as f64 / n as f64)
        .collect()
}

/// Every `step`-th row's position: the poses of a drawing.
fn positions<P: Copy, V, A>(rows: &[Pose<(P, V, A)>], step: usize) -> Vec<Pose<P>> {
    rows.iter()
        .step_by(step)
        .map(|(x, r)| (*x, r.as_ref().map(|r| r.0)))
        .collect()
}

/// A caption `name = 60°` for an input in degrees.
fn degrees(name: &'static str) -> impl Fn(f64) -> String {
    move |d| format!("{name} = {d:.0}°")
}

/// Four-bar of seed 002 at 250 rad/s: the coupler's and the rocker's angles, rates and
/// accelerations over a turn; the path of B.
pub fn fourbar(dir: &Path) -> Result<Vec<PathBuf>, PlotError> {
    let m = FourBar::<f64>::default();
    let rows: Vec<_> = grid(0.0, 360.0, 180)
        .into_iter()
        .map(|d| {
            let s = m.solve(
                &FourBarInput {
                    theta2: d.to_radians(),
                },
                &FourBarInput { theta2: 250.0 },
                &FourBarInput { theta2: 0.0 },
            );
            (d, s.ok().map(|s| (s.position, s.velocity, s.acceleration)))
        })
        .collect();
    let title = "Four-bar of seed 002, crank at 250 rad/s";
    let x = ("crank angle θ2", "deg");
    let fig = any::kinematics_chart(title, x, &rows, &["link3", "link4"])?;
    // Every other pose, 0..356 deg: 90 frames 4 deg apart.
    let poses = &positions(&rows, 2)[..90];
    let sk = any::sketch_with::<FourBar<f64>, _>(title, poses, &["B"], degrees("θ2"))?;
    // The drawing: theta2 = 60 deg (frame 15).
    save(dir, fig, &sk, 15)
}

/// Six-bar of seed 000 at 10 rad/s over the document's range 40..55 deg (its `range`);
/// the animation goes there and back.
pub fn sixbar(dir: &Path) -> Result<Vec<PathBuf>, PlotError> {
    let m = SixBar::<f64>::default();
    let solve = |d: f64| {
        let s = m.solve(
            &SixBarInput {
                phi1: d.to_radians(),
            },
            &SixBarInput { phi1: 10.0 },
            &SixBarInput { phi1: 0.0 },
        );
        (d, s.ok().map(|s| (s.position, s.velocity, s.acceleration)))
    };
    let rows: Vec<_> = grid(40.0, 55.0, 60).into_iter().map(solve).collect();
    let title = "Six-bar of seed 000 (problem 3-28), crank at 10 rad/s";
    let x = ("crank angle φ1", "deg");
    let fig = any::kinematics_chart(title, x, &rows, &["link2", "link3", "link4", "af"])?;
    let there = positions(&rows, 2);
    let back = there.iter().rev().skip(1).take(there.len() - 2).cloned();
    let poses: Vec<_> = there.iter().cloned().chain(back).collect();
    let sk = any::sketch_with::<SixBar<f64>, _>(title, &poses, &["C"], degrees("φ1"))?;
    save(dir, fig, &sk, 0)
}

/// Quick-return shaper of seed 001 at 1 rad/s over a turn: the ram E, the rocker's and
/// the rod's angles, their rates and accelerations; the path of D.
pub fn shaper(dir: &Path) -> Result<Vec<PathBuf>, PlotError> {
    let m = Shaper::<f64>::default();
    let rows: Vec<_> = grid(0.0, 360.0, 180)
        .into_iter()
        .map(|d| {
            let s = m.solve(
                &ShaperInput {
                    crank: d.to_radians(),
                },
                &ShaperInput { crank: 1.0 },
                &ShaperInput { crank: 0.0 },
            );
            (d, s.ok().map(|s| (s.position, s.velocity, s.acceleration)))
        })
        .collect();
    let title = "Quick-return shaper of seed 001, crank at 1 rad/s";
    let x = ("crank angle", "deg");
    let fig = any::kinematics_chart(title, x, &rows, &["E", "link3", "link4"])?;
    let poses = &positions(&rows, 2)[..90];
    let sk = any::sketch_with::<Shaper<f64>, _>(title, poses, &["D"], degrees("crank"))?;
    save(dir, fig, &sk, 15)
}

/// Offset slider-crank at 3000 rpm over a turn: the slide x and the rod's angle, their
/// rates and accelerations.
pub fn slider_crank(dir: &Path) -> Result<Vec<PathBuf>, PlotError> {
    let m = SliderCrank::<f64>::default();
    let omega = 3000.0 * 2.0 * PI / 60.0;
    let rows: Vec<_> = grid(0.0, 360.0, 180)
        .into_iter()
        .map(|d| {
            let s = m.solve(
                &SliderCrankInput {
                    theta: d.to_radians(),
                },
                &SliderCrankInput { theta: omega },
                &SliderCrankInput { theta: 0.0 },
            );
            (d, s.ok().map(|s| (s.position, s.velocity, s.acceleration)))
        })
        .collect();
    let title = "Offset slider-crank at 3000 rpm";
    let x = ("crank angle θ", "deg");
    let fig = any::kinematics_chart(title, x, &rows, &["x", "link3"])?;
    let poses = &positions(&rows, 2)[..90];
    let sk = any::sketch_with::<SliderCrank<f64>, _>(title, poses, &[], degrees("θ"))?;
    save(dir, fig, &sk, 15)
}

/// Two-input five-bar along a closed loop of both inputs round the centre of the
/// example's grid, q1 = 105° + 40° cos t, q2 = 45° + 40° sin t: the end point P against
/// t, a drawing and an animation with the path of P.
pub fn five_bar(dir: &Path) -> Result<Vec<PathBuf>, PlotError> {
    let m = FiveBar::<f64>::default();
    let inputs = |t: f64| {
        let t = t.to_radians();
        (105.0 + 40.0 * t.cos(), 45.0 + 40.0 * t.sin())
    };
    let rows: Vec<_> = grid(0.0, 360.0, 90)
        .into_iter()
        .map(|t| {
            let (q1, q2) = inputs(t);
            let p = m.position(&FiveBarInput {
                q1: q1.to_radians(),
                q2: q2.to_radians(),
            });
            let rates = FiveBarInput { q1: 1.0, q2: 1.0 };
            let s = p.and_then(|p| {
                let v = m.velocity(&p, &rates)?;
                let a = m.acceleration(&p, &v, &FiveBarInput { q1: 0.0, q2: 0.0 })?;
                Ok((p, v, a))
            });
            (t, s.ok())
        })
        .collect();
    let title = "Five-bar robot (m): P along a loop of both inputs, both at 1 rad/s";
    let x = ("loop parameter t", "deg");
    let fig = any::kinematics_chart(title, x, &rows, &["P"])?;
    let poses = &positions(&rows, 1)[..90];
    let sk = any::sketch_with::<FiveBar<f64>, _>(title, poses, &["P"], |t| {
        let (q1, q2) = inputs(t);
        format!("q1 = {q1:.0}°, q2 = {q2:.0}°")
    })?;
    save(dir, fig, &sk, 0)
}

/// Writes `kinematics.svg`, `drawing.svg` (pose `pose`) and `animation.svg` into `dir`.
fn save(dir: &Path, fig: Figure, sk: &Sketch, pose: usize) -> Result<Vec<PathBuf>, PlotError> {
    let files = [
        dir.join("kinematics.svg"),
        dir.join("drawing.svg"),
        dir.join("animation.svg"),
    ];
    fig.write(&files[0])?;
    sk.write_drawing(pose, &files[1])?;
    sk.write_animation(CYCLE_S, &files[2])?;
    Ok(files.to_vec())
}

/// Sine mechanism of seed 000, problem 4-23 (g = 10, as the document): the driving
/// torque and the reactions over a turn (`forces.svg`), a drawing and an animation.
pub fn sine_mechanism(dir: &Path) -> Result<Vec<PathBuf>, PlotError> {
    let m = SineMechanism::<f64>::default();
    let solved: Vec<_> = grid(0.0, 360.0, 180)
        .into_iter()
        .map(|d| {
            let s = m.solve(
                &SineMechanismInput {
                    phi1: d.to_radians(),
                },
                &SineMechanismInput { phi1: 10.0 },
                &SineMechanismInput { phi1: 0.0 },
            );
            (d, s.ok())
        })
        .collect();
    let forces: Vec<_> = solved
        .iter()
        .map(|(d, s)| (*d, s.as_ref().map(|s| s.forces)))
        .collect();
    let poses: Vec<_> = solved
        .iter()
        .step_by(2)
        .take(90)
        .map(|(d, s)| (*d, s.as_ref().map(|s| s.position)))
        .collect();
    let title = "Sine mechanism of seed 000 (4-23): crank 10 rad/s, Fr = 400 N";
    let fig = any::force_chart(title, ("crank angle φ1", "deg"), &forces)?;
    let sk = any::sketch_with::<SineMechanism<f64>, _>(title, &poses, &["B"], degrees("φ1"))?;
    let files = [
        dir.join("forces.svg"),
        dir.join("drawing.svg"),
        dir.join("animation.svg"),
    ];
    fig.write(&files[0])?;
    sk.write_drawing(15, &files[1])?;
    sk.write_animation(CYCLE_S, &files[2])?;
    Ok(files.to_vec())
}

/// The shaper with masses, gravity and a 5 kN cutting force on the forward stroke at
/// 60 rpm: the driving torque and the reactions (`forces.svg`), plus the shaper's
/// pictures (the same linkage as `shaper`; the scene `ShaperForces` keeps only the
/// outputs its table needs, so its poses cannot be drawn whole).
pub fn shaper_forces(dir: &Path) -> Result<Vec<PathBuf>, PlotError> {
    let m = ShaperForces::<f64>::default();
    let forces: Vec<_> = grid(0.0, 360.0, 360)
        .into_iter()
        .map(|d| {
            let p = m.position(&ShaperForcesInput {
                crank: d.to_radians(),
            });
            let rates = ShaperForcesInput { crank: 2.0 * PI };
            let f = p.and_then(|p| {
                let v = m.velocity(&p, &rates)?;
                let a = m.acceleration(&p, &v, &ShaperForcesInput { crank: 0.0 })?;
                let cut = if v.s_ram > 0.0 { -5000.0 } else { 0.0 };
                m.forces(&p, &v, &a, &ShaperForcesLoads { cut })
            });
            (d, f.ok())
        })
        .collect();
    let title = "Shaper with masses and gravity, 60 rpm, 5 kN cut on the forward stroke";
    let mut files = shaper(dir)?;
    let path = dir.join("forces.svg");
    any::force_chart(title, ("crank angle", "deg"), &forces)?.write(&path)?;
    files.push(path);
    Ok(files)
}
