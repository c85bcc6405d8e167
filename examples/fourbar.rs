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
use common::plots::{degrees, grid, positions, save};
use mechanism::geometry::angle_deg_0_360;
use mechanism::mechanism;
use mechanism_plot::any;
use mechanism_plot::PlotError;
use std::path::{Path, PathBuf};

/// Crank speed (rad/s).
const OMEGA2: f64 = 250.0;

mechanism! {
    /// Crank-rocker four-bar of seed 002 (mm). Ground O2-O4 = 304.8, crank
    /// O2-A = 101.6, coupler A-B = 254.0, rocker O4-B = 177.8; the document's
    /// branch has B above the line A-O4 (`left`).
    #[self_test]
    pub FourBar {
        params { ground = 304.8, crank = 101.6, coupler = 254.0, rocker = 177.8 }
        units { length = "mm" }
        dof 1;
        let O2 = ground(0.0, 0.0);
        let O4 = ground(ground, 0.0);
        let A = crank(O2, crank, theta2) as link2;
        let B = rrr(A, coupler, O4, rocker, left) as (link3, link4);
    }
}

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
    common::plots::write_and_report("fourbar", pictures);
}

/// Four-bar of seed 002 at 250 rad/s: the coupler's and the rocker's angles, rates and
/// accelerations over a turn; the path of B.
pub fn pictures(dir: &Path) -> Result<Vec<PathBuf>, PlotError> {
    let m = FourBar::<f64>::default();
    let rows: Vec<_> = grid(0.0, 360.0, 180)
        .into_iter()
        .map(|d| {
            let s = m.solve(
                &FourBarInput {
                    theta2: d.to_radians(),
                },
                &FourBarInput { theta2: 250.0 },
                &FourBarInput { theta2: 0.0 },
            );
            (d, s.ok().map(|s| (s.position, s.velocity, s.acceleration)))
        })
        .collect();
    let title = "Four-bar of seed 002, crank at 250 rad/s";
    let x = ("crank angle θ2", "deg");
    let fig = any::kinematics_chart(title, x, &rows, &["link3", "link4"])?;
    // Every other pose, 0..356 deg: 90 frames 4 deg apart.
    let poses = &positions(&rows, 2)[..90];
    let sk = any::sketch_with::<FourBar<f64>, _>(title, poses, &["B"], degrees("θ2"))?;
    // The drawing: theta2 = 60 deg (frame 15).
    save(dir, fig, &sk, 15)
}
