//! `mechanism`: planar linkage definitions (the language of `mechanism!`)
//! read from text files and worked on without compiling them. See
//! `docs/cli.md`.

mod spec;
mod table;

use clap::{Parser, Subcommand};
use mechanism_codegen::runtime::{Errors, Mechanism};
use spec::Spec;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

/// Rows from which `table` shows a progress bar (on a terminal).
const PROGRESS_FROM: usize = 10_000;

#[derive(Parser)]
#[command(
    name = "mechanism",
    version,
    about = "Check, tabulate and emit planar linkage definitions (the mechanism! language) without compiling them",
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
        Command::Emit { file, name } => emit(&file, name.as_deref()),
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
    let bar = if n >= PROGRESS_FROM {
        indicatif::ProgressBar::new(n as u64)
    } else {
        indicatif::ProgressBar::hidden()
    };
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
