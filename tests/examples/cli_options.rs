//! The examples' command line (`examples/common/cli.rs`): known options are
//! read with their values, `--help` is a request for help, and an unknown
//! option or a missing value is an error that names the nearest option only
//! when it is a plausible typo.

use crate::cli::{flag, parse_from, Opt, CSV};

fn opts() -> [Opt; 3] {
    [
        CSV,
        flag("--standard-gravity", "g = 9.80665"),
        Opt {
            name: "--show",
            value: Some("N"),
            help: "expansion of N groups",
        },
    ]
}

fn run(args: &[&str]) -> Result<Option<crate::cli::Args>, String> {
    parse_from(args.iter().map(|s| s.to_string()), &opts())
}

/// Flags and values are found; absent ones are not.
#[test]
fn known_options_are_read() {
    let a = run(&["--csv", "--show", "12"]).unwrap().unwrap();
    assert!(a.flag("--csv"));
    assert!(!a.flag("--standard-gravity"));
    assert_eq!(a.value("--show"), Some("12"));
    let none = run(&[]).unwrap().unwrap();
    assert!(!none.flag("--csv") && none.value("--show").is_none());
}

/// `--help` and `-h` ask for help wherever they stand.
#[test]
fn help_is_a_request_not_an_option() {
    assert!(run(&["--help"]).unwrap().is_none());
    assert!(run(&["--csv", "-h"]).unwrap().is_none());
}

/// A typo gets the nearest option; a word far from every option gets none;
/// an option without its value says which value it needs.
#[test]
fn unknown_options_are_errors_with_a_suggestion() {
    assert_eq!(
        run(&["--cvs"]).err().unwrap(),
        "unknown option `--cvs`; did you mean `--csv`?"
    );
    assert_eq!(
        run(&["--standard-gravty"]).err().unwrap(),
        "unknown option `--standard-gravty`; did you mean `--standard-gravity`?"
    );
    assert_eq!(
        run(&["-csv"]).err().unwrap(),
        "unknown option `-csv`; did you mean `--csv`?"
    );
    assert_eq!(run(&["table"]).err().unwrap(), "unknown option `table`");
    assert_eq!(
        run(&["--show"]).err().unwrap(),
        "`--show` needs a value: `--show N`"
    );
}
