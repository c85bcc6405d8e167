//! `cargo run --release --example report`: error against run time for every
//! example scene, written to `target/report/` (a markdown summary, one SVG
//! work-precision plot and one CSV per scene).
//!
//! Every method is timed over the whole 3600-point grid of its scene, in
//! interleaved rounds; its outputs are compared with an independent
//! double-double reference (`mechanism-reference`: Newton on the loop-closure
//! equations, rates from the differentiated constraints) at exactly the inputs
//! the method saw (the `f32` methods' inputs rounded to `f32`).

#[path = "../../benches/common/baselines.rs"]
mod baselines;
#[macro_use]
#[path = "../common/cli.rs"]
mod cli;
mod batch;
/// The dynamics section: the run-up four-bar's q'' against its kinematics,
/// the dense global formulation and Pinocchio.
mod dynamics;
mod dynamics_dense;
/// The forces section: generated force analysis against the Newton-Euler reference.
mod forces;
mod generated;
/// The global Newton-Euler method, the timed baseline of the forces section.
mod global_forces;
/// The inverse-kinematics section: the five-bar given its end point.
mod inverse;
mod methods;
mod numpy;
mod reference;
#[path = "../common/run_up.rs"]
mod run_up;
mod runtime;
#[path = "../common/scenes.rs"]
mod scenes;
/// The stability section: error against distance to each singularity.
mod stability;
#[path = "../common/stephenson.rs"]
mod stephenson;
mod svg;
mod timing;
/// The triad section: the Stephenson III six-bar against Newton baselines.
mod triad;
#[path = "../../benches/common/variants.rs"]
mod variants;

use mechanism_reference::Dd;
use methods::{Method, Precision};
use reference::{Kind, Scene};
use std::fmt::Write as _;
use std::path::Path;

/// Interleaved rounds per method (the targets ask for at least 5).
const ROUNDS: usize = 21;
/// Minimum duration of one timed sample (ns): long against the timer.
const MIN_SAMPLE_NS: f64 = 1.5e7;

/// Error figures of one method over its scene's grid.
#[derive(Clone, Copy, Debug, Default)]
pub struct Errors {
    /// Largest absolute error of an angle (rad).
    pub angle_abs: f64,
    /// Largest error of a position value relative to its column's largest value.
    pub pos_rel: f64,
    /// Largest error of a velocity or acceleration (angular ones included)
    /// relative to its column's largest value.
    pub rate_rel: f64,
    /// Largest of all errors relative to the column scale (plotted).
    pub all_rel: f64,
    /// Largest relative loop-closure residual of the method's positions.
    pub residual: f64,
    /// Grid points where the method returned an error.
    pub failures: usize,
    /// Grid points where the reference failed (excluded).
    pub ref_failures: usize,
    /// The column of the largest relative error.
    pub worst: &'static str,
}

/// Column scales: the largest |reference| of each column, floored at 1e-6 of
/// the largest non-angle column of the same derivative order: below that (a column that
/// is zero in exact arithmetic, like the velocity across a fixed guide, is
/// then measured against the magnitude its rounding errors come from).
fn scales(scene: &Scene, refs: &[Option<(Vec<Dd>, f64)>]) -> Vec<f64> {
    let n = scene.columns.len();
    let mut s = vec![0.0f64; n];
    for (v, _) in refs.iter().flatten() {
        for (k, x) in v.iter().enumerate() {
            s[k] = s[k].max(x.to_f64().abs());
        }
    }
    let mut floor = [0.0f64; 3];
    for (k, c) in scene.columns.iter().enumerate() {
        if !(c.kind == Kind::Angle && c.order == 0) {
            floor[c.order] = floor[c.order].max(s[k]);
        }
    }
    for (k, c) in scene.columns.iter().enumerate() {
        if s[k] < 1e-6 * floor[c.order] {
            s[k] = floor[c.order];
        }
    }
    s
}

fn wrap(d: f64) -> f64 {
    let tau = std::f64::consts::TAU;
    d - tau * (d / tau).round()
}

