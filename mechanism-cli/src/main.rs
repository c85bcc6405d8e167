//! `mechanism`: planar linkage definitions (the language of `mechanism!`)
//! read from text files and worked on without compiling them. See
//! `docs/cli.md`.

mod picture;
mod spec;
mod synthesize;
mod table;

use clap::{Parser, Subcommand};
use mechanism_codegen::runtime::{Errors, Mechanism};
use spec::Spec;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

/// Poses from which a sweep shows a progress bar (on a terminal).
const PROGRESS_FROM: usize = 2_000;

#[derive(Parser)]
#[command(
    name = "mechanism",
    version,
    about = "Check, tabulate, draw, animate, chart and emit planar linkage definitions (the mechanism! language) without compiling them, and synthesize four-bars through given points",
    long_about = "Reads a definition from FILE: the text between the braces of `mechanism! { ... }` \
(statements, params, modes, loads; grouped or drawn form), or the whole `pub Name { ... }` item. \
`-` reads standard input. The definition goes through the macro's own stages: the same rules \
and messages, every error at once."
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Checks a definition: its errors rustc-style, exit status 1 on an error.
    #[command(after_help = "Example:\n  mechanism check fourbar.mech")]
    Check {
        /// The definition's file (`-`: standard input).
        file: PathBuf,
    },
    /// Tabulates every output over a sweep of the inputs.
    #[command(after_help = "Examples:\n  \
mechanism table fourbar.mech --input theta=0:360deg:73 --csv\n  \
mechanism table fourbar.mech --input theta=0:360deg:73 --rate theta=10 --accel theta=0 --json\n  \
mechanism table five_bar.mech --input a=0:90deg:10 --input b=90:180deg:10            (a grid)\n  \
mechanism table five_bar.mech --input a=0,10deg --input b=90,100deg --paired          (pairs)\n  \
mechanism table press.mech --input theta=0:360deg:73 --rate theta=10 --forces --load cut=250 --csv\n\n\
Values: NAME=V (one), NAME=LO:HI:N (N values, ends included), NAME=A,B,C (a list); angles in rad, \
or with a `deg` suffix. Columns: the inputs, then each output as the generated struct names it \
(`B.x`, `link3`), with its unit in brackets; angles in rad. With --rate, `velocity.` columns; \
with --accel, `acceleration.` columns too; with --forces, `forces.` columns: each reaction \
`r_FROM_TO` (the force of FROM on TO, global frame) as `.x`, `.y`, a prismatic pair's as `.force.x`, \
`.force.y`, `.moment`, each driving effort `drive_INPUT`, then `condition` and `power_residual`. A pose that fails: a `# ...` comment with its error, \
then its row with the inputs and empty outputs.")]
    Table {
        /// The definition's file (`-`: standard input).
        file: PathBuf,
        /// Values of an input: NAME=LO:HI:N, NAME=V or NAME=A,B,C (`deg` suffix for degrees).
        #[arg(long = "input", value_name = "NAME=VALUES")]
        inputs: Vec<String>,
        /// Pairs the inputs' lists (the k-th values together) instead of a grid.
        #[arg(long)]
        paired: bool,
        /// Rate of an input (rad/s or L/s; `deg` suffix: deg/s); others 0. Adds the velocity.
        #[arg(long = "rate", value_name = "NAME=V")]
        rates: Vec<String>,
        /// Acceleration of an input (rad/s^2 or L/s^2); others 0. Adds the acceleration.
        #[arg(long = "accel", value_name = "NAME=V")]
        accels: Vec<String>,
        /// A run-time parameter's value.
        #[arg(long = "param", value_name = "NAME=V")]
        params: Vec<String>,
        /// A run-time assembly mode: NAME=left|right (plus|minus).
        #[arg(long = "mode", value_name = "NAME=left|right")]
        modes: Vec<String>,
        /// The force analysis too: joint reactions and driving efforts (`forces.` columns) at
        /// the rates and accelerations given (others 0).
        #[arg(long)]
        forces: bool,
        /// A `loads { .. }` value for the force analysis.
        #[arg(long = "load", value_name = "NAME=V")]
        loads: Vec<String>,
        /// CSV, every number with 17 significant digits.
        #[arg(long, conflicts_with = "json")]
        csv: bool,
        /// JSON.
        #[arg(long)]
        json: bool,
    },
    /// Draws the mechanism at one pose (SVG).
    #[command(after_help = "Examples:\n  \
