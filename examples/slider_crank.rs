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
use common::plots::{degrees, grid, positions, save};
use mechanism::geometry::{angle_deg_0_360, unit};
use mechanism::mechanism;
use mechanism_plot::any;
use mechanism_plot::PlotError;
use std::f64::consts::PI;
use std::path::{Path, PathBuf};

mechanism! {
    /// Offset slider-crank (m): crank 0.1, connecting rod 0.4, slide line at
    /// y = 0.02 along +x.
    #[self_test]
    pub SliderCrank {
        params { crank = 0.1, rod = 0.4, offset = 0.02 }
        units { length = "m" }
        dof 1;
        let O = ground(0.0, 0.0);
        let line = guide((0.0, offset), 0 deg);
        let A = crank(O, crank, theta) as link2;
        let B = rrp(A, rod, line, plus) as (link3, slider) slide x;
        outputs { B, link3, x, O, A }
    }
}

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
    common::plots::write_and_report("slider_crank", pictures);
}

/// Offset slider-crank at 3000 rpm over a turn: the slide x and the rod's angle, their
/// rates and accelerations.
pub fn pictures(dir: &Path) -> Result<Vec<PathBuf>, PlotError> {
    let m = SliderCrank::<f64>::default();
    let omega = 3000.0 * 2.0 * PI / 60.0;
    let rows: Vec<_> = grid(0.0, 360.0, 180)
        .into_iter()
        .map(|d| {
            let s = m.solve(
                &SliderCrankInput {
                    theta: d.to_radians(),
                },
                &SliderCrankInput { theta: omega },
                &SliderCrankInput { theta: 0.0 },
            );
            (d, s.ok().map(|s| (s.position, s.velocity, s.acceleration)))
        })
        .collect();
    let title = "Offset slider-crank at 3000 rpm";
    let x = ("crank angle θ", "deg");
    let fig = any::kinematics_chart(title, x, &rows, &["x", "link3"])?;
    let poses = &positions(&rows, 2)[..90];
    let sk = any::sketch_with::<SliderCrank<f64>, _>(title, poses, &[], degrees("θ"))?;
    save(dir, fig, &sk, 15)
}
