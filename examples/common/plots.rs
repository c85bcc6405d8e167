//! Pictures of the example mechanisms (`mechanism-plot`): for each scene, a figure of
//! its kinematic outputs against the input, a drawing of one pose with the paths of its
//! points, and an animation over the input range. The examples write them to
//! `target/plots/<example>/`; `tests/examples/plots.rs` writes them to a temporary directory and
//! checks every SVG.
//!
//! The curves use a finer input grid than the examples' tables (which keep the source
//! documents' grids) so that they read as curves; markers appear only on coarse series.
#![allow(dead_code)]

use super::scenes::*;
use mechanism::Point2;
use mechanism_plot::{Figure, Frame, Plot, PlotError, Sketch, Xy};
use std::f64::consts::PI;
use std::path::{Path, PathBuf};

/// Seconds per animation cycle.
const CYCLE_S: f64 = 4.0;

/// `target/plots/<example>/`: under `CARGO_TARGET_DIR` if set (at run time, else at
/// build time), else under the workspace's `target/`.
pub fn out_dir(example: &str) -> PathBuf {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
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

fn xy(p: &Point2<f64>) -> Xy {
    [p.x, p.y]
}

/// Inputs from `lo` to `hi` (deg) in `n` equal steps, both ends included.
fn grid(lo: f64, hi: f64, n: usize) -> Vec<f64> {
    (0..=n)
        .map(|k| lo + (hi - lo) * k as f64 / n as f64)
        .collect()
}

/// Link angles (rad, (-pi, pi]) as continuous degrees: each value is moved by whole
/// turns to lie within half a turn of its predecessor, and the whole series by whole
/// turns so that it starts in [0, 360).
fn unwrap_deg(rad: &[f64]) -> Vec<f64> {
    let mut out: Vec<f64> = Vec::with_capacity(rad.len());
    for &r in rad {
        let d = r.to_degrees();
        let v = match out.last() {
            Some(&prev) => d + 360.0 * ((prev - d) / 360.0).round(),
            None => d,
        };
        out.push(v);
    }
    if let Some(&first) = out.first() {
        let shift = 360.0 * (first / 360.0).floor();
        for v in &mut out {
            *v -= shift;
        }
    }
    out
}

fn caption(name: &str, deg: f64) -> String {
    format!("{name} = {deg:.0}°")
}

/// Four-bar of seed 002 at 250 rad/s: angles, rates, accelerations over a turn; the
/// coupler point P of `docs/dsl.md` (120 mm from A at 30 deg to the coupler) traced.
pub fn fourbar(dir: &Path) -> Result<Vec<PathBuf>, PlotError> {
    let m = FourBar::<f64>::default();
    let omega = 250.0;
    let deg = grid(0.0, 360.0, 180);
    let mut cols: [Vec<f64>; 6] = Default::default();
    let mut poses = Vec::new();
    for &d in &deg {
        let s = m
            .solve(
                &FourBarInput {
                    theta2: d.to_radians(),
                },
                &FourBarInput { theta2: omega },
                &FourBarInput { theta2: 0.0 },
            )
            .expect("the seed 002 four-bar assembles over the whole turn");
        let (p, v, a) = (&s.position, &s.velocity, &s.acceleration);
        for (c, x) in cols
            .iter_mut()
            .zip([p.link3, p.link4, v.link3, v.link4, a.link3, a.link4])
        {
            c.push(x);
        }
        poses.push(s.position);
    }
    let (th3, th4) = (unwrap_deg(&cols[0]), unwrap_deg(&cols[1]));
    let x = ("crank angle θ2", "deg");
    let fig = Figure::new("Four-bar of seed 002, crank at 250 rad/s")
        .panel(
            Plot::new("Angles")
                .x_axis(x.0, x.1)
                .y_axis("angle", "deg")
                .series("θ3 (coupler)", &deg, &th3)
                .series("θ4 (rocker)", &deg, &th4),
        )
        .panel(
            Plot::new("Angular velocities")
                .x_axis(x.0, x.1)
                .y_axis("angular velocity", "rad/s")
                .series("ω3", &deg, &cols[2])
                .series("ω4", &deg, &cols[3]),
        )
        .panel(
            Plot::new("Angular accelerations")
                .x_axis(x.0, x.1)
                .y_axis("angular acceleration", "rad/s^2")
                .series("α3", &deg, &cols[4])
                .series("α4", &deg, &cols[5]),
        );
    let coupler = |p: &FourBarPosition<f64>| -> Xy {
        let t = p.link3 + 30f64.to_radians();
        [p.A.x + 120.0 * t.cos(), p.A.y + 120.0 * t.sin()]
    };
    let mut sk = Sketch::new("Four-bar of seed 002 with coupler point P (mm)", "mm");
    sk.ground_pivot("O2", xy(&poses[0].O2))
        .ground_pivot("O4", xy(&poses[0].O4));
    let path: Vec<Xy> = poses.iter().map(coupler).collect();
    sk.path("P", &path);
    // Every other grid pose: 90 frames, 4 deg apart.
    for (p, d) in poses.iter().zip(&deg).step_by(2).take(90) {
        let pp = coupler(p);
        sk.frame(
            Frame::new(&caption("θ2", *d))
                .link("link2", &[xy(&p.O2), xy(&p.A)])
                .link("link3", &[xy(&p.A), xy(&p.B), pp])
                .link("link4", &[xy(&p.O4), xy(&p.B)])
                .joint("A", xy(&p.A))
                .joint("B", xy(&p.B))
                .point("P", pp),
        );
    }
    // The drawing: theta2 = 60 deg (frame 15).
    save(dir, fig, &sk, 15)
}

/// Six-bar of seed 000 at 10 rad/s over the document's range 40..55 deg; the drawing and
/// the animation over every crank angle that assembles on the document's branch.
pub fn sixbar(dir: &Path) -> Result<Vec<PathBuf>, PlotError> {
    let m = SixBar::<f64>::default();
    let deg = grid(40.0, 55.0, 60);
    let mut cols: [Vec<f64>; 10] = Default::default();
    for &d in &deg {
        let s = m
            .solve(
                &SixBarInput {
                    phi1: d.to_radians(),
                },
                &SixBarInput { phi1: 10.0 },
                &SixBarInput { phi1: 0.0 },
            )
            .expect("the seed 000 six-bar assembles for 40..55 deg");
        let (p, v, a) = (&s.position, &s.velocity, &s.acceleration);
        for (c, x) in cols.iter_mut().zip([
            p.link2, p.link3, p.link4, p.af, v.link2, v.link3, v.link4, a.link2, a.link3, a.link4,
        ]) {
            c.push(x);
        }
    }
    let x = ("crank angle φ1", "deg");
    let fig = Figure::new("Six-bar of seed 000 (problem 3-28), crank at 10 rad/s")
        .panel(
            Plot::new("Link angles")
                .x_axis(x.0, x.1)
                .y_axis("angle", "deg")
                .series("θ2 (B-C)", &deg, &unwrap_deg(&cols[0]))
                .series("θ3 (C-D)", &deg, &unwrap_deg(&cols[1]))
                .series("θ4 (rocker)", &deg, &unwrap_deg(&cols[2])),
        )
        .panel(
            Plot::new("Slide of block F along the crank line")
                .x_axis(x.0, x.1)
                .y_axis("AF", "mm")
                .series("AF", &deg, &cols[3]),
        )
        .panel(
            Plot::new("Angular velocities")
                .x_axis(x.0, x.1)
                .y_axis("angular velocity", "rad/s")
                .series("ω2", &deg, &cols[4])
                .series("ω3", &deg, &cols[5])
                .series("ω4", &deg, &cols[6]),
        )
        .panel(
            Plot::new("Angular accelerations")
                .x_axis(x.0, x.1)
                .y_axis("angular acceleration", "rad/s^2")
                .series("α2", &deg, &cols[7])
                .series("α3", &deg, &cols[8])
                .series("α4", &deg, &cols[9]),
        );
    // The poses that assemble, in 2 deg steps over a turn, in one contiguous run
    // containing 40 deg (the animation must not jump over a gap).
    let pose = |d: f64| {
        m.position(&SixBarInput {
            phi1: d.to_radians(),
        })
        .ok()
    };
    let (mut lo, mut hi) = (40.0, 40.0);
    while lo > 40.0 - 360.0 && pose(lo - 2.0).is_some() {
        lo -= 2.0;
    }
    while hi < lo + 358.0 && pose(hi + 2.0).is_some() {
        hi += 2.0;
    }
    let run: Vec<(f64, SixBarPosition<f64>)> = grid(lo, hi, ((hi - lo) / 2.0) as usize)
        .into_iter()
        .filter_map(|d| pose(d).map(|p| (d, p)))
        .collect();
    let full = hi - lo >= 358.0;
    let mut sk = Sketch::new(
        "Six-bar of seed 000: block F slides on the crank line (mm)",
        "mm",
    );
    let first = &run[0].1;
    sk.ground_pivot("A", xy(&first.A))
        .ground_pivot("E", xy(&first.E));
    let path: Vec<Xy> = run.iter().map(|(_, p)| xy(&p.C)).collect();
    sk.path("C", &path);
    // Out and back when the crank cannot turn fully, so the animation does not jump.
    let mut order: Vec<usize> = (0..run.len()).collect();
    if !full {
        order.extend((1..run.len().saturating_sub(1)).rev());
    }
    for &k in &order {
        let (d, p) = &run[k];
        let u = [p.link1.cos(), p.link1.sin()];
        let reach = p.af.max(40.0) + 15.0;
        sk.frame(
            Frame::new(&caption("φ1", *d))
                .guide(xy(&p.A), [p.A.x + reach * u[0], p.A.y + reach * u[1]])
                .link("link1", &[xy(&p.B), xy(&p.K)])
                .link("link2", &[xy(&p.B), xy(&p.C)])
                .link("link3", &[xy(&p.C), xy(&p.D)])
                .link("link4", &[xy(&p.D), xy(&p.F)])
                .slider("block5", xy(&p.F), p.link1)
                .joint("B", xy(&p.B))
                .joint("C", xy(&p.C))
                .joint("D", xy(&p.D))
                .joint("F", xy(&p.F)),
        );
    }
    let at40 = run.iter().position(|(d, _)| *d >= 40.0).unwrap_or(0);
    save(dir, fig, &sk, at40)
}

/// Quick-return shaper of seed 001 at 1 rad/s over a turn.
pub fn shaper(dir: &Path) -> Result<Vec<PathBuf>, PlotError> {
    let m = Shaper::<f64>::default();
    let deg = grid(0.0, 360.0, 180);
    let mut cols: [Vec<f64>; 9] = Default::default();
    let mut poses = Vec::new();
    for &d in &deg {
        let s = m
            .solve(
                &ShaperInput {
                    crank: d.to_radians(),
                },
                &ShaperInput { crank: 1.0 },
                &ShaperInput { crank: 0.0 },
            )
            .expect("the seed 001 shaper assembles over the whole turn");
        let (p, v, a) = (&s.position, &s.velocity, &s.acceleration);
        for (c, x) in cols.iter_mut().zip([
            p.link3, p.link4, v.link3, v.link4, a.link3, a.link4, p.E.x, v.E.x, a.E.x,
        ]) {
            c.push(x);
        }
        poses.push(s.position);
    }
    let x = ("crank angle", "deg");
    let fig = Figure::new("Quick-return shaper of seed 001, crank at 1 rad/s")
        .panel(
            Plot::new("Ram E")
                .x_axis(x.0, x.1)
                .y_axis("position x", "m")
                .series("x_E", &deg, &cols[6]),
        )
        .panel(
            Plot::new("Ram velocity")
                .x_axis(x.0, x.1)
                .y_axis("v_E", "m/s")
                .series("v_E", &deg, &cols[7]),
        )
        .panel(
            Plot::new("Ram acceleration")
                .x_axis(x.0, x.1)
                .y_axis("a_E", "m/s^2")
                .series("a_E", &deg, &cols[8]),
        )
        .panel(
            Plot::new("Link angles")
                .x_axis(x.0, x.1)
                .y_axis("angle", "deg")
                .series("θ3 (rocker)", &deg, &unwrap_deg(&cols[0]))
                .series("θ4 (rod D-E)", &deg, &unwrap_deg(&cols[1])),
        )
        .panel(
            Plot::new("Angular velocities")
                .x_axis(x.0, x.1)
                .y_axis("angular velocity", "rad/s")
                .series("ω3", &deg, &cols[2])
                .series("ω4", &deg, &cols[3]),
        )
        .panel(
            Plot::new("Angular accelerations")
                .x_axis(x.0, x.1)
                .y_axis("angular acceleration", "rad/s^2")
                .series("α3", &deg, &cols[4])
                .series("α4", &deg, &cols[5]),
        );
    let (xmin, xmax) = cols[6]
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| {
            (a.min(x), b.max(x))
        });
    let y_ram = poses[0].E.y;
    let mut sk = Sketch::new("Quick-return shaper of seed 001 (m)", "m");
    // Hatching above the ram's guide (right of the direction -x), away from the links.
    sk.ground_guide([xmax + 0.06, y_ram], [xmin - 0.06, y_ram])
        .ground_pivot("A", xy(&poses[0].A))
        .ground_pivot("C", xy(&poses[0].C));
    let path: Vec<Xy> = poses.iter().map(|p| xy(&p.D)).collect();
    sk.path("D", &path);
    for (p, d) in poses.iter().zip(&deg).step_by(2).take(90) {
        sk.frame(
            Frame::new(&caption("crank", *d))
                .link("link3", &[xy(&p.C), xy(&p.D)])
                .link("link2", &[xy(&p.A), xy(&p.B)])
                .slider("block", xy(&p.B), p.link3)
                .link("link4", &[xy(&p.D), xy(&p.E)])
                .slider("ram", xy(&p.E), PI)
                .joint("B", xy(&p.B))
                .joint("D", xy(&p.D))
                .joint("E", xy(&p.E)),
        );
    }
    save(dir, fig, &sk, 15)
}

