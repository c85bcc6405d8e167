//! Prints the report's stability section and writes its plots into
//! `target/stability-report/` (the report binary calls the same `section`).
//! Run: `cargo run --release --example stability_report`.

#[macro_use]
#[path = "common/cli.rs"]
mod cli;
#[path = "report/stability.rs"]
mod stability;

fn main() {
    cli::parse(
        "stability_report",
        "The report's stability section (error against distance to each singularity), with its plots in target/stability-report/.",
        &[],
    );
    let dir = std::path::Path::new("target/stability-report");
    if let Err(e) = std::fs::create_dir_all(dir) {
        eprintln!("cannot create {}: {e}", dir.display());
        return;
    }
    out!("{}", stability::section(dir));
}