mechanism draw fourbar.mech --at theta=30deg -o fourbar.svg\n  \
mechanism draw five_bar.mech --at a=10deg --at b=100deg --trace P -o five_bar.svg\n\n\
Ground pivots hatched, links as bars (plates for three points or more), blocks on their guides; \
the caption gives the inputs. Without -o the SVG goes to standard output.")]
    Draw {
        /// The definition's file (`-`: standard input).
        file: PathBuf,
        /// An input's value: NAME=V (`deg` suffix for degrees); every input needs one.
        #[arg(long = "at", value_name = "NAME=V")]
        at: Vec<String>,
        #[command(flatten)]
        pic: PictureArgs,
    },
    /// Animates the mechanism over a sweep of its input (SVG with SMIL, plays in a browser).
    #[command(after_help = "Examples:\n  \
mechanism animate fourbar.mech --input theta=0:360deg:120 --trace P -o fourbar.svg\n  \
mechanism animate press.mech --input theta=0:360deg:72 --seconds 2 -o press.svg\n\n\
One frame per pose that assembles (a pose that does not is left out; traced paths break there).")]
    Animate {
        /// The definition's file (`-`: standard input).
        file: PathBuf,
        /// Values of an input: NAME=LO:HI:N, NAME=V or NAME=A,B,C (`deg` suffix for degrees).
        #[arg(long = "input", value_name = "NAME=VALUES")]
        inputs: Vec<String>,
        /// Pairs the inputs' lists instead of a grid.
        #[arg(long)]
        paired: bool,
        /// Duration of one cycle (s).
        #[arg(long, default_value_t = 4.0)]
        seconds: f64,
        #[command(flatten)]
        pic: PictureArgs,
    },
    /// Charts outputs against the first input over a sweep (SVG).
    #[command(after_help = "Examples:\n  \
mechanism chart fourbar.mech --input theta=0:360deg:73 --outputs B,link3 -o fourbar-chart.svg\n  \
mechanism chart press.mech --input theta=0:360deg:73 --rate theta=10 --outputs forces.drive_theta -o torque.svg\n\n\
Outputs: a column of `mechanism table` without its unit (`link3`, `velocity.B.x`, \
`forces.drive_theta`) or a point (`B`: its x and y). One panel per output; angles in degrees; \
a pose that fails is a gap. Naming a `velocity.`, `acceleration.` or `forces.` output computes \
that analysis (at the rates and accelerations given, 0 for the others).")]
    Chart {
        /// The definition's file (`-`: standard input).
        file: PathBuf,
        /// Values of an input: NAME=LO:HI:N, NAME=V or NAME=A,B,C (`deg` suffix for degrees).
        #[arg(long = "input", value_name = "NAME=VALUES")]
        inputs: Vec<String>,
        /// The outputs to chart, comma separated.
        #[arg(long, value_delimiter = ',', required = true)]
        outputs: Vec<String>,
        /// Rate of an input (rad/s or L/s); others 0.
        #[arg(long = "rate", value_name = "NAME=V")]
        rates: Vec<String>,
        /// Acceleration of an input (rad/s^2 or L/s^2); others 0.
        #[arg(long = "accel", value_name = "NAME=V")]
        accels: Vec<String>,
        /// A `loads { .. }` value for the force analysis.
        #[arg(long = "load", value_name = "NAME=V")]
        loads: Vec<String>,
        #[command(flatten)]
        pic: PictureArgs,
    },
    /// Synthesizes a four-bar whose coupler point passes through given points, and writes its
    /// definition.
    #[command(after_help = "Examples:\n  \
mechanism synthesize --target 20,20 --target 20,25 --target 20,30 --target 20,35 -o path.mech\n  \
mechanism synthesize --target 3,3 --target 2.759,3.363 --target 2.372,3.663 \\\n    \
--angle 30deg --angle 45deg --angle 60deg --frame 0,0,0 --links 0:50 --coords=-50:50 --json\n  \
mechanism animate path.mech --input phi=0:360deg:120 --trace P -o path.svg\n\n\
The four-bar: ground pivot O2 = (x0, y0), the other at r1 from it at angle theta0, crank r2 at \
an angle from the ground link, coupler r3, rocker r4, the coupler point P at (rcx, rcy) in the \
frame of A -> B; always a Grashof crank-rocker with the crank shortest. The objective: the sum \
of squared distances from P at each target's crank angle to the target (given with --angle, one \
per target, or free and ascending). The definition (its input `phi` is the crank's absolute \
angle, theta0 plus the angle from the ground link) goes to -o or standard output; a summary \
to standard error. The result depends only on the arguments (--seed included).")]
    Synthesize(synthesize::Args),
    /// Writes the Rust source of the `mechanism!` item, to paste into a crate.
    #[command(after_help = "Example:\n  mechanism emit press.mech --name Press > src/press.rs")]
    Emit {
        /// The definition's file (`-`: standard input).
        file: PathBuf,
        /// The type name, for a file that holds a body only (default `Mechanism`).
        #[arg(long)]
        name: Option<String>,
    },
}

