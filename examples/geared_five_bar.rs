//! A geared five-bar (m): one motor turns the crank `link2`, whose gear
//! meshes with the gear `link5` at ratio 2, so the second crank of the
//! five-bar turns back at half speed plus a phase (`gear(..)`, docs/dsl.md,
//! "Gear pairs"); the RRR closes the loop at B. 60 rpm, a full turn of the
//! crank in steps of 10 deg.
//!
//! Run: `cargo run --release --example geared_five_bar` (table) or with
//! `-- --csv`.
//!
//! Also writes SVG pictures (kinematics, a drawing, an animation) to
//! `target/plots/geared_five_bar/` and says where on stderr (`docs/plots.md`).
#[macro_use]
#[path = "common/cli.rs"]
mod cli;
mod common;
use common::plots::{degrees, grid, positions, save};
use mechanism::mechanism;
use mechanism_plot::any;
use mechanism_plot::PlotError;
use std::f64::consts::PI;
use std::path::{Path, PathBuf};

mechanism! {
    /// A geared five-bar (m): the crank `link2` about O2 = (0, 0) and the
    /// gear `link5` about O5 = (0.3, 0) mesh at ratio 2 (external: `link5`
    /// turns at 30 deg - 2 theta, its point C at 0.08 from O5); the RRR
    /// `link3`, `link4` closes the loop at B, left of the directed line
    /// A -> C. It assembles over the whole turn: |AC| stays within 0.12 to
    /// 0.48, inside the 0.06 to 0.58 the dyad reaches.
    #[self_test]
    pub GearedFiveBar {
        units { length = "m" }
        dof 1;
        let O2 = ground(0.0, 0.0);
        let O5 = ground(0.3, 0.0);
        let A = crank(O2, 0.1, theta) as link2;
        let C = gear(O5, 0.08, link2, 2.0, 30 deg, ground) as link5;
        let B = rrr(A, 0.32, C, 0.26, left) as (link3, link4);
        outputs { B, link3, link4, link5, A, C, O2, O5 }
    }
}

/// The crank's rate: 60 rpm (rad/s).
const OMEGA: f64 = 2.0 * PI;

fn main() {
    let args = cli::parse(
        "geared_five_bar",
        "A geared five-bar (m) at 60 rpm over a full turn of its crank.",
        &[cli::CSV],
    );
    let csv = args.flag("--csv");
    let m = GearedFiveBar::<f64>::default();
    let names = [
        "theta_deg",
        "phi5_deg",
        "omega5",
        "b_x",
        "b_y",
        "v_b_x",
        "v_b_y",
        "omega3",
        "alpha3",
    ];
    if csv {
        outln!("{}", names.join(","));
    } else {
        outln!("Geared five-bar: crank 0.1 m, gear ratio 2, coupler 0.32 m, 0.26 m; 60 rpm");
        outln!("angles deg, rates rad/s and rad/s^2; B: m, m/s");
        outln!("{}", common::header(&names, 12));
    }
    for step in 0..36 {
        let deg = 10.0 * step as f64;
        let s = m
            .solve(
                &GearedFiveBarInput {
                    theta: deg.to_radians(),
                },
                &GearedFiveBarInput { theta: OMEGA },
                &GearedFiveBarInput { theta: 0.0 },
            )
            .expect("|AC| stays within the dyad's reach: it assembles everywhere");
        let (p, v, a) = (&s.position, &s.velocity, &s.acceleration);
        let row = [
            deg,
            p.link5.to_degrees(),
            v.link5,
            p.B.x,
            p.B.y,
            v.B.x,
            v.B.y,
            v.link3,
            a.link3,
        ];
        if csv {
            outln!("{}", common::csv_row(&row));
        } else {
            outln!("{}", common::table_row(&row, 12, 5));
        }
    }
    common::plots::write_and_report("geared_five_bar", pictures);
}

/// The geared five-bar at 60 rpm over a turn: B and the gear's angle, their
/// rates and accelerations; a drawing and an animation with B's path.
pub fn pictures(dir: &Path) -> Result<Vec<PathBuf>, PlotError> {
    let m = GearedFiveBar::<f64>::default();
    let rows: Vec<_> = grid(0.0, 360.0, 180)
        .into_iter()
        .map(|d| {
            let s = m.solve(
                &GearedFiveBarInput {
                    theta: d.to_radians(),
                },
                &GearedFiveBarInput { theta: OMEGA },
                &GearedFiveBarInput { theta: 0.0 },
            );
            (d, s.ok().map(|s| (s.position, s.velocity, s.acceleration)))
        })
        .collect();
    let title = "Geared five-bar at 60 rpm (gear ratio 2)";
    let x = ("crank angle θ", "deg");
    let fig = any::kinematics_chart(title, x, &rows, &["B", "link5"])?;
    let poses = &positions(&rows, 2)[..90];
    let sk = any::sketch_with::<GearedFiveBar<f64>, _>(title, poses, &["B"], degrees("θ"))?;
    save(dir, fig, &sk, 15)
}