/// Offset slider-crank at 3000 rpm over a turn.
pub fn slider_crank(dir: &Path) -> Result<Vec<PathBuf>, PlotError> {
    let m = SliderCrank::<f64>::default();
    let omega = 3000.0 * 2.0 * PI / 60.0;
    let deg = grid(0.0, 360.0, 180);
    let mut cols: [Vec<f64>; 6] = Default::default();
    let mut poses = Vec::new();
    for &d in &deg {
        let s = m
            .solve(
                &SliderCrankInput {
                    theta: d.to_radians(),
                },
                &SliderCrankInput { theta: omega },
                &SliderCrankInput { theta: 0.0 },
            )
            .expect("the rod is longer than crank + offset: it assembles everywhere");
        let (p, v, a) = (&s.position, &s.velocity, &s.acceleration);
        for (c, x) in cols
            .iter_mut()
            .zip([p.link3, v.link3, a.link3, p.x, v.x, a.x])
        {
            c.push(x);
        }
        poses.push(s.position);
    }
    let x = ("crank angle θ", "deg");
    let fig = Figure::new("Offset slider-crank at 3000 rpm")
        .panel(
            Plot::new("Slider B position")
                .x_axis(x.0, x.1)
                .y_axis("x_B", "m")
                .series("x_B", &deg, &cols[3]),
        )
        .panel(
            Plot::new("Slider B velocity")
                .x_axis(x.0, x.1)
                .y_axis("v_B", "m/s")
                .series("v_B", &deg, &cols[4]),
        )
        .panel(
            Plot::new("Slider B acceleration")
                .x_axis(x.0, x.1)
                .y_axis("a_B", "m/s^2")
                .series("a_B", &deg, &cols[5]),
        )
        .panel(
            Plot::new("Connecting rod angle")
                .x_axis(x.0, x.1)
                .y_axis("φ3", "deg")
                .series("φ3", &deg, &unwrap_deg(&cols[0])),
        )
        .panel(
            Plot::new("Connecting rod angular velocity")
                .x_axis(x.0, x.1)
                .y_axis("ω3", "rad/s")
                .series("ω3", &deg, &cols[1]),
        )
        .panel(
            Plot::new("Connecting rod angular acceleration")
                .x_axis(x.0, x.1)
                .y_axis("α3", "rad/s^2")
                .series("α3", &deg, &cols[2]),
        );
    let (xmin, xmax) = cols[3]
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| {
            (a.min(x), b.max(x))
        });
    let y_line = poses[0].B.y;
    let mut sk = Sketch::new("Offset slider-crank (m)", "m");
    // The block rides on the line: the guide drawn half a block below its pin, hatched
    // underneath (right of +x).
    sk.ground_guide([xmin - 0.04, y_line], [xmax + 0.04, y_line])
        .ground_pivot("O", xy(&poses[0].O));
    for (p, d) in poses.iter().zip(&deg).step_by(2).take(90) {
        sk.frame(
            Frame::new(&caption("θ", *d))
                .slider("slider", xy(&p.B), 0.0)
                .link("link2", &[xy(&p.O), xy(&p.A)])
                .link("link3", &[xy(&p.A), xy(&p.B)])
                .joint("A", xy(&p.A))
                .joint("B", xy(&p.B)),
        );
    }
    save(dir, fig, &sk, 15)
}