/// What every picture takes.
#[derive(clap::Args)]
struct PictureArgs {
    /// The SVG file to write (default: standard output).
    #[arg(short = 'o', long = "output", value_name = "FILE.svg")]
    output: Option<PathBuf>,
    /// The picture's title (default: the definition's name).
    #[arg(long)]
    title: Option<String>,
    /// A point whose path to draw (repeatable).
    #[arg(long = "trace", value_name = "POINT")]
    traced: Vec<String>,
    /// A run-time parameter's value.
    #[arg(long = "param", value_name = "NAME=V")]
    params: Vec<String>,
    /// A run-time assembly mode: NAME=left|right (plus|minus).
    #[arg(long = "mode", value_name = "NAME=left|right")]
    modes: Vec<String>,
}

/// The text of `file` (`-`: standard input).
fn read(file: &Path) -> Result<String, String> {
    if file == Path::new("-") {
        std::io::read_to_string(std::io::stdin()).map_err(|e| format!("standard input: {e}"))
    } else {
        std::fs::read_to_string(file).map_err(|e| format!("{}: {e}", file.display()))
    }
}

/// The mechanism of `file`, or its diagnostics.
fn load(file: &Path) -> Result<Mechanism, Failure> {
    let text = read(file).map_err(Failure::Usage)?;
    Mechanism::new(&text)
        .map_err(|e: Errors| Failure::Definition(e.in_file(&file.display().to_string())))
}

/// Why a command failed.
enum Failure {
    /// The definition has errors (exit status 1).
    Definition(Errors),
    /// The command line or a file is wrong (exit status 2).
    Usage(String),
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        Command::Check { file } => check(&file),
        Command::Table {
            file,
            inputs,
            paired,
            rates,
            accels,
            params,
            modes,
            forces,
            loads,
            csv,
            json,
        } => {
            let args = TableArgs {
                inputs,
                paired,
                rates,
                accels,
                params,
                modes,
                forces,
                loads,
            };
            run_table(&file, &args, csv, json)
        }
        Command::Draw { file, at, pic } => draw(&file, &at, &pic),
        Command::Animate {
            file,
            inputs,
            paired,
            seconds,
            pic,
        } => animate(&file, &inputs, paired, seconds, &pic),
        Command::Chart {
            file,
            inputs,
            outputs,
            rates,
            accels,
            loads,
            pic,
        } => {
            let args = TableArgs {
                inputs,
                paired: false,
                rates,
                accels,
                params: pic.params.clone(),
                modes: pic.modes.clone(),
                forces: false,
                loads,
            };
            chart(&file, &args, &outputs, &pic)
        }
        Command::Emit { file, name } => emit(&file, name.as_deref()),
        Command::Synthesize(args) => synthesize::run(&args).map_err(Failure::Usage),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(Failure::Definition(e)) => {
            eprintln!("{e}");
            ExitCode::from(1)
        }
        Err(Failure::Usage(m)) => {
            eprintln!("error: {m}");
            ExitCode::from(2)
        }
    }
}

/// `check`: the diagnostics, or a summary of the definition.
fn check(file: &Path) -> Result<(), Failure> {
    let m = load(file)?;
    let inputs: Vec<String> = m
        .inputs()
        .iter()
        .map(|i| format!("{} ({})", i.name, if i.angle { "rad" } else { "L" }))
        .collect();
    let outputs = m.columns(mechanism_codegen::runtime::Analysis::Position);
    println!(
        "{}: ok; inputs: {}; {} position outputs; params: {}",
        file.display(),
        inputs.join(", "),
        outputs.len(),
        m.params().len()
    );
    Ok(())
}

/// The table's arguments past the file and format.
struct TableArgs {
    inputs: Vec<String>,
    paired: bool,
    rates: Vec<String>,
    accels: Vec<String>,
    params: Vec<String>,
    modes: Vec<String>,
    forces: bool,
    loads: Vec<String>,
}

