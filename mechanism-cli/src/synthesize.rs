//! `synthesize`: a four-bar whose coupler point passes through given points
//! (`mechanism_synthesis::cases::solve_user`: multi-start Levenberg-Marquardt
//! on exact Jacobians, in both assembly modes), written as a definition
//! file the other commands read.

use crate::spec::number;
use mechanism_synthesis::cases::{self, Case, Found};
use std::path::PathBuf;
use std::time::Instant;

/// The names of a design's first nine numbers, in `Design`'s order.
const DESIGN: [&str; 9] = ["r1", "r2", "r3", "r4", "rcx", "rcy", "theta0", "x0", "y0"];

/// What `synthesize` is given on the command line.
pub struct Args {
    /// `X,Y` each.
    pub targets: Vec<String>,
    /// Crank angles from the ground link (rad, or with `deg`), one per target.
    pub angles: Vec<String>,
    /// `THETA0,X0,Y0` (`THETA0` in rad, or with `deg`).
    pub frame: Option<String>,
    /// `LO:HI` of `r1 .. r4`.
    pub links: String,
    /// `LO:HI` of `rcx, rcy, x0, y0`.
    pub coords: String,
    /// Local solves per assembly mode.
    pub starts: usize,
    /// Basin hops per assembly mode.
    pub hops: usize,
    /// The search's seed.
    pub seed: u64,
    /// Where to write the definition (standard output when `None`).
    pub output: Option<PathBuf>,
    /// The result as JSON on standard output (the definition in it).
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
    if a.starts == 0 {
        return Err("--starts 0: the search needs a start".into());
    }
    let clock = Instant::now();
    let found = cases::solve_user(&case, a.starts, a.hops, a.seed);
    let seconds = clock.elapsed().as_secs_f64();
    if !found.objective.is_finite() {
        return Err(
            "no design assembled at every target: widen the bounds or move the targets".into(),
        );
    }
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

/// `left` for `Mode::Plus`, `right` for `Mode::Minus`.
fn mode_word(f: &Found) -> &'static str {
    match f.mode {
        mechanism_core::Mode::Plus => "left",
        mechanism_core::Mode::Minus => "right",
    }
}

/// The result as one JSON object (numbers round-trip).
fn json(f: &Found, text: &str) -> String {
    let design: serde_json::Map<String, serde_json::Value> = DESIGN
        .iter()
        .zip(&f.design.0)
        .map(|(n, v)| (n.to_string(), serde_json::json!(v)))
        .collect();
    serde_json::json!({
        "objective": f.objective,
        "mode": mode_word(f),
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
    let design: Vec<String> = DESIGN
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
        mode_word(f),
        design.join(", "),
        angles.join(", "),
        f.evaluations,
        f.jacobians
    )
}