/// Errors of one method's samples against the reference.
fn errors(
    scene: &Scene,
    grid: &[Vec<f64>],
    refs: &[Option<(Vec<Dd>, f64)>],
    scale: &[f64],
    samples: &[Option<generated::Sample>],
) -> Errors {
    let mut e = Errors::default();
    for ((r, s), q) in refs.iter().zip(samples).zip(grid) {
        let Some(s) = s else {
            e.failures += 1;
            continue;
        };
        let Some((r, _)) = r else {
            e.ref_failures += 1;
            continue;
        };
        e.residual = e.residual.max(reference::residual(scene, q, &s.points));
        for (k, c) in scene.columns.iter().enumerate() {
            let Some(m) = s.cols[k] else { continue };
            let mut d = (Dd::from_f64(m) - r[k]).to_f64();
            if !d.is_finite() {
                d = f64::INFINITY;
            }
            let rel;
            if c.kind == Kind::Angle && c.order == 0 {
                d = wrap(d).abs();
                e.angle_abs = e.angle_abs.max(d);
                rel = d / scale[k];
            } else {
                rel = d.abs() / scale[k];
                if c.order == 0 {
                    e.pos_rel = e.pos_rel.max(rel);
                } else {
                    e.rate_rel = e.rate_rel.max(rel);
                }
            }
            if rel > e.all_rel {
                e.all_rel = rel;
                e.worst = c.name;
            }
        }
    }
    e
}

/// Half an ulp of a cosine or sine in [0.5, 1) (f32): the angle by which a
/// correctly rounded f32 `(cos, sin)` pair can be turned from the exact one
/// per component (rad).
pub const COS_SIN_HALF_ULP: f64 = 1.0 / 33_554_432.0;

/// The f32 floor of a scene: how far its outputs move (relative to the column
/// scales, positions and rates apart) when one input angle is turned by
/// [`COS_SIN_HALF_ULP`], the worst over the grid (at the f32-rounded inputs)
/// and the inputs, from the f64 generated code (accurate to about 1e-14, far
/// below the differences). It is the conditioning times the rounding of the
/// f32 cos/sin that every f32 evaluation starts from; the actual rounding of
/// a pair can turn it by up to about `sqrt(2)` times as much, and also changes
/// its length by as much (which the code can and should compensate).
fn cos_sin_floor(
    scene: &Scene,
    grid32: &[Vec<f64>],
    w: &[f64],
    a: &[f64],
    scale: &[f64],
) -> (f64, f64) {
    let (mut pos, mut rate) = (0.0f64, 0.0f64);
    for q in grid32 {
        let Some(base) = generated::f64_sample(scene.name, q, w, a) else {
            continue;
        };
        for j in 0..q.len() {
            let mut qj = q.clone();
            qj[j] += COS_SIN_HALF_ULP;
            let Some(p) = generated::f64_sample(scene.name, &qj, w, a) else {
                continue;
            };
            for (k, c) in scene.columns.iter().enumerate() {
                let (Some(x), Some(y)) = (base.cols[k], p.cols[k]) else {
                    continue;
                };
                let d = if c.kind == Kind::Angle && c.order == 0 {
                    wrap(y - x).abs()
                } else {
                    (y - x).abs()
                } / scale[k];
                if c.order == 0 && c.kind != Kind::Angle {
                    pos = pos.max(d);
                } else if c.order > 0 {
                    rate = rate.max(d);
                }
            }
        }
    }
    (pos, rate)
}

/// The reference at one grid point: columns and residual (`None`: failed).
type RefPoint = Option<(Vec<Dd>, f64)>;

