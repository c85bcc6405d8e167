//! Seed 003: the force analysis of an RRR Assur group (links 2 and 3 of a
//! four-bar) with inertia forces and couples, weights and an external force,
//! through the core primitive `mechanism::force::rrr::reactions` (the data are
//! in `common/seed003.rs`, shared with the core's tests).
//!
//! Run: `cargo run --release --example assur_rrr` or with `-- --csv`.
#[macro_use]
#[path = "common/cli.rs"]
mod cli;
mod common;
use common::seed003;

fn main() {
    let args = cli::parse(
        "assur_rrr",
        "Seed 003: an RRR group's reactions through the core primitive, against the printed values.",
        &[cli::CSV],
    );
    let ours = seed003::group::<f64>(-1.0);
    let text = seed003::group::<f64>(1.0);
    // The document's printed results (two decimals; F23 is not printed).
    let printed = [1317.57, 3011.05, -2355.29, 2604.79];
    let rows = [
        ("F12x", ours.f12.x, printed[0], text.f12.x),
        ("F12y", ours.f12.y, printed[1], text.f12.y),
        ("F03x", ours.f03.x, printed[2], text.f03.x),
        ("F03y", ours.f03.y, printed[3], text.f03.y),
        ("F23x", ours.f23.x, f64::NAN, text.f23.x),
        ("F23y", ours.f23.y, f64::NAN, text.f23.y),
    ];
    if args.flag("--csv") {
        outln!("name,ours,printed,text_formula");
        for (name, o, p, t) in rows {
            outln!("{name},{}", common::csv_row(&[o, p, t]));
        }
        return;
    }
    outln!("Seed 003: RRR group with inertia (Mu = -J e), weights (g = 9.81) and F = (1000, 1000) N at D");
    outln!(
        "reactions in N; `text formula` uses the text's Mu3 = +J3 e3 (a typo: 3.6 N off the print)"
    );
    outln!(
        "{:>6} {:>14} {:>10} {:>14}",
        "",
        "ours",
        "printed",
        "text formula"
    );
    for (name, o, p, t) in rows {
        let printed = if p.is_nan() {
            "-".to_string()
        } else {
            format!("{p:.2}")
        };
        outln!("{name:>6} {o:>14.6} {printed:>10} {t:>14.6}");
    }
    outln!(
        "conditioning indicator (|sin| of the angle between the links at C): {:.4}",
        ours.ratio
    );
}
