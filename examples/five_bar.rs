//! A two-input five-bar robot (m): the end point P over a grid of both crank
//! angles. With these dimensions every grid pose assembles; a pose that cannot
//! (shorter distal links, a run-time parameter) prints the typed error instead.
//!
//! Run: `cargo run --release --example five_bar` (table) or with `-- --csv`.
//!
//! Also writes SVG pictures (kinematics, a drawing, an animation) to
//! `target/plots/five_bar/` and says where on stderr (`docs/plots.md`).
#[macro_use]
#[path = "common/cli.rs"]
mod cli;
mod common;
use common::scenes::{FiveBar, FiveBarInput};

fn main() {
    let args = cli::parse(
        "five_bar",
        "A two-input five-bar robot (m): the end point over a grid of both crank angles.",
        &[cli::CSV],
    );
    let csv = args.flag("--csv");
    let m = FiveBar::<f64>::default();
    let names = ["q1_deg", "q2_deg", "p_x", "p_y", "vp_x", "vp_y"];
    if csv {
        outln!("{}", names.join(","));
    } else {
        outln!("Five-bar: base 0.08 m, proximal 0.1 m, distal 0.16 m; both cranks at 1 rad/s");
        outln!("{}", common::header(&names, 12));
    }
    for i in 0..=6 {
        for j in 0..=6 {
            let q1 = 60.0 + 15.0 * i as f64;
            let q2 = 0.0 + 15.0 * j as f64;
            let input = FiveBarInput {
                q1: q1.to_radians(),
                q2: q2.to_radians(),
            };
            let rates = FiveBarInput { q1: 1.0, q2: 1.0 };
            let result = m
                .position(&input)
                .and_then(|p| m.velocity(&p, &rates).map(|v| (p, v)));
            match result {
                Ok((p, v)) => {
                    let row = [q1, q2, p.P.x, p.P.y, v.P.x, v.P.y];
                    if csv {
                        outln!("{}", common::csv_row(&row));
                    } else {
                        outln!("{}", common::table_row(&row, 12, 5));
                    }
                }
                Err(e) if !csv => outln!("{q1:>12.1} {q2:>12.1}   {e}"),
                Err(_) => {}
            }
        }
    }
    common::plots::write_and_report("five_bar", common::plots::five_bar);
}