/// Reads `NAME=...` arguments.
fn specs(args: &[String]) -> Result<Vec<Spec>, Failure> {
    args.iter()
        .map(|a| Spec::parse(a))
        .collect::<Result<_, _>>()
        .map_err(Failure::Usage)
}

/// Sets the parameters and modes given on the command line.
fn configure(m: &mut Mechanism, args: &TableArgs) -> Result<(), Failure> {
    for s in specs(&args.params)? {
        let v = s.values.first().copied().unwrap_or(f64::NAN);
        m.set_param(&s.name, v).map_err(Failure::Usage)?;
    }
    for s in specs(&args.loads)? {
        let v = s.values.first().copied().unwrap_or(f64::NAN);
        m.set_load(&s.name, v).map_err(Failure::Usage)?;
    }
    for text in &args.modes {
        let (name, value) = text
            .split_once('=')
            .ok_or_else(|| Failure::Usage(format!("`{text}`: expected NAME=left|right")))?;
        let left = match value.trim() {
            "left" | "plus" => true,
            "right" | "minus" => false,
            other => {
                return Err(Failure::Usage(format!(
                    "mode `{name}`: `{other}` is not left, right, plus or minus"
                )))
            }
        };
        m.set_mode(name.trim(), left).map_err(Failure::Usage)?;
    }
    Ok(())
}

/// `table`.
fn run_table(file: &Path, args: &TableArgs, csv: bool, json: bool) -> Result<(), Failure> {
    let mut m = load(file)?;
    if args.forces && !m.has_forces() {
        return Err(Failure::Usage(
            "--forces: the definition has no force analysis (no `mass`, `gravity`, `force`, \
             `torque` or `loads`)"
                .into(),
        ));
    }
    configure(&mut m, args)?;
    let req = table::Request {
        inputs: specs(&args.inputs)?,
        paired: args.paired,
        rates: (!args.rates.is_empty())
            .then(|| specs(&args.rates))
            .transpose()?,
        accels: (!args.accels.is_empty())
            .then(|| specs(&args.accels))
            .transpose()?,
        forces: args.forces,
    };
    let n = table::points(&m, &req.inputs, req.paired)
        .map_err(Failure::Usage)?
        .len();
    let bar = progress(n);
    let t = table::build(&m, &req, &|| bar.inc(1)).map_err(Failure::Usage)?;
    bar.finish_and_clear();
    let out = if csv {
        t.csv()
    } else if json {
        t.json()
    } else {
        t.text()
    };
    print!("{out}");
    if json {
        println!();
    }
    Ok(())
}

/// A progress bar for `n` steps: drawn on a terminal for long sweeps
/// only, hidden otherwise.
fn progress(n: usize) -> indicatif::ProgressBar {
    use std::io::IsTerminal;
    if n >= PROGRESS_FROM && std::io::stderr().is_terminal() {
        indicatif::ProgressBar::new(n as u64)
    } else {
        indicatif::ProgressBar::hidden()
    }
}

/// The mechanism of `file` with a picture's parameters and modes set.
fn load_for_picture(file: &Path, pic: &PictureArgs) -> Result<Mechanism, Failure> {
    let mut m = load(file)?;
    let args = TableArgs {
        inputs: Vec::new(),
        paired: false,
        rates: Vec::new(),
        accels: Vec::new(),
        params: pic.params.clone(),
        modes: pic.modes.clone(),
        forces: false,
        loads: Vec::new(),
    };
    configure(&mut m, &args)?;
    Ok(m)
}

/// Writes `svg` to the picture's file, or to standard output.
fn write_svg(pic: &PictureArgs, svg: &str) -> Result<(), Failure> {
    match &pic.output {
        Some(path) => std::fs::write(path, svg)
            .map_err(|e| Failure::Usage(format!("{}: {e}", path.display()))),
        None => {
            print!("{svg}");
            Ok(())
        }
    }
}