/// Reference columns at every grid point, started from the given samples'
/// points (falling back to the previous grid point's solution).
fn references(
    scene: &Scene,
    grid: &[Vec<f64>],
    rates: &[f64],
    accels: &[f64],
    starts: &[Option<generated::Sample>],
) -> (Vec<RefPoint>, Vec<String>) {
    let mut out = Vec::with_capacity(grid.len());
    let mut problems = Vec::new();
    let mut last: Option<Vec<(f64, f64)>> = None;
    for (q, s) in grid.iter().zip(starts) {
        let start = s.as_ref().map(|s| s.points.clone()).or(last.clone());
        let Some(start) = start else {
            out.push(None);
            continue;
        };
        match reference::solve(scene, q, rates, accels, &start) {
            Ok(r) => {
                last = Some(start);
                out.push(Some(r));
            }
            Err(err) => {
                problems.push(format!("{} at {q:?}: {err:?}", scene.name));
                out.push(None);
            }
        }
    }
    (out, problems)
}

fn machine() -> String {
    let cpu = std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|t| {
            t.lines()
                .find(|l| l.starts_with("model name"))
                .map(|l| l.split(':').nth(1).unwrap_or("?").trim().to_string())
        })
        .unwrap_or_else(|| "unknown CPU".into());
    let cores = std::thread::available_parallelism()
        .map(|n| n.get())
        .unwrap_or(0);
    let cmd = |c: &str, a: &[&str]| {
        std::process::Command::new(c)
            .args(a)
            .output()
            .ok()
            .map(|o| String::from_utf8_lossy(&o.stdout).trim().to_string())
            .unwrap_or_default()
    };
    let date = cmd("date", &["-u", "+%Y-%m-%d %H:%M UTC"]);
    let rustc = cmd("rustc", &["-V"]);
    let load = std::fs::read_to_string("/proc/loadavg")
        .map(|l| l.split_whitespace().take(3).collect::<Vec<_>>().join(" "))
        .unwrap_or_default();
    let flags = std::env::var("RUSTFLAGS").unwrap_or_default();
    let flags = if flags.is_empty() {
        "(none)".into()
    } else {
        flags
    };
    format!(
        "Machine: {cpu}, {cores} logical cores (`nproc`); {rustc}; RUSTFLAGS: {flags}; made {date}; load average at the start (1, 5, 15 min): {load}."
    )
}

fn sci(x: f64) -> String {
    if x == 0.0 {
        "0".into()
    } else {
        format!("{x:.1e}")
    }
}

/// What one kinematic scene adds to the report.
struct SceneSection {
    /// Its table and lines (Markdown).
    md: String,
    /// Its issue-5 target lines.
    targets: Vec<String>,
    /// Where the reference failed.
    problems: Vec<String>,
}

/// One kinematic scene's section: its methods timed and compared with the
/// reference, the table (and its SVG and CSV in `out_dir`), its target
/// lines and the reference's failures.
fn scene_section(scene: &Scene, out_dir: &Path) -> SceneSection {
    eprintln!("scene {}", scene.name);
    let mut problems = Vec::new();
    let grid64 = scene.grid.clone();
    let r32 = |v: &[f64]| v.iter().map(|&x| x as f32 as f64).collect::<Vec<_>>();
    let grid32: Vec<Vec<f64>> = grid64.iter().map(|q| r32(q)).collect();
    let (rates32, accels32) = (r32(&scene.rates), r32(&scene.accels));
    let mut ms: Vec<Method> = methods::for_scene(scene, out_dir);
    let gen_of = |p: Precision| {
        ms.iter()
            .find(|m| m.precision == p && m.family.starts_with("generated"))
            .map(|m| m.samples.clone())
            .expect("a generated method per precision")
    };
    let (ref64, p64) = references(
        scene,
        &grid64,
        &scene.rates,
        &scene.accels,
        &gen_of(Precision::F64),
    );
    let (ref32, p32) = references(scene, &grid32, &rates32, &accels32, &gen_of(Precision::F32));
    problems.extend(p64);
    problems.extend(p32);
    let scale = scales(scene, &ref64);
    let floor = cos_sin_floor(scene, &grid32, &rates32, &accels32, &scale);
    let max_res = ref64.iter().flatten().map(|r| r.1).fold(0.0f64, f64::max);
    for m in ms.iter_mut() {
        let (g, r) = match m.precision {
            Precision::F64 => (&grid64, &ref64),
            Precision::F32 => (&grid32, &ref32),
        };
        m.errors = errors(scene, g, r, &scale, &m.samples);
    }
    // Timing: every timed method interleaved.
    let timed: Vec<(&timing::Sweep, usize)> = ms
        .iter()
        .filter_map(|m| m.sweep.as_ref().map(|s| (s, grid64.len())))
        .collect();
    let ns = timing::interleaved(&timed, ROUNDS, MIN_SAMPLE_NS);
    let mut it = ns.into_iter();
    for m in ms.iter_mut() {
        if m.sweep.is_some() {
            m.ns = it.next().unwrap_or_default();
        }
    }
    SceneSection {
        md: scene_table(scene, &ms, &grid64, max_res, floor, out_dir),
        targets: methods::targets(scene, &ms, floor),
        problems,
    }
}

