//! Pictures of the example mechanisms, all from the generic calls of
//! `mechanism_plot::any` (the definitions describe themselves): for each scene, the
//! inputs it is solved at and which outputs to chart; no geometry. The examples write
//! them to `target/plots/<example>/`; `tests/examples/plots.rs` writes them to a
//! temporary directory and checks every SVG, `tests/examples/png.rs` renders them.
//!
//! The curves use a finer input grid than the examples' tables (which keep the source
//! documents' grids) so that they read as curves.
#![allow(dead_code)]

use mechanism_plot::any::Pose;
use mechanism_plot::{Figure, PlotError, Sketch};
use std::path::{Path, PathBuf};

/// Seconds per animation cycle.
pub const CYCLE_S: f64 = 4.0;

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
pub fn grid(lo: f64, hi: f64, n: usize) -> Vec<f64> {
    (0..=n)
        .map(|k| lo + (hi - lo) * k as f64 / n as f64)
        .collect()
}

/// Every `step`-th row's position: the poses of a drawing.
pub fn positions<P: Copy, V, A>(rows: &[Pose<(P, V, A)>], step: usize) -> Vec<Pose<P>> {
    rows.iter()
        .step_by(step)
        .map(|(x, r)| (*x, r.as_ref().map(|r| r.0)))
        .collect()
}

/// A caption `name = 60°` for an input in degrees.
pub fn degrees(name: &'static str) -> impl Fn(f64) -> String {
    move |d| format!("{name} = {d:.0}°")
}

/// Writes `kinematics.svg`, `drawing.svg` (pose `pose`) and `animation.svg` into `dir`.
pub fn save(dir: &Path, fig: Figure, sk: &Sketch, pose: usize) -> Result<Vec<PathBuf>, PlotError> {
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
