//! Shared by the examples: full-precision CSV rows and aligned table rows
//! (the command line is `cli.rs`, mounted at each example's root).
#![allow(dead_code)]

pub mod leg_drop;
pub mod plots;
pub mod run_up;
pub mod seed003;

/// One CSV row, every number with 17 significant digits (round-trip exact for f64).
pub fn csv_row(values: &[f64]) -> String {
    values
        .iter()
        .map(|v| format!("{v:.16e}"))
        .collect::<Vec<_>>()
        .join(",")
}

/// One table row: each value right-aligned in `width` with `decimals` digits.
pub fn table_row(values: &[f64], width: usize, decimals: usize) -> String {
    values
        .iter()
        .map(|v| format!("{v:>width$.decimals$}"))
        .collect::<Vec<_>>()
        .join(" ")
}

/// A header row right-aligned like [`table_row`].
pub fn header(names: &[&str], width: usize) -> String {
    names
        .iter()
        .map(|n| format!("{n:>width$}"))
        .collect::<Vec<_>>()
        .join(" ")
}
pub mod leg;
pub mod stephenson;