/// A scene's table of methods (ns, errors), its work-precision SVG and CSV
/// written to `out_dir`, and the f32 floor line.
fn scene_table(
    scene: &Scene,
    ms: &[Method],
    grid64: &[Vec<f64>],
    max_res: f64,
    floor: (f64, f64),
    out_dir: &Path,
) -> String {
    let mut md = String::new();
    let _ = writeln!(md, "## {}\n", scene.name);
    let _ = writeln!(
        md,
        "{} grid points; input rates {:?}, accelerations {:?}; reference residual at most {:.1e}.\n",
        grid64.len(),
        scene.rates,
        scene.accels,
        max_res
    );
    let _ = writeln!(
        md,
        "| method | ns/eval median | min - max | angle err (rad) | position rel err | rate rel err | worst column | loop residual | failed |"
    );
    let _ = writeln!(md, "|---|---:|---:|---:|---:|---:|---|---:|---:|");
    let mut csv = String::from(
        "method,precision,ns_median,ns_min,ns_max,angle_abs,pos_rel,rate_rel,all_rel,residual,failures\n",
    );
    let mut pts = Vec::new();
    for m in ms {
        let (med, lo, hi) = if m.ns.is_empty() {
            (f64::NAN, f64::NAN, f64::NAN)
        } else {
            timing::stats(&m.ns)
        };
        let e = m.errors;
        let _ = writeln!(
            md,
            "| {} | {:.1} | {:.1} - {:.1} | {} | {} | {} | {} | {} | {} |",
            m.name,
            med,
            lo,
            hi,
            sci(e.angle_abs),
            sci(e.pos_rel),
            sci(e.rate_rel),
            e.worst,
            sci(e.residual),
            e.failures
        );
        let _ = writeln!(
            csv,
            "{},{:?},{med},{lo},{hi},{},{},{},{},{},{}",
            m.name,
            m.precision,
            e.angle_abs,
            e.pos_rel,
            e.rate_rel,
            e.all_rel,
            e.residual,
            e.failures
        );
        if med.is_finite() {
            pts.push(svg::Pt {
                family: m.family.clone(),
                label: m.name.clone(),
                ns: med,
                err: e.all_rel,
            });
        }
    }
    let file = format!("{}.svg", scene.name.to_lowercase());
    std::fs::write(
        out_dir.join(&file),
        svg::plot(&format!("{}: work-precision", scene.name), &pts, 1e-17),
    )
    .expect("write svg");
    std::fs::write(
        out_dir.join(format!("{}.csv", scene.name.to_lowercase())),
        csv,
    )
    .expect("write csv");
    let _ = writeln!(
        md,
        "\nf32 floor (conditioning times the rounding of the f32 cos/sin: every input \
         turned by 2^-25 rad, f64 code): positions {}, rates {} (relative, as in the table).\n",
        sci(floor.0),
        sci(floor.1)
    );
    let _ = writeln!(md, "Plot: `target/report/{file}`.\n");
    md
}

