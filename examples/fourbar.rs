//! Seed 002: a crank-rocker four-bar (lengths in mm), crank at 250 rad/s, on
//! the document's branch (theta3 = 44.05 deg, theta4 = 96.67 deg at theta2 = 0).
//!
//! Run: `cargo run --release --example fourbar` (table) or with `-- --csv`
//! (CSV only, 17 significant digits).
//!
//! Also writes SVG pictures (kinematics, a drawing, an animation) to
//! `target/plots/fourbar/` and says where on stderr (`docs/plots.md`).
#[macro_use]
#[path = "common/cli.rs"]
mod cli;
mod common;
use common::scenes::{FourBar, FourBarInput};
use mechanism::geometry::angle_deg_0_360;

/// Crank speed (rad/s).
const OMEGA2: f64 = 250.0;

fn main() {
    let args = cli::parse(
        "fourbar",
        "Seed 002's crank-rocker four-bar (mm), crank at 250 rad/s: angles, angular velocities and accelerations over a full turn.",
        &[cli::CSV],
    );
    let csv = args.flag("--csv");
    let fb = FourBar::<f64>::default();
    let names = [
        "theta2_deg",
        "theta3_deg",
        "theta4_deg",
        "omega3",
        "omega4",
        "alpha3",
        "alpha4",
    ];
    if csv {
        outln!("{}", names.join(","));
    } else {
        outln!("Crank-rocker four-bar: ground 304.8, crank 101.6, coupler 254.0, rocker 177.8 mm; crank 250 rad/s");
        outln!(
            "angles in deg, omega in rad/s, alpha in rad/s^2\n{}",
            common::header(&names, 14)
        );
    }
    for step in 0..72 {
        let deg = 5.0 * step as f64;
        let s = fb
            .solve(
                &FourBarInput {
                    theta2: deg.to_radians(),
                },
                &FourBarInput { theta2: OMEGA2 },
                &FourBarInput { theta2: 0.0 },
            )
            .expect("the seed 002 four-bar assembles over the whole turn");
        let (p, v, a) = (&s.position, &s.velocity, &s.acceleration);
        let row = [
            deg,
            angle_deg_0_360(&(p.B - p.A)),
            angle_deg_0_360(&(p.B - p.O4)),
            v.link3,
            v.link4,
            a.link3,
            a.link4,
        ];
        if csv {
            outln!("{}", common::csv_row(&row));
        } else {
            outln!("{}", common::table_row(&row, 14, 4));
        }
    }
    common::plots::write_and_report("fourbar", common::plots::fourbar);
}
