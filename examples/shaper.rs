//! Seed 001: the quick-return shaper (crank + RPR + RRP, m), crank at 1 rad/s,
//! 0..360 deg in steps of 30, on the document's branch (theta3 = 65.556 deg,
//! theta4 = 168.938 deg at crank 0).
//!
//! Run: `cargo run --release --example shaper` (table) or with `-- --csv`.
//!
//! Also writes SVG pictures (kinematics, a drawing, an animation) to
//! `target/plots/shaper/` and says where on stderr (`docs/plots.md`).
#[macro_use]
#[path = "common/cli.rs"]
mod cli;
mod common;
use common::scenes::{Shaper, ShaperInput};
use mechanism::geometry::{angle_deg_0_360, unit};

fn main() {
    let args = cli::parse(
        "shaper",
        "Seed 001's quick-return shaper (m), crank at 1 rad/s: angles, rates and the ram's motion over a full turn.",
        &[cli::CSV],
    );
    let csv = args.flag("--csv");
    let m = Shaper::<f64>::default();
    let names = [
        "crank_deg",
        "theta3_deg",
        "omega3",
        "alpha3",
        "theta4_deg",
        "omega4",
        "alpha4",
        "x_e",
        "v_e",
        "a_e",
    ];
    if csv {
        outln!("{}", names.join(","));
    } else {
        outln!("Quick-return shaper of seed 001 (m); crank 1 rad/s");
        outln!("angles deg, rates rad/s and rad/s^2; ram E: m, m/s, m/s^2");
        outln!("{}", common::header(&names, 11));
    }
    for step in 0..=12 {
        let deg = 30.0 * step as f64;
        let s = m
            .solve(
                &ShaperInput {
                    crank: deg.to_radians(),
                },
                &ShaperInput { crank: 1.0 },
                &ShaperInput { crank: 0.0 },
            )
            .expect("the seed 001 shaper assembles over the whole turn");
        let (p, v, a) = (&s.position, &s.velocity, &s.acceleration);
        let row = [
            deg,
            angle_deg_0_360(&unit(p.link3)),
            v.link3,
            a.link3,
            angle_deg_0_360(&unit(p.link4)),
            v.link4,
            a.link4,
            p.E.x,
            v.E.x,
            a.E.x,
        ];
        if csv {
            outln!("{}", common::csv_row(&row));
        } else {
            outln!("{}", common::table_row(&row, 11, 6));
        }
    }
    common::plots::write_and_report("shaper", common::plots::shaper);
}
