//! `synthesize`: a four-bar whose coupler point passes through given points
//! (`mechanism_synthesis::cases::solve_user`: multi-start Levenberg-Marquardt
//! on exact Jacobians, in both assembly modes), written as a definition
//! file the other commands read.

use crate::spec::number;
use mechanism_synthesis::cases::{self, Case, Found};
use mechanism_synthesis::fourbar::{circuit_word, Design};
use std::path::PathBuf;
use std::time::Instant;

/// What `synthesize` is given on the command line.
#[derive(clap::Args)]
pub struct Args {
    /// A point of the path: X,Y (at least 3).
    #[arg(
        long = "target",
        value_name = "X,Y",
        required = true,
        allow_hyphen_values = true
    )]
    pub targets: Vec<String>,
    /// The crank angle from the ground link at each target, in order (rad, or with `deg`);
    /// none: free timing.
    #[arg(long = "angle", value_name = "ANGLE", allow_hyphen_values = true)]
    pub angles: Vec<String>,
    /// The frame fixed: THETA0,X0,Y0 (THETA0 in rad, or with `deg`); default free.
    #[arg(long, value_name = "THETA0,X0,Y0", allow_hyphen_values = true)]
    pub frame: Option<String>,
    /// Bounds of the link lengths r1 .. r4.
    #[arg(long, value_name = "LO:HI", default_value = "0:60")]
    pub links: String,
    /// Bounds of rcx, rcy, x0, y0.
    #[arg(
        long,
        value_name = "LO:HI",
        default_value = "-60:60",
        allow_hyphen_values = true
    )]
    pub coords: String,
    /// Local solves per assembly mode.
    #[arg(long, default_value_t = 300)]
    pub starts: usize,
    /// Basin hops from the best, per assembly mode.
    #[arg(long, default_value_t = 300)]
    pub hops: usize,
    /// The search's seed.
    #[arg(long, default_value_t = 0)]
    pub seed: u64,
    /// The definition file to write (default: standard output).
    #[arg(short = 'o', long = "output", value_name = "FILE.mech")]
    pub output: Option<PathBuf>,
    /// The result as JSON on standard output: objective, mode, design, angles (rad),
    /// definition, evaluations, jacobians.
    #[arg(long)]
    pub json: bool,
}

/// `X,Y`: two plain numbers.
fn pair(text: &str) -> Result<[f64; 2], String> {
    let parts: Vec<&str> = text.split(',').collect();
    let [x, y] = parts.as_slice() else {
        return Err(format!("--target `{text}`: write X,Y (e.g. `20,25`)"));
    };
    let n = |t: &str| number(t).map_err(|e| format!("--target `{text}`: {e}"));
    Ok([n(x)?, n(y)?])
}

/// `LO:HI`: two plain numbers.
fn bounds(flag: &str, text: &str) -> Result<(f64, f64), String> {
    match text.split_once(':') {
        Some((lo, hi)) => Ok((number(lo)?, number(hi)?)),
        None => Err(format!("--{flag} `{text}`: write LO:HI (e.g. `0:60`)")),
    }
}

/// The case the arguments describe.
fn case(a: &Args) -> Result<Case, String> {
    let targets = a
        .targets
        .iter()
        .map(|t| pair(t))
        .collect::<Result<_, _>>()?;
    let angles = if a.angles.is_empty() {
        None
    } else {
        Some(
            a.angles
                .iter()
                .map(|t| number(t))
                .collect::<Result<_, _>>()?,
        )
    };
    let frame = match &a.frame {
        None => None,
        Some(f) => match f.split(',').collect::<Vec<_>>().as_slice() {
            [t, x, y] => Some([number(t)?, number(x)?, number(y)?]),
            _ => {
                return Err(format!(
                    "--frame `{f}`: write THETA0,X0,Y0 (e.g. `0deg,0,0`)"
                ))
            }
        },
    };
    let links = bounds("links", &a.links)?;
    let coords = bounds("coords", &a.coords)?;
    Case::path(targets, angles, frame, links, coords)
}

/// Runs the search, writes the definition, and shows the result.
pub fn run(a: &Args) -> Result<(), String> {
    let case = case(a)?;
    let clock = Instant::now();
    let found = cases::solve_user(&case, a.starts, a.hops, a.seed)?;
    let seconds = clock.elapsed().as_secs_f64();
    let text = found.design.definition(found.mode);
    if let Some(path) = &a.output {
        std::fs::write(path, &text).map_err(|e| format!("{}: {e}", path.display()))?;
    }
    if a.json {
        println!("{}", json(&found, &text));
    } else if a.output.is_none() {
        print!("{text}");
    }
    eprintln!("{}", summary(&found, seconds));
    Ok(())
}

/// The result as one JSON object (numbers round-trip).
fn json(f: &Found, text: &str) -> String {
    let design: serde_json::Map<String, serde_json::Value> = Design::NAMES
        .iter()
        .zip(&f.design.0)
        .map(|(n, v)| (n.to_string(), serde_json::json!(v)))
        .collect();
    serde_json::json!({
        "objective": f.objective,
        "mode": circuit_word(f.mode),
        "design": design,
        "angles": f.design.angles(),
        "definition": text,
        "evaluations": f.evaluations,
        "jacobians": f.jacobians,
    })
    .to_string()
}

/// What a person reads: the objective, the design, the crank angles in
/// degrees, the cost.
fn summary(f: &Found, seconds: f64) -> String {
    let design: Vec<String> = Design::NAMES
        .iter()
        .zip(&f.design.0)
        .map(|(n, v)| format!("{n} = {v:.6}"))
        .collect();
    let angles: Vec<String> = f
        .design
        .angles()
        .iter()
        .map(|a| format!("{:.3}", a.to_degrees()))
        .collect();
    format!(
        "objective {:.6e} (sum of squared distances), circuit {}\n{}\ncrank angles from the ground link (deg): {}\n{} evaluations, {} Jacobians, {seconds:.2} s; input `phi` = theta0 + crank angle",
        f.objective,
        circuit_word(f.mode),
        design.join(", "),
        angles.join(", "),
        f.evaluations,
        f.jacobians
    )
}
