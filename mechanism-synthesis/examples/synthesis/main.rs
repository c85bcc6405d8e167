//! Dimensional synthesis of the path-generating four-bar on the five benchmark
//! cases of the literature (issue 37; `mechanism_synthesis::cases`): many
//! quasi-random starts placed on the targets, each polished by a bounded
//! Levenberg-Marquardt on the exact Jacobian that dual numbers carry through
//! the generated `FourBarPath` code, in both assembly modes.
//!
//! Run: `cargo run --release -p mechanism-synthesis --example synthesis` (a table with the time and
//! the evaluations per case, and a picture of each design in
//! `target/plots/synthesis/`), or with `-- --json` (one JSON object per case
//! per line: `{"case", "objective", "design": [r1, r2, r3, r4, rcx, rcy,
//! theta0, x0, y0, th2_1 ..]}`, 17 significant digits). `--seed N` changes the
//! seed (default 1); the run is deterministic for a seed.
//!
//! `-- --report [--runs N]` prints the `## Synthesis` section of
//! `docs/report.md` (markdown; progress on stderr): N seeded runs per case
//! (default 20) beside plain differential evolution at the same budget, the
//! local solver against its alternatives, and Jansen's leg (`report.rs`,
//! `extra.rs`); 28.8 minutes on two cores shared at a load average of 5 to 8.
#[macro_use]
#[path = "../../../examples/common/cli.rs"]
mod cli;
mod extra;
mod measure;
mod report;
use std::f64::consts::TAU;
use std::path::PathBuf;
use std::time::Instant;

use mechanism::Mode;
use mechanism_plot::any::{self, Pose};
use mechanism_synthesis::cases::{self, Case, Found};
use mechanism_synthesis::fourbar::{FourBarPath, FourBarPathInput, FourBarPathPosition};

/// Starts per assembly mode, candidates screened per start, LM iterations per
/// start, basin hops, for each case (in `cases::all()` order). Sized so that the five
/// cases take well under 60 s in release on two cores.
pub const BUDGET: [(usize, usize, usize, usize); 5] = [
    (12000, 50, 30, 0),
    (300, 20, 30, 300),
    (300, 20, 30, 600),
    (600, 20, 30, 3000),
    (1200, 20, 30, 6000),
];

fn main() {
    let args = cli::parse(
        "synthesis",
        "Four-bar path synthesis on the five benchmark cases: best objective, design, time and evaluations per case.",
        &[
            cli::flag("--json", "one JSON object per case per line (17 significant digits)"),
            cli::flag(
                "--report",
                "the docs/report.md section: seeded runs beside differential evolution (markdown)",
            ),
            cli::Opt {
                name: "--runs",
                value: Some("N"),
                help: "seeded runs per case and method for --report (default 20)",
            },
            cli::Opt {
                name: "--seed",
                value: Some("N"),
                help: "seed of the runs (default 1)",
            },
        ],
    );
    let json = args.flag("--json");
    let seed = number(args.value("--seed"), 1, "--seed");
    if args.flag("--report") {
        let runs = number(args.value("--runs"), 20, "--runs").max(1);
        out!("{}", report::section(runs));
        return;
    }
    if !json {
        outln!(
            "{:<16} {:>24} {:>5} {:>10} {:>10} {:>8}",
            "case",
            "objective",
            "mode",
            "evals",
            "jacobians",
            "time_s"
        );
    }
    let total = Instant::now();
    let mut found = Vec::new();
    for (case, &(starts, screen, iters, hops)) in cases::all().iter().zip(BUDGET.iter()) {
        let t = Instant::now();
        let f = cases::solve(case, starts, screen, iters, hops, seed);
        let dt = t.elapsed().as_secs_f64();
        if json {
            let design: Vec<String> = f.design.0.iter().map(|v| format!("{v:.16e}")).collect();
            outln!(
                "{{\"case\": \"{}\", \"objective\": {:.16e}, \"design\": [{}]}}",
                case.id,
                f.objective,
                design.join(", ")
            );
        } else {
            outln!(
                "{:<16} {:>24.16e} {:>5} {:>10} {:>10} {:>8.2}",
                case.id,
                f.objective,
                if f.mode == Mode::Plus { "+1" } else { "-1" },
                f.evaluations,
                f.jacobians,
                dt
            );
        }
        found.push((case.clone(), f));
    }
    if !json {
        outln!("total {:.2} s", total.elapsed().as_secs_f64());
        let dir = out_dir();
        for (case, f) in &found {
            match picture(case, f, &dir) {
                Ok(p) => eprintln!("wrote {}", p.display()),
                Err(e) => eprintln!("no picture of {}: {e}", case.id),
            }
        }
    }
}

/// The value of option `name` as a non-negative integer, `default` when
/// absent; exits with code 2 on anything else.
fn number(v: Option<&str>, default: u64, name: &str) -> u64 {
    match v.map(str::parse) {
        None => default,
        Some(Ok(s)) => s,
        Some(Err(_)) => {
            eprintln!("error: {name} takes a non-negative integer");
            std::process::exit(2);
        }
    }
}

/// `target/plots/synthesis/` (under `CARGO_TARGET_DIR` when set).
fn out_dir() -> PathBuf {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let target = std::env::var_os("CARGO_TARGET_DIR")
        .map(PathBuf::from)
        .unwrap_or_else(|| root.join("target"));
    let target = if target.is_relative() {
        root.join(target)
    } else {
        target
    };
    target.join("plots").join("synthesis")
}

/// The design drawn at its first target's crank angle, with the coupler curve
/// over a full turn and a cross at each target (from the definition's own
/// description, as the other examples' drawings).
fn picture(case: &Case, f: &Found, dir: &std::path::Path) -> Result<PathBuf, String> {
    let fb = f.design.mechanism(f.mode);
    let th0 = f.design.angles().first().copied().unwrap_or(0.0);
    let poses: Vec<Pose<FourBarPathPosition<f64>>> = (0..=180)
        .map(|k| {
            let th = th0 + TAU * k as f64 / 180.0;
            let phi = fb.theta0 + th;
            (th, fb.position(&FourBarPathInput { phi }).ok())
        })
        .collect();
    let title = format!("{}: objective {:.4e}", case.id, f.objective);
    let mut sk = any::sketch_with::<FourBarPath<f64>, _>(&title, &poses, &["P"], |q| {
        format!("th2 = {:.1} deg", q.to_degrees())
    })
    .map_err(|e| e.to_string())?;
    let span = case
        .targets
        .iter()
        .fold(0.0f64, |s, t| s.max(t[0].abs()).max(t[1].abs()))
        .max(1e-9);
    let h = 0.02 * span;
    for t in &case.targets {
        sk.faint_path(&[[t[0] - h, t[1] - h], [t[0] + h, t[1] + h]]);
        sk.faint_path(&[[t[0] - h, t[1] + h], [t[0] + h, t[1] - h]]);
    }
    std::fs::create_dir_all(dir).map_err(|e| e.to_string())?;
    let path = dir.join(format!("{}.svg", case.id));
    sk.write_drawing(0, &path).map_err(|e| e.to_string())?;
    Ok(path)
}