/// `draw`: one pose.
fn draw(file: &Path, at: &[String], pic: &PictureArgs) -> Result<(), Failure> {
    let m = load_for_picture(file, pic)?;
    let given = specs(at)?;
    let mut q = Vec::new();
    for i in m.inputs() {
        let v = given
            .iter()
            .find(|s| s.name == i.name)
            .and_then(|s| s.values.first().copied())
            .ok_or_else(|| {
                Failure::Usage(format!(
                    "--at: no value for input `{}` (add --at {}=V)",
                    i.name, i.name
                ))
            })?;
        q.push(v);
    }
    if let Some(s) = given
        .iter()
        .find(|s| !m.inputs().iter().any(|i| i.name == s.name))
    {
        return Err(Failure::Usage(format!("--at: no input `{}`", s.name)));
    }
    let pos = m
        .position(&q)
        .map_err(|e| Failure::Usage(format!("{}: {e}", picture::caption(&m, &q))))?;
    let title = pic.title.clone().unwrap_or_else(|| m.name());
    let poses = vec![(picture::caption(&m, &q), Some(pos))];
    let sketch = picture::sketch(&m, &title, &poses, &pic.traced).map_err(Failure::Usage)?;
    let svg = sketch
        .drawing(0)
        .map_err(|e| Failure::Usage(e.to_string()))?;
    write_svg(pic, &svg)
}

/// `animate`: every pose of a sweep.
fn animate(
    file: &Path,
    inputs: &[String],
    paired: bool,
    seconds: f64,
    pic: &PictureArgs,
) -> Result<(), Failure> {
    let m = load_for_picture(file, pic)?;
    let points = table::points(&m, &specs(inputs)?, paired).map_err(Failure::Usage)?;
    let bar = progress(points.len());
    let poses = picture::poses(&m, &points, &|| bar.inc(1));
    bar.finish_and_clear();
    let title = pic.title.clone().unwrap_or_else(|| m.name());
    let sketch = picture::sketch(&m, &title, &poses, &pic.traced).map_err(Failure::Usage)?;
    let svg = sketch
        .animation(seconds)
        .map_err(|e| Failure::Usage(e.to_string()))?;
    write_svg(pic, &svg)
}

/// `chart`: outputs against the first input.
fn chart(
    file: &Path,
    args: &TableArgs,
    outputs: &[String],
    pic: &PictureArgs,
) -> Result<(), Failure> {
    let mut m = load(file)?;
    configure(&mut m, args)?;
    let (vel, acc, forces) = picture::needs(outputs);
    if forces && !m.has_forces() {
        return Err(Failure::Usage(
            "--outputs: the definition has no force analysis".into(),
        ));
    }
    let req = table::Request {
        inputs: specs(&args.inputs)?,
        paired: false,
        rates: (vel || !args.rates.is_empty())
            .then(|| specs(&args.rates))
            .transpose()?,
        accels: (acc || !args.accels.is_empty())
            .then(|| specs(&args.accels))
            .transpose()?,
        forces,
    };
    let n = table::points(&m, &req.inputs, false)
        .map_err(Failure::Usage)?
        .len();
    let bar = progress(n);
    let t = table::build(&m, &req, &|| bar.inc(1)).map_err(Failure::Usage)?;
    bar.finish_and_clear();
    let title = pic.title.clone().unwrap_or_else(|| m.name());
    let fig = picture::chart(&t, &m, &title, outputs).map_err(Failure::Usage)?;
    let svg = fig.to_svg().map_err(|e| Failure::Usage(e.to_string()))?;
    write_svg(pic, &svg)
}

/// `emit`: the item, checked first.
fn emit(file: &Path, name: Option<&str>) -> Result<(), Failure> {
    let m = load(file)?;
    let text = read(file).map_err(Failure::Usage)?;
    let body_only = !mechanism_codegen::runtime::text::is_item_text(&text);
    drop(m);
    let indent = |s: &str, by: &str| -> String {
        s.trim_end()
            .lines()
            .map(|l| {
                if l.trim().is_empty() {
                    String::new()
                } else {
                    format!("{by}{l}")
                }
            })
            .collect::<Vec<_>>()
            .join("\n")
    };
    let item = if body_only {
        let name = name.unwrap_or("Mechanism");
        format!("pub {name} {{\n{}\n}}", indent(&dedent(&text), "    "))
    } else if name.is_some() {
        return Err(Failure::Usage(
            "--name: the file names its mechanism already (`pub Name { ... }`)".into(),
        ));
    } else {
        dedent(&text)
    };
    println!(
        "use mechanism::mechanism;\n\nmechanism! {{\n{}\n}}",
        indent(&item, "    ")
    );
    Ok(())
}

/// `text` with the indentation common to its non-blank lines removed.
fn dedent(text: &str) -> String {
    let common = text
        .lines()
        .filter(|l| !l.trim().is_empty())
        .map(|l| l.len() - l.trim_start().len())
        .min()
        .unwrap_or(0);
    text.lines()
        .map(|l| l.get(common..).unwrap_or("").trim_end())
        .collect::<Vec<_>>()
        .join("\n")
}