/// Two-input five-bar: the end point against q1 for each q2 of the example's grid; the
/// drawing over the workspace grid; the animation along a closed loop of both inputs.
pub fn five_bar(dir: &Path) -> Result<Vec<PathBuf>, PlotError> {
    let m = FiveBar::<f64>::default();
    let pos = |q1: f64, q2: f64| {
        m.position(&FiveBarInput {
            q1: q1.to_radians(),
            q2: q2.to_radians(),
        })
    };
    let q1s = grid(60.0, 150.0, 90);
    let mut px = Plot::new("End point x")
        .x_axis("crank angle q1", "deg")
        .y_axis("x_P", "m");
    let mut py = Plot::new("End point y")
        .x_axis("crank angle q1", "deg")
        .y_axis("y_P", "m");
    let mut sk = Sketch::new("Five-bar robot (m): input grid and a loop of P", "m");
    for j in 0..=6 {
        let q2 = 15.0 * j as f64;
        let pts: Vec<(f64, Xy)> = q1s
            .iter()
            .filter_map(|&q1| pos(q1, q2).ok().map(|p| (q1, xy(&p.P))))
            .collect();
        let name = format!("q2 = {q2:.0}°");
        px = px.points(&name, pts.iter().map(|(q, p)| (*q, p[0])));
        py = py.points(&name, pts.iter().map(|(q, p)| (*q, p[1])));
        let line: Vec<Xy> = pts.iter().map(|(_, p)| *p).collect();
        sk.faint_path(&line);
    }
    // The lines of constant q1 complete the workspace grid.
    for i in 0..=6 {
        let q1 = 60.0 + 15.0 * i as f64;
        let line: Vec<Xy> = grid(0.0, 90.0, 90)
            .into_iter()
            .filter_map(|q2| pos(q1, q2).ok().map(|p| xy(&p.P)))
            .collect();
        sk.faint_path(&line);
    }
    let fig = Figure::new("Five-bar: end point P").panel(px).panel(py);
    let p0 = pos(105.0, 45.0).expect("the centre of the grid assembles");
    sk.ground_pivot("O1", xy(&p0.O1))
        .ground_pivot("O2", xy(&p0.O2));
    // A loop round the centre of the grid: q1 = 105 + 40 cos t, q2 = 45 + 40 sin t.
    let lp = |k: usize| {
        let t = 2.0 * PI * k as f64 / 90.0;
        (105.0 + 40.0 * t.cos(), 45.0 + 40.0 * t.sin())
    };
    let path: Vec<Xy> = (0..=90)
        .filter_map(|k| pos(lp(k).0, lp(k).1).ok().map(|p| xy(&p.P)))
        .collect();
    sk.path("P", &path);
    for k in 0..90 {
        let (q1, q2) = lp(k);
        if let Ok(p) = pos(q1, q2) {
            sk.frame(
                Frame::new(&format!("q1 = {q1:.0}°, q2 = {q2:.0}°"))
                    .link("arm1", &[xy(&p.O1), xy(&p.A)])
                    .link("arm2", &[xy(&p.O2), xy(&p.C)])
                    .link("forearm1", &[xy(&p.A), xy(&p.P)])
                    .link("forearm2", &[xy(&p.C), xy(&p.P)])
                    .joint("A", xy(&p.A))
                    .joint("C", xy(&p.C))
                    .joint("P", xy(&p.P)),
            );
        }
    }
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
    let deg = grid(0.0, 360.0, 180);
    let mut cols: [Vec<f64>; 5] = Default::default();
    let mut poses = Vec::new();
    for &d in &deg {
        let s = m
            .solve(
                &SineMechanismInput {
                    phi1: d.to_radians(),
                },
                &SineMechanismInput { phi1: 10.0 },
                &SineMechanismInput { phi1: 0.0 },
            )
            .expect("the sine mechanism is regular over the whole turn");
        let (p, f) = (&s.position, &s.forces);
        let m43 = f.r_ground_link3.wrench_about(&p.B, &p.Q).moment;
        for (c, x) in cols.iter_mut().zip([
            f.drive_phi1,
            f.r_link1_block2.x,
            f.r_link1_block2.y,
            f.r_block2_link3.force.y,
            m43,
        ]) {
            c.push(x);
        }
        poses.push(s.position);
    }
    let x = ("crank angle φ1", "deg");
    let fig = Figure::new("Sine mechanism of seed 000 (4-23): crank 10 rad/s, Fr = 400 N")
        .panel(
            Plot::new("Driving torque on the crank and guide couple on link 3")
                .x_axis(x.0, x.1)
                .y_axis("moment", "N m")
                .series("Mb (ccw +)", &deg, &cols[0])
                .series("m43 (about S3)", &deg, &cols[4]),
        )
        .panel(
            Plot::new("Reactions")
                .x_axis(x.0, x.1)
                .y_axis("force", "N")
                .series("R12x (crank on block)", &deg, &cols[1])
                .series("R12y (crank on block)", &deg, &cols[2])
                .series("R23y (block on link 3)", &deg, &cols[3]),
        );
    let mut sk = Sketch::new("Sine mechanism, seed 000 (4-23)", "m");
    sk.ground_pivot("A", [0.0, 0.0])
        .ground_guide([0.0, -0.22], [0.0, -0.15])
        .ground_guide([0.0, 0.15], [0.0, 0.22]);
    let path: Vec<Xy> = poses.iter().map(|p| xy(&p.B)).collect();
    sk.path("B", &path);
    for (p, d) in poses.iter().zip(&deg).step_by(2).take(90) {
        let q = xy(&p.Q);
        sk.frame(
            Frame::new(&caption("φ1", *d))
                .link("link3", &[[q[0], q[1] - 0.2], [q[0], q[1] + 0.2]])
                .link("slot", &[[q[0] - 0.13, q[1]], [q[0] + 0.13, q[1]]])
                .link("link1", &[[0.0, 0.0], xy(&p.B)])
                .slider("block2", xy(&p.B), 0.0)
                .joint("B", xy(&p.B)),
        );
    }
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
/// 60 rpm: driving torque and reactions (`forces.svg`), plus the shaper's drawing and
/// animation (the same linkage as `shaper`).
pub fn shaper_forces(dir: &Path) -> Result<Vec<PathBuf>, PlotError> {
    let m = ShaperForces::<f64>::default();
    let deg = grid(0.0, 360.0, 360);
    let mut cols: [Vec<f64>; 5] = Default::default();
    for &d in &deg {
        let input = ShaperForcesInput {
            crank: d.to_radians(),
        };
        let p = m.position(&input).expect("the shaper assembles");
        let rates = ShaperForcesInput { crank: 2.0 * PI };
        let v = m.velocity(&p, &rates).expect("regular");
        let a = m
            .acceleration(&p, &v, &ShaperForcesInput { crank: 0.0 })
            .expect("regular");
        let cut = if v.s_ram > 0.0 { -5000.0 } else { 0.0 };
        let f = m
            .forces(&p, &v, &a, &ShaperForcesLoads { cut })
            .expect("regular force systems");
        for (c, x) in cols.iter_mut().zip([
            f.drive_crank,
            f.r_ground_link3.x,
            f.r_ground_link3.y,
            f.r_ground_ram_block.normal,
            cut,
        ]) {
            c.push(x);
        }
    }
    let x = ("crank angle", "deg");
    let fig = Figure::new("Shaper with masses and gravity, 60 rpm, 5 kN cut on the forward stroke")
        .panel(
            Plot::new("Driving torque")
                .x_axis(x.0, x.1)
                .y_axis("torque", "N m")
                .series("T (ccw +)", &deg, &cols[0]),
        )
        .panel(
            Plot::new("Reactions")
                .x_axis(x.0, x.1)
                .y_axis("force", "N")
                .series("ground on rocker at C, x", &deg, &cols[1])
                .series("ground on rocker at C, y", &deg, &cols[2])
                .series("guide on ram, normal", &deg, &cols[3])
                .series("cutting force along the guide", &deg, &cols[4]),
        );
    let mut files = shaper(dir)?;
    let forces = dir.join("forces.svg");
    fig.write(&forces)?;
    files.push(forces);
    Ok(files)
}
