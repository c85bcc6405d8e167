//! An offset slider-crank (m): crank 0.1, rod 0.4, slide line 0.02 above the
//! crank pivot, 3000 rpm, a full turn in steps of 10 deg.
//!
//! Run: `cargo run --release --example slider_crank` (table) or with `-- --csv`.
//!
//! Also writes SVG pictures (kinematics, a drawing, an animation) to
//! `target/plots/slider_crank/` and says where on stderr (`docs/plots.md`).
#[macro_use]
#[path = "common/cli.rs"]
mod cli;
mod common;
use common::scenes::{SliderCrank, SliderCrankInput};
use mechanism::geometry::{angle_deg_0_360, unit};

fn main() {
    let args = cli::parse(
        "slider_crank",
        "An offset slider-crank (m) at 3000 rpm over a full turn.",
        &[cli::CSV],
    );
    let csv = args.flag("--csv");
    let m = SliderCrank::<f64>::default();
    let omega = 3000.0 * 2.0 * std::f64::consts::PI / 60.0;
    let names = [
        "theta_deg",
        "phi3_deg",
        "omega3",
        "alpha3",
        "x_b",
        "v_b",
        "a_b",
    ];
    if csv {
        outln!("{}", names.join(","));
    } else {
        outln!("Offset slider-crank: crank 0.1 m, rod 0.4 m, offset 0.02 m, 3000 rpm");
        outln!("angles deg, rod rates rad/s and rad/s^2; slider B: m, m/s, m/s^2");
        outln!("{}", common::header(&names, 12));
    }
    for step in 0..36 {
        let deg = 10.0 * step as f64;
        let s = m
            .solve(
                &SliderCrankInput {
                    theta: deg.to_radians(),
                },
                &SliderCrankInput { theta: omega },
                &SliderCrankInput { theta: 0.0 },
            )
            .expect("the rod is longer than crank + offset: it assembles everywhere");
        let (p, v, a) = (&s.position, &s.velocity, &s.acceleration);
        let row = [
            deg,
            angle_deg_0_360(&unit(p.link3)),
            v.link3,
            a.link3,
            p.x,
            v.x,
            a.x,
        ];
        if csv {
            outln!("{}", common::csv_row(&row));
        } else {
            outln!("{}", common::table_row(&row, 12, 5));
        }
    }
    common::plots::write_and_report("slider_crank", common::plots::slider_crank);
}
