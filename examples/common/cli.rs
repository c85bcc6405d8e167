//! The examples as command-line programs: their options, `--help`, an error
//! (exit code 2, with the nearest option) for an argument they do not know,
//! and output that ends quietly when the reader goes away
//! (`cargo run --example fourbar | head -1`).
//!
//! Mounted at the root of each example (`#[macro_use] #[path = ...] mod cli;`)
//! so that [`outln!`] and [`out!`] find [`write_out`] at `$crate::cli`.
#![allow(dead_code, unused_macros)]

use std::fmt;
use std::io::{self, Write};

/// `println!` to stdout through [`write_out`].
macro_rules! outln {
    () => {
        $crate::cli::write_out(::std::format_args!("\n"))
    };
    ($($arg:tt)*) => {
        $crate::cli::write_out(::std::format_args!("{}\n", ::std::format_args!($($arg)*)))
    };
}

/// `print!` to stdout through [`write_out`].
macro_rules! out {
    ($($arg:tt)*) => {
        $crate::cli::write_out(::std::format_args!($($arg)*))
    };
}

/// Writes to stdout. A closed pipe (the reader has what it wanted) ends the
/// program quietly with exit code 0; any other write error is reported on
/// stderr with exit code 1. Never panics.
pub fn write_out(args: fmt::Arguments<'_>) {
    let mut stdout = io::stdout().lock();
    if let Err(e) = stdout.write_fmt(args) {
        if e.kind() == io::ErrorKind::BrokenPipe {
            std::process::exit(0);
        }
        eprintln!("error: cannot write to stdout: {e}");
        std::process::exit(1);
    }
}

/// One option: its name (`--csv`), the name of its value if it takes one
/// (`Some("N")` for `--show N`), and what it does.
pub struct Opt {
    pub name: &'static str,
    pub value: Option<&'static str>,
    pub help: &'static str,
}

/// A flag without a value.
pub const fn flag(name: &'static str, help: &'static str) -> Opt {
    Opt {
        name,
        value: None,
        help,
    }
}

/// The `--csv` flag every table example has.
pub const CSV: Opt = flag(
    "--csv",
    "print only CSV (a header row, then numbers with 17 significant digits)",
);

/// The options given on the command line.
pub struct Args {
    given: Vec<(&'static str, Option<String>)>,
}

impl Args {
    /// `true` when flag `name` was given.
    pub fn flag(&self, name: &str) -> bool {
        self.given.iter().any(|(n, _)| *n == name)
    }

    /// The value of option `name`, when given (the last one wins).
    pub fn value(&self, name: &str) -> Option<&str> {
        self.given
            .iter()
            .rev()
            .find(|(n, _)| *n == name)
            .and_then(|(_, v)| v.as_deref())
    }
}

/// Reads the command line of example `name` against `opts`. `--help` (or
/// `-h`) prints `about`, the usage and the options, and exits with code 0;
/// an unknown argument or a missing value is an error on stderr, with the
/// nearest option when one is close, and exit code 2.
pub fn parse(name: &str, about: &str, opts: &[Opt]) -> Args {
    match parse_from(std::env::args().skip(1), opts) {
        Ok(Some(args)) => args,
        Ok(None) => {
            outln!("{}", help(name, about, opts));
            std::process::exit(0);
        }
        Err(msg) => {
            eprintln!(
                "error: {msg}\n\nRun `cargo run --example {name} -- --help` for the options."
            );
            std::process::exit(2);
        }
    }
}

/// The options in `args`, `None` for a request for help, or the error.
pub fn parse_from(
    args: impl Iterator<Item = String>,
    opts: &[Opt],
) -> Result<Option<Args>, String> {
    let mut given = Vec::new();
    let mut args = args.peekable();
    while let Some(arg) = args.next() {
        if arg == "--help" || arg == "-h" {
            return Ok(None);
        }
        let Some(opt) = opts.iter().find(|o| o.name == arg) else {
            let near = nearest(&arg, opts.iter().map(|o| o.name).chain(["--help"]));
            return Err(match near {
                Some(n) => format!("unknown option `{arg}`; did you mean `{n}`?"),
                None => format!("unknown option `{arg}`"),
            });
        };
        let value = match opt.value {
            None => None,
            Some(v) => Some(
                args.next()
                    .ok_or_else(|| format!("`{}` needs a value: `{} {v}`", opt.name, opt.name))?,
            ),
        };
        given.push((opt.name, value));
    }
    Ok(Some(Args { given }))
}

/// The help text.
fn help(name: &str, about: &str, opts: &[Opt]) -> String {
    let mut lines = vec![
        about.to_string(),
        String::new(),
        format!("Usage: cargo run --release --example {name} -- [OPTIONS]"),
        String::new(),
        "Options:".to_string(),
    ];
    let label = |o: &Opt| match o.value {
        Some(v) => format!("{} {v}", o.name),
        None => o.name.to_string(),
    };
    let width = opts
        .iter()
        .map(|o| label(o).len())
        .max()
        .unwrap_or(0)
        .max(10);
    for o in opts {
        lines.push(format!("  {:width$}  {}", label(o), o.help));
    }
    lines.push(format!("  {:width$}  print this help", "-h, --help"));
    lines.join("\n")
}

/// The candidate closest to `arg` in edit distance, if it is close: at most
/// a third of the longer name's length in edits (a typo, a swapped pair of
/// letters, a missing dash), and at least one character.
pub fn nearest<'a>(arg: &str, candidates: impl Iterator<Item = &'a str>) -> Option<&'a str> {
    candidates
        .map(|c| (edit_distance(arg, c), c))
        .filter(|(d, c)| *d <= (arg.len().max(c.len()) / 3).max(1))
        .min_by_key(|(d, _)| *d)
        .map(|(_, c)| c)
}

/// Optimal string alignment distance (insertions, deletions, substitutions,
/// transpositions of neighbours), on bytes.
fn edit_distance(a: &str, b: &str) -> usize {
    let (a, b) = (a.as_bytes(), b.as_bytes());
    let mut d = vec![vec![0usize; b.len() + 1]; a.len() + 1];
    for (i, row) in d.iter_mut().enumerate() {
        row[0] = i;
    }
    for (j, cell) in d[0].iter_mut().enumerate() {
        *cell = j;
    }
    for i in 1..=a.len() {
        for j in 1..=b.len() {
            let cost = usize::from(a[i - 1] != b[j - 1]);
            let mut best = (d[i - 1][j] + 1)
                .min(d[i][j - 1] + 1)
                .min(d[i - 1][j - 1] + cost);
            if i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1] {
                best = best.min(d[i - 2][j - 2] + 1);
            }
            d[i][j] = best;
        }
    }
    d[a.len()][b.len()]
}