fn main() {
    cli::parse(
        "report",
        "Error against run time for every example scene and method, written to target/report/ (summary.md, one SVG and one CSV per scene); the summary is also printed.",
        &[],
    );
    let out_dir = mechanism_dev::workspace_root().join("target/report");
    std::fs::create_dir_all(&out_dir).expect("create target/report");
    if std::env::var_os("REPORT_FORCES_ONLY").is_some() {
        // The forces section alone (development): not written to summary.md.
        outln!("{}", forces::section(&out_dir));
        return;
    }
    if std::env::var_os("REPORT_TRIAD_ONLY").is_some() {
        // The triad section alone (development): not written to summary.md.
        outln!("{}", triad::section(&out_dir));
        return;
    }
    if std::env::var_os("REPORT_DYNAMICS_ONLY").is_some() {
        // The dynamics section alone (development).
        outln!("{}", dynamics::section(&out_dir));
        return;
    }
    if std::env::var_os("REPORT_RUNTIME_ONLY").is_some() {
        // The run-time mechanism's timing alone, with the machine it ran on.
        outln!("{}\n\n{}", machine(), runtime::section());
        return;
    }
    if std::env::var_os("REPORT_INVERSE_ONLY").is_some() {
        // The inverse-kinematics section alone (development).
        outln!("{}", inverse::section());
        return;
    }
    let mut md = String::new();
    let _ = writeln!(md, "# Error against run time\n");
    let _ = writeln!(md, "{}\n", machine());
    let _ = writeln!(
        md,
        "Made by `cargo run --release --example report` (see `docs/performance.md`). Every \
         method runs over the whole 3600-point grid of its scene; times are ns per evaluation \
         (position + velocity + acceleration), median and min-max over {ROUNDS} interleaved \
         rounds. Errors are against an independent double-double reference \
         (`mechanism-reference`, about 106 bits: Newton on the loop-closure equations with a \
         convergence check, rates and accelerations from the differentiated constraints) at \
         the inputs the method saw (rounded to f32 for f32 methods; the dimensions are the \
         exact decimals of the definitions). Angles: absolute error in rad; everything else: \
         error relative to the column's largest value. Residual: the method's positions put \
         into the reference's constraint equations, relative to the length scale.\n"
    );
    let mut all_problems = Vec::new();
    let mut target_lines = Vec::new();
    // One kinematic scene's table and target lines alone (development):
    // `REPORT_SCENE_ONLY=SliderCrank`; not written to summary.md.
    let only_scene = std::env::var("REPORT_SCENE_ONLY").ok();
    let wanted = |name: &str| only_scene.as_deref().is_none_or(|n| n == name);
    for scene in reference::scenes().into_iter().filter(|s| wanted(s.name)) {
        let section = scene_section(&scene, &out_dir);
        md += &section.md;
        target_lines.extend(section.targets);
        all_problems.extend(section.problems);
    }
    if only_scene.is_some() {
        for l in &target_lines {
            let _ = writeln!(md, "- {l}");
        }
        outln!("{md}");
        return;
    }
    eprintln!("scene Stephenson (triad)");
    md += &triad::section(&out_dir);
    eprintln!("scene five-bar given its end point");
    md += &inverse::section();
    let _ = writeln!(md, "## Targets (issue 5)\n");
    for l in &target_lines {
        let _ = writeln!(md, "- {l}");
    }
    if !all_problems.is_empty() {
        let _ = writeln!(md, "\n## Reference failures\n");
        for p in all_problems.iter().take(20) {
            let _ = writeln!(md, "- {p}");
        }
        let _ = writeln!(md, "- ({} in all)", all_problems.len());
    }
    md += &forces::section(&out_dir);
    eprintln!("the run-time mechanism");
    md += &runtime::section();
    md += &stability::section(&out_dir);
    md += &dynamics::section(&out_dir);
    std::fs::write(out_dir.join("summary.md"), &md).expect("write summary");
    outln!("{md}");
    eprintln!("wrote {}", out_dir.display());
}
