//! Prints the report's stability section and writes its plots into
//! `target/stability-report/` (the report binary calls the same `section`).
//! Run: `cargo run --release --example stability_report`.

#[path = "report/stability.rs"]
mod stability;

fn main() {
    let dir = std::path::Path::new("target/stability-report");
    if let Err(e) = std::fs::create_dir_all(dir) {
        eprintln!("cannot create {}: {e}", dir.display());
        return;
    }
    print!("{}", stability::section(dir));
}
